/*
 * The exported program on a PC: `parpe run` without a simulator, as a small C program.
 *
 *   ./program [--duration SECONDS] [--seed N] [--stimulus FILE] [--trace FILE|-]
 *
 * Writes the CSV trace of PARSL.md section 11 (header time,m<ID>,...; every number as %.6f);
 * exit codes as parpe run: 0 success, 2 usage errors, 3 run-time error.
 */
#include "parsl_rt.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_STIMULI 4096
#define MAX_STIMULUS_LINE 256   /* characters of a stimulus line (a longer comment is cut, a longer assignment refused) */
#define MAX_WARNINGS 1024

typedef struct {
    double time;
    int line;
    char text[MAX_STIMULUS_LINE];
} stimulus;

static parsl_rt rt;
static parsl_rt probe;
static stimulus stimuli[MAX_STIMULI];
static int stimulus_count;

static int16_t warned[MAX_WARNINGS][2];
static int warned_count;

/* The warning of parpe run, once per pair of instances: the later one wins. */
static void report_overlap(parsl_rt *r, int16_t earlier, int16_t later, int16_t module)
{
    char t[PARSL_FORMAT_MAX];
    int i;
    uint16_t at = PARSL_U16(parsl_inst[later], PARSL_I_POS);
    for (i = 0; i < warned_count; i++) {
        if (warned[i][0] == earlier && warned[i][1] == later) {
            return;
        }
    }
    if (warned_count == MAX_WARNINGS) {
        return;
    }
    warned[warned_count][0] = earlier;
    warned[warned_count++][1] = later;
    parsl_format(t, r->time);
    fprintf(stderr, "%s:%u:%u: warning: instances '%s' on group '%s' (line %u) and '%s' on group '%s' both drive"
            " module %u at t=%s s; the later one wins\n", parsl_files[PARSL_U16(parsl_pos[at], 0)],
            (unsigned) PARSL_U16(parsl_pos[at], 1), (unsigned) PARSL_U16(parsl_pos[at], 2),
            parsl_aut_names[PARSL_I16(parsl_inst[earlier], PARSL_I_AUT)], parsl_inst_groups[earlier],
            (unsigned) PARSL_U16(parsl_pos[PARSL_U16(parsl_inst[earlier], PARSL_I_POS)], 1),
            parsl_aut_names[PARSL_I16(parsl_inst[later], PARSL_I_AUT)], parsl_inst_groups[later],
            (unsigned) PARSL_U16(parsl_ids, module), t);
}

static int usage(const char *message)
{
    fprintf(stderr, "%s: %s\nusage: program [--duration SECONDS] [--seed N] [--stimulus FILE] [--trace FILE|-]\n",
            PARSL_FILE, message);
    return 2;
}

/*
 * A plain decimal number as parpe run reads times (org.parpe.core.model.Numbers.parsePlain):
 * [+-]digits[.digits][e[+-]digits] or [+-].digits[...], finite; no hex, inf, nan or trailing text.
 */
static int parse_plain(const char *s, double *v)
{
    const char *p = s;
    int digits = 0;
    char *end;
    if (*p == '+' || *p == '-') {
        p++;
    }
    while (*p >= '0' && *p <= '9') {
        p++;
        digits++;
    }
    if (*p == '.') {
        p++;
        while (*p >= '0' && *p <= '9') {
            p++;
            digits++;
        }
    }
    if (digits == 0) {
        return -1;
    }
    if (*p == 'e' || *p == 'E') {
        int exp_digits = 0;
        p++;
        if (*p == '+' || *p == '-') {
            p++;
        }
        while (*p >= '0' && *p <= '9') {
            p++;
            exp_digits++;
        }
        if (exp_digits == 0) {
            return -1;
        }
    }
    if (*p != '\0') {
        return -1;
    }
    *v = strtod(s, &end);
    return *end == '\0' && isfinite(*v) ? 0 : -1;
}

/* Reads "TIME $NAME=VALUE" lines (# comments) into stimuli, sorted by time, stable. */
static const char *stimulus_file = "";

static int read_stimuli(const char *file)
{
    char line[MAX_STIMULUS_LINE];
    int number = 0;
    int c = 0;
    FILE *in = fopen(file, "r");
    stimulus_file = file;
    if (in == NULL) {
        fprintf(stderr, "parpe: cannot read stimulus file '%s'\n", file);
        return 2;
    }
    while (c != EOF) {
        char *hash;
        char *body = line;
        char *end;
        char *space;
        double t;
        int i;
        size_t used = 0;
        /* one whole line, however long: the rest of a long comment is dropped, a longer assignment refused */
        while ((c = getc(in)) != EOF && c != '\n') {
            if (used + 1 < sizeof line) {
                line[used] = (char) c;
            }
            used++;
        }
        if (c == EOF && used == 0) {
            break;
        }
        number++;
        line[used + 1 > sizeof line ? sizeof line - 1 : used] = '\0';
        if (used + 1 > sizeof line && strchr(line, '#') == NULL) {
            fprintf(stderr, "%s:%d:1: error: a stimulus assignment may have at most %d characters\n", file, number,
                    (int) sizeof line - 1);
            fclose(in);
            return 2;
        }
        hash = strchr(line, '#');
        if (hash != NULL) {
            *hash = '\0';
        }
        while (*body == ' ' || *body == '\t') {
            body++;
        }
        for (end = body + strlen(body); end > body && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\n'
                || end[-1] == '\r'); end--) {
        }
        *end = '\0';
        if (*body == '\0') {
            continue;
        }
        for (space = body; *space != '\0' && *space != ' ' && *space != '\t'; space++) {
        }
        end = space;
        if (*space != '\0') {
            char keep = *space;
            *space = '\0';
            if (parse_plain(body, &t) != 0 || !(t >= 0)) {
                *space = keep;
                fprintf(stderr, "%s:%d:1: error: time must be a number of seconds >= 0, got '%.*s'\n", file, number,
                        (int) (space - body), body);
                fclose(in);
                return 2;
            }
            *space = keep;
        } else {
            t = -1;
        }
        if (stimulus_count == MAX_STIMULI) {
            fprintf(stderr, "%s:%d:1: error: more than %d stimuli\n", file, number, MAX_STIMULI);
            fclose(in);
            return 2;
        }
        if (t < 0) {
            fprintf(stderr, "%s:%d:1: error: expected 'TIME $NAME=VALUE', got '%s'\n", file, number, body);
            fclose(in);
            return 2;
        }
        while (*end == ' ' || *end == '\t') {
            end++;
        }
        for (i = stimulus_count; i > 0 && stimuli[i - 1].time > t; i--) {
            stimuli[i] = stimuli[i - 1];
        }
        stimuli[i].time = t;
        stimuli[i].line = number;
        snprintf(stimuli[i].text, sizeof stimuli[i].text, "%s", end);
        stimulus_count++;
    }
    fclose(in);
    return 0;
}

static void row(FILE *out)
{
    char buf[PARSL_FORMAT_MAX];
    int i;
    parsl_format(buf, rt.time);
    fputs(buf, out);
    for (i = 0; i < PARSL_N; i++) {
        parsl_format(buf, rt.commanded[i]);
        fputc(',', out);
        fputs(buf, out);
    }
    fputc('\n', out);
}

int main(int argc, char **argv)
{
    double duration = INFINITY;
    unsigned long long seed = 0;
    const char *trace = NULL;
    FILE *out = NULL;
    int next = 0;
    long k;
    int i;
    for (i = 1; i < argc; i++) {
        if (i + 1 >= argc) {
            return usage("an option needs a value");
        } else if (strcmp(argv[i], "--duration") == 0) {
            /* as parpe run: a number >= 0 of at most 1e9 ticks */
            if (parse_plain(argv[++i], &duration) != 0 || !(duration >= 0) || duration / PARSL_DT > 1e9) {
                return usage("--duration must be a number of seconds >= 0 and of at most 1e9 ticks");
            }
        } else if (strcmp(argv[i], "--seed") == 0) {
            char *end;
            long long s;
            errno = 0;
            s = strtoll(argv[++i], &end, 10);
            if (end == argv[i] || *end != '\0' || errno != 0 || argv[i][0] == ' ' || argv[i][0] == '\t') {
                return usage("--seed must be a whole number");
            }
            seed = (unsigned long long) s;
        } else if (strcmp(argv[i], "--stimulus") == 0) {
            if (read_stimuli(argv[++i]) != 0) {
                return 2;
            }
        } else if (strcmp(argv[i], "--trace") == 0) {
            trace = argv[++i];
        } else {
            return usage("unknown option");
        }
    }
    parsl_init(&rt, (uint64_t) seed, NULL);
    rt.overlap = report_overlap;
    probe = rt;
    for (i = 0; i < stimulus_count; i++) {
        char msg[120];
        if (parsl_assign(&probe, stimuli[i].text, msg, sizeof msg) != 0) {
            fprintf(stderr, "%s:%d:1: error: %s\n", stimulus_file, stimuli[i].line, msg);
            return 2;
        }
    }
    if (trace != NULL) {
        out = strcmp(trace, "-") == 0 ? stdout : fopen(trace, "w");
        if (out == NULL) {
            fprintf(stderr, "parpe: cannot write trace file '%s'\n", trace);
            return 2;
        }
        fputs("time", out);
        for (i = 0; i < PARSL_N; i++) {
            fprintf(out, ",m%u", (unsigned) PARSL_U16(parsl_ids, i));
        }
        fputc('\n', out);
    }
    for (k = 0;; k++) {
        double t = k * PARSL_DT;
        int status;
        if (t > duration + 1e-9) {
            break;
        }
        while (next < stimulus_count && stimuli[next].time <= t + 1e-9) {
            parsl_assign(&rt, stimuli[next++].text, NULL, 0);
        }
        status = parsl_step(&rt);
        if (status == PARSL_ERROR) {
            char msg[200];
            fprintf(stderr, "%s:%u:%u: error: %s (at t=%.6f s)\n", parsl_files[PARSL_U16(parsl_pos[rt.err_pos], 0)],
                    (unsigned) PARSL_U16(parsl_pos[rt.err_pos], 1), (unsigned) PARSL_U16(parsl_pos[rt.err_pos], 2),
                    parsl_error_text(&rt, msg, sizeof msg), rt.time);
            if (out != NULL) {
                fclose(out);
            }
            return 3;
        }
        if (out != NULL) {
            row(out);
        }
        if (status == PARSL_ENDED) {
            break;
        }
    }
    if (out != NULL && out != stdout) {
        fclose(out);
    } else if (out != NULL) {
        fflush(out);
    }
    return 0;
}
