package org.parpe.serial.servo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Holding servos where they are (the IDE's Hold and jog, pose recording) is safety code: a servo
 * is held only at a position it has just reported, a reply lost on a busy line is asked for once
 * more, and a servo that stays silent is not told to hold, so the caller can say it may be limp.
 */
class HoldHereTest {
    /** A bus whose servos answer a position read only from its {@code answerFrom}-th read on. */
    static final class SilentBus implements ServoBus {
        final int answerFrom;
        int reads;
        final List<String> written = new ArrayList<>();

        SilentBus(int answerFrom) {
            this.answerFrom = answerFrom;
        }

        @Override public ServoProtocol protocol() { return ServoProtocol.DXL2; }
        @Override public String name() { return "silent"; }
        @Override public int ping(int id, int attempts) { return NO_REPLY; }
        @Override public void torque(int[] ids, ServoModel[] models, int n, boolean on) { written.add("torque " + on + " " + n); }
        @Override public int torqueState(int id, ServoModel model, int attempts) { return NO_REPLY; }
        @Override public void writeGoals(int[] ids, ServoModel[] models, int[] ticks, int n) { written.add("goals " + n); }
        @Override public int readPositions(int[] ids, ServoModel[] models, int n, double[] degrees, int[] errors) {
            reads++;
            for (int i = 0; i < n; i++) {
                degrees[i] = 12.5;
                errors[i] = reads >= answerFrom ? 0 : NO_REPLY;
            }
            return reads >= answerFrom ? n : 0;
        }
        @Override public boolean faulty(int statusError) { return false; }
        @Override public String describeFault(int id, ServoModel model, int statusError) { return ""; }
        @Override public String watchdog(int[] ids, ServoModel[] models, int n, int ms, boolean limp) { return ""; }
        @Override public boolean resumeIfTripped(int id, ServoModel model, int statusError, int ms) { return false; }
        @Override public String emergencyStop(int[] ids, ServoModel[] models, int n, boolean limp) { return ""; }
        @Override public int pendingOutput() { return 0; }
        @Override public Counters counters() { return new Counters(0, 0, 0, 0, 0); }
        @Override public java.io.IOException linkError() { return null; }
        @Override public void close() { }
    }

    private static final ServoModel XL430 = ServoModel.of(ServoProtocol.DXL2, 1060);

    @Test
    void aReplyLostOnceIsAskedForAgainAndTheServoHolds() throws Exception {
        SilentBus bus = new SilentBus(2);
        assertEquals(1, bus.holdHere(new int[] {3}, new ServoModel[] {XL430}, 1));
        assertEquals(2, bus.reads);
        assertEquals(List.of("goals 1", "torque true 1"), bus.written);
    }

    @Test
    void aServoThatStaysSilentIsNotToldToHold() throws Exception {
        SilentBus bus = new SilentBus(Integer.MAX_VALUE);
        assertEquals(0, bus.holdHere(new int[] {3, 4}, new ServoModel[] {XL430, XL430}, 2));
        assertEquals(List.of(), bus.written, "no goal and no torque for servos whose position is not known");
    }
}
