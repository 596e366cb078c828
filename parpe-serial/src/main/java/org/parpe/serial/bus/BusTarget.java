package org.parpe.serial.bus;

import java.io.IOException;
import java.util.function.Consumer;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunInfo;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.RunTarget;
import org.parpe.core.run.TargetException;
import org.parpe.core.run.TraceColumns;
import org.parpe.serial.link.LinkOpener;

/**
 * Modules on a serial bus as a run target, for the command line's {@code --port} and the IDE's
 * Hardware target alike: opens the bus, pings the script's modules before anything moves
 * (reporting the missing ones), and adds the bus as a plant, as the sensor source (priority
 * {@value #PRIORITY}, above the simulator), and as trace columns {@code hw<ID>}. The run is
 * paced to the wall clock. A run stopped by the user ends in an emergency stop. Bus problems
 * become warnings located at {@code bus PORT}; notes (counts, recoveries) go to {@code notes}.
 */
public final class BusTarget implements RunTarget {
    /** Priority of the bus as a sensor source (the simulator has 5). */
    public static final int PRIORITY = 10;

    private final String port;
    private final BusConfig config;
    private final LinkOpener opener;
    private final Consumer<String> notes;
    private HardwareBus bus;

    /** The bus on serial device {@code port} with {@code config}; notes for the user go to {@code notes}. */
    public BusTarget(String port, BusConfig config, Consumer<String> notes) {
        this(port, config, port == null ? null : LinkOpener.serial(port, config.baud()), notes);
    }

    /** The bus reached through {@code opener} (tests, benchmarks), named {@code port} in messages. */
    public BusTarget(String port, BusConfig config, LinkOpener opener, Consumer<String> notes) {
        this.port = port;
        this.config = config;
        this.opener = opener;
        this.notes = notes;
    }

    @Override
    public void attach(Run.Builder run) throws TargetException {
        if (port == null || port.isBlank()) {
            throw new TargetException(SourcePos.origin("hardware"),
                    "no serial port chosen; choose the port the robot is connected to (e.g. /dev/ttyUSB0 or COM3)");
        }
        SourcePos where = SourcePos.origin("bus " + port);
        DiagnosticSink diags = run.diagnostics();
        HardwareBus hw;
        try {
            hw = HardwareBus.open(opener, config, report(where, diags));
        } catch (IOException e) {
            throw new TargetException(where, "cannot open the serial device: " + message(e));
        }
        run.closeAtEnd(hw);
        int[] ids = run.program().moduleIds();
        Discovery d;
        try {
            d = hw.discover(ids);
        } catch (IOException e) {
            throw new TargetException(where, "the bus failed while looking for modules: " + message(e));
        }
        int[] found = d.found().stream().mapToInt(Integer::intValue).toArray();
        notes.accept("bus " + port + ": " + found.length + " of " + ids.length + " modules answer"
                + (found.length == 0 ? "" : " (" + Discovery.format(found) + ")"));
        if (!d.missing().isEmpty()) {
            diags.warning(where, "modules " + Discovery.format(d.missing()) + " of the script do not answer; they will not move");
        }
        if (!d.unaddressable().isEmpty()) {
            diags.warning(where, "modules " + Discovery.format(d.unaddressable())
                    + " cannot be on the bus (IDs 0..254); they will not move");
        }
        if (found.length == 0) {
            throw new TargetException(where, "no module answers on " + port + " at " + config.baud()
                    + " baud (is the robot powered and connected, and is the baud rate right?)");
        }
        run.plant(new StopGuard(hw));
        run.sensorSource("hardware", hw, PRIORITY);
        run.traceColumns(measuredColumns(hw, ids));
        run.requireRealtime();
        bus = hw;
    }

    /** The bus attached last (null before {@link #attach}). */
    public HardwareBus bus() {
        return bus;
    }

    private BusReport report(SourcePos where, DiagnosticSink diags) {
        return new BusReport() {
            @Override
            public void problem(String message) {
                diags.warning(where, message.startsWith("bus: ") ? message.substring(5) : message);
            }

            @Override
            public void note(String message) {
                notes.accept(message);
            }
        };
    }

    private static String message(IOException e) {
        return e.getMessage() == null ? e.toString() : e.getMessage();
    }

    /** Trace columns {@code hw<ID>}: the angle each module last reported (empty until read). */
    private static TraceColumns measuredColumns(HardwareBus hw, int[] ids) {
        String[] names = new String[ids.length];
        for (int i = 0; i < ids.length; i++) {
            names[i] = "hw" + ids[i];
        }
        return new TraceColumns() {
            @Override
            public String[] names() {
                return names.clone();
            }

            @Override
            public void values(double[] out) {
                for (int i = 0; i < ids.length; i++) {
                    out[i] = hw.measuredAngle(i);
                }
            }
        };
    }

    /** The bus as a plant, except that a run stopped by the user ends in an emergency stop. */
    private static final class StopGuard implements JointSink {
        private final HardwareBus hw;

        StopGuard(HardwareBus hw) {
            this.hw = hw;
        }

        @Override
        public void start(RunInfo info) {
            hw.start(info);
        }

        @Override
        public void accept(long tick, double time, double[] commanded) {
            hw.accept(tick, time, commanded);
        }

        @Override
        public void finish(RunOutcome outcome) {
            if (outcome.status() == RunOutcome.Status.STOPPED) {
                hw.emergencyStopIfRunning();
            }
            hw.finish(outcome);
        }
    }
}
