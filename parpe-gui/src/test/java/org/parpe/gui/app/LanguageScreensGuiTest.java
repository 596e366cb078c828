package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.CTabItem;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.Shell;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.core.text.Lang;
import org.parpe.gui.automation.Screenshot;

/**
 * Issue 38, acceptance 3: in German, Japanese and the pseudo-language {@code qps} (every text
 * 40 % longer and accented), at 1366×768 and at the IDE's 200 % zoom, no label of the main
 * window, of any of its tabs or of any dialog its menus open is clipped or overlapped
 * ({@link LayoutCheck}). One IDE per language and size; each tab is brought to the front and
 * each dialog opened and closed in turn; every screen is saved under
 * {@code target/i18n-screens/} (system property {@code parpe.i18nScreens}), and the main window's
 * picture at 1366×768 in {@code docs/images/i18n/} (property {@code parpe.i18nImages}) for
 * docs/ide.md. The dialogs are found in the menus, not named: every item whose text ends in "…"
 * (a dialog follows, by the desktop's convention; in {@code qps} before the padding), and every item of Help; the native file
 * choosers (Open…, Save As…, found by their keys) are GTK's own and not PARPE's layouts.
 * Tagged {@code screens}: about two minutes, so CI's second GUI run may leave it out.
 */
@Tag("screens")
class LanguageScreensGuiTest {
    private static final int WIDTH = 1366;
    private static final int HEIGHT = 768;
    private IdeWindow ide;

    @AfterEach
    void close() {
        Gui.closeIde(ide);
        Lang.use(Locale.ENGLISH);
    }

    static Stream<Arguments> languagesAndSizes() {
        return Stream.of(Locale.GERMAN, Locale.JAPANESE, Lang.PSEUDO)
                .flatMap(l -> Stream.of(Arguments.of(l, false), Arguments.of(l, true)));
    }

    @ParameterizedTest(name = "{0}, zoomed {1}")
    @MethodSource("languagesAndSizes")
    void noLabelIsClippedOrOverlapped(Locale language, boolean zoomed) throws Exception {
        Lang.use(language);
        String tag = language.getLanguage() + "-" + (zoomed ? "zoom200" : WIDTH + "x" + HEIGHT);
        Path dir = Path.of(System.getProperty("parpe.i18nScreens", "target/i18n-screens"));
        Files.createDirectories(dir);
        ide = Gui.openIde(Files.createTempDirectory("parpe-i18n"));
        ide.shell.setBounds(0, 0, WIDTH, HEIGHT);
        Gui.open(ide, Gui.example("tutorial/02-gait-table-snake.xml"));
        Gui.pump(() -> ide.program() != null, "lesson 2 to load");
        assertTrue(ide.grid.showTable("travel"), "lesson 2 has its gait table 'travel'");
        if (zoomed) {
            int normal = ide.editor.widget().getFont().getFontData()[0].getHeight();
            while (ide.editor.widget().getFont().getFontData()[0].getHeight() < 2 * normal) {
                ide.zoom(1);
            }
        }
        Gui.settle();
        Map<String, String> problems = new LinkedHashMap<>();
        check(ide.shell, dir.resolve("main-" + tag + ".png"), "main window", problems);
        if (!zoomed) {
            Path images = Path.of(System.getProperty("parpe.i18nImages", "../docs/images/i18n"));
            Files.createDirectories(images);
            Screenshot.save(ide.shell, images.resolve("main-" + tag + ".png"));
        }
        int screens = 1 + tabs(dir, tag, problems) + dialogs(dir, tag, problems);
        assertTrue(screens >= 15, "the tabs and dialogs were found: " + screens + " screens");
        List<String> lines = new ArrayList<>();
        problems.forEach((p, where) -> lines.add(p + "   [" + where + "]"));
        Files.write(dir.resolve("problems-" + tag + ".txt"), lines);
        assertEquals(List.of(), lines, tag + ": clipped or overlapping (screens in " + dir.toAbsolutePath() + "):\n"
                + String.join("\n", lines));
    }

    /** Checks {@code shell} and saves its picture; a problem seen before is listed once, with the first screen that showed it. */
    private static void check(Shell shell, Path png, String screen, Map<String, String> problems) throws Exception {
        for (String p : LayoutCheck.problems(shell)) {
            problems.putIfAbsent(p, screen);
        }
        // a window larger than the screen shows only part of itself (run on a 1366x768 screen for the laptop's)
        Rectangle b = shell.getBounds();
        Rectangle area = shell.getMonitor().getClientArea();
        if (b.width > area.width || b.height > area.height) {
            problems.putIfAbsent("larger than the screen (" + area.width + "x" + area.height + "): Shell '" + shell.getText()
                    + "' " + b.width + "x" + b.height, screen);
        }
        Screenshot.save(shell, png);
    }

    /** Brings every tab of every folder of the main window to the front in turn; the number of screens. */
    private int tabs(Path dir, String tag, Map<String, String> problems) throws Exception {
        List<CTabFolder> folders = new ArrayList<>();
        collect(ide.shell, folders);
        int n = 0;
        for (int f = 0; f < folders.size(); f++) {
            CTabFolder folder = folders.get(f);
            for (int i = 0; i < folder.getItemCount(); i++) {
                CTabItem item = folder.getItem(i);
                folder.setSelection(item);
                Event e = new Event();
                e.item = item;
                folder.notifyListeners(SWT.Selection, e);
                Gui.settle();
                check(ide.shell, dir.resolve("tab-" + f + "." + i + "-" + slug(item.getText()) + "-" + tag + ".png"),
                        "tab " + item.getText(), problems);
                n++;
            }
        }
        return n;
    }

    private static void collect(Control c, List<CTabFolder> out) {
        if (c instanceof CTabFolder f) {
            out.add(f);
        }
        if (c instanceof Composite k) {
            for (Control child : k.getChildren()) {
                collect(child, out);
            }
        }
    }

    /** Opens every dialog of the menus, checks it and closes it; the number of screens. */
    private int dialogs(Path dir, String tag, Map<String, String> problems) throws Exception {
        MenuItem[] top = ide.shell.getMenuBar().getItems();
        List<MenuItem> items = new ArrayList<>();
        for (MenuItem m : top) {
            for (MenuItem it : m.getMenu().getItems()) {
                boolean fileChooser = it.getAccelerator() == SWT.MOD1 + 'O' || it.getAccelerator() == SWT.MOD1 + SWT.SHIFT + 'S';
                boolean dialog = ellipsis(it.getText().split("\t")[0]) || m == top[top.length - 1];
                if ((it.getStyle() & SWT.PUSH) != 0 && dialog && !fileChooser) {
                    items.add(it);
                }
            }
        }
        for (int i = 0; i < items.size(); i++) {
            MenuItem it = items.get(i);
            String name = it.getText().split("\t")[0].replace("&", "");
            open(() -> it.notifyListeners(SWT.Selection, new Event()), name,
                    dir.resolve("dialog-" + i + "-" + slug(name) + "-" + tag + ".png"), problems);
        }
        return items.size() + windowsOfPanes(dir, tag, problems);
    }

    /**
     * The dialogs a pane opens: the grid's Wave… (found by its text in the language shown),
     * the 3D view's module camera, and the parameters asked before a run of lesson 7.
     */
    private int windowsOfPanes(Path dir, String tag, Map<String, String> problems) throws Exception {
        org.eclipse.swt.widgets.Button wave = Arrays.stream(ide.grid.toolBar().getChildren())
                .filter(c -> c instanceof org.eclipse.swt.widgets.Button b && b.getText().equals(org.parpe.gui.text.PanelMsg.GRID_WAVE.text()))
                .map(c -> (org.eclipse.swt.widgets.Button) c).findFirst()
                .orElseThrow(() -> new AssertionError("the grid's bar has no button ending in \u2026 (Wave\u2026)"));
        open(() -> wave.notifyListeners(SWT.Selection, new Event()), wave.getText(),
                dir.resolve("pane-wave-" + tag + ".png"), problems);
        open(ide::openModuleCamera, "module camera", dir.resolve("pane-camera-" + tag + ".png"), problems);
        var lesson7 = org.parpe.core.load.ScriptLoader.load(Gui.example("tutorial/07-parameters-snake.xml"), Map.of());
        assertTrue(lesson7.ok() && !lesson7.program().parameters().isEmpty(), "lesson 7 has parameters");
        open(() -> new org.parpe.gui.panels.ParametersDialog(ide.shell, lesson7.program().parameters(), Map.of()).open(),
                "parameters", dir.resolve("pane-parameters-" + tag + ".png"), problems);
        return 3;
    }

    /**
     * Runs {@code trigger} (chooses a menu item, presses a button) and checks the window it opens, then closes it. A modal dialog blocks
     * in its own event loop, so the check runs from a timer inside that loop. An item that opens
     * no window (the tutorial docked beside the outline) is checked in the main window.
     */
    private void open(Runnable trigger, String name, Path png, Map<String, String> problems) throws Exception {
        Display d = ide.shell.getDisplay();
        Set<Shell> before = Set.of(d.getShells());
        long until = System.currentTimeMillis() + 5_000;
        boolean[] done = {false};
        Exception[] failed = {null};
        Runnable[] poll = new Runnable[1];
        poll[0] = () -> {
            Shell s = Arrays.stream(d.getShells()).filter(x -> !before.contains(x) && x.isVisible()).findFirst().orElse(null);
            try {
                if (s != null) {
                    Gui.settle();
                    check(s, png, name, problems);
                    s.close();
                } else if (System.currentTimeMillis() < until) {
                    d.timerExec(100, poll[0]);
                    return;
                } else {
                    Gui.settle();
                    Gui.settle();
                    check(ide.shell, png, name, problems);
                }
            } catch (Exception e) {
                failed[0] = e;
            }
            done[0] = true;
        };
        d.timerExec(100, poll[0]);
        trigger.run();
        Gui.pump(() -> done[0], name + " to open and close");
        if (failed[0] != null) {
            throw failed[0];
        }
        Gui.settle();
    }

    /** Whether a menu item's text ends in "…", also in the pseudo-language, where its padding and bracket follow ({@code [Éxþöŕţ… ~~~]}). */
    private static boolean ellipsis(String text) {
        return text.replaceAll(" ~+\\]$", "").endsWith("\u2026");
    }

    /** The ASCII letters and digits of {@code text} (accents taken off), for a file name. */
    private static String slug(String text) {
        String s = java.text.Normalizer.normalize(text, java.text.Normalizer.Form.NFD).replaceAll("\\p{M}", "").replaceAll("[^A-Za-z0-9]+", "-").replaceAll("^-|-$", "");
        return s.isEmpty() ? "x" : s.length() > 24 ? s.substring(0, 24) : s;
    }
}
