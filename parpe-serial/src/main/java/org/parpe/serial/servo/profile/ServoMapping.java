package org.parpe.serial.servo.profile;

import org.parpe.core.diag.SourcePos;
import org.parpe.serial.servo.ServoModel;

/**
 * How one PARSL module is driven: servo angle = {@code zero} + {@code direction} × joint angle.
 *
 * @param module    PARSL module ID
 * @param servo     servo ID on the bus
 * @param model     the servo's model (its units)
 * @param zero      servo angle of joint angle 0, degrees
 * @param direction +1, or −1 when the servo turns the other way than the joint
 * @param min       lowest joint angle ever commanded, degrees
 * @param max       highest joint angle ever commanded, degrees
 * @param where     the {@code <servo>} element, for messages
 */
public record ServoMapping(int module, int servo, ServoModel model, double zero, int direction, double min, double max,
                           SourcePos where) {
    /** Degrees a tick may lie beyond a limit through floating-point rounding alone. */
    private static final double LIMIT_SLACK = 1e-9;
    /** The joint limit, either way, of a servo PARPE drives before a profile says otherwise. */
    public static final double STARTER_LIMIT_DEG = 90;

    /**
     * How PARPE drives servo {@code servo} of {@code model} as module {@code module} without a
     * profile, as a starter profile writes it: zero 0, direction +1, limits ±{@value #STARTER_LIMIT_DEG}°
     * (within the model's range).
     */
    public static ServoMapping starter(int module, int servo, ServoModel model, SourcePos where) {
        return new ServoMapping(module, servo, model, 0, 1, Math.max(-STARTER_LIMIT_DEG, model.minDegrees()),
                Math.min(STARTER_LIMIT_DEG, model.maxDegrees()), where);
    }

    /** The joint angle clamped to {@link #min}…{@link #max}. */
    public double clamp(double joint) {
        return Math.max(min, Math.min(max, joint));
    }

    /** The servo angle of a joint angle (not clamped). */
    public double servoAngle(double joint) {
        return zero + direction * joint;
    }

    /** The joint angle of a servo angle. */
    public double jointAngle(double servoAngle) {
        return (servoAngle - zero) * direction;
    }

    /**
     * The goal position, in the model's ticks as the wire carries them, of a joint angle already
     * clamped: the nearest tick, or the next one inwards when the nearest lies beyond
     * {@link #min} or {@link #max} (half a tick can be a large angle on a 1024-step servo).
     */
    public int goalTicks(double joint) {
        int t = model.nearestTick(servoAngle(joint));
        double at = jointAngle(model.tickDegrees(t));
        if (at > max + LIMIT_SLACK) {
            t -= direction;
        } else if (at < min - LIMIT_SLACK) {
            t += direction;
        }
        return model.encode(t);
    }

    /**
     * The same mapping with {@link #min} and {@link #max} narrowed, where needed, to joint angles
     * the servo can reach with this zero and direction.
     */
    public ServoMapping reachable() {
        double a = jointAngle(model.minDegrees());
        double b = jointAngle(model.maxDegrees());
        double lo = Math.max(min, Math.min(a, b));
        double hi = Math.min(max, Math.max(a, b));
        return lo == min && hi == max ? this : new ServoMapping(module, servo, model, zero, direction, lo, hi, where);
    }

    /** The same mapping with another zero offset. */
    public ServoMapping withZero(double z) {
        return new ServoMapping(module, servo, model, z, direction, min, max, where);
    }
}
