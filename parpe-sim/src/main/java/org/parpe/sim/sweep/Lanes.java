package org.parpe.sim.sweep;

import java.io.File;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.Function;

/**
 * Private copies of the simulator's classes, one per worker thread. ODE4j keeps the random
 * generator with which its solver shuffles constraints in one static field, and the simulator
 * reseeds it before every step to stay reproducible; two simulations on two threads of one
 * class loader would draw from each other's sequence, and their results would depend on timing.
 * A class loader of its own gives each worker its own ODE4j and so its own generator. Only ODE4j
 * and the simulator (which links to it) are private; the script loader, scheduler and XML and
 * expression libraries come from the application's loader, so there is one copy of them for
 * every worker, which the JIT compiles once and which every worker's runs warm up together
 * (each run loads its script afresh, code that runs once per run and would otherwise reach its
 * compiled form slowly, once per worker, while the compiler threads take CPU time from the
 * simulations). Loaders are kept for the next sweep (their classes stay compiled) and lent to
 * one thread at a time.
 */
final class Lanes {
    private static final ConcurrentLinkedQueue<ClassLoader> FREE = new ConcurrentLinkedQueue<>();

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

    /** A new evaluator object in {@code loader}. */
    @SuppressWarnings("unchecked")
    static Function<Object[], Object[]> evaluatorIn(ClassLoader loader) {
        try {
            Class<?> c = Class.forName(IsolatedEvaluator.class.getName(), true, loader);
            var ctor = c.getDeclaredConstructor();
            ctor.setAccessible(true);
            return (Function<Object[], Object[]>) ctor.newInstance();
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot load the simulator in a worker's class loader: " + e, e);
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
        return name.startsWith("org.ode4j.") || name.startsWith("org.parpe.sim.");
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
