package org.parpe.core.run;

/**
 * Extra columns a plant adds to a CSV trace (measured angles, centre of mass). Values are
 * read right after the commanded angles of the same tick were accepted by every sink.
 */
public interface TraceColumns {

    /** Column names, fixed for the run. */
    String[] names();

    /** Writes the current values, one per name, into {@code out}. */
    void values(double[] out);
}
