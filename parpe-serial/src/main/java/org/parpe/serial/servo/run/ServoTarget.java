package org.parpe.serial.servo.run;

import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import java.io.IOException;
import java.nio.file.Path;
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
import org.parpe.serial.servo.profile.ProfileReader;

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
     * What the command line's {@code --hardware}/{@code --port} and the IDE's Hardware target
     * both drive: the servos of the hardware profile {@code profile} (read here; {@code port},
     * when given, replaces its port), or without a profile the script's G1 modules on
     * {@code port}. A blank port is none.
     *
     * @param origin what named the profile, for a file that cannot be read ({@code --hardware})
     * @throws TargetException when the profile cannot be read or has errors, every problem located
     */
    public static ServoTarget open(Path profile, String port, String origin, BusConfig config, Consumer<String> notes)
            throws TargetException {
        String p = port == null || port.isBlank() ? null : port;
        return profile == null ? modules(p, config, notes)
                : new ServoTarget(ProfileReader.load(profile, p, origin), config, notes);
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

    /** The serial device it drives, or null when none was given. */
    public String port() {
        return port;
    }

    /** The hardware profile whose servos it drives, or null for the script's G1 modules. */
    public HardwareProfile profile() {
        return profile;
    }

    @Override
    public void attach(Run.Builder run) throws TargetException {
        boolean modules = profile == null;
        if (port == null || port.isBlank() || opener == null) {
            throw modules ? new TargetException(SourcePos.origin("hardware"), Msg.NO_PORT_CHOSEN)
                    : new TargetException(SourcePos.origin(profile.file()), Msg.NO_PORT_IN_PROFILE);
        }
        SourcePos where = SourcePos.origin("bus " + port);
        DiagnosticSink diags = run.diagnostics();
        int[] ids = run.program().moduleIds();
        HardwareProfile p = modules ? HardwareProfile.ofModules(port, config, ids) : profile;
        ServoDriver d;
        try {
            d = ServoDriver.open(opener, config, p, ids, HostPlant.reportTo(where, diags, notes));
        } catch (IOException e) {
            throw new TargetException(where, Msg.CANNOT_OPEN_PORT, HostPlant.message(e));
        }
        run.closeAtEnd(d);
        List<Integer> unmapped = d.unmapped();
        if (!modules && !unmapped.isEmpty()) {
            diags.warning(SourcePos.origin(profile.file()), Msg.MODULES_UNMAPPED, Discovery.format(unmapped));
        }
        List<Integer> found;
        try {
            found = d.discover();
        } catch (IOException e) {
            throw new TargetException(where, modules ? Msg.BUS_FAILED_MODULES : Msg.BUS_FAILED_SERVOS, HostPlant.message(e));
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
            throw new TargetException(where, Msg.SERVOS_LIMP, Discovery.format(limp));
        }
        HostPlant.attachTo(run, d, ids);
        // neither G1 modules nor servos latch: plate actions (PARSL.md §14) are the user's to do by hand
        run.plates(new PlatesByHand(diags, ids, modules ? Msg.THE_MODULES_ON.text(port) : Msg.THE_SERVOS_OF_THE_PROFILE.text()));
        driver = d;
    }

    /** What discovery found among the script's G1 modules, in the words of modules. */
    private void reportModules(DiagnosticSink diags, SourcePos where, int[] ids, List<Integer> found,
                               List<Integer> missing, List<Integer> unaddressable) throws TargetException {
        notes.accept("bus " + port + ": " + Msg.MODULES_ANSWER.text(found.size(), ids.length,
                found.isEmpty() ? Message.EMPTY : Message.of(Msg.IN_PARENTHESES, Discovery.format(found))));
        if (!missing.isEmpty()) {
            // they are asked again every half second and driven once they answer (ServoSetUp.bringIn)
            if (missing.size() == 1) {
                diags.warning(where, Msg.MODULE_SILENT, missing.get(0));
            } else {
                diags.warning(where, Msg.MODULES_SILENT, Discovery.format(missing));
            }
        }
        if (!unaddressable.isEmpty()) {
            if (unaddressable.size() == 1) {
                diags.warning(where, Msg.MODULE_UNADDRESSABLE, unaddressable.get(0));
            } else {
                diags.warning(where, Msg.MODULES_UNADDRESSABLE, Discovery.format(unaddressable));
            }
        }
        if (found.isEmpty()) {
            throw new TargetException(where, Msg.NO_MODULE_ANSWERS, port, config.baud());
        }
    }

    /** What discovery found among the servos of the profile. */
    private void reportServos(DiagnosticSink diags, SourcePos where, int mapped, List<Integer> found,
                              List<Integer> missing, List<Integer> other) throws TargetException {
        notes.accept("bus " + port + " (" + profile.protocol().key() + ", " + profile.baud() + " baud): "
                + Msg.SERVOS_ANSWER.text(found.size(), mapped,
                found.isEmpty() ? Message.EMPTY : Message.of(Msg.MODULES_IN_PARENTHESES, Discovery.format(found)),
                other.isEmpty() ? Message.EMPTY : Message.of(Msg.MORE_AS_OTHER_MODEL, other.size())));
        if (!missing.isEmpty()) {
            diags.warning(where, Msg.SERVOS_SILENT, Discovery.format(missing));
        }
        if (found.isEmpty() && !other.isEmpty()) {
            throw new TargetException(where, Msg.SERVOS_OTHER_MODEL, port, Discovery.format(other), profile.file());
        }
        if (found.isEmpty()) {
            throw new TargetException(where, Msg.NO_SERVO_ANSWERS, port, profile.baud(), profile.protocol().key());
        }
    }

    /** The driver attached last (null before {@link #attach}). */
    public ServoDriver driver() {
        return driver;
    }
}
