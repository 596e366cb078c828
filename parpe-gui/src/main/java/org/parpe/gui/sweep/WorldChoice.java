package org.parpe.gui.sweep;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.parpe.gui.files.Examples;
import org.parpe.gui.text.ToolMsg;

/**
 * Where the runs are simulated, with the choices of the IDE's World picker: the flat floor, the
 * example worlds of {@code examples/worlds}, or a world file. Starts on the world of the IDE's
 * runs, so that a sweep measures what a run shows; only in a world does a run have a score.
 */
final class WorldChoice {

    private final Combo combo;
    private final List<Path> files = new ArrayList<>();
    private int previous;

    /** The choice in {@code parent}, on {@code current} (a world file, or null for the flat floor). */
    WorldChoice(Composite parent, Path current) {
        combo = new Combo(parent, SWT.READ_ONLY);
        combo.add(ToolMsg.SWEEP_FLAT.text());
        Examples.worlds().forEach(this::add);
        combo.add(ToolMsg.SWEEP_WORLD_FILE_BROWSE.text());
        combo.select(0);
        if (current != null) {
            choose(current);
        }
        previous = combo.getSelectionIndex();
        combo.setToolTipText(ToolMsg.SWEEP_WORLD_TIP.text());
        combo.addListener(SWT.Selection, e -> chosen());
    }

    Combo control() {
        return combo;
    }

    private void add(Path p) {
        files.add(p);
        combo.add(p.getFileName().toString());
    }

    private void chosen() {
        if (!ToolMsg.SWEEP_WORLD_FILE_BROWSE.text().equals(combo.getText())) {
            previous = combo.getSelectionIndex();
            return;
        }
        Path p = org.parpe.gui.panels.FileDialogs.ask(combo.getShell(), SWT.OPEN, ToolMsg.SWEEP_WORLD_FILE.text(), "*.xml", null, null);
        if (p == null) {
            combo.select(previous);
            return;
        }
        choose(p);
        previous = combo.getSelectionIndex();
    }

    /** Selects the world file {@code p}, adding it to the choices if needed (also for tests). */
    void choose(Path p) {
        Path abs = p.toAbsolutePath().normalize();
        int i = files.stream().map(f -> f.toAbsolutePath().normalize()).toList().indexOf(abs);
        if (i < 0) {
            files.add(abs);
            combo.add(abs.getFileName().toString(), combo.getItemCount() - 1);
            i = files.size() - 1;
        }
        combo.select(i + 1);
    }

    /** The chosen world file, or null for the flat floor. */
    Path world() {
        int i = combo.getSelectionIndex() - 1;
        return i >= 0 && i < files.size() ? files.get(i) : null;
    }
}
