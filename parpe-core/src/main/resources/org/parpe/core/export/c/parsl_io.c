/*
 * PARSL embedded runtime: text in and out. Control and sensor assignments (the serial
 * commands of a board, the lines of a stimulus file), the trace number format, and the
 * wording of run-time errors.
 */
#include "parsl_rt.h"
#include <math.h>
#include <string.h>
#include <stdlib.h>
#include <stdio.h>

/* Texts stay in flash on AVR, where string literals would otherwise be copied to RAM. */
#if defined(__AVR__)
#define TXT(s) PSTR(s)
#define SAME(s, word) (strcmp_P((s), PSTR(word)) == 0)
#define FORMAT(buf, n, fmt, ...) snprintf_P((buf), (n), PSTR(fmt), __VA_ARGS__)
#define TEXT_ARG "%S"
#else
#define TXT(s) (s)
#define SAME(s, word) (strcmp((s), (word)) == 0)
#define FORMAT(buf, n, fmt, ...) snprintf((buf), (n), fmt, __VA_ARGS__)
#define TEXT_ARG "%s"
#endif

/* The channel named by a sensor reference's suffix ("touch_left"), or PARSL_CHANNELS. */
static int16_t channel_of(const char *c)
{
    if (SAME(c, "angle")) {
        return PARSL_ANGLE;
    } else if (SAME(c, "accel_x")) {
        return PARSL_ACCEL_X;
    } else if (SAME(c, "accel_y")) {
        return PARSL_ACCEL_Y;
    } else if (SAME(c, "accel_z")) {
        return PARSL_ACCEL_Z;
    } else if (SAME(c, "touch_left")) {
        return PARSL_TOUCH_LEFT;
    } else if (SAME(c, "touch_right")) {
        return PARSL_TOUCH_RIGHT;
    }
    return PARSL_CHANNELS;
}

#ifndef PARSL_NO_NAMES
/* One-argument functions, in the order of org.parpe.core.export.CExpressions.FUNCTIONS. */
static const char *const FUNCTIONS[] = {
    "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "log", "ln",
    "exp", "sqrt", "abs", "round", "floor", "ceil", "rad", "deg"
};
#endif

static int fail(char *msg, size_t n, const char *what, const char *name)
{
    if (msg != NULL && n > 0) {
        FORMAT(msg, n, TEXT_ARG " '%s'", what, name);
    }
    return -1;
}

/* A plain decimal number as the interpreter reads one (Numbers.parsePlain): digits, one '.', sign, exponent. */
static int number(const char *s, double *out)
{
    char *end;
    const char *c = s;
    if (*c == '+' || *c == '-') {
        c++;
    }
    if (!((*c >= '0' && *c <= '9') || *c == '.')) {
        return -1;
    }
    for (; *c != '\0'; c++) {
        if (!((*c >= '0' && *c <= '9') || *c == '.' || *c == 'e' || *c == 'E' || *c == '+' || *c == '-')) {
            return -1;
        }
    }
    *out = strtod(s, &end);
    return *end == '\0' && isfinite(*out) ? 0 : -1;
}

static int sensor(parsl_rt *r, const char *name, const char *value, char *msg, size_t n)
{
    long id = 0;
    const char *c = name;
    int16_t ch;
    int16_t lo = 0;
    int16_t hi = PARSL_N - 1;
    double v;
    for (; *c >= '0' && *c <= '9'; c++) {
        id = id * 10 + (*c - '0');
        if (id > 65535) {
            return fail(msg, n, TXT("no module"), name);
        }
    }
    if (c == name || *c != '_') {
        return fail(msg, n, TXT("unknown control or sensor"), name);
    }
    c++;
    ch = channel_of(c);
    if (ch == PARSL_CHANNELS) {
        return fail(msg, n, TXT("not a sensor reading (angle, accel_x|y|z, touch_left|right)"), name);
    }
    while (lo <= hi) {
        int16_t mid = (int16_t) ((lo + hi) / 2);
        long at = (long) PARSL_U16(parsl_ids, mid);
        if (at == id) {
            int16_t slot = PARSL_I16(parsl_slot, mid * PARSL_CHANNELS + ch);
            if (slot < 0) {
                return fail(msg, n, TXT("the module does not carry this sensor"), name);
            }
            if (number(value, &v) != 0) {
                return fail(msg, n, TXT("the value must be a number, got"), value);
            }
            r->over[slot] = v;
            return 0;
        }
        if (at < id) {
            lo = (int16_t) (mid + 1);
        } else {
            hi = (int16_t) (mid - 1);
        }
    }
    return fail(msg, n, TXT("the robot has no module"), name);
}

int parsl_assign(parsl_rt *r, const char *text, char *msg, size_t n)
{
    char name[40];
    const char *eq = strchr(text, '=');
    const char *value;
    size_t len;
    int16_t c;
    double v;
    if (*text == '$') {
        text++;
    }
    if (eq == NULL || eq == text || (size_t) (eq - text) >= sizeof name) {
        return fail(msg, n, TXT("expected '$NAME=VALUE', got"), text);
    }
    len = (size_t) (eq - text);
    while (len > 0 && (text[len - 1] == ' ' || text[len - 1] == '\t')) {
        len--;
    }
    memcpy(name, text, len);
    name[len] = '\0';
    value = eq + 1;
    while (*value == ' ' || *value == '\t') {
        value++;
    }
    c = parsl_control_index(name);
    if (c < 0) {
        return sensor(r, name, value, msg, n);
    }
    if (PARSL_I16(parsl_control[c], PARSL_C_TYPE) == PARSL_CT_RADIO) {
        int16_t code = parsl_word_code(value);
        int16_t first = PARSL_I16(parsl_control[c], PARSL_C_WORDS);
        int16_t i;
        for (i = 0; i < PARSL_I16(parsl_control[c], PARSL_C_NWORDS); i++) {
            if (code >= 0 && PARSL_I16(parsl_words, first + i) == code) {
                r->controls[c] = code;
                return 0;
            }
        }
        return fail(msg, n, TXT("the radio control has no such word"), value);
    }
    if (number(value, &v) != 0) {
        return fail(msg, n, TXT("the value must be a number, got"), value);
    }
    if (PARSL_I16(parsl_control[c], PARSL_C_TYPE) == PARSL_CT_SLIDER
            && (v < PARSL_DBL(parsl_control_range[c], 0) || v > PARSL_DBL(parsl_control_range[c], 1))) {
        return fail(msg, n, TXT("the value is outside the slider's range"), value);
    }
    r->controls[c] = v;
    return 0;
}

int parsl_format(char *buf, double v)
{
    /* the algorithm of org.parpe.core.run.TraceWriter.format: exact, half-even, -0 as 0 */
    double a = fabs(v);
    long long ip;
    double f;
    long long m;
    double tie;
    int len = 0;
    long long d;
    char digits[24];
    int nd = 0;
    if (!(a < 0x1p63)) {
        return snprintf(buf, PARSL_FORMAT_MAX, "%.6f", v);
    }
    ip = (long long) a;
    f = a - (double) ip;
    m = (long long) (f * 1e6);
    if (fma(f, 1e6, (double) -m) < 0) {
        m--;
    }
    tie = fma(f, 1e6, -((double) m + 0.5));
    if (tie > 0 || (tie == 0 && (m & 1) == 1)) {
        m++;
    }
    if (m == 1000000) {
        ip++;
        m = 0;
    }
    if (v < 0 && (ip != 0 || m != 0)) {
        buf[len++] = '-';
    }
    do {
        digits[nd++] = (char) ('0' + ip % 10);
        ip /= 10;
    } while (ip > 0);
    while (nd > 0) {
        buf[len++] = digits[--nd];
    }
    buf[len++] = '.';
    for (d = 100000; d > 0; d /= 10) {
        buf[len++] = (char) ('0' + m / d % 10);
    }
    buf[len] = '\0';
    return len;
}

#ifndef PARSL_NO_NAMES
/*
 * A number in an error text as parpe run writes it (org.parpe.core.lang.Numbers.brief): rounded half up
 * to 6 significant digits, trailing zeros dropped, positional notation, Java's names of the non-finite
 * values. The exact decimal expansion glibc prints gives the digits and the rounding.
 */
typedef struct {
    char s[340];
} brief_text;

static brief_text brief(double v)
{
    brief_text out;
    char e[64];
    char d[7];
    const char *p;
    int exp;
    int nd = 6;
    int len = 0;
    int i;
    if (isnan(v) || isinf(v)) {
        snprintf(out.s, sizeof out.s, "%s", isnan(v) ? "NaN" : v > 0 ? "Infinity" : "-Infinity");
        return out;
    }
    if (v == 0) {
        snprintf(out.s, sizeof out.s, "0");
        return out;
    }
    snprintf(e, sizeof e, "%.40e", v);
    p = e[0] == '-' ? e + 1 : e;
    d[0] = p[0];
    memcpy(d + 1, p + 2, 5);
    exp = atoi(strchr(p, 'e') + 1);
    if (p[7] >= '5') {
        for (i = 5; i >= 0 && d[i] == '9'; i--) {
            d[i] = '0';
        }
        if (i < 0) {
            d[0] = '1';
            exp++;
        } else {
            d[i]++;
        }
    }
    while (nd > 1 && d[nd - 1] == '0') {
        nd--;
    }
    if (v < 0) {
        out.s[len++] = '-';
    }
    if (exp < 0) {
        out.s[len++] = '0';
        out.s[len++] = '.';
        for (i = 0; i < -exp - 1; i++) {
            out.s[len++] = '0';
        }
        for (i = 0; i < nd; i++) {
            out.s[len++] = d[i];
        }
    } else {
        for (i = 0; i <= exp; i++) {
            out.s[len++] = i < nd ? d[i] : '0';
        }
        if (nd > exp + 1) {
            out.s[len++] = '.';
            for (i = exp + 1; i < nd; i++) {
                out.s[len++] = d[i];
            }
        }
    }
    out.s[len] = '\0';
    return out;
}
#endif

const char *parsl_error_text(const parsl_rt *r, char *msg, size_t n)
{
#ifdef PARSL_NO_NAMES
    FORMAT(msg, n, "run-time error %d", (int) r->err_code);
#else
    const char *aut = r->err_code >= PARSL_E_PERIOD && r->err_code != PARSL_E_NEGATIVE ? parsl_aut_names[r->err_what] : "";
    switch (r->err_code) {
    case PARSL_E_DIV: snprintf(msg, n, "division by zero"); break;
    case PARSL_E_REM: snprintf(msg, n, "remainder of a division by zero"); break;
    case PARSL_E_MODF: snprintf(msg, n, "mod() by zero"); break;
    case PARSL_E_SUM: snprintf(msg, n, "a sum is not a finite number"); break;
    case PARSL_E_DIFF: snprintf(msg, n, "a difference is not a finite number"); break;
    case PARSL_E_PROD: snprintf(msg, n, "a product is not a finite number"); break;
    case PARSL_E_QUOT: snprintf(msg, n, "a quotient is not a finite number"); break;
    case PARSL_E_POW: snprintf(msg, n, "%s^%s is not a finite number", brief(r->err_a).s, brief(r->err_b).s); break;
    case PARSL_E_FUNC: snprintf(msg, n, "%s() of %s is not a finite number", FUNCTIONS[r->err_what], brief(r->err_a).s); break;
    case PARSL_E_SUMF: snprintf(msg, n, "sum() is not a finite number"); break;
    case PARSL_E_VALUE: snprintf(msg, n, "the value %s is not a finite number", brief(r->err_a).s); break;
    case PARSL_E_PERIOD: snprintf(msg, n, "period of automaton '%s' must be > 0, got %s", aut, brief(r->err_a).s); break;
    case PARSL_E_TOTAL:
        snprintf(msg, n, "the states of automaton '%s' last %s s in total; the total must be > 0", aut,
                 brief(r->err_a).s);
        break;
    case PARSL_E_NEGATIVE: {
        int16_t a = 0;
        while (a + 1 < PARSL_NA && PARSL_I16(parsl_aut[a + 1], PARSL_A_STATES) <= r->err_what) {
            a++;
        }
        snprintf(msg, n, "state '%s' of automaton '%s' has a negative duration: %s s (durations must be >= 0)",
                 parsl_state_names[r->err_what], parsl_aut_names[a], brief(r->err_a).s);
        break;
    }
    case PARSL_E_ALLZERO: snprintf(msg, n, "every state of automaton '%s' has a duration <= 0", aut); break;
    default:
        snprintf(msg, n, "automaton '%s' makes more than 10000 state changes in one tick; its states are far shorter"
                 " than the tick (%s s)", aut, brief(PARSL_DT).s);
        break;
    }
#endif
#ifndef PARSL_NO_NAMES
    if (r->err_code < PARSL_E_PERIOD) {
        size_t used = strlen(msg);
        snprintf(msg + used, n - used, " in '%s'", parsl_expr_text[r->err_pos]);
    }
#endif
    return msg;
}
