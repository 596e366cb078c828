package org.parpe.cli;

/**
 * Something {@code parpe run} can drive besides the trace: the simulator ({@code --sim}) or
 * the serial bus ({@code --port}). Each is a picocli mixin of {@link RunCommand} that, when its
 * options are given, adds its sinks and sensor source to the run.
 */
public interface RunTarget {

    /** Adds this target to the run if its options were given; does nothing otherwise. */
    void configure(RunSetup setup) throws Exception;
}
