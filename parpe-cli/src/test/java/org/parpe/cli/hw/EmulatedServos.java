package org.parpe.cli.hw;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.PtyPair;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.emu.ServoEmulator;

/** A socat pty pair with emulated Dynamixel or Feetech servos on end b; the command under test opens end a. */
final class EmulatedServos implements AutoCloseable {
    final PtyPair pty;
    final ServoEmulator emulator;
    final List<String> events = new CopyOnWriteArrayList<>();
    /** Every goal Sync Write received: servo degrees in servo ID order, NaN for servos it left out. */
    final List<double[]> goals = new CopyOnWriteArrayList<>();

    EmulatedServos(Path dir, ServoModel model, EmulatorOptions options) throws IOException {
        pty = PtyPair.start(dir.resolve("servo-a"), dir.resolve("servo-b"));
        try {
            emulator = ServoEmulator.start(LinkOpener.serial(pty.b().toString(), 1_000_000), model, options,
                    new EmulatorListener() {
                        @Override
                        public void onSetpoints(int seq, double[] angles) {
                            goals.add(angles.clone());
                        }

                        @Override
                        public void onEvent(String message) {
                            events.add(message);
                        }
                    });
        } catch (IOException | RuntimeException | Error e) {
            pty.close();
            throw e;
        }
        warmUp(model, options.modules()[options.modules().length - 1]);
    }

    /**
     * Waits until servo {@code id} answers a ping: the first packets of a fresh emulator load its
     * classes, which on a loaded machine takes longer than a scan's two 10 ms tries.
     */
    private void warmUp(ServoModel model, int id) throws IOException {
        try (org.parpe.serial.servo.ServoBus b = org.parpe.serial.servo.host.ServoBuses.open(model.protocol(),
                LinkOpener.serial(port(), 1_000_000), org.parpe.serial.bus.BusConfig.defaults().withBaud(1_000_000))) {
            long deadline = System.nanoTime() + 5_000_000_000L;
            while (b.ping(id, 1) < 0 && System.nanoTime() < deadline) {
                Thread.onSpinWait();
            }
        }
    }

    String port() {
        return pty.a().toString();
    }

    @Override
    public void close() {
        emulator.close();
        pty.close();
    }
}
