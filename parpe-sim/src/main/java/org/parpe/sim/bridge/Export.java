package org.parpe.sim.bridge;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.io.AtomicFiles;
import org.parpe.core.io.Content;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;
import org.parpe.sim.internal.Assembly;
import org.parpe.sim.text.SimMsg;

/**
 * A robot exported to MJCF, URDF or SDF, as {@code parpe export --target mjcf|urdf|sdf} and the
 * IDE's File → Export Robot… both do it: the robot resolved as {@code --sim} takes it, its names
 * checked for the format, and its files written into a folder as one (every file in full before
 * any replaces its old version), so a refused or failed export leaves the folder as it was.
 */
public final class Export {
    /** The formats, as {@code --target} names them. */
    public static final List<String> TARGETS = List.of("mjcf", "urdf", "sdf");

    private Export() {
    }

    /** A robot ready to write: its model, the files' base name and the robot's file (name → text). */
    public record Robot(RobotModel model, String base, Map<String, String> files, List<Latches.Pair> latches) {
        /** One line on what the robot holds: links, servo joints, loops, and the plate pairs that can latch. */
        public String summary() {
            long servos = model.joints().stream().filter(RobotModel.Joint::revolute).count();
            int loops = model.closures().size();
            String robot = SimMsg.EXPORT_SUMMARY.text(model.links().size(), servos,
                    (loops == 1 ? SimMsg.EXPORT_LOOP : SimMsg.EXPORT_LOOPS).text(loops));
            return latches.isEmpty() ? robot : SimMsg.EXPORT_SUMMARY_LATCHES.text(robot,
                    (latches.size() == 1 ? SimMsg.EXPORT_LATCH_PAIR : SimMsg.EXPORT_LATCH_PAIRS).text(latches.size()));
        }
    }

    /** {@link #robot(String, String, int[], Set, DiagnosticList)} for a robot without latches. */
    public static Robot robot(String target, String robot, int[] moduleIds, DiagnosticList diags) {
        return robot(target, robot, moduleIds, Set.of(), diags);
    }

    /**
     * The robot {@code robot} ({@code --sim}'s configuration file or generator, sized for the
     * script's {@code moduleIds}) in {@code target}'s format, or null with located errors in
     * {@code diags} (a configuration with errors, names the format cannot carry, more than one robot).
     * In MJCF, the free plates of the {@code latchModules} (the script's modules with the
     * {@code latch} actuator, PARSL.md §14) are written as switched welds ({@link Latches}).
     */
    public static Robot robot(String target, String robot, int[] moduleIds, Set<Integer> latchModules,
                              DiagnosticList diags) {
        RobotConfig config = RobotConfigs.resolve(robot, moduleIds, diags);
        Assembly a = config == null ? null : Assembly.build(config, diags);
        if (a != null) {
            checkNames(config, target, diags);
            if (config.roots().size() > 1) {
                diags.error(SourcePos.origin(config.name()), SimMsg.EXPORT_ROBOTS, config.roots().size());
            }
        }
        if (diags.hasErrors()) {
            return null;
        }
        RobotModel m = RobotModel.of(config, a);
        String base = baseName(robot);
        List<Latches.Pair> latches = target.equals("mjcf") ? Latches.of(a, latchModules) : List.of();
        Map<String, String> files = new LinkedHashMap<>();
        switch (target) {
            case "mjcf" -> files.put(base + ".xml", Mjcf.of(m, latches));
            case "urdf" -> files.put(base + ".urdf", Urdf.of(m));
            case "sdf" -> files.put(base + ".sdf", Sdf.of(m));
            default -> throw new IllegalArgumentException("target " + target);
        }
        return new Robot(m, base, files, latches);
    }

    /**
     * Why the files {@code names} cannot be written into {@code dir} (it is a file, or one of the
     * names is taken by something other than a regular file), or null when they can.
     */
    public static String refusal(Path dir, Collection<String> names) {
        if (Files.exists(dir) && !Files.isDirectory(dir)) {
            return SimMsg.EXPORT_DIR_IS_FILE.text(dir);
        }
        for (String name : names) {
            Path p = dir.resolve(name);
            if (Files.exists(p, LinkOption.NOFOLLOW_LINKS) && !Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
                return SimMsg.EXPORT_NOT_REGULAR.text(p);
            }
        }
        return null;
    }

    /**
     * Writes {@code files} (name → text) into {@code dir}, creating it, all or nothing; the caller
     * has asked {@link #refusal} first.
     */
    public static void write(Path dir, Map<String, String> files) throws IOException {
        Files.createDirectories(dir);
        Map<Path, Content> contents = new LinkedHashMap<>();
        files.forEach((name, text) -> contents.put(dir.resolve(name), Content.text(text)));
        AtomicFiles.writeAll(contents);
    }

    /** Refuses part names that the format cannot carry, at the part. */
    private static void checkNames(RobotConfig config, String target, DiagnosticSink diags) {
        for (PartSpec p : config.parts()) {
            if (!validName(p.name()) || p.name().equals("world")) {
                diags.error(p.pos(), SimMsg.EXPORT_PART_NAME, p.name(), target.toUpperCase(Locale.ROOT));
            }
        }
    }

    /** Whether every format takes {@code name}: ASCII letters, digits, {@code _ . -}, not starting with a digit or {@code . -}. */
    static boolean validName(String name) {
        if (name.isEmpty()) {
            return false;
        }
        for (int i = 0; i < name.length(); i++) {
            char c = name.charAt(i);
            boolean letter = c >= 'A' && c <= 'Z' || c >= 'a' && c <= 'z' || c == '_';
            boolean other = c >= '0' && c <= '9' || c == '.' || c == '-';
            if (!letter && (i == 0 || !other)) {
                return false;
            }
        }
        return true;
    }

    private static String baseName(String robot) {
        String name = Path.of(robot).getFileName().toString().replaceFirst("\\.xml$", "");
        name = name.replaceAll("[^A-Za-z0-9_.-]", "_");
        return name.isEmpty() ? "robot" : name;
    }
}
