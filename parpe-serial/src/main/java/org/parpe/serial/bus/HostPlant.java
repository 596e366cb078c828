package org.parpe.serial.bus;

import java.io.IOException;
import java.util.function.Consumer;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunInfo;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.SensorSource;
import org.parpe.core.run.SourceKind;
import org.parpe.core.run.TraceColumns;

/**
 * What the host side of a servo bus is to a run (G1 modules, Dynamixel and Feetech servos alike,
 * all driven by {@link org.parpe.serial.servo.run.ServoDriver}): a plant and a sensor source that reports the angle each
 * module last measured and can stop every module at once. {@link #attachTo} adds it to a run
 * the one way all bus targets share.
 */
public interface HostPlant extends JointSink, SensorSource {

    /** The angle module {@code index} (program order) last reported, or NaN before any reading. */
    double measuredAngle(int index);

    /** An emergency stop, if a run is going on; safe from any thread. */
    void emergencyStopIfRunning();

    /**
     * Adds {@code plant} to {@code run}: as a plant whose run, when stopped by the user, ends
     * in an emergency stop; as the sensor source "hardware"; as trace columns {@code hw<ID>}
     * for {@code ids}; paced to the wall clock.
     */
    static void attachTo(Run.Builder run, HostPlant plant, int[] ids) {
        run.plant(new JointSink() {
            @Override
            public void start(RunInfo info) {
                plant.start(info);
            }

            @Override
            public void accept(long tick, double time, double[] commanded) {
                plant.accept(tick, time, commanded);
            }

            @Override
            public void finish(RunOutcome outcome) {
                if (outcome.status() == RunOutcome.Status.STOPPED) {
                    plant.emergencyStopIfRunning();
                }
                plant.finish(outcome);
            }
        });
        run.sensorSource(SourceKind.HARDWARE, plant);
        String[] names = new String[ids.length];
        for (int i = 0; i < ids.length; i++) {
            names[i] = SourceKind.HARDWARE.column(ids[i]);
        }
        run.traceColumns(new TraceColumns() {
            @Override
            public String[] names() {
                return names.clone();
            }

            @Override
            public void values(double[] out) {
                for (int i = 0; i < ids.length; i++) {
                    out[i] = plant.measuredAngle(i);
                }
            }
        });
        run.requireRealtime();
    }

    /**
     * A report that turns bus problems into warnings located at {@code where} (without their
     * {@code "bus: "} prefix) and passes notes to {@code notes}.
     */
    static BusReport reportTo(SourcePos where, DiagnosticSink diags, Consumer<String> notes) {
        return new BusReport() {
            @Override
            public void problem(String message) {
                diags.warning(where, message.startsWith("bus: ") ? message.substring(5) : message);
            }

            @Override
            public void note(String message) {
                notes.accept(message);
            }
        };
    }

    /** The message of an I/O failure for the user. */
    static String message(IOException e) {
        return e.getMessage() == null ? e.toString() : e.getMessage();
    }
}
