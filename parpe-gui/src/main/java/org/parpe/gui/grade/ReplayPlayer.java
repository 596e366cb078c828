package org.parpe.gui.grade;

import org.parpe.gui.text.UiMsg;
import java.nio.file.Path;
import java.util.function.Consumer;
import org.eclipse.swt.widgets.Display;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.grade.Replay;
import org.parpe.sim.world.Challenge;
import org.parpe.sim.world.World;

/**
 * Plays a graded run back from its trace ({@link Replay}) on a thread of its own, at the speed
 * the run had in simulated time; the 3D view pulls {@link #snapshot} on its own timer. What the
 * player has to say (it started, it ended, the trace cannot be used) goes to the UI thread.
 */
final class ReplayPlayer {
    private final Display display;
    private volatile Replay replay;
    private volatile boolean stop;
    private final String name;
    private final Thread thread;

    /**
     * Starts playing {@code trace}, student {@code name}'s run of {@code c} in {@code world};
     * {@code said} is told on the UI thread why the trace cannot be played, if it cannot.
     */
    ReplayPlayer(Display display, String name, Challenge c, World world, Path trace, Consumer<String> said) {
        this.display = display;
        this.name = name;
        thread = new Thread(() -> play(c, world, trace, said), "parpe-class-replay");
        thread.setDaemon(true);
        thread.start();
    }

    private void play(Challenge c, World world, Path trace, Consumer<String> said) {
        try (Replay r = Replay.of(c, world, trace)) {
            replay = r;
            long t0 = System.nanoTime();
            while (!stop && r.position() < r.ticks()) {
                double due = (System.nanoTime() - t0) / 1e9 / c.tick(); // the ticks simulated time has reached
                while (!stop && r.position() < due && r.advance()) {
                    // catch up with the clock
                }
                Thread.sleep(10);
            }
            if (!stop) {
                Thread.sleep(Long.MAX_VALUE); // keep the last picture until the next replay or the window closes
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (Exception e) {
            tell(said, UiMsg.CLASS_CANNOT_REPLAY.text(e.getMessage()));
        } finally {
            replay = null;
        }
    }

    private void tell(Consumer<String> said, String text) {
        if (!display.isDisposed()) {
            display.asyncExec(() -> said.accept(text));
        }
    }

    /** The replayed world now, or null before it starts or after it was stopped. */
    SimSnapshot snapshot() {
        Replay r = replay;
        return r == null ? null : r.snapshot();
    }

    /** The line the 3D view shows in its corner: whose run, and the simulated time. */
    String caption() {
        SimSnapshot s = snapshot();
        return s == null ? "" : UiMsg.CLASS_REPLAY_OF.text(name, String.format(java.util.Locale.ROOT, "%.2f", s.time()));
    }

    /** Whether the replay is still playing or showing its last picture. */
    boolean alive() {
        return thread.isAlive();
    }

    /** Stops playing (the simulator is closed by the player's thread). */
    void stop() {
        stop = true;
        thread.interrupt();
    }
}
