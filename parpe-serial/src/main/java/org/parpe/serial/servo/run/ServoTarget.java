package org.parpe.serial.servo.run;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.PlatesByHand;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunTarget;
import org.parpe.core.run.TargetException;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.Discovery;
import org.parpe.serial.bus.HostPlant;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.servo.profile.HardwareProfile;

/**
 * Servos on a serial bus as a run target, for the command line's {@code --hardware} and
 * {@code --port} and the IDE's Hardware target alike: the servos of a hardware profile (any
 * protocol), or, without a profile, the script's G1 modules ({@link #modules}). It opens the bus,
 * pings the script's servos before anything moves (reporting modules without a servo in the
 * profile or that cannot be on the bus, and servos that do not answer), and adds the servos as a
 * plant, as the sensor source (priority {@link org.parpe.core.run.SourceKind#HARDWARE}, above the
 * simulator) and as trace columns {@code hw<ID>}. The run is paced to the wall clock; a run
 * stopped by the user ends in an emergency stop. Bus problems become warnings located at
 * {@code bus PORT}; notes go to {@code notes}.
 */
public final class ServoTarget implements RunTarget {
    private final HardwareProfile profile;
    private final String port;
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
        this(profile, profile.port(), config.withBaud(profile.baud()).withSafeMode(profile.onFault()), opener, notes);
    }

    private ServoTarget(HardwareProfile profile, String port, BusConfig config, LinkOpener opener,
                        Consumer<String> notes) {
        this.profile = profile;
        this.port = port;
        this.config = config;
        this.opener = opener;
        this.notes = notes;
    }

    /**
     * The script's G1 modules on serial device {@code port}, without a profile: each module is
     * its own device ({@link HardwareProfile#ofModules}), with the line and watchdog of
     * {@code config}.
     */
    public static ServoTarget modules(String port, BusConfig config, Consumer<String> notes) {
        return modules(port, config, port == null ? null : LinkOpener.serial(port, config.baud()), notes);
    }

    /** The script's G1 modules reached through {@code opener} (tests, benchmarks), named {@code port} in messages. */
    public static ServoTarget modules(String port, BusConfig config, LinkOpener opener, Consumer<String> notes) {
        return new ServoTarget(null, port, config, opener, notes);
    }

    @Override
    public void attach(Run.Builder run) throws TargetException {
        boolean modules = profile == null;
        if (port == null || port.isBlank() || opener == null) {
            throw modules ? new TargetException(SourcePos.origin("hardware"), "no serial port chosen; choose the port "
                    + "the robot is connected to (e.g. /dev/ttyUSB0 or COM3)")
                    : new TargetException(SourcePos.origin(profile.file()), "no serial port: give --port or a port "
                    + "attribute in the profile (e.g. /dev/ttyUSB0 or COM3)");
        }
        SourcePos where = SourcePos.origin("bus " + port);
        DiagnosticSink diags = run.diagnostics();
        int[] ids = run.program().moduleIds();
        HardwareProfile p = modules ? HardwareProfile.ofModules(port, config, ids) : profile;
        ServoDriver d;
        try {
            d = ServoDriver.open(opener, config, p, ids, HostPlant.reportTo(where, diags, notes));
        } catch (IOException e) {
            throw new TargetException(where, "cannot open the serial device: " + HostPlant.message(e));
        }
        run.closeAtEnd(d);
        List<Integer> unmapped = d.unmapped();
        if (!modules && !unmapped.isEmpty()) {
            diags.warning(SourcePos.origin(profile.file()), "modules " + Discovery.format(unmapped)
                    + " of the script have no <servo> in the profile; they will not move");
        }
        List<Integer> found;
        try {
            found = d.discover();
        } catch (IOException e) {
            throw new TargetException(where, "the bus failed while looking for " + (modules ? "modules" : "servos")
                    + ": " + HostPlant.message(e));
        }
        List<Integer> other = d.answeredAsOtherModel();
        List<Integer> missing = new ArrayList<>();
        for (int id : ids) {
            if (!unmapped.contains(id) && !found.contains(id) && !other.contains(id)) {
                missing.add(id);
            }
        }
        if (modules) {
            reportModules(diags, where, ids, found, missing, unmapped);
        } else {
            reportServos(diags, where, ids.length - unmapped.size(), found, missing, other);
        }
        List<Integer> limp = d.limp();
        if (!limp.isEmpty()) {
            throw new TargetException(where, "the servos of modules " + Discovery.format(limp) + " answer but their "
                    + "torque did not come on (see the warnings above); they would stay limp while the run drives "
                    + "the others, so it does not start");
        }
        HostPlant.attachTo(run, d, ids);
        // neither G1 modules nor servos latch: plate actions (PARSL.md §14) are the user's to do by hand
        run.plates(new PlatesByHand(diags, ids, modules ? "the modules on " + port : "the servos of the profile"));
        driver = d;
    }

    /** What discovery found among the script's G1 modules, in the words of modules. */
    private void reportModules(DiagnosticSink diags, SourcePos where, int[] ids, List<Integer> found,
                               List<Integer> missing, List<Integer> unaddressable) throws TargetException {
        notes.accept("bus " + port + ": " + found.size() + " of " + ids.length + " modules answer"
                + (found.isEmpty() ? "" : " (" + Discovery.format(found) + ")"));
        if (!missing.isEmpty()) {
            // they are asked again every half second and driven once they answer (ServoSetUp.bringIn)
            diags.warning(where, missing.size() == 1
                    ? "module " + missing.get(0) + " of the script does not answer; it moves once it answers"
                    : "modules " + Discovery.format(missing) + " of the script do not answer; each moves once it answers");
        }
        if (!unaddressable.isEmpty()) {
            diags.warning(where, (unaddressable.size() == 1 ? "module " + unaddressable.get(0) + " cannot be on the bus (IDs 0..254); it"
                    : "modules " + Discovery.format(unaddressable) + " cannot be on the bus (IDs 0..254); they") + " will not move");
        }
        if (found.isEmpty()) {
            throw new TargetException(where, "no module answers on " + port + " at " + config.baud()
                    + " baud (is the robot powered and connected, and is the baud rate right?)");
        }
    }

    /** What discovery found among the servos of the profile. */
    private void reportServos(DiagnosticSink diags, SourcePos where, int mapped, List<Integer> found,
                              List<Integer> missing, List<Integer> other) throws TargetException {
        notes.accept("bus " + port + " (" + profile.protocol().key() + ", " + profile.baud() + " baud): " + found.size()
                + " of " + mapped + " servos answer" + (found.isEmpty() ? "" : " (modules "
                + Discovery.format(found) + ")") + (other.isEmpty() ? "" : "; " + other.size() + " more answer as another model"));
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
    }

    /** The driver attached last (null before {@link #attach}). */
    public ServoDriver driver() {
        return driver;
    }
}
