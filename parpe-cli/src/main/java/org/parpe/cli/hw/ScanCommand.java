package org.parpe.cli.hw;

import org.parpe.cli.text.CliMsg;
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
                : OutputPlan.Existing.KEEP, CliMsg.OTHER_OUT_OR_FORCE.text());
        ServoScanner.Result r;
        try {
            r = ServoScanner.scan(port, protocols, baud, wanted, (p, rate) -> err.println("scan: "
                    + CliMsg.SCANNING.text(p.key(), rate, ModuleList.format(ServoScanner.idsFor(p, wanted)))),
                    () -> false);
        } catch (IOException | IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        if (r != null) {
            return report(r.protocol(), r.baud(), r.servos(), stdout, err);
        }
        err.println("scan: " + CliMsg.NO_SERVO_ANSWERS.text(port));
        return 1;
    }

    private List<ServoProtocol> protocols() throws UsageException {
        if (protocol == null) {
            return ServoScanner.allProtocols();
        }
        ServoProtocol p = ServoProtocol.of(protocol);
        if (p == null) {
            throw new UsageException(CliMsg.BAD_PROTOCOL.text(ServoProtocol.keys(), protocol));
        }
        return List.of(p);
    }

    /** Lists the servos found and writes the starter profile; 1, and no file, when none is of a known model. */
    private int report(ServoProtocol p, int rate, List<Found> found, PrintWriter stdout, PrintWriter err)
            throws UsageException {
        stdout.println((found.size() == 1 ? CliMsg.ONE_SERVO_FOUND : CliMsg.N_SERVOS_FOUND).text(found.size(), p.key(), port, rate));
        stdout.println(String.format(Locale.ROOT, "  %3s  %-18s  %s", CliMsg.SCAN_ID.text(), CliMsg.SCAN_MODEL.text(),
                CliMsg.SCAN_POSITION.text()));
        for (Found f : found) {
            stdout.println(String.format(Locale.ROOT, "  %3d  %-18s  %s", f.id(),
                    f.model() == null ? CliMsg.UNKNOWN_MODEL_NUMBER.text(f.modelNumber()) : f.model().label(),
                    Double.isNaN(f.degrees()) ? "?" : String.format(Locale.ROOT, "%.2f°", f.degrees())));
            if (f.model() == null) {
                err.println("scan: " + CliMsg.MODEL_LEFT_OUT.text(f.id(), f.modelNumber(), ServoModel.names(p)));
            }
        }
        HardwareProfile profile = ServoScanner.starterProfile(out.toString(), p, port, rate, found);
        int servos = profile.servos().size();
        if (servos == 0) {
            err.println("scan: " + CliMsg.NO_KNOWN_MODEL.text(port, ServoModel.names(p), out));
            return 1;
        }
        try {
            ProfileWriter.write(profile, out, "written by parpe scan: one module per servo, in ID order; set module, "
                    + "direction and limits, then run parpe calibrate");
        } catch (IOException e) {
            throw new UsageException(CliMsg.CANNOT_WRITE_OUT.text(out, e.getMessage()));
        }
        err.println("scan: " + CliMsg.PROFILE_WRITTEN.text(out, servos - 1));
        return 0;
    }
}
