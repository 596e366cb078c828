/**
 * {@code parpe grade}: a class's scripts run in a challenge, each in a child JVM of its own
 * ({@link org.parpe.cli.grade.GradeChild}) with a CPU-time and memory limit and confined to its
 * student's folder, then ranked into a CSV table and a self-contained HTML page.
 */
package org.parpe.cli.grade;
