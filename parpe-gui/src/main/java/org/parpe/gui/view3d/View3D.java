package org.parpe.gui.view3d;

import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.function.Supplier;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Event;
import org.parpe.gui.text.PanelMsg;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.geom.Vec3;

/**
 * The 3D view in the spirit of PBSim: draws the latest simulator snapshot on a double-buffered
 * canvas at about 30 frames a second. Left drag orbits, right (or Shift+left, or middle) drag
 * pans, the wheel zooms; TrackRobot keeps the robot's centre of mass in the middle. The
 * snapshot is pulled from a supplier on the UI thread's timer, never pushed by the engine.
 * While a {@link JointDrag} is set (the Pose panel), a left drag on a module turns its joint
 * and Ctrl+click picks modules.
 */
public final class View3D {
    private static final int FRAME_MS = 33;

    private final Canvas canvas;
    private final Camera camera = new Camera();
    private final SceneRenderer renderer = new SceneRenderer();
    private Supplier<SimSnapshot> source = () -> null;
    private Supplier<Set<Integer>> highlighted = Set::of;
    private Supplier<String> overlay = () -> "";
    private BuildLayer builder;
    private Point pressed;
    private String emptyText = PanelMsg.VIEW3D_EMPTY.text();
    private boolean track = true;
    private boolean labels;
    private boolean animating;
    private SimSnapshot framedFor;
    private SimSnapshot last;
    private Point drag;
    private int dragButton;
    private long frames;
    private JointDrag jointDrag;
    private int turning = -1;
    /** The module a left drag would turn now (the mouse is over it), or −1: a drag orbits. */
    private int hover = -1;
    private boolean hovering;
    /** TrackRobot's readout: the centre of mass at the start of the run, and its path since. */
    private final RunTrail trail = new RunTrail();

    /** Creates the view in {@code parent}. */
    public View3D(Composite parent) {
        canvas = new Canvas(parent, SWT.DOUBLE_BUFFERED | SWT.NO_BACKGROUND);
        canvas.addListener(SWT.Paint, this::paint);
        canvas.addListener(SWT.MouseDown, e -> {
            drag = new Point(e.x, e.y);
            pressed = drag;
            dragButton = e.button == 1 && (e.stateMask & SWT.SHIFT) != 0 ? 2 : e.button;
            turning = e.button == 1 && (e.stateMask & SWT.SHIFT) == 0 ? grab(e) : -1;
            canvas.setFocus();
        });
        canvas.addListener(SWT.MouseUp, e -> {
            drag = null;
            turning = -1;
            BuildLayer b = builder;
            // a click, not the end of a drag: the builder picks what is under it
            if (b != null && e.button == 1 && pressed != null && Math.abs(e.x - pressed.x) + Math.abs(e.y - pressed.y) < CLICK_SLOP) {
                b.clicked(e.x, e.y, e.stateMask, false);
            }
            pressed = null;
        });
        canvas.addListener(SWT.MouseMove, this::mouseMove);
        canvas.addListener(SWT.MouseExit, e -> hoverAt(-1, -1));
        canvas.addListener(SWT.MouseVerticalWheel, e -> {
            // Towards the group being posed (the Pose panel's), not the body's centre.
            double[] c = centre(highlighted.get());
            if (c != null) {
                camera.lookAt(c[0], c[1], c[2]);
                track = false;
                framedFor = last;
            }
            camera.zoom(e.count > 0 ? 0.88 : 1.0 / 0.88);
            canvas.redraw();
        });
        canvas.addListener(SWT.MouseDoubleClick, e -> {
            BuildLayer b = builder;
            if (b == null || !b.clicked(e.x, e.y, e.stateMask, true)) {
                resetView();
            }
        });
    }

    /** Pixels the mouse may move between press and release and still click (not drag). */
    private static final int CLICK_SLOP = 5;

    /**
     * Building on the view (the Robot tab): it draws over each frame, picks on clicks, paints
     * pieces in its own colours and shows pieces not yet placed translucent. Null: none.
     */
    public void setBuilder(BuildLayer b) {
        builder = b;
        canvas.redraw();
    }

    /**
     * Where world point {@code p} appears on the canvas with the camera of the last frame drawn,
     * as {x, y, pixels per metre there}, or null when it is behind the eye.
     */
    public double[] project(Vec3 p) {
        double[] c = new double[3];
        camera.toCamera(p.x(), p.y(), p.z(), c);
        if (c[2] < SceneRenderer.NEAR_VIEW) {
            return null;
        }
        return new double[] {camera.screenX(c[0], c[2]), camera.screenY(c[1], c[2]), camera.scale(c[2])};
    }

    /** The camera's eye in world coordinates in the last frame drawn (x, y, z). */
    public double[] eye() {
        return camera.eye().clone();
    }

    /** The part under canvas point (x, y) in the last frame drawn (any piece, active or passive), or null. */
    public String partAt(int x, int y) {
        SimBody b = Picking.bodyAt(camera, last, x, y, false);
        return b == null ? null : b.part();
    }

    /** Turns the view around the robot by the given angles, radians (the benchmark, tests). */
    public void rotate(double dYaw, double dPitch) {
        camera.rotate(dYaw, dPitch);
        canvas.redraw();
    }

    /** The canvas. */
    public Canvas control() {
        return canvas;
    }

    /** Where snapshots come from (called on the UI thread, may return null). */
    public void setSource(Supplier<SimSnapshot> source) {
        this.source = source;
    }

    /** Where snapshots come from now (to show another picture for a while and then give the view back). */
    public Supplier<SimSnapshot> source() {
        return source;
    }

    /** Which modules are highlighted now. */
    public Supplier<Set<Integer>> highlighted() {
        return highlighted;
    }

    /**
     * Posing with the mouse (null: none). While set, a left press on a module the handler accepts
     * turns that module's joint as the mouse moves up and down, instead of orbiting; Ctrl+click
     * picks a module.
     */
    public void setJointDrag(JointDrag d) {
        jointDrag = d;
        turning = -1;
    }

    /** Posing with the mouse in the 3D view. */
    public interface JointDrag {
        /** Whether the joint of module {@code id} may be turned now. */
        boolean canTurn(int id);

        /** Turns the joint of module {@code id} by {@code degrees}. */
        void turn(int id, double degrees);

        /** Module {@code id} was Ctrl+clicked. */
        void picked(int id);
    }

    /** Degrees a joint turns per pixel of mouse movement. */
    public static final double DEGREES_PER_PIXEL = 0.5;

    /** The module under canvas point (x, y) in the last frame drawn, or −1. */
    public int moduleAt(int x, int y) {
        return Picking.moduleAt(camera, last, x, y);
    }

    /** Where module {@code id}'s segment appears on the canvas in the last frame drawn, or null. */
    public Point screenPoint(int id) {
        return Picking.screenPoint(camera, last, id);
    }

    /** A left press: the module whose joint to turn, or −1 (orbit); a Ctrl+click picks instead. */
    private int grab(Event e) {
        JointDrag d = jointDrag;
        if (d == null) {
            return -1;
        }
        int id = moduleAt(e.x, e.y);
        if (id >= 0 && (e.stateMask & SWT.MOD1) != 0) {
            d.picked(id);
            return -1;
        }
        return id >= 0 && d.canTurn(id) ? id : -1;
    }

    /** Which modules to highlight (those driven by the current behavior). */
    public void setHighlighted(Supplier<Set<Integer>> highlighted) {
        this.highlighted = highlighted;
    }

    /** The text in the corner while there is no robot to draw (a hint what to do). */
    public void setEmptyText(String text) {
        emptyText = text;
        canvas.redraw();
    }

    /** A line of text drawn in the corner (simulated time). */
    public void setOverlay(Supplier<String> overlay) {
        this.overlay = overlay;
    }

    /** Keeps the robot centred. */
    public void setTrackRobot(boolean on) {
        track = on;
        canvas.redraw();
    }

    /** Shows the module IDs. */
    public void setShowIds(boolean on) {
        labels = on;
        canvas.redraw();
    }

    /** Whether the module IDs are shown. */
    public boolean showIds() {
        return labels;
    }

    /** Forgets the robot drawn (another script was opened). */
    public void clear() {
        last = null;
        framedFor = null;
        trail.clear();
        canvas.redraw();
    }

    /** Frames the robot again on the next snapshot. */
    public void resetView() {
        // The angle too: after a drag that went wrong, Reset view gives back the usual view.
        camera.resetAngles();
        framedFor = null;
        canvas.redraw();
    }

    /** Starts redrawing on a timer (idempotent). */
    public void startAnimation() {
        if (animating) {
            return;
        }
        animating = true;
        Runnable tick = new Runnable() {
            @Override
            public void run() {
                if (canvas.isDisposed() || !animating) {
                    animating = false;
                    return;
                }
                if (canvas.isVisible()) {
                    canvas.redraw();
                }
                canvas.getDisplay().timerExec(FRAME_MS, this);
            }
        };
        canvas.getDisplay().timerExec(FRAME_MS, tick);
    }

    /** Stops the timer (the view still redraws when exposed). */
    public void stopAnimation() {
        animating = false;
    }

    /** Frames painted since creation (for the benchmark). */
    public long frames() {
        return frames;
    }

    /** The snapshot drawn last, or null. */
    public SimSnapshot lastSnapshot() {
        return last;
    }

    private void mouseMove(Event e) {
        if (drag == null) {
            hoverAt(e.x, e.y);
            return;
        }
        int dx = e.x - drag.x;
        int dy = e.y - drag.y;
        drag = new Point(e.x, e.y);
        Rectangle r = canvas.getClientArea();
        JointDrag d = jointDrag;
        if (turning >= 0 && d != null) {
            d.turn(turning, -dy * DEGREES_PER_PIXEL);
        } else if (dragButton == 1) {
            camera.rotate(-dx * 0.01, dy * 0.01);
        } else {
            camera.pan(dx / (double) Math.max(1, r.height), dy / (double) Math.max(1, r.height));
            track = false;
        }
        canvas.redraw();
    }

    /**
     * The mouse is at (x, y) without a button down (−1, −1: it left): while posing, the module
     * under it whose joint a drag would turn is lit and the cursor is the up-down arrow; anywhere
     * else the cursor is the arrow and a drag orbits. The corner says which.
     */
    private void hoverAt(int x, int y) {
        JointDrag d = jointDrag;
        int id = d == null || x < 0 ? -1 : moduleAt(x, y);
        int now = id >= 0 && d.canTurn(id) ? id : -1;
        boolean over = d != null && x >= 0;
        if (now != hover || over != hovering) {
            hover = now;
            hovering = over;
            canvas.setCursor(now >= 0 ? canvas.getDisplay().getSystemCursor(SWT.CURSOR_SIZENS) : null);
            canvas.redraw();
        }
    }

    /** The module a left drag would turn now, or −1 (it would orbit). */
    public int hovered() {
        return hover;
    }

    /** What a left drag does now, as the corner of the view says it while posing ("" when not posing). */
    public String dragHint() {
        if (jointDrag == null || !hovering) {
            return "";
        }
        return hover >= 0 ? PanelMsg.VIEW3D_BEND.text(hover) : PanelMsg.VIEW3D_TURN.text();
    }

    /** The centre of modules {@code ids} in the last picture, or null when none is drawn. */
    private double[] centre(Set<Integer> ids) {
        SimSnapshot snap = last;
        if (snap == null || ids.isEmpty()) {
            return null;
        }
        double x = 0, y = 0, z = 0;
        int n = 0;
        for (SimBody b : snap.bodies()) {
            if (ids.contains(b.moduleId())) {
                x += b.position().x();
                y += b.position().y();
                z += b.position().z();
                n++;
            }
        }
        return n == 0 ? null : new double[] {x / n, y / n, z / n};
    }

    /** The renderer (tests). */
    SceneRenderer renderer() {
        return renderer;
    }

    /** Where the camera looks (x, y, z; tests). */
    public double[] target() {
        return camera.target.clone();
    }

    /** TrackRobot's distance of the centre of mass from where the run started, in metres (NaN before a run). */
    public double distanceFromStart() {
        return trail.distanceFromStart(last);
    }

    /** The points of TrackRobot's trail (tests). */
    public int trailPoints() {
        return trail.points().size();
    }

    private void paint(Event e) {
        Rectangle r = canvas.getClientArea();
        render(e.gc, r.width, r.height);
        frames++;
    }

    /** Draws one frame of the current snapshot on {@code gc} (also used to time drawing off screen). */
    public void render(GC gc, int width, int height) {
        SimSnapshot snap = source.get();
        if (snap != null) {
            last = snap;
        }
        snap = last;
        // a new run is framed when the view does not track the robot, so that it never starts off the screen
        if (snap != null && trail.add(snap) && !track) {
            framedFor = null;
        }
        if (snap != null && framedFor == null) {
            frame(snap);
        }
        if (snap != null && track && snap.centerOfMass().isFinite()) {
            Vec3 c = snap.centerOfMass();
            camera.follow(c.x(), c.y(), Math.max(0.0, c.z()), 0.25);
        }
        gc.setAntialias(SWT.ON);
        BuildLayer b = builder;
        renderer.draw(gc, camera, snap, new SceneRenderer.Style(highlighted.get(), labels, hover,
                b == null ? null : b::colour), width, height);
        if (snap != null && track) {
            renderer.trail(gc, camera, trail.points());
        }
        if (b != null) {
            renderer.ghosts(gc, camera, b.ghosts());
            b.decorate(gc);
        }
        gc.setAntialias(SWT.DEFAULT);
        hud(gc, snap);
    }

    private void hud(GC gc, SimSnapshot snap) {
        gc.setForeground(renderer.color(0x2A3648));
        gc.drawText(hudText(), 8, 6, true);
        String hint = dragHint();
        if (!hint.isEmpty()) {
            gc.drawText(hint, 8, 6 + gc.getFontMetrics().getHeight() + 2, true);
        }
    }

    /** The line of text in the corner now: the overlay (time), and with TrackRobot the distance from the start. */
    public String hudText() {
        SimSnapshot snap = last;
        double d = distanceFromStart();
        String text = snap == null ? emptyText : overlay.get();
        return snap != null && track && !Double.isNaN(d)
                ? text + (text.isEmpty() ? "" : "   ") + PanelMsg.VIEW3D_FROM_START.text(String.format(Locale.ROOT, "%.2f", d)) : text;
    }

    /**
     * Points the camera from close by at modules {@code ids} of the last picture (the group being
     * posed) and stops tracking the robot, so that it stays there; false if none is drawn.
     */
    public boolean focus(Set<Integer> ids) {
        SimSnapshot snap = last;
        double minX = 1e9, minY = 1e9, maxX = -1e9, maxY = -1e9, maxZ = 0;
        boolean any = false;
        for (SimBody b : snap == null ? List.<SimBody>of() : snap.bodies()) {
            if (ids.contains(b.moduleId())) {
                Vec3 p = b.position();
                minX = Math.min(minX, p.x());
                maxX = Math.max(maxX, p.x());
                minY = Math.min(minY, p.y());
                maxY = Math.max(maxY, p.y());
                maxZ = Math.max(maxZ, p.z());
                any = true;
            }
        }
        if (!any) {
            return false;
        }
        track = false;
        framedFor = snap;
        camera.lookAt((minX + maxX) / 2, (minY + maxY) / 2, maxZ / 2);
        camera.setDistance(Math.max(0.15, Math.max(maxX - minX, maxY - minY)) * 2 + 0.3);
        canvas.redraw();
        return true;
    }

    /** Points the camera at the robot from a distance that shows all of it. */
    private void frame(SimSnapshot snap) {
        framedFor = snap;
        double minX = 1e9, minY = 1e9, maxX = -1e9, maxY = -1e9, maxZ = -1e9;
        for (SimBody b : snap.bodies()) {
            Vec3 p = b.position();
            minX = Math.min(minX, p.x());
            maxX = Math.max(maxX, p.x());
            minY = Math.min(minY, p.y());
            maxY = Math.max(maxY, p.y());
            maxZ = Math.max(maxZ, p.z());
        }
        if (snap.bodies().isEmpty()) {
            return;
        }
        // a robot that stands up (a loop, lesson 15) is framed on its height as well as its footprint
        double size = Math.max(0.2, Math.max(Math.max(maxX - minX, maxY - minY), maxZ));
        camera.lookAt((minX + maxX) / 2, (minY + maxY) / 2, Math.max(0.03, maxZ / 2));
        camera.setDistance(size * 1.25 + 0.2);
    }
}
