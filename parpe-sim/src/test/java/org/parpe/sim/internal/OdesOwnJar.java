package org.parpe.sim.internal;

import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.net.URL;
import java.net.URLClassLoader;

/**
 * ODE4j's own classes, loaded from its jar apart from this module's patched copies: the reference
 * the patched classes are held to, bit for bit ({@link QuickStepReferenceTest},
 * {@link SapSpaceOrderTest}).
 */
final class OdesOwnJar {
    private OdesOwnJar() {
    }

    /**
     * A loader of ODE4j's jar (and the logger it needs) alone; fails if its {@code patchedClass}
     * is the same as this module's, which would make the comparison prove nothing.
     */
    static URLClassLoader open(String patchedClass) throws Exception {
        URLClassLoader odes = new URLClassLoader(new URL[] {jarOf("org.ode4j.ode.internal.DxSpace"), jarOf("org.slf4j.Logger")},
                ClassLoader.getPlatformClassLoader());
        assertNotEquals(OdesOwnJar.class.getClassLoader().loadClass(patchedClass).getProtectionDomain().getCodeSource(),
                odes.loadClass(patchedClass).getProtectionDomain().getCodeSource(),
                "the reference must be ODE4j's own class, not the patched one");
        return odes;
    }

    private static URL jarOf(String className) throws ClassNotFoundException {
        return Class.forName(className).getProtectionDomain().getCodeSource().getLocation();
    }
}
