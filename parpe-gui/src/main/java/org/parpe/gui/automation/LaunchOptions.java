package org.parpe.gui.automation;

import java.nio.file.Path;
import java.util.List;

/**
 * What {@code parpe gui} was asked to do.
 *
 * @param file       the script to open, or {@code null}
 * @param runFor     seconds of simulated time to run the script for, or a negative number for no run
 * @param screenshot where to save a picture of the window, or {@code null}
 * @param exit       whether to close the IDE when the automation is done
 * @param bench      whether to print start-up and drawing figures and exit
 * @param posePanel  whether to bring the Pose panel to the front with the poses the script plays
 * @param grid       the gait table to show in the grid editor (selected whole), or {@code null}
 */
public record LaunchOptions(Path file, double runFor, Path screenshot, boolean exit, boolean bench,
                            boolean posePanel, String grid) {

    /** The usage text printed for {@code --help} and bad arguments. */
    public static final String USAGE = String.join("\n",
            "usage: parpe gui [FILE] [--run-for SECONDS] [--screenshot FILE.png] [--exit] [--bench] [--pose-panel]"
                    + " [--grid NAME]",
            "  FILE              PARSL script to open",
            "  --run-for S       run the script in the simulator for S seconds of simulated time",
            "  --screenshot F    save a PNG picture of the window (after the run, if any)",
            "  --exit            close the IDE when done",
            "  --pose-panel      show the Pose panel with the poses of the gait table the script plays (a recording)",
            "  --grid NAME       show gait table NAME in the grid editor, all of it selected",
            "  --bench           print window-up time, 3D frame rate (centipede), the live diagrams during a run and opening a 10 MB script as name=value lines, then exit");

    /** Whether anything automatic is requested. */
    public boolean automated() {
        return runFor >= 0 || screenshot != null || exit || posePanel || grid != null;
    }

    /**
     * Parses the arguments that follow {@code gui}.
     *
     * @throws IllegalArgumentException with a message for the user on a bad argument
     */
    public static LaunchOptions parse(List<String> args) {
        Path file = null;
        double runFor = -1;
        Path shot = null;
        boolean exit = false;
        boolean bench = false;
        boolean posePanel = false;
        String grid = null;
        for (int i = 0; i < args.size(); i++) {
            String a = args.get(i);
            switch (a) {
                case "--run-for" -> runFor = seconds(value(args, i++, a));
                case "--screenshot" -> shot = Path.of(value(args, i++, a));
                case "--exit" -> exit = true;
                case "--bench" -> bench = true;
                case "--pose-panel" -> posePanel = true;
                case "--grid" -> grid = value(args, i++, a);
                default -> {
                    if (a.startsWith("-")) {
                        throw new IllegalArgumentException("unknown option '" + a + "'");
                    }
                    if (file != null) {
                        throw new IllegalArgumentException("only one FILE may be given, got '" + file + "' and '" + a + "'");
                    }
                    file = Path.of(a);
                }
            }
        }
        return new LaunchOptions(file, runFor, shot, exit, bench, posePanel, grid);
    }

    private static String value(List<String> args, int i, String option) {
        if (i + 1 >= args.size()) {
            throw new IllegalArgumentException(option + " needs a value");
        }
        return args.get(i + 1);
    }

    private static double seconds(String text) {
        try {
            double v = Double.parseDouble(text);
            if (!Double.isFinite(v) || v < 0) {
                throw new NumberFormatException();
            }
            return v;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("--run-for must be a number of seconds >= 0, got '" + text + "'");
        }
    }
}
