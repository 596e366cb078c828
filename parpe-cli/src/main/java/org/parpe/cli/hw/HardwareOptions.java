package org.parpe.cli.hw;

import org.parpe.cli.RunSetup;
import org.parpe.cli.RunTarget;

/** The serial-bus options of {@code parpe run} ({@code --port}, {@code --baud}). */
public class HardwareOptions implements RunTarget {
    @Override
    public void configure(RunSetup setup) {
        // Filled in by the serial-bus work (issue 4).
    }
}
