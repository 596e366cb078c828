package org.parpe.cli.grade;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;
import org.parpe.sim.grade.Report;

/**
 * Issue 37's acceptance: a class of 30 scripts, good and bad, graded. Every good script is
 * ranked, every bad one has a row with its reason; no file outside the students' folder and no
 * other student's file is read (checked by the files' access times, which the kernel keeps, not
 * by PARPE's own account); the HTML holds no markup but the page's own; the report is the same
 * with one job or two and on a rerun.
 */
class GradeCommandTest {
    private static final String HYPERLINK = "=HYPERLINK(\"http:x\";\"y\")<script>alert('x')<b>.xml";
    private static final String NEWLINE = "new\nline \"q\".xml";

    @TempDir
    Path dir;

    static String snake(String bend, String main) {
        return "<program>\n  <robot><structure><body elements=\"0..7\"/></structure></robot>\n"
                + "  <parameters><bend value=\"" + bend + "\" min=\"0\" max=\"80\"/></parameters>\n"
                + "  " + main + "\n"
                + "  <behaviors><race><wave group=\"body\" phase=\"0.2\" period=\"1.5\"/></race></behaviors>\n"
                + "  <automata><wave states=\"up, down\"/></automata>\n"
                + "  <states><up angles=\"bend\" interp=\"smooth\"/><down angles=\"-bend\" interp=\"smooth\"/></states>\n"
                + "</program>\n";
    }

    /** The class: 30 students, 18 of them good. Returns the expected reason (a pattern) of each bad one. */
    private Map<String, String> students(Path s) throws Exception {
        Files.createDirectories(s);
        String[] bends = {"10", "15", "20", "20", "25", "30", "35", "40", "45", "50", "55", "60", "65", "70"};
        for (int i = 0; i < bends.length; i++) {
            Files.writeString(s.resolve(String.format("good-%02d.xml", i + 1)), snake(bends[i], "<main><race/></main>"));
        }
        Files.writeString(s.resolve(HYPERLINK), snake("30", "<main><race/></main>"));
        Files.writeString(s.resolve(NEWLINE), snake("30", "<main><race/></main>"));
        Files.writeString(s.resolve("forever.xml"), snake("35", "<main cycles=\"forever\"><race/></main>"));
        Path other = Files.createDirectories(s.resolve("other-student"));
        Files.writeString(other.resolve("main.xml"), snake("40", "<main><race/></main>"));
        Files.writeString(other.resolve("x.xml"), "<program><parameters><speed value=\"1\"/></parameters></program>");
        Map<String, String> bad = new LinkedHashMap<>();
        Files.writeString(s.resolve("err-malformed.xml"), "<program>\n  <robot>\n</program>\n");
        bad.put("err-malformed.xml", "err-malformed\\.xml:3:\\d+: error: .*");
        Files.writeString(s.resolve("err-section.xml"), snake("20", "<main><race/></main>").replace("<automata>", "<automaton>")
                .replace("</automata>", "</automaton>"));
        bad.put("err-section.xml", "(?s)err-section\\.xml:\\d+:\\d+: error: unknown section <automaton>.*");
        Files.writeString(s.resolve("err-norobot.xml"), "<program>\n  <main/>\n</program>\n");
        bad.put("err-norobot.xml", "(?s)err-norobot\\.xml:1:2: error: the program has no <robot> section.*");
        Files.writeString(s.resolve("err-expr.xml"), snake("20 +* 3", "<main><race/></main>"));
        bad.put("err-expr.xml", "(?s)err-expr\\.xml:3:\\d+: error: .*");
        Files.writeString(s.resolve("err-empty.xml"), "");
        bad.put("err-empty.xml", "err-empty\\.xml:1:1: error: the file holds no script yet.*");
        try (RandomAccessFile f = new RandomAccessFile(s.resolve("huge.xml").toFile(), "rw")) {
            f.write("<program>".getBytes());
            f.setLength(50L << 20);
        }
        bad.put("huge.xml", "cannot read 'huge\\.xml': it is 52428800 bytes, larger than the limit of 16 MiB for an input file");
        Path includer = Files.createDirectories(s.resolve("includer"));
        Files.writeString(includer.resolve("main.xml"), snake("20", "<include file=\"../other-student/x.xml\"/><main><race/></main>"));
        bad.put("includer", "(?s)includer/main\\.xml:4:\\d+: error: cannot include '\\.\\./other-student/x\\.xml': a graded script"
                + " may only read files inside its own folder 'includer' \\(the confinement rule of parpe grade\\).*");
        Files.writeString(s.resolve("passwd.xml"), "<program>\n  <robot file=\"/etc/passwd\"/>\n  <main/>\n</program>\n");
        bad.put("passwd.xml", "passwd\\.xml:2:16: error: cannot read robot file '/etc/passwd': a graded script handed in as a"
                + " lone file may read no other file \\(the confinement rule of parpe grade\\)");
        Files.writeString(s.resolve("secret.xml"), "<program>\n  <robot file=\"../secret/robot.xml\"/>\n  <main/>\n</program>\n");
        bad.put("secret.xml", "secret\\.xml:2:16: error: cannot read robot file '.*secret/robot\\.xml': .*confinement rule.*");
        Files.createSymbolicLink(s.resolve("link.xml"), dir.resolve("secret/robot.xml"));
        bad.put("link.xml", "it is a link, not a file or folder handed in \\(the confinement rule of parpe grade\\)");
        Files.writeString(s.resolve("modules.xml"), snake("20", "<main><race/></main>").replace("0..7", "0..9999"));
        bad.put("modules.xml", "modules\\.xml: error: the robot has 10000 modules; this challenge allows at most 8 \\(max-modules\\)");
        Files.writeString(s.resolve("runtime.xml"), snake("20", "<main><race/></main>").replace("angles=\"bend\"",
                "angles=\"bend * sqrt(0.5 - $time)\""));
        bad.put("runtime.xml", "(?s)runtime\\.xml:7:\\d+: error: sqrt\\(\\) of .*");
        return bad;
    }

    private Path challenge() throws Exception {
        return challenge(2);
    }

    private Path challenge(double duration) throws Exception {
        Path world = Path.of("../examples/worlds/race-track.xml").toAbsolutePath().normalize();
        Path c = dir.resolve("race.xml");
        Files.writeString(c, "<challenge world=\"" + world + "\" robot=\"snake:n=8\" duration=\"" + duration
                + "\" tick=\"0.01\""
                + " max-modules=\"8\" tie-break=\"distance\"/>\n");
        return c;
    }

    /** The CSV's rows as cells (quoted cells may hold commas, quotes and newlines). */
    static List<List<String>> parse(String csv) {
        List<List<String>> rows = new ArrayList<>();
        List<String> row = new ArrayList<>();
        StringBuilder cell = new StringBuilder();
        boolean quoted = false;
        for (int i = 0; i < csv.length(); i++) {
            char ch = csv.charAt(i);
            if (quoted) {
                if (ch == '"' && i + 1 < csv.length() && csv.charAt(i + 1) == '"') {
                    cell.append('"');
                    i++;
                } else if (ch == '"') {
                    quoted = false;
                } else {
                    cell.append(ch);
                }
            } else if (ch == '"') {
                quoted = true;
            } else if (ch == ',' || ch == '\n') {
                row.add(cell.toString());
                cell.setLength(0);
                if (ch == '\n') {
                    rows.add(row);
                    row = new ArrayList<>();
                }
            } else {
                cell.append(ch);
            }
        }
        return rows;
    }

    @Test
    void aClassOfThirtyIsGradedTheSameWithOneJobOrTwo() throws Exception {
        Path s = dir.resolve("students");
        Map<String, String> bad = students(s);
        Path secret = Files.createDirectories(dir.resolve("secret"));
        Files.writeString(secret.resolve("robot.xml"), "<robot><structure><body elements=\"0..7\"/></structure></robot>");
        List<Path> untouchable = List.of(secret.resolve("robot.xml"), s.resolve("other-student/x.xml"));
        FileTime old = FileTime.fromMillis(946684800000L); // 2000-01-01: older than the files' change times
        for (Path p : untouchable) {
            Files.setAttribute(p, "lastAccessTime", old);
        }
        Path control = Files.writeString(dir.resolve("control.txt"), "read me");
        Files.setAttribute(control, "lastAccessTime", old);
        Files.readString(control); // a read moves the access time on this file system (relatime), or the check proves nothing
        assertFalse(old.equals(Files.getAttribute(control, "lastAccessTime")), "access times are not kept here");

        Path c = challenge();
        Cli one = Cli.run("grade", c.toString(), s.toString(), "--out", dir.resolve("r1").toString(), "--jobs", "1",
                "--memory", "256");
        assertEquals(0, one.code, one.toString());
        for (Path p : untouchable) {
            assertEquals(old, Files.getAttribute(p, "lastAccessTime"), p + " was read");
        }
        List<List<String>> rows = parse(Files.readString(dir.resolve("r1/report.csv")));
        assertEquals(List.of(Report.HEADER.split(",")), rows.get(0));
        assertEquals(31, rows.size(), rows.toString());
        Map<String, List<String>> byName = new LinkedHashMap<>();
        rows.subList(1, 31).forEach(r -> byName.put(r.get(1), r));
        for (Map.Entry<String, String> b : bad.entrySet()) {
            List<String> r = byName.get(b.getKey());
            assertEquals("", r.get(0), "not ranked: " + r);
            assertTrue(r.get(10).matches(b.getValue()), b.getKey() + ": " + r.get(10));
        }
        List<List<String>> ranked = rows.subList(1, 31).stream().filter(r -> !r.get(0).isEmpty()).toList();
        assertEquals(18, ranked.size(), ranked.toString());
        ranked.forEach(r -> assertEquals("", r.get(10), r.toString()));
        ranked.forEach(r -> assertEquals("2.00", r.get(8), r.toString()));
        // a run that ended with a run-time error keeps its trace, whatever words its reason has (they are the teacher's language)
        String runtimeTrace = byName.get("runtime.xml").get(9);
        assertTrue(runtimeTrace.startsWith("traces/") && Files.isRegularFile(dir.resolve("r1").resolve(runtimeTrace)),
                "the run-time error's trace: " + byName.get("runtime.xml"));
        assertTrue(byName.containsKey("'" + HYPERLINK), "the formula name is made safe: " + byName.keySet());
        assertTrue(byName.containsKey(NEWLINE), byName.keySet().toString());
        List<String> tie = List.of(byName.get("good-03.xml").get(0), byName.get("good-04.xml").get(0));
        assertEquals(tie.get(0), tie.get(1), "equal runs share a rank");
        int shared = Integer.parseInt(tie.get(0));
        assertTrue(ranked.stream().noneMatch(r -> r.get(0).equals(Integer.toString(shared + 1))), "the next rank is skipped");

        String html = Files.readString(dir.resolve("r1/report.html"));
        assertOnlyOwnMarkup(html);
        assertTrue(html.contains("=HYPERLINK(&quot;http:x&quot;;&quot;y&quot;)&lt;script&gt;alert(&#39;x&#39;)&lt;b&gt;.xml"));

        Cli two = Cli.run("grade", c.toString(), s.toString(), "--out", dir.resolve("r2").toString(), "--jobs", "2",
                "--memory", "256");
        assertEquals(0, two.code, two.toString());
        assertSameFiles(dir.resolve("r1"), dir.resolve("r2"));
        Cli again = Cli.run("grade", c.toString(), s.toString(), "--out", dir.resolve("r2").toString(), "--jobs", "2",
                "--memory", "256");
        assertEquals(0, again.code, again.toString());
        assertSameFiles(dir.resolve("r1"), dir.resolve("r2"));
        assertFalse(one.err.contains("Exception") || one.err.contains("\tat "), one.err);
    }

    @Test
    void aRunPastItsCpuLimitIsStoppedAndCostsOnlyItsRow() throws Exception {
        Path s = Files.createDirectories(dir.resolve("students"));
        Files.writeString(s.resolve("slow.xml"), snake("30", "<main cycles=\"forever\"><race/></main>"));
        // an hour of simulated time: far more than 0.3 s of CPU however fast the simulator gets
        Cli r = Cli.run("grade", challenge(3600).toString(), s.toString(), "--out", dir.resolve("r").toString(),
                "--cpu-limit", "0.3", "--memory", "128");
        assertEquals(0, r.code, r.toString());
        List<List<String>> rows = parse(Files.readString(dir.resolve("r/report.csv")));
        assertEquals(List.of("", "slow.xml", "slow.xml", "", "", "", "", "", "", "",
                "stopped after 0.30 s of CPU time (the limit, --cpu-limit)"), rows.get(1));
        try (Stream<Path> left = Files.list(dir.resolve("r/traces"))) {
            assertEquals(List.of(), left.toList(), "no partial trace is left");
        }
    }

    @Test
    void aRunPastItsMemoryLimitCostsOnlyItsRow() throws Exception {
        Path s = Files.createDirectories(dir.resolve("students"));
        StringBuilder big = new StringBuilder("<program>\n<robot><structure>\n");
        for (int i = 0; i < 300_000; i++) {
            big.append("<g").append(i).append(" elements=\"").append(i).append("\"/>\n");
        }
        Files.writeString(s.resolve("big.xml"), big.append("</structure></robot>\n<main/>\n</program>\n"));
        Files.writeString(s.resolve("good.xml"), snake("30", "<main><race/></main>"));
        Cli r = Cli.run("grade", challenge().toString(), s.toString(), "--out", dir.resolve("r").toString(), "--memory", "64");
        assertEquals(0, r.code, r.toString());
        List<List<String>> rows = parse(Files.readString(dir.resolve("r/report.csv")));
        assertEquals("1", rows.get(1).get(0), rows.toString());
        assertEquals(List.of("", "big.xml", "big.xml", "", "", "", "", "", "", "",
                "the run ran out of memory (the limit is 64 MB, --memory)"), rows.get(2));
    }

    @Test
    void aFixedParameterReachesEveryScriptOrItsRowSaysWhyNot() throws Exception {
        Path s = Files.createDirectories(dir.resolve("students"));
        Files.writeString(s.resolve("a.xml"), snake("10", "<main><race/></main>"));
        Files.writeString(s.resolve("b.xml"), snake("60", "<main><race/></main>"));
        Files.writeString(s.resolve("narrow.xml"), snake("10", "<main><race/></main>").replace("max=\"80\"", "max=\"20\""));
        Path c = Files.writeString(dir.resolve("fixed.xml"), Files.readString(challenge()).replace("/>",
                "><parameter name=\"bend\" value=\"40\"/><parameter name=\"speed\" value=\"2\"/></challenge>"));
        Cli r = Cli.run("grade", c.toString(), s.toString(), "--out", dir.resolve("r").toString());
        assertEquals(0, r.code, r.toString());
        List<List<String>> rows = parse(Files.readString(dir.resolve("r/report.csv")));
        assertEquals(List.of("1", "1", ""), List.of(rows.get(1).get(0), rows.get(2).get(0), rows.get(3).get(0)), rows.toString());
        assertEquals(rows.get(1).subList(3, 9), rows.get(2).subList(3, 9), "both ran with bend 40");
        assertTrue(rows.get(3).get(10).matches("narrow\\.xml:3:\\d+: error: .*40.*\\n\\(the challenge fixes this parameter's value\\)"),
                rows.get(3).get(10));
    }

    @Test
    void nobodyRunsAnotherStudentsScriptThroughALink() throws Exception {
        Path s = Files.createDirectories(dir.resolve("students"));
        Files.writeString(s.resolve("good.xml"), snake("30", "<main><race/></main>"));
        Files.createSymbolicLink(Files.createDirectories(s.resolve("copycat")).resolve("main.xml"), s.resolve("good.xml"));
        Files.createSymbolicLink(s.resolve("twin.xml"), s.resolve("good.xml"));
        Cli r = Cli.run("grade", challenge().toString(), s.toString(), "--out", dir.resolve("r").toString());
        assertEquals(0, r.code, r.toString());
        List<List<String>> rows = parse(Files.readString(dir.resolve("r/report.csv")));
        assertEquals(List.of("1", "good.xml"), rows.get(1).subList(0, 2), rows.toString());
        assertEquals(List.of("", "copycat"), rows.get(2).subList(0, 2), rows.toString());
        assertTrue(rows.get(2).get(10).matches("copycat/main\\.xml:1:1: error: cannot read file 'copycat/main\\.xml': a graded"
                + " script may only read files inside its own folder 'copycat' \\(the confinement rule of parpe grade\\)"),
                rows.get(2).get(10));
        assertEquals(List.of("", "twin.xml"), rows.get(3).subList(0, 2), rows.toString());
        assertEquals("it is a link, not a file or folder handed in (the confinement rule of parpe grade)", rows.get(3).get(10));
    }

    @Test
    void checkKnowsAChallengeAndLocatesItsErrors() throws Exception {
        Cli ok = Cli.run("check", "../examples/challenges/race-track.xml", "../examples/challenges/rubble.xml",
                "../examples/challenges/slot-machine.xml");
        assertEquals(0, ok.code, ok.toString());
        assertEquals(3, ok.out.split("ok \\(challenge\\)").length - 1, ok.out);
        Path bad = Files.writeString(dir.resolve("bad.xml"), "<challenge world=\"nowhere.xml\" robot=\"snake\"\n"
                + "  tie-break=\"coin\" laps=\"3\">\n  <parameter name=\"bend\"/>\n</challenge>\n");
        Cli no = Cli.run("check", bad.toString());
        assertEquals(1, no.code, no.toString());
        assertTrue(no.err.contains("bad.xml:1:1: error: <challenge> has no attribute 'laps'"), no.err);
        assertTrue(no.err.contains("bad.xml:1:1: error: tie-break must be 'distance' or 'none', got 'coin'"), no.err);
        assertTrue(no.err.contains("bad.xml:3:3: error: <parameter> needs the attribute 'value'"), no.err);
        Cli grade = Cli.run("grade", bad.toString(), dir.toString(), "--out", dir.resolve("r").toString());
        assertEquals(2, grade.code, grade.toString());
        assertTrue(grade.err.contains("has errors (above)"), grade.err);
        Cli inside = Cli.run("grade", "../examples/challenges/race-track.xml", dir.toString(), "--out",
                dir.resolve("new/report").toString());
        assertEquals(2, inside.code, inside.toString());
        assertTrue(inside.err.contains("--out must not be inside the students' folder"), inside.err);
        assertFalse(Files.exists(dir.resolve("new")), "nothing is made in the students' folder");
    }

    private static final Set<String> TAGS = Set.of("html", "head", "meta", "title", "style", "body", "h1", "p", "svg",
            "rect", "polygon", "circle", "polyline", "table", "tr", "th", "td", "span", "a", "pre");

    /** Every '<' of the page opens or closes one of the page's own elements: nothing from a name or message is markup. */
    static void assertOnlyOwnMarkup(String html) {
        Matcher m = Pattern.compile("<(/?)([^\\s>/]*)").matcher(html);
        while (m.find()) {
            String tag = m.group(2);
            assertTrue(TAGS.contains(tag) || tag.equals("!DOCTYPE") && m.start() == 0, "markup <" + m.group(1) + tag + "> at "
                    + m.start() + ": " + html.substring(Math.max(0, m.start() - 80), Math.min(html.length(), m.start() + 80)));
        }
        assertFalse(html.contains("<script"), "no script element");
    }

    private static void assertSameFiles(Path a, Path b) throws Exception {
        List<Path> files;
        try (Stream<Path> w = Files.walk(a)) {
            files = w.filter(Files::isRegularFile).map(a::relativize).sorted().toList();
        }
        try (Stream<Path> w = Files.walk(b)) {
            assertEquals(files, w.filter(Files::isRegularFile).map(b::relativize).sorted().toList());
        }
        assertTrue(files.contains(Path.of("report.csv")) && files.contains(Path.of("report.html")), files.toString());
        for (Path f : files) {
            assertArrayEquals(Files.readAllBytes(a.resolve(f)), Files.readAllBytes(b.resolve(f)), f.toString());
        }
    }
}
