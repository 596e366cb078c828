package org.parpe.cli.hw;

import java.util.Locale;
import org.parpe.serial.emu.BusEmulator;
import org.parpe.serial.protocol.Protocol;

/** The emulator's console: posing limp modules by hand, touch sensors, status. */
final class ConsoleCommands {

    private ConsoleCommands() {
    }

    /** Applies one command line split into words; returns the reply to print. */
    static String apply(BusEmulator emu, String[] w) {
        try {
            switch (w[0]) {
                case "pose":
                    if (w.length != 3) {
                        return "usage: pose ID DEGREES";
                    }
                    return emu.backDrive(Integer.parseInt(w[1]), Double.parseDouble(w[2]))
                            ? "module " + w[1] + " posed at " + w[2] + "°"
                            : "module " + w[1] + " is driven by its servo; it can be posed only while limp";
                case "touch":
                    if (w.length != 3) {
                        return "usage: touch ID left|right|both|none";
                    }
                    emu.setTouch(Integer.parseInt(w[1]), touchBits(w[2]));
                    return "module " + w[1] + " touch " + w[2];
                case "status":
                    return status(emu);
                default:
                    return "unknown command '" + w[0] + "'; try pose, touch, status or quit";
            }
        } catch (IllegalArgumentException e) {
            return "error: " + e.getMessage();
        }
    }

    private static int touchBits(String side) {
        switch (side) {
            case "left": return Protocol.TOUCH_LEFT;
            case "right": return Protocol.TOUCH_RIGHT;
            case "both": return Protocol.TOUCH_LEFT | Protocol.TOUCH_RIGHT;
            case "none": return 0;
            default: throw new IllegalArgumentException("touch side must be left, right, both or none, got '" + side + "'");
        }
    }

    private static String status(BusEmulator emu) {
        StringBuilder b = new StringBuilder();
        for (int id : emu.moduleIds()) {
            b.append(String.format(Locale.ROOT, "module %d: %.2f°%s%s%n", id, emu.angle(id),
                    emu.isLimp(id) ? " limp" : "", emu.isSafeStopped(id) ? " stopped" : ""));
        }
        return b.toString().stripTrailing();
    }
}
