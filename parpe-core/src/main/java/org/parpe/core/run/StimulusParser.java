package org.parpe.core.run;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Control;
import org.parpe.core.model.Program;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorRef;
import org.parpe.core.sensor.SensorTable;
import org.parpe.core.text.Msg;

/**
 * Reads a stimulus file (PARSL.md §11): one {@code TIME NAME=VALUE} per line, {@code #}
 * comments. A problem is a {@link Diagnostic} at {@code FILE:LINE:1}, shown in the chosen
 * language (a usage error).
 */
public final class StimulusParser {
    private static final Pattern LINE = Pattern.compile("(\\S+)\\s+\\$([A-Za-z0-9_]+)\\s*=\\s*(\\S+)");

    /** A malformed stimulus file: its first problem, with its place. */
    public static final class StimulusException extends Exception {
        private final transient Diagnostic diagnostic;

        /** The problem {@code key} with {@code args} at {@code where}. */
        StimulusException(SourcePos where, Msg key, Object... args) {
            super(null, null, false, false);
            this.diagnostic = new Diagnostic(Severity.ERROR, where, key, args);
        }

        /** The problem, with its key and arguments, formatted when it is shown. */
        public Diagnostic diagnostic() {
            return diagnostic;
        }

        /** {@code FILE:LINE:1: error: MESSAGE} in the chosen language. */
        @Override
        public String getMessage() {
            return diagnostic.format();
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
            SourcePos where = new SourcePos(file, i + 1, 1);
            Matcher m = LINE.matcher(body);
            if (!m.matches()) {
                throw new StimulusException(where, Msg.STIMULUS_LINE, body);
            }
            Double time = Numbers.parsePlain(m.group(1));
            if (time == null || time < 0) {
                throw new StimulusException(where, Msg.STIMULUS_TIME, m.group(1));
            }
            out.add(assignment(where, i + 1, time, m.group(2), m.group(3), body, program, ids));
        }
        return out;
    }

    private static Stimulus assignment(SourcePos where, int line, double time, String name, String value, String text,
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
            throw new StimulusException(where, Msg.STIMULUS_UNKNOWN_NAME, name,
                    org.parpe.core.expr.Names.suggest(name, controls.stream().map(Control::name).toList(), "$"));
        }
        int id = s.moduleId();
        Channel ch = s.channel();
        int index = id < 0 ? -1 : java.util.Arrays.binarySearch(ids, id);
        if (ch == null) {
            throw new StimulusException(where, Msg.STIMULUS_NOT_A_READING, name);
        }
        if (index < 0) {
            throw new StimulusException(where, Msg.MODULE_NOT_IN_ROBOT, s.module());
        }
        if (!program.robot().carries(id, ch.sensor())) {
            throw new StimulusException(where, Msg.STIMULUS_NO_SENSOR, id, ch.sensor());
        }
        Double v = Numbers.parsePlain(value);
        if (v == null) {
            throw new StimulusException(where, Msg.STIMULUS_NUMBER, name, value);
        }
        return new Stimulus(time, line, Stimulus.Kind.SENSOR, SensorTable.slot(index, ch), v, text);
    }

    private static double controlValue(SourcePos where, Control c, String value, Program program) throws StimulusException {
        if (c.type() == Control.ControlType.RADIO) {
            if (!c.words().contains(value)) {
                throw new StimulusException(where, Msg.STIMULUS_RADIO_WORD, c.name(), value,
                        String.join(", ", c.words()));
            }
            return program.radioWords().get(value);
        }
        Double v = Numbers.parsePlain(value);
        if (v == null) {
            throw new StimulusException(where, Msg.STIMULUS_NUMBER, c.name(), value);
        }
        if (c.min() != null && (v < c.min() || v > c.max())) {
            throw new StimulusException(where, Msg.STIMULUS_SLIDER_RANGE, c.name(), Numbers.format(c.min()),
                    Numbers.format(c.max()), Numbers.format(v));
        }
        return v;
    }
}
