/*
 * PARSL embedded runtime, internal: one automaton instance of the running main entry, a port of
 * PARPE's org.parpe.core.run.InstanceRun (PARSL.md 7.1, section 13 rules 6-9 and 18-22).
 */
#ifndef PARSL_INST_H
#define PARSL_INST_H

#include "parsl_rt.h"

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

#endif
