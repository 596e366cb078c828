package org.parpe.cli.hw;

import java.io.IOException;
import java.io.PrintStream;
import java.util.List;
import org.parpe.cli.RunSetup;
import org.parpe.cli.RunTarget;
import org.parpe.cli.UsageException;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.SensorSource;
import org.parpe.core.run.TraceColumns;
import org.parpe.serial.bus.Discovery;
import org.parpe.serial.bus.HardwareBus;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.SerialLink;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * The serial-bus options of {@code parpe run}: with {@code --port} the run drives real (or
 * emulated) modules, paced to the wall clock. Before anything moves, the modules of the script
 * are pinged and the missing ones reported; the hardware becomes the sensor source. With
 * {@code --sim} as well, both are driven and {@code --diverge} reports where they disagree.
 * Stopping the run (Ctrl-C) sends an emergency stop.
 */
public class HardwareOptions implements RunTarget {
    @Option(names = "--port", paramLabel = "PATH",
            description = "Drive the modules on this serial device (e.g. /dev/ttyUSB0, or a socat pty).")
    String port;

    @Option(names = "--diverge", paramLabel = "DEG",
            description = "With --port and --sim: report where measured angles of hardware and simulator differ by more.")
    Double diverge;

    @Mixin
    BusOptions bus = new BusOptions();

    @Override
    public void configure(RunSetup setup) throws UsageException, IOException {
        if (port == null) {
            if (diverge != null) {
                throw new UsageException("--diverge compares hardware with the simulator: it needs --port and --sim");
            }
            return;
        }
        if (diverge != null && !(diverge > 0)) {
            throw new UsageException("--diverge must be > 0 degrees, got " + diverge);
        }
        PrintStream err = setup.err();
        HardwareBus hw = HardwareBus.open(LinkOpener.serial(port, bus.baud), bus.config(), err::println);
        setup.closeAtEnd(hw);
        // Ctrl-C: the emergency stop must leave before jSerialComm closes the port at shutdown.
        SerialLink.beforePortsClose(hw::emergencyStopIfRunning);
        int[] ids = setup.program().moduleIds();
        Discovery d = hw.discover(ids);
        reportDiscovery(d, ids.length, err);
        if (d.found().isEmpty()) {
            throw new UsageException("no module answers on " + port + " at " + bus.baud
                    + " baud (is the robot powered and connected, and is --baud right?)");
        }
        setup.addSink(new StopGuard(hw));
        setup.offerSensorSource("hardware", hw, 10);
        setup.addTraceColumns(measuredColumns(hw, ids));
        setup.setRealtime(true);
        if (diverge != null) {
            SensorSource sim = setup.sensorSources().get("sim");
            if (sim == null) {
                throw new UsageException("--diverge compares hardware with the simulator: add --sim");
            }
            setup.addSink(new DivergenceMonitor(sim, hw, diverge, err));
        }
    }

    private void reportDiscovery(Discovery d, int total, PrintStream err) {
        int[] found = d.found().stream().mapToInt(Integer::intValue).toArray();
        err.println("bus " + port + ": " + found.length + " of " + total + " modules answer"
                + (found.length == 0 ? "" : " (" + ModuleList.format(found) + ")"));
        if (!d.missing().isEmpty()) {
            err.println("bus " + port + ": warning: modules " + list(d.missing())
                    + " of the script do not answer; they will not move");
        }
        if (!d.unaddressable().isEmpty()) {
            err.println("bus " + port + ": warning: modules " + list(d.unaddressable())
                    + " cannot be on the bus (IDs 0..254); they will not move");
        }
    }

    private static String list(List<Integer> ids) {
        return ModuleList.format(ids.stream().mapToInt(Integer::intValue).toArray());
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

    /** The bus as a sink, except that a run stopped by the user ends in an emergency stop. */
    private static final class StopGuard implements org.parpe.core.run.JointSink {
        private final HardwareBus hw;

        StopGuard(HardwareBus hw) {
            this.hw = hw;
        }

        @Override
        public void start(org.parpe.core.run.RunInfo info) {
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
