/*
 * PARSL embedded runtime: the scheduler of PARSL.md sections 7, 11 and 13 over the tables
 * that `parpe export` generates into parsl_program.c / parsl_program.h.
 *
 * Portable C99: no dynamic memory, no floating-point output from the library, a fixed tick.
 * The board code calls parsl_init once and parsl_step once per tick, reads the setpoints
 * from r->commanded, and may pass a function that reads sensors (NULL: the angle sensors
 * read the commanded angles, the others 0, as in a plain headless run).
 */
#ifndef PARSL_RT_H
#define PARSL_RT_H

#include <stdint.h>
#include <stddef.h>
#include <setjmp.h>
/* parsl_program.h declares the sizes, the tables' widths and column indices, and the codes of the
   sensor channels, control types and profiles (all generated from the translation's CLayout). */
#include "parsl_program.h"

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__AVR__)
#include <avr/pgmspace.h>
#define PARSL_ROM PROGMEM
#define PARSL_I16(a, i) ((int16_t) pgm_read_word(&(a)[i]))
#define PARSL_U16(a, i) ((uint16_t) pgm_read_word(&(a)[i]))
#define PARSL_DBL(a, i) ((double) pgm_read_float(&(a)[i]))
#define PARSL_NO_NAMES 1
#else
#define PARSL_ROM
#define PARSL_I16(a, i) ((a)[i])
#define PARSL_U16(a, i) ((a)[i])
#define PARSL_DBL(a, i) ((a)[i])
#endif

/*
 * Exact time on boards whose double is a 32-bit float (AVR; a PC test sets PARSL_REAL32): a float
 * cannot count ticks or cycles for long (at 2^24 it stops adding 1), so there the clock counts
 * whole seconds and parts of PARSL_DT_DEN in integers, $time and $btime are converted from it on
 * every tick, and the progress u is an integer count of whole cycles (cyc) and a fixed-point
 * fraction. With a 64-bit double the runtime does what the interpreter does, bit for bit.
 */
#if defined(PARSL_REAL32) || (defined(__SIZEOF_DOUBLE__) && __SIZEOF_DOUBLE__ == 4)
#define PARSL_EXACT_TIME 1
/* A time since the start: whole seconds and parts of a second in units of 1/PARSL_DT_DEN. */
typedef struct {
    uint32_t s;
    uint32_t f;
} parsl_clock;
typedef int32_t parsl_cycles;
#else
typedef double parsl_cycles;
#endif
/* The common case of a tick generated per automaton (parsl_inst.h), where double has 64 bits. */
#if !defined(PARSL_EXACT_TIME) && !defined(__AVR__) && !defined(PARSL_NO_FAST)
#define PARSL_FAST 1
#endif

/* Results of parsl_step. */
enum { PARSL_ENDED = 0, PARSL_RUNNING = 1, PARSL_ERROR = 2 };

/* Run-time errors (PARSL.md section 8 and section 13 rules 9 and 21). */
enum {
    PARSL_E_NONE, PARSL_E_DIV, PARSL_E_REM, PARSL_E_MODF, PARSL_E_SUM, PARSL_E_DIFF, PARSL_E_PROD,
    PARSL_E_QUOT, PARSL_E_POW, PARSL_E_FUNC, PARSL_E_SUMF, PARSL_E_VALUE, PARSL_E_PERIOD,
    PARSL_E_TOTAL, PARSL_E_NEGATIVE, PARSL_E_ALLZERO, PARSL_E_TRANSITIONS
};

/* Per-instance state of the running main entry. */
typedef struct {
    double sum_t;
    double scale;
    double limit;
    int16_t finished;
    uint8_t has_scale;
    uint8_t started;
    uint8_t was_active;
} parsl_inst_state;

struct parsl_rt;
/* Reads the board's sensors for this tick with parsl_set_reading. */
typedef void (*parsl_read_fn)(struct parsl_rt *r);
/*
 * Told when two instances under <if> drive the same module in one tick (the later one wins):
 * instance table rows `earlier` and `later`, the module index. May be NULL.
 */
typedef void (*parsl_overlap_fn)(struct parsl_rt *r, int16_t earlier, int16_t later, int16_t module);

/* The whole run-time state: one static object, sized by parsl_program.h. */
typedef struct parsl_rt {
    /* expression context (EvalContext) */
    double time;
    double btime;
    double phase;
    double cycle;
    int16_t index;
    int16_t count;
    uint16_t id;
    int16_t group_off;
    int16_t group_n;
    int16_t cur_x;
    double controls[PARSL_NC1];
    double macros[PARSL_NM1];
    double sens[PARSL_NS1];
    double over[PARSL_NS1];
    uint64_t seed;
    /* scheduler (Engine) */
    double commanded[PARSL_N];
    double next[PARSL_N];
    uint8_t driven[PARSL_N];
    int16_t driver[PARSL_N];
    long tick;
#ifdef PARSL_EXACT_TIME
    parsl_clock now;
    parsl_clock entry_start;
#else
    long entry_start;
#endif
    long main_cycle;
    int16_t entry;
    uint8_t ended;
    parsl_read_fn read;
    parsl_overlap_fn overlap;
    /* instances of the running entry (InstanceRun), pooled across entries */
    parsl_inst_state inst[PARSL_NI1];
    int16_t st[PARSL_POOL1];
    uint8_t fin[PARSL_POOL1];
    double p[PARSL_POOL1];
    double p0[PARSL_POOL1];
    double a0[PARSL_POOL1];
#ifdef PARSL_EXACT_TIME
    uint32_t u[PARSL_POOL1]; /* the fraction of a cycle, in units of 2^-32 (parsl_inst.c) */
    uint32_t pf[PARSL_POOL1]; /* p in units of 2^-32 (parsl_inst.c) */
#else
    double u[PARSL_POOL1];
    double uk[PARSL_POOL1];
#endif
    double ph[PARSL_POOL1];
    parsl_cycles cyc[PARSL_POOL1];
    double out[PARSL_POOL1];
    double tbuf[PARSL_TPOOL1];
    /* the error that stopped the run */
    jmp_buf fail;
    int16_t err_code;
    int16_t err_pos;
    int16_t err_what;
    double err_a;
    double err_b;
} parsl_rt;

/* Resets r for a run; seed is rand()'s seed (parpe run --seed); read may be NULL. */
void parsl_init(parsl_rt *r, uint64_t seed, parsl_read_fn read);
/* Runs the next tick (the first call runs tick 0); setpoints are then in r->commanded. */
int parsl_step(parsl_rt *r);
/* Stores a measured reading of the module at index i (ascending ID order); call from read. */
void parsl_set_reading(parsl_rt *r, int16_t i, int16_t channel, double value);
/*
 * Applies one assignment "$name=value" (or "name=value"): a control (number, or a radio word)
 * or a sensor override "$3_touch_left=1". Returns 0, or -1 with a message in msg (size n).
 */
int parsl_assign(parsl_rt *r, const char *text, char *msg, size_t n);
/* Room for any finite double written by parsl_format ("%.6f" of -1.8e308: 318 characters and the NUL). */
#define PARSL_FORMAT_MAX 320
/* Writes v as C's "%.6f" with the trace rules of PARSL.md section 13 rule 23 and -0 as 0 into buf
   (PARSL_FORMAT_MAX bytes); returns the length. */
int parsl_format(char *buf, double v);
/* Describes the error that stopped the run (without its place); returns msg. */
const char *parsl_error_text(const parsl_rt *r, char *msg, size_t n);

/* Used by the generated expressions. */
double parsl_eval(parsl_rt *r, int16_t x);
void parsl_raise(parsl_rt *r, int16_t code, double a, double b, int16_t what);
double parsl_local(parsl_rt *r, int16_t position, int16_t channel);
double parsl_rand(parsl_rt *r);
/* java.lang.Math.min and max: NaN wins, -0.0 is below 0.0. */
double parsl_min(double a, double b);
double parsl_max(double a, double b);

/* Generated in parsl_program.c. */
double parsl_expr(parsl_rt *r, int16_t x);
int16_t parsl_control_index(const char *name);
int16_t parsl_word_code(const char *name);
extern PARSL_ROM const uint16_t parsl_ids[];
extern PARSL_ROM const int16_t parsl_slot[];
extern PARSL_ROM const double parsl_control_init[];
extern PARSL_ROM const int16_t parsl_control[][PARSL_CONTROL_COLS];
extern PARSL_ROM const double parsl_control_range[][2];
extern PARSL_ROM const int16_t parsl_words[];
extern PARSL_ROM const int16_t parsl_entry[][PARSL_ENTRY_COLS];
extern PARSL_ROM const int16_t parsl_varg[][PARSL_VARG_COLS];
extern PARSL_ROM const int16_t parsl_inst[][PARSL_INST_COLS];
extern PARSL_ROM const int16_t parsl_inst_mod[];
extern PARSL_ROM const int16_t parsl_cond[];
extern PARSL_ROM const int16_t parsl_aut[][PARSL_AUT_COLS];
extern PARSL_ROM const int16_t parsl_state[][PARSL_STATE_COLS];
extern PARSL_ROM const int16_t parsl_angle[];
/* Places: every expression's id is its place; instances name theirs (file, line, column). */
extern PARSL_ROM const uint16_t parsl_pos[][3];
#ifndef PARSL_NO_NAMES
extern const char *const parsl_files[];
extern const char *const parsl_expr_text[];
extern const char *const parsl_aut_names[];
extern const char *const parsl_inst_groups[];
extern const char *const parsl_state_names[];
#endif

#ifdef __cplusplus
}
#endif

#endif
