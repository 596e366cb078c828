package org.parpe.gui.hardware;

import org.parpe.gui.text.UiMsg;
import java.util.List;
import org.parpe.core.diag.SourcePos;
import org.parpe.gui.pose.PoseHardware;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ServoMapping;

/**
 * The robot connected in the Hardware dialog, in script modules, for the Pose panel: through the
 * tool bar's hardware profile (servo, zero, direction), or without one servo ID = module ID as a
 * starter profile maps it ({@link ServoMapping#starter}: servo angle 0 is joint angle 0, ±90°). Limp, hold and moves go through the dialog's
 * {@link HardwareSession} (its own thread); angles are the dialog's last poll.
 */
public final class ConnectedRobot implements PoseHardware {
    private final HardwareDialog dialog;
    private final HardwareProfile profile;

    public ConnectedRobot(HardwareDialog dialog, HardwareProfile profile) {
        this.dialog = dialog;
        this.profile = profile;
    }

    @Override
    public String describe() {
        int n = dialog.servos().size();
        String which = profile == null ? "" : UiMsg.HW_DESCRIBE_PROFILE.text(profile.file());
        return n == 1 ? UiMsg.HW_DESCRIBE_ONE.text(which) : UiMsg.HW_DESCRIBE_N.text(n, which);
    }

    /** The dialog's row of module {@code id}'s servo, or −1. */
    private int row(int id) {
        ServoMapping m = mapping(id);
        List<HardwareSession.Servo> servos = dialog.servos();
        for (int r = 0; m != null && r < servos.size(); r++) {
            if (servos.get(r).id() == m.servo() && servos.get(r).model() != null) {
                return r;
            }
        }
        return -1;
    }

    private ServoMapping mapping(int id) {
        if (profile != null) {
            return profile.forModule(id);
        }
        for (HardwareSession.Servo s : dialog.servos()) {
            if (s.id() == id && s.model() != null) {
                return ServoMapping.starter(id, id, s.model(), SourcePos.origin(UiMsg.HW_TITLE.text()));
            }
        }
        return null;
    }

    @Override
    public void limp(int[] modules, boolean limp) {
        // Twice, as the command-line recorder does: a torque write has no reply, so a lost packet would go unnoticed.
        for (int pass = 0; pass < 2; pass++) {
            for (int id : modules) {
                int r = row(id);
                if (r >= 0) {
                    dialog.session().torque(r, !limp);
                }
            }
        }
    }

    @Override
    public double[] angles(int[] modules) {
        double[] out = new double[modules.length];
        List<HardwareSession.Servo> servos = dialog.servos();
        for (int k = 0; k < modules.length; k++) {
            int r = row(modules[k]);
            if (r < 0) {
                throw new IllegalStateException(UiMsg.HW_MODULE_NO_SERVO.text(modules[k], profile == null
                        ? UiMsg.HW_MODULE_NO_SERVO_PLAIN.text() : UiMsg.HW_MODULE_NO_SERVO_PROFILE.text(profile.file())));
            }
            HardwareSession.Servo s = servos.get(r);
            if (Double.isNaN(s.degrees()) || !s.status().isEmpty()) {
                throw new IllegalStateException(UiMsg.HW_NO_GOOD_READING.text(modules[k], s.id(),
                        s.status().isEmpty() ? "" : ": " + s.status()));
            }
            out[k] = mapping(modules[k]).jointAngle(s.degrees());
        }
        return out;
    }

    @Override
    public void move(int id, double degrees) {
        int r = row(id);
        ServoMapping m = mapping(id);
        if (r >= 0 && m != null) {
            dialog.session().jog(r, m.servoAngle(m.clamp(degrees)));
        }
    }
}
