package org.parpe.serial.link;

import java.io.IOException;

/** A serial device that cannot be opened or has gone away; the message is meant for users. */
public class LinkException extends IOException {

    /** An exception with a message for the user. */
    public LinkException(String message) {
        super(message);
    }
}
