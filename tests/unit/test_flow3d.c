/* aero: tests of the 3D box flow solver (src/core/solve/flow3d.c) on tiny grids:
 * the projection is exact for its discrete operator (a random field
 * becomes divergence-free, a divergence-free field is left alone, a pure
 * gradient is removed), a uniform inflow stays uniform (no spurious
 * vorticity), a perturbed inflow stays finite and bounded with the
 * absorbing top layer, the vorticity of a known shear flow, and the
 * vorticity confinement eps h (Fedkiw, Stam & Jensen 2001): grid-scale
 * eddies of one speed get the same forcing at n and 2n cells. */
#include "unit.h"
#include "aero_air.h"
#include "aero_util.h"
#include "flow3d.h"

#include <stdlib.h>
#include <string.h>

static int make(aero_flow3d *s, int nx, int ny, int nz, double conf)
{
    aero_flow3d_params p;
    char err[256];
    memset(&p, 0, sizeof p);
    p.nx = nx;
    p.ny = ny;
    p.nz = nz;
    p.h = 0.01;
    p.nu = 0.0;
    p.confinement = conf;
    p.u_ref = 2.0;
    p.sponge = 0.15;
    if (aero_flow3d_init(s, &p, err, sizeof err)) {
        printf("  init failed: %s\n", err);
        return -1;
    }
    return 0;
}

static double max_abs(const float *a, size_t n)
{
    double m = 0.0;
    for (size_t k = 0; k < n; k++)
        if (fabs(a[k]) > m) m = fabs(a[k]);
    return m;
}

UNIT_TEST(projection)
{
    aero_flow3d s;
    uint32_t rng = 12345;
    size_t uvn, wn;
    double before, after;
    printf("projection (8 x 6 x 10)\n");
    if (make(&s, 8, 6, 10, 0.0)) return;
    uvn = s.plane * (s.nz + 2);
    wn = s.plane * (s.nz + 1);
    for (size_t k = 0; k < uvn; k++) {
        s.u[k] = (float)aero_uniform(&rng);
        s.v[k] = (float)aero_uniform(&rng);
    }
    for (size_t k = 0; k < wn; k++)
        s.w[k] = (float)(2.0 + aero_uniform(&rng));
    for (size_t k = 0; k < s.plane; k++) {
        s.in_u[k] = s.u[k];
        s.in_v[k] = s.v[k];
        s.in_w[k] = s.w[k];
    }
    before = aero_flow3d_max_divergence(&s);
    aero_flow3d_project(&s);
    after = aero_flow3d_max_divergence(&s);
    /* negative control: the random field is far from divergence-free */
    UNIT_CHECK(before > 0.5, "a random field has |div u| h up to %.3g m/s",
               before);
    /* float rounding of O(1) values: ~1e-6 */
    UNIT_CHECK(after < 1e-5, "after the projection |div u| h <= %.2g m/s",
               after);
    /* projecting again changes nothing (a projection is idempotent) */
    {
        float *copy = malloc(sizeof(float) * uvn);
        double change = 0.0;
        memcpy(copy, s.u, sizeof(float) * uvn);
        aero_flow3d_project(&s);
        for (size_t k = 0; k < uvn; k++)
            if (fabs(copy[k] - s.u[k]) > change) change = fabs(copy[k] - s.u[k]);
        UNIT_CHECK(change < 1e-5, "a divergence-free field is left alone "
                   "(largest change %.2g m/s)", change);
        free(copy);
    }
    aero_flow3d_free(&s);
}

/* a discrete gradient (Neumann at the inflow, phi = 0 on the top face)
   is removed entirely: the Poisson solve is exact for its operator */
UNIT_TEST(gradient_removed)
{
    aero_flow3d s;
    double *phi;
    uint32_t rng = 777;
    double size = 0.0, left;
    printf("a pure gradient is removed\n");
    if (make(&s, 6, 8, 7, 0.0)) return;
    phi = malloc(sizeof(double) * s.plane * s.nz);
    for (size_t c = 0; c < s.plane * s.nz; c++)
        phi[c] = aero_uniform(&rng);
    memset(s.u, 0, sizeof(float) * s.plane * (s.nz + 2));
    memset(s.v, 0, sizeof(float) * s.plane * (s.nz + 2));
    memset(s.w, 0, sizeof(float) * s.plane * (s.nz + 1));
    for (int k = 0; k < s.nz; k++)
        for (int j = 0; j < s.ny; j++)
            for (int i = 0; i < s.nx; i++) {
                int im = i ? i - 1 : s.nx - 1, jm = j ? j - 1 : s.ny - 1;
                size_t c = AERO_F3_C(&s, i, j, k);
                s.u[AERO_F3_UV(&s, i, j, k)] =
                    (float)(phi[c] - phi[AERO_F3_C(&s, im, j, k)]);
                s.v[AERO_F3_UV(&s, i, j, k)] =
                    (float)(phi[c] - phi[AERO_F3_C(&s, i, jm, k)]);
                if (k > 0)
                    s.w[c] = (float)(phi[c] - phi[c - s.plane]);
            }
    for (size_t c = 0; c < s.plane; c++)
        s.w[(size_t)s.nz * s.plane + c] =
            (float)(-2.0 * phi[(size_t)(s.nz - 1) * s.plane + c]);
    size = max_abs(s.u + s.plane, s.plane * s.nz);
    aero_flow3d_project(&s);
    left = max_abs(s.u + s.plane, s.plane * s.nz);
    left = fmax(left, max_abs(s.v + s.plane, s.plane * s.nz));
    left = fmax(left, max_abs(s.w, s.plane * (s.nz + 1)));
    UNIT_CHECK(size > 0.5 && left < 1e-5 * size,
               "gradient of size %.3g reduced to %.2g", size, left);
    free(phi);
    aero_flow3d_free(&s);
}

UNIT_TEST(uniform_flow)
{
    aero_flow3d s;
    const double U = 2.0;
    double dev = 0.0;
    printf("uniform inflow\n");
    if (make(&s, 8, 8, 12, 0.3)) return;
    for (size_t c = 0; c < s.plane * (s.nz + 1); c++)
        s.w[c] = (float)U;
    for (size_t c = 0; c < s.plane; c++)
        s.in_w[c] = (float)U;
    for (int n = 0; n < 50; n++)
        aero_flow3d_step(&s, 0.5 * 0.01 / U);
    aero_flow3d_vorticity(&s);
    for (size_t c = 0; c < s.plane * (s.nz + 1); c++)
        if (fabs(s.w[c] - U) > dev) dev = fabs(s.w[c] - U);
    UNIT_CHECK(dev < 1e-4 * U, "stays uniform: largest |w - U| = %.2g m/s",
               dev);
    UNIT_CHECK(max_abs(s.omag, s.plane * s.nz) < 1e-3 * U / 0.01,
               "no spurious vorticity: max |omega| %.2g 1/s",
               max_abs(s.omag, s.plane * s.nz));
    aero_flow3d_free(&s);
}

/* a shear u = A sin(2 pi j / ny) (divergence-free) has omega_z =
   -du/dy = -A (2 pi / L) cos(...), within the central difference's
   sin(k h)/(k h) */
UNIT_TEST(vorticity)
{
    aero_flow3d s;
    const double A = 1.0;
    double kk, want, got;
    printf("vorticity of a shear flow\n");
    if (make(&s, 8, 16, 6, 0.0)) return;
    kk = 2.0 * AERO_PI / (16 * 0.01);
    for (int k = -1; k <= s.nz; k++)
        for (int j = 0; j < s.ny; j++)
            for (int i = 0; i < s.nx; i++)
                s.u[AERO_F3_UV(&s, i, j, k)] =
                    (float)(A * sin(kk * (j + 0.5) * 0.01));
    aero_flow3d_vorticity(&s);
    got = s.oz[AERO_F3_C(&s, 3, 0, 2)];
    want = -A * kk * cos(kk * 0.5 * 0.01) * sin(kk * 0.01) / (kk * 0.01);
    UNIT_NEAR_REL(got, want, 1e-4, "omega_z at y = h/2 (1/s)");
    UNIT_CHECK(max_abs(s.ox, s.plane * s.nz) < 1e-6 &&
                   max_abs(s.oy, s.plane * s.nz) < 1e-6,
               "omega_x, omega_y zero");
    aero_flow3d_free(&s);
}

/* a strongly perturbed inflow for many steps: finite and bounded */
UNIT_TEST(turbulent_stays_bounded)
{
    aero_flow3d s;
    const double U = 2.0, dt = 0.5 * 0.01 / U;
    uint32_t rng = 99;
    double worst = 0.0;
    int ok = 1;
    printf("perturbed inflow, 1500 steps (12 x 12 x 18)\n");
    if (make(&s, 12, 12, 18, 0.3)) return;
    for (size_t c = 0; c < s.plane * (s.nz + 1); c++)
        s.w[c] = (float)U;
    for (int n = 0; n < 1500 && ok; n++) {
        /* a new random inflow every 10 steps */
        if (n % 10 == 0)
            for (size_t c = 0; c < s.plane; c++) {
                s.in_u[c] = (float)(0.5 * U * aero_uniform(&rng));
                s.in_v[c] = (float)(0.5 * U * aero_uniform(&rng));
                s.in_w[c] = (float)(U * (1.0 + 0.5 * aero_uniform(&rng)));
            }
        if (aero_flow3d_step(&s, dt)) ok = 0;
        worst = fmax(worst, max_abs(s.w, s.plane * (s.nz + 1)));
    }
    UNIT_CHECK(ok && worst < 6.0 * U, "finite, max |w| %.3g m/s (U = %g)",
               worst, U);
    UNIT_CHECK(aero_flow3d_max_divergence(&s) < 1e-5,
               "divergence-free after every step (%.2g m/s)",
               aero_flow3d_max_divergence(&s));
    aero_flow3d_free(&s);
}

/* a NaN in the velocity (a step that diverged): every step after it
   reports the divergence (-1) and none reads outside the box, with each
   advection. Before the sampler clamped a NaN departure height, the
   second step's samples were indexed from (int)NaN and crashed. */
UNIT_TEST(nan_reported)
{
    const int kinds[3] = {AERO_F3_SEMI_LAGRANGIAN, AERO_F3_MACCORMACK,
                          AERO_F3_MACCORMACK_UNLIMITED};
    printf("a NaN in the velocity is reported, every step\n");
    for (int q = 0; q < 3; q++) {
        aero_flow3d s;
        aero_flow3d_params p;
        char err[256];
        int r1, r2, r3;
        memset(&p, 0, sizeof p);
        p.nx = p.ny = 8;
        p.nz = 12;
        p.h = 0.01;
        p.u_ref = 2.0;
        p.confinement = 0.3;
        p.advection = kinds[q];
        if (aero_flow3d_init(&s, &p, err, sizeof err)) {
            UNIT_CHECK(0, "init failed: %s", err);
            continue;
        }
        for (size_t c = 0; c < s.plane * (s.nz + 1); c++)
            s.w[c] = 2.0f;
        s.w[AERO_F3_C(&s, 3, 4, 2)] = NAN;
        s.u[AERO_F3_UV(&s, 5, 1, 1)] = NAN;
        r1 = aero_flow3d_step(&s, 0.002);
        r2 = aero_flow3d_step(&s, 0.002);
        r3 = aero_flow3d_step(&s, 0.002);
        UNIT_CHECK(r1 == -1 && r2 == -1 && r3 == -1,
                   "advection %d: steps after the NaN return %d %d %d "
                   "(want -1)", kinds[q], r1, r2, r3);
        aero_flow3d_free(&s);
    }
}

UNIT_TEST(bad_params)
{
    aero_flow3d s;
    aero_flow3d_params p;
    char err[256];
    printf("bad parameters\n");
    memset(&p, 0, sizeof p);
    p.nx = 7;
    p.ny = 8;
    p.nz = 8;
    p.h = 0.01;
    UNIT_CHECK(aero_flow3d_init(&s, &p, err, sizeof err) == -1,
               "odd nx refused: %s", err);
    p.nx = 8;
    p.h = -1.0;
    UNIT_CHECK(aero_flow3d_init(&s, &p, err, sizeof err) == -1,
               "negative cell size refused: %s", err);
}

/* rms of the acceleration vorticity confinement gives a random
   grid-scale field (velocity rms ~1 m/s on 2 m/s) in a 0.1 m box of n
   cells across: one step with and one without it, from the same state */
static double confinement_accel(int n, double eps, double length)
{
    aero_flow3d a, b;
    aero_flow3d_params p;
    char err[256];
    uint32_t rng = 99;
    const double dt = 1e-5;
    double sum = 0.0;
    long count = 0;
    memset(&p, 0, sizeof p);
    p.nx = p.ny = n;
    p.nz = n + n / 2;
    p.h = 0.1 / n;
    p.u_ref = 2.0;
    p.confinement = eps;
    p.confinement_length = length;
    if (aero_flow3d_init(&a, &p, err, sizeof err)) {
        printf("  init failed: %s\n", err);
        return -1.0;
    }
    p.confinement = 0.0;
    if (aero_flow3d_init(&b, &p, err, sizeof err)) {
        aero_flow3d_free(&a);
        return -1.0;
    }
    {
        size_t uvn = a.plane * (a.nz + 2), wn = a.plane * (a.nz + 1);
        for (size_t k = 0; k < uvn; k++) {
            a.u[k] = (float)(1.7 * aero_uniform(&rng));
            a.v[k] = (float)(1.7 * aero_uniform(&rng));
        }
        for (size_t k = 0; k < wn; k++)
            a.w[k] = (float)(2.0 + 1.7 * aero_uniform(&rng));
        for (size_t k = 0; k < a.plane; k++) {
            a.in_u[k] = b.in_u[k] = 0.0f;
            a.in_v[k] = b.in_v[k] = 0.0f;
            a.in_w[k] = b.in_w[k] = 2.0f;
        }
        aero_flow3d_project(&a);
        memcpy(b.u, a.u, sizeof(float) * uvn);
        memcpy(b.v, a.v, sizeof(float) * uvn);
        memcpy(b.w, a.w, sizeof(float) * wn);
    }
    aero_flow3d_step(&a, dt);
    aero_flow3d_step(&b, dt);
    /* the lower 3/4 (below the absorbing layer), away from the inflow */
    for (int k = 2; k < 3 * a.nz / 4; k++)
        for (size_t c = 0; c < a.plane; c++) {
            size_t i = (size_t)k * a.plane + c;
            double d = (a.u[i] - b.u[i]) / dt;
            sum += d * d;
            count++;
        }
    aero_flow3d_free(&a);
    aero_flow3d_free(&b);
    return sqrt(sum / count);
}

UNIT_TEST(confinement_scales_with_h)
{
    double a16, a32, o16, o32;
    printf("vorticity confinement eps h (FSJ01)\n");
    a16 = confinement_accel(16, 4.8, 0.1);
    a32 = confinement_accel(32, 4.8, 0.1);
    UNIT_CHECK(a16 > 0.0 && a32 / a16 > 0.8 && a32 / a16 < 1.25,
               "grid-scale eddies at 32 vs 16 cells: forcing ratio %.3f "
               "(the same: 1 +- 0.25)", a32 / a16);
    /* the older form, eps U (N x omega), forced them as 1 / h */
    o16 = confinement_accel(16, 0.3, 0.0);
    o32 = confinement_accel(32, 0.3, 0.0);
    UNIT_CHECK(o32 / o16 > 1.6,
               "without h the forcing ratio is %.3f (~2: grows as 1/h)",
               o32 / o16);
}

/* the fraction of a wave v = sin(2 pi x / (8 h)) left after a uniform u
   has carried it once across the periodic box (32 cells at CFL 0.7), no
   viscosity, with the given advection: its largest |v| after over before */
static double carried_wave(int advection)
{
    aero_flow3d_params p;
    aero_flow3d s;
    char err[256];
    const double U = 1.0, h = 0.01;
    const int steps = (int)(32 / 0.7 + 0.5);
    double peak = 0.0, peak0 = 0.0;
    memset(&p, 0, sizeof p);
    p.nx = 32;
    p.ny = 4;
    p.nz = 6;
    p.h = h;
    p.advection = advection;
    if (aero_flow3d_init(&s, &p, err, sizeof err)) {
        printf("  init failed: %s\n", err);
        return -1.0;
    }
    for (int k = -1; k <= s.nz; k++)
        for (int j = 0; j < s.ny; j++)
            for (int i = 0; i < s.nx; i++) {
                size_t a = AERO_F3_UV(&s, i, j, k);
                s.u[a] = (float)U;
                s.v[a] = (float)sin(2.0 * AERO_PI * (i + 0.5) / 8.0);
                if (fabs(s.v[a]) > peak0) peak0 = fabs(s.v[a]);
            }
    memcpy(s.in_u, s.u, sizeof(float) * s.plane);
    memcpy(s.in_v, s.v, sizeof(float) * s.plane);
    for (int n = 0; n < steps; n++)
        aero_flow3d_step(&s, 0.7 * h / U);
    for (int i = 0; i < s.nx; i++) {
        double v = fabs(s.v[AERO_F3_UV(&s, i, 1, s.nz / 2)]);
        if (v > peak) peak = v;
    }
    aero_flow3d_free(&s);
    return peak / peak0;
}

/* the MacCormack limiter (Selle et al. 2008) clamps every new extremum,
   so a wave of 8 cells loses amplitude at each crest as under a
   first-order step; without it the second-order scheme keeps it */
UNIT_TEST(limiter_damping)
{
    double sl, limited, unlimited;
    printf("advection of an 8-cell wave across the box\n");
    sl = carried_wave(AERO_F3_SEMI_LAGRANGIAN);
    limited = carried_wave(AERO_F3_MACCORMACK);
    unlimited = carried_wave(AERO_F3_MACCORMACK_UNLIMITED);
    printf("  fraction left: semi-Lagrangian %.3f, limited MacCormack "
           "%.3f, unlimited %.3f\n", sl, limited, unlimited);
    UNIT_CHECK(unlimited > 0.0 && unlimited < 1.0, "unlimited MacCormack "
               "makes no new extremum here: fraction %.3f", unlimited);
    UNIT_CHECK(unlimited > limited && limited > sl, "each scheme keeps more "
               "of the wave: %.3f > %.3f > %.3f", unlimited, limited, sl);
}

UNIT_MAIN(UNIT_CASE(limiter_damping), UNIT_CASE(confinement_scales_with_h), UNIT_CASE(projection), UNIT_CASE(gradient_removed), UNIT_CASE(uniform_flow), UNIT_CASE(vorticity), UNIT_CASE(turbulent_stays_bounded), UNIT_CASE(bad_params), UNIT_CASE(nan_reported))
