package org.parpe.core.run;

import java.util.concurrent.locks.LockSupport;

/**
 * Paces a run to the wall clock at a speed factor (1 = real time, 2 = twice as fast,
 * {@code +∞} = as fast as possible), with pause. Speed and pause may be changed from any
 * thread; they take effect at the next tick. When the plant cannot keep up for more than
 * {@value #MAX_LAG_S} s, pacing carries on from where the run is instead of racing to catch up.
 */
public final class WallClockPacer implements Pacer {
    static final double MAX_LAG_S = 0.25;
    private static final long PAUSE_POLL_NS = 20_000_000L;

    private volatile double factor;
    private volatile boolean paused;
    private double pacedAt = Double.NaN;
    private long wall0;
    private double sim0;

    /** A pacer at {@code factor} times real time. */
    public WallClockPacer(double factor) {
        setFactor(factor);
    }

    /** Changes the speed factor (> 0; {@code Double.POSITIVE_INFINITY} for no pacing). */
    public void setFactor(double factor) {
        if (!(factor > 0)) {
            throw new IllegalArgumentException("speed factor must be > 0, got " + factor);
        }
        this.factor = factor;
    }

    public double factor() {
        return factor;
    }

    /** Pauses or resumes: while paused, the run waits before its next tick. */
    public void setPaused(boolean paused) {
        this.paused = paused;
    }

    public boolean paused() {
        return paused;
    }

    @Override
    public void beforeTick(Run run, double time) throws InterruptedException {
        if (paused) {
            while (paused && !run.stopRequested()) {
                LockSupport.parkNanos(PAUSE_POLL_NS);
                if (Thread.interrupted()) {
                    throw new InterruptedException();
                }
            }
            pacedAt = Double.NaN; // resume from here, not from before the pause
        }
        double f = factor;
        long now = System.nanoTime();
        if (f != pacedAt) {
            pacedAt = f;
            wall0 = now;
            sim0 = time;
            return;
        }
        if (!Double.isFinite(f)) {
            return;
        }
        double ahead = (time - sim0) / f - (now - wall0) / 1e9;
        if (ahead > 0) {
            long until = now + (long) (ahead * 1e9);
            long left;
            while ((left = until - System.nanoTime()) > 0 && !run.stopRequested()) {
                LockSupport.parkNanos(Math.min(left, PAUSE_POLL_NS));
                if (Thread.interrupted()) {
                    throw new InterruptedException();
                }
            }
        } else if (ahead < -MAX_LAG_S) {
            wall0 = now;
            sim0 = time;
        }
    }
}
