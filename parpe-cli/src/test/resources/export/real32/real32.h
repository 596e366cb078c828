/*
 * Included before every file of an exported program (gcc -include real32.h
 * -fsingle-precision-constant) to compile it on a PC as an AVR compiles it: there `double` is a
 * 32-bit float, in variables and in constants. The C library is declared first, with its real
 * types, so that sin() and the others still compute in double and round their results to float
 * (avr-libc computes them in float; the long-run test measures time keeping, not those last bits).
 * PARSL_REAL32 selects the runtime's exact time keeping, as __SIZEOF_DOUBLE__ == 4 does on AVR.
 */
#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define PARSL_REAL32 1
#define double float
