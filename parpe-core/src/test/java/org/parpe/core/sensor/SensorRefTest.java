package org.parpe.core.sensor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.regex.Matcher;
import java.util.regex.Pattern;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.junit.jupiter.api.Test;

/**
 * The one reader of sensor references (issue 32 item 6: the expressions, the stimulus files and
 * {@link Channel} each parsed them). It must read exactly what the loader's two patterns read
 * (PARSL.md §10: {@code $ID_SENSOR[_ARG]} and {@code $_WHO_SENSOR[_ARG]}), so that no script
 * loads differently.
 */
class SensorRefTest {
    /** The loader's patterns before the one reader, kept here as the reference. */
    private static final Pattern GLOBAL = Pattern.compile("(\\d+)_([A-Za-z]+)(?:_([A-Za-z0-9]+))?");
    private static final Pattern LOCAL = Pattern.compile("_(\\d+|self|prev|next)_([A-Za-z]+)(?:_([A-Za-z0-9]+))?");

    @Test
    void globalAndLocalReferences() {
        assertEquals(new SensorRef(false, "3", "accel", "z"), SensorRef.parse("3_accel_z"));
        assertEquals(Channel.ACCEL_Z, SensorRef.parse("3_accel_z").channel());
        assertEquals(3, SensorRef.parse("3_accel_z").moduleId());
        assertEquals(new SensorRef(false, "12", "angle", ""), SensorRef.parse("12_angle"));
        assertEquals(Channel.ANGLE, SensorRef.parse("12_angle").channel());
        assertEquals(new SensorRef(true, "self", "touch", "left"), SensorRef.parse("_self_touch_left"));
        assertEquals(new SensorRef(true, "2", "dock", "1"), SensorRef.parse("_2_dock_1"));
        assertEquals(-1, SensorRef.parse("123456789_angle").moduleId());
    }

    @Test
    void shapesThatAreNoReference() {
        for (String s : new String[] {"", "_", "3", "3_", "3_accel_", "3_accel_z_w", "x_angle", "self_angle",
                "_me_angle", "__angle", "3__angle", "3_acc3l", "3_accel_é"}) {
            assertNull(SensorRef.parse(s), s);
        }
    }

    @Test
    void wellShapedButUnknownChannelsAreTheCallersToRefuse() {
        assertNull(SensorRef.parse("3_accel_w").channel());
        assertNull(SensorRef.parse("3_sonar").channel());
        assertNull(SensorRef.parse("3_angle_x").channel());
    }

    @Property(tries = 3000)
    void readsWhatTheLoadersPatternsRead(@ForAll("names") String name) {
        SensorRef ref = SensorRef.parse(name);
        Matcher g = GLOBAL.matcher(name);
        Matcher l = LOCAL.matcher(name);
        Matcher m = g.matches() ? g : l.matches() ? l : null;
        if (m == null) {
            assertNull(ref, name);
            return;
        }
        assertEquals(new SensorRef(m == l, m.group(1), m.group(2), m.group(3) == null ? "" : m.group(3)), ref, name);
    }

    @Provide
    Arbitrary<String> names() {
        Arbitrary<String> pieces = Arbitraries.of("_", "_", "_", "3", "42", "self", "prev", "next", "accel", "x", "Z",
                "angle", "touch", "left", "dock", "0", "é", "-", "");
        return pieces.list().ofMinSize(0).ofMaxSize(6).map(l -> String.join("", l));
    }
}
