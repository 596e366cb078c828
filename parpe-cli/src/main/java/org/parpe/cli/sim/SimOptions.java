package org.parpe.cli.sim;

import org.parpe.cli.RunSetup;
import org.parpe.cli.RunTarget;

/** The simulator options of {@code parpe run} ({@code --sim}, {@code --metrics}, {@code --plot}, {@code --realtime}). */
public class SimOptions implements RunTarget {
    @Override
    public void configure(RunSetup setup) {
        // Filled in by the simulator work (issue 3).
    }
}
