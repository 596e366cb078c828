package org.parpe.sim.sheet;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diagram.Labels;
import org.parpe.core.diagram.Scene;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;
import org.parpe.sim.internal.Assembly;

/**
 * The robot sheet in each language (issue 38: "no clipped or overlapping label"): a view's title
 * stays inside its view and the part list's headings and cells do not run into each other. In
 * Spanish the titles ran into the next view and "número de módulo" over "ángulo".
 */
class RobotSheetLanguagesTest {
    @AfterEach
    void english() {
        org.parpe.core.text.Lang.use(Locale.ENGLISH);
    }

    @ParameterizedTest
    @ValueSource(strings = {"en", "de", "es", "ja", "qps"})
    void noWordOfTheSheetRunsIntoAnother(String language) throws Exception {
        org.parpe.core.text.Lang.use(Locale.forLanguageTag(language));
        Path file = Path.of("../examples/configs/humanoid15.xml");
        DiagnosticList d = new DiagnosticList();
        RobotConfig c = RobotConfigs.read(file.toString(), Files.readString(file), d).config();
        assertNotNull(c, d.all().toString());
        Scene sc = RobotSheet.of(c, Assembly.build(c, d));
        List<Scene.Text> titles = new ArrayList<>();
        List<Scene.Rect> views = new ArrayList<>();
        List<Scene.Text> list = new ArrayList<>();
        for (Scene.Shape s : sc.shapes()) {
            if (s instanceof Scene.Rect r && r.w() == r.h()) {
                views.add(r);
            } else if (s instanceof Scene.Text t && views.size() > titles.size() && t.y() < views.get(0).y() + 20) {
                titles.add(t);
            } else if (s instanceof Scene.Text t && !views.isEmpty() && t.y() > views.get(0).y() + views.get(0).h() + 30) {
                list.add(t);
            }
        }
        assertEquals(3, titles.size(), "three views, each with its title");
        List<String> problems = new ArrayList<>();
        for (int v = 0; v < 3; v++) {
            Labels.Box b = Labels.box(titles.get(v));
            if (b.x() + b.w() > views.get(v).x() + views.get(v).w()) {
                problems.add("the title '" + titles.get(v).text() + "' leaves its view");
            }
        }
        for (int i = 0; i < list.size(); i++) {
            for (int j = i + 1; j < list.size(); j++) {
                if (Labels.box(list.get(i)).overlaps(Labels.box(list.get(j)))) {
                    problems.add("'" + list.get(i).text() + "' meets '" + list.get(j).text() + "'");
                }
            }
            Labels.Box b = Labels.box(list.get(i));
            if (b.x() + b.w() > sc.width()) {
                problems.add("'" + list.get(i).text() + "' leaves the sheet");
            }
        }
        assertEquals(List.of(), problems, language);
    }
}
