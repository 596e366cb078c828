package org.parpe.serial.servo.run;

import java.io.IOException;
import java.util.List;
import java.util.function.Consumer;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunTarget;
import org.parpe.core.run.TargetException;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.Discovery;
import org.parpe.serial.bus.HostPlant;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.servo.profile.HardwareProfile;

/**
 * The servos of a hardware profile as a run target, on any protocol, for the command line's
 * {@code --hardware} and the IDE alike: opens the profile's bus, pings the script's servos before
 * anything moves (reporting modules without a servo in the profile and servos that do not
 * answer), and adds the servos as a plant, as the sensor source (priority
 * {@link org.parpe.core.run.SourceKind#HARDWARE}, above the simulator) and as trace columns {@code hw<ID>}. The run is
 * paced to the wall clock; a run stopped by the user ends in an emergency stop. Bus problems
 * become warnings located at {@code bus PORT}; notes go to {@code notes}.
 */
public final class ServoTarget implements RunTarget {
    private final HardwareProfile profile;
    private final BusConfig config;
    private final LinkOpener opener;
    private final Consumer<String> notes;
    private ServoDriver driver;

    /** The servos of {@code profile} on its port, with the read timing of {@code config}. */
    public ServoTarget(HardwareProfile profile, BusConfig config, Consumer<String> notes) {
        this(profile, config, profile.port() == null ? null : LinkOpener.serial(profile.port(), profile.baud()), notes);
    }

    /** The servos reached through {@code opener} (tests, benchmarks). */
    public ServoTarget(HardwareProfile profile, BusConfig config, LinkOpener opener, Consumer<String> notes) {
        this.profile = profile;
        this.config = config.withBaud(profile.baud()).withSafeMode(profile.onFault());
        this.opener = opener;
        this.notes = notes;
    }

    @Override
    public void attach(Run.Builder run) throws TargetException {
        String port = profile.port();
        if (port == null || port.isBlank() || opener == null) {
            throw new TargetException(SourcePos.origin(profile.file()), "no serial port: give --port or a port "
                    + "attribute in the profile (e.g. /dev/ttyUSB0 or COM3)");
        }
        SourcePos where = SourcePos.origin("bus " + port);
        DiagnosticSink diags = run.diagnostics();
        int[] ids = run.program().moduleIds();
        ServoDriver d;
        try {
            d = ServoDriver.open(opener, config, profile, ids, HostPlant.reportTo(where, diags, notes));
        } catch (IOException e) {
            throw new TargetException(where, "cannot open the serial device: " + HostPlant.message(e));
        }
        run.closeAtEnd(d);
        List<Integer> unmapped = d.unmapped();
        if (!unmapped.isEmpty()) {
            diags.warning(SourcePos.origin(profile.file()), "modules " + Discovery.format(unmapped)
                    + " of the script have no <servo> in the profile; they will not move");
        }
        List<Integer> found;
        try {
            found = d.discover();
        } catch (IOException e) {
            throw new TargetException(where, "the bus failed while looking for servos: " + HostPlant.message(e));
        }
        int mapped = ids.length - unmapped.size();
        List<Integer> other = d.answeredAsOtherModel();
        notes.accept("bus " + port + " (" + profile.protocol().key() + ", " + profile.baud() + " baud): " + found.size()
                + " of " + mapped + " servos answer" + (found.isEmpty() ? "" : " (modules "
                + Discovery.format(found) + ")") + (other.isEmpty() ? "" : "; " + other.size() + " more answer as another model"));
        List<Integer> missing = new java.util.ArrayList<>();
        for (int id : ids) {
            if (!unmapped.contains(id) && !found.contains(id) && !other.contains(id)) {
                missing.add(id);
            }
        }
        if (!missing.isEmpty()) {
            diags.warning(where, "the servos of modules " + Discovery.format(missing) + " do not answer; they will not move");
        }
        if (found.isEmpty() && !other.isEmpty()) {
            throw new TargetException(where, "the servos on " + port + " answer, but not as the model the profile "
                    + "says (modules " + Discovery.format(other) + "; see the warnings above): correct model= in "
                    + profile.file() + ", or run parpe scan");
        }
        if (found.isEmpty()) {
            throw new TargetException(where, "no servo answers on " + port + " at " + profile.baud() + " baud ("
                    + profile.protocol().key() + "; is the robot powered, and are protocol and baud rate right? "
                    + "parpe scan finds them)");
        }
        List<Integer> limp = d.limp();
        if (!limp.isEmpty()) {
            throw new TargetException(where, "the servos of modules " + Discovery.format(limp) + " answer but their "
                    + "torque did not come on (see the warnings above); they would stay limp while the run drives "
                    + "the others, so it does not start");
        }
        HostPlant.attachTo(run, d, ids);
        driver = d;
    }

    /** The driver attached last (null before {@link #attach}). */
    public ServoDriver driver() {
        return driver;
    }
}
