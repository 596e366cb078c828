package org.parpe.sim.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.net.URLClassLoader;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The patched SAP space ({@code org.ode4j.ode.internal.DxSAPSpace} of this module: a sorted
 * lookup in {@code collide2}, a sort that starts from the last step's order in {@code collide})
 * calls the near callback with the same pairs in the same order as ODE4j 0.5.3's own class, which
 * is the reference: the order of the pairs is the order of the contact joints, and so of the
 * solver's rows (traces stay byte-identical only if it is kept). The same scene is built twice, in
 * this module's classes and in ODE4j's jar loaded on its own, and moved over several steps: boxes
 * of many sizes (some sharing a start on the sorted axis), long walls, a plane, geoms moved and
 * disabled between steps.
 */
class SapSpaceOrderTest {
    private static final int MOVING = 120;
    private static final int FIXED = 45;
    private static final int STEPS = 12;

    @Test
    void pairsAndTheirOrderAreOdes() throws Exception {
        ClassLoader ours = SapSpaceOrderTest.class.getClassLoader();
        try (URLClassLoader odes = OdesOwnJar.open("org.ode4j.ode.internal.DxSAPSpace")) {
            List<String> expected = new Scene(odes).run();
            List<String> actual = new Scene(ours).run();
            assertTrue(expected.size() > 1000, "the scene pairs few geoms: " + expected.size());
            assertEquals(expected.size(), actual.size());
            for (int i = 0; i < expected.size(); i++) {
                assertEquals(expected.get(i), actual.get(i), "pair " + i);
            }
        }
    }

    /** The scene, driven by reflection in the classes of one loader; records "step: a-b" per callback. */
    private static final class Scene {
        private final ClassLoader loader;
        private final Class<?> helper;
        private final Class<?> geom;
        private final Class<?> space;
        private final Method setPosition;
        private final Method getData;
        private final List<String> pairs = new ArrayList<>();
        private int step;

        Scene(ClassLoader loader) throws Exception {
            this.loader = loader;
            helper = loader.loadClass("org.ode4j.ode.OdeHelper");
            geom = loader.loadClass("org.ode4j.ode.DGeom");
            space = loader.loadClass("org.ode4j.ode.DSpace");
            setPosition = geom.getMethod("setPosition", double.class, double.class, double.class);
            getData = geom.getMethod("getData");
        }

        List<String> run() throws Exception {
            helper.getMethod("initODE2", int.class).invoke(null, 0);
            Class<?> axes = loader.loadClass("org.ode4j.ode.DSapSpace$AXES");
            Method createSap = helper.getMethod("createSapSpace", axes);
            Object xyz = axes.getField("XYZ").get(null);
            Object moving = createSap.invoke(null, xyz);
            Object fixed = createSap.invoke(null, xyz);
            Method box = helper.getMethod("createBox", space, double.class, double.class, double.class);
            Method setData = geom.getMethod("setData", Object.class);
            Random r = new Random(36);
            Object[] parts = new Object[MOVING];
            double length = 0;
            for (int i = 0; i < MOVING; i++) {
                // every tenth part is as long as the one before it, and lies at the same x (a tie in the sort)
                length = i % 10 == 1 ? length : 0.02 + 0.1 * r.nextDouble();
                parts[i] = box.invoke(null, moving, length, 0.02 + 0.05 * r.nextDouble(), 0.03);
                setData.invoke(parts[i], i);
            }
            Object plane = helper.getMethod("createPlane", space, double.class, double.class, double.class, double.class)
                    .invoke(null, moving, 0, 0, 1, 0);
            setData.invoke(plane, -1);
            for (int i = 0; i < FIXED; i++) {
                boolean wall = i % 9 == 0;
                Object g = box.invoke(null, fixed, wall ? 3 : 0.01 + 0.04 * r.nextDouble(), wall ? 0.02 : 0.03, 0.1);
                setData.invoke(g, 1000 + i);
                setPosition.invoke(g, wall ? 1.5 : 2 * r.nextDouble(), 0.6 * r.nextDouble() - 0.3, 0.02);
            }
            Object callback = Proxy.newProxyInstance(loader, new Class<?>[] {loader.loadClass("org.ode4j.ode.DGeom$DNearCallback")},
                    (proxy, method, args) -> {
                        if (method.getName().equals("call")) {
                            pairs.add(step + ": " + getData.invoke(args[1]) + "-" + getData.invoke(args[2]));
                        }
                        return null;
                    });
            Class<?> nearCallback = loader.loadClass("org.ode4j.ode.DGeom$DNearCallback");
            Method collide = space.getMethod("collide", Object.class, nearCallback);
            Method collide2 = helper.getMethod("spaceCollide2", geom, geom, Object.class, nearCallback);
            Method enable = geom.getMethod("enable");
            Method disable = geom.getMethod("disable");
            for (step = 0; step < STEPS; step++) {
                double x = 0;
                for (int i = 0; i < MOVING; i++) {
                    // a chain along x that drifts and jitters
                    x = i % 10 == 1 ? x : i * 0.015 + 0.01 * step + 0.004 * r.nextDouble();
                    setPosition.invoke(parts[i], x, 0.4 * r.nextDouble() - 0.2, 0.05 * r.nextDouble());
                }
                (step % 4 == 3 ? disable : enable).invoke(parts[7 * step % MOVING]);
                collide.invoke(moving, null, callback);
                collide2.invoke(null, moving, fixed, null, callback);
                collide2.invoke(null, fixed, moving, null, callback);
                // a single geom against a space: the fixed space's lookup (its walls are long), and the plane's fallback
                collide2.invoke(null, parts[(5 * step + 3) % MOVING], fixed, null, callback);
                collide2.invoke(null, plane, fixed, null, callback);
            }
            return pairs;
        }
    }
}
