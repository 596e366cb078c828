package org.parpe.gui.hardware;

import org.parpe.gui.text.UiMsg;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.host.ServoBuses;
import org.parpe.serial.servo.host.ServoScanner;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ProfileWriter;

/**
 * The servo bus held by the Hardware dialog. Every bus operation runs on one background thread
 * ("hardware-bus"), so the UI never waits for a servo; results come back through the
 * {@link Listener}, on that thread (the dialog moves them to the UI thread). Positions are read
 * every {@value #POLL_MS} ms while connected.
 */
public final class HardwareSession {
    static final int POLL_MS = 200;
    /** Jog speed limit, degrees per second of the servo. */
    public static final double JOG_DEG_PER_S = 30;
    /** Time between two jog goals. */
    public static final int JOG_TICK_MS = 20;
    private static final int READ_TIMEOUT_MS = 20;

    /** One servo as the dialog shows it; immutable snapshot. */
    record Servo(int id, int modelNumber, ServoModel model, double degrees, Boolean torque, String status) {
        Servo with(double deg, Boolean on, String st) {
            return new Servo(id, modelNumber, model, deg, on, st);
        }
    }

    /** What the bus thread reports. */
    interface Listener {
        /** A line of progress or an error, in words. */
        void message(String text, boolean error);

        /** The servos now connected (empty when none), with protocol, baud and port. */
        void connected(List<Servo> servos, ServoProtocol protocol, int baud, String port);

        /** New positions and states. */
        void updated(List<Servo> servos);
    }

    private final Listener listener;
    private final ScheduledExecutorService worker = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "hardware-bus");
        t.setDaemon(true);
        return t;
    });
    private volatile boolean closing;
    // Confined to the worker thread:
    private ServoBus bus;
    /** Servos on the move: row → {goal sent, target}. */
    private final java.util.Map<Integer, double[]> jogs = new java.util.LinkedHashMap<>();
    private java.util.concurrent.ScheduledFuture<?> jogTask;
    private ServoProtocol protocol;
    private int baud;
    private String port;
    private List<Servo> servos = List.of();

    HardwareSession(Listener listener) {
        this.listener = listener;
        worker.scheduleWithFixedDelay(this::poll, POLL_MS, POLL_MS, TimeUnit.MILLISECONDS);
    }

    /**
     * Closes any bus held, then looks for servos {@code ids} on {@code port}: with {@code p} and
     * {@code rate} when given, else every protocol and common baud rate; keeps the bus open.
     * {@code ids} null: every ID the protocol allows.
     */
    void connect(String port, ServoProtocol p, Integer rate, int[] ids) {
        submit(() -> {
            disconnect();
            try {
                scanAndOpen(port, p, rate, ids);
            } catch (IOException e) {
                listener.message(e.getMessage() + ".", true);
                listener.connected(List.of(), p, rate == null ? 0 : rate, port);
            }
        });
    }

    private void scanAndOpen(String port, ServoProtocol p, Integer rate, int[] ids) throws IOException {
        {
            ServoScanner.Result found;
            if (p != null && rate != null) {
                listener.message(UiMsg.HW_LOOKING.text(p.key(), port, rate), false);
                found = new ServoScanner.Result(p, rate, ServoScanner.scanOne(port, p, rate, ServoScanner.idsFor(p, ids)));
            } else {
                found = ServoScanner.scan(port, p == null ? ServoScanner.allProtocols() : List.of(p), rate, ids,
                        (q, r) -> listener.message(UiMsg.HW_SCANNING_AT.text(q.key(), r), false), () -> closing);
            }
            if (found == null || found.servos().isEmpty()) {
                listener.message(UiMsg.HW_NO_SERVO_ANSWERS.text(port, p == null ? ""
                        : rate == null ? UiMsg.HW_PROTOCOL_ONLY.text(p.key()) : UiMsg.HW_PROTOCOL_AT.text(p.key(), rate)), true);
                listener.connected(List.of(), p, rate == null ? 0 : rate, port);
                return;
            }
            open(port, found);
        }
    }

    private void open(String port, ServoScanner.Result found) throws IOException {
        bus = ServoBuses.open(found.protocol(), LinkOpener.serial(port, found.baud()),
                BusConfig.defaults().withBaud(found.baud()).withReads(READ_TIMEOUT_MS, 1));
        protocol = found.protocol();
        baud = found.baud();
        this.port = port;
        servos = found.servos().stream().map(f -> new Servo(f.id(), f.modelNumber(), f.model(), f.degrees(), null,
                f.model() == null ? UiMsg.HW_MODEL_UNKNOWN.text(f.modelNumber()) : "")).toList();
        listener.connected(servos, protocol, baud, port);
        listener.message(servos.size() == 1 ? UiMsg.HW_FOUND_ONE.text(port, protocol.key(), baud)
                : UiMsg.HW_FOUND_N.text(servos.size(), port, protocol.key(), baud), false);
    }

    /** Torque on (hold where it is) or off (limp) for servo {@code row}, or all when {@code row} < 0. */
    void torque(int row, boolean on) {
        submit(() -> {
            if (bus == null) {
                return;
            }
            int[] rows = rows(row);
            int[] ids = new int[rows.length];
            ServoModel[] models = new ServoModel[rows.length];
            for (int i = 0; i < rows.length; i++) {
                ids[i] = servos.get(rows[i]).id();
                models[i] = servos.get(rows[i]).model();
            }
            // Limp or hold ends the jogs; the next one starts again from where the servo is.
            stopJogs();
            int held = ids.length;
            if (on) {
                held = bus.holdHere(ids, models, ids.length);
            } else {
                bus.torque(ids, models, ids.length, false);
            }
            Servo[] next = servos.toArray(new Servo[0]);
            for (int r : rows) {
                // a servo that did not answer was not told to hold: its torque is not known to be on
                next[r] = next[r].with(next[r].degrees(), held == ids.length ? on : null, next[r].status());
            }
            servos = List.of(next);
            listener.updated(servos);
            if (held < ids.length) {
                listener.message(UiMsg.HW_NOT_HELD.text(ids.length - held, ids.length), true);
            }
        });
    }

    /**
     * Moves servo {@code row} toward {@code degrees} (servo degrees, kept within the model's range)
     * at no more than {@value #JOG_DEG_PER_S} °/s: goals a step apart every {@value #JOG_TICK_MS}
     * ms, from where the servo is. A limp servo first holds where it is. A new target replaces the
     * servo's old one and the move goes on from the goal reached; several servos move at once
     * (the Pose panel's "Real robot follows"), their goals in one packet per step.
     */
    void jog(int row, double degrees) {
        submit(() -> {
            if (bus == null || row < 0 || row >= servos.size() || servos.get(row).model() == null) {
                return;
            }
            Servo s = servos.get(row);
            ServoModel m = s.model();
            double[] j = jogs.get(row);
            if (j == null) {
                if (Double.isNaN(s.degrees())) {
                    listener.message(UiMsg.HW_SERVO_POSITION_UNKNOWN.text(s.id()), true);
                    return;
                }
                if (!Boolean.TRUE.equals(s.torque())) {
                    // Hold where it is first: the move starts from the present position, not an old goal.
                    if (bus.holdHere(new int[] {s.id()}, new ServoModel[] {m}, 1) == 0) {
                        listener.message(UiMsg.HW_SERVO_DID_NOT_ANSWER.text(s.id()), true);
                        return;
                    }
                    Servo[] next = servos.toArray(new Servo[0]);
                    next[row] = s.with(s.degrees(), true, s.status());
                    servos = List.of(next);
                }
                j = new double[] {s.degrees(), s.degrees()};
                jogs.put(row, j);
            }
            j[1] = Math.max(m.minDegrees(), Math.min(m.maxDegrees(), degrees));
            if (jogTask == null) {
                jogTask = worker.scheduleAtFixedRate(this::jogStep, 0, JOG_TICK_MS, TimeUnit.MILLISECONDS);
            }
        });
    }

    /** One step of the jogs: each goal moves at most {@value #JOG_DEG_PER_S} °/s toward its target. */
    private void jogStep() {
        if (bus == null || closing) {
            stopJogs();
            return;
        }
        double max = JOG_DEG_PER_S * JOG_TICK_MS / 1000.0;
        int n = jogs.size();
        int[] ids = new int[n];
        ServoModel[] models = new ServoModel[n];
        int[] ticks = new int[n];
        int k = 0;
        for (java.util.Iterator<java.util.Map.Entry<Integer, double[]>> it = jogs.entrySet().iterator(); it.hasNext(); ) {
            java.util.Map.Entry<Integer, double[]> e = it.next();
            double[] j = e.getValue();
            if (e.getKey() >= servos.size()) {
                it.remove();
                continue;
            }
            double d = j[1] - j[0];
            j[0] = Math.abs(d) <= max ? j[1] : j[0] + Math.copySign(max, d);
            Servo s = servos.get(e.getKey());
            ids[k] = s.id();
            models[k] = s.model();
            ticks[k++] = s.model().ticks(j[0]);
            if (j[0] == j[1]) {
                // Reached: the servo holds its goal; a later jog starts from there.
                it.remove();
            }
        }
        try {
            if (k > 0) {
                bus.writeGoals(ids, models, ticks, k);
            }
        } catch (IOException e) {
            stopJogs();
            lost(e);
            return;
        }
        if (jogs.isEmpty()) {
            stopJogs();
        }
    }

    private void stopJogs() {
        jogs.clear();
        if (jogTask != null) {
            jogTask.cancel(false);
            jogTask = null;
        }
    }

    /** Writes a starter profile of the servos connected to {@code file}; {@code done} gets the file on success. */
    void saveProfile(Path file, Consumer<Path> done) {
        submit(() -> {
            if (bus == null || servos.isEmpty()) {
                listener.message(UiMsg.HW_NONE_CONNECTED.text(), true);
                return;
            }
            List<ServoScanner.Found> found = servos.stream()
                    .map(s -> new ServoScanner.Found(s.id(), s.modelNumber(), s.model(), s.degrees())).toList();
            HardwareProfile profile = ServoScanner.starterProfile(file.toString(), protocol, port, baud, found);
            try {
                ProfileWriter.write(profile, file, UiMsg.HW_PROFILE_COMMENT.text());
            } catch (IOException e) {
                listener.message(UiMsg.HW_CANNOT_WRITE.text(file, e.getMessage()), true);
                return;
            }
            listener.message(UiMsg.HW_PROFILE_WRITTEN.text(file, profile.servos().size()), false);
            done.accept(file);
        });
    }

    /** Closes the bus and stops the thread; returns at once. */
    void close() {
        closing = true;
        worker.execute(this::disconnect);
        worker.shutdown();
    }

    /** Waits up to {@code ms} for the bus to be closed (tests). */
    public boolean awaitClosed(long ms) throws InterruptedException {
        return worker.awaitTermination(ms, TimeUnit.MILLISECONDS);
    }

    private int[] rows(int row) {
        if (row >= 0) {
            return servos.get(row).model() == null ? new int[0] : new int[] {row};
        }
        return java.util.stream.IntStream.range(0, servos.size()).filter(i -> servos.get(i).model() != null).toArray();
    }

    private void poll() {
        if (bus == null || closing || servos.isEmpty()) {
            return;
        }
        try {
            int[] rows = rows(-1);
            int[] ids = new int[rows.length];
            ServoModel[] models = new ServoModel[rows.length];
            for (int i = 0; i < rows.length; i++) {
                ids[i] = servos.get(rows[i]).id();
                models[i] = servos.get(rows[i]).model();
            }
            double[] deg = new double[rows.length];
            int[] err = new int[rows.length];
            bus.readPositions(ids, models, rows.length, deg, err);
            Servo[] next = servos.toArray(new Servo[0]);
            for (int i = 0; i < rows.length; i++) {
                Servo s = next[rows[i]];
                String status = err[i] == ServoBus.NO_REPLY ? UiMsg.HW_NO_REPLY.text()
                        : bus.faulty(err[i]) ? describe(s, err[i]) : "";
                next[rows[i]] = s.with(err[i] == ServoBus.NO_REPLY ? s.degrees() : deg[i], s.torque(), status);
            }
            servos = List.of(next);
            listener.updated(servos);
        } catch (IOException e) {
            lost(e);
        } catch (RuntimeException e) {
            listener.message(UiMsg.HW_READ_FAILED.text(e), true);
        }
    }

    private String describe(Servo s, int error) throws IOException {
        String what = bus.describeFault(s.id(), s.model(), error);
        return what == null ? String.format(Locale.ROOT, "error 0x%02X", error) : what;
    }

    private void lost(IOException e) {
        listener.message(UiMsg.HW_BUS_FAILED.text(e.getMessage()), true);
        disconnect();
        listener.connected(List.of(), protocol, baud, port);
    }

    private void disconnect() {
        stopJogs();
        if (bus != null) {
            bus.close();
            bus = null;
        }
        servos = List.of();
    }

    /** A bus operation; an error becomes a message, never a stack trace. */
    private interface BusTask {
        void run() throws IOException;
    }

    private void submit(BusTask task) {
        if (closing) {
            return;
        }
        worker.execute(() -> {
            try {
                task.run();
            } catch (IOException e) {
                lost(e);
            } catch (IllegalArgumentException e) {
                listener.message(e.getMessage(), true);
            } catch (RuntimeException e) {
                listener.message(UiMsg.HW_INTERNAL_ERROR.text(e), true);
            }
        });
    }
}
