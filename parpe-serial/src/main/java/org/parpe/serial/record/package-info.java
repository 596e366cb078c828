/**
 * Posable programming from hardware (PARSL.md §12): capturing poses of a limp group of modules
 * and saving them as a PARSL gait-table recording (public API).
 */
package org.parpe.serial.record;
