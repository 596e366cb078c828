package org.parpe.cli.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.BooleanSupplier;
import java.util.function.DoubleSupplier;
import java.util.function.Supplier;

/**
 * Waits for an emulated servo to reach where the run left it. An emulator moves at the servo's
 * rated speed in wall time, so on a loaded machine the last goal lands later than on a quiet
 * one; a fixed sleep made these checks fail under load. The wait ends as soon as the angle is
 * within the tolerance, and fails with the usual message if it never gets there.
 */
final class Settle {
    private static final long PATIENCE_NANOS = 15_000_000_000L;

    private Settle() {
    }

    static void angle(double expected, DoubleSupplier actual, double tolerance, Supplier<String> message)
            throws InterruptedException {
        long deadline = System.nanoTime() + PATIENCE_NANOS;
        while (Math.abs(actual.getAsDouble() - expected) > tolerance && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        assertEquals(expected, actual.getAsDouble(), tolerance, message);
    }

    static void until(BooleanSupplier condition, Supplier<String> message) throws InterruptedException {
        long deadline = System.nanoTime() + PATIENCE_NANOS;
        while (!condition.getAsBoolean() && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        assertTrue(condition.getAsBoolean(), message);
    }
}
