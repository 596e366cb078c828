package org.parpe.gui.panels;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Consumer;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Tree;
import org.eclipse.swt.widgets.TreeItem;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Control;
import org.parpe.core.model.Group;
import org.parpe.core.model.Instance;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Parameter;
import org.parpe.core.model.Program;
import org.parpe.core.model.StateDef;
import org.parpe.gui.text.ToolMsg;

/**
 * The outline of the last program that loaded: robot groups, parameters, controls, states,
 * automata, behaviors with their instances, and the main sequence. Selecting a node jumps to
 * its definition. A section lists at most {@link #SECTION_LIMIT} entries and then says how many
 * more there are: native tree rows cost about a millisecond each, so a generated script with a
 * hundred thousand states would otherwise freeze the window for minutes.
 */
public final class OutlineView {
    /** Entries shown per section (and per behavior). */
    public static final int SECTION_LIMIT = 500;

    private final Tree tree;
    /** Entries per section of the outline being filled (counted here: asking the native tree is slow). */
    private final Map<TreeItem, Integer> entries = new LinkedHashMap<>();

    /** Creates the view; {@code jump} receives the place the user picked. */
    public OutlineView(Composite parent, Consumer<SourcePos> jump) {
        tree = new Tree(parent, SWT.SINGLE | SWT.V_SCROLL | SWT.H_SCROLL);
        tree.addListener(SWT.Selection, e -> {
            if (e.item != null && e.item.getData() instanceof SourcePos p) {
                jump.accept(p);
            }
        });
    }

    /** The tree. */
    public Tree control() {
        return tree;
    }

    /** Shows {@code program}; {@code null} clears the outline. */
    public void show(Program program) {
        tree.setRedraw(false);
        tree.removeAll();
        if (program != null) {
            fill(program);
        }
        entries.forEach((section, n) -> {
            if (n > SECTION_LIMIT) {
                new TreeItem(section, SWT.NONE).setText(ToolMsg.OUTLINE_MORE.text(n - SECTION_LIMIT));
            }
        });
        entries.clear();
        tree.setRedraw(true);
    }

    private void fill(Program p) {
        TreeItem robot = section(ToolMsg.OUTLINE_ROBOT.text(p.moduleIds().length), p.robot().pos());
        for (Group g : p.robot().groups()) {
            if (!g.implicit()) {
                node(robot, g.name() + "  [" + g.size() + "]", g.pos());
            }
        }
        if (!p.parameters().isEmpty()) {
            TreeItem s = section(ToolMsg.OUTLINE_PARAMETERS.text(), null);
            for (Parameter x : p.parameters()) {
                node(s, x.name() + " = " + org.parpe.core.lang.Numbers.format(p.parameterValues().getOrDefault(x.name(), x.value())), x.pos());
            }
        }
        if (!p.controls().isEmpty()) {
            TreeItem s = section(ToolMsg.OUTLINE_CONTROLS.text(), null);
            for (Control c : p.controls()) {
                node(s, c.name() + "  (" + c.type().word() + ")", c.pos());
            }
        }
        TreeItem states = section(ToolMsg.OUTLINE_STATES.text(), null);
        for (StateDef st : p.states()) {
            node(states, st.name(), st.pos());
        }
        TreeItem automata = section(ToolMsg.OUTLINE_AUTOMATA.text(), null);
        for (Automaton a : p.automata()) {
            node(automata, (a.table() ? ToolMsg.OUTLINE_GAIT_TABLE : ToolMsg.OUTLINE_AUTOMATON).text(a.name(), a.states().size()), a.pos());
        }
        TreeItem behaviors = section(ToolMsg.OUTLINE_BEHAVIORS.text(), null);
        for (Behavior b : p.behaviors()) {
            TreeItem bi = node(behaviors, b.name(), b.pos());
            for (Instance in : b.instances()) {
                node(bi, ToolMsg.OUTLINE_INSTANCE.text(in.name(), in.group()), in.pos());
            }
        }
        p.mainDef().ifPresent(m -> {
            TreeItem main = section((m.cycles() == org.parpe.core.model.MainDef.FOREVER ? ToolMsg.OUTLINE_MAIN_FOREVER : ToolMsg.OUTLINE_MAIN).text(), m.pos());
            for (MainEntry e : m.entries()) {
                node(main, e.behavior(), e.pos());
            }
        });
        for (TreeItem top : tree.getItems()) {
            top.setExpanded(true);
        }
    }

    private TreeItem section(String text, SourcePos pos) {
        TreeItem it = new TreeItem(tree, SWT.NONE);
        it.setText(text);
        it.setData(pos);
        it.setFont(org.eclipse.jface.resource.JFaceResources.getFontRegistry().getBold(org.eclipse.jface.resource.JFaceResources.DEFAULT_FONT));
        return it;
    }

    /** Adds an entry under {@code parent}, or counts it as hidden once the section is full (then returns {@code parent}). */
    private TreeItem node(TreeItem parent, String text, SourcePos pos) {
        if (entries.merge(parent, 1, Integer::sum) > SECTION_LIMIT) {
            return parent;
        }
        TreeItem it = new TreeItem(parent, SWT.NONE);
        it.setText(text);
        it.setData(pos);
        return it;
    }
}
