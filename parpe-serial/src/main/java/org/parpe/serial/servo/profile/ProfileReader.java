package org.parpe.serial.servo.profile;

import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.TargetException;
import org.parpe.core.xml.FlatXmlFile;
import org.parpe.core.xml.InputFiles;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;

/**
 * Reads a hardware profile (docs/hardware-profile.md) through {@link FlatXmlFile}, which keeps
 * the place of every element: each problem is reported at {@code FILE:LINE:COL}, all of them,
 * not only the first.
 */
public final class ProfileReader {
    private static final Set<String> ROOT_ATTRS = Set.of("protocol", "port", "baud", "on-fault", "watchdog");
    private static final Set<String> SERVO_ATTRS = Set.of("module", "id", "model", "zero", "direction", "min", "max");
    /** Joint range given to a servo whose profile names none. */
    private static final double DEFAULT_LIMIT = 90;
    private static final Set<String> WHOLE = Set.of("module", "id", "baud", "watchdog");

    private final FlatXmlFile xml;
    private final List<ServoMapping> servos = new ArrayList<>();
    private final Map<Integer, SourcePos> byModule = new java.util.HashMap<>();
    private final Map<Integer, Placed> byId = new java.util.HashMap<>();

    /** The module a servo ID drives and where. */
    private record Placed(int module, SourcePos where) {
    }
    private final Map<String, String> root;
    private final SourcePos rootPos;

    private ProfileReader(FlatXmlFile xml) {
        this.xml = xml;
        this.root = xml.rootAttributes();
        this.rootPos = xml.root();
    }

    /** Reads {@code path}; returns null after reporting every problem to {@code diags}. */
    public static HardwareProfile read(Path path, DiagnosticSink diags) {
        FlatXmlFile xml = FlatXmlFile.read(path, Message.of(Msg.FILE_HARDWARE), "hardware",
                Message.of(Msg.EXPECTED_HARDWARE), diags);
        if (xml.root() == null) {
            return null;
        }
        HardwareProfile profile = new ProfileReader(xml).build(path.toString());
        return xml.ok() ? profile : null;
    }

    /**
     * Reads the profile {@code file} a run or command was given as {@code origin} (an option, a
     * field); {@code port}, when given, replaces the profile's port.
     *
     * @throws TargetException with every problem of the file, located
     */
    public static HardwareProfile load(Path file, String port, String origin) throws TargetException {
        try {
            InputFiles.check(file);
        } catch (java.io.IOException e) {
            throw new TargetException(SourcePos.origin(origin), Msg.PROFILE_UNREADABLE, file, e.getMessage());
        }
        DiagnosticList diags = new DiagnosticList();
        HardwareProfile p = read(file, diags);
        if (p == null) {
            long n = diags.errorCount();
            throw new TargetException((n == 1 ? Msg.PROFILE_ERRORS_ONE : Msg.PROFILE_ERRORS).text(file, n), diags.all());
        }
        return port == null ? p : p.withPort(port);
    }

    private HardwareProfile build(String file) {
        xml.known(root, ROOT_ATTRS, "hardware", rootPos);
        List<FlatXmlFile.Element> servoElements = new ArrayList<>();
        for (FlatXmlFile.Element e : xml.children()) {
            if (e.name().equals("servo")) {
                servoElements.add(e);
            } else {
                error(e.at(), Msg.PROFILE_UNKNOWN_ELEMENT, e.name());
            }
        }
        String key = root.get("protocol");
        ServoProtocol protocol = key == null ? null : ServoProtocol.of(key.toLowerCase(Locale.ROOT));
        if (key == null) {
            error(rootPos, Msg.PROFILE_NEEDS_PROTOCOL, ServoProtocol.keys());
        } else if (protocol == null) {
            error(rootPos, Msg.UNKNOWN_PROTOCOL, key, ServoProtocol.keys());
        }
        int baud = protocol == null ? 0 : (int) number(root, "baud", protocol.scanBauds().get(0), rootPos, 1, 10_000_000);
        int watchdog = (int) number(root, "watchdog", HardwareProfile.DEFAULT_WATCHDOG_MS, rootPos, 0, 2540);
        String fault = root.getOrDefault("on-fault", "hold");
        if (!fault.equals("hold") && !fault.equals("limp")) {
            error(rootPos, Msg.BAD_ON_FAULT, fault);
        }
        String port = root.get("port");
        if (port != null && port.isEmpty()) {
            error(rootPos, Msg.EMPTY_PORT);
        }
        // With an unknown protocol the servos are still checked, as far as they can be without one.
        for (FlatXmlFile.Element e : servoElements) {
            servo(protocol, e.attributes(), e.at());
        }
        if (servoElements.isEmpty()) {
            error(rootPos, Msg.PROFILE_NO_SERVO);
        }
        return xml.ok() ? new HardwareProfile(file, protocol, port, baud, fault.equals("limp") ? SafeMode.LIMP : SafeMode.HOLD,
                watchdog, servos) : null;
    }

    /**
     * One {@code <servo>}; {@code protocol} null when the profile's is unknown (then model and ID
     * range are not checked). A servo with a bad module or ID is not kept, so that it cannot
     * clash with the others (a fallback ID would make every bad line a duplicate of every other).
     */
    private void servo(ServoProtocol protocol, Map<String, String> a, SourcePos at) {
        if (!xml.known(a, SERVO_ATTRS, "servo", at) || !xml.required(a, at, "servo", "module", "id")) {
            return;
        }
        int before = xml.errors();
        int maxId = protocol == null ? ServoProtocol.G1.maxId() : protocol.maxId();
        int module = (int) number(a, "module", 0, at, 0, 65_535);
        int id = (int) number(a, "id", 0, at, 0, maxId);
        boolean placed = xml.errors() == before;
        ServoModel model = protocol == null ? null : ServoModel.defaultFor(protocol);
        if (protocol != null && a.containsKey("model")) {
            model = ServoModel.named(a.get("model"));
            if (model == null || model.protocol() != protocol) {
                error(at, Msg.UNKNOWN_SERVO_MODEL, protocol.key(), a.get("model"), ServoModel.names(protocol));
                model = null;
            }
        }
        double zero = number(a, "zero", 0, at, -360, 360);
        double direction = number(a, "direction", 1, at, -1, 1);
        if (direction != 1 && direction != -1) {
            error(at, Msg.BAD_DIRECTION, a.get("direction"));
        }
        double min = number(a, "min", -DEFAULT_LIMIT, at, -360, 360);
        double max = number(a, "max", DEFAULT_LIMIT, at, -360, 360);
        boolean limits = min < max;
        if (!limits) {
            error(at, Msg.MIN_NOT_BELOW_MAX, fmt(min), fmt(max));
        }
        ServoMapping m = model == null || !limits ? null
                : new ServoMapping(module, id, model, zero, direction == -1 ? -1 : 1, min, max, at);
        if (m != null) {
            for (double joint : new double[] {min, max}) {
                double s = m.servoAngle(joint);
                if (s < model.minDegrees() - 1e-9 || s > model.maxDegrees() + 1e-9) {
                    error(at, Msg.SERVO_RANGE, fmt(joint), fmt(s), model.name(), fmt(model.minDegrees()),
                            fmt(model.maxDegrees()));
                }
            }
        }
        if (!placed) {
            return;
        }
        SourcePos firstOfModule = byModule.putIfAbsent(module, at);
        if (firstOfModule != null) {
            error(at, Msg.MODULE_MAPPED_TWICE, module, firstOfModule);
        }
        Placed sameId = byId.putIfAbsent(id, new Placed(module, at));
        if (sameId != null) {
            error(at, Msg.SERVO_ID_TWICE, id, sameId.module(), sameId.where(), module);
        }
        if (m != null && firstOfModule == null && sameId == null) {
            servos.add(m);
        }
    }

    /** A number attribute within {@code lo…hi}; whole for IDs, baud and watchdog. */
    private double number(Map<String, String> a, String key, double fallback, SourcePos at, double lo, double hi) {
        return xml.number(a, key, fallback, at, WHOLE.contains(key), lo, hi);
    }

    private static String fmt(double d) {
        return FlatXmlFile.plain(d);
    }

    private void error(SourcePos at, Msg key, Object... args) {
        xml.error(at, key, args);
    }
}
