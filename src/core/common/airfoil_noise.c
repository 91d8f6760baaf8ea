/* aero: airfoil self-noise after Brooks, Pope and Marcolini (1989),
 * NASA RP-1218. The report's fitted equations, written from its text. */
#include "airfoil_noise.h"

#include "aero_air.h"

#include <math.h>
#include <stddef.h>

/* the report's fits hold for alpha* 0..25 deg */
#define ALPHA_MAX_DEG 25.0
/* below this an energy is "nothing" (a floor that keeps logs finite) */
#define ENERGY_FLOOR 1e-20

static int finite_positive(double v)
{
    return isfinite(v) && v > 0;
}

static double clamp(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

static int valid(const aero_airfoil *a, const aero_airfoil_flow *f)
{
    if (!a || !f)
        return 0;
    if (!finite_positive(a->chord) || !finite_positive(a->span) ||
        !isfinite(a->te_thickness) || a->te_thickness < 0 ||
        !isfinite(a->te_angle_deg) || !isfinite(a->tip_alpha_deg))
        return 0;
    if (!finite_positive(f->speed) || !finite_positive(f->c0) ||
        !finite_positive(f->nu) || !isfinite(f->alpha_deg))
        return 0;
    /* the model is a low-Mach one (the report's data end at M 0.21) */
    return f->speed < 0.5 * f->c0;
}

static double alpha_of(const aero_airfoil_flow *f)
{
    return clamp(fabs(f->alpha_deg), 0, ALPHA_MAX_DEG);
}

/* ---- boundary-layer thickness at the trailing edge ---- */

/* zero-angle thickness and displacement thickness over the chord, from
   the chord Reynolds number (heavily tripped and untripped) */
static void zero_angle(double rc, int tripped, double *d0, double *ds0)
{
    double lg = log10(rc);
    if (tripped) {
        *d0 = pow(10, 1.892 - 0.9045 * lg + 0.0596 * lg * lg);
        *ds0 = rc <= 0.3e6
                   ? 0.0601 * pow(rc, -0.114)
                   : pow(10, 3.411 - 1.5397 * lg + 0.1059 * lg * lg);
    } else {
        *d0 = pow(10, 1.6569 - 0.9045 * lg + 0.0596 * lg * lg);
        *ds0 = pow(10, 3.0187 - 1.5397 * lg + 0.1059 * lg * lg);
    }
}

/* suction side over zero angle and 12-13
   (untripped): the boundary layer thickens with angle, fastest where
   the flow begins to separate */
static void suction_growth(double al, int tripped, double *g_delta,
                           double *g_star)
{
    if (tripped) {
        if (al <= 5) {
            *g_star = pow(10, 0.0679 * al);
            *g_delta = pow(10, 0.0311 * al);
        } else if (al <= 12.5) {
            *g_star = 0.381 * pow(10, 0.1516 * al);
            *g_delta = 0.3468 * pow(10, 0.1231 * al);
        } else {
            *g_star = 14.296 * pow(10, 0.0258 * al);
            *g_delta = 5.718 * pow(10, 0.0258 * al);
        }
    } else {
        if (al <= 7.5) {
            *g_star = pow(10, 0.0679 * al);
            *g_delta = pow(10, 0.03114 * al);
        } else if (al <= 12.5) {
            *g_star = 0.0162 * pow(10, 0.3066 * al);
            *g_delta = 0.0303 * pow(10, 0.2336 * al);
        } else {
            *g_star = 52.42 * pow(10, 0.0258 * al);
            *g_delta = 12 * pow(10, 0.0258 * al);
        }
    }
}

static void boundary_layer(const aero_airfoil *a, const aero_airfoil_flow *f,
                           double bl[6])
{
    double c = a->chord, al = alpha_of(f);
    double rc = f->speed * c / f->nu;
    double d0, ds0, gd, gs;
    zero_angle(rc, a->tripped, &d0, &ds0);
    bl[0] = d0 * c;
    bl[1] = ds0 * c;
    /* pressure side: thins with angle */
    bl[2] = bl[0] * pow(10, -0.04175 * al + 0.00106 * al * al);
    bl[3] = bl[1] * pow(10, -0.0432 * al + 0.00113 * al * al);
    suction_growth(al, a->tripped, &gd, &gs);
    bl[4] = bl[0] * gd;
    bl[5] = bl[1] * gs;
}

int aero_airfoil_boundary_layer(const aero_airfoil *a,
                                const aero_airfoil_flow *f,
                                aero_boundary_layer *out)
{
    double bl[6];
    if (!out)
        return -1;
    if (!valid(a, f)) {
        *out = (aero_boundary_layer){0, 0, 0, 0, 0, 0};
        return -1;
    }
    boundary_layer(a, f, bl);
    out->delta0 = (float)bl[0];
    out->delta_star0 = (float)bl[1];
    out->delta_p = (float)bl[2];
    out->delta_star_p = (float)bl[3];
    out->delta_s = (float)bl[4];
    out->delta_star_s = (float)bl[5];
    return 0;
}

/* ---- directivity (appendix B) ---- */

double aero_airfoil_directivity_high(double mach, double theta_deg,
                                     double phi_deg)
{
    double th = theta_deg * AERO_PI / 180, ph = phi_deg * AERO_PI / 180;
    double mc = 0.8 * mach; /* the wake's convection Mach number */
    double s = sin(th / 2), sp = sin(ph);
    double d1 = 1 + mach * cos(th), d2 = 1 + (mach - mc) * cos(th);
    double v;
    if (!isfinite(th) || !isfinite(ph) || !isfinite(mach) || d1 <= 0)
        return 0;
    v = 2 * s * s * sp * sp / (d1 * d2 * d2);
    return isfinite(v) ? v : 0;
}

double aero_airfoil_directivity_low(double mach, double theta_deg,
                                    double phi_deg)
{
    double th = theta_deg * AERO_PI / 180, ph = phi_deg * AERO_PI / 180;
    double s = sin(th), sp = sin(ph), d1 = 1 + mach * cos(th);
    double v;
    if (!isfinite(th) || !isfinite(ph) || !isfinite(mach) || d1 <= 0)
        return 0;
    v = s * s * sp * sp / (d1 * d1 * d1 * d1);
    return isfinite(v) ? v : 0;
}

/* ---- TBL-TE and separation spectral shapes ---- */

/* the A curve's bounds over a = |log10(St / St_peak)| */
static double a_min(double a)
{
    if (a < 0.204)
        return sqrt(fmax(67.552 - 886.788 * a * a, 0)) - 8.219;
    if (a <= 0.244)
        return -32.665 * a + 3.981;
    return -142.795 * a * a * a + 103.656 * a * a - 57.757 * a + 6.006;
}

static double a_max(double a)
{
    if (a < 0.13)
        return sqrt(fmax(67.552 - 886.788 * a * a, 0)) - 8.219;
    if (a <= 0.321)
        return -15.901 * a + 1.098;
    return -4.669 * a * a * a + 3.491 * a * a - 16.699 * a + 1.149;
}

/* the spectrum's half-width in decades at -20 dB over the chord Reynolds
   number: `low` below Rc 9.52e4, `high` above 8.57e5, a parabola in Rc
   of curvature k between */
static double width_20db(double rc, double low, double high, double k)
{
    if (rc < 9.52e4)
        return low;
    if (rc <= 8.57e5)
        return k * (rc - 8.57e5) * (rc - 8.57e5) + high;
    return high;
}

typedef double (*bound_fn)(double);

/* a shape at x decades from its peak: between its bounds lo and hi, in
   the proportion that puts -20 dB at x0 */
static double between_bounds(double x, double x0, bound_fn lo, bound_fn hi)
{
    double r = (-20 - lo(x0)) / (hi(x0) - lo(x0));
    return lo(x) + r * (hi(x) - lo(x));
}

/* A at a Strouhal ratio and chord Reynolds number rc: the spectrum is as
   wide as its -20 dB point a0(rc) says */
static double shape_a(double st_ratio, double rc)
{
    return between_bounds(fabs(log10(st_ratio)),
                          width_20db(rc, 0.57, 1.13, -9.57e-13), a_min,
                          a_max);
}

/* the B curve's bounds */
static double b_min(double b)
{
    if (b < 0.13)
        return sqrt(fmax(16.888 - 886.788 * b * b, 0)) - 4.109;
    if (b <= 0.145)
        return -83.607 * b + 8.138;
    return -817.810 * b * b * b + 355.210 * b * b - 135.024 * b + 10.619;
}

static double b_max(double b)
{
    if (b < 0.10)
        return sqrt(fmax(16.888 - 886.788 * b * b, 0)) - 4.109;
    if (b <= 0.187)
        return -31.330 * b + 1.854;
    return -80.541 * b * b * b + 44.174 * b * b - 39.381 * b + 2.344;
}

/* B, the separation term's narrower shape */
static double shape_b(double st_ratio, double rc)
{
    return between_bounds(fabs(log10(st_ratio)),
                          width_20db(rc, 0.30, 0.56, -4.48e-13), b_min,
                          b_max);
}

/* the amplitude K1 over the chord Reynolds number */
static double k1_of(double rc)
{
    if (rc < 2.47e5)
        return -4.31 * log10(rc) + 156.3;
    if (rc <= 8.0e5)
        return -9.0 * log10(rc) + 181.6;
    return 128.5;
}

/* the separation term's amplitude K2 - K1 over angle and Mach number,
   nothing below gamma0 - gamma, a rise to -12 dB above */
static double k2_minus_k1(double al, double mach)
{
    double gamma = 27.094 * mach + 3.31, gamma0 = 23.43 * mach + 4.651;
    double beta = 72.65 * mach + 10.74, beta0 = -34.19 * mach - 13.82;
    double x;
    if (al < gamma0 - gamma)
        return -1000;
    if (al > gamma0 + gamma)
        return -12;
    x = (beta / gamma) * (al - gamma0);
    return sqrt(fmax(beta * beta - x * x, 0)) + beta0;
}

/* ---- the mechanisms ---- */

typedef struct {
    double u, mach, nu, rc, al, dh, dl, span, r2;
    double bl[6]; /* as aero_boundary_layer, in its order */
} conditions;

static double level(double energy)
{
    return energy > ENERGY_FLOOR ? 10 * log10(energy) : AERO_BPM_SILENT_DB;
}

static float to_db(double spl)
{
    if (!isfinite(spl) || spl < AERO_BPM_SILENT_DB)
        return AERO_BPM_SILENT_DB;
    return (float)spl;
}

static void silence(float *o, int n)
{
    for (int i = 0; i < n; i++)
        o[i] = AERO_BPM_SILENT_DB;
}

/* the separation term's peak Strouhal number St2 over St1 */
static double st2_over_st1(double al)
{
    if (al < 1.33)
        return 1;
    if (al <= 12.5)
        return pow(10, 0.0054 * (al - 1.33) * (al - 1.33));
    return 4.72;
}

/* the pressure side's amplitude falls with angle while its
   displacement-thickness Reynolds number is low */
static double delta_k1(double al, double re_dsp)
{
    if (re_dsp > 5000 || re_dsp <= 0)
        return 0;
    return al * (1.43 * log10(re_dsp) - 5.29);
}

/* TBL-TE both sides and separation at each band; past
   alpha0 = min(gamma0, 12.5 deg) the section is stalled:
   separation only, with the wider A of three times the Reynolds number
   and the low-frequency directivity */
static void tbl_te(const conditions *k, const float *hz, int n, float *out)
{
    double m5 = pow(k->mach, 5), dsp = k->bl[3], dss = k->bl[5];
    double st1 = 0.02 * pow(k->mach, -0.6);
    double st2 = st1 * st2_over_st1(k->al);
    double st1m = (st1 + st2) / 2;
    double k1 = k1_of(k->rc), k2 = k1 + k2_minus_k1(k->al, k->mach);
    double dk1 = delta_k1(k->al, k->u * dsp / k->nu);
    double base_p = level(dsp * m5 * k->span * k->dh / k->r2);
    double base_s = level(dss * m5 * k->span * k->dh / k->r2);
    double base_l = level(dss * m5 * k->span * k->dl / k->r2);
    int stalled = k->al > fmin(23.43 * k->mach + 4.651, 12.5);
    for (int i = 0; i < n; i++) {
        double stp = hz[i] * dsp / k->u, sts = hz[i] * dss / k->u;
        float *p = out + AERO_BPM_TBL_PRESSURE * n + i;
        float *s = out + AERO_BPM_TBL_SUCTION * n + i;
        float *a = out + AERO_BPM_SEPARATION * n + i;
        if (stalled) {
            *p = AERO_BPM_SILENT_DB;
            *s = AERO_BPM_SILENT_DB;
            *a = to_db(base_l + shape_a(sts / st2, 3 * k->rc) + k2);
        } else {
            *p = to_db(base_p + shape_a(stp / st1, k->rc) + (k1 - 3) + dk1);
            *s = to_db(base_s + shape_a(sts / st1m, k->rc) + (k1 - 3));
            *a = to_db(base_s + shape_b(sts / st2, k->rc) + k2);
        }
    }
}

/* ---- LBL-VS ---- */

/* spectral shape over e = St' / St'_peak */
static double g1_of(double e)
{
    double lg = log10(e);
    if (e <= 0.5974)
        return 39.8 * lg - 11.12;
    if (e <= 0.8545)
        return 98.409 * lg + 2.0;
    if (e <= 1.17)
        return -5.076 + sqrt(fmax(2.484 - 506.25 * lg * lg, 0));
    if (e <= 1.674)
        return -98.409 * lg + 2.0;
    return -39.8 * lg - 11.12;
}

/* the peak level over d = Rc / (Rc)0 */
static double g2_of(double d)
{
    double lg = log10(d);
    if (d <= 0.3237)
        return 77.852 * lg + 15.328;
    if (d <= 0.5689)
        return 65.188 * lg + 9.125;
    if (d <= 1.7579)
        return -114.052 * lg * lg;
    if (d <= 3.0889)
        return -65.188 * lg + 9.125;
    return -77.852 * lg + 15.328;
}

/* tones of the laminar boundary layer, on the pressure
   side's thickness; an untripped section only */
static void lbl_vs(const conditions *k, int tripped, const float *hz, int n,
                   float *out)
{
    double st1p, stpk, rc0, g, base;
    float *o = out + AERO_BPM_LBL_VS * n;
    if (tripped) {
        silence(o, n);
        return;
    }
    if (k->rc <= 1.3e5)
        st1p = 0.18;
    else if (k->rc <= 4.0e5)
        st1p = 0.001756 * pow(k->rc, 0.3931);
    else
        st1p = 0.28;
    stpk = st1p * pow(10, -0.04 * k->al);
    rc0 = k->al <= 3 ? pow(10, 0.215 * k->al + 4.978)
                     : pow(10, 0.120 * k->al + 5.263);
    g = g2_of(k->rc / rc0) + 171.04 - 3.03 * k->al; /* G2 + G3 */
    base = level(k->bl[2] * pow(k->mach, 5) * k->span * k->dh / k->r2);
    for (int i = 0; i < n; i++) {
        double st = hz[i] * k->bl[2] / k->u;
        o[i] = to_db(base + g1_of(st / stpk) + g);
    }
}

/* ---- trailing-edge bluntness ---- */

/* the peak Strouhal number over h / delta*_avg */
static double bluntness_peak(double hd, double psi)
{
    if (hd >= 0.2)
        return (0.212 - 0.0045 * psi) /
               (1 + 0.235 / hd - 0.0132 / (hd * hd));
    return 0.1 * hd + 0.095 - 0.00243 * psi;
}

/* the spectral shape G5 at Psi = 14 deg, over eta, the
   log10 of the Strouhal number on h over its peak */
static double g5_shape(double hd, double eta)
{
    double mu, m, eta0, kk;
    if (hd < 0.25)
        mu = 0.1221;
    else if (hd < 0.62)
        mu = -0.2175 * hd + 0.1755;
    else if (hd < 1.15)
        mu = -0.0308 * hd + 0.0596;
    else
        mu = 0.0242;
    if (hd <= 0.02)
        m = 0;
    else if (hd <= 0.5)
        m = 68.724 * hd - 1.35;
    else if (hd <= 0.62)
        m = 308.475 * hd - 121.23;
    else if (hd <= 1.15)
        m = 224.811 * hd - 69.35;
    else if (hd <= 1.2)
        m = 1583.28 * hd - 1631.59;
    else
        m = 268.344;
    eta0 = -sqrt(m * m * mu * mu * mu * mu / (6.25 + m * m * mu * mu));
    kk = 2.5 * sqrt(fmax(1 - (eta0 / mu) * (eta0 / mu), 0)) - 2.5 - m * eta0;
    if (eta < eta0)
        return m * eta + kk;
    if (eta < 0)
        return 2.5 * sqrt(fmax(1 - (eta / mu) * (eta / mu), 0)) - 2.5;
    if (eta < 0.03616)
        return sqrt(fmax(1.5625 - 1194.99 * eta * eta, 0)) - 1.25;
    return -155.543 * eta + 4.375;
}

/* vortex shedding from a blunt trailing edge of thickness h */
static void bluntness(const conditions *k, double h, double psi,
                      const float *hz, int n, float *out)
{
    float *o = out + AERO_BPM_BLUNTNESS * n;
    double dsa = (k->bl[3] + k->bl[5]) / 2, hd, pk, g4, hd0, base;
    if (!(h > 0) || !(dsa > 0)) {
        silence(o, n);
        return;
    }
    psi = clamp(psi, 0, 90);
    hd = h / dsa;
    pk = bluntness_peak(hd, psi);
    if (!(pk > 0)) {
        silence(o, n);
        return;
    }
    g4 = hd <= 5 ? 17.5 * log10(hd) + 157.5 - 1.114 * psi
                 : 169.7 - 1.114 * psi;
    hd0 = 6.724 * hd * hd - 4.019 * hd + 1.107;
    base = level(h * pow(k->mach, 5.5) * k->span * k->dh / k->r2);
    for (int i = 0; i < n; i++) {
        double eta = log10(hz[i] * h / k->u / pk);
        double g14 = g5_shape(hd, eta), g0 = g5_shape(hd0, eta);
        double g5 = g0 + 0.0714 * psi * (g14 - g0);
        if (g5 > 0) /* the shape's peak is its 0 dB */
            g5 = 0;
        o[i] = to_db(base + g4 + g5);
    }
}

/* ---- tip vortex formation ---- */

/* the tip vortex's separated flow, of spanwise extent l,
   at the maximum velocity about the tip */
static void tip(const conditions *k, const aero_airfoil *a, double c0,
                const float *hz, int n, float *out)
{
    float *o = out + AERO_BPM_TIP * n;
    double at = clamp(fabs(a->tip_alpha_deg), 0, ALPHA_MAX_DEG), l, mmax;
    double base;
    if (a->tip != AERO_AIRFOIL_TIP_ROUNDED &&
        a->tip != AERO_AIRFOIL_TIP_FLAT) {
        silence(o, n);
        return;
    }
    if (a->tip == AERO_AIRFOIL_TIP_ROUNDED)
        l = 0.008 * at * a->chord;
    else
        l = (at <= 2 ? 0.0230 + 0.0169 * at : 0.0378 + 0.0095 * at) *
            a->chord;
    mmax = k->mach * (1 + 0.036 * at);
    base = level(k->mach * k->mach * mmax * mmax * mmax * l * l * k->dh /
                 k->r2);
    for (int i = 0; i < n; i++) {
        double st = hz[i] * l / (mmax * c0), x;
        if (!(st > 0)) {
            o[i] = AERO_BPM_SILENT_DB;
            continue;
        }
        x = log10(st) + 0.3;
        o[i] = to_db(base - 30.5 * x * x + 126);
    }
}

int aero_airfoil_noise_spectrum(const aero_airfoil *a,
                                const aero_airfoil_flow *f,
                                const aero_airfoil_observer *o,
                                const float *band_hz, int n_bands,
                                float *spl_db)
{
    conditions k;
    int ok = valid(a, f) && o && finite_positive(o->r) &&
             isfinite(o->theta_deg) && isfinite(o->phi_deg) && band_hz;
    if (!spl_db || n_bands <= 0)
        return -1;
    for (int i = 0; ok && i < n_bands; i++)
        ok = finite_positive(band_hz[i]);
    if (!ok) {
        silence(spl_db, AERO_BPM_MECHANISMS * n_bands);
        return -1;
    }
    k.u = f->speed;
    k.mach = f->speed / f->c0;
    k.nu = f->nu;
    k.rc = f->speed * a->chord / f->nu;
    k.al = alpha_of(f);
    k.dh = aero_airfoil_directivity_high(k.mach, o->theta_deg, o->phi_deg);
    k.dl = aero_airfoil_directivity_low(k.mach, o->theta_deg, o->phi_deg);
    k.span = a->span;
    k.r2 = (double)o->r * o->r;
    boundary_layer(a, f, k.bl);
    tbl_te(&k, band_hz, n_bands, spl_db);
    lbl_vs(&k, a->tripped, band_hz, n_bands, spl_db);
    bluntness(&k, a->te_thickness, a->te_angle_deg, band_hz, n_bands, spl_db);
    tip(&k, a, f->c0, band_hz, n_bands, spl_db);
    return 0;
}

void aero_airfoil_noise_total(const float *spl_db, int n_bands,
                              float *total_db)
{
    if (!spl_db || !total_db)
        return;
    for (int i = 0; i < n_bands; i++) {
        double e = 0;
        for (int m = 0; m < AERO_BPM_MECHANISMS; m++) {
            double v = spl_db[m * n_bands + i];
            if (isfinite(v) && v > AERO_BPM_SILENT_DB)
                e += pow(10, v / 10);
        }
        total_db[i] = to_db(level(e));
    }
}

int aero_third_octave_bands(float lo_hz, float hi_hz, float *band_hz,
                            int max)
{
    int n = 0;
    if (!band_hz || max <= 0 || !finite_positive(lo_hz) ||
        !finite_positive(hi_hz) || hi_hz < lo_hz)
        return 0;
    /* band b has its centre at 10^(b/10) Hz (1 kHz is b = 30); a
       band whose named (rounded) centre is an end counts: 19.95 Hz is
       "20 Hz" (a twentieth of a band's slack) */
    for (int b = (int)ceil(10 * log10(lo_hz) - 0.05); n < max; b++) {
        double fc = pow(10, b / 10.0);
        if (10 * log10(fc / hi_hz) > 0.05)
            break;
        band_hz[n++] = (float)fc;
    }
    return n;
}
