package org.parpe.gui.run;

import org.parpe.core.run.Engine;

/**
 * The state each module is in, as the running engine last published it, for live views: the
 * engine thread copies {@link Engine#moduleStates} into its own arrays (allocating nothing) and
 * then, under a short lock, into the shared ones; the UI thread copies them out under the same
 * lock. Neither waits for more than an array copy.
 */
public final class LiveStates {
    private int[] ids = new int[0];
    private int[] instance = new int[0];
    private int[] state = new int[0];
    private int[] engineInstance = new int[0];
    private int[] engineState = new int[0];
    private double[] progress = new double[0];
    private double[] engineProgress = new double[0];
    private int entry = -1;
    private long tick = -1;
    private long published;

    /** A new run of {@code e} starts (engine thread, before its first tick). */
    synchronized void start(Engine e) {
        ids = e.moduleIds().clone();
        int n = ids.length;
        instance = new int[n];
        state = new int[n];
        engineInstance = new int[n];
        engineState = new int[n];
        progress = new double[n];
        engineProgress = new double[n];
        java.util.Arrays.fill(progress, -1);
        java.util.Arrays.fill(instance, -1);
        java.util.Arrays.fill(state, -1);
        entry = -1;
        tick = -1;
        published++;
    }

    /** Publishes the states of the last tick (engine thread). */
    void publish(Engine e, long atTick, int atEntry) {
        e.moduleStates(engineInstance, engineState);
        e.moduleProgress(engineProgress);
        synchronized (this) {
            System.arraycopy(engineProgress, 0, progress, 0, progress.length);
            System.arraycopy(engineInstance, 0, instance, 0, instance.length);
            System.arraycopy(engineState, 0, state, 0, state.length);
            entry = atEntry;
            tick = atTick;
            published++;
        }
    }

    /**
     * A copy of the last published states, or {@code null} when nothing new was published
     * since {@code seen} (the {@link Frame#version()} of the caller's last frame).
     */
    public synchronized Frame since(long seen) {
        if (published == seen) {
            return null;
        }
        return new Frame(published, tick, entry, ids, instance.clone(), state.clone(), progress.clone());
    }

    /**
     * The states at one tick (UI side; a copy).
     *
     * @param version  how many times states were published before this copy
     * @param tick     the engine tick, or −1 before the first
     * @param entry    the {@code <main>} entry that ran, or −1
     * @param ids      the module IDs, by index
     * @param instance per module, the instance (document position in the entry's behavior) that drove it, or −1
     * @param state    per module, that instance's state index, or −1
     * @param progress per module, how far it is through that state, in [0, 1], or −1
     */
    public record Frame(long version, long tick, int entry, int[] ids, int[] instance, int[] state, double[] progress) {
    }
}
