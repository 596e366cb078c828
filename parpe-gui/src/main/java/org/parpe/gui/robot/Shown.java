package org.parpe.gui.robot;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.parpe.core.edit.SectionEdits;
import org.parpe.core.model.Program;
import org.parpe.core.xml.InputFiles;
import org.parpe.core.xml.XmlReader;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.SimTarget;
import org.parpe.sim.build.RobotDraft;

/**
 * What the Robot tab shows: the robot configuration in the editor (editable; a blank document
 * is an empty one), or the robot a script runs on, read-only: its configuration file (one click
 * from the text) or a generator (which "Make editable" writes out).
 *
 * @param kind   which of these
 * @param draft  the robot, or null ({@link Kind#NOTHING})
 * @param config the configuration file ({@link Kind#FILE}), else null
 * @param spec   the generator ({@link Kind#GENERATOR}), else null
 * @param note   what the tab says of it
 */
record Shown(Kind kind, RobotDraft draft, Path config, String spec, String note) {
    /** Where the robot shown comes from. */
    enum Kind { NOTHING, EDITOR, FILE, GENERATOR }

    /** Whether the tab's edits go into the editor's document. */
    boolean editable() {
        return kind == Kind.EDITOR;
    }

    /** Whether {@code text} is a robot configuration (or blank: one to start). */
    static boolean isConfig(String text) {
        return SectionEdits.blank(text) || "robot-config".equals(XmlReader.rootName(text));
    }

    /**
     * What to show for {@code text} in the editor (file {@code file}), whose script (if it is one)
     * loaded to {@code program} (null: not yet, or it has errors) and runs on {@code choice}.
     */
    static Shown of(Path file, String text, Program program, String choice) {
        if (isConfig(text)) {
            RobotDraft d = SectionEdits.blank(text) ? RobotDraft.empty(file.toString()) : RobotDraft.of(file.toString(), text);
            return new Shown(Kind.EDITOR, d, file, null, ToolMsg.ROBOT_EDITOR_NOTE.text(file.getFileName()));
        }
        if (!SimTarget.AUTO.equals(choice) && Files.isRegularFile(Path.of(choice))) {
            return ofFile(Path.of(choice).toAbsolutePath().normalize());
        }
        String spec = SimTarget.AUTO.equals(choice) ? program == null ? null : SimTarget.autoSpec(program) : choice;
        if (spec == null) {
            return new Shown(Kind.NOTHING, null, null, null,
                    ToolMsg.ROBOT_OPEN_SOMETHING.text());
        }
        try {
            // sized by the script's modules, as a run sizes it
            RobotDraft d = RobotDraft.fromGenerator(besideScript(file).toString(), spec, program == null ? new int[0] : program.moduleIds());
            return new Shown(Kind.GENERATOR, d, null, spec,
                    ToolMsg.ROBOT_GENERATED_NOTE.text(spec, d.config().moduleIds().length));
        } catch (IllegalArgumentException e) {
            return new Shown(Kind.NOTHING, null, null, null, ToolMsg.ROBOT_CANNOT_SHOW.text(spec, e.getMessage()));
        }
    }

    /** A script's configuration file, read-only (Edit robot opens it). */
    static Shown ofFile(Path config) {
        try {
            String text = InputFiles.readText(config);
            return new Shown(Kind.FILE, RobotDraft.of(config.toString(), text), config, null,
                    ToolMsg.ROBOT_FILE_NOTE.text(config.getFileName()));
        } catch (IOException | RuntimeException e) {
            return new Shown(Kind.NOTHING, null, config, null, ToolMsg.ROBOT_CANNOT_READ.text(config, e.getMessage()));
        }
    }

    /** The file "Make editable" proposes for a script's generator: {@code NAME-robot.xml} beside it. */
    static Path besideScript(Path script) {
        String name = script.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String stem = dot > 0 ? name.substring(0, dot) : name;
        Path dir = script.toAbsolutePath().getParent();
        return (dir == null ? Path.of(".") : dir).resolve(stem + "-robot.xml");
    }
}
