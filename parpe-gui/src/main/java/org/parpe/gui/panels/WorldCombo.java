package org.parpe.gui.panels;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;

/**
 * The choice of a world as the IDE's World picker and the Sweep dialog show it: the flat floor
 * first, the example worlds of {@code examples/worlds} and the world files chosen so far, and last
 * an item that asks for a file. (The owner lists the example worlds: {@code files} shows this
 * package's dialogs, so this package does not read {@code files}.) Files are kept as absolute, normalized paths, so a file chosen
 * twice is listed once. What choosing the last item does is the owner's ({@link #browse}).
 */
public final class WorldCombo {
    private final Combo combo;
    private final String browseItem;
    private final List<Path> files = new ArrayList<>();

    /** The combo in {@code parent}: {@code flat}, the world files {@code worlds} (each once), {@code browseItem}. */
    public WorldCombo(Composite parent, String flat, List<Path> worlds, String browseItem) {
        this.browseItem = browseItem;
        combo = new Combo(parent, SWT.READ_ONLY);
        combo.add(flat);
        worlds.forEach(this::offer);
        combo.add(browseItem);
        combo.select(0);
    }

    public Combo control() {
        return combo;
    }

    /** The files listed, in their order. */
    public List<Path> files() {
        return Collections.unmodifiableList(files);
    }

    /** Whether the item that asks for a file is selected. */
    public boolean browsing() {
        return browseItem.equals(combo.getText());
    }

    /** Lists the world file {@code p} (before the last item) unless it is listed; returns its place among the files. */
    private int offer(Path p) {
        Path abs = p.toAbsolutePath().normalize();
        int i = files.indexOf(abs);
        if (i < 0) {
            files.add(abs);
            combo.add(abs.getFileName().toString(), files.size());
            i = files.size() - 1;
        }
        return i;
    }

    /** Selects the world file {@code p}, listing it if needed; null selects the flat floor. */
    public void choose(Path p) {
        combo.select(p == null ? 0 : offer(p) + 1);
    }

    /** The chosen world file, or null for the flat floor. */
    public Path file() {
        int i = combo.getSelectionIndex() - 1;
        return i >= 0 && i < files.size() ? files.get(i) : null;
    }

    /** Asks for a world file with a dialog titled {@code title} and selects it; null, and nothing selected, when none is chosen. */
    public Path browse(String title) {
        Path p = FileDialogs.ask(combo.getShell(), SWT.OPEN, title, "*.xml", null, null);
        if (p != null) {
            choose(p);
        }
        return p;
    }
}
