package org.parpe.sim.build;

import java.util.ArrayDeque;
import java.util.Deque;

/**
 * Undo and redo for a robot builder: one step per applied edit, each the text before and after
 * it with the edit's description. Pushing a step clears what could be redone. Not thread-safe:
 * a builder uses it from its UI thread.
 */
public final class BuildHistory {
    private record Step(String before, String after, String description) {
    }

    private final Deque<Step> undo = new ArrayDeque<>();
    private final Deque<Step> redo = new ArrayDeque<>();

    /** Records an applied edit that turned {@code before} into {@code after}. */
    public void push(String before, String after, String description) {
        undo.push(new Step(before, after, description));
        redo.clear();
    }

    /** Whether there is an edit to undo. */
    public boolean canUndo() {
        return !undo.isEmpty();
    }

    /** Whether there is an undone edit to redo. */
    public boolean canRedo() {
        return !redo.isEmpty();
    }

    /** Undoes the last edit: returns the text before it. */
    public String undo() {
        if (undo.isEmpty()) {
            throw new IllegalStateException("nothing to undo");
        }
        Step s = undo.pop();
        redo.push(s);
        return s.before();
    }

    /** Redoes the last undone edit: returns the text after it. */
    public String redo() {
        if (redo.isEmpty()) {
            throw new IllegalStateException("nothing to redo");
        }
        Step s = redo.pop();
        undo.push(s);
        return s.after();
    }

    /** The description of the edit {@link #undo} would undo (a menu shows "Undo " before it), or null when there is none. */
    public String undoLabel() {
        return undo.isEmpty() ? null : undo.peek().description();
    }

    /** The description of the edit {@link #redo} would redo, or null when there is none. */
    public String redoLabel() {
        return redo.isEmpty() ? null : redo.peek().description();
    }

    /** Forgets every step (another file was opened). */
    public void clear() {
        undo.clear();
        redo.clear();
    }
}
