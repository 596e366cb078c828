package org.parpe.sim.grade;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.run.RunInfo;
import org.parpe.core.run.TargetException;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;
import org.parpe.sim.world.Challenge;
import org.parpe.sim.world.World;
import org.parpe.sim.text.SimMsg;

/**
 * A graded run played back from its trace: the trace's commanded angles ({@code m<ID>}, one row
 * a tick) given, tick by tick, to a simulator of the challenge's robot in its world. The script
 * itself is not run again (it is a student's, untrusted, and the grading JVM is the teacher's):
 * the commanded angles are everything a run gives the simulator, sensors or not, so the robot
 * moves as it did (a script that works docking latches is the exception: latches are not in
 * the trace). Not thread-safe: one thread advances it; {@link #snapshot} may be read from any.
 */
public final class Replay implements AutoCloseable {
    private final Simulator simulator;
    private final double[] time;
    private final double[][] commanded;
    private int next;

    private Replay(Simulator simulator, double[] time, double[][] commanded) {
        this.simulator = simulator;
        this.time = time;
        this.commanded = commanded;
    }

    /**
     * The replay of {@code trace}, a run of challenge {@code c} in {@code world}.
     *
     * @throws IOException     when the trace cannot be read or has no commanded angles (the message says which line)
     * @throws TargetException when the challenge's robot cannot be built for the trace's modules
     */
    public static Replay of(Challenge c, World world, Path trace) throws IOException, TargetException {
        List<double[]> rows = new ArrayList<>();
        int[] ids;
        try (BufferedReader in = Files.newBufferedReader(trace, StandardCharsets.UTF_8)) {
            String header = in.readLine();
            String[] names = header == null ? new String[0] : header.split(",");
            ids = moduleColumns(names);
            if (names.length == 0 || !names[0].equals("time") || ids.length == 0) {
                throw new IOException(trace + ":1: " + SimMsg.REPLAY_NOT_A_TRACE.text());
            }
            int line = 1;
            for (String s = in.readLine(); s != null; s = in.readLine()) {
                line++;
                String[] cells = s.split(",");
                double[] row = new double[ids.length + 1];
                try {
                    for (int k = 0; k <= ids.length; k++) {
                        row[k] = Double.parseDouble(cells[k]);
                    }
                } catch (NumberFormatException | ArrayIndexOutOfBoundsException e) {
                    throw new IOException(trace + ":" + line + ": " + SimMsg.REPLAY_NOT_NUMBERS.text(), e);
                }
                rows.add(row);
            }
        }
        Simulator s = SimTarget.create(c.robot(), ids, new DiagnosticList(), world);
        s.start(new RunInfo(null, ids, c.tick()));
        double[] t = new double[rows.size()];
        double[][] m = new double[rows.size()][];
        for (int k = 0; k < t.length; k++) {
            t[k] = rows.get(k)[0];
            m[k] = java.util.Arrays.copyOfRange(rows.get(k), 1, ids.length + 1);
        }
        return new Replay(s, t, m);
    }

    /** The IDs of the columns {@code m<ID>} that follow {@code time} (the commanded angles). */
    private static int[] moduleColumns(String[] names) {
        int n = 1;
        while (n < names.length && names[n].matches("m\\d+")) {
            n++;
        }
        int[] ids = new int[n - 1];
        for (int k = 1; k < n; k++) {
            ids[k - 1] = Integer.parseInt(names[k].substring(1));
        }
        return ids;
    }

    /** How many ticks the trace holds. */
    public int ticks() {
        return time.length;
    }

    /** The tick {@link #advance} plays next (from 0). */
    public int position() {
        return next;
    }

    /** Plays the next tick of the trace; false when it is over. */
    public boolean advance() {
        if (next >= time.length) {
            return false;
        }
        simulator.accept(next, time[next], commanded[next]);
        next++;
        return true;
    }

    /** The simulated robot and world now; safe from any thread. */
    public SimSnapshot snapshot() {
        return simulator.snapshot();
    }

    /** The centre of mass's x, y now, m. */
    public double[] com() {
        SimSnapshot s = simulator.snapshot();
        return new double[] {s.centerOfMass().x(), s.centerOfMass().y()};
    }

    @Override
    public void close() {
        simulator.close();
    }
}
