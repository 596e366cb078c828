package org.parpe.serial.g1;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.constraints.Size;

class DecoderFuzzProperties {

    @Property(tries = 500)
    void garbageNeverCrashesTheDecoder(@ForAll @Size(max = 3000) byte[] garbage, @ForAll @IntRange(min = 1, max = 64) int chunk) {
        int[] frames = {0};
        FrameDecoder d = new FrameDecoder((a, c, b, o, l) -> {
            assertTrue(o >= 0 && l >= 0 && o + l <= b.length);
            frames[0]++;
        });
        for (int i = 0; i < garbage.length; i += chunk) {
            d.feed(garbage, i, Math.min(chunk, garbage.length - i));
        }
        d.idle();
        assertEquals(0, d.pending());
        assertEquals(frames[0], d.frames());
    }

    @Property(tries = 300)
    void aValidFrameAfterGarbageIsFoundOnceTheLineGoesQuiet(@ForAll @Size(max = 600) byte[] garbage,
                                                            @ForAll @IntRange(min = 0, max = 200) int module,
                                                            @ForAll short angle) {
        FrameEncoder e = new FrameEncoder();
        short[] wire = {angle};
        int n = e.setpoints(77, module, wire, 1);
        byte[] frame = Arrays.copyOf(e.buffer(), n);
        int[] seen = {0};
        FrameDecoder d = new FrameDecoder((a, c, b, o, l) -> {
            if (Command.SETPOINTS.is(c) && FrameHandler.u16(b, o) == 77 && (b[o + 2] & 0xFF) == module
                    && FrameHandler.i16(b, o + 3) == angle) {
                seen[0]++;
            }
        });
        d.feed(garbage, 0, garbage.length);
        // A corrupted length in the garbage may swallow the frame until a silence.
        d.idle();
        d.feed(frame, 0, n);
        assertEquals(1, seen[0]);
    }
}
