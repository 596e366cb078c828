package org.parpe.gui.app;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.jface.dialogs.IDialogConstants;
import org.eclipse.jface.dialogs.InputDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.parpe.gui.automation.Screenshot;
import org.parpe.gui.prefs.Prefs;
import org.parpe.gui.text.IdeLanguage;

/**
 * A fresh IDE process for {@link LanguageGuiTest}: chooses the language as {@code parpe gui}
 * does ({@code --lang}, the preference of the settings folder, the environment), opens the window
 * at 1366×768 with JFace's input dialog over it, prints what a user reads (the menu bar, the
 * status bar, the dialog's buttons) as {@code name=text} lines and saves a picture of it and one
 * of the Hardware dialog ({@code …-hardware.png}).
 * Arguments: settings folder, picture file, and {@code --lang CODE} or nothing.
 */
final class LanguageProbe {
    private LanguageProbe() {
    }

    public static void main(String[] args) throws Exception {
        Prefs prefs = new Prefs(Path.of(args[0]));
        IdeLanguage.use(IdeLanguage.choose(args.length > 3 ? args[3] : null, prefs.get(IdeLanguage.PREFERENCE, null),
                System::getenv));
        IdeWindow ide = Gui.openIde(Path.of(args[0]));
        ide.shell.setBounds(0, 0, 1366, 768);
        Gui.open(ide, Gui.example("tutorial/02-gait-table-snake.xml"));
        Gui.pump(() -> ide.program() != null, "lesson 2 to load");
        List<String> menus = new ArrayList<>();
        for (MenuItem m : ide.shell.getMenuBar().getItems()) {
            menus.add(m.getText());
        }
        InputDialog d = new InputDialog(ide.shell, "?", "?", "", null);
        d.setBlockOnOpen(false);
        d.open();
        Gui.settle();
        Gui.settle();
        Screenshot.save(ide.shell, Path.of(args[1]));
        System.out.println("menus=" + String.join("|", menus));
        System.out.println("cut=" + String.join("|", cutCombos(ide.shell)));
        System.out.println("status=" + ide.status.sim() + "|" + ide.status.hardware());
        // the dialog's own buttons in GTK's order (Cancel, OK, as JFace labels them), then JFace's Yes and No
        System.out.println("buttons=" + String.join("|", buttons(d.getShell())) + "|" + IDialogConstants.YES_LABEL
                + "|" + IDialogConstants.NO_LABEL);
        d.close();
        // the biggest dialog of the window's own, beside the main window's picture
        org.parpe.gui.hardware.HardwareDialog hardware = org.parpe.gui.hardware.HardwareDialog.open(ide.hardware);
        Gui.settle();
        Gui.settle();
        Screenshot.save(hardware.shell(), Path.of(args[1].replace(".png", "-hardware.png")));
        System.out.println("clipped=" + String.join("|", clippedHeaders(hardware.shell())));
        hardware.shell().close();
        Gui.closeIde(ide);
        System.exit(0);
    }

    /** The shown texts of the visible choice boxes in {@code c} narrower than their longest item. */
    private static List<String> cutCombos(Composite c) {
        return IdeAccess.allChildren(c).stream()
                .filter(k -> k instanceof Combo box && box.isVisible() && (box.getStyle() & SWT.READ_ONLY) != 0
                        && box.getSize().x < box.computeSize(SWT.DEFAULT, SWT.DEFAULT).x)
                .map(k -> ((Combo) k).getText()).toList();
    }

    /** The column headers of the tables in {@code c} narrower than their text (and the header's padding). */
    private static List<String> clippedHeaders(Composite c) {
        List<String> out = new ArrayList<>();
        for (Control k : IdeAccess.allChildren(c)) {
            if (k instanceof Table t) {
                GC gc = new GC(t);
                for (TableColumn col : t.getColumns()) {
                    if (col.getWidth() < gc.textExtent(col.getText()).x + 12) {
                        out.add(col.getText());
                    }
                }
                gc.dispose();
            }
        }
        return out;
    }

    private static List<String> buttons(Composite c) {
        return IdeAccess.allChildren(c).stream().filter(k -> k instanceof Button b && (b.getStyle() & SWT.PUSH) != 0)
                .map(k -> ((Button) k).getText()).toList();
    }
}
