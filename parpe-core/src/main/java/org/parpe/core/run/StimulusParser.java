package org.parpe.core.run;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Control;
import org.parpe.core.model.Program;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorRef;
import org.parpe.core.sensor.SensorTable;

/**
 * Reads a stimulus file (PARSL.md §11): one {@code TIME NAME=VALUE} per line, {@code #}
 * comments. Problems are reported as {@code FILE:LINE:1: error: …} (a usage error).
 */
public final class StimulusParser {
    private static final Pattern LINE = Pattern.compile("(\\S+)\\s+\\$([A-Za-z0-9_]+)\\s*=\\s*(\\S+)");

    /** A malformed stimulus file. */
    public static final class StimulusException extends Exception {
        /** An error already formatted with its place. */
        public StimulusException(String message) {
            super(message, null, false, false);
        }
    }

    private StimulusParser() {
    }

    /** Parses {@code text} (read from {@code file}) for {@code program}. */
    public static List<Stimulus> parse(String file, String text, Program program) throws StimulusException {
        List<Stimulus> out = new ArrayList<>();
        String[] lines = text.split("\r?\n", -1);
        int[] ids = program.moduleIds();
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i];
            int hash = line.indexOf('#');
            String body = (hash >= 0 ? line.substring(0, hash) : line).trim();
            if (body.isEmpty()) {
                continue;
            }
            String where = file + ":" + (i + 1) + ":1: error: ";
            Matcher m = LINE.matcher(body);
            if (!m.matches()) {
                throw new StimulusException(where + "expected 'TIME $NAME=VALUE', got '" + body + "'");
            }
            Double time = Numbers.parsePlain(m.group(1));
            if (time == null || time < 0) {
                throw new StimulusException(where + "time must be a number of seconds >= 0, got '" + m.group(1) + "'");
            }
            out.add(assignment(where, i + 1, time, m.group(2), m.group(3), body, program, ids));
        }
        return out;
    }

    private static Stimulus assignment(String where, int line, double time, String name, String value, String text,
                                       Program program, int[] ids) throws StimulusException {
        List<Control> controls = program.controls();
        for (int c = 0; c < controls.size(); c++) {
            Control ctl = controls.get(c);
            if (ctl.name().equals(name)) {
                return new Stimulus(time, line, Stimulus.Kind.CONTROL, c, controlValue(where, ctl, value, program), text);
            }
        }
        SensorRef s = SensorRef.parse(name);
        if (s == null || s.local() || !org.parpe.core.lang.Vocabulary.SENSOR_TYPES.contains(s.sensor())) {
            throw new StimulusException(where + "unknown control or sensor '$" + name + "'"
                    + org.parpe.core.expr.Names.suggest(name, controls.stream().map(Control::name).toList(), "$"));
        }
        int id = s.moduleId();
        Channel ch = s.channel();
        int index = id < 0 ? -1 : java.util.Arrays.binarySearch(ids, id);
        if (ch == null) {
            throw new StimulusException(where + "'$" + name + "' is not a sensor reading (use angle, accel_x|y|z, touch_left|right, dock_0|1)");
        }
        if (index < 0) {
            throw new StimulusException(where + "module " + s.module() + " is not part of the robot");
        }
        if (!program.robot().carries(id, ch.sensor())) {
            throw new StimulusException(where + "module " + id + " has no " + ch.sensor() + " sensor");
        }
        Double v = Numbers.parsePlain(value);
        if (v == null) {
            throw new StimulusException(where + "value of '$" + name + "' must be a number, got '" + value + "'");
        }
        return new Stimulus(time, line, Stimulus.Kind.SENSOR, SensorTable.slot(index, ch), v, text);
    }

    private static double controlValue(String where, Control c, String value, Program program) throws StimulusException {
        if (c.type() == Control.ControlType.RADIO) {
            if (!c.words().contains(value)) {
                throw new StimulusException(where + "radio '" + c.name() + "' has no word '" + value + "' (words: "
                        + String.join(", ", c.words()) + ")");
            }
            return program.radioWords().get(value);
        }
        Double v = Numbers.parsePlain(value);
        if (v == null) {
            throw new StimulusException(where + "value of '$" + c.name() + "' must be a number, got '" + value + "'");
        }
        if (c.min() != null && (v < c.min() || v > c.max())) {
            throw new StimulusException(where + "slider '" + c.name() + "' must be within [" + Numbers.format(c.min())
                    + ", " + Numbers.format(c.max()) + "], got " + Numbers.format(v));
        }
        return v;
    }
}
