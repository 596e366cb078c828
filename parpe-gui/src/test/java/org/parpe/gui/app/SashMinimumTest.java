package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * A pane squeezed below its minimum grows back in one step, and the weights that step sets need
 * no further step. A helper saw the IDE's UI thread busy at 58 % in {@code SashMinimum.enforce} →
 * {@code SashForm.setWeights} after resizing the window: the weights it set were corrected again
 * on the next resize event, for ever.
 */
class SashMinimumTest {
    @Test
    void theWeightsSetOnceNeedNoSecondCorrection() {
        Random random = new Random(24);
        for (int run = 0; run < 200_000; run++) {
            int n = 2 + random.nextInt(3);
            int[] minimum = new int[n];
            int[] w = new int[n];
            for (int i = 0; i < n; i++) {
                minimum[i] = random.nextInt(400);
                w[i] = 1 + random.nextInt(run % 2 == 0 ? 1000 : 10);
            }
            int need = Arrays.stream(minimum).sum();
            int total = need + random.nextInt(run % 3 == 0 ? 8 : 2000);
            int[] once = SashMinimum.grown(w, total, minimum);
            if (once == null) {
                continue;
            }
            String what = "weights " + Arrays.toString(w) + " over " + total + " px, minimum " + Arrays.toString(minimum)
                    + " -> " + Arrays.toString(once);
            assertNull(SashMinimum.grown(once, total, minimum), what + " is corrected again: " + Arrays.toString(SashMinimum.grown(once, total, minimum)));
            long sum = Arrays.stream(once).asLongStream().sum();
            for (int i = 0; i < n; i++) {
                assertTrue(total * once[i] / sum >= minimum[i], what + ": pane " + i + " is still below its minimum");
            }
        }
    }
}
