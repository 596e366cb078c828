package org.parpe.gui.pose;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.gui.text.PanelMsg;

/**
 * The Pose panel's lists of poses, one set per document the editor showed (issue 23, item 10):
 * the lists of the document in the editor, by group, and which of them were changed since they
 * were last saved or written into the script, of every document, so that closing the window can
 * say which poses it would lose. A document is its path; each untitled script is one of its own.
 * UI thread only.
 */
final class PoseDocuments {
    /** The lists of the document in the editor, by group key. */
    private Map<String, PoseList> lists = new HashMap<>();
    /** Every document's lists, by its path (an untitled script: a key of its own). */
    private final Map<Object, Map<String, PoseList>> byDocument = new LinkedHashMap<>();
    private Object document = new Untitled();
    /** The poses of a list as they were when last saved or written into the script. */
    private final Map<PoseList, List<PoseList.Pose>> kept = new IdentityHashMap<>();

    /** The key of an untitled script's poses: each untitled script is a document of its own. */
    private static final class Untitled {
        @Override
        public String toString() {
            return PanelMsg.POSE_UNTITLED.text();
        }
    }

    PoseDocuments() {
        byDocument.put(document, lists);
    }

    /** The lists of the document in the editor, by group key (the panel adds to it). */
    Map<String, PoseList> lists() {
        return lists;
    }

    /**
     * Another document is in the editor ({@code file}, or null for a new untitled script): its
     * own lists from now on; false when it is the document shown already (Save As keeps the document).
     */
    boolean switchTo(Path file) {
        Object key = file == null ? new Untitled() : file.toAbsolutePath().normalize();
        if (key.equals(document)) {
            return false;
        }
        if (document instanceof Untitled && lists.values().stream().allMatch(l -> l.size() == 0)) {
            byDocument.remove(document); // an untitled script without poses leaves nothing behind
        }
        document = key;
        lists = byDocument.computeIfAbsent(key, k -> new HashMap<>());
        return true;
    }

    /** The document a Save As gave a path to keeps its poses under that path. */
    void renamed(Path file) {
        Object key = file.toAbsolutePath().normalize();
        if (!key.equals(document)) {
            byDocument.remove(document);
            Map<String, PoseList> before = byDocument.put(key, lists);
            if (before != null && before != lists) {
                before.forEach(lists::putIfAbsent);
            }
            document = key;
        }
    }

    /** Remembers that the poses of {@code list} as they are now are kept in a file or the script. */
    void markKept(PoseList list) {
        kept.put(list, list.poses());
    }

    /**
     * Lists with poses that were changed since they were last saved or written into the script,
     * of every document, as "3 poses of front in lesson.xml".
     */
    List<String> unsaved() {
        List<String> out = new ArrayList<>();
        byDocument.forEach((doc, ls) -> {
            for (PoseList l : ls.values()) {
                if (l.size() > 0 && !l.poses().equals(kept.get(l))) {
                    out.add(PanelMsg.POSE_UNSAVED_LIST.text(l.size(), l.group(),
                            doc instanceof Path p ? p.getFileName().toString() : doc.toString()));
                }
            }
        });
        return out;
    }

    /** The sentence that says which poses quitting would lose ({@link #unsaved}), or null when none. */
    String lossSentence() {
        List<String> lost = unsaved();
        return lost.isEmpty() ? null : PanelMsg.POSE_LOSS.text(String.join(", ", lost));
    }
}
