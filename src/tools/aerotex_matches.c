/* aerotex info's table of what a texture matches: the quantity, the
 * texture's value, the published value, its source, the test that checks
 * it, and whether the texture was calibrated on it or it is an independent
 * check (textures/README.md has the same table per shipped texture).
 * A texture may carry its rows (`match1=`, `match2=`, ...: six fields
 * separated by '|'; aerotex object writes them); for the others, and for
 * files made before the rows existed, they are derived here from the
 * metadata every texture has (kind, shape, span3d, st, cd, ...). */
#include "aerotex.h"
#include "strouhal.h"
#include "texture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ROSSITER_ALPHA 0.25
#define ROSSITER_KAPPA 0.57

/* a metadata value into buf (NULL when missing) */
static const char *meta(const aero_texture *t, const char *key, char *buf,
                        size_t len)
{
    return aero_texture_get(t, key, buf, len);
}

/* a comma-separated list of numbers: how many were read (at most max) */
static int meta_list(const aero_texture *t, const char *key, double *x,
                     int max)
{
    char buf[8192], *p = buf, *end;
    int n = 0;
    if (!aero_texture_get(t, key, buf, sizeof buf))
        return 0;
    while (n < max) {
        x[n] = strtod(p, &end);
        if (end == p)
            break;
        n++;
        p = end;
        while (*p == ',' || *p == ' ')
            p++;
    }
    return n;
}

static void row(const char *quantity, const char *value,
                const char *published, const char *source, const char *test,
                const char *kind)
{
    printf("| %s | %s | %s | %s | %s | %s |\n", quantity, value, published,
           source, test, kind);
}

/* the rows the file carries: how many */
static int stored_rows(const aero_texture *t)
{
    char key[16];
    const char *v;
    int n = 0;
    for (int k = 1; k <= 32; k++) {
        char buf[1024], *f[6], *p;
        int nf = 0;
        snprintf(key, sizeof key, "match%d", k);
        if (!(v = meta(t, key, buf, sizeof buf)))
            break;
        for (p = buf; nf < 6; nf++) {
            f[nf] = p;
            p = strchr(p, '|');
            if (!p) {
                nf++;
                break;
            }
            *p++ = '\0';
        }
        for (int i = nf; i < 6; i++)
            f[i] = "";
        row(f[0], f[1], f[2], f[3], f[4], f[5]);
        n++;
    }
    return n;
}

/* the nearest Rossiter stage to st_l at Mach number mach */
static int rossiter_stage(double st_l, double mach, double *st_m)
{
    int best = 1;
    for (int m = 1; m <= 4; m++) {
        double s = (m - ROSSITER_ALPHA) / (mach + 1.0 / ROSSITER_KAPPA);
        if (m == 1 || fabs(log(st_l / s)) < fabs(log(st_l / *st_m))) {
            best = m;
            *st_m = s;
        }
    }
    return best;
}

/* a URANS texture's band limit at what its grid resolves (band_limit.h) */
static void band_row(const aero_texture *t)
{
    const double lo = aero_texture_getd(t, "band_limit_pass", 0.0);
    const double hi = aero_texture_getd(t, "band_limit_stop", 0.0);
    char v[64];
    if (!(hi > 0.0))
        return;
    snprintf(v, sizeof v, "%.0f-%.0f Hz roll-off", lo, hi);
    row("band limit: wavelengths of 16 to 8 cells at v0", v,
        "the scheme carries waves of >= 16 cells", "Vichnevetsky and Bowles "
        "1982; Lele 1992; Trefethen 1982",
        "tests/unit/test_band_limit.c (the filter)", "method");
}

/* a thin blade (the sword): its tone's St on the projected width,
   chord sin(angle) from 20 deg on, and the checks that only Pd measures */
static void blade_rows(const aero_texture *t)
{
    double st[64], ang[64], lo = 1e9, hi = -1e9;
    int n = meta_list(t, "st_list", st, 64);
    int na = meta_list(t, "angles", ang, 64);
    char v[64];
    for (int k = 0; k < n && k < na; k++)
        if (ang[k] >= 20.0 - 1e-9 && ang[k] <= 90.0 + 1e-9) {
            double s = st[k] * sin(ang[k] * 3.14159265358979323846 / 180.0);
            lo = s < lo ? s : lo;
            hi = s > hi ? s : hi;
        }
    if (hi >= lo)
        snprintf(v, sizeof v, "%.3f-%.3f", lo, hi);
    else
        snprintf(v, sizeof v, "(no directions at 20-90 deg)");
    row("St on the projected width (chord sin a), 20-90 deg", v,
        "0.14-0.20 (0.146 broadside)", "Fage and Johansen 1927",
        "16-sword.sh 3 (metadata and heard)", "independent");
    row("clicks of the force channels", "(measured by the test)",
        "at most 3", "issue 39", "16-sword.sh 2", "independent");
    row("clicks, whirled in Pd, chord at 0-90 deg", "(measured in Pd)",
        "within the whirled cylinder's + 0.5", "issue 39",
        "16-sword.sh 1 (45 deg open)", "independent");
    row("edge-on tone below broadside", "(measured in Pd)",
        "below broadside, not silent", "issue 39", "16-sword.sh 4",
        "independent");
    band_row(t);
}

static void aeolian_rows(const aero_texture *t)
{
    char sb[64], hb[256];
    const char *span = meta(t, "span3d", sb, sizeof sb);
    const char *shape = meta(t, "shape", hb, sizeof hb);
    const double re = aero_texture_getd(t, "re", 0.0);
    char v[64], pub[96];
    if (span && !strcmp(span, "circle-calibrated") && shape &&
        !strncmp(shape, "circle", 6)) {
        snprintf(v, sizeof v, "%.3f", aero_texture_getd(t, "st", 0.0));
        snprintf(pub, sizeof pub, "%.3f at Re %.0f", aero_strouhal(re), re);
        row("St", v, pub, "Roshko 1954", "15-aeolian-texture.sh 11; in Pd 12",
            "calibrated");
        snprintf(v, sizeof v, "%.3f", aero_texture_getd(t, "cl_rms", 0.0));
        snprintf(pub, sizeof pub, "%.3f at Re %.0f", aero_lift_rms(re), re);
        row("sectional C_L'", v, pub, "Norberg 2003",
            "15-aeolian-texture.sh 11; in Pd 12", "calibrated");
        row("level against speed", "U^3 (St C_L')(Re)",
            "U^3 (Curle), C_L'(Re)", "Curle 1955; Norberg 2003",
            "15-aeolian-texture.sh 5", "independent");
        snprintf(v, sizeof v, "%.2f", aero_texture_getd(t, "cd", 0.0));
        row("mean Cd (2D flow)", v, "1.0-1.3", "Roshko 1961",
            "not asserted (open)", "independent");
        return;
    }
    if (shape && !strncmp(shape, "polygon", 7)) {
        blade_rows(t);
        return;
    }
    if (span && !strcmp(span, "urans")) {
        double st[64], cd[64], ang[64];
        int n = meta_list(t, "st_list", st, 64);
        int nc = meta_list(t, "cd_list", cd, 64);
        int na = meta_list(t, "angles", ang, 64), kmax = 0;
        snprintf(v, sizeof v, "%.3f", n > 0 ? st[0] : 0.0);
        row("St, flow onto a face", v, "0.13 (0.132 at Re 21,400)",
            "Okajima 1982; Lyn et al. 1995",
            "tests/unit/test_urans.c (the flow, +-10 %)", "independent");
        snprintf(v, sizeof v, "%.2f", nc > 0 ? cd[0] : 0.0);
        row("mean Cd, flow onto a face", v, "2.0-2.3", "Lyn et al. 1995",
            "not asserted (open: 8 % under)", "independent");
        for (int k = 1; k < n && k < na; k++)
            if (st[k] > st[kmax])
                kmax = k;
        snprintf(v, sizeof v, "largest at %.1f deg",
                 kmax < na ? ang[kmax] : 0.0);
        row("St against incidence", v, "a maximum near 12-15 deg",
            "Knisely 1990", "not asserted (open)", "independent");
        band_row(t);
        return;
    }
}

static void cavity_rows(const aero_texture *t)
{
    const double st = aero_texture_getd(t, "st", 0.0);
    const double mach = aero_texture_getd(t, "v0", 10.0) /
                        aero_texture_getd(t, "c0", 343.0);
    double st_m = 0.0;
    char v[64], pub[96];
    int m = st > 0.0 ? rossiter_stage(st, mach, &st_m) : 0;
    snprintf(v, sizeof v, "%.3f", st);
    snprintf(pub, sizeof pub, "stage %d: %.3f +-15 %%", m, st_m);
    row("St_L of the shear-layer tone", v, pub,
        "Rossiter 1964; Rowley, Colonius and Basu 2002",
        "tests/unit/test_cavity_flow.c (this flow and a sweep of L/theta0)",
        "independent");
    row("pitch against length", "f L / v kept", "f ~ v / L (Strouhal)",
        "Rossiter 1964", "20-cavity.sh 4", "independent");
}

static void vortex_rows(const aero_texture *t)
{
    double u[64], rms[64];
    int n = meta_list(t, "speeds", u, 64);
    int nr = meta_list(t, "rms", rms, 64);
    double lo = 1e9, hi = -1e9;
    char v[64];
    /* every pair of speeds a doubling apart */
    for (int a = 0; a < n && a < nr; a++)
        for (int b = 0; b < n && b < nr; b++)
            if (fabs(u[b] - 2.0 * u[a]) < 1e-9 && rms[a] > 0.0 &&
                rms[b] > 0.0) {
                double slope = 20.0 * log10(rms[b] / rms[a]);
                lo = slope < lo ? slope : lo;
                hi = slope > hi ? slope : hi;
            }
    if (hi >= lo)
        snprintf(v, sizeof v, "%+.1f..%+.1f dB per doubling", lo, hi);
    else
        snprintf(v, sizeof v, "(no rms list)");
    row("level against speed u", v, "+24.1 dB per doubling (p ~ u^4)",
        "Lighthill 1952 (compact quadrupole)", "40-vortex.sh 2 (+-3 dB)",
        "independent");
}

static void object_rows(const aero_texture *t)
{
    char mb[32];
    const char *method = meta(t, "method", mb, sizeof mb);
    char v[64];
    if (method && !strcmp(method, "strip")) {
        snprintf(v, sizeof v, "%.3f (strongest slice)",
                 aero_texture_getd(t, "st", 0.0));
        row("each slice's St on its diameter", v, "St(Re) of a cylinder",
            "Roshko 1954", "tests/unit/test_strip_body.c (1.5 %)",
            "calibrated");
        row("tone of the tapered body", "between its ends' tones",
            "cells follow the local d", "Gaster 1969",
            "45-body.sh 3 (+-5 %)", "independent");
        row("broadside level", "strip theory", "model-mode segments +-6 dB",
            "Norberg 2003", "45-body.sh 3", "independent");
        return;
    }
    /* a 3D flow whose file has no rows of its own */
    snprintf(v, sizeof v, "%.3f", aero_texture_getd(t, "st", 0.0));
    if (meta(t, "calibration", mb, sizeof mb) && strcmp(mb, "none")) {
        char pub[32];
        snprintf(pub, sizeof pub, "%.3f",
                 aero_texture_getd(t, "calibration_st", 0.0));
        row("St of the lateral force, as heard", v, pub,
            !strcmp(mb, "sphere") ? "Sakamoto and Haniu 1990; Kim and "
                                    "Durbin 1988"
                                  : "Roshko 1954 (cylinder St(Re))",
            !strcmp(mb, "sphere") ? "46-sphere-pitch.sh (whirled in Pd, "
                                    "+-5 %)"
                                  : "(no test for this body)",
            "calibrated");
    } else
        row("St", v, "0.2 (sphere, Re 800-2e5)",
            "Sakamoto and Haniu 1990", "not asserted", "independent");
    snprintf(v, sizeof v, "%.2f", aero_texture_getd(t, "cd", 0.0));
    row("mean Cd", v, "0.4-0.55 (sphere, subcritical)", "Achenbach 1972",
        "45-body.sh 1b", "independent");
}

void aerotex_print_matches(const aero_texture *t)
{
    char kb[32];
    const char *kind = meta(t, "kind", kb, sizeof kb);
    printf("\nwhat it matches (textures/README.md):\n");
    printf("| quantity | texture | published | source | checked by | "
           "calibrated or independent |\n|---|---|---|---|---|---|\n");
    if (stored_rows(t))
        return;
    if (!kind)
        printf("(no kind: not a texture aerotex made)\n");
    else if (!strcmp(kind, "aeolian"))
        aeolian_rows(t);
    else if (!strcmp(kind, "cavity"))
        cavity_rows(t);
    else if (!strcmp(kind, "vortex"))
        vortex_rows(t);
    else if (!strcmp(kind, "object"))
        object_rows(t);
    else
        printf("(kind %s: no published values)\n", kind);
}
