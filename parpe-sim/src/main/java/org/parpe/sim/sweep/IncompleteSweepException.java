package org.parpe.sim.sweep;

import java.util.List;
import java.util.stream.Collectors;
import org.parpe.core.text.Message;

/**
 * Shards that cannot be merged yet because some of them are missing or unfinished: the message
 * has one line per such shard, and {@link #rerun()} says which shards to run again.
 */
public final class IncompleteSweepException extends SweepException {
    private static final long serialVersionUID = 1L;

    private final transient List<Message> problems;
    private final transient List<Integer> rerun;
    private final int of;

    /**
     * Shards {@code rerun} (numbered from 1) of a split into {@code of} are missing or
     * unfinished; {@code problems} says so, one line each (at least one).
     */
    public IncompleteSweepException(List<Message> problems, List<Integer> rerun, int of) {
        super(problems.get(0));
        this.problems = List.copyOf(problems);
        this.rerun = List.copyOf(rerun);
        this.of = of;
    }

    /** One line per missing or unfinished shard, in the chosen language. */
    @Override
    public String getMessage() {
        return problems.stream().map(Message::toString).collect(Collectors.joining("\n"));
    }

    /** The shards to run again, in order. */
    public List<Integer> rerun() {
        return rerun;
    }

    /** Into how many shards the sweep was split. */
    public int of() {
        return of;
    }
}
