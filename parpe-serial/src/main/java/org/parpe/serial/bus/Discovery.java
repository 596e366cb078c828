package org.parpe.serial.bus;

import java.util.List;

/**
 * Which of the wanted modules answered a ping.
 *
 * @param found         module IDs that answered
 * @param missing       addressable IDs that did not answer
 * @param unaddressable IDs above {@link org.parpe.serial.protocol.Protocol#MAX_MODULE_ID}
 */
public record Discovery(List<Integer> found, List<Integer> missing, List<Integer> unaddressable) {

    public Discovery {
        found = List.copyOf(found);
        missing = List.copyOf(missing);
        unaddressable = List.copyOf(unaddressable);
    }

    /** Whether every wanted module answered. */
    public boolean complete() {
        return missing.isEmpty() && unaddressable.isEmpty();
    }
}
