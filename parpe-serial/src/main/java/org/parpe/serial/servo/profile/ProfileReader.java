package org.parpe.serial.servo.profile;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.dataformat.xml.XmlFactory;
import com.fasterxml.jackson.dataformat.xml.deser.FromXmlParser;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.model.Numbers;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.wire.PacketCodec;

/**
 * Reads a hardware profile (docs/hardware-profile.md) with Jackson's XML streaming parser,
 * keeping the place of every element: each problem is reported at {@code FILE:LINE:COL}, all of
 * them, not only the first.
 */
public final class ProfileReader {
    private static final Set<String> ROOT_ATTRS = Set.of("protocol", "port", "baud", "on-fault", "watchdog");
    private static final Set<String> SERVO_ATTRS = Set.of("module", "id", "model", "zero", "direction", "min", "max");
    /** Joint range given to a servo whose profile names none. */
    private static final double DEFAULT_LIMIT = 90;

    private final String file;
    private final DiagnosticSink diags;
    private final List<ServoMapping> servos = new ArrayList<>();
    private final Map<String, String> root = new LinkedHashMap<>();
    private final List<Map<String, String>> servoAttrs = new ArrayList<>();
    private final List<SourcePos> servoPlaces = new ArrayList<>();
    private SourcePos rootPos;
    private boolean ok = true;

    private ProfileReader(String file, DiagnosticSink diags) {
        this.file = file;
        this.diags = diags;
    }

    /** Reads {@code path}; returns null after reporting every problem to {@code diags}. */
    public static HardwareProfile read(Path path, DiagnosticSink diags) {
        ProfileReader r = new ProfileReader(path.toString(), diags);
        try (InputStream in = Files.newInputStream(path);
             JsonParser p = new XmlFactory().createParser(in)) {
            r.document(p);
        } catch (JsonProcessingException e) {
            JsonLocation l = e.getLocation();
            r.error(l == null ? new SourcePos(r.file, 1, 1) : r.pos(l), "not well-formed XML: " + e.getOriginalMessage());
            return null;
        } catch (IOException e) {
            r.error(new SourcePos(r.file, 1, 1), "cannot read the hardware profile: " + e.getMessage());
            return null;
        }
        if (r.rootPos == null) {
            return null;
        }
        HardwareProfile profile = r.build();
        return r.ok ? profile : null;
    }

    private void document(JsonParser p) throws IOException {
        if (p.nextToken() != JsonToken.START_OBJECT) {
            error(new SourcePos(file, 1, 1), "expected a <hardware> element with <servo> elements");
            return;
        }
        SourcePos start = pos(p.currentTokenLocation());
        String rootName = p instanceof FromXmlParser x ? x.getStaxReader().getLocalName() : "hardware";
        if (!"hardware".equals(rootName)) {
            error(start, "<" + rootName + "> is not a hardware profile"
                    + ("program".equals(rootName) ? " but a PARSL script" : "")
                    + "; expected a <hardware protocol=\"…\"> element with <servo> elements");
            return;
        }
        rootPos = start;
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String name = p.currentName();
            SourcePos at = pos(p.currentTokenLocation());
            boolean element = isElement(p, name);
            JsonToken t = p.nextToken();
            if (t == JsonToken.START_OBJECT) {
                Map<String, String> attrs = attributes(p, name);
                if (name.equals("servo")) {
                    servoAttrs.add(attrs);
                    servoPlaces.add(at);
                } else {
                    error(at, "unknown element <" + name + "> in <hardware>; expected <servo>");
                }
            } else if (name.equals("servo")) {
                error(at, "<servo> needs the attributes module and id");
            } else if (name.isEmpty()) {
                if (!p.getText().isBlank()) {
                    error(at, "<hardware> may not contain text");
                }
            } else if (element || t == JsonToken.START_ARRAY) {
                error(at, "unknown element <" + name + "> in <hardware>; expected <servo>");
                p.skipChildren();
            } else {
                root.put(name, p.getText() == null ? "" : p.getText().trim());
            }
        }
    }

    /** Whether the field just read is a child element (an empty one looks like an attribute otherwise). */
    private static boolean isElement(JsonParser p, String name) {
        if (!(p instanceof FromXmlParser x)) {
            return false;
        }
        javax.xml.stream.XMLStreamReader r = x.getStaxReader();
        return r.getEventType() == javax.xml.stream.XMLStreamConstants.START_ELEMENT && name.equals(r.getLocalName());
    }

    /** The attributes of the current element; nested elements and text are errors. */
    private Map<String, String> attributes(JsonParser p, String element) throws IOException {
        Map<String, String> attrs = new LinkedHashMap<>();
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String key = p.currentName();
            SourcePos at = pos(p.currentTokenLocation());
            JsonToken t = p.nextToken();
            if (t == JsonToken.START_OBJECT || t == JsonToken.START_ARRAY) {
                error(at, "<" + element + "> may not contain <" + key + ">");
                p.skipChildren();
            } else if (!key.isEmpty()) {
                attrs.put(key, p.getText() == null ? "" : p.getText().trim());
            } else if (!p.getText().isBlank()) {
                error(at, "<" + element + "> may not contain text");
            }
        }
        return attrs;
    }

    private HardwareProfile build() {
        known(root, ROOT_ATTRS, "hardware", rootPos);
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
        if (protocol != null) {
            for (int i = 0; i < servoAttrs.size(); i++) {
                servo(protocol, servoAttrs.get(i), servoPlaces.get(i));
            }
            if (servoAttrs.isEmpty()) {
                error(rootPos, "the profile maps no module: add <servo module=\"0\" id=\"1\"/> elements");
            }
        }
        return ok ? new HardwareProfile(file, protocol, port, baud, fault.equals("limp") ? SafeMode.LIMP : SafeMode.HOLD,
                watchdog, servos) : null;
    }

    private void servo(ServoProtocol protocol, Map<String, String> a, SourcePos at) {
        if (!known(a, SERVO_ATTRS, "servo", at) || !required(a, at, "module", "id")) {
            return;
        }
        int maxId = protocol == ServoProtocol.G1 ? 254 : PacketCodec.BROADCAST - 1;
        int module = (int) number(a, "module", 0, at, 0, 65_535);
        int id = (int) number(a, "id", 0, at, 0, maxId);
        ServoModel model = ServoModel.defaultFor(protocol);
        if (a.containsKey("model")) {
            model = ServoModel.named(a.get("model"));
            if (model == null || model.protocol() != protocol) {
                error(at, "unknown " + protocol.key() + " servo model '" + a.get("model") + "'; expected one of "
                        + ServoModel.names(protocol));
                return;
            }
        }
        double zero = number(a, "zero", 0, at, -360, 360);
        double direction = number(a, "direction", 1, at, -1, 1);
        if (direction != 1 && direction != -1) {
            error(at, "direction must be 1 or -1, got '" + a.get("direction") + "'");
        }
        double min = number(a, "min", -DEFAULT_LIMIT, at, -360, 360);
        double max = number(a, "max", DEFAULT_LIMIT, at, -360, 360);
        if (min >= max) {
            error(at, String.format(Locale.ROOT, "min must be below max, got min %s and max %s", fmt(min), fmt(max)));
            return;
        }
        ServoMapping m = new ServoMapping(module, id, model, zero, (int) direction, min, max, at);
        for (double joint : new double[] {min, max}) {
            double s = m.servoAngle(joint);
            if (s < model.minDegrees() - 1e-9 || s > model.maxDegrees() + 1e-9) {
                error(at, String.format(Locale.ROOT, "joint angle %s° is servo angle %s°, outside the %s's range %s..%s°;"
                        + " narrow min/max or change zero", fmt(joint), fmt(s), model.name(), fmt(model.minDegrees()),
                        fmt(model.maxDegrees())));
            }
        }
        for (ServoMapping other : servos) {
            if (other.module() == module) {
                error(at, "module " + module + " is mapped twice; first at " + other.where());
            } else if (other.servo() == id) {
                error(at, "servo ID " + id + " drives two modules (" + other.module() + " at " + other.where()
                        + " and " + module + ")");
            }
        }
        servos.add(m);
    }

    private boolean known(Map<String, String> a, Set<String> allowed, String element, SourcePos at) {
        boolean good = true;
        for (String k : a.keySet()) {
            if (!allowed.contains(k)) {
                error(at, "<" + element + "> has no attribute '" + k + "'; it takes "
                        + String.join(", ", allowed.stream().sorted().toList()));
                good = false;
            }
        }
        return good;
    }

    private boolean required(Map<String, String> a, SourcePos at, String... keys) {
        boolean good = true;
        for (String k : keys) {
            if (!a.containsKey(k) || a.get(k).isEmpty()) {
                error(at, "<servo> needs the attribute '" + k + "'");
                good = false;
            }
        }
        return good;
    }

    /** A number attribute within {@code lo…hi}; whole when both bounds are whole and the fallback is. */
    private double number(Map<String, String> a, String key, double fallback, SourcePos at, double lo, double hi) {
        String v = a.get(key);
        if (v == null) {
            return fallback;
        }
        boolean whole = Set.of("module", "id", "baud", "watchdog").contains(key);
        // the plain decimals of scripts and robot configurations: Double.parseDouble would take
        // "1d", "0x1p3" or "NaN"
        Double d = Numbers.parsePlain(v);
        if (d == null || whole && d != Math.rint(d)) {
            error(at, key + " must be " + (whole ? "a whole number" : "a number") + ", got '" + v + "'");
            return fallback;
        }
        if (d < lo || d > hi) {
            error(at, key + " must be in " + fmt(lo) + ".." + fmt(hi) + ", got " + v);
            return fallback;
        }
        return d;
    }

    private static String fmt(double d) {
        return d == Math.rint(d) ? String.valueOf((long) d) : String.format(Locale.ROOT, "%.2f", d);
    }

    private SourcePos pos(JsonLocation l) {
        return new SourcePos(file, Math.max(1, l.getLineNr()), Math.max(1, l.getColumnNr()));
    }

    private void error(SourcePos at, String message) {
        diags.error(at, message);
        ok = false;
    }
}
