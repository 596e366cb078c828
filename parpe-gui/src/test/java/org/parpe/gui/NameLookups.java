package org.parpe.gui;

import com.tngtech.archunit.base.DescribedPredicate;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaMethodCall;
import com.tngtech.archunit.lang.ArchCondition;
import com.tngtech.archunit.lang.ConditionEvents;
import com.tngtech.archunit.lang.SimpleConditionEvent;
import java.util.Set;

/** What "looking a name up" is for {@link EditLayerTest}, and who may do it besides loading and editing. */
final class NameLookups {
    /** The program's and robot's lookups by name. */
    private static final Set<String> LOOKUPS = Set.of("org.parpe.core.model.Program.group",
            "org.parpe.core.model.Program.behavior", "org.parpe.core.model.Program.automaton",
            "org.parpe.core.model.Program.state", "org.parpe.core.model.Program.control",
            "org.parpe.core.model.Robot.group");

    /**
     * The classes that resolve a name the user typed or chose: the diagram views' choosers and
     * palette fields, the Pose panel's group choice and "Use on another group" targets.
     */
    static final DescribedPredicate<JavaClass> RESOLVE_USER_INPUT = DescribedPredicate.describe(
            "resolve a name the user typed or chose", c -> Set.of("org.parpe.gui.diagram.Projection",
                    "org.parpe.gui.diagram.Palette", "org.parpe.gui.pose.PosePanel", "org.parpe.gui.pose.ScriptInsert")
                    .contains(c.getName().replaceAll("\\$.*", "")));

    static final ArchCondition<JavaClass> NOT_LOOK_A_NAME_UP = new ArchCondition<>("not look a name up in the program") {
        @Override
        public void check(JavaClass c, ConditionEvents events) {
            for (JavaMethodCall call : c.getMethodCallsFromSelf()) {
                String target = call.getTargetOwner().getName() + "." + call.getName();
                if (LOOKUPS.contains(target) && call.getTarget().getRawParameterTypes().size() == 1
                        && call.getTarget().getRawParameterTypes().get(0).isEquivalentTo(String.class)) {
                    events.add(SimpleConditionEvent.violated(c, call.getDescription()));
                }
            }
        }
    };

    private NameLookups() {
    }
}
