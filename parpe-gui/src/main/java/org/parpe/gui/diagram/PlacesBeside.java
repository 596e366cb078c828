package org.parpe.gui.diagram;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.Collection;
import java.util.function.Consumer;
import org.parpe.core.diagram.NodePlaces;
import org.parpe.core.io.IoReasons;
import org.parpe.core.io.AtomicFiles;
import org.parpe.gui.text.PanelMsg;

/**
 * The places of the open script's free nodes ({@link NodePlaces}), kept beside the script in
 * {@code SCRIPT.layout} (for {@code walk.xml}: {@code walk.xml.layout}), never inside it. Read
 * when a document is shown, written through {@link AtomicFiles} each time a node is put down.
 * A file of that name that is not a PARPE layout file is never written over; an untitled
 * document, or a folder that cannot be written, keeps its places only while the IDE is open;
 * each of these is said once. Reading never throws. UI thread only.
 */
final class PlacesBeside {
    /** Larger than any layout of a script: a file this large is not one. */
    static final long MAX_BYTES = 1 << 20;

    private Consumer<String> say;
    private Path script;
    private NodePlaces places = NodePlaces.NONE;
    /** Whether the layout file may be written (it is absent, or ours). */
    private boolean ours = true;
    /** Why the layout file is not ours, said at the first place put (when it would have been written), or {@code ""}. */
    private String notOurs = "";
    /** Whether a failed write was said already (once per document). */
    private boolean toldCannotWrite;

    /** Places that say what they cannot read or write with {@code say}. */
    PlacesBeside(Consumer<String> say) {
        this.say = say;
    }

    /** Says from now on with {@code s} (the IDE's status bar). */
    void sayWith(Consumer<String> s) {
        say = s;
    }

    /** The layout file of {@code script}. */
    static Path of(Path script) {
        return script.resolveSibling(script.getFileName() + ".layout");
    }

    /** The places now. */
    NodePlaces places() {
        return places;
    }

    /** The script whose places these are, or {@code null} for an untitled document. */
    Path script() {
        return script;
    }

    /** Another document is shown ({@code file}, or {@code null} untitled): its places are read from beside it. */
    void documentSwitched(Path file) {
        script = file == null ? null : file.toAbsolutePath().normalize();
        toldCannotWrite = false;
        places = NodePlaces.NONE;
        ours = true;
        notOurs = "";
        if (script != null) {
            NodePlaces.Read r = read(of(script));
            places = r.places();
            ours = r.ours();
            if (!ours) {
                notOurs = r.message();
            } else if (!r.message().isEmpty()) {
                say.accept(r.message());
            }
        }
    }

    /**
     * The document was saved as {@code file} (Save As, or the first Save of an untitled one):
     * its places go beside the new file, unless a file there is not ours.
     */
    void documentRenamed(Path file) {
        Path to = file.toAbsolutePath().normalize();
        if (to.equals(script)) {
            return;
        }
        script = to;
        toldCannotWrite = false;
        notOurs = "";
        NodePlaces.Read there = read(of(to));
        ours = there.ours();
        if (!ours) {
            say.accept(there.message());
        } else if (!places.isEmpty()) {
            write();
        }
    }

    /**
     * {@code name} of {@code view} was put at {@code x, y} of its workbench; only the places of
     * {@code free} (the view's free nodes now) are kept. Written beside the script at once.
     */
    void put(String view, String name, double x, double y, Collection<String> free) {
        places = places.with(view, name, x, y).retain(view, free);
        write();
    }

    private void write() {
        if (script == null) {
            return;
        }
        Path file = of(script);
        // another program may have put a file there since it was read
        NodePlaces.Read now = ours ? read(file) : null;
        if (now != null && !now.ours()) {
            ours = false;
            notOurs = now.message();
        }
        if (!ours) {
            if (!notOurs.isEmpty()) {
                say.accept(notOurs);
                notOurs = "";
            }
            return;
        }
        try {
            AtomicFiles.write(file, places.format());
        } catch (IOException | RuntimeException e) {
            if (!toldCannotWrite) {
                toldCannotWrite = true;
                say.accept(PanelMsg.DIAGRAM_CANNOT_WRITE_LAYOUT.text(file, e.getMessage()));
            }
        }
    }

    /** Reads the layout file {@code file}: none when absent; never throws. */
    static NodePlaces.Read read(Path file) {
        if (!Files.exists(file, LinkOption.NOFOLLOW_LINKS)) {
            return new NodePlaces.Read(NodePlaces.NONE, true, "");
        }
        try {
            if (!Files.isRegularFile(file) || Files.size(file) > MAX_BYTES) {
                return new NodePlaces.Read(NodePlaces.NONE, false, PanelMsg.DIAGRAM_NOT_A_LAYOUT.text(file));
            }
            return NodePlaces.parse(file.toString(), new String(Files.readAllBytes(file), StandardCharsets.UTF_8));
        } catch (IOException | RuntimeException e) {
            return new NodePlaces.Read(NodePlaces.NONE, false,
                    PanelMsg.DIAGRAM_CANNOT_READ_LAYOUT.text(file, IoReasons.of(e)));
        }
    }
}
