package org.parpe.cli.options;

import java.io.IOException;
import java.nio.file.Path;
import org.parpe.cli.text.CliMsg;
import org.parpe.core.xml.InputFiles;

/** Checks of the input files named on the command line, made before anything is loaded. */
public final class Inputs {
    private Inputs() {
    }

    /**
     * Refuses a file that cannot be read as an input (missing, a directory, a device or FIFO, or
     * larger than {@link InputFiles#MAX_BYTES}): an unreadable file on the command line is a usage
     * error (PARSL.md §13 rule 15).
     */
    public static void check(Path file) throws UsageException {
        try {
            InputFiles.check(file);
        } catch (IOException e) {
            throw new UsageException(CliMsg.CANNOT_READ.text(file, e.getMessage()));
        }
    }

    /**
     * Refuses a file that cannot be read as an input, whatever its size: for files PARPE wrote
     * itself and reads as a stream (a sweep's shards).
     */
    public static void checkKind(Path file) throws UsageException {
        try {
            InputFiles.checkKind(file);
        } catch (IOException e) {
            throw new UsageException(CliMsg.CANNOT_READ.text(file, e.getMessage()));
        }
    }

    /** The assignments of stimulus file {@code stimulus} for {@code program}; none without a file. */
    public static java.util.List<org.parpe.core.run.Stimulus> stimuli(Path stimulus, org.parpe.core.model.Program program)
            throws UsageException {
        if (stimulus == null) {
            return java.util.List.of();
        }
        String text;
        try {
            text = InputFiles.readText(stimulus);
        } catch (IOException e) {
            throw new UsageException(CliMsg.CANNOT_READ_STIMULUS.text(stimulus, e.getMessage()));
        }
        try {
            return org.parpe.core.run.StimulusParser.parse(stimulus.toString(), text, program);
        } catch (org.parpe.core.run.StimulusParser.StimulusException e) {
            throw new UsageException(e.getMessage());
        }
    }
}
