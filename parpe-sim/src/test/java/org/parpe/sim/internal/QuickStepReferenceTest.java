package org.parpe.sim.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.lang.reflect.Method;
import java.net.URLClassLoader;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The patched QuickStep ({@code org.ode4j.ode.internal.DxQuickStep} of this module and the
 * classes it calls: kept work arrays, the LCP sweep's rows in one loop with the body forces kept
 * in locals from row to row, the 3x3 products of {@code Multiply333}) moves the bodies bit for
 * bit as ODE4j 0.5.3's own classes do, which are the reference. The same world is built twice,
 * in this module's classes and in ODE4j's jar loaded on its own, and stepped: a chain of boxes
 * joined by hinges with motors and limits (two-body rows, neighbours sharing a body), its first
 * box hinged to the world and every box touching the ground by a contact with friction (one-body
 * rows, friction rows bounded by their normal row's force), boxes two apart touching each other.
 */
class QuickStepReferenceTest {
    private static final int BOXES = 10;
    private static final int STEPS = 150;

    @Test
    void bodiesMoveAsInOdes() throws Exception {
        ClassLoader ours = QuickStepReferenceTest.class.getClassLoader();
        try (URLClassLoader odes = OdesOwnJar.open("org.ode4j.ode.internal.DxQuickStep")) {
            List<String> expected = new Chain(odes).run();
            List<String> actual = new Chain(ours).run();
            assertEquals(BOXES * STEPS, expected.size());
            assertNotEquals(expected.get(0), expected.get(expected.size() - BOXES), "the chain does not move");
            for (int i = 0; i < expected.size(); i++) {
                assertEquals(expected.get(i), actual.get(i), "step " + i / BOXES + ", box " + i % BOXES);
            }
        }
    }

    /** The chain, driven by reflection in the classes of one loader; records each box's state per step. */
    private static final class Chain {
        private final ClassLoader loader;

        Chain(ClassLoader loader) {
            this.loader = loader;
        }

        List<String> run() throws Exception {
            Class<?> helper = loader.loadClass("org.ode4j.ode.OdeHelper");
            ofClass(helper, "initODE2", 0);
            ofClass(loader.loadClass("org.ode4j.ode.internal.Misc"), "dRandSetSeed", 36L);
            Object world = ofClass(helper, "createWorld");
            call(world, "setGravity", 0.0, 0.0, -9.81);
            Object group = ofClass(helper, "createJointGroup");
            Object[] boxes = new Object[BOXES];
            for (int i = 0; i < BOXES; i++) {
                boxes[i] = ofClass(helper, "createBody", world);
                Object mass = ofClass(helper, "createMass");
                call(mass, "setBox", 1000.0, 0.05, 0.04, 0.04);
                call(boxes[i], "setMass", mass);
                call(boxes[i], "setPosition", 0.06 * i, 0.0, 0.02);
            }
            Object[] hinges = new Object[BOXES];
            for (int i = 0; i < BOXES; i++) {
                hinges[i] = ofClass(helper, "createHingeJoint", world);
                call(hinges[i], "attach", boxes[i], i == 0 ? null : boxes[i - 1]);
                call(hinges[i], "setAnchor", 0.06 * i - 0.03, 0.0, 0.02);
                call(hinges[i], "setAxis", 0.0, i % 2 == 0 ? 1.0 : 0.0, i % 2 == 0 ? 0.0 : 1.0);
                call(hinges[i], "setParamLoStop", -0.5);
                call(hinges[i], "setParamHiStop", 0.5);
                call(hinges[i], "setParamFMax", 0.5);
            }
            Class<?> contactClass = loader.loadClass("org.ode4j.ode.DContact");
            int mode = constant("dContactApprox1") | constant("dContactSoftERP") | constant("dContactSoftCFM");
            List<String> states = new ArrayList<>();
            for (int step = 0; step < STEPS; step++) {
                call(group, "empty");
                for (int i = 0; i < BOXES; i++) {
                    call(hinges[i], "setParamVel", 2 * Math.sin(0.2 * step + i));
                    Object at = call(boxes[i], "getPosition");
                    double x = (double) call(at, "get0");
                    double z = (double) call(at, "get2");
                    contact(world, group, contactClass, mode, boxes[i], null, x, 0.03 - z);
                    if (i >= 2) {
                        contact(world, group, contactClass, mode, boxes[i], boxes[i - 2], x - 0.06, 0.001);
                    }
                }
                call(world, "quickStep", 0.005);
                for (Object b : boxes) {
                    states.add(bits(call(b, "getPosition")) + "; " + bits(call(b, "getQuaternion")));
                }
            }
            return states;
        }

        private void contact(Object world, Object group, Class<?> contactClass, int mode, Object b1, Object b2,
                double x, double depth) throws Exception {
            Object c = contactClass.getConstructor().newInstance();
            Object surface = contactClass.getField("surface").get(c);
            surface.getClass().getField("mode").setInt(surface, mode);
            surface.getClass().getField("mu").setDouble(surface, 0.8);
            surface.getClass().getField("soft_erp").setDouble(surface, 0.2);
            surface.getClass().getField("soft_cfm").setDouble(surface, 1e-4);
            Object geom = contactClass.getField("geom").get(c);
            call(geom.getClass().getField("pos").get(geom), "set", x, 0.0, 0.0);
            call(geom.getClass().getField("normal").get(geom), "set", 0.0, 0.0, 1.0);
            geom.getClass().getField("depth").setDouble(geom, depth);
            Object joint = ofClass(loader.loadClass("org.ode4j.ode.OdeHelper"), "createContactJoint", world, group, c);
            call(joint, "attach", b1, b2);
        }

        private int constant(String name) throws Exception {
            return loader.loadClass("org.ode4j.ode.OdeConstants").getField(name).getInt(null);
        }

        private static String bits(Object vector) throws Exception {
            StringBuilder s = new StringBuilder();
            for (Method m : vector.getClass().getMethods()) {
                if (m.getName().equals("get") && m.getParameterCount() == 1 && m.getParameterTypes()[0] == int.class) {
                    int n = vector.getClass().getSimpleName().contains("Quaternion") ? 4 : 3;
                    for (int i = 0; i < n; i++) {
                        s.append(i == 0 ? "" : ",").append(Long.toHexString(Double.doubleToRawLongBits((double) m.invoke(vector, i))));
                    }
                    return s.toString();
                }
            }
            throw new AssertionError("no get(int) on " + vector.getClass());
        }

        private static Object call(Object target, String name, Object... args) throws Exception {
            return invoke(target.getClass(), target, name, args);
        }

        private static Object ofClass(Class<?> type, String name, Object... args) throws Exception {
            return invoke(type, null, name, args);
        }

        /** The public method {@code name} of {@code type} whose parameters take {@code args}. */
        private static Object invoke(Class<?> type, Object target, String name, Object... args) throws Exception {
            for (Method m : type.getMethods()) {
                if (m.getName().equals(name) && m.getParameterCount() == args.length && takes(m.getParameterTypes(), args)) {
                    m.setAccessible(true);
                    return m.invoke(target, args);
                }
            }
            throw new NoSuchMethodException(type.getName() + "." + name);
        }

        private static boolean takes(Class<?>[] types, Object[] args) {
            for (int i = 0; i < types.length; i++) {
                Class<?> t = types[i];
                Object a = args[i];
                boolean ok = a == null ? !t.isPrimitive()
                        : t == double.class ? a instanceof Double
                        : t == int.class ? a instanceof Integer
                        : t == long.class ? a instanceof Long
                        : t.isInstance(a);
                if (!ok) {
                    return false;
                }
            }
            return true;
        }
    }
}
