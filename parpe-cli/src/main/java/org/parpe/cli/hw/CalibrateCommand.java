package org.parpe.cli.hw;

import org.parpe.cli.text.CliMsg;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.parpe.cli.options.ReadsInput;
import org.parpe.cli.options.UsageException;
import org.parpe.core.run.TargetException;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.record.PoseRecorder;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.host.ServoBuses;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ProfileReader;
import org.parpe.serial.servo.profile.ProfileWriter;
import org.parpe.serial.servo.profile.ServoMapping;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code parpe calibrate}: makes every servo of a profile limp, waits for the user to pose the
 * robot in its zero pose and press Enter, then writes each servo's present angle into the
 * profile as its zero offset, and makes the servos hold.
 */
@Command(name = "calibrate", mixinStandardHelpOptions = true, description = {"Set the zero offsets of a hardware profile from the robot posed by hand.",
    "The servos go limp; pose the robot with every joint at 0° and press Enter."})
public final class CalibrateCommand implements ReadsInput, Callable<Integer> {
    @Option(names = "--hardware", required = true, paramLabel = "PROFILE.xml", description = "The profile to calibrate.")
    Path hardware;

    @Option(names = "--port", paramLabel = "PATH", description = "The serial device (replaces the profile's port).")
    String port;

    @Spec
    CommandSpec spec;

    /** Standard input, or what the command line was handed instead ({@link ReadsInput}). */
    InputStream input = System.in;

    @Override
    public void readFrom(InputStream in) {
        input = in;
    }

    @Override
    public Integer call() throws Exception {
        return calibrate(spec.commandLine().getErr());
    }

    private int calibrate(PrintWriter err) throws UsageException, IOException {
        HardwareProfile saved;
        try {
            saved = ProfileReader.load(hardware, null, "--hardware");
        } catch (TargetException e) {
            StringBuilder b = new StringBuilder(e.getMessage() + ":");
            e.diagnostics().forEach(d -> b.append('\n').append(d.format()));
            throw new UsageException(b.toString());
        }
        // --port is for this session: the profile keeps the port it names
        HardwareProfile profile = port == null ? saved : saved.withPort(port);
        if (profile.port() == null) {
            throw new UsageException(CliMsg.NO_SERIAL_PORT.text(hardware));
        }
        ServoBus bus;
        try {
            bus = ServoBuses.open(profile.protocol(), LinkOpener.serial(profile.port(), profile.baud()),
                    BusConfig.defaults().withBaud(profile.baud()));
        } catch (IOException | IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        try {
            return calibrate(profile, saved, new PoseRecorder(bus, profile.servos()), err);
        } finally {
            bus.close();
        }
    }

    private int calibrate(HardwareProfile profile, HardwareProfile saved, PoseRecorder servos, PrintWriter err)
            throws UsageException, IOException {
        List<Integer> missing = servos.missing();
        if (!missing.isEmpty()) {
            throw new UsageException(CliMsg.SERVOS_SILENT.text(missing, profile.port(), profile.protocol().key(), profile.baud()));
        }
        servos.begin();
        err.println("calibrate: " + CliMsg.CALIBRATE_POSE.text());
        err.flush();
        BufferedReader in = new BufferedReader(new InputStreamReader(input, StandardCharsets.UTF_8));
        double[] servo = new double[profile.servos().size()];
        try {
            if (in.readLine() == null) {
                err.println("calibrate: " + CliMsg.CALIBRATE_CANCELLED.text(hardware));
                return 1;
            }
            int silent = servos.captureServoAngles(servo);
            if (silent >= 0) {
                err.println("calibrate: " + CliMsg.CALIBRATE_SILENT.text(silent, hardware));
                return 1;
            }
        } finally {
            servos.end();
        }
        List<ServoMapping> calibrated = new ArrayList<>();
        List<String> unreachable = new ArrayList<>();
        for (int i = 0; i < servo.length; i++) {
            ServoMapping m = profile.servos().get(i);
            ServoMapping c = m.withZero(Math.round(servo[i] * 100) / 100.0);
            if (c.reachable().min() > c.reachable().max()) {
                unreachable.add("calibrate: " + CliMsg.CANNOT_REACH.text(m.module(), num(m.min()), num(m.max()),
                        String.format(Locale.ROOT, "%.2f", c.zero())));
            }
            calibrated.add(c.reachable());
        }
        if (!unreachable.isEmpty()) {
            // checked before anything is written: a profile with min > max is one nothing can load
            unreachable.forEach(err::println);
            err.println("calibrate: " + CliMsg.UNCHANGED.text(hardware));
            return 1;
        }
        for (int i = 0; i < servo.length; i++) {
            ServoMapping m = profile.servos().get(i);
            ServoMapping c = calibrated.get(i);
            String zero = String.format(Locale.ROOT, "%.2f", c.zero());
            String was = String.format(Locale.ROOT, "%.2f", m.zero());
            err.println("calibrate: " + (c.min() == m.min() && c.max() == m.max()
                    ? CliMsg.ZERO_SET.text(m.module(), m.servo(), zero, was)
                    : CliMsg.ZERO_SET_NARROWED.text(m.module(), m.servo(), zero, was, String.format(Locale.ROOT, "%.2f", c.min()),
                            String.format(Locale.ROOT, "%.2f", c.max()))));
        }
        try {
            ProfileWriter.write(saved.withServos(calibrated), hardware, "calibrated by parpe calibrate");
        } catch (IOException e) {
            throw new UsageException(CliMsg.CANNOT_WRITE_HARDWARE.text(hardware, e.getMessage()));
        }
        err.println("calibrate: " + CliMsg.ZEROS_WRITTEN.text(hardware));
        return 0;
    }

    private static String num(double d) {
        return d == Math.rint(d) ? Long.toString((long) d) : String.format(Locale.ROOT, "%.2f", d);
    }
}
