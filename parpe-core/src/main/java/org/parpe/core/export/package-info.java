/**
 * Translation of a loaded PARSL program into portable C99 (public API): expression trees to C
 * functions, the behaviors, automata and states to constant tables for the embedded runtime, and
 * a RAM/flash estimate per target. Pure: writes no files; the command line adds the runtime and
 * writes the folder.
 */
package org.parpe.core.export;
