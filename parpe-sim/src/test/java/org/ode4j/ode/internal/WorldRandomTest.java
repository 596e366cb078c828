package org.ode4j.ode.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * A world's own generator of QuickStep's constraint shuffle ({@link WorldRandom}) draws the numbers
 * ODE4j's global one ({@code Misc.dRand}, {@code Misc.dRandInt} in the ODE4j 0.5.3 jar, which PARPE
 * does not patch) draws from the same seed: the shuffles, and so every trace, stay as they were.
 */
class WorldRandomTest {
    @Test
    void drawsWhatOdesGlobalGeneratorDrawsFromTheSameSeed() {
        long saved = Misc.dRandGetSeed();
        try {
            SplittableRandom pick = new SplittableRandom(36);
            WorldRandom own = new WorldRandom();
            // The step counts PhysicsWorld seeds with, then seeds of every size.
            for (int s = 0; s < 400; s++) {
                long seed = s < 200 ? s : pick.nextLong(1L << 32);
                own.setSeed(seed);
                Misc.dRandSetSeed(seed);
                for (int draw = 0; draw < 600; draw++) {
                    // Every branch of dRandInt: n up to 2, 4, 16, 256, 65536 and beyond.
                    long n = draw < 500 ? draw + 1 : pick.nextLong(1, 1L << 32);
                    assertEquals(Misc.dRandInt(n), own.nextInt(n), "seed " + seed + ", draw " + draw + ", n " + n);
                }
                assertEquals(Misc.dRand(), own.next(), "seed " + seed + " after its draws");
            }
        } finally {
            Misc.dRandSetSeed(saved);
        }
    }
}
