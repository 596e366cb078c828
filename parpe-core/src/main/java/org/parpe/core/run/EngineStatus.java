package org.parpe.core.run;

/**
 * What the engine is doing, for status bars and highlighting.
 *
 * @param tick        the last tick run
 * @param time        its time, seconds
 * @param entry       the behavior of the current {@code <main>} entry, or empty
 * @param entryIndex  the entry's position in {@code <main>}, or −1
 * @param mainCycle   the current repetition of {@code <main>} (0-based)
 * @param driven      IDs of the modules driven at the last tick
 * @param ended       whether {@code <main>} has ended
 */
public record EngineStatus(long tick, double time, String entry, int entryIndex, long mainCycle,
                           int[] driven, boolean ended) {
}
