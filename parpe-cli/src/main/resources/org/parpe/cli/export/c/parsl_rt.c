/*
 * PARSL embedded runtime: the scheduler (PARSL.md sections 7, 11, 13), a line-by-line port of
 * PARPE's org.parpe.core.run.Engine and InstanceRun so that the trace is the interpreter's,
 * bit for bit: the same operations on doubles in the same order.
 */
#include "parsl_rt.h"
#include <math.h>
#include <string.h>
#include <stdlib.h>
#include <stdio.h>

#define EPS 1e-9
#define MAX_TRANSITIONS 10000

static void state_error(parsl_rt *r, int16_t code, int16_t pos, double a, int16_t what)
{
    r->err_code = code;
    r->err_pos = pos;
    r->err_a = a;
    r->err_b = 0;
    r->err_what = what;
    longjmp(r->fail, 1);
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

/* ---- one automaton instance (InstanceRun) ---- */

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
} inst_view;

static void view(parsl_rt *r, int16_t slot, int16_t row, inst_view *v)
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
}

static int16_t module_of(const inst_view *v, int16_t k)
{
    return PARSL_I16(parsl_inst_mod, v->mod + k);
}

static void enter(parsl_rt *r, const inst_view *v, int16_t k)
{
    int16_t q = v->pool + k;
    r->index = k;
    r->id = PARSL_U16(parsl_ids, module_of(v, k));
    r->count = v->n;
    r->group_off = v->mod;
    r->group_n = v->n;
    r->phase = r->ph[q];
    r->cycle = r->cyc[q];
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

static void inst_init(parsl_rt *r, const inst_view *v, double phase, double offset, double cycles)
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
        enter(r, v, k);
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
        r->uk[q] = start;
        r->u[q] = start;
        r->p0[q] = r->p[q];
        r->a0[q] = r->commanded[module_of(v, k)];
        r->cyc[q] = 0;
        r->ph[q] = start;
        r->fin[q] = 0;
    }
}

static void reanchor(parsl_rt *r, const inst_view *v)
{
    int16_t k;
    for (k = 0; k < v->n; k++) {
        int16_t q = v->pool + k;
        if (!r->fin[q]) {
            r->a0[q] = r->commanded[module_of(v, k)];
            r->p0[q] = r->p[q];
        }
    }
}

static void prepare_tick(parsl_rt *r, const inst_view *v)
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
        enter(r, v, 0);
        eval_times(r, v);
    }
    v->is->scale = per;
    v->is->has_scale = x >= 0;
}

static double target(parsl_rt *r, const inst_view *v, int16_t s, int16_t k)
{
    int16_t row = v->s0 + s;
    int16_t first = PARSL_I16(parsl_state[row], PARSL_S_ANGLES);
    int16_t x = PARSL_I16(parsl_state[row], PARSL_S_NANGLES) == 1 ? PARSL_I16(parsl_angle, first)
            : PARSL_I16(parsl_angle, first + k);
    double a = parsl_eval(r, x);
    return v->mirror ? -a : a;
}

static double setpoint(parsl_rt *r, const inst_view *v, int16_t k, int16_t s)
{
    int16_t q = v->pool + k;
    int16_t interp = PARSL_I16(parsl_state[v->s0 + s], PARSL_S_INTERP);
    double g = target(r, v, s, k);
    double qq;
    double shape;
    if (interp == PARSL_STEP) {
        return g;
    }
    qq = (r->p[q] - r->p0[q]) / (1 - r->p0[q]);
    shape = interp == PARSL_SMOOTH ? (1.0 - cos(3.141592653589793 * qq)) / 2.0 : qq;
    return r->a0[q] + (g - r->a0[q]) * shape;
}

static double phase_of(parsl_rt *r, const inst_view *v, int16_t s, double prog)
{
    double cum = 0;
    int16_t j;
    for (j = 0; j < s; j++) {
        cum += r->tbuf[v->tb + j];
    }
    return (cum + prog * r->tbuf[v->tb + s]) / v->is->sum_t;
}

static void finish(parsl_rt *r, const inst_view *v, int16_t k, double angle)
{
    int16_t q = v->pool + k;
    r->fin[q] = 1;
    v->is->finished++;
    r->out[q] = angle;
    r->u[q] = r->uk[q] + v->is->limit;
    r->cyc[q] = floor(v->is->limit + EPS);
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
    double f = r->p[q] + (lim - r->u[q]) * v->is->sum_t / r->tbuf[v->tb + s];
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

static void hold(parsl_rt *r, const inst_view *v, int16_t k)
{
    enter(r, v, k);
    r->out[v->pool + k] = setpoint(r, v, k, r->st[v->pool + k]);
}

static void next_state(parsl_rt *r, const inst_view *v, int16_t q, int16_t *s)
{
    *s = (int16_t) ((*s + 1) % v->ns);
    r->st[q] = *s;
    r->p[q] = r->p0[q] = 0;
}

static void advance(parsl_rt *r, const inst_view *v, int16_t k, double dt)
{
    parsl_inst_state *is = v->is;
    int16_t q = v->pool + k;
    int16_t s;
    int16_t ex;
    double lim;
    double rem = dt;
    int16_t skips = 0;
    int16_t transitions = 0;
    enter(r, v, k);
    if (v->per_module) {
        eval_times(r, v);
    }
    lim = r->uk[q] + is->limit;
    s = r->st[q];
    ex = PARSL_I16(parsl_state[v->s0 + s], PARSL_S_EXIT);
    if (ex >= 0 && parsl_eval(r, ex) != 0) {
        double du = (1 - r->p[q]) * r->tbuf[v->tb + s] / is->sum_t;
        if (r->u[q] + du >= lim - EPS) {
            finish(r, v, k, r->commanded[module_of(v, k)]);
            return;
        }
        r->u[q] += du;
        r->a0[q] = r->commanded[module_of(v, k)];
        next_state(r, v, q, &s);
    }
    for (;;) {
        double t = r->tbuf[v->tb + s];
        double d = is->has_scale ? t * is->scale / is->sum_t : t;
        double need;
        double du;
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
            du = rem / d * t / is->sum_t;
            if (r->u[q] + du >= lim - EPS) {
                finish_inside(r, v, k, s, lim);
                return;
            }
            r->p[q] += rem / d;
            r->u[q] += du;
            break;
        }
        du = (1 - r->p[q]) * t / is->sum_t;
        rem -= need;
        skips = 0;
        if (++transitions > MAX_TRANSITIONS) {
            state_error(r, PARSL_E_TRANSITIONS, PARSL_I16(parsl_inst[v->row], PARSL_I_POS), dt, v->aut);
        }
        if (r->u[q] + du >= lim - EPS) {
            if (r->u[q] + du <= lim + EPS) {
                finish_at_end(r, v, k, s);
            } else {
                finish_inside(r, v, k, s, lim);
            }
            return;
        }
        r->u[q] += du;
        r->a0[q] = target(r, v, s, k);
        next_state(r, v, q, &s);
    }
    r->ph[q] = phase_of(r, v, s, r->p[q]);
    r->cyc[q] = floor(r->u[q] - r->uk[q] + EPS);
    r->phase = r->ph[q];
    r->cycle = r->cyc[q];
    r->out[q] = setpoint(r, v, k, s);
}

/* ---- the scheduler (Engine) ---- */

static void drive(parsl_rt *r, const inst_view *v, int16_t k)
{
    int16_t m = module_of(v, k);
    r->driven[m] = 1;
    r->next[m] = r->out[v->pool + k];
}

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
    r->btime = r->tick * PARSL_DT - r->entry_start * PARSL_DT;
    for (i = 0; i < count; i++) {
        inst_view v;
        int active;
        int16_t row = (int16_t) (first + i);
        view(r, i, row, &v);
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
            inst_init(r, &v, phase, offset, eval_or(r, PARSL_I16(parsl_inst[row], PARSL_I_CYCLES), INFINITY));
            v.is->was_active = (uint8_t) active;
            if (active) {
                for (k = 0; k < v.n; k++) {
                    if (!r->fin[v.pool + k]) {
                        hold(r, &v, k);
                        drive(r, &v, k);
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
            reanchor(r, &v);
            v.is->was_active = 1;
        }
        prepare_tick(r, &v);
        for (k = 0; k < v.n; k++) {
            if (!r->fin[v.pool + k]) {
                advance(r, &v, k, PARSL_DT);
                drive(r, &v, k);
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
    r->entry_start = r->tick;
    r->btime = 0;
    for (i = 0; i < n; i++) {
        r->macros[PARSL_I16(parsl_varg[first + i], 0)] = parsl_eval(r, PARSL_I16(parsl_varg[first + i], 1));
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
    r->btime = r->tick * PARSL_DT - r->entry_start * PARSL_DT;
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
    r->tick++;
    r->time = r->tick * PARSL_DT;
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
