package org.parpe.gui.sweep;

import java.nio.file.Path;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.parpe.gui.files.Examples;
import org.parpe.gui.panels.WorldCombo;
import org.parpe.gui.text.ToolMsg;

/**
 * Where the runs are simulated, with the choices of the IDE's World picker: the flat floor, the
 * example worlds of {@code examples/worlds}, or a world file. Starts on the world of the IDE's
 * runs, so that a sweep measures what a run shows; only in a world does a run have a score.
 */
final class WorldChoice {
    private final WorldCombo worlds;
    private int previous;

    /** The choice in {@code parent}, on {@code current} (a world file, or null for the flat floor). */
    WorldChoice(Composite parent, Path current) {
        worlds = new WorldCombo(parent, ToolMsg.SWEEP_FLAT.text(), Examples.worlds(), ToolMsg.SWEEP_WORLD_FILE_BROWSE.text());
        worlds.choose(current);
        Combo combo = worlds.control();
        previous = combo.getSelectionIndex();
        combo.setToolTipText(ToolMsg.SWEEP_WORLD_TIP.text());
        combo.addListener(SWT.Selection, e -> chosen());
    }

    Combo control() {
        return worlds.control();
    }

    private void chosen() {
        if (worlds.browsing() && worlds.browse(ToolMsg.SWEEP_WORLD_FILE.text()) == null) {
            worlds.control().select(previous);
            return;
        }
        previous = worlds.control().getSelectionIndex();
    }

    /** Selects the world file {@code p}, adding it to the choices if needed (also for tests). */
    void choose(Path p) {
        worlds.choose(p);
    }

    /** The chosen world file, or null for the flat floor. */
    Path world() {
        return worlds.file();
    }
}
