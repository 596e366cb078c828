package org.parpe.cli.hw;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.parpe.cli.UsageException;
import org.parpe.core.diag.SourcePos;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.host.ServoBuses;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ProfileWriter;
import org.parpe.serial.servo.profile.ServoMapping;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code parpe scan}: finds the servos on a serial device by pinging every ID, for one protocol or
 * all, at one baud rate or all common ones (stopping at the first that finds servos); prints ID,
 * model and position of each, and writes a starter hardware profile with one module per servo.
 */
@Command(name = "scan", mixinStandardHelpOptions = true, description = {"Find Dynamixel 2.0, Feetech STS/SCS or G1 servos on a serial device and write "
    + "a starter hardware profile.", "Without --protocol every protocol is tried, without --baud every common baud rate."})
public final class ScanCommand implements Callable<Integer> {
    /** A reply takes 2.5 ms at 57 600 baud, plus the servo's return delay and a loaded host's latency. */
    private static final int PING_TIMEOUT_MS = 10;

    @Option(names = "--port", required = true, paramLabel = "PATH", description = "The serial device.")
    String port;

    @Option(names = "--protocol", paramLabel = "dxl2|sts|scs|g1", description = "Only this protocol.")
    String protocol;

    @Option(names = "--baud", paramLabel = "N", description = "Only this line speed.")
    Integer baud;

    @Option(names = "--ids", defaultValue = "0..253", paramLabel = "IDS",
            description = "Servo IDs to ping (default ${DEFAULT-VALUE}).")
    String ids;

    @Option(names = "--out", defaultValue = "hardware.xml", paramLabel = "FILE.xml",
            description = "The starter profile to write (default ${DEFAULT-VALUE}); an existing file is kept unless --force.")
    Path out;

    @Option(names = "--force", description = "Overwrite --out if it exists.")
    boolean force;

    @Spec
    CommandSpec spec;

    /** One servo found. */
    private record Found(int id, int modelNumber, ServoModel model, double degrees) {
    }

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        try {
            return scan(stdout, err);
        } catch (UsageException e) {
            err.println("parpe: " + e.getMessage());
            return 2;
        }
    }

    private int scan(PrintWriter stdout, PrintWriter err) throws UsageException {
        List<ServoProtocol> protocols = protocols();
        int[] wanted = ModuleList.sorted(ModuleList.parse(ids, "--ids"));
        if (Files.exists(out) && !force) {
            throw new UsageException("'" + out + "' exists; choose another --out or add --force");
        }
        for (ServoProtocol p : protocols) {
            for (int rate : baud == null ? p.scanBauds() : List.of(baud)) {
                err.println(String.format(Locale.ROOT, "scan: %s at %d baud, IDs %s ...", p.key(), rate,
                        ModuleList.format(wanted)));
                List<Found> found = scanOne(p, rate, wanted);
                if (!found.isEmpty()) {
                    report(p, rate, found, stdout, err);
                    return 0;
                }
            }
        }
        err.println("scan: no servo answers on " + port + " (is the robot powered? is the adapter for this bus?)");
        return 1;
    }

    private List<ServoProtocol> protocols() throws UsageException {
        if (protocol == null) {
            return List.of(ServoProtocol.DXL2, ServoProtocol.STS, ServoProtocol.SCS, ServoProtocol.G1);
        }
        ServoProtocol p = ServoProtocol.of(protocol);
        if (p == null) {
            throw new UsageException("--protocol must be one of " + ServoProtocol.keys() + ", got '" + protocol + "'");
        }
        return List.of(p);
    }

    private List<Found> scanOne(ServoProtocol p, int rate, int[] wanted) throws UsageException {
        List<Found> found = new ArrayList<>();
        int max = p == ServoProtocol.G1 ? 254 : 253;
        if (wanted.length > 0 && wanted[wanted.length - 1] > max) {
            throw new UsageException("--ids: " + p.key() + " servo IDs are 0.." + max + ", got " + wanted[wanted.length - 1]);
        }
        BusConfig config;
        try {
            config = BusConfig.defaults().withBaud(rate).withReads(PING_TIMEOUT_MS, 0);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        try (ServoBus bus = ServoBuses.open(p, LinkOpener.serial(port, rate), config)) {
            int[] numbers = bus.scan(wanted);
            for (int i = 0; i < wanted.length; i++) {
                if (numbers[i] < 0) {
                    continue;
                }
                ServoModel model = ServoModel.of(p, numbers[i]);
                double deg = Double.NaN;
                if (model != null) {
                    double[] d = new double[1];
                    int[] e = new int[1];
                    e[0] = ServoBus.NO_REPLY;
                    for (int attempt = 0; attempt < 3 && e[0] == ServoBus.NO_REPLY; attempt++) {
                        bus.readPositions(new int[] {wanted[i]}, new ServoModel[] {model}, 1, d, e);
                    }
                    deg = e[0] == ServoBus.NO_REPLY ? Double.NaN : d[0];
                }
                found.add(new Found(wanted[i], numbers[i], model, deg));
            }
        } catch (IOException e) {
            throw new UsageException(e.getMessage());
        }
        return found;
    }

    private void report(ServoProtocol p, int rate, List<Found> found, PrintWriter stdout, PrintWriter err)
            throws UsageException {
        stdout.println(String.format(Locale.ROOT, "%d %s servo%s on %s at %d baud:", found.size(), p.key(),
                found.size() == 1 ? "" : "s", port, rate));
        stdout.println("   ID  model               position");
        List<ServoMapping> servos = new ArrayList<>();
        for (Found f : found) {
            stdout.println(String.format(Locale.ROOT, "  %3d  %-18s  %s", f.id(),
                    f.model() == null ? "unknown (" + f.modelNumber() + ")" : f.model().label(),
                    Double.isNaN(f.degrees()) ? "?" : String.format(Locale.ROOT, "%.2f°", f.degrees())));
            if (f.model() == null) {
                err.println("scan: servo " + f.id() + " has model number " + f.modelNumber() + ", which PARPE does not "
                        + "know; it is left out of the profile (known: " + ServoModel.names(p) + ")");
                continue;
            }
            ServoModel m = f.model();
            servos.add(new ServoMapping(servos.size(), f.id(), m, 0, 1, Math.max(-90, m.minDegrees()),
                    Math.min(90, m.maxDegrees()), SourcePos.NONE));
        }
        HardwareProfile profile = new HardwareProfile(out.toString(), p, port, rate, SafeMode.HOLD,
                HardwareProfile.DEFAULT_WATCHDOG_MS, servos);
        try {
            ProfileWriter.write(profile, out, "written by parpe scan: one module per servo, in ID order; set module, "
                    + "direction and limits, then run parpe calibrate");
        } catch (IOException e) {
            throw new UsageException("cannot write '" + out + "': " + e.getMessage());
        }
        err.println("scan: starter profile written to " + out + " (modules 0.." + (servos.size() - 1)
                + "); next: parpe calibrate --hardware " + out);
    }
}
