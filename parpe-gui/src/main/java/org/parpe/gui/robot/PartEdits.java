package org.parpe.gui.robot;

import java.util.OptionalDouble;
import java.util.function.Consumer;
import java.util.function.Predicate;
import java.util.function.Supplier;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.build.BuildEdit;
import org.parpe.sim.build.BuildPlate;
import org.parpe.sim.build.RobotDraft;
import org.parpe.sim.config.Connection;
import org.parpe.sim.config.PartSpec;

/**
 * The Robot tab's row for the selected part: a segment's module ID, initial angle and limp flag,
 * the root's roll, Turn 90°, Delete (and the Delete key on the view) and Make root, each a
 * {@link RobotDraft} edit made only when the value changes. Numbers are typed and entered
 * (Enter, or the focus leaving the box).
 */
final class PartEdits {
    private final TabControls ui;
    private final Supplier<Shown> shown;
    private final Supplier<String> selected;
    private final Consumer<BuildEdit> apply;
    private final Consumer<String> say;

    PartEdits(TabControls ui, Supplier<Shown> shown, Supplier<String> selected, Consumer<BuildEdit> apply, Consumer<String> say) {
        this.ui = ui;
        this.shown = shown;
        this.selected = selected;
        this.apply = apply;
        this.say = say;
        typed(ui.moduleId, () -> number(ui.moduleId, ToolMsg.ROBOT_WHAT_ID).ifPresent(v -> change(p -> p.moduleId() != v,
                (d, part) -> d.setModuleId(part, (int) Math.round(v)))));
        typed(ui.angle, () -> number(ui.angle, ToolMsg.ROBOT_WHAT_ANGLE).ifPresent(v -> change(p -> p.angle() != v,
                (d, part) -> d.setAngle(part, v))));
        ui.limp.addListener(SWT.Selection, e -> change(p -> p.limp() != ui.limp.getSelection(),
                (d, part) -> d.setLimp(part, ui.limp.getSelection())));
        typed(ui.roll, () -> number(ui.roll, ToolMsg.ROBOT_WHAT_ROLL).ifPresent(v -> change(p -> isRoot(p) && rootRoll() != v,
                (d, part) -> d.setRootPose("roll", v))));
        ui.turn.addListener(SWT.Selection, e -> change(p -> true, (d, part) -> d.turn(part, (turnOf(d, part) + 1) % 4)));
        ui.delete.addListener(SWT.Selection, e -> change(p -> true, RobotDraft::remove));
        ui.makeRoot.addListener(SWT.Selection, e -> change(p -> true, RobotDraft::makeRoot));
        ui.view.control().addListener(SWT.KeyDown, e -> {
            if (e.keyCode == SWT.DEL || e.keyCode == SWT.BS) {
                change(p -> true, RobotDraft::remove);
            }
        });
    }

    /** {@code then} runs when a value typed into {@code box} is entered (Enter, or the focus leaves it). */
    static void typed(Text box, Runnable then) {
        box.addListener(SWT.DefaultSelection, e -> then.run());
        box.addListener(SWT.FocusOut, e -> then.run());
    }

    /** The number in {@code box}, or empty (nothing typed, no part selected, or not a number: said). */
    private OptionalDouble number(Text box, ToolMsg what) {
        if (box.getText().isBlank() || selected.get() == null) {
            return OptionalDouble.empty();
        }
        try {
            double v = Double.parseDouble(box.getText().trim());
            if (Double.isFinite(v)) {
                return OptionalDouble.of(v);
            }
        } catch (NumberFormatException e) {
            // said below
        }
        say.accept(ToolMsg.ROBOT_NOT_A_NUMBER.text(what.text(), box.getText().trim()));
        return OptionalDouble.empty();
    }

    /** A change of the selected part, made when {@code changed} holds for it. */
    private void change(Predicate<PartSpec> changed, java.util.function.BiFunction<RobotDraft, String, BuildEdit> make) {
        Shown s = shown.get();
        String part = selected.get();
        if (part == null || s.draft() == null || !s.editable()) {
            return;
        }
        PartSpec p = s.draft().part(part).orElse(null);
        if (p != null && changed.test(p)) {
            apply.accept(make.apply(s.draft(), part));
        }
    }

    private boolean isRoot(PartSpec p) {
        return p.name().equals(shown.get().draft().root()) && shown.get().draft().config() != null;
    }

    private double rootRoll() {
        return shown.get().draft().config().root().roll();
    }

    /** The orientation (quarter turns) of the connection that attaches {@code part} to its parent. */
    private static int turnOf(RobotDraft d, String part) {
        BuildPlate at = d.attachment(part).orElse(null);
        if (at == null || d.config() == null) {
            return 0;
        }
        for (Connection c : d.config().connections()) {
            boolean down = c.from().equals(at.part()) && c.fromPlate() == at.plate() && c.to().equals(part);
            boolean up = c.to().equals(at.part()) && c.toPlate() == at.plate() && c.from().equals(part);
            if (down || up) {
                return c.quarterTurns();
            }
        }
        return 0;
    }
}
