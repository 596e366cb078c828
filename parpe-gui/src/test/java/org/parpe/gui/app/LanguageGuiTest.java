package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Menu;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.Shell;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.parpe.gui.automation.Screenshot;
import org.parpe.gui.prefs.Prefs;
import org.parpe.gui.text.IdeLanguage;

/**
 * The IDE in the students' language (issue 38): started in German it shows German menus and
 * JFace's buttons in German ("OK", "Abbrechen"), in Japanese Japanese; the Language preference
 * is kept and chosen at the next start, {@code --lang} before it, the environment after it. JFace
 * reads its labels once per process, so each language is a fresh IDE process
 * ({@link LanguageProbe}); its picture of the main window at 1366×768 is kept with the artefacts.
 */
class LanguageGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        Gui.closeIde(ide);
    }

    /**
     * Started in German or Japanese: the menus, the status bar and JFace's buttons are in that
     * language, and the Hardware dialog's column headers and the window's choice boxes fit its words.
     */
    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
        "de; &Datei|&Bearbeiten|&Ausführen|&Ansicht|&Hilfe; Simulator: bereit|Hardware: nicht verbunden; Abbrechen|OK|&Ja|&Nein",
        "ja; ファイル(&F)|編集(&E)|実行(&R)|表示(&V)|ヘルプ(&H); シミュレーター: 待機中|ハードウェア: 未接続; キャンセル|OK|はい(&Y)|いいえ(&N)"})
    void startedInALanguageTheMenusAndJFaceButtonsAreInIt(String lang, String menus, String status, String buttons)
            throws Exception {
        Map<String, String> seen = probe(Files.createTempDirectory("parpe-lang-" + lang), lang, "--lang", lang);
        assertEquals(menus, seen.get("menus"));
        assertEquals(status, seen.get("status"));
        assertEquals(buttons, seen.get("buttons"));
        assertEquals("", seen.get("clipped"), "the Hardware dialog's column headers fit the words of " + lang);
        assertEquals("", seen.get("cut"), "the window's choice boxes fit the items of " + lang);
    }

    /** The preference chooses when there is no --lang (the tests' environment is LC_ALL=C.UTF-8: English); --lang beats it. */
    @Test
    void thePreferenceChoosesAtTheNextStartAndLangBeatsIt() throws Exception {
        Path home = Files.createTempDirectory("parpe-lang-pref");
        new Prefs(home).put(IdeLanguage.PREFERENCE, "es");
        assertEquals("&Archivo|&Editar|E&jecutar|&Ver|A&yuda", probe(home, "es-pref").get("menus"));
        Map<String, String> german = probe(home, "de-over-pref", "--lang", "de");
        assertEquals("&Datei|&Bearbeiten|&Ausführen|&Ansicht|&Hilfe", german.get("menus"));
        assertEquals("Abbrechen|OK|&Ja|&Nein", german.get("buttons"));
    }

    /** View → Language → Deutsch keeps "de" in the settings and says that it applies from the next start. */
    @Test
    void theLanguageMenuKeepsTheChoice() throws Exception {
        Path home = Files.createTempDirectory("parpe-lang-menu");
        ide = Gui.openIde(home);
        MenuItem deutsch = item(item(ide.shell.getMenuBar(), "&View").getMenu(), "&Language").getMenu().getItems()[3];
        assertEquals("Deutsch", deutsch.getText());
        String[] told = new String[1];
        ide.shell.getDisplay().timerExec(200, () -> {
            for (Shell s : ide.shell.getDisplay().getShells()) {
                if (s != ide.shell && !s.isDisposed() && s.isVisible()) {
                    told[0] = s.getText();
                    try {
                        Screenshot.save(s, Path.of(System.getProperty("parpe.artefacts", "target/gui-test-artefacts"),
                                "language-after-restart.png"));
                    } catch (IOException e) {
                        throw new java.io.UncheckedIOException(e);
                    }
                    s.close();
                }
            }
        });
        deutsch.setSelection(true);
        deutsch.notifyListeners(SWT.Selection, new Event());
        assertEquals("Language", told[0]);
        assertEquals("de", new Prefs(home).get(IdeLanguage.PREFERENCE, null));
        assertEquals(Locale.GERMAN, IdeLanguage.choose(null, new Prefs(home).get(IdeLanguage.PREFERENCE, null), v -> "ja_JP.UTF-8"));
    }

    private static MenuItem item(Menu m, String text) {
        for (MenuItem i : m.getItems()) {
            if (i.getText().equals(text)) {
                return i;
            }
        }
        throw new AssertionError("no menu item " + text);
    }

    /** Runs {@link LanguageProbe} with the settings {@code home} and the arguments; returns what it printed. */
    private static Map<String, String> probe(Path home, String name, String... lang) throws IOException, InterruptedException {
        Path dir = Path.of(System.getProperty("parpe.artefacts", "target/gui-test-artefacts"));
        Files.createDirectories(dir);
        Path png = dir.resolve("ide-" + name + "-1366x768.png");
        java.util.List<String> cmd = new java.util.ArrayList<>(java.util.List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), "-Dparpe.examples=" + System.getProperty("parpe.examples"),
                LanguageProbe.class.getName(), home.toString(), png.toString()));
        cmd.addAll(java.util.List.of(lang));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true);
        pb.environment().put("LC_ALL", "C.UTF-8");
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the IDE process did not end");
        assertEquals(0, p.exitValue(), out);
        Map<String, String> seen = new HashMap<>();
        for (String line : out.split("\n")) {
            int eq = line.indexOf('=');
            if (eq > 0 && line.matches("(menus|status|buttons|clipped|cut)=.*")) {
                seen.put(line.substring(0, eq), line.substring(eq + 1));
            }
        }
        org.eclipse.swt.graphics.ImageData d = new org.eclipse.swt.graphics.ImageLoader().load(png.toString())[0];
        assertTrue(Screenshot.distinctColours(d, 64) >= 64, png + " looks blank");
        return seen;
    }
}
