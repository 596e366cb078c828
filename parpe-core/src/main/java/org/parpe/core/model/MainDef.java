package org.parpe.core.model;

import java.util.List;
import org.parpe.core.diag.SourcePos;

/**
 * The {@code <main>} sequence.
 *
 * @param cycles     how many times the sequence runs; {@link #FOREVER} for {@code forever}
 * @param cyclesText the {@code cycles} attribute as written, or {@code null}
 * @param entries    behavior invocations in order
 * @param pos        the element
 */
public record MainDef(long cycles, String cyclesText, List<MainEntry> entries, SourcePos pos) {

    /** The cycle count of {@code cycles="forever"}. */
    public static final long FOREVER = -1;

    public MainDef {
        entries = List.copyOf(entries);
    }
}
