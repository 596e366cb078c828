package org.parpe.cli.hw;

import org.parpe.cli.text.CliMsg;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import org.parpe.cli.options.UsageException;
import org.parpe.core.run.Run;
import org.parpe.core.run.SensorSource;
import org.parpe.core.run.SourceKind;
import org.parpe.core.run.TargetException;
import org.parpe.serial.link.SerialLink;
import org.parpe.serial.servo.run.ServoTarget;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * The serial-bus options of {@code parpe run}: the run drives, through a {@link ServoTarget} and
 * paced to the wall clock, with {@code --port} alone the script's G1 modules (real or emulated),
 * with {@code --hardware} the servos of a hardware profile (any protocol). With {@code --sim}
 * as well, both are driven and {@code --diverge} reports where they disagree. Stopping the run
 * (Ctrl-C) sends an emergency stop.
 */
public class HardwareOptions {
    @Option(names = "--port", paramLabel = "PATH",
            description = "Drive the modules on this serial device (e.g. /dev/ttyUSB0, or a socat pty); without "
                    + "--hardware, PARPE's G1 modules; with it, overrides the profile's port.")
    String port;

    @Option(names = "--hardware", paramLabel = "PROFILE.xml",
            description = "Drive the servos of this hardware profile (Dynamixel 2.0, Feetech STS/SCS or G1; "
                    + "docs/hardware-profile.md). Protocol, baud, limits and on-fault come from the profile.")
    Path hardware;

    @Option(names = "--diverge", paramLabel = "DEG",
            description = "With --port and --sim: report where measured angles of hardware and simulator differ by more.")
    Double diverge;

    @Mixin
    BusOptions bus = new BusOptions();

    /** Attaches the bus to {@code run} when {@code --port} was given (after the simulator, for {@code --diverge}). */
    /** Adds the hardware profile, a file the run reads, to {@code inputs}. */
    public void addInputs(List<Path> inputs) {
        if (hardware != null) {
            inputs.add(hardware);
        }
    }

    public void configure(Run.Builder run, PrintStream err) throws UsageException, TargetException {
        if (hardware == null && port == null) {
            if (diverge != null) {
                throw new UsageException(CliMsg.DIVERGE_NEEDS_PORT_SIM.text());
            }
            return;
        }
        SensorSource sim = run.sensorSource(SourceKind.SIMULATOR);
        checkDiverge(sim);
        ServoTarget target = ServoTarget.open(hardware, port, "--hardware", bus.config(), err::println);
        run.attach(target);
        // Ctrl-C: the emergency stop must leave before jSerialComm closes the port at shutdown.
        SerialLink.beforePortsClose(target.driver()::emergencyStopIfRunning);
        if (diverge != null) {
            run.observer(new DivergenceMonitor(sim, target.driver()::measuredAngle, diverge, err));
        }
    }

    private void checkDiverge(SensorSource sim) throws UsageException {
        if (diverge != null && !(diverge > 0)) {
            throw new UsageException(CliMsg.DIVERGE_POSITIVE.text(diverge));
        }
        if (diverge != null && sim == null) {
            throw new UsageException(CliMsg.DIVERGE_NEEDS_SIM.text());
        }
    }
}
