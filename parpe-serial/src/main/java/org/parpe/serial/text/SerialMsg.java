package org.parpe.serial.text;

import org.parpe.core.text.Key;

/**
 * The keys of the servo buses' own messages: a servo that does not answer, whose torque does
 * not come on or whose model differs from the profile. Each constant is a key of
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
    WATCHDOG_NOT_ARMED;

    /** The bundle of these keys. */
    public static final String BUNDLE = "org.parpe.serial.text.SerialMessages";

    @Override
    public String bundle() {
        return BUNDLE;
    }
}
