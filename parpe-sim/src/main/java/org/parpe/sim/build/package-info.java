/**
 * Building robots (public API): a robot configuration being built, edit by edit, as a robot
 * builder (the IDE's Robot tab) does it.
 *
 * <ul>
 * <li>{@link org.parpe.sim.build.RobotDraft} is one state of a configuration: its text, what
 *     it reads as ({@link org.parpe.sim.config.RobotConfig}), its located problems, the robot
 *     assembled at rest (bodies and free plates, for drawing and clicking), and the edits a
 *     builder offers (add a part on a free plate, remove, turn, set an ID, an angle, limp, make
 *     the root, close a loop, number the modules).</li>
 * <li>Every edit is a {@link org.parpe.sim.build.BuildEdit}: a {@link org.parpe.core.edit.TextEdit}
 *     of the edit layer on the draft's text with a line for the Undo menu, or a refusal saying
 *     why. The text is the source; the draft after an edit is read again from the edited text
 *     ({@link org.parpe.sim.build.RobotDraft#apply}).</li>
 * <li>{@link org.parpe.sim.build.BuildHistory} keeps undo and redo, one step per edit.</li>
 * <li>{@link org.parpe.sim.build.ScriptFit} compares a robot with a script's modules and groups.</li>
 * </ul>
 *
 * Nothing here draws or touches files: a builder reads and writes the file, draws the bodies,
 * and runs drafts on a worker thread (a draft is immutable).
 */
package org.parpe.sim.build;
