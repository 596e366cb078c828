/**
 * Grading a class: a folder of students' scripts run in a challenge, each in a child JVM of its
 * own ({@link org.parpe.sim.grade.GradeChild}, started by {@link org.parpe.sim.grade.Isolation})
 * with a CPU-time and memory limit and confined to its student's folder, then ranked
 * ({@link org.parpe.sim.grade.Row}) into a CSV table ({@link org.parpe.sim.grade.Report}) and a
 * self-contained HTML page ({@link org.parpe.sim.grade.ReportPage}). {@link org.parpe.sim.grade.Grading}
 * runs a class; {@code parpe grade} and the IDE's Class window both use it, and
 * {@link org.parpe.sim.grade.Replay} plays a graded run's trace back in a simulator for the 3D view.
 */
package org.parpe.sim.grade;
