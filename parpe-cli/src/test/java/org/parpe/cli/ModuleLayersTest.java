package org.parpe.cli;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.classes;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaMethodCall;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.junit.AnalyzeClasses;
import com.tngtech.archunit.junit.ArchTest;
import com.tngtech.archunit.lang.ArchCondition;
import com.tngtech.archunit.lang.ArchRule;
import com.tngtech.archunit.lang.ConditionEvents;
import com.tngtech.archunit.lang.SimpleConditionEvent;

/**
 * The module layering of STYLE.md ("One direction of dependencies"), over every module this one
 * sees: {@code parpe-cli} → {@code parpe-sim}, {@code parpe-serial} → {@code parpe-core}, the
 * simulator and the serial bus independent of each other, and each library kept to its module.
 * (The IDE is not on this module's class path: it uses the CLI's {@code cli.text} only, for its
 * options' help and errors, and Maven's module graph keeps the CLI from using the IDE.)
 */
@AnalyzeClasses(packages = "org.parpe", importOptions = ImportOption.DoNotIncludeTests.class)
class ModuleLayersTest {
    @ArchTest
    static final ArchRule MODULES_DEPEND_DOWNWARDS = layeredArchitecture().consideringOnlyDependenciesInLayers()
            .layer("core").definedBy("org.parpe.core..")
            .layer("sim").definedBy("org.parpe.sim..")
            .layer("serial").definedBy("org.parpe.serial..")
            .layer("cli").definedBy("org.parpe.cli..")
            .whereLayer("cli").mayNotBeAccessedByAnyLayer()
            .whereLayer("sim").mayOnlyBeAccessedByLayers("cli")
            .whereLayer("serial").mayOnlyBeAccessedByLayers("cli")
            .whereLayer("core").mayOnlyBeAccessedByLayers("sim", "serial", "cli");

    @ArchTest
    static final ArchRule ONLY_THE_SIMULATOR_USES_ODE4J = noClasses().that().resideOutsideOfPackage("org.parpe.sim..")
            .and().resideInAPackage("org.parpe..")
            .should().dependOnClassesThat().resideInAPackage("org.ode4j..");

    @ArchTest
    static final ArchRule ONLY_THE_SERIAL_BUS_USES_JSERIALCOMM = noClasses()
            .that().resideOutsideOfPackage("org.parpe.serial..").and().resideInAPackage("org.parpe..")
            .should().dependOnClassesThat().resideInAPackage("com.fazecast..");

    /**
     * Issue 32, item 4: no package cycle anywhere in core, sim, serial and cli. One slice per
     * package, by its full name: slices such as {@code org.parpe.sim.(*)..} left the root
     * packages out ({@code sim ↔ sim.internal ↔ sim.world}, {@code cli ↔ cli.bench} went unseen)
     * and merged a package with its subpackages.
     */
    @ArchTest
    static final ArchRule PACKAGES_FORM_NO_CYCLE = slices().matching("org.parpe.(**)").should().beFreeOfCycles();

    @ArchTest
    static final ArchRule NO_SWT_BELOW_THE_IDE = noClasses().that().resideInAPackage("org.parpe..")
            .should().dependOnClassesThat().resideInAPackage("org.eclipse..");

    /**
     * Issue 32, item 3 ("resolve once", as the IDE's EditLayerTest checks for its modules): the
     * loader binds instances and entries, so no command looks a name up in the program but to
     * resolve a name the user gave as an option ({@code parpe diagram --behavior/--automaton},
     * {@code parpe record --group}).
     */
    @ArchTest
    static final ArchRule COMMANDS_LOOK_UP_ONLY_THE_NAMES_THE_USER_GAVE = classes().that().resideInAPackage("org.parpe.cli..")
            .and().doNotHaveFullyQualifiedName("org.parpe.cli.diagram.DiagramCommand")
            .and().doNotHaveFullyQualifiedName("org.parpe.cli.hw.RecordCommand")
            .should(new ArchCondition<JavaClass>("not look a name up in the program") {
                @Override
                public void check(JavaClass c, ConditionEvents events) {
                    for (JavaMethodCall call : c.getMethodCallsFromSelf()) {
                        String owner = call.getTargetOwner().getName();
                        if ((owner.equals("org.parpe.core.model.Program") || owner.equals("org.parpe.core.model.Robot"))
                                && call.getTarget().getRawParameterTypes().size() == 1
                                && call.getTarget().getRawParameterTypes().get(0).isEquivalentTo(String.class)) {
                            events.add(SimpleConditionEvent.violated(c, call.getDescription()));
                        }
                    }
                }
            });
}
