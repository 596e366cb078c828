/**
 * The output policy of every file PARPE writes, in one place: a command registers the files it
 * reads ({@link org.parpe.core.io.OutputPlan}), each output is checked against them and against
 * the other outputs before any work starts, and every file is written whole to a random temporary
 * name beside its target and then moved into place ({@link org.parpe.core.io.AtomicFiles}). Also
 * the CSV cell rule that keeps spreadsheets from evaluating what PARPE wrote
 * ({@link org.parpe.core.io.CsvCells}). {@code java.nio} only.
 */
package org.parpe.core.io;
