package org.parpe.cli.hw;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.parpe.cli.options.OutputFile;
import org.parpe.cli.options.UsageException;
import org.parpe.core.io.OutputPlan;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.host.ServoScanner;
import org.parpe.serial.servo.host.ServoScanner.Found;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ProfileWriter;
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
    @Option(names = "--port", required = true, paramLabel = "PATH", description = "The serial device.")
    String port;

    @Option(names = "--protocol", paramLabel = "dxl2|sts|scs|g1", description = "Only this protocol.")
    String protocol;

    @Option(names = "--baud", paramLabel = "N", description = "Only this line speed.")
    Integer baud;

    @Option(names = "--ids", paramLabel = "IDS",
            description = "Servo IDs to ping (default: every ID the protocol allows, dxl2 0..252, sts and scs 0..253, g1 0..254).")
    String ids;

    @Option(names = "--out", defaultValue = "hardware.xml", paramLabel = "FILE.xml",
            description = "The starter profile to write (default ${DEFAULT-VALUE}); an existing file is kept unless --force.")
    Path out;

    @Option(names = "--force", description = "Overwrite --out if it exists.")
    boolean force;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws UsageException {
        return scan(spec.commandLine().getOut(), spec.commandLine().getErr());
    }

    private int scan(PrintWriter stdout, PrintWriter err) throws UsageException {
        List<ServoProtocol> protocols = protocols();
        int[] wanted = ids == null ? null : ModuleList.sorted(ModuleList.parse(ids, "--ids"));
        // checked before scanning; --force replaces a regular file only, never a device, FIFO or link to nothing
        OutputFile.of(OutputFile.plan(List.of()), "--out", out.toString(), force ? OutputPlan.Existing.REPLACE
                : OutputPlan.Existing.KEEP, "choose another --out or add --force");
        ServoScanner.Result r;
        try {
            r = ServoScanner.scan(port, protocols, baud, wanted, (p, rate) -> err.println(String.format(Locale.ROOT,
                    "scan: %s at %d baud, IDs %s ...", p.key(), rate, ModuleList.format(ServoScanner.idsFor(p, wanted)))),
                    () -> false);
        } catch (IOException | IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        if (r != null) {
            return report(r.protocol(), r.baud(), r.servos(), stdout, err);
        }
        err.println("scan: no usable servos found on " + port + ": no servo answers (is the robot powered? is the "
                + "adapter for this bus?)");
        return 1;
    }

    private List<ServoProtocol> protocols() throws UsageException {
        if (protocol == null) {
            return ServoScanner.allProtocols();
        }
        ServoProtocol p = ServoProtocol.of(protocol);
        if (p == null) {
            throw new UsageException("--protocol must be one of " + ServoProtocol.keys() + ", got '" + protocol + "'");
        }
        return List.of(p);
    }

    /** Lists the servos found and writes the starter profile; 1, and no file, when none is of a known model. */
    private int report(ServoProtocol p, int rate, List<Found> found, PrintWriter stdout, PrintWriter err)
            throws UsageException {
        stdout.println(String.format(Locale.ROOT, "%d %s servo%s on %s at %d baud:", found.size(), p.key(),
                found.size() == 1 ? "" : "s", port, rate));
        stdout.println("   ID  model               position");
        for (Found f : found) {
            stdout.println(String.format(Locale.ROOT, "  %3d  %-18s  %s", f.id(),
                    f.model() == null ? "unknown (" + f.modelNumber() + ")" : f.model().label(),
                    Double.isNaN(f.degrees()) ? "?" : String.format(Locale.ROOT, "%.2f°", f.degrees())));
            if (f.model() == null) {
                err.println("scan: servo " + f.id() + " has model number " + f.modelNumber() + ", which PARPE does not "
                        + "know; it is left out of the profile (known: " + ServoModel.names(p) + ")");
            }
        }
        HardwareProfile profile = ServoScanner.starterProfile(out.toString(), p, port, rate, found);
        int servos = profile.servos().size();
        if (servos == 0) {
            err.println("scan: no usable servos found on " + port + ": none of a model PARPE knows (" + ServoModel.names(p)
                    + "); " + out + " not written");
            return 1;
        }
        try {
            ProfileWriter.write(profile, out, "written by parpe scan: one module per servo, in ID order; set module, "
                    + "direction and limits, then run parpe calibrate");
        } catch (IOException e) {
            throw new UsageException("cannot write --out file '" + out + "': " + e.getMessage());
        }
        err.println("scan: starter profile written to " + out + " (modules 0.." + (servos - 1)
                + "); next: parpe calibrate --hardware " + out);
        return 0;
    }
}
