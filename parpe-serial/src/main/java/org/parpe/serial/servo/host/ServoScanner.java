package org.parpe.serial.servo.host;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;
import org.parpe.core.diag.SourcePos;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ServoMapping;
import org.parpe.serial.text.SerialMsg;

/**
 * Finding servos on a serial device, shared by {@code parpe scan} and the IDE's Hardware dialog:
 * every protocol asked for at each of its common baud rates (or the one given), stopping at the
 * first that finds servos; the ID, model and present position of each; a starter profile.
 */
public final class ServoScanner {
    /** A reply takes 2.5 ms at 57 600 baud, plus the servo's return delay and a loaded host's latency. */
    public static final int PING_TIMEOUT_MS = 10;

    private ServoScanner() {
    }

    /**
     * One servo found.
     *
     * @param id          its ID on the bus
     * @param modelNumber the model number it reported (0 when it could not be read)
     * @param model       the model, or null when PARPE does not know the number
     * @param degrees     servo angle, NaN when it could not be read
     */
    public record Found(int id, int modelNumber, ServoModel model, double degrees) {
    }

    /** The servos found on one protocol and baud rate (empty when none answered anywhere). */
    public record Result(ServoProtocol protocol, int baud, List<Found> servos) {
    }

    /** Told before each protocol and baud rate is tried. */
    public interface Progress {
        void trying(ServoProtocol protocol, int baud);
    }

    /** Every protocol, in the order a scan tries them. */
    public static List<ServoProtocol> allProtocols() {
        return List.of(ServoProtocol.DXL2, ServoProtocol.STS, ServoProtocol.SCS, ServoProtocol.G1);
    }

    /**
     * Tries {@code protocols} at {@code baud} (null: each protocol's common rates) until servos
     * answer, or until {@code cancelled}. {@code ids} (sorted; null for every ID) are pinged
     * where the protocol allows them. Returns null when none answered.
     *
     * @throws IOException with a user message when the device cannot be opened
     * @throws IllegalArgumentException with a user message for an ID or baud rate out of range
     */
    public static Result scan(String port, List<ServoProtocol> protocols, Integer baud, int[] ids, Progress progress,
                              BooleanSupplier cancelled) throws IOException {
        if (protocols.size() == 1 && ids != null) {
            checkIds(protocols.get(0), ids);
        }
        for (ServoProtocol p : protocols) {
            int[] mine = idsFor(p, ids);
            if (mine.length == 0) {
                continue;
            }
            for (int rate : baud == null ? p.scanBauds() : List.of(baud)) {
                if (cancelled.getAsBoolean()) {
                    return null;
                }
                progress.trying(p, rate);
                List<Found> found = scanOne(port, p, rate, mine);
                if (!found.isEmpty()) {
                    return new Result(p, rate, found);
                }
            }
        }
        return null;
    }

    /** Of {@code ids} (sorted; null for all) those {@code p} allows. */
    public static int[] idsFor(ServoProtocol p, int[] ids) {
        if (ids == null) {
            return java.util.stream.IntStream.rangeClosed(0, p.maxId()).toArray();
        }
        return java.util.Arrays.stream(ids).filter(id -> id >= 0 && id <= p.maxId()).toArray();
    }

    /** The servos {@code ids} (sorted) that answer {@code p} at {@code rate} on {@code port}. */
    public static List<Found> scanOne(String port, ServoProtocol p, int rate, int[] ids) throws IOException {
        checkIds(p, ids);
        BusConfig config = BusConfig.defaults().withBaud(rate).withReads(PING_TIMEOUT_MS, 0);
        try (ServoBus bus = ServoBuses.open(p, LinkOpener.serial(port, rate), config)) {
            return find(bus, ids);
        }
    }

    /** Throws when an ID is beyond what {@code p} allows; {@code ids} sorted. */
    public static void checkIds(ServoProtocol p, int[] ids) {
        if (ids.length > 0 && ids[ids.length - 1] > p.maxId()) {
            throw new IllegalArgumentException("--ids: " + SerialMsg.SERVO_IDS.text(p.key(), p.maxId(), ids[ids.length - 1]));
        }
    }

    /** The servos {@code ids} that answer on an open bus, with model and present position. */
    public static List<Found> find(ServoBus bus, int[] ids) throws IOException {
        List<Found> found = new ArrayList<>();
        int[] numbers = bus.scan(ids);
        for (int i = 0; i < ids.length; i++) {
            if (numbers[i] < 0) {
                continue;
            }
            ServoModel model = ServoModel.of(bus.protocol(), numbers[i]);
            double deg = Double.NaN;
            if (model != null) {
                double[] d = new double[1];
                int[] e = {ServoBus.NO_REPLY};
                for (int attempt = 0; attempt < 3 && e[0] == ServoBus.NO_REPLY; attempt++) {
                    bus.readPositions(new int[] {ids[i]}, new ServoModel[] {model}, 1, d, e);
                }
                deg = e[0] == ServoBus.NO_REPLY ? Double.NaN : d[0];
            }
            found.add(new Found(ids[i], numbers[i], model, deg));
        }
        return found;
    }

    /**
     * A starter profile for {@code found}: one module per servo of a known model, in ID order,
     * zero 0, direction 1, limits ±90° within the servo's range.
     */
    public static HardwareProfile starterProfile(String file, ServoProtocol p, String port, int baud,
                                                 List<Found> found) {
        List<ServoMapping> servos = new ArrayList<>();
        for (Found f : found) {
            if (f.model() != null) {
                servos.add(ServoMapping.starter(servos.size(), f.id(), f.model(), SourcePos.NONE));
            }
        }
        return new HardwareProfile(file, p, port, baud, SafeMode.HOLD, HardwareProfile.DEFAULT_WATCHDOG_MS, servos);
    }
}
