/*
 * FastFormTest's driver: runs the exported program for argv[1] ticks (seed argv[2]) and prints,
 * after every tick, a hash (FNV-1a) of the bits of every module's setpoint, every pooled module
 * state (state, finished, progress, cycle position, phase, cycle count, setpoint) and the
 * expression context, so that two builds (with and without PARSL_NO_FAST) can be compared bit for
 * bit; then how the run ended.
 */
#include "parsl_rt.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static parsl_rt rt;
static uint64_t hash;

static void mix(const void *p, size_t n)
{
    const unsigned char *b = p;
    size_t i;
    for (i = 0; i < n; i++) {
        hash = (hash ^ b[i]) * 0x100000001b3ULL;
    }
}

int main(int argc, char **argv)
{
    long ticks = argc > 1 ? atol(argv[1]) : 100;
    long i;
    int j;
    int s = PARSL_RUNNING;
    parsl_init(&rt, argc > 2 ? strtoull(argv[2], NULL, 10) : 0, NULL);
    for (i = 0; i < ticks && s == PARSL_RUNNING; i++) {
        s = parsl_step(&rt);
        hash = 0xcbf29ce484222325ULL;
        mix(rt.commanded, sizeof rt.commanded);
        for (j = 0; j < PARSL_POOL1; j++) {
            mix(&rt.st[j], sizeof rt.st[j]);
            mix(&rt.fin[j], sizeof rt.fin[j]);
            mix(&rt.p[j], sizeof rt.p[j]);
            mix(&rt.p0[j], sizeof rt.p0[j]);
            mix(&rt.a0[j], sizeof rt.a0[j]);
            mix(&rt.u[j], sizeof rt.u[j]);
            mix(&rt.ph[j], sizeof rt.ph[j]);
            mix(&rt.cyc[j], sizeof rt.cyc[j]);
            mix(&rt.out[j], sizeof rt.out[j]);
        }
        mix(&rt.phase, sizeof rt.phase);
        mix(&rt.cycle, sizeof rt.cycle);
        mix(&rt.index, sizeof rt.index);
        mix(&rt.id, sizeof rt.id);
        mix(&rt.count, sizeof rt.count);
        mix(&rt.group_off, sizeof rt.group_off);
        mix(&rt.group_n, sizeof rt.group_n);
        printf("%ld %016llx %a\n", i, (unsigned long long) hash, rt.commanded[0]);
    }
    printf("end %d error %d at %d (%a %a %d)\n", s, rt.err_code, rt.err_pos, rt.err_a, rt.err_b, rt.err_what);
    return 0;
}
