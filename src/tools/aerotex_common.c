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
