package org.parpe.gui.app;

import org.parpe.gui.text.UiMsg;
import org.parpe.gui.prefs.Prefs;
import org.parpe.gui.files.Examples;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.parpe.gui.panels.WorldCombo;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;

/**
 * The world picker beside the robot picker: the flat floor, the example worlds of
 * {@code examples/worlds}, or a world file. Each file has its own world ({@link RunChoices}), shown
 * here when the file is. A world's problems go to the run log with their {@code FILE:LINE:COL};
 * the choice then falls back to the flat floor.
 */
final class WorldPicker {
    /** The flat floor as {@link RunChoices} keeps it (a word, not the text shown). */
    static final String FLAT = "flat";

    private final WorldCombo worlds;
    private final IdeWindow ide;
    private final Prefs prefs;
    private Path loadedFrom;
    private World loaded;

    WorldPicker(Composite bar, IdeWindow ide, Prefs prefs, Runnable changed) {
        this.ide = ide;
        this.prefs = prefs;
        new Label(bar, SWT.NONE).setText(UiMsg.VIEW_WORLD.text());
        String file = prefs.get("view.worldFile", null);
        Path last = file == null ? null : Path.of(file);
        List<Path> listed = new ArrayList<>(Examples.worlds());
        if (last != null && Files.isRegularFile(last)) {
            listed.add(last);
        }
        worlds = new WorldCombo(bar, UiMsg.WORLD_FLAT.text(), listed, UiMsg.WORLD_FILE.text());
        Combo combo = worlds.control();
        combo.setToolTipText(UiMsg.VIEW_WORLD_TIP.text());
        // Each file has its own world (RunChoices): the flat floor until the file is shown.
        combo.addListener(SWT.Selection, e -> {
            if (worlds.browsing() && !browse()) {
                worlds.choose(null);
            }
            changed.run();
        });
    }

    /** The choice as {@link RunChoices} keeps it: {@link #FLAT} or the world file's path. */
    String choice() {
        Path f = file();
        return f == null ? FLAT : f.toString();
    }

    /**
     * Shows {@code choice} ({@link #FLAT} or a world file) as chosen for the file now in the
     * editor; a world file that is no longer there shows the example world of that name, else the flat floor.
     */
    void show(String choice) {
        Path p = FLAT.equals(choice) ? null : Path.of(choice);
        if (p != null && !Files.isRegularFile(p)) {
            p = worlds.files().stream().filter(f -> f.getFileName().equals(Path.of(choice).getFileName())).findFirst().orElse(null);
        }
        worlds.choose(p);
    }

    /** Picks the world file {@code p} (null: the flat floor) as the user does in the picker (automation, tests). */
    void pick(Path p) {
        worlds.choose(p);
        worlds.control().notifyListeners(SWT.Selection, new org.eclipse.swt.widgets.Event());
    }

    private boolean browse() {
        Path p = worlds.browse(UiMsg.WORLD_FILE_TITLE.text());
        if (p == null) {
            return false;
        }
        prefs.put("view.worldFile", p.toString());
        return true;
    }

    /** Selects the world file {@code p}, adding it to the choices if needed (also for automation and tests). */
    void choose(Path p) {
        worlds.choose(p);
    }

    /** The chosen world file, or null for the flat floor. */
    Path file() {
        return worlds.file();
    }

    /** The chosen world, read once per choice; null for the flat floor or after errors (logged). */
    World world() {
        Path f = file();
        if (f == null) {
            return null;
        }
        if (!f.equals(loadedFrom)) {
            DiagnosticList found = new DiagnosticList();
            loaded = WorldReader.read(f, found);
            loadedFrom = f;
            found.all().forEach(d -> ide.bottom.log(d.format()));
        }
        return loaded;
    }
}
