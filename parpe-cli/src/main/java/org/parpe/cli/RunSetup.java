package org.parpe.cli;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.parpe.core.model.Program;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.SensorSource;
import org.parpe.core.run.TraceColumns;

/**
 * What the run targets of one {@code parpe run} contribute: sinks, sensor sources (the one with
 * the highest priority is read; hardware outranks the simulator), trace columns, work to do at
 * the end, and pacing.
 */
public final class RunSetup {
    private final Program program;
    private final RunOptions options;
    private final double duration;
    private final PrintStream err;
    private final List<JointSink> sinks = new ArrayList<>();
    private final List<TraceColumns> columns = new ArrayList<>();
    private final List<Consumer<RunOutcome>> finishers = new ArrayList<>();
    private final List<AutoCloseable> closeables = new ArrayList<>();
    private final java.util.Map<String, SensorSource> offered = new java.util.LinkedHashMap<>();
    private SensorSource source;
    private int sourcePriority = Integer.MIN_VALUE;
    private boolean realtime;

    /** A setup for running {@code program} for at most {@code duration} seconds. */
    public RunSetup(Program program, RunOptions options, double duration, PrintStream err) {
        this.program = program;
        this.options = options;
        this.duration = duration;
        this.err = err;
    }

    public Program program() {
        return program;
    }

    public RunOptions options() {
        return options;
    }

    /** The requested duration, seconds ({@code Double.POSITIVE_INFINITY} when not given). */
    public double duration() {
        return duration;
    }

    /** Where warnings and reports go (standard error). */
    public PrintStream err() {
        return err;
    }

    /** Adds a sink fed every tick. */
    public void addSink(JointSink sink) {
        sinks.add(sink);
    }

    /**
     * Offers a sensor source under a name ({@code "sim"}, {@code "hardware"}); the highest
     * priority offered is the one the scheduler reads (hardware 10, simulator 5). Every
     * offered source stays reachable through {@link #sensorSources()}, e.g. to compare the
     * simulator with the hardware.
     */
    public void offerSensorSource(String name, SensorSource s, int priority) {
        offered.put(name, s);
        if (priority > sourcePriority) {
            source = s;
            sourcePriority = priority;
        }
    }

    /** Adds columns to the trace. */
    public void addTraceColumns(TraceColumns c) {
        columns.add(c);
    }

    /** Runs {@code f} after the run, before resources are closed. */
    public void onFinish(Consumer<RunOutcome> f) {
        finishers.add(f);
    }

    /** Closes {@code c} when the run is over (reverse order of registration). */
    public void closeAtEnd(AutoCloseable c) {
        closeables.add(c);
    }

    /** Asks for the run to be paced to the wall clock. */
    public void setRealtime(boolean realtime) {
        this.realtime = this.realtime || realtime;
    }

    public List<JointSink> sinks() {
        return sinks;
    }

    public List<TraceColumns> columns() {
        return columns;
    }

    public SensorSource sensorSource() {
        return source;
    }

    /** Every offered sensor source by name, in the order offered. */
    public java.util.Map<String, SensorSource> sensorSources() {
        return java.util.Collections.unmodifiableMap(offered);
    }

    public boolean realtime() {
        return realtime;
    }

    List<Consumer<RunOutcome>> finishers() {
        return finishers;
    }

    List<AutoCloseable> closeables() {
        return closeables;
    }
}
