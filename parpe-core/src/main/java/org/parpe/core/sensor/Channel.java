package org.parpe.core.sensor;

/**
 * One sensor reading of a module (PARSL.md §2, §10). The sensor reference
 * {@code $3_accel_z} reads channel {@link #ACCEL_Z} of module 3.
 */
public enum Channel {
    /** Measured joint angle, degrees. */
    ANGLE("angle", ""),
    /** 100 × body x axis · gravity direction. */
    ACCEL_X("accel", "x"),
    /** 100 × body y axis · gravity direction. */
    ACCEL_Y("accel", "y"),
    /** 100 × body z axis · gravity direction. */
    ACCEL_Z("accel", "z"),
    /** 1 while the +y side touches something. */
    TOUCH_LEFT("touch", "left"),
    /** 1 while the −y side touches something. */
    TOUCH_RIGHT("touch", "right"),
    /** Connection plate 0: 0 free, 1 a plate it can latch onto is within reach, 2 latched (PARSL.md §14). */
    DOCK_0("dock", "0"),
    /** Connection plate 1, read as {@link #DOCK_0}. */
    DOCK_1("dock", "1");

    private static final Channel[] ALL = values();

    private final String sensor;
    private final String argument;

    Channel(String sensor, String argument) {
        this.sensor = sensor;
        this.argument = argument;
    }

    /** The sensor type that provides this channel: {@code angle}, {@code accel}, {@code touch} or {@code dock}. */
    public String sensor() {
        return sensor;
    }

    /** The argument ({@code x}, {@code left}, {@code 0}, …), empty for {@code angle}. */
    public String argument() {
        return argument;
    }

    /** The suffix used in sensor references, e.g. {@code accel_z} or {@code angle}. */
    public String suffix() {
        return argument.isEmpty() ? sensor : sensor + "_" + argument;
    }

    /** Number of channels. */
    public static int count() {
        return ALL.length;
    }

    /** The channel of a sensor type and argument, or {@code null}. */
    public static Channel of(String sensor, String argument) {
        for (Channel c : ALL) {
            if (c.sensor.equals(sensor) && c.argument.equals(argument)) {
                return c;
            }
        }
        return null;
    }

    /** What a reference to sensor type {@code sensor} must add after the type, for messages. */
    public static org.parpe.core.text.Msg argumentHint(String sensor) {
        switch (sensor) {
            case "angle": return org.parpe.core.text.Msg.ANGLE_NO_ARGUMENT;
            case "accel": return org.parpe.core.text.Msg.ACCEL_NEEDS_AXIS;
            case "touch": return org.parpe.core.text.Msg.TOUCH_NEEDS_SIDE;
            default: return org.parpe.core.text.Msg.DOCK_NEEDS_PLATE;
        }
    }
}
