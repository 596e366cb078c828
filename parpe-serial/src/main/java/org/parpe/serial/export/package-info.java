/**
 * The export of a program to C and to Arduino sketches, in one place for {@code parpe export}
 * and the IDE ({@link org.parpe.serial.export.ProgramExport}): the translation and the C runtime
 * are core's ({@code org.parpe.core.export}, pure text); this package adds what needs the servo
 * models of {@code org.parpe.serial.servo}: the sketch's options and the cost its servo driver
 * adds on a board, the servo constants of {@code parsl_servo.h}, the {@code .ino} and the board
 * code it appends ({@code sketch.inc}, a resource here). Numbers the board code and the cost model
 * share are declared once ({@code SketchConstants}) and generated into {@code parsl_servo.h}.
 */
package org.parpe.serial.export;
