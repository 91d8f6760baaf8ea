/* aerotex: helpers every command shares (option numbers, the progress
 * bar); apart from aerotex.c's main() so that the fuzz harness of the
 * option parser links them (fuzz/targets.txt). */
#include "aerotex.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

double aerotex_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

void aerotex_progress_show(aerotex_progress *p, int final)
{
    double t = aerotex_now(), frac, eta;
    int bar = 30, fill;
    if (!p->show || (!final && t - p->last < 0.25))
        return;
    p->last = t;
    frac = p->total ? (double)p->done / p->total : 1.0;
    if (frac > 1.0) frac = 1.0;
    fill = (int)(frac * bar + 0.5);
    eta = frac > 0.01 ? (t - p->t0) * (1.0 - frac) / frac : 0.0;
    fprintf(stderr, "\r[%.*s%*s] %3d%%  %s %dm%02ds ", fill,
            "##############################", bar - fill, "",
            (int)(100.0 * frac), final ? "took" : "ETA",
            (int)((final ? t - p->t0 : eta) / 60.0),
            (int)fmod(final ? t - p->t0 : eta, 60.0));
    if (final) fprintf(stderr, "\n");
    fflush(stderr);
}

int aerotex_number(int argc, char **argv, int *i, double lo, double hi,
                   double *x)
{
    const char *opt = argv[*i];
    char *end;
    if (*i + 1 >= argc) {
        aerotex_error("%s needs a value", opt);
        return -1;
    }
    (*i)++;
    *x = strtod(argv[*i], &end);
    if (end == argv[*i] || *end || !isfinite(*x)) {
        aerotex_error("%s: '%s' is not a number", opt, argv[*i]);
        return -1;
    }
    if (*x < lo || *x > hi) {
        aerotex_error("%s %g is out of range [%g, %g]", opt, *x, lo, hi);
        return -1;
    }
    return 0;
}

void aerotex_command_line(char *buf, size_t len, int argc, char **argv)
{
    size_t used = 0;
    buf[0] = 0;
    for (int i = -1; i < argc && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s",
                                 i < 0 ? "aerotex" : " ", i < 0 ? "" : argv[i]);
}

aerotex_loop_plan aerotex_plan_loop(int l0)
{
    aerotex_loop_plan p;
    p.xfade = l0 / 10 > 8 ? l0 / 10 : 8;
    p.lmin = (int)floor(0.95 * l0) > 2 ? (int)floor(0.95 * l0) : 2;
    p.lmax = (int)ceil(1.05 * l0);
    p.avail = p.lmax + p.xfade;
    return p;
}
