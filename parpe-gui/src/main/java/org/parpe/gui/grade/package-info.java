/**
 * The Class window (Run → Grade a Class…): a challenge and a folder of students' scripts graded
 * by {@link org.parpe.sim.grade.Grading} (the engine of {@code parpe grade}) on a thread of its
 * own, the ranking shown as it comes, and any student's run played back from its trace in a 3D
 * view beside that student's script. Widgets are touched on the UI thread only.
 */
package org.parpe.gui.grade;
