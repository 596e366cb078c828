package org.parpe.cli.hw;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import org.parpe.serial.g1.emu.BusEmulator;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.PtyPair;

/**
 * A socat pty pair with an emulator on end b, recording what the modules receive; the command
 * under test opens end a. Closing kills socat.
 */
final class EmulatedBus implements AutoCloseable {
    final PtyPair pty;
    final BusEmulator emulator;
    /** Setpoints received, by sequence number (= tick). */
    final Map<Integer, double[]> received = new ConcurrentHashMap<>();
    /** [module, nanoTime] of each safe stop. */
    final List<long[]> stops = new CopyOnWriteArrayList<>();
    volatile long unplugNanos;

    EmulatedBus(Path dir, EmulatorOptions options) throws IOException {
        pty = PtyPair.start(dir.resolve("parpe-a"), dir.resolve("parpe-b"));
        try {
            emulator = BusEmulator.start(LinkOpener.serial(pty.b().toString(), 115200), options, new EmulatorListener() {
                @Override
                public void onSetpoints(int seq, double[] angles) {
                    received.put(seq, angles.clone());
                }

                @Override
                public void onSafeStop(int id, long nanoTime, String why) {
                    stops.add(new long[] {id, nanoTime});
                }

                @Override
                public void onEvent(String message) {
                    if (message.contains("unplugged")) {
                        unplugNanos = System.nanoTime();
                    }
                }
            });
        } catch (IOException | RuntimeException | Error e) {
            pty.close();
            throw e;
        }
    }

    /** The device the command under test opens. */
    String port() {
        return pty.a().toString();
    }

    @Override
    public void close() {
        emulator.close();
        pty.close();
    }
}
