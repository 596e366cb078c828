/**
 * {@code parpe grade}: the command line of class grading; the grading itself (isolation,
 * confinement, ranking, the report) is {@link org.parpe.sim.grade}, shared with the IDE.
 */
package org.parpe.cli.grade;
