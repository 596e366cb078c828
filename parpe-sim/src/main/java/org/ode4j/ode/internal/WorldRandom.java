package org.ode4j.ode.internal;

/**
 * PARPE's own class (not a copy of ODE4j's): one world's random generator for QuickStep's
 * constraint shuffle, a plain {@code long} instead of ODE4j's global one ({@code Misc.seed}, an
 * {@code AtomicLong} shared by every world of the class loader, advanced by a compare-and-set on
 * every draw). The same linear congruential sequence as ODE's {@code dRand} and the same
 * folding into {@code 0..n-1} as ODE4j 0.5.3's {@code dRandInt}, so a world seeded as the global
 * generator was draws exactly the same numbers. One world's, used on one thread (issue 36;
 * docs/decisions.md, "A faster simulator tick, same results").
 */
public final class WorldRandom {
    private long seed;

    /** Starts the sequence again from {@code s}, as ODE's {@code dRandSetSeed}. */
    public void setSeed(long s) {
        seed = s;
    }

    /** The next 32-bit number of ODE's {@code dRand}: {@code seed * 1664525 + 1013904223 mod 2^32}. */
    long next() {
        seed = (1664525L * seed + 1013904223L) & 0xffffffffL;
        return seed;
    }

    /**
     * A number in {@code 0..n-1}, {@code n} at most 2^32, as ODE4j 0.5.3's {@code dRandInt}: the
     * 32 bits folded by exclusive or into as many as {@code n} needs, then scaled to {@code n}.
     */
    int nextInt(long n) {
        long r = next();
        long result;
        if (n <= 16) {
            r ^= r >> 16;
            r ^= r >> 8;
            r ^= r >> 4;
            if (n <= 2) {
                r ^= r >> 2;
                r ^= r >> 1;
                result = r & (n >> 1);
            } else if (n <= 4) {
                r ^= r >> 2;
                result = ((r & 3) * n) >> 2;
            } else {
                result = ((r & 15) * n) >> 4;
            }
        } else if (n <= 256) {
            r ^= r >> 16;
            r ^= r >> 8;
            result = ((r & 255) * n) >> 8;
        } else if (n <= 65536) {
            r ^= r >> 16;
            result = ((r & 65535) * n) >> 16;
        } else {
            result = (int) ((r * n) >> 32);
        }
        return (int) result;
    }
}
