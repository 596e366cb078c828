package org.parpe.cli.options;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import java.util.Collection;
import org.parpe.core.io.Content;
import org.parpe.core.io.Output;
import org.parpe.core.io.OutputException;
import org.parpe.core.io.OutputPlan;

/**
 * A file the command line writes (trace, metrics, plot, CSV, recording, profile, emulator log),
 * claimed from the command's {@link OutputPlan} before any work starts and written through it
 * (see {@code org.parpe.core.io} and the table in docs/cli.md). This class only turns the
 * policy's refusals and failures into {@link UsageException}s (exit code 2).
 */
public final class OutputFile {
    private final Output output;

    private OutputFile(Output output) {
        this.output = output;
    }

    /** A plan whose inputs are {@code inputs}. */
    public static OutputPlan plan(Collection<Path> inputs) {
        return new OutputPlan().inputs(inputs);
    }

    /** Claims {@code path}, given to {@code option}, from {@code plan}: an existing regular file is replaced. */
    public static OutputFile of(OutputPlan plan, String option, String path) throws UsageException {
        return of(plan, option, path, OutputPlan.Existing.REPLACE, null);
    }

    /** Claims {@code path}; with {@link OutputPlan.Existing#KEEP} an existing file is refused with {@code hint}. */
    public static OutputFile of(OutputPlan plan, String option, String path, OutputPlan.Existing existing, String hint)
            throws UsageException {
        try {
            return new OutputFile(plan.output(option, path, existing, hint));
        } catch (OutputException e) {
            throw new UsageException(e.getMessage());
        }
    }

    /** {@link #of} unless {@code path} is {@code null} or {@code "-"} (standard output). */
    public static OutputFile ofOptional(OutputPlan plan, String option, String path) throws UsageException {
        return path == null || path.equals("-") ? null : of(plan, option, path);
    }

    /** Writes the whole file. */
    public void write(Content content) throws UsageException {
        try {
            output.write(content);
        } catch (OutputException e) {
            throw new UsageException(e.getMessage());
        }
    }

    /** Writes the whole file as UTF-8 text. */
    public void write(String text) throws UsageException {
        write(Content.text(text));
    }

    /**
     * A writer for streaming content: {@code close()} puts the file in place; {@link Output.Stream#abort()}
     * (in a {@code finally}) discards it after a failure. Failures name the option and the file.
     */
    public Output.Stream openWriter() throws UsageException {
        try {
            return output.open();
        } catch (OutputException e) {
            throw new UsageException(e.getMessage());
        }
    }

    /** The message of a failure {@code e} while writing this file. */
    public String failed(IOException e) {
        return output.failed(e).getMessage();
    }

    /** Discards {@code w} if it was not closed (a writer of {@link #openWriter}; other writers are left alone). */
    public static void abort(Writer w) {
        if (w instanceof Output.Stream s) {
            s.abort();
        }
    }

    /** The path as the user gave it. */
    @Override
    public String toString() {
        return output.toString();
    }
}
