/*
 * PARSL embedded runtime: sine and cosine of the generated expressions and of the smooth profile
 * (issue 36 item 3). The C library's sin was 40 % of the exported program's time on a PC, a call
 * per module and tick; these are inline, and within 0.81 ulp of the exact value wherever they do
 * not call the C library, so within 2 ulps of java.lang.Math (itself within 1 ulp): the bound the
 * export states for every maths function (docs/decisions.md, MathsBoundTest).
 *
 * Written from the maths, not ported: x = k pi/2 + r with k the nearest integer to x 2/pi and
 * |r| <= pi/4; r is x - k (c1 + c2 + c3), pi/2 split into c1 and c2 of 33 significant bits (so
 * k c1 and k c2 are exact for |k| < 2^20, and x - k c1 too, its operands within a factor of two)
 * and c3 its next 53 bits; r is kept as hi + lo. Then sin x is +-sin r or +-cos r by the last two
 * bits of k, each a polynomial in z = hi^2 on [0, 0.786^2], fitted by scripts/sincos-coefficients
 * (Chebyshev fit at 60 digits, rounded to double: 2^-57 relative for sin, 2^-59 for cos), plus lo
 * times the derivative. The C library is called beyond |x| = 2^20 (a million radians: sin of
 * 2 pi $time after 46 hours), for NaN and infinities, and within 2^-10 of a multiple of pi/2
 * (k != 0), where hi + lo would need more bits of pi/2; also where double is a 32-bit float (AVR:
 * its code is what it was) or evaluated with more precision than its type (x87).
 * Included after parsl_rt.h, which tells a 32-bit double (PARSL_EXACT_TIME).
 */
#ifndef PARSL_MATHS_H
#define PARSL_MATHS_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#if defined(PARSL_EXACT_TIME) || !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#define parsl_sin sin
#define parsl_cos cos
#else

#define PARSL_2_PI 0x1.45f306dc9c883p-1
#define PARSL_PIO2_1 0x1.921fb544p+0
#define PARSL_PIO2_2 0x1.0b4611a6p-34
#define PARSL_PIO2_3 0x1.3198a2e037073p-69
/* 1.5 * 2^52: x + it rounds x to an integer, which its low bits then hold */
#define PARSL_ROUNDER 0x1.8p52

/* x - k pi/2 as hi + lo and k's last two bits in *q; 0 where the C library must compute instead. */
static inline int parsl_reduce(double x, double *hi, double *lo, uint32_t *q)
{
    double n;
    double k;
    double a;
    double b;
    double h;
    uint64_t bits;
    if (!(fabs(x) <= 0x1p20)) {
        return 0;
    }
    n = x * PARSL_2_PI + PARSL_ROUNDER;
    k = n - PARSL_ROUNDER;
    memcpy(&bits, &n, sizeof bits);
    *q = (uint32_t) bits;
    a = x - k * PARSL_PIO2_1;
    b = k * PARSL_PIO2_2;
    h = a - b;
    if (fabs(h) < 0x1p-10 && k != 0) {
        return 0;
    }
    *hi = h;
    *lo = ((a - h) - b) - k * PARSL_PIO2_3; /* |a| > |b| here, so (a - h) - b is a - b's rounding error */
    return 1;
}

/* sin(hi + lo) for |hi| <= 0.786: the polynomial at hi, plus lo cos(hi) */
static inline double parsl_sin_poly(double hi, double lo)
{
    double z = hi * hi;
    double z2 = z * z;
    double p = (-0x1.5555555555555p-3 + z * 0x1.1111111111110p-7)
            + z2 * ((-0x1.a01a01a01992ap-13 + z * 0x1.71de3a545ef0dp-19)
            + z2 * (-0x1.ae64540feaf6dp-26 + z * 0x1.61217cc913f00p-33 + z2 * -0x1.ab167f4fb1867p-41));
    return hi + (hi * z * p + lo * (1.0 - 0.5 * z + z2 * 0x1.5555555555555p-5));
}

/* cos(hi + lo) for |hi| <= 0.786: 1 - z/2 with its rounding error carried, the polynomial, less lo sin(hi) */
static inline double parsl_cos_poly(double hi, double lo)
{
    double z = hi * hi;
    double z2 = z * z;
    double p = (0x1.5555555555555p-5 + z * -0x1.6c16c16c16962p-10)
            + z2 * ((0x1.a01a019f4d709p-16 + z * -0x1.27e4fa163c142p-22)
            + z2 * (0x1.1eeb673a2e0cap-29 + z * -0x1.907c6d159beaap-37));
    double hz = 0.5 * z;
    double w = 1.0 - hz;
    return w + (((1.0 - w) - hz) + (z2 * p - hi * lo * (1.0 - z * 0x1.5555555555555p-3)));
}

/* sin or cos of the quadrant q: the polynomial of r, its sign */
static inline double parsl_quadrant(uint32_t q, double hi, double lo)
{
    double v = (q & 1) ? parsl_cos_poly(hi, lo) : parsl_sin_poly(hi, lo);
    return (q & 2) ? -v : v;
}

/* inline where it is called: gcc would otherwise call a part of it out of line, for a twentieth of
   a module's tick more */
#if defined(__GNUC__)
#define PARSL_INLINE static inline __attribute__((always_inline))
#else
#define PARSL_INLINE static inline
#endif

PARSL_INLINE double parsl_sin(double x)
{
    double hi;
    double lo;
    uint32_t q;
    if (fabs(x) < 0x1p-26) {
        return x; /* sin x rounds to x, and -0 stays -0 */
    }
    return parsl_reduce(x, &hi, &lo, &q) ? parsl_quadrant(q, hi, lo) : sin(x);
}

PARSL_INLINE double parsl_cos(double x)
{
    double hi;
    double lo;
    uint32_t q;
    return parsl_reduce(x, &hi, &lo, &q) ? parsl_quadrant(q + 1, hi, lo) : cos(x);
}
#endif

#endif
