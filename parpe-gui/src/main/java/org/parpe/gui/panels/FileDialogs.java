package org.parpe.gui.panels;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Supplier;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.FileDialog;
import org.eclipse.swt.widgets.Shell;

/**
 * Every file dialog of the IDE (open, save, Save profile…, Save CSV…, robot, world, recording):
 * each has a title (a GTK save dialog without one is a bare "Save"), and all start in one place
 * (issue 23, item 15): the folder of the script being edited when it is the student's own, else
 * the folder last chosen in any of them, else Documents, else the home folder; never the
 * process's working folder and never the bundled examples' install folder. UI thread only.
 */
public final class FileDialogs {
    private static volatile Supplier<Path> document = () -> null;
    private static volatile Path installed;
    private static volatile Path last;

    private FileDialogs() {
    }

    /**
     * The IDE's window tells where its script is ({@code script}: null for an untitled one) and
     * where the bundled examples are ({@code examples}, may be null: not a place for a student's files).
     */
    public static void follow(Supplier<Path> script, Path examples) {
        document = script;
        installed = examples == null ? null : examples.toAbsolutePath().normalize().getParent();
    }

    /**
     * Where a file dialog starts, from the script {@code script} (may be null), the bundled
     * examples' install folder {@code install} (may be null), the home folder and the folder
     * chosen last (may be null).
     */
    public static Path start(Path script, Path install, Path home, Path chosenLast) {
        Path parent = script == null ? null : script.toAbsolutePath().normalize().getParent();
        if (parent != null && Files.isDirectory(parent) && Files.isWritable(parent)
                && (install == null || !parent.startsWith(install))) {
            return parent;
        }
        if (chosenLast != null && Files.isDirectory(chosenLast)) {
            return chosenLast;
        }
        Path documents = home.resolve("Documents");
        return Files.isDirectory(documents) ? documents : home;
    }

    /** Where a file dialog starts now ({@link #start(Path, Path, Path, Path)} for the IDE's script). */
    public static Path start() {
        return start(document.get(), installed, Path.of(System.getProperty("user.home")), last);
    }

    /**
     * Shows a file dialog: {@code style} {@link SWT#OPEN} or {@link SWT#SAVE} (a save asks before
     * replacing a file), titled {@code title}, for the files {@code filter} matches ({@code "*.xml"}; or any), proposing
     * {@code name} (may be null), starting in {@code folder} (null: {@link #start()}). Returns the
     * file chosen, whose folder is remembered for the next dialog, or null.
     */
    public static Path ask(Shell parent, int style, String title, String filter, String name, Path folder) {
        if (title == null || title.isBlank()) {
            throw new IllegalArgumentException("a file dialog needs a title");
        }
        FileDialog d = new FileDialog(parent, style);
        d.setText(title);
        d.setFilterExtensions(new String[] {filter, "*"});
        d.setFilterPath((folder != null ? folder : start()).toString());
        if (name != null) {
            d.setFileName(name);
        }
        if ((style & SWT.SAVE) != 0) {
            d.setOverwrite(true);
        }
        String chosen = d.open();
        if (chosen == null) {
            return null;
        }
        Path p = Path.of(chosen).toAbsolutePath().normalize();
        last = p.getParent();
        return p;
    }
}
