package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.LocalDate;
import java.time.LocalTime;
import java.time.ZoneId;
import org.junit.jupiter.api.Test;

/**
 * The status bar's "robot not responding since HH:MM:SS" keeps its seconds when they are 0: the
 * time was LocalTime.toString, which writes 09:31 for 09:31:00, and ServoProfileGuiTest failed
 * once a minute on it (the fresh-clone CI of 29 November).
 */
class SilentTimeTest {
    @Test
    void aSilenceThatBeganOnTheMinuteKeepsItsSeconds() {
        long ms = LocalDate.of(2026, 11, 29).atTime(LocalTime.of(9, 31, 0)).atZone(ZoneId.systemDefault()).toInstant().toEpochMilli();
        assertEquals("09:31:00", RunActions.silentTime(ms));
        assertEquals("09:31:07", RunActions.silentTime(ms + 7_250));
    }
}
