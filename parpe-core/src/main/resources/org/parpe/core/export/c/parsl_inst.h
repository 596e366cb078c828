/*
 * PARSL embedded runtime, internal: one automaton instance of the running main entry, a port of
 * PARPE's org.parpe.core.run.InstanceRun (PARSL.md 7.1, section 13 rules 6-9 and 18-22).
 */
#ifndef PARSL_INST_H
#define PARSL_INST_H

#include "parsl_rt.h"
#include "parsl_maths.h"
#include <math.h>
#include <string.h>

/* An instance's table row and its slice of the pooled per-module state. */
typedef struct {
    int16_t row;      /* instance table row */
    int16_t aut;      /* automaton table row */
    int16_t ns;
    int16_t s0;       /* first state row */
    int16_t n;
    int16_t mod;      /* offset of the module indices */
    int16_t pool;     /* offset of the per-module state */
    int16_t tb;       /* offset of the durations */
    uint8_t mirror;
    uint8_t per_module;
    parsl_inst_state *is;
#ifndef PARSL_EXACT_TIME
    /* a whole tick's step in state step_s (-1: none yet), the same for every module that spends
       the tick in it: kept from the module before (see parsl_advance) */
    int16_t step_s;
    double step_d;
    double step_du;
    double step_dp;
#endif
} inst_view;

/* Fills v for the instance table row `row`, using state slot `slot` of the running entry. */
void parsl_view(parsl_rt *r, int16_t slot, int16_t row, inst_view *v);
/* The module index (ascending ID order) of position k of the instance's group. */
#define parsl_module_of(v, k) PARSL_I16(parsl_inst_mod, (v)->mod + (k))
/* The helpers of a module's tick, inlined where double has 64 bits (the PC's speed, issue 36);
   an AVR's code stays as the compiler chose it for size. */
#if defined(__AVR__)
#define PARSL_HOT static
#else
#define PARSL_HOT static inline
#endif
/*
 * The arithmetic of a module's tick, written once for parsl_advance and for the common case that
 * the generated program runs inline (PARSL_FAST, below): the interpreter's operations in its order.
 */
#define PARSL_EPS 1e-9
/* the tick's length in state time units (t: the state's duration) */
#define PARSL_STEP_D(t, is) ((is)->has_scale ? (t) * (is)->scale / (is)->sum_t : (t))
/* the phase at progress prog of a state of duration t after cum of the cycle's sum */
#define PARSL_PHASE_OF(cum, prog, t) ((cum) + (prog) * (t))
#define PARSL_PHASE(cum, prog, t, sum) (PARSL_PHASE_OF(cum, prog, t) / (sum))
/* the profile: progress since the anchor, the smooth shape, the blend from a0 to g */
#define PARSL_LINEAR_SHAPE(p, p0) (((p) - (p0)) / (1 - (p0)))
#define PARSL_SMOOTH_SHAPE(qq) ((1.0 - parsl_cos(3.141592653589793 * (qq))) / 2.0)
#define PARSL_BLEND(a0, g, shape) ((a0) + ((g) - (a0)) * (shape))

/* Places every module when the instance starts; r->commanded holds the angles of the last tick. */
void parsl_inst_init(parsl_rt *r, const inst_view *v, double phase, double offset, double cycles);
/* Re-anchors after a suspension: motion resumes from the current angle. */
void parsl_reanchor(parsl_rt *r, const inst_view *v);
/* Evaluates the period and, unless they depend on the module, the durations for this tick. */
void parsl_prepare_tick(parsl_rt *r, const inst_view *v);
/* Advances module k by dt and computes its setpoint. */
void parsl_advance(parsl_rt *r, inst_view *v, int16_t k, double dt);
/* Computes module k's setpoint without advancing (the instance's first tick). */
void parsl_hold(parsl_rt *r, const inst_view *v, int16_t k);

/* Sets the expression context ($index, $phase, ...) to module k's. */
PARSL_HOT void parsl_enter(parsl_rt *r, const inst_view *v, int16_t k)
{
    int16_t q = v->pool + k;
    r->index = k;
    r->id = PARSL_U16(parsl_ids, parsl_module_of(v, k));
    r->count = v->n;
    r->group_off = v->mod;
    r->group_n = v->n;
    r->phase = r->ph[q];
    r->cycle = r->cyc[q];
}

/* Hands module k's setpoint to the engine (later instances win; the overlap is told). */
PARSL_HOT void parsl_drive(parsl_rt *r, const inst_view *v, int16_t k)
{
    int16_t m = parsl_module_of(v, k);
    if (r->driven[m] && r->driver[m] != v->row && r->overlap != NULL) {
        r->overlap(r, r->driver[m], v->row, m);
    }
    r->driven[m] = 1;
    r->driver[m] = v->row;
    r->next[m] = r->out[v->pool + k];
}

#ifndef PARSL_EXACT_TIME
/* floor(c) of the cycle count: a conversion below 2^52 (without SSE4.1 gcc inlines floor as some
   twenty instructions); -0 and the rest go to floor, which keeps their sign */
PARSL_HOT double parsl_whole(double c)
{
    return c > 0 && c < 0x1p52 ? (double) (int64_t) c : floor(c);
}
/* u's step over rem in a state of duration t and tick length d */
#define PARSL_U_STEP(rem, d, t, sum) ((rem) / (d) * (t) / (sum))
/* the whole cycles of progress u counted from uk */
#define PARSL_CYCLES(u, uk) parsl_whole((u) - (uk) + PARSL_EPS)
#endif

#ifdef PARSL_FAST
/*
 * The common case of a tick, generated per automaton into parsl_program.c (issue 36): a module that
 * spends the whole tick in its state, which has no exit condition and one angle, steps by what every
 * module in that state steps (parsl_fast_begin, once per tick), and its angle is computed inline
 * without checks (NaN where a check could fail or an operation could hide a non-finite value); any
 * other module, and one whose angle is not finite, runs parsl_advance instead, from the same state,
 * which raises what the interpreter raises. The stores and operations are parsl_advance's for that
 * case, in its order (PARSL_* above), so the setpoints are equal bit for bit (the export's tests
 * compare both forms); PARSL_NO_FAST compiles the general form only.
 */
typedef struct {
    double t;      /* the state's duration */
    double d;
    double du;
    double dp;
    double cum;    /* the durations of the states before it, summed as phase_of sums them */
    double inv;    /* parsl_exact_inverse of the sum of the durations */
    int16_t interp;
} parsl_fast_step;
/* A module's progress, phase and cycle count after the tick, before they are stored. */
typedef struct {
    double p;
    double u;
    double phase;
    double cycle;
} parsl_fast_mod;

/* A value of an angle the same for every module of the instance in this tick (or every one with the
   same cycle count): computed for the first, reused by the others (generated as memo[i]). */
typedef struct {
    double value;
    double cycle;
    uint8_t ok;
} parsl_memo;

/* Whether a and b have the same bits (0 and -0 differ). */
PARSL_HOT int parsl_same(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* Generated: runs the tick of the instance v in the common case (1), or 0 where it has none. */
int parsl_fast(parsl_rt *r, inst_view *v);

/*
 * 1/s where s is a power of two whose reciprocal is a normal number, else 0. Then x * (1/s) is
 * x / s bit for bit: both are the exact x 2^-e rounded once (IEEE 754), so a division by the sum of
 * the durations, the same for every module, becomes a multiplication where the sum allows it.
 */
PARSL_HOT double parsl_exact_inverse(double s)
{
    int e;
    return s > 0 && frexp(s, &e) == 0.5 && e > -1000 && e < 1000 ? 1.0 / s : 0.0;
}

/* The whole-tick step of each of the automaton's states, for this tick. */
PARSL_HOT void parsl_fast_begin(const parsl_rt *r, const inst_view *v, parsl_fast_step *f)
{
    double cum = 0;
    double inv = parsl_exact_inverse(v->is->sum_t);
    int16_t j;
    for (j = 0; j < v->ns; j++) {
        double t = r->tbuf[v->tb + j];
        f[j].inv = inv;
        double d = PARSL_STEP_D(t, v->is);
        f[j].t = t;
        f[j].d = d;
        f[j].du = PARSL_U_STEP(PARSL_DT, d, t, v->is->sum_t);
        f[j].dp = PARSL_DT / d;
        f[j].cum = cum;
        f[j].interp = PARSL_I16(parsl_state[v->s0 + j], PARSL_S_INTERP);
        cum += t;
    }
}

/* Module k's state if it spends the whole tick there without finishing (m: its values after the
   tick), else -1. */
PARSL_HOT int16_t parsl_fast_enter(const parsl_rt *r, const inst_view *v, const parsl_fast_step *f, int16_t k,
        parsl_fast_mod *m)
{
    int16_t q = v->pool + k;
    int16_t s = r->st[q];
    const parsl_fast_step *fs = &f[s];
    double p = r->p[q];
    double u = r->u[q];
    double uk = r->uk[q];
    if (!(PARSL_DT < (1 - p) * fs->d - PARSL_EPS) || u + fs->du >= uk + v->is->limit - PARSL_EPS) {
        return -1;
    }
    m->p = p + fs->dp;
    m->u = u + fs->du;
    m->phase = fs->inv != 0 ? PARSL_PHASE_OF(fs->cum, m->p, fs->t) * fs->inv : PARSL_PHASE(fs->cum, m->p, fs->t, v->is->sum_t);
    m->cycle = PARSL_CYCLES(m->u, uk);
    return s;
}

/* Stores module k's tick with angle a (finite) of state s. */
PARSL_HOT void parsl_fast_store(parsl_rt *r, const inst_view *v, const parsl_fast_step *fs, int16_t k,
        const parsl_fast_mod *m, double a)
{
    int16_t q = v->pool + k;
    double g = v->mirror ? -a : a;
    r->p[q] = m->p;
    r->u[q] = m->u;
    r->ph[q] = m->phase;
    r->cyc[q] = m->cycle;
    if (fs->interp == PARSL_STEP) {
        r->out[q] = g;
    } else {
        /* where 1 - p0 is 1 (p0 is 0 after a transition) the division by it returns its dividend */
        double qq = 1 - r->p0[q] == 1 ? m->p - r->p0[q] : PARSL_LINEAR_SHAPE(m->p, r->p0[q]);
        double shape = fs->interp == PARSL_SMOOTH ? PARSL_SMOOTH_SHAPE(qq) : qq;
        r->out[q] = PARSL_BLEND(r->a0[q], g, shape);
    }
}
#endif

#endif
