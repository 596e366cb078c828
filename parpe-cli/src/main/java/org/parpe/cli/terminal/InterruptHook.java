package org.parpe.cli.terminal;

import org.parpe.cli.text.CliMsg;
import java.lang.reflect.InvocationHandler;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * Ctrl-C or SIGTERM (a cluster's scheduler cancelling a job or ending it at its time limit)
 * during a command that must end properly (a run: emergency stop on the bus, trace flushed; a
 * sweep: the finished rows written): asks the work to stop and holds the JVM's shutdown for a
 * few seconds until {@link #close()} says the work has ended. {@link #cause()} tells the two
 * signals apart, so that a batch job's log does not speak of a Ctrl-C nobody pressed.
 */
public final class InterruptHook implements AutoCloseable {
    /** The last of SIGINT and SIGTERM received ("INT", "TERM"), or null. */
    private static volatile String lastSignal;

    static {
        for (String name : new String[] {"INT", "TERM"}) {
            watch(name);
        }
    }

    private final CountDownLatch done = new CountDownLatch(1);
    private final Thread hook;
    private volatile boolean interrupted;

    /**
     * Installs the hook: on Ctrl-C, {@code stop} runs (it must only set a flag), then shutdown
     * waits up to {@code holdSeconds} for {@link #close()}.
     */
    public InterruptHook(Runnable stop, int holdSeconds) {
        hook = new Thread(() -> {
            interrupted = true;
            stop.run();
            try {
                done.await(holdSeconds, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "parpe-interrupt");
        Runtime.getRuntime().addShutdownHook(hook);
    }

    /** Whether Ctrl-C was pressed or the process was told to stop. */
    public boolean interrupted() {
        return interrupted;
    }

    /** Why the work was stopped, for a message: "interrupted (Ctrl-C)", "stopped by SIGTERM (...)". */
    public String cause() {
        String signal = lastSignal;
        if ("INT".equals(signal)) {
            return CliMsg.INTERRUPTED_CTRL_C.text();
        }
        if ("TERM".equals(signal)) {
            return CliMsg.STOPPED_BY_SIGTERM.text();
        }
        return CliMsg.STOPPED_TOLD.text();
    }

    /**
     * Notes the arrival of signal {@code name}, then hands it to the JVM's own handler, which
     * starts the shutdown; a signal the process ignores (nohup) stays ignored. The JDK's
     * {@code sun.misc.Signal} (module jdk.unsupported) is reached by reflection: it is the only
     * way to tell SIGINT from SIGTERM, and javac warns of it at every direct use.
     */
    private static void watch(String name) {
        try {
            Class<?> signalType = Class.forName("sun.misc.Signal");
            Class<?> handlerType = Class.forName("sun.misc.SignalHandler");
            Method handle = signalType.getMethod("handle", signalType, handlerType);
            Method handleBy = handlerType.getMethod("handle", signalType);
            Object ignore = handlerType.getField("SIG_IGN").get(null);
            Object fallback = handlerType.getField("SIG_DFL").get(null);
            Object signal = signalType.getConstructor(String.class).newInstance(name);
            int number = (Integer) signalType.getMethod("getNumber").invoke(signal);
            Object[] before = new Object[1];
            InvocationHandler watcher = (proxy, method, args) -> switch (method.getName()) {
                case "handle" -> {
                    lastSignal = name;
                    if (before[0] == null || before[0] == fallback) {
                        System.exit(128 + number);
                    } else {
                        handleBy.invoke(before[0], args[0]);
                    }
                    yield null;
                }
                case "equals" -> proxy == args[0];
                case "hashCode" -> System.identityHashCode(proxy);
                default -> "parpe's SIG" + name + " watcher";
            };
            before[0] = handle.invoke(null, signal,
                    Proxy.newProxyInstance(InterruptHook.class.getClassLoader(), new Class<?>[] {handlerType}, watcher));
            if (before[0] == ignore) {
                handle.invoke(null, signal, ignore);
            }
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            // no jdk.unsupported, or the JVM keeps the signal for itself (-Xrs): no cause then
        }
    }

    /** The work has ended: shutdown may go on, and without Ctrl-C the hook is removed. */
    @Override
    public void close() {
        done.countDown();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // the JVM is exiting because of Ctrl-C: the hook is running and waits for us
        }
    }
}
