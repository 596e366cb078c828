package org.parpe.core.run;

/**
 * Something a run drives besides its observers: the simulator or a serial bus. The simulator
 * and serial modules implement it; the command line and the IDE pick targets from the user's
 * choices and attach them to the same {@link Run.Builder}, so a run is assembled one way.
 */
@FunctionalInterface
public interface RunTarget {

    /**
     * Adds this target's plant, sensor source, trace columns and resources to {@code run}.
     *
     * @throws TargetException when the target cannot be used (a robot that does not build, a
     *                         port that will not open); its diagnostics say why
     */
    void attach(Run.Builder run) throws TargetException;
}
