package org.parpe.serial.g1.emu;

import org.parpe.serial.g1.Protocol;
import org.parpe.serial.bus.SafeMode;

/**
 * One emulated module: a hobby servo with a speed limit, its PIC's watchdog and latches, and its
 * sensors. The emulator serialises access; this class is not thread-safe.
 */
final class ServoModule {
    final int id;
    double angle;
    double target;
    boolean limp;
    boolean estop;
    boolean watchdogTripped;
    boolean watchdogArmed;
    int touch;

    ServoModule(int id) {
        this.id = id;
    }

    /** Moves toward the target by at most {@code speed·dt}; a limp servo does not drive. */
    void step(double dt, double speed) {
        if (limp) {
            return;
        }
        double d = target - angle;
        double max = speed * dt;
        angle = Math.abs(d) <= max ? target : angle + Math.copySign(max, d);
    }

    /** A new commanded angle (wire units), obeyed unless stopped. */
    void command(int wire) {
        if (estop || watchdogTripped) {
            return;
        }
        target = Protocol.fromWire(wire);
        limp = false;
        watchdogArmed = true;
    }

    /** Enters the safe mode: hold where it is, or go limp. */
    void safe(int mode) {
        watchdogArmed = false;
        if (mode == SafeMode.LIMP.wire()) {
            limp = true;
        } else {
            limp = false;
            target = angle;
        }
    }

    /** Holds with the servo on, at the current angle or at the last setpoint; disarms the watchdog. */
    void hold(boolean keepTarget) {
        if (estop) {
            // An emergency stop stays as it is until RESUME: HOLD must not power a limp servo again.
            return;
        }
        watchdogArmed = false;
        if (!keepTarget || limp) {
            target = angle;
        }
        limp = false;
    }

    int flags() {
        return (limp ? Protocol.Flag.LIMP.bit() : 0) | (estop ? Protocol.Flag.ESTOP.bit() : 0)
                | (watchdogTripped ? Protocol.Flag.WATCHDOG.bit() : 0);
    }

    /** Gravity along a body axis of a module whose body turns with its joint, ×100. */
    int accel(int axis) {
        double r = Math.toRadians(angle);
        switch (axis) {
            case 0: return (int) Math.round(100 * Math.sin(r));
            case 1: return (int) Math.round(-100 * Math.cos(r));
            default: return 0;
        }
    }
}
