package org.parpe.core.run;

import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Instance;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Program;
import org.parpe.core.model.StateDef;
import org.parpe.core.text.Msg;

/**
 * Breakpoints of the diagrams: on a module entering a state of an automaton, or on a state's
 * exit condition becoming true (the module leaves the state by it). The UI thread sets them;
 * during a run a {@link #watch watcher} on the engine thread looks, after every tick, at the
 * states the engine reports ({@link Engine#moduleStates}, {@link Engine#moduleExits}) and, at
 * the tick a breakpoint is reached, records the {@link Hit} and pauses the run (the same pause
 * as the Pause button: no further tick until Continue, so the simulator stands still and on
 * hardware every servo keeps the goal of that tick). The watcher allocates nothing per tick
 * except when a breakpoint is hit or the set was changed.
 */
public final class Breakpoints {

    /** What a breakpoint waits for. */
    public enum Kind {
        /** A module enters the state (also when it starts in it). */
        ENTER,
        /** The state's exit condition becomes true for a module (it leaves the state by it). */
        EXIT
    }

    /**
     * One breakpoint.
     *
     * @param automaton the automaton (or gait table) name
     * @param state     the state's index in its cycle
     * @param kind      what it waits for
     */
    public record Point(String automaton, int state, Kind kind) {
    }

    /**
     * A breakpoint reached.
     *
     * @param tick     the engine tick at which it was reached (the run pauses after it)
     * @param time     that tick's time, seconds
     * @param moduleId the first module (lowest index) that reached it
     * @param point    the breakpoint
     * @param state    the state's name
     */
    public record Hit(long tick, double time, int moduleId, Point point, String state) {

        /** What the IDE says about it. */
        public String describe() {
            return (point.kind() == Kind.ENTER ? Msg.BREAK_ENTERED : Msg.BREAK_EXIT).text(moduleId, point.automaton(), state, tick,
                    org.parpe.core.lang.Numbers.format(Math.round(time * 1e6) / 1e6));
        }
    }

    private volatile Set<Point> points = Set.of();
    private volatile Hit hit;

    /** Sets {@code p} if it is not set, else clears it (UI thread). */
    public synchronized void toggle(Point p) {
        Set<Point> next = new HashSet<>(points);
        if (!next.remove(p)) {
            next.add(p);
        }
        points = Set.copyOf(next);
    }

    /** Whether {@code p} is set. */
    public boolean has(Point p) {
        return points.contains(p);
    }

    /** The breakpoints set. */
    public Set<Point> points() {
        return points;
    }

    /** The breakpoint the run is paused at, or {@code null}. */
    public Hit hit() {
        return hit;
    }

    /** Forgets the hit (the run goes on). */
    public void clearHit() {
        hit = null;
    }

    /**
     * A watcher for a run of {@code e}, to add as an observer: it calls {@code pause} (on the
     * engine thread, after the tick's setpoints have gone to every plant) at the tick a
     * breakpoint is reached. Made before the run starts.
     */
    public JointSink watch(Engine e, Runnable pause) {
        hit = null;
        return new Watcher(e, pause);
    }

    private final class Watcher implements JointSink {
        private final Engine engine;
        private final Runnable pause;
        /** Per entry, per instance: the automaton and its state names. */
        private final String[][] automaton;
        private final String[][][] states;
        private final int[] instance;
        private final int[] state;
        private final int[] exited;
        private final int[] lastInstance;
        private final int[] lastState;
        private int lastEntry = -1;
        private Set<Point> compiled;
        private boolean[][][] onEnter;
        private boolean[][][] onExit;

        Watcher(Engine e, Runnable pause) {
            this.engine = e;
            this.pause = pause;
            Program p = e.program();
            List<MainEntry> entries = p.main() == null ? List.of() : p.main().entries();
            automaton = new String[entries.size()][];
            states = new String[entries.size()][][];
            for (int i = 0; i < entries.size(); i++) {
                Behavior b = entries.get(i).definition();
                List<Instance> list = b.instances();
                automaton[i] = new String[list.size()];
                states[i] = new String[list.size()][];
                for (int k = 0; k < list.size(); k++) {
                    automaton[i][k] = list.get(k).name();
                    states[i][k] = list.get(k).automaton().states().stream()
                            .map(StateDef::name).toArray(String[]::new);
                }
            }
            int n = e.moduleIds().length;
            instance = new int[n];
            state = new int[n];
            exited = new int[n];
            lastInstance = new int[n];
            lastState = new int[n];
            Arrays.fill(lastInstance, -1);
            Arrays.fill(lastState, -1);
            compile(points);
        }

        /** The breakpoints as flags per entry, instance and state (again only after a change). */
        private void compile(Set<Point> set) {
            compiled = set;
            onEnter = new boolean[automaton.length][][];
            onExit = new boolean[automaton.length][][];
            for (int i = 0; i < automaton.length; i++) {
                onEnter[i] = new boolean[automaton[i].length][];
                onExit[i] = new boolean[automaton[i].length][];
                for (int k = 0; k < automaton[i].length; k++) {
                    onEnter[i][k] = new boolean[states[i][k].length];
                    onExit[i][k] = new boolean[states[i][k].length];
                    for (Point pt : set) {
                        if (pt.automaton().equals(automaton[i][k]) && pt.state() >= 0 && pt.state() < states[i][k].length) {
                            (pt.kind() == Kind.ENTER ? onEnter : onExit)[i][k][pt.state()] = true;
                        }
                    }
                }
            }
        }

        @Override
        public void accept(long tick, double time, double[] commanded) {
            Set<Point> now = points;
            if (now != compiled) {
                compile(now);
            }
            int entry = engine.entryIndex();
            engine.moduleStates(instance, state);
            engine.moduleExits(exited);
            boolean newEntry = entry != lastEntry;
            Hit first = null;
            for (int m = 0; m < instance.length && entry >= 0 && entry < automaton.length; m++) {
                int i = instance[m];
                int s = state[m];
                if (i < 0 || i >= automaton[entry].length) {
                    continue;
                }
                if (first == null && exited[m] >= 0 && exited[m] < onExit[entry][i].length && onExit[entry][i][exited[m]]) {
                    first = hit(tick, time, m, entry, i, exited[m], Kind.EXIT);
                }
                boolean entered = newEntry || i != lastInstance[m] || s != lastState[m];
                if (first == null && entered && s >= 0 && s < onEnter[entry][i].length && onEnter[entry][i][s]) {
                    first = hit(tick, time, m, entry, i, s, Kind.ENTER);
                }
            }
            System.arraycopy(instance, 0, lastInstance, 0, instance.length);
            System.arraycopy(state, 0, lastState, 0, state.length);
            lastEntry = entry;
            if (first != null) {
                hit = first;
                pause.run();
            }
        }

        private Hit hit(long tick, double time, int m, int entry, int i, int s, Kind kind) {
            return new Hit(tick, time, engine.moduleIds()[m], new Point(automaton[entry][i], s, kind), states[entry][i][s]);
        }
    }
}
