package org.parpe.sim;

import org.parpe.sim.internal.PhysicsWorld;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldScore;

/**
 * Scores a run in a {@link World} tick by tick, as the world's scoring declares: when the
 * robot's centre of mass first enters the goal zone, its best progress along the path from the
 * start through the checkpoints in order, lever presses (each one must go back below half of
 * the press angle before the next counts), objects in their zones; disqualification when the
 * root tilts too far or the centre of mass leaves the arena before the robot reached the goal
 * zone (a robot that finished is not judged on what it does afterwards). Does not allocate per
 * tick.
 */
final class Referee {
    private final PhysicsWorld world;
    private final World scene;
    private final World.Scoring rules;
    /** Path vertices x, y: the start's centre of mass, then each checkpoint's centre. */
    private final double[] path;
    private final double[] cumulative;
    private final boolean[] pressed;
    private final int[] pressCount;
    private final double[] objectCentre = new double[3];
    private double startTime;
    private double timeToZone;
    private double best;
    private int nextCheckpoint;
    private String disqualified;
    private boolean marked;
    /** The score's parts at the last marked tick. */
    private final Parts kept = new Parts();

    Referee(PhysicsWorld world, World scene) {
        this.world = world;
        this.scene = scene;
        this.rules = scene.scoring();
        int n = scene.checkpoints().size();
        path = new double[2 * (n + 1)];
        cumulative = new double[n + 1];
        pressed = new boolean[scene.levers().size()];
        pressCount = new int[scene.levers().size()];
    }

    /** Starts scoring from the current state, with the robot's centre of mass at {@code com}. */
    void reset(double[] com) {
        startTime = world.time();
        timeToZone = Double.NaN;
        best = 0;
        nextCheckpoint = 0;
        disqualified = "";
        marked = false;
        java.util.Arrays.fill(pressed, false);
        java.util.Arrays.fill(pressCount, 0);
        path[0] = com[0];
        path[1] = com[1];
        for (int i = 0; i < scene.checkpoints().size(); i++) {
            World.Region c = scene.checkpoints().get(i);
            path[2 * i + 2] = c.cx();
            path[2 * i + 3] = c.cy();
            cumulative[i + 1] = cumulative[i] + Math.hypot(path[2 * i + 2] - path[2 * i], path[2 * i + 3] - path[2 * i + 1]);
        }
    }

    /** Updates after a tick, with the robot's centre of mass and its root's tilt so far (radians). */
    void update(double[] com, double maxTilt) {
        if (!disqualified.isEmpty()) {
            return;
        }
        double x = com[0];
        double y = com[1];
        boolean finished = rules.goal() != null && !Double.isNaN(timeToZone);
        if (finished) {
            // past the finish nothing is judged any more but the levers and objects
        } else if (!Double.isNaN(rules.maxTiltDeg()) && Math.toDegrees(maxTilt) > rules.maxTiltDeg()) {
            disqualified = "tilt";
        } else if (rules.leaveArena() && scene.arena() != null && !scene.arena().contains(x, y)) {
            disqualified = "arena";
        }
        if (rules.goal() != null && Double.isNaN(timeToZone) && rules.goal().zone().contains(x, y)) {
            timeToZone = world.time() - startTime;
        }
        int n = scene.checkpoints().size();
        while (nextCheckpoint < n && scene.checkpoints().get(nextCheckpoint).contains(x, y)) {
            nextCheckpoint++;
        }
        best = Math.max(best, progress(x, y));
        for (int i = 0; i < pressed.length; i++) {
            double a = world.leverAngle(i);
            World.Lever l = scene.levers().get(i);
            if (!pressed[i] && a >= l.pressAngle()) {
                pressed[i] = true;
                pressCount[i]++;
            } else if (pressed[i] && a < l.pressAngle() / 2) {
                pressed[i] = false;
            }
        }
    }

    /** Distance along the path to the projection of (x, y) on the leg towards the next checkpoint. */
    private double progress(double x, double y) {
        int n = scene.checkpoints().size();
        if (n == 0) {
            return 0;
        }
        if (nextCheckpoint == n) {
            return cumulative[n];
        }
        int a = 2 * nextCheckpoint;
        double dx = path[a + 2] - path[a];
        double dy = path[a + 3] - path[a + 1];
        double len = Math.hypot(dx, dy);
        if (len == 0) {
            return cumulative[nextCheckpoint];
        }
        double t = ((x - path[a]) * dx + (y - path[a + 1]) * dy) / len;
        return cumulative[nextCheckpoint] + Math.max(0, Math.min(len, t));
    }

    /**
     * Remembers the score of the tick being emitted, before the plant moves on (as
     * {@link MotionTracker#mark} does for the distance).
     */
    void mark() {
        marked = true;
        kept.points = tally(true);
    }

    /** The points now, for a live display. */
    double livePoints() {
        return tally(false);
    }

    /** The points now (the score if the run ended here); {@code keep}: also keeps the parts. */
    private double tally(boolean keep) {
        int delivered = 0;
        double points = 0;
        // Indexed loops: this runs every tick, and a list's iterator is an object (issue 36).
        for (int di = 0; di < rules.deliveries().size(); di++) {
            World.Delivery d = rules.deliveries().get(di);
            for (int i = 0; i < scene.objects().size(); i++) {
                if (scene.objects().get(i).name().startsWith(d.objects())) {
                    world.objectCentre(i, objectCentre);
                    if (d.zone().contains(objectCentre[0], objectCentre[1])) {
                        delivered++;
                        points += d.points();
                    }
                }
            }
        }
        int presses = 0;
        for (int pi = 0; pi < rules.presses().size(); pi++) {
            World.Presses p = rules.presses().get(pi);
            presses += pressCount[p.lever()];
            points += p.points() * pressCount[p.lever()];
        }
        if (rules.goal() != null && !Double.isNaN(timeToZone)) {
            points += rules.goal().points() + rules.goal().perSecondLeft() * Math.max(0, scene.timeLimit() - timeToZone);
        }
        points += rules.pathPerMetre() * best;
        if (keep) {
            kept.delivered = delivered;
            kept.presses = presses;
            kept.timeToZone = timeToZone;
            kept.best = best;
            kept.checkpoints = nextCheckpoint;
            kept.disqualified = disqualified;
        }
        return disqualified.isEmpty() ? points : 0;
    }

    /** The score at the last marked tick, or now when no tick was marked (stepped by hand). */
    WorldScore score() {
        if (!marked) {
            kept.points = tally(true);
        }
        return new WorldScore(kept.points, kept.timeToZone, kept.best, kept.checkpoints, kept.delivered, kept.presses,
                kept.disqualified);
    }

    /** A {@link WorldScore}'s parts, overwritten at every marked tick so that marking does not allocate. */
    private static final class Parts {
        double points;
        int delivered;
        int presses;
        double timeToZone;
        double best;
        int checkpoints;
        String disqualified;
    }
}
