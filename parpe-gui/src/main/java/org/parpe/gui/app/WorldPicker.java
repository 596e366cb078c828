package org.parpe.gui.app;

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
import org.parpe.core.diag.DiagnosticList;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;

/**
 * The world picker beside the robot picker: the flat floor, the example worlds of
 * {@code examples/worlds}, or a world file. A world's problems go to the run log with their
 * {@code FILE:LINE:COL}; the choice then falls back to the flat floor.
 */
final class WorldPicker {
    static final String FLAT = "flat floor";
    private static final String BROWSE = "World file\u2026";

    private final Combo combo;
    private final List<Path> files = new ArrayList<>();
    private final IdeWindow ide;
    private final Prefs prefs;
    private Path loadedFrom;
    private World loaded;

    WorldPicker(Composite bar, IdeWindow ide, Prefs prefs, Runnable changed) {
        this.ide = ide;
        this.prefs = prefs;
        new Label(bar, SWT.NONE).setText("World:");
        combo = new Combo(bar, SWT.READ_ONLY);
        combo.setToolTipText("Where the simulated robot runs: the flat floor or a world with a score");
        combo.add(FLAT);
        Examples.worlds().forEach(this::add);
        String file = prefs.get("view.worldFile", null);
        if (file != null && Files.isRegularFile(Path.of(file)) && !files.contains(Path.of(file))) {
            add(Path.of(file));
        }
        combo.add(BROWSE);
        int at = combo.indexOf(prefs.get("view.world", FLAT));
        combo.select(at >= 0 ? at : 0);
        combo.addListener(SWT.Selection, e -> {
            if (BROWSE.equals(combo.getText()) && !browse()) {
                combo.select(0);
            }
            prefs.put("view.world", combo.getText());
            changed.run();
        });
    }

    private void add(Path p) {
        files.add(p);
        combo.add(p.getFileName().toString());
    }

    private boolean browse() {
        Path p = org.parpe.gui.panels.FileDialogs.ask(combo.getShell(), SWT.OPEN, "World file", "*.xml", null, null);
        if (p == null) {
            return false;
        }
        choose(p);
        prefs.put("view.worldFile", p.toString());
        return true;
    }

    /** Selects the world file {@code p}, adding it to the choices if needed (also for automation and tests). */
    void choose(Path p) {
        int i = files.indexOf(p);
        if (i < 0) {
            files.add(p);
            combo.add(p.getFileName().toString(), combo.getItemCount() - 1);
            i = files.size() - 1;
        }
        combo.select(i + 1);
    }

    /** The chosen world file, or null for the flat floor. */
    Path file() {
        int i = combo.getSelectionIndex() - 1;
        return i >= 0 && i < files.size() ? files.get(i) : null;
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
            found.all().forEach(d -> ide.log(d.format()));
        }
        return loaded;
    }
}
