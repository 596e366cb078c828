package org.parpe.cli.hw;

import java.io.PrintStream;
import org.parpe.cli.UsageException;
import org.parpe.core.run.Run;
import org.parpe.core.run.SensorSource;
import org.parpe.core.run.TargetException;
import org.parpe.serial.bus.BusTarget;
import org.parpe.serial.link.SerialLink;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * The serial-bus options of {@code parpe run}: with {@code --port} the run drives real (or
 * emulated) modules through a {@link BusTarget}, paced to the wall clock. With {@code --sim}
 * as well, both are driven and {@code --diverge} reports where they disagree. Stopping the run
 * (Ctrl-C) sends an emergency stop.
 */
public class HardwareOptions {
    @Option(names = "--port", paramLabel = "PATH",
            description = "Drive the modules on this serial device (e.g. /dev/ttyUSB0, or a socat pty).")
    String port;

    @Option(names = "--diverge", paramLabel = "DEG",
            description = "With --port and --sim: report where measured angles of hardware and simulator differ by more.")
    Double diverge;

    @Mixin
    BusOptions bus = new BusOptions();

    /** Attaches the bus to {@code run} when {@code --port} was given (after the simulator, for {@code --diverge}). */
    public void configure(Run.Builder run, PrintStream err) throws UsageException, TargetException {
        if (port == null) {
            if (diverge != null) {
                throw new UsageException("--diverge compares hardware with the simulator: it needs --port and --sim");
            }
            return;
        }
        if (diverge != null && !(diverge > 0)) {
            throw new UsageException("--diverge must be > 0 degrees, got " + diverge);
        }
        SensorSource sim = run.sensorSource("sim");
        if (diverge != null && sim == null) {
            throw new UsageException("--diverge compares hardware with the simulator: add --sim");
        }
        BusTarget target = new BusTarget(port, bus.config(), err::println);
        run.attach(target);
        // Ctrl-C: the emergency stop must leave before jSerialComm closes the port at shutdown.
        SerialLink.beforePortsClose(target.bus()::emergencyStopIfRunning);
        if (diverge != null) {
            run.observer(new DivergenceMonitor(sim, target.bus(), diverge, err));
        }
    }
}
