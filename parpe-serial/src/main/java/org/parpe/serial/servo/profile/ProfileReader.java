package org.parpe.serial.servo.profile;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.xml.FlatXmlFile;
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
        FlatXmlFile xml = FlatXmlFile.read(path, "hardware profile", "hardware",
                "a <hardware protocol=\"…\"> element with <servo> elements", diags);
        if (xml.root() == null) {
            return null;
        }
        HardwareProfile profile = new ProfileReader(xml).build(path.toString());
        return xml.ok() ? profile : null;
    }

    private HardwareProfile build(String file) {
        xml.known(root, ROOT_ATTRS, "hardware", rootPos);
        List<FlatXmlFile.Element> servoElements = new ArrayList<>();
        for (FlatXmlFile.Element e : xml.children()) {
            if (e.name().equals("servo")) {
                servoElements.add(e);
            } else {
                error(e.at(), "unknown element <" + e.name() + "> in <hardware>; expected <servo>");
            }
        }
        String key = root.get("protocol");
        ServoProtocol protocol = key == null ? null : ServoProtocol.of(key.toLowerCase(Locale.ROOT));
        if (key == null) {
            error(rootPos, "<hardware> needs the attribute 'protocol' (" + ServoProtocol.keys() + ")");
        } else if (protocol == null) {
            error(rootPos, "unknown protocol '" + key + "'; expected one of " + ServoProtocol.keys());
        }
        int baud = protocol == null ? 0 : (int) number(root, "baud", protocol.scanBauds().get(0), rootPos, 1, 10_000_000);
        int watchdog = (int) number(root, "watchdog", HardwareProfile.DEFAULT_WATCHDOG_MS, rootPos, 0, 2540);
        String fault = root.getOrDefault("on-fault", "hold");
        if (!fault.equals("hold") && !fault.equals("limp")) {
            error(rootPos, "on-fault must be hold or limp, got '" + fault + "'");
        }
        String port = root.get("port");
        if (port != null && port.isEmpty()) {
            error(rootPos, "port is empty; give the serial device (e.g. /dev/ttyUSB0) or leave the attribute out");
        }
        // With an unknown protocol the servos are still checked, as far as they can be without one.
        for (FlatXmlFile.Element e : servoElements) {
            servo(protocol, e.attributes(), e.at());
        }
        if (servoElements.isEmpty()) {
            error(rootPos, "the profile maps no module: add <servo module=\"0\" id=\"1\"/> elements");
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
                error(at, "unknown " + protocol.key() + " servo model '" + a.get("model") + "'; expected one of "
                        + ServoModel.names(protocol));
                model = null;
            }
        }
        double zero = number(a, "zero", 0, at, -360, 360);
        double direction = number(a, "direction", 1, at, -1, 1);
        if (direction != 1 && direction != -1) {
            error(at, "direction must be 1 or -1, got '" + a.get("direction") + "'");
        }
        double min = number(a, "min", -DEFAULT_LIMIT, at, -360, 360);
        double max = number(a, "max", DEFAULT_LIMIT, at, -360, 360);
        boolean limits = min < max;
        if (!limits) {
            error(at, String.format(Locale.ROOT, "min must be below max, got min %s and max %s", fmt(min), fmt(max)));
        }
        ServoMapping m = model == null || !limits ? null
                : new ServoMapping(module, id, model, zero, direction == -1 ? -1 : 1, min, max, at);
        if (m != null) {
            for (double joint : new double[] {min, max}) {
                double s = m.servoAngle(joint);
                if (s < model.minDegrees() - 1e-9 || s > model.maxDegrees() + 1e-9) {
                    error(at, String.format(Locale.ROOT, "joint angle %s° is servo angle %s°, outside the %s's range "
                            + "%s..%s°; narrow min/max or change zero", fmt(joint), fmt(s), model.name(),
                            fmt(model.minDegrees()), fmt(model.maxDegrees())));
                }
            }
        }
        if (!placed) {
            return;
        }
        SourcePos firstOfModule = byModule.putIfAbsent(module, at);
        if (firstOfModule != null) {
            error(at, "module " + module + " is mapped twice; first at " + firstOfModule);
        }
        Placed sameId = byId.putIfAbsent(id, new Placed(module, at));
        if (sameId != null) {
            error(at, "servo ID " + id + " drives two modules (" + sameId.module() + " at " + sameId.where()
                    + " and " + module + ")");
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

    private void error(SourcePos at, String message) {
        xml.error(at, message);
    }
}
