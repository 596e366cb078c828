/*
 * Runs an exported program for argv[1] ticks and prints, at every argv[2]-th tick and the last,
 * "tick $cycle $phase $time $btime entry angle" of the first module (9 significant digits: a
 * float's exact value).
 */
#include "parsl_rt.h"

static parsl_rt rt;

int main(int argc, char **argv)
{
    long long n;
    long long every;
    long long i;
    if (argc != 3) {
        fprintf(stderr, "usage: long_run TICKS EVERY\n");
        return 2;
    }
    n = atoll(argv[1]);
    every = atoll(argv[2]);
    parsl_init(&rt, 0, NULL);
    for (i = 0; i <= n; i++) {
        if (parsl_step(&rt) != PARSL_RUNNING) {
            printf("stopped at tick %lld\n", i);
            return 1;
        }
        if (i % every == 0 || i == n) {
            printf("%lld %.9g %.9g %.9g %.9g %d %.9g\n", i, (double) rt.cycle, (double) rt.phase, (double) rt.time,
                   (double) rt.btime, (int) rt.entry, (double) rt.commanded[0]);
        }
    }
    return 0;
}
