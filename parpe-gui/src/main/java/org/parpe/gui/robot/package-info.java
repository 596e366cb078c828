/**
 * The IDE's Robot tab (issue 33): a robot configuration built by clicks on the 3D view. Every
 * change is a {@link org.parpe.sim.build.RobotDraft} edit applied to the editor's document as
 * one Undo step, so the text stays the source; the tab re-reads the document on the
 * validator's schedule. A script's robot is shown read-only, one click from its text.
 */
package org.parpe.gui.robot;
