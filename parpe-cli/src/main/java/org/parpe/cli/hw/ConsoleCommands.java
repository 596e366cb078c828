package org.parpe.cli.hw;

import org.parpe.cli.text.CliMsg;
import java.util.Locale;
import java.util.function.BiFunction;
import java.util.function.IntFunction;
import java.util.function.Supplier;
import org.parpe.serial.g1.emu.BusEmulator;
import org.parpe.serial.g1.Protocol;

/**
 * The emulator's console, the same for every protocol: {@code pose ID DEGREES} (move a limp device
 * by hand), one protocol's own word ({@code touch} for G1 modules, {@code fault} for servos),
 * {@code status}; {@code quit} is the caller's.
 */
final class ConsoleCommands {

    /** Moves a limp device by hand; false, and nothing moves, while it is driven. */
    interface Poser {
        boolean pose(int id, double degrees);
    }

    /**
     * What one emulator offers the console.
     *
     * @param unit        the word for one device: module or servo
     * @param poser       moves a limp device by hand
     * @param whyNotPosed why a driven device cannot be posed: {0} the unit, {1} its ID
     * @param word        the protocol's own command word ({@code touch}, {@code fault})
     * @param usage       the usage line of {@code word}
     * @param apply       runs {@code word} on a device ID with its argument; returns the reply
     * @param status      one line per device
     */
    record Console(CliMsg unit, Poser poser, CliMsg whyNotPosed, String word, String usage,
                   BiFunction<Integer, String, String> apply, Supplier<String> status) {
    }

    private ConsoleCommands() {
    }

    /** Applies one command line split into words; returns the reply to print. */
    static String apply(Console c, String[] w) {
        try {
            if (w[0].equals("pose")) {
                if (w.length != 3) {
                    return CliMsg.USAGE.text("pose ID DEGREES");
                }
                return c.poser().pose(Integer.parseInt(w[1]), Double.parseDouble(w[2]))
                        ? CliMsg.POSED_AT.text(c.unit().text(), w[1], w[2])
                        : c.whyNotPosed().text(c.unit().text(), w[1]);
            } else if (w[0].equals(c.word())) {
                return w.length != 3 ? CliMsg.USAGE.text(c.usage()) : c.apply().apply(Integer.parseInt(w[1]), w[2]);
            } else if (w[0].equals("status")) {
                return c.status().get();
            }
            return CliMsg.UNKNOWN_CONSOLE_COMMAND.text(w[0], c.word());
        } catch (IllegalArgumentException e) {
            return "error: " + e.getMessage();
        }
    }

    /** The console of emulated G1 modules: {@code touch ID left|right|both|none}. */
    static Console of(BusEmulator emu) {
        return new Console(CliMsg.UNIT_MODULE, emu::backDrive, CliMsg.DRIVEN_BY_SERVO, "touch",
                "touch ID left|right|both|none", (id, side) -> {
                    emu.setTouch(id, touchBits(side));
                    return CliMsg.UNIT_MODULE.text() + " " + id + " touch " + side;
                }, () -> lines(emu.moduleIds(), id -> CliMsg.UNIT_MODULE.text() + String.format(Locale.ROOT, " %d: %.2f°%s%s", id,
                        emu.angle(id), emu.isLimp(id) ? " " + CliMsg.LIMP.text() : "", emu.isSafeStopped(id) ? " " + CliMsg.STOPPED.text() : "")));
    }

    /** One line per device of {@code ids}, as {@code line} writes it. */
    static String lines(int[] ids, IntFunction<String> line) {
        StringBuilder b = new StringBuilder();
        for (int id : ids) {
            b.append(line.apply(id)).append(System.lineSeparator());
        }
        return b.toString().stripTrailing();
    }

    private static int touchBits(String side) {
        switch (side) {
            case "left": return Protocol.Touch.LEFT.bit();
            case "right": return Protocol.Touch.RIGHT.bit();
            case "both": return Protocol.Touch.LEFT.bit() | Protocol.Touch.RIGHT.bit();
            case "none": return 0;
            default: throw new IllegalArgumentException(CliMsg.BAD_TOUCH_SIDE.text(side));
        }
    }
}
