package org.parpe.core.sensor;

/**
 * A sensor reference as written after its {@code $} (PARSL.md §10), split into its parts: the
 * one reader of this syntax, for the expressions' names and the stimulus files alike. A global
 * reference {@code ID_SENSOR[_ARG]} ({@code 3_accel_z}) reads module {@code ID}; a local one
 * {@code _WHO_SENSOR[_ARG]} ({@code _self_touch_left}, {@code _2_angle}) reads a module of the
 * instance's group, {@code WHO} a position or {@code self}, {@code prev}, {@code next}. Only the
 * shape is read here: whether the sensor type, its argument and the module exist is the
 * caller's to say, each with its own message.
 *
 * @param local    whether it is a local reference (it starts with {@code _})
 * @param module   the module's id (digits) or, for a local reference, its position or {@code self}, {@code prev}, {@code next}
 * @param sensor   the sensor type as written (letters)
 * @param argument the argument as written (letters and digits), empty where there is none
 */
public record SensorRef(boolean local, String module, String sensor, String argument) {
    /** The reference {@code name} (without {@code $}) splits into, or {@code null} if it does not have the shape of one. */
    public static SensorRef parse(String name) {
        boolean local = name.startsWith("_");
        int moduleStart = local ? 1 : 0;
        int moduleEnd = name.indexOf('_', moduleStart);
        if (moduleEnd < 0) {
            return null;
        }
        String module = name.substring(moduleStart, moduleEnd);
        if (!digits(module) && !(local && (module.equals("self") || module.equals("prev") || module.equals("next")))) {
            return null;
        }
        int sensorEnd = name.indexOf('_', moduleEnd + 1);
        String sensor = name.substring(moduleEnd + 1, sensorEnd < 0 ? name.length() : sensorEnd);
        String argument = sensorEnd < 0 ? "" : name.substring(sensorEnd + 1);
        if (!all(sensor, false) || sensorEnd >= 0 && !all(argument, true)) {
            return null;
        }
        return new SensorRef(local, module, sensor, argument);
    }

    /** The channel this reference reads, or {@code null} if its sensor type and argument name none. */
    public Channel channel() {
        return Channel.of(sensor, argument);
    }

    /** The module's id of a global reference, or -1 where it has more than 7 digits (no module has such an id). */
    public int moduleId() {
        return module.length() > 7 ? -1 : Integer.parseInt(module);
    }

    private static boolean digits(String s) {
        if (s.isEmpty()) {
            return false;
        }
        for (int i = 0; i < s.length(); i++) {
            if (s.charAt(i) < '0' || s.charAt(i) > '9') {
                return false;
            }
        }
        return true;
    }

    /** Whether {@code s} is one or more ASCII letters (and, with {@code orDigits}, digits). */
    private static boolean all(String s, boolean orDigits) {
        if (s.isEmpty()) {
            return false;
        }
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            boolean letter = c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z';
            if (!letter && !(orDigits && c >= '0' && c <= '9')) {
                return false;
            }
        }
        return true;
    }
}
