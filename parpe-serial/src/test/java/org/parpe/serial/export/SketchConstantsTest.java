package org.parpe.serial.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.export.Board;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;

/**
 * Issue 32 item 5: the numbers the sketch's board code and the export's cost model share are
 * declared once, in {@link SketchConstants}, and generated into {@code parsl_servo.h}, as
 * core's {@code CLayoutTest} holds for the tables. Before, {@code sketch.inc} sized its console
 * rings and packet buffer with literals and declared {@code BUS_WINDOW_US} itself while
 * {@link SketchOptions#cost} counted the same bytes and cycles from numbers of its own.
 */
class SketchConstantsTest {
    private static final Pattern DEFINE = Pattern.compile("(?m)^\\s*#\\s*define\\s+(\\w+)");
    private static final Pattern ENUM = Pattern.compile("enum\\s*\\{([^}]*)\\}");

    private static final String SNAKE = """
            <program>
              <robot><structure><body elements="0..3"/></structure></robot>
              <main><go/></main>
              <behaviors><go><wave group="body" phase="0.25" period="2"/></go></behaviors>
              <automata><wave states="a, b"/></automata>
              <states><a angles="20"/><b angles="-20"/></states>
            </program>
            """;

    private static Set<String> declared(String c) {
        Set<String> names = new TreeSet<>();
        Matcher d = DEFINE.matcher(c);
        while (d.find()) {
            names.add(d.group(1));
        }
        Matcher m = ENUM.matcher(c);
        while (m.find()) {
            for (String member : m.group(1).split(",")) {
                String name = member.replaceAll("/\\*.*?\\*/", "").split("=")[0].trim();
                if (!name.isEmpty()) {
                    names.add(name);
                }
            }
        }
        return names;
    }

    private static ProgramExport.Result sketch(String servo) {
        LoadResult r = ScriptLoader.loadText(Path.of("snake.xml"), SNAKE, Map.of());
        Program p = r.program();
        assertNotNull(p, () -> r.diagnostics().toString());
        DiagnosticList d = new DiagnosticList();
        ProgramExport.Result x = ProgramExport.export(p, new ProgramExport.Request(ProgramExport.Target.ARDUINO,
                Board.UNO, 0.01, SketchOptions.of(servo, List.of(), 1_000_000, null, false)), d);
        assertNotNull(x, () -> d.all().toString());
        return x;
    }

    @Test
    void theBoardCodeDeclaresNoneOfTheGeneratedNames() {
        String board = ArduinoSketch.boardCode();
        for (String servo : List.of("pwm", "dxl", "sts")) {
            ProgramExport.Result x = sketch(servo);
            Set<String> generated = declared(x.files().get("parsl_servo.h"));
            generated.addAll(declared(x.files().get("parsl_program.h")));
            assertTrue(generated.contains("PARSL_BUS_WINDOW_US"), generated::toString);
            Set<String> own = declared(board);
            own.retainAll(generated);
            assertEquals(Set.of(), own, "declared both in sketch.inc and in a generated header");
        }
        assertTrue(!declared(board).contains("BUS_WINDOW_US"), "sketch.inc declares the alarm's window itself");
    }

    @Test
    void theBuffersTheCostModelCountsAreSizedByTheGeneratedConstants() {
        String board = ArduinoSketch.boardCode();
        String servoH = sketch("dxl").files().get("parsl_servo.h");
        Map<String, String> arrays = Map.of("in_ring", "PARSL_CONSOLE_IN_RING", "out_ring", "PARSL_CONSOLE_OUT_RING",
                "packet", "PARSL_PACKET_HEADER + PARSL_N * PARSL_PACKET_PER_SERVO");
        arrays.forEach((array, size) -> {
            Matcher m = Pattern.compile("static uint8_t " + array + "\\[([^\\]]*)\\];").matcher(board);
            assertTrue(m.find(), array + " in sketch.inc");
            assertEquals(size, m.group(1), array + " is sized by the generated constants");
        });
        assertTrue(servoH.contains("#define PARSL_CONSOLE_IN_RING " + SketchConstants.CONSOLE_IN_RING + "\n"), servoH);
        assertTrue(servoH.contains("#define PARSL_CONSOLE_OUT_RING " + SketchConstants.CONSOLE_OUT_RING + "\n"), servoH);
        // Xl430's goal position is 4 bytes: an entry is ID and goal, doubled for byte stuffing.
        assertTrue(servoH.contains("#define PARSL_PACKET_PER_SERVO 10\n"), servoH);
        assertTrue(servoH.contains("#define PARSL_BUS_WINDOW_US " + SketchConstants.BUS_WINDOW_US + "u\n"), servoH);
        assertEquals(16 + 4 * 10 + 64 + 128 + 9, sketch("dxl").memory().boardBytes() - Board.UNO.boardRam(),
                "the driver's RAM in the estimate: packet for 4 servos and the console");
    }
}
