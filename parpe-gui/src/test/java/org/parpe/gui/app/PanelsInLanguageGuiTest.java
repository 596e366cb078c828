package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.CTabItem;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.TabFolder;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.parpe.core.text.Lang;
import org.parpe.gui.prefs.Prefs;
import org.parpe.gui.sweep.SweepDialog;
import org.parpe.gui.sweep.SweepHost;

/**
 * Issue 38 for the panels: the Pose panel, the diagram with its palette, the Robot tab and the
 * sweep dialog built with real widgets in German, Spanish and Japanese show the words of
 * docs/glossary-de.md, -es.md and -ja.md, not English; screenshots of each at 1366×768 are
 * saved for a person to look at (clipped labels). The language is chosen before the widgets are
 * built, as the IDE chooses it at start, and English is restored after.
 */
class PanelsInLanguageGuiTest {

    /** Texts each part shows in {@code language}: the Pose panel, the diagram, the Robot tab, the sweep dialog. */
    private static List<List<String>> expected(String language) {
        if (language.equals("es")) {
            return List.of(List.of("&Capturar", "Del script", "Reproducir", "Guardar grabaci\u00f3n\u2026"),
                    List.of("Vista:", "Carriles", "Nuevo:", "Tabla de marcha", "Aut\u00f3mata", "Comportamiento", "Todo"),
                    List.of("Probar", "Conectar", "Numerar", "Colocar", "Hacer ra\u00edz"),
                    List.of("Barrido", "Optimizar", "Variar", "Fijar en", "Aplicar la mejor", "Guardar CSV\u2026"));
        }
        return language.equals("de")
                ? List.of(List.of("&Aufnehmen", "Aus dem Skript", "Abspielen", "Aufnahme speichern\u2026", "Gelenkwinkel (\u00b0)"),
                        List.of("Ansicht:", "Bahnen", "Neu:", "Gangtabelle", "Automat", "Verhalten", "Alle"),
                        List.of("Testen", "Verbinden", "Nummerieren", "Neu:", "Setzen", "Als Wurzel"),
                        List.of("Durchlauf", "Optimieren", "Variieren", "Festhalten bei", "Besten \u00fcbernehmen", "CSV speichern\u2026"))
                : List.of(List.of("\u8a18\u9332(&C)", "\u30b9\u30af\u30ea\u30d7\u30c8\u304b\u3089", "\u518d\u751f"),
                        List.of("\u30d3\u30e5\u30fc:", "\u30ec\u30fc\u30f3", "\u65b0\u898f:", "\u6b69\u5bb9\u30c6\u30fc\u30d6\u30eb"),
                        List.of("\u8a66\u3059", "\u63a5\u7d9a", "\u914d\u7f6e"),
                        List.of("\u30b9\u30a4\u30fc\u30d7", "\u6700\u9069\u5316", "\u5909\u5316", "\u6700\u826f\u3092\u9069\u7528"));
    }

    @ParameterizedTest
    @ValueSource(strings = {"de", "es", "ja"})
    void panelsSpeakTheChosenLanguage(String language) throws Exception {
        Lang.use(Locale.forLanguageTag(language));
        IdeWindow ide = null;
        SweepDialog sweep = null;
        try {
            ide = new IdeWindow(Gui.display(), new Prefs(Files.createTempDirectory("parpe-panels-" + language)));
            ide.open(null, true);
            IdeWindow shown = ide;
            Gui.pump(() -> shown.validations() > 0, "the first validation");
            ide.shell.setBounds(0, 0, 1366, 768);
            Gui.open(ide, Gui.example("param-loop.xml"));
            Gui.settle();
            List<List<String>> want = expected(language);

            ide.bottom.showPose();
            Gui.settle();
            has(texts(ide.pose.control()), want.get(0), "the Pose panel");

            select(ide.diagram.control());
            has(texts(ide.diagram.control()), want.get(1), "the diagram and its palette");
            Gui.screenshot(ide.shell, "panels-" + language + "-diagram-pose-1366x768.png");

            select(ide.robotTab.control());
            has(texts(ide.robotTab.control()), want.get(2), "the Robot tab");
            Gui.screenshot(ide.shell, "panels-" + language + "-robot-1366x768.png");

            sweep = SweepDialog.open(new SweepHost(ide.shell, ide.editor, ide.document, ide::robotChoice,
                    () -> shown.viewBar.world().file(), ide::showRunDiagnostics));
            Gui.settle();
            has(texts(sweep.shell()), want.get(3), "the sweep dialog");
            Gui.screenshot(sweep.shell(), "panels-" + language + "-sweep.png");
        } finally {
            if (sweep != null && !sweep.shell().isDisposed()) {
                sweep.shell().dispose();
            }
            Gui.closeIde(ide);
            Lang.use(Locale.ENGLISH);
        }
    }

    private static void has(Set<String> shown, List<String> wanted, String where) {
        for (String w : wanted) {
            assertTrue(shown.contains(w), where + " lacks \"" + w + "\"; it shows " + shown);
        }
    }

    /** Brings the tab of {@code control} in its folder to the front. */
    private static void select(Control control) {
        CTabFolder folder = (CTabFolder) control.getParent();
        CTabItem item = null;
        for (CTabItem i : folder.getItems()) {
            if (i.getControl() == control) {
                item = i;
            }
        }
        assertNotNull(item, "no tab for " + control);
        folder.setSelection(item);
        Gui.settle();
    }

    /** Every text {@code c} and its children show: labels, buttons, choosers' items, columns, tabs. */
    private static Set<String> texts(Control c) {
        Set<String> out = new TreeSet<>();
        List<Control> todo = new ArrayList<>(List.of(c));
        while (!todo.isEmpty()) {
            Control x = todo.remove(todo.size() - 1);
            if (x instanceof Label l) {
                out.add(l.getText());
            } else if (x instanceof Button b) {
                out.add(b.getText());
            } else if (x instanceof Combo k) {
                out.addAll(List.of(k.getItems()));
            } else if (x instanceof Table t) {
                for (TableColumn col : t.getColumns()) {
                    out.add(col.getText());
                }
            }
            if (x instanceof TabFolder f) {
                for (var i : f.getItems()) {
                    out.add(i.getText());
                }
            }
            if (x instanceof Composite k) {
                todo.addAll(List.of(k.getChildren()));
            }
        }
        return out;
    }
}
