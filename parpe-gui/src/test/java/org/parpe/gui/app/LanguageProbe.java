package org.parpe.gui.app;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.jface.dialogs.IDialogConstants;
import org.eclipse.jface.dialogs.InputDialog;
import org.eclipse.swt.widgets.MenuItem;
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
        ide.shell().setBounds(0, 0, 1366, 768);
        Gui.open(ide, Gui.example("tutorial/02-gait-table-snake.xml"));
        Gui.pump(() -> ide.program() != null, "lesson 2 to load");
        List<String> menus = new ArrayList<>();
        for (MenuItem m : ide.shell().getMenuBar().getItems()) {
            menus.add(m.getText());
        }
        InputDialog d = new InputDialog(ide.shell(), "?", "?", "", null);
        d.setBlockOnOpen(false);
        d.open();
        Gui.settle();
        Gui.settle();
        Screenshot.save(ide.shell(), Path.of(args[1]));
        System.out.println("menus=" + String.join("|", menus));
        System.out.println("cut=" + String.join("|", cutCombos(ide.shell())));
        System.out.println("status=" + ide.status().sim() + "|" + ide.status().hardware());
        // the dialog's own buttons in GTK's order (Cancel, OK, as JFace labels them), then JFace's Yes and No
        System.out.println("buttons=" + String.join("|", buttons(d.getShell())) + "|" + IDialogConstants.YES_LABEL
                + "|" + IDialogConstants.NO_LABEL);
        d.close();
        // the biggest dialog of the window's own, beside the main window's picture
        org.parpe.gui.hardware.HardwareDialog hardware = org.parpe.gui.hardware.HardwareDialog.open(ide.hardware());
        Gui.settle();
        Gui.settle();
        Screenshot.save(hardware.shell(), Path.of(args[1].replace(".png", "-hardware.png")));
        System.out.println("clipped=" + String.join("|", clippedHeaders(hardware.shell())));
        hardware.shell().close();
        Gui.closeIde(ide);
        System.exit(0);
    }

    /** The shown texts of the visible choice boxes in {@code c} narrower than their longest item. */
    private static List<String> cutCombos(org.eclipse.swt.widgets.Composite c) {
        List<String> out = new ArrayList<>();
        for (org.eclipse.swt.widgets.Control k : c.getChildren()) {
            if (k instanceof org.eclipse.swt.widgets.Combo box && box.isVisible()
                    && (box.getStyle() & org.eclipse.swt.SWT.READ_ONLY) != 0
                    && box.getSize().x < box.computeSize(org.eclipse.swt.SWT.DEFAULT, org.eclipse.swt.SWT.DEFAULT).x) {
                out.add(box.getText());
            } else if (k instanceof org.eclipse.swt.widgets.Composite inner) {
                out.addAll(cutCombos(inner));
            }
        }
        return out;
    }

    /** The column headers of the tables in {@code c} narrower than their text (and the header's padding). */
    private static List<String> clippedHeaders(org.eclipse.swt.widgets.Composite c) {
        List<String> out = new ArrayList<>();
        for (org.eclipse.swt.widgets.Control k : c.getChildren()) {
            if (k instanceof org.eclipse.swt.widgets.Table t) {
                org.eclipse.swt.graphics.GC gc = new org.eclipse.swt.graphics.GC(t);
                for (org.eclipse.swt.widgets.TableColumn col : t.getColumns()) {
                    if (col.getWidth() < gc.textExtent(col.getText()).x + 12) {
                        out.add(col.getText());
                    }
                }
                gc.dispose();
            } else if (k instanceof org.eclipse.swt.widgets.Composite inner) {
                out.addAll(clippedHeaders(inner));
            }
        }
        return out;
    }

    private static List<String> buttons(org.eclipse.swt.widgets.Composite c) {
        List<String> out = new ArrayList<>();
        for (org.eclipse.swt.widgets.Control k : c.getChildren()) {
            if (k instanceof org.eclipse.swt.widgets.Button b && (b.getStyle() & org.eclipse.swt.SWT.PUSH) != 0) {
                out.add(b.getText());
            } else if (k instanceof org.eclipse.swt.widgets.Composite inner) {
                out.addAll(buttons(inner));
            }
        }
        return out;
    }
}
