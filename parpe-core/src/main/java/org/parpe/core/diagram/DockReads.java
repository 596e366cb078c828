package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.expr.ExprTree;
import org.parpe.core.expr.Expression;
import org.parpe.core.sensor.Channel;
import org.parpe.core.text.DiagramMsg;
import org.parpe.core.text.Msg;

/**
 * The {@code dock} readings an exit condition waits on (PARSL.md §14), in words for the
 * diagrams: "dock: module 0 plate 0, module 9 plate 1". Global references name their module;
 * local ones name it by its place ("its plates 0, 1", "the next module's plate 1").
 */
final class DockReads extends ExprTree.Question {
    private final int[] ids;
    /**
     * Whose plates are read (a key of {@link DiagramMsg} and its argument), in the order first
     * read, and which plates of each.
     */
    private final Map<List<Object>, List<Integer>> reads = new LinkedHashMap<>();

    private DockReads(int[] ids) {
        super(false);
        this.ids = ids;
    }

    /** The dock readings of {@code e} on a program whose modules are {@code ids} (ascending), or "" for none. */
    static String words(Expression e, int[] ids) {
        if (e == null || e.isConstant()) {
            return "";
        }
        DockReads d = new DockReads(ids);
        ExprTree.visit(e.root(), d);
        List<String> words = new ArrayList<>();
        d.reads.forEach((whose, plates) -> words.add(((DiagramMsg) whose.get(0)).text(whose.get(1),
                Diagrams.plateWords(plates.stream().sorted().toList()))));
        return words.isEmpty() ? "" : DiagramMsg.DOCK.text(String.join(", ", words));
    }

    @Override
    public Boolean variable(String name) {
        return false;
    }

    @Override
    public Boolean globalSensor(int slot) {
        int channel = slot % Channel.count();
        int module = slot / Channel.count();
        int plate = plate(channel);
        if (plate >= 0 && module < ids.length) {
            add(DiagramMsg.DOCK_MODULE, ids[module], plate);
        }
        return false;
    }

    @Override
    public Boolean localSensor(int position, int channel) {
        int plate = plate(channel);
        if (plate >= 0) {
            add(position == ExprTree.SELF ? DiagramMsg.DOCK_ITS : position == ExprTree.PREV ? DiagramMsg.DOCK_PREVIOUS
                    : position == ExprTree.NEXT ? DiagramMsg.DOCK_NEXT : DiagramMsg.DOCK_NTH,
                    position >= 0 ? Msg.ordinal(position) : "", plate);
        }
        return false;
    }

    /** Plate {@code plate} of the module {@code whose} says ({@code {0}} its argument, {@code {1}} the plates). */
    private void add(DiagramMsg whose, Object argument, int plate) {
        List<Integer> plates = reads.computeIfAbsent(List.of(whose, String.valueOf(argument)), w -> new ArrayList<>());
        if (!plates.contains(plate)) {
            plates.add(plate);
        }
    }

    private static int plate(int channel) {
        return channel == Channel.DOCK_0.ordinal() ? 0 : channel == Channel.DOCK_1.ordinal() ? 1 : -1;
    }
}
