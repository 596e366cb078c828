/*
 * PARSL embedded runtime: one automaton instance (see parsl_inst.h), the same operations on
 * doubles in the same order as PARPE's InstanceRun, so that setpoints are equal bit for bit;
 * with 32-bit floats (PARSL_EXACT_TIME) the progress is summed in fixed point (below).
 */
#include "parsl_inst.h"

#define EPS PARSL_EPS
#define MAX_TRANSITIONS 10000

#ifdef PARSL_EXACT_TIME
/*
 * 32-bit floats (see parsl_rt.h): a float adding the same step tick after tick rounds the same
 * way each time and drifts (u by a cycle in days; p made a 1 s gait of one state 0.002 cycles
 * late in an hour, 0.06 in a day). So both are summed exactly in fixed point, units of 2^-31
 * (ONE): u is the fraction of a cycle since the start (the interpreter's u - uk less cyc), a
 * carry one more cycle in cyc and one less in the local limit; pf is p's copy, p its float.
 */
#define ONE 0x80000000UL
#define U(r, q) u_value(r, q)
static double u_value(const parsl_rt *r, int16_t q)
{
    return ldexp((double) r->u[q], -31);
}
#define P_START(r, q) ((r)->pf[q] = (uint32_t) ldexp((r)->p[q], 31))
#define P_RESET(r, q) ((r)->pf[q] = 0)
/* whether adding du reaches the limit (never without one: the test is costly on AVR) */
#define REACHES(r, q, du, lim) ((lim) < INFINITY && U(r, q) + (du) >= (lim) - EPS)
#define U_START(r, q, start) ((r)->u[q] = 0, P_START(r, q))
#define U_LIMIT(r, is, q) ((is)->limit - (r)->cyc[q])
/* rem / d * t / sum_t with d = t * scale / sum_t (or t), in one division: faster, and one rounding */
#define U_STEP(rem, d, t, is) ((rem) / ((is)->has_scale ? (is)->scale : (is)->sum_t))
/* du <= 1 (one state's share of the cycle); below 0 only by what a transition left, within EPS */
static void add_u(parsl_rt *r, int16_t q, double du, double *lim)
{
    if (du > 0) {
        r->u[q] += (uint32_t) ldexp(du, 31);
        if (r->u[q] >= ONE) {
            r->u[q] -= ONE;
            r->cyc[q]++;
            *lim -= 1;
        }
    }
}
/* p < 1 and 0 <= dp < 1 - p; below 0 only by what a transition left, within EPS */
static void add_p(parsl_rt *r, int16_t q, double dp)
{
    if (dp < 0) {
        r->p[q] += dp; /* the copy stays at 0 */
        return;
    }
    r->pf[q] += (uint32_t) ldexp(dp, 31);
    r->p[q] = ldexp((double) r->pf[q], -31);
}
#else
#define P_START(r, q)
#define P_RESET(r, q)
#define add_p(r, q, dp) ((r)->p[q] += (dp))
#define U(r, q) ((r)->u[q])
#define REACHES(r, q, du, lim) ((r)->u[q] + (du) >= (lim) - EPS)
#define U_START(r, q, start) ((r)->uk[q] = (r)->u[q] = (start))
#define U_LIMIT(r, is, q) ((r)->uk[q] + (is)->limit)
#define U_STEP(rem, d, t, is) PARSL_U_STEP(rem, d, t, (is)->sum_t)
#define add_u(r, q, du, lim) ((r)->u[q] += (du))
#endif

#ifdef PARSL_EXACT_TIME
#define STEP_KEPT(v, s, rem, dt) 0
#define STEP(v, f) 0.0
#define STEP_KEEP(v, s, d, du, dp)
#else
/*
 * A module that spends the whole tick in state s steps by what the module before it in s did:
 * d, du and dp are computed from the tick, the state's duration, the scale and the sum of the
 * durations, the same for all (unless durations are per module), so they are equal bit for bit;
 * only their divisions are saved. Not with 32-bit floats: the AVR's code stays as it was.
 */
#define STEP_KEPT(v, s, rem, dt) ((v)->step_s == (s) && (rem) == (dt))
#define STEP(v, f) ((v)->step_##f)
#define STEP_KEEP(v, s, d, du, dp) \
    ((v)->step_s = (int16_t) ((v)->per_module ? -1 : (s)), (v)->step_d = (d), (v)->step_du = (du), (v)->step_dp = (dp))
#endif

static void state_error(parsl_rt *r, int16_t code, int16_t pos, double a, int16_t what)
{
    r->err_code = code;
    r->err_pos = pos;
    r->err_a = a;
    r->err_b = 0;
    r->err_what = what;
    longjmp(r->fail, 1);
}
void parsl_view(parsl_rt *r, int16_t slot, int16_t row, inst_view *v)
{
    v->row = row;
    v->aut = PARSL_I16(parsl_inst[row], PARSL_I_AUT);
    v->ns = PARSL_I16(parsl_aut[v->aut], PARSL_A_NS);
    v->s0 = PARSL_I16(parsl_aut[v->aut], PARSL_A_STATES);
    v->per_module = (uint8_t) PARSL_I16(parsl_aut[v->aut], PARSL_A_PERMODULE);
    v->n = PARSL_I16(parsl_inst[row], PARSL_I_N);
    v->mod = PARSL_I16(parsl_inst[row], PARSL_I_MOD);
    v->pool = PARSL_I16(parsl_inst[row], PARSL_I_POOL);
    v->tb = PARSL_I16(parsl_inst[row], PARSL_I_TBUF);
    v->mirror = (uint8_t) PARSL_I16(parsl_inst[row], PARSL_I_MIRROR);
    v->is = &r->inst[slot];
#ifndef PARSL_EXACT_TIME
    v->step_s = -1;
#endif
}

static void eval_times(parsl_rt *r, const inst_view *v)
{
    double s = 0;
    int16_t j;
    for (j = 0; j < v->ns; j++) {
        int16_t x = PARSL_I16(parsl_state[v->s0 + j], PARSL_S_TIME);
        double t = parsl_eval(r, x);
        if (t < 0) {
            state_error(r, PARSL_E_NEGATIVE, x, t, (int16_t) (v->s0 + j));
        }
        r->tbuf[v->tb + j] = t;
        s += t;
    }
    v->is->sum_t = s;
    if (!(s > 0)) {
        state_error(r, PARSL_E_TOTAL, PARSL_I16(parsl_inst[v->row], PARSL_I_POS), s, v->aut);
    }
}

void parsl_inst_init(parsl_rt *r, const inst_view *v, double phase, double offset, double cycles)
{
    parsl_inst_state *is = v->is;
    int16_t k;
    int16_t j;
    is->started = 1;
    is->limit = cycles;
    if (cycles <= 0) {
        for (k = 0; k < v->n; k++) {
            r->fin[v->pool + k] = 1;
        }
        is->finished = v->n;
        return;
    }
    is->finished = 0;
    for (k = 0; k < v->n; k++) {
        int16_t q = v->pool + k;
        double x = -(offset + k * phase);
        double start = x - floor(x);
        double pos;
        double cum = 0;
        int16_t found = -1;
        parsl_enter(r, v, k);
        r->phase = start;
        r->cycle = 0;
        if (k == 0 || v->per_module) {
            eval_times(r, v);
        }
        pos = start * is->sum_t;
        for (j = 0; j < v->ns; j++) {
            double t = r->tbuf[v->tb + j];
            if (t > 0 && pos < cum + t - EPS) {
                found = j;
                break;
            }
            cum += t;
        }
        if (found < 0) {
            r->st[q] = 0;
            r->p[q] = 0;
            start = 0;
        } else {
            double f = (pos - cum) / r->tbuf[v->tb + found];
            r->st[q] = found;
            r->p[q] = f > 0 ? f : 0;
        }
        U_START(r, q, start);
        r->p0[q] = r->p[q];
        r->a0[q] = r->commanded[parsl_module_of(v, k)];
        r->cyc[q] = 0;
        r->ph[q] = start;
        r->fin[q] = 0;
    }
}

void parsl_reanchor(parsl_rt *r, const inst_view *v)
{
    int16_t k;
    for (k = 0; k < v->n; k++) {
        int16_t q = v->pool + k;
        if (!r->fin[q]) {
            r->a0[q] = r->commanded[parsl_module_of(v, k)];
            r->p0[q] = r->p[q];
        }
    }
}

void parsl_prepare_tick(parsl_rt *r, const inst_view *v)
{
    int16_t x = PARSL_I16(parsl_inst[v->row], PARSL_I_PERIOD);
    double per = 0;
    if (x >= 0) {
        per = parsl_eval(r, x);
        if (!(per > 0)) {
            state_error(r, PARSL_E_PERIOD, x, per, v->aut);
        }
    }
    if (!v->per_module) {
        parsl_enter(r, v, 0);
        eval_times(r, v);
    }
    v->is->scale = per;
    v->is->has_scale = x >= 0;
}

PARSL_HOT double target(parsl_rt *r, const inst_view *v, int16_t s, int16_t k)
{
    int16_t row = v->s0 + s;
    int16_t first = PARSL_I16(parsl_state[row], PARSL_S_ANGLES);
    int16_t x = PARSL_I16(parsl_state[row], PARSL_S_NANGLES) == 1 ? PARSL_I16(parsl_angle, first)
            : PARSL_I16(parsl_angle, first + k);
    double a = parsl_eval(r, x);
    return v->mirror ? -a : a;
}

PARSL_HOT double setpoint(parsl_rt *r, const inst_view *v, int16_t k, int16_t s)
{
    int16_t q = v->pool + k;
    int16_t interp = PARSL_I16(parsl_state[v->s0 + s], PARSL_S_INTERP);
    double g = target(r, v, s, k);
    double qq;
    double shape;
    if (interp == PARSL_STEP) {
        return g;
    }
    qq = PARSL_LINEAR_SHAPE(r->p[q], r->p0[q]);
    shape = interp == PARSL_SMOOTH ? PARSL_SMOOTH_SHAPE(qq) : qq;
    return PARSL_BLEND(r->a0[q], g, shape);
}

static double phase_of(parsl_rt *r, const inst_view *v, int16_t s, double prog)
{
    double cum = 0;
    int16_t j;
    for (j = 0; j < s; j++) {
        cum += r->tbuf[v->tb + j];
    }
    return PARSL_PHASE(cum, prog, r->tbuf[v->tb + s], v->is->sum_t);
}

static void finish(parsl_rt *r, const inst_view *v, int16_t k, double angle)
{
    int16_t q = v->pool + k;
    r->fin[q] = 1;
    v->is->finished++;
    r->out[q] = angle;
    r->cyc[q] = floor(v->is->limit + EPS);
#ifdef PARSL_EXACT_TIME
    r->u[q] = 0; /* not read once finished */
#else
    r->u[q] = r->uk[q] + v->is->limit;
#endif
}

static void see_final(parsl_rt *r, const inst_view *v, int16_t k, int16_t s)
{
    int16_t q = v->pool + k;
    r->ph[q] = phase_of(r, v, s, r->p[q]);
    r->phase = r->ph[q];
    r->cycle = floor(v->is->limit + EPS);
}

static void finish_inside(parsl_rt *r, const inst_view *v, int16_t k, int16_t s, double lim)
{
    int16_t q = v->pool + k;
    double f = r->p[q] + (lim - U(r, q)) * v->is->sum_t / r->tbuf[v->tb + s];
    r->p[q] = f < 1 ? f : 1;
    see_final(r, v, k, s);
    finish(r, v, k, setpoint(r, v, k, s));
}

static void finish_at_end(parsl_rt *r, const inst_view *v, int16_t k, int16_t s)
{
    r->p[v->pool + k] = 1;
    see_final(r, v, k, s);
    finish(r, v, k, target(r, v, s, k));
}

void parsl_hold(parsl_rt *r, const inst_view *v, int16_t k)
{
    parsl_enter(r, v, k);
    r->out[v->pool + k] = setpoint(r, v, k, r->st[v->pool + k]);
}

static void next_state(parsl_rt *r, const inst_view *v, int16_t q, int16_t *s)
{
    *s = (int16_t) ((*s + 1) % v->ns);
    r->st[q] = *s;
    r->p[q] = r->p0[q] = 0;
    P_RESET(r, q);
}

void parsl_advance(parsl_rt *r, inst_view *v, int16_t k, double dt)
{
    parsl_inst_state *is = v->is;
    int16_t q = v->pool + k;
    int16_t s;
    int16_t ex;
    double lim;
    double rem = dt;
    int16_t skips = 0;
    int16_t transitions = 0;
    parsl_enter(r, v, k);
    if (v->per_module) {
        eval_times(r, v);
    }
    lim = U_LIMIT(r, is, q);
    s = r->st[q];
    ex = PARSL_I16(parsl_state[v->s0 + s], PARSL_S_EXIT);
    if (ex >= 0 && parsl_eval(r, ex) != 0) {
        double du = (1 - r->p[q]) * r->tbuf[v->tb + s] / is->sum_t;
        if (REACHES(r, q, du, lim)) {
            finish(r, v, k, r->commanded[parsl_module_of(v, k)]);
            return;
        }
        add_u(r, q, du, &lim);
        r->a0[q] = r->commanded[parsl_module_of(v, k)];
        next_state(r, v, q, &s);
    }
    for (;;) {
        double t = r->tbuf[v->tb + s];
        int kept = STEP_KEPT(v, s, rem, dt);
        double d = kept ? STEP(v, d) : PARSL_STEP_D(t, is);
        double need;
        double du;
        double dp;
        if (d <= 0) {
            if (++skips > v->ns) {
                state_error(r, PARSL_E_ALLZERO, PARSL_I16(parsl_inst[v->row], PARSL_I_POS), 0, v->aut);
            }
            r->a0[q] = target(r, v, s, k);
            next_state(r, v, q, &s);
            continue;
        }
        need = (1 - r->p[q]) * d;
        if (rem < need - EPS) {
            if (kept) {
                du = STEP(v, du);
                dp = STEP(v, dp);
            } else {
                du = U_STEP(rem, d, t, is);
                dp = rem / d;
                if (rem == dt) {
                    STEP_KEEP(v, s, d, du, dp);
                }
            }
            if (REACHES(r, q, du, lim)) {
                finish_inside(r, v, k, s, lim);
                return;
            }
            add_p(r, q, dp);
            add_u(r, q, du, &lim);
            break;
        }
        du = (1 - r->p[q]) * t / is->sum_t;
        rem -= need;
        skips = 0;
        if (++transitions > MAX_TRANSITIONS) {
            state_error(r, PARSL_E_TRANSITIONS, PARSL_I16(parsl_inst[v->row], PARSL_I_POS), dt, v->aut);
        }
        if (REACHES(r, q, du, lim)) {
            if (U(r, q) + du <= lim + EPS) {
                finish_at_end(r, v, k, s);
            } else {
                finish_inside(r, v, k, s, lim);
            }
            return;
        }
        add_u(r, q, du, &lim);
        r->a0[q] = target(r, v, s, k);
        next_state(r, v, q, &s);
    }
    r->ph[q] = phase_of(r, v, s, r->p[q]);
#ifndef PARSL_EXACT_TIME
    r->cyc[q] = PARSL_CYCLES(r->u[q], r->uk[q]);
#endif
    r->phase = r->ph[q];
    r->cycle = r->cyc[q];
    r->out[q] = setpoint(r, v, k, s);
}
