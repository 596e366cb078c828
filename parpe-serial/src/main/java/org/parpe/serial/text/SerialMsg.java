package org.parpe.serial.text;

import org.parpe.core.text.Key;

/**
 * The keys of the servo buses' own messages: a servo that does not answer, whose torque does
 * not come on or whose model differs from the profile, a robot that stopped answering, a lost
 * device, the emergency stop, a setpoint outside the limits, a servo's fault; the bus and emulator
 * options' checks, the emulators' log lines, the pose recording's checks, the end-of-run counters.
 * Each constant is a key of
 * {@code SerialMessages.properties} (English) and of its translations beside it;
 * {@code SerialMessagesTest} fails on a key missing from a bundle, on a bundle key without a
 * constant here, on a constant no code uses and on placeholders that differ from the English ones.
 */
public enum SerialMsg implements Key {
    // ServoSetUp.who: which device
    WHO_MODULE,
    WHO_SERVO,

    // ServoSetUp, ServoDriver
    WRONG_MODEL,
    UNKNOWN_MODEL,
    A_MODEL,
    DRIVING_ANYWAY,
    WILL_NOT_MOVE,
    PING_BUT_NO_READS,
    TORQUE_NOT_ON,
    READ_BACK_0,
    NOT_READ_BACK,
    ANSWERS_NOW,
    DID_NOT_ANSWER_READS,
    WATCHDOG_NOT_ARMED,
    ANSWER,
    ANSWER_MISSING,

    // BusThread: the device in messages, a lost or silent bus, the emergency stop
    UNIT_MODULE,
    UNIT_SERVO,
    UNITS_MODULE,
    UNITS_SERVO,
    FINAL_HOLD_FAILED,
    NONE_ANSWERED_SINCE,
    ESTOP_NOT_CONFIRMED,
    ESTOP_SENT,
    ESTOP_NOT_SENT_SILENT,
    ESTOP_NOT_SENT,
    NO_REPLY,
    WATCHDOG_STOPPED,
    BACK,
    LINK_LOST,

    // ServoBus, ControlTableBus, G1Bus: what the devices do
    HOLD_LAST_GOAL,
    KEEP_LAST_GOAL,
    TORQUE_OFF_SENT,
    HOLD_OR_WATCHDOG,
    NO_WATCHDOG,
    WATCHDOG_ARMED,
    CANNOT_GO_LIMP,
    ESTOP_LIMP,
    ESTOP_HOLD,
    G1_WATCHDOGS_OFF,
    G1_WATCHDOG_LIMP,
    G1_WATCHDOG_HOLD,
    G1_STOPPED_LIMP,
    G1_STOPPED_HOLD,
    G1_WHILE_LOST_LIMP,
    G1_WHILE_LOST_HOLD,

    // ServoSet: limits and faults
    CLAMPED_JOINT_RANGE,
    CLAMPED_LIMITS,
    FAULT,
    NO_FAULT_NOW,

    // SerialLink, PipeLink, PtyPair: the serial device
    LINK_BAD_BAUD,
    LINK_NO_DEVICE,
    LINK_NOT_SERIAL,
    LINK_NO_PERMISSION,
    LINK_CANNOT_USE,
    LINK_NOT_TTY,
    LINK_BUSY,
    LINK_CANNOT_OPEN,
    LINK_CLOSED,
    LINK_GONE,
    LINK_STALLED,
    SOCAT_MISSING,
    SOCAT_NO_PTYS,
    SOCAT_INTERRUPTED,

    // BusConfig: the bus options' names in Msg.MUST_BE_IN_RANGE
    OPTION_BAUD,
    OPTION_READ_TIMEOUT,
    OPTION_RETRIES,
    OPTION_WATCHDOG,
    OPTION_DEAD_AFTER,
    OPTION_KEEPALIVE,
    OPTION_RECONNECT,
    OPTION_IDLE_GAP,
    SAFE_MODE_HOLD_OR_LIMP,

    // EmulatorOptions, ServedLine, BusEmulator, ServoEmulator: the emulators' options and log lines
    EMU_MODULE_ID,
    EMU_LISTED_TWICE,
    EMU_DROP,
    EMU_CORRUPT,
    EMU_LATENCY,
    EMU_SPEED,
    EMU_WAITING,
    EMU_SERVING_AGAIN,
    EMU_UNPLUGGED,
    EMU_PLUGGED_BACK,
    EMU_ESTOP,
    EMU_WATCHDOG,
    WHO_SERVO_ID,
    NOT_EMULATED,

    // ServoScanner, ServoEmulator: a servo ID beyond the protocol's
    SERVO_IDS,

    // PoseRecording, RecordingWriter: the pose recording's checks
    REC_GROUP_NAME,
    REC_NO_MODULES,
    REC_POSE_ANGLES,
    REC_RATE,
    REC_NO_POSES,

    // ServoDriver.summary: the end-of-run counters line
    SUMMARY,
    SENT_PACKETS,
    SENT_FRAMES,
    REJECTED_BY_MODULES,
    REJECTED_BY_SERVOS,
    FAULTS_MODULE,
    FAULTS_SERVO;

    /** The bundle of these keys. */
    public static final String BUNDLE = "org.parpe.serial.text.SerialMessages";

    @Override
    public String bundle() {
        return BUNDLE;
    }
}
