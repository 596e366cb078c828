/*
 * PARSL embedded runtime: the scheduler (PARSL.md sections 7, 11, 13), a line-by-line port of
 * PARPE's org.parpe.core.run.Engine so that the trace is the interpreter's, bit for bit: the
 * same operations on doubles in the same order. Instances are in parsl_inst.c. Where double is a
 * 32-bit float (PARSL_EXACT_TIME, parsl_rt.h) the clock is counted in integers instead.
 */
#include "parsl_inst.h"
#include <math.h>
#include <string.h>
#include <stdlib.h>
#include <stdio.h>
#include <limits.h>

#define EPS 1e-9

#ifdef PARSL_EXACT_TIME
/*
 * s + f / PARSL_DT_DEN seconds as a float: within half a unit in its last place plus 2^-23 s (the
 * fraction is multiplied by the rounded reciprocal, a third of the time a division takes on AVR).
 */
static double seconds(uint32_t s, uint32_t f)
{
    return (double) s + (double) f * (1.0 / PARSL_DT_DEN);
}
#endif

/* Counts one more tick and sets $time. */
static void count_tick(parsl_rt *r)
{
#ifdef PARSL_EXACT_TIME
    if (r->tick >= 0) {
        r->now.s += PARSL_DT_S;
        r->now.f += PARSL_DT_F;
        if (r->now.f >= PARSL_DT_DEN) {
            r->now.f -= PARSL_DT_DEN;
            r->now.s++;
        }
    }
    if (r->tick < LONG_MAX) {
        r->tick++; /* beyond, only "not the first tick" matters */
    }
    r->time = seconds(r->now.s, r->now.f);
#else
    r->tick++;
    r->time = r->tick * PARSL_DT;
#endif
}

/* $btime: the time since the running main entry started. */
static double behavior_time(const parsl_rt *r)
{
#ifdef PARSL_EXACT_TIME
    uint32_t s = r->now.s - r->entry_start.s;
    uint32_t f = r->now.f;
    if (f < r->entry_start.f) {
        f += PARSL_DT_DEN;
        s--;
    }
    return seconds(s, f - r->entry_start.f);
#else
    return r->tick * PARSL_DT - r->entry_start * PARSL_DT;
#endif
}

void parsl_raise(parsl_rt *r, int16_t code, double a, double b, int16_t what)
{
    r->err_code = code;
    r->err_pos = r->cur_x;
    r->err_a = a;
    r->err_b = b;
    r->err_what = what;
    longjmp(r->fail, 1);
}

double parsl_eval(parsl_rt *r, int16_t x)
{
    double v;
    r->cur_x = x;
    v = parsl_expr(r, x);
    if (!isfinite(v)) {
        parsl_raise(r, PARSL_E_VALUE, v, 0, 0);
    }
    return v;
}

static double eval_or(parsl_rt *r, int16_t x, double fallback)
{
    return x < 0 ? fallback : parsl_eval(r, x);
}

double parsl_rand(parsl_rt *r)
{
    /* java.util.SplittableRandom(seed).nextDouble() */
    uint64_t z = (r->seed += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z = z ^ (z >> 31);
    return (double) (z >> 11) * 0x1.0p-53;
}

double parsl_min(double a, double b)
{
    if (a != a) {
        return a;
    }
    if (a == 0.0 && b == 0.0 && signbit(b)) {
        return b;
    }
    return a <= b ? a : b;
}

double parsl_max(double a, double b)
{
    if (a != a) {
        return a;
    }
    if (a == 0.0 && b == 0.0 && signbit(a)) {
        return b;
    }
    return a >= b ? a : b;
}

double parsl_local(parsl_rt *r, int16_t position, int16_t channel)
{
    int16_t n = r->group_n;
    int16_t p;
    int16_t slot;
    if (position == -1) {
        p = r->index;
    } else if (position == -2) {
        p = (int16_t) ((r->index - 1 + n) % n);
    } else if (position == -3) {
        p = (int16_t) ((r->index + 1) % n);
    } else {
        p = position;
    }
    slot = PARSL_I16(parsl_slot, PARSL_I16(parsl_inst_mod, r->group_off + p) * PARSL_CHANNELS + channel);
    return slot < 0 ? 0 : r->sens[slot];
}

void parsl_init(parsl_rt *r, uint64_t seed, parsl_read_fn read)
{
    int16_t i;
    memset(r, 0, sizeof *r);
    r->seed = seed;
    r->read = read;
    r->entry = -1;
    r->tick = -1;
    for (i = 0; i < PARSL_NC; i++) {
        r->controls[i] = PARSL_DBL(parsl_control_init, i);
    }
    for (i = 0; i < PARSL_NS1; i++) {
        r->over[i] = NAN;
    }
}

void parsl_set_reading(parsl_rt *r, int16_t i, int16_t channel, double value)
{
    int16_t slot = PARSL_I16(parsl_slot, i * PARSL_CHANNELS + channel);
    if (slot >= 0) {
        r->sens[slot] = value;
    }
    if (channel == PARSL_ANGLE && r->tick == 0) {
        r->commanded[i] = value;
    }
}
/* ---- the scheduler (Engine) ---- */

static int conditions_hold(parsl_rt *r, int16_t row)
{
    int16_t first = PARSL_I16(parsl_inst[row], PARSL_I_COND);
    int16_t n = PARSL_I16(parsl_inst[row], PARSL_I_NCOND);
    int16_t i;
    for (i = 0; i < n; i++) {
        if (parsl_eval(r, PARSL_I16(parsl_cond, first + i)) == 0) {
            return 0;
        }
    }
    return 1;
}

static void run_instances(parsl_rt *r)
{
    int16_t first = PARSL_I16(parsl_entry[r->entry], PARSL_E_FIRST);
    int16_t count = PARSL_I16(parsl_entry[r->entry], PARSL_E_NINST);
    int16_t i;
    int16_t k;
    /* r->btime is this tick's: set by entry_ends, or 0 by start_entry */
    for (i = 0; i < count; i++) {
        inst_view v;
        int active;
        int16_t row = (int16_t) (first + i);
        parsl_view(r, i, row, &v);
        if (v.is->started && v.is->finished == v.n) {
            continue;
        }
        active = conditions_hold(r, row);
        r->count = v.n;
        if (!v.is->started) {
            double phase;
            double offset;
            if (r->btime < eval_or(r, PARSL_I16(parsl_inst[row], PARSL_I_START), 0) - EPS) {
                continue;
            }
            phase = eval_or(r, PARSL_I16(parsl_inst[row], PARSL_I_PHASE), 0);
            offset = eval_or(r, PARSL_I16(parsl_inst[row], PARSL_I_OFFSET), 0);
            parsl_inst_init(r, &v, phase, offset, eval_or(r, PARSL_I16(parsl_inst[row], PARSL_I_CYCLES), INFINITY));
            v.is->was_active = (uint8_t) active;
            if (active) {
                for (k = 0; k < v.n; k++) {
                    if (!r->fin[v.pool + k]) {
                        parsl_hold(r, &v, k);
                        parsl_drive(r, &v, k);
                    }
                }
            }
            continue;
        }
        if (!active) {
            v.is->was_active = 0;
            continue;
        }
        if (!v.is->was_active) {
            parsl_reanchor(r, &v);
            v.is->was_active = 1;
        }
        parsl_prepare_tick(r, &v);
#ifdef PARSL_FAST
        if (parsl_fast(r, &v)) {
            continue;
        }
#endif
        for (k = 0; k < v.n; k++) {
            if (!r->fin[v.pool + k]) {
                parsl_advance(r, &v, k, PARSL_DT);
                parsl_drive(r, &v, k);
            }
        }
    }
}

static void start_entry(parsl_rt *r, int16_t index)
{
    int16_t first = PARSL_I16(parsl_entry[index], PARSL_E_VARGS);
    int16_t n = PARSL_I16(parsl_entry[index], PARSL_E_NVARGS);
    int16_t i;
    r->entry = index;
#ifdef PARSL_EXACT_TIME
    r->entry_start = r->now;
#else
    r->entry_start = r->tick;
#endif
    r->btime = 0;
    for (i = 0; i < n; i++) {
        r->macros[PARSL_I16(parsl_varg[first + i], PARSL_V_SLOT)] =
                parsl_eval(r, PARSL_I16(parsl_varg[first + i], PARSL_V_EXPR));
    }
    for (i = 0; i < PARSL_I16(parsl_entry[index], PARSL_E_NINST); i++) {
        r->inst[i].started = 0;
        r->inst[i].was_active = 0;
    }
    run_instances(r);
}

static int entry_ends(parsl_rt *r)
{
    int16_t e = r->entry;
    int16_t tx = PARSL_I16(parsl_entry[e], PARSL_E_TIME);
    int16_t xx = PARSL_I16(parsl_entry[e], PARSL_E_EXIT);
    int16_t n = PARSL_I16(parsl_entry[e], PARSL_E_NINST);
    int16_t first = PARSL_I16(parsl_entry[e], PARSL_E_FIRST);
    int time_up;
    int ex;
    int16_t i;
    r->btime = behavior_time(r);
    /* both are evaluated on every tick (PARSL.md section 13 rule 4) */
    time_up = tx >= 0 && r->btime >= parsl_eval(r, tx) - EPS;
    ex = xx >= 0 && parsl_eval(r, xx) != 0;
    if (time_up || ex) {
        return 1;
    }
    if (n == 0) {
        return 0;
    }
    for (i = 0; i < n; i++) {
        if (!(r->inst[i].started && r->inst[i].finished == PARSL_I16(parsl_inst[first + i], PARSL_I_N))) {
            return 0;
        }
    }
    return 1;
}

static void next_entry(parsl_rt *r)
{
    int16_t next = (int16_t) (r->entry + 1);
    if (next >= PARSL_NE) {
        r->main_cycle++;
        if (PARSL_MAIN_CYCLES >= 0 && r->main_cycle >= PARSL_MAIN_CYCLES) {
            r->ended = 1;
            return;
        }
        next = 0;
    }
    start_entry(r, next);
}

static void read_inputs(parsl_rt *r)
{
    int16_t i;
    if (r->read != NULL) {
        r->read(r);
    } else {
        for (i = 0; i < PARSL_N; i++) {
            int16_t slot = PARSL_I16(parsl_slot, i * PARSL_CHANNELS + PARSL_ANGLE);
            if (slot >= 0) {
                r->sens[slot] = r->commanded[i];
            }
        }
    }
    for (i = 0; i < PARSL_NS; i++) {
        if (!isnan(r->over[i])) {
            r->sens[i] = r->over[i];
        }
    }
    if (r->tick == 0 && r->read != NULL) {
        for (i = 0; i < PARSL_N; i++) {
            int16_t slot = PARSL_I16(parsl_slot, i * PARSL_CHANNELS + PARSL_ANGLE);
            if (slot >= 0) {
                r->commanded[i] = r->sens[slot];
            }
        }
    }
}

int parsl_step(parsl_rt *r)
{
    if (r->ended) {
        return PARSL_ENDED;
    }
    if (setjmp(r->fail) != 0) {
        r->ended = 1;
        return PARSL_ERROR;
    }
    count_tick(r);
    read_inputs(r);
    memset(r->driven, 0, sizeof r->driven);
    memcpy(r->next, r->commanded, sizeof r->next);
    if (r->tick == 0) {
        if (PARSL_NE == 0 || PARSL_MAIN_CYCLES == 0) {
            r->ended = 1;
        } else {
            start_entry(r, 0);
        }
    } else if (entry_ends(r)) {
        next_entry(r);
    } else {
        run_instances(r);
    }
    memcpy(r->commanded, r->next, sizeof r->commanded);
    return r->ended ? PARSL_ENDED : PARSL_RUNNING;
}
