package org.parpe.core.run;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import org.parpe.core.expr.EvalContext;
import org.parpe.core.model.Control;
import org.parpe.core.model.Program;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorTable;
import org.parpe.core.text.Msg;

/**
 * What flows into the scheduler at step 1 of a tick (PARSL.md §11): control changes queued by
 * other threads, due stimuli, and sensor readings with the stimulus overrides on top.
 */
final class TickInputs {
    private static final double EPS = 1e-9;

    private final Program program;
    private final EvalContext ctx;
    private final SensorTable sensors;
    private final double[] overrides;
    /** The slots a stimulus has overridden so far, in the order they were first set: each tick visits these, not every slot. */
    private final int[] overridden;
    private final boolean[] listed;
    private int overriddenCount;
    private final Stimulus[] stimuli;
    private final ConcurrentLinkedQueue<Runnable> commands = new ConcurrentLinkedQueue<>();
    private int nextStimulus;

    TickInputs(Program program, EvalContext ctx, SensorTable sensors, List<Stimulus> stimuli) {
        this.program = program;
        this.ctx = ctx;
        this.sensors = sensors;
        this.overrides = new double[sensors.moduleCount() * Channel.count()];
        Arrays.fill(overrides, Double.NaN);
        List<Stimulus> sorted = new ArrayList<>(stimuli);
        sorted.sort((a, b) -> Double.compare(a.time(), b.time())); // stable: equal times keep file order
        this.stimuli = sorted.toArray(new Stimulus[0]);
        this.overridden = new int[(int) Math.min(overrides.length, this.stimuli.length)];
        this.listed = new boolean[overrides.length];
        ctx.controls = new double[program.controls().size()];
        for (int i = 0; i < ctx.controls.length; i++) {
            ctx.controls[i] = program.controls().get(i).value();
        }
    }

    /** Queues a slider or text value (any thread). */
    void setControl(String name, double value) {
        int i = controlIndex(name);
        Control c = program.controls().get(i);
        if (c.type() == Control.ControlType.RADIO) {
            throw new IllegalArgumentException(Msg.CONTROL_IS_RADIO.text(name));
        }
        if (!Double.isFinite(value) || c.min() != null && (value < c.min() || value > c.max())) {
            throw new IllegalArgumentException(Msg.CONTROL_RANGE.text(name, c.min(), c.max(), value));
        }
        commands.add(() -> ctx.controls[i] = value);
    }

    /** Queues a radio word (any thread). */
    void setControlWord(String name, String word) {
        int i = controlIndex(name);
        Control c = program.controls().get(i);
        if (!c.words().contains(word)) {
            throw new IllegalArgumentException(Msg.STIMULUS_RADIO_WORD.text(name, word, String.join(", ", c.words())));
        }
        double code = program.radioWords().get(word);
        commands.add(() -> ctx.controls[i] = code);
    }

    /** The current value of a control (engine thread). */
    double control(String name) {
        return ctx.controls[controlIndex(name)];
    }

    private int controlIndex(String name) {
        for (int i = 0; i < program.controls().size(); i++) {
            if (program.controls().get(i).name().equals(name)) {
                return i;
            }
        }
        throw new IllegalArgumentException(Msg.UNKNOWN_CONTROL.text(name));
    }

    /**
     * Step 1 of a tick: queued commands, stimuli due by {@code ctx.time}, then sensor readings
     * from {@code source} (or, without one, the commanded angles of the previous tick) with
     * the stimulus overrides applied.
     */
    void read(SensorSource source, double[] commanded) {
        Runnable cmd;
        while ((cmd = commands.poll()) != null) {
            cmd.run();
        }
        while (nextStimulus < stimuli.length && stimuli[nextStimulus].time() <= ctx.time + EPS) {
            Stimulus s = stimuli[nextStimulus++];
            if (s.target() == Stimulus.Kind.CONTROL) {
                ctx.controls[s.index()] = s.value();
            } else {
                if (!listed[s.index()]) {
                    listed[s.index()] = true;
                    overridden[overriddenCount++] = s.index();
                }
                overrides[s.index()] = s.value();
            }
        }
        if (source != null) {
            source.read(ctx.time, sensors);
        } else {
            for (int i = 0; i < commanded.length; i++) {
                sensors.set(i, Channel.ANGLE, commanded[i]);
            }
        }
        for (int i = 0; i < overriddenCount; i++) {
            int slot = overridden[i];
            if (!Double.isNaN(overrides[slot])) {
                sensors.setSlot(slot, overrides[slot]);
            }
        }
    }
}
