package org.parpe.gui.pose;

import java.util.Arrays;
import java.util.function.Supplier;
import java.util.stream.Collectors;
import org.eclipse.swt.dnd.DND;
import org.eclipse.swt.dnd.DragSource;
import org.eclipse.swt.dnd.DragSourceAdapter;
import org.eclipse.swt.dnd.DragSourceEvent;
import org.eclipse.swt.dnd.TextTransfer;
import org.eclipse.swt.dnd.Transfer;
import org.eclipse.swt.widgets.Control;
import org.parpe.core.lang.Numbers;

/**
 * A pose dragged out of the Pose panel: as text, the angles of a state ({@code "10, -20.5"}),
 * which the Diagram pane takes when it is dropped on a state of the ring (or any program that
 * takes text).
 */
final class PoseDrag {
    private PoseDrag() {
    }

    /** {@code angles} as a state's angles attribute: degrees in order, comma separated. */
    static String angles(double[] angles) {
        return Arrays.stream(angles).mapToObj(Numbers::format).collect(Collectors.joining(", "));
    }

    /** Lets the selected pose ({@code selected}, null when none) be dragged out of {@code table}. */
    static void from(Control table, Supplier<String> selected) {
        DragSource source = new DragSource(table, DND.DROP_COPY);
        source.setTransfer(new Transfer[] {TextTransfer.getInstance()});
        source.addDragListener(new DragSourceAdapter() {
            @Override
            public void dragStart(DragSourceEvent e) {
                e.doit = selected.get() != null;
            }

            @Override
            public void dragSetData(DragSourceEvent e) {
                e.data = selected.get();
            }
        });
    }
}
