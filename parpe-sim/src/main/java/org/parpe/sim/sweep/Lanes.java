package org.parpe.sim.sweep;

import java.io.File;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.Set;
import org.parpe.sim.world.WorldScore;

/**
 * Private copies of the simulator's classes, one per worker thread. ODE4j keeps the random
 * generator with which its QuickStep solver shuffles constraints in one static field
 * ({@code org.ode4j.ode.internal.Misc.seed}); two simulations on two threads of one class loader
 * would draw from each other's sequence, and their results would depend on timing. (A world of
 * the simulator now draws from its own, {@code WorldRandom}; the lanes keep the rest of ODE4j's
 * static state apart as well.) A class loader of its own gives
 * each worker its own ODE4j and so its own generator. Only ODE4j and the simulator (which links
 * to it) are private; the script loader, the read script, the scheduler and the XML and
 * expression libraries come from the application's loader, one copy for every worker, which the
 * JIT compiles once. The worker speaks to its copy through a typed bridge: {@link PointRunner},
 * {@link RunSetup}, {@link Point}, {@link SweepRow} (with its {@link WorldScore}) and
 * {@link Cancellation} are the application's classes on both sides ({@link #SHARED}). Loaders are kept for the next sweep
 * (their classes stay compiled) and lent to one thread at a time.
 */
final class Lanes {
    private static final ConcurrentLinkedQueue<ClassLoader> FREE = new ConcurrentLinkedQueue<>();
    /** The classes of the bridge: the application's own on both sides of a lane. */
    static final Set<String> SHARED = Set.of(PointRunner.class.getName(), RunSetup.class.getName(),
            Point.class.getName(), SweepRow.class.getName(), WorldScore.class.getName(), Cancellation.class.getName());

    private Lanes() {
    }

    /** A loader no other thread is using. */
    static ClassLoader acquire() {
        ClassLoader l = FREE.poll();
        return l != null ? l : create();
    }

    /** Gives {@code loader} back for another thread. */
    static void release(ClassLoader loader) {
        FREE.offer(loader);
    }

    /**
     * The lane's own {@link Evaluator} of {@code setup}, or {@code null} when {@code loader} has
     * no copy of the simulator (no class path to copy it from: a custom runtime image).
     */
    static PointRunner runnerIn(ClassLoader loader, RunSetup setup) {
        Method of;
        try {
            of = Class.forName(Evaluator.class.getName(), true, loader).getMethod("of", RunSetup.class);
        } catch (ClassNotFoundException | NoSuchMethodException e) {
            return null;
        }
        try {
            return (PointRunner) of.invoke(null, setup);
        } catch (InvocationTargetException e) {
            throw new IllegalStateException("the worker's copy of the script does not load: "
                    + e.getCause().getMessage(), e.getCause());
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("cannot make the simulator in a worker's class loader: " + e, e);
        }
    }

    private static ClassLoader create() {
        List<URL> urls = new ArrayList<>();
        for (String entry : System.getProperty("java.class.path", "").split(File.pathSeparator)) {
            if (!entry.isEmpty()) {
                try {
                    urls.add(new File(entry).toURI().toURL());
                } catch (MalformedURLException e) {
                    throw new IllegalStateException("class path entry '" + entry + "': " + e.getMessage(), e);
                }
            }
        }
        return new LaneLoader(urls.toArray(new URL[0]), Lanes.class.getClassLoader());
    }

    /** Whether class {@code name} has a copy of its own in each lane. */
    static boolean privateToLane(String name) {
        return (name.startsWith("org.ode4j.") || name.startsWith("org.parpe.sim.")) && !SHARED.contains(name);
    }

    /** Loads the physics library and the simulator itself, everything else from its parent. */
    private static final class LaneLoader extends URLClassLoader {
        static {
            ClassLoader.registerAsParallelCapable();
        }

        LaneLoader(URL[] urls, ClassLoader parent) {
            super("parpe-sweep-lane", urls, parent);
        }

        @Override
        protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
            if (!privateToLane(name)) {
                return super.loadClass(name, resolve);
            }
            synchronized (getClassLoadingLock(name)) {
                Class<?> c = findLoadedClass(name);
                if (c == null) {
                    c = findClass(name);
                }
                if (resolve) {
                    resolveClass(c);
                }
                return c;
            }
        }
    }
}
