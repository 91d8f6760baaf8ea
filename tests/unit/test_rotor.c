/* tests for the rotor (src/core/play/rotor.c): the tones of a static
 * propeller against Gutin's (1936) levels, the Doppler shift of the
 * blade-passing tone of a rotor flying past, bad input, block sizes and
 * two instances at once. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "airfoil_noise.h"
#include "rotor.h"

#include "clicks.h"
#include "multi_instance.h"
#include "unit.h"

#define SR 48000.0
#define PI 3.14159265358979323846

/* J_n(x) by its power series (the renderer uses Miller's recurrence) */
static double series_jn(int n, double x)
{
    double term = 1.0, sum = 0.0;
    for (int k = 1; k <= n; k++)
        term *= 0.5 * x / k;
    for (int k = 0; k < 200; k++) {
        sum += term;
        term *= -0.25 * x * x / ((k + 1.0) * (n + k + 1.0));
        if (fabs(term) < 1e-18 * fabs(sum))
            break;
    }
    return sum;
}

/* the amplitude of frequency f in x[0..n) (a whole number of its periods
   or a Hann window: `hann`) */
static double tone_amplitude(const float *x, int n, double f, int hann)
{
    double re = 0.0, im = 0.0, wsum = 0.0;
    for (int i = 0; i < n; i++) {
        double w = hann ? 0.5 - 0.5 * cos(2.0 * PI * i / n) : 1.0;
        re += w * x[i] * cos(2.0 * PI * f * i / SR);
        im += w * x[i] * sin(2.0 * PI * f * i / SR);
        wsum += w;
    }
    return 2.0 * sqrt(re * re + im * im) / wsum;
}

/* n samples of the rotor at a constant rpm, in blocks of 64 */
static void render(aero_rotor *r, float *out, int n, double rpm)
{
    float in[64];
    for (int i = 0; i < 64; i++)
        in[i] = (float)rpm;
    for (int i = 0; i < n; i += 64) {
        int m = n - i < 64 ? n - i : 64;
        aero_rotor_process(r, in, (float *[]){out + i}, m);
    }
}

/* Gutin's (1936) level of harmonic m in the English units of its usual
 * statement (Marte & Kurtz 1970, eq. for the rotational noise of a static
 * propeller):
 *   p_m = 169.3 m B R M_t / (S A) [0.76 P_h / M_t^2 - T cos(theta)]
 *         J_mB(0.8 M_t m B sin(theta))
 * p_m rms in dyn/cm^2, R and S (distance) in ft, A the disc area in ft^2,
 * P_h the power in horsepower, T the thrust in lb, theta from the
 * propeller's forward axis; 0.8 R is the effective radius. Returns Pa
 * rms. Written from the formula alone, in its units, independently of
 * the renderer's SI derivation. */
static double gutin_rms_pa(int m, int B, double R_m, double rpm,
                           double thrust_n, double torque_nm, double S_m,
                           double theta)
{
    const double ft = 0.3048, lbf = 4.448222, hp = 745.699872;
    const double c0_ft = 343.0 / ft;
    double R = R_m / ft, S = S_m / ft, A = PI * R * R;
    double omega = rpm * 2.0 * PI / 60.0;
    double Mt = omega * R / c0_ft;
    double Ph = torque_nm * omega / hp, T = thrust_n / lbf;
    double p = 169.3 * m * B * R * Mt / (S * A) *
               (0.76 * Ph / (Mt * Mt) - T * cos(theta)) *
               series_jn(m * B, 0.8 * Mt * m * B * sin(theta));
    return fabs(p) * 0.1; /* dyn/cm^2 -> Pa */
}

/* a two-bladed light-aircraft propeller, 1.9 m across at 2400 rpm (tip
 * Mach 0.70), 2000 N of thrust and 400 N m of torque, heard 30 m away at
 * 60, 90 and 120 deg from its forward axis: its first three harmonics
 * within 1.5 dB of Gutin's. One strip (Gutin's effective radius), no
 * thickness (Gutin's formula is the loading alone). */
UNIT_TEST(gutin_static_propeller)
{
    const double rpm = 2400.0, R = 0.95, d = 30.0;
    const int B = 2, N = 48000;
    const double bpf = B * rpm / 60.0; /* 80 Hz: whole periods in 1 s */
    float *out = malloc(sizeof(float) * (N + 24000));
    const double angles[3] = {60.0, 90.0, 120.0};
    for (int a = 0; a < 3; a++) {
        aero_rotor r;
        double th = angles[a] * PI / 180.0;
        aero_rotor_init(&r, SR, 1, 1u);
        aero_rotor_set_ramp_ms(&r, 0.0);
        aero_rotor_set_blades(&r, B);
        aero_rotor_set_radius(&r, R);
        aero_rotor_set_strips(&r, 1);
        aero_rotor_set_thickness(&r, 0.0);
        aero_rotor_set_noise_db(&r, -200.0); /* the tones alone */
        aero_rotor_set_thrust(&r, 2000.0);
        aero_rotor_set_torque(&r, 400.0);
        aero_rotor_set_design(&r, rpm);
        aero_ears e = aero_ears_at(d * sin(th), 0.0, d * cos(th));
        aero_rotor_set_ears(&r, &e);
        render(&r, out, N + 24000, rpm);
        for (int m = 1; m <= 3; m++) {
            double got = tone_amplitude(out + 24000, N, m * bpf, 0) /
                         sqrt(2.0);
            double want = gutin_rms_pa(m, B, R, rpm, 2000.0, 400.0, d, th);
            double db = 20.0 * log10(got / want);
            UNIT_CHECK(fabs(db) <= 1.5,
                       "theta %g deg, harmonic %d (%g Hz): %.2f dB SPL, "
                       "Gutin %.2f dB (%+.2f dB, within 1.5)",
                       angles[a], m, m * bpf, 20 * log10(got / 2e-5),
                       20 * log10(want / 2e-5), db);
        }
        aero_rotor_free(&r);
    }
    free(out);
}

/* on the axis a steady rotor makes no tone (J_mB(0) = 0, Gutin 1936) */
UNIT_TEST(silent_on_axis)
{
    aero_rotor r;
    float *out = malloc(sizeof(float) * 48000);
    aero_rotor_init(&r, SR, 1, 1u);
    aero_rotor_set_ramp_ms(&r, 0.0);
    aero_rotor_set_noise_db(&r, -200.0); /* the tones alone */
    aero_ears e = aero_ears_at(0.0, 0.0, -10.0);
    aero_rotor_set_ears(&r, &e);
    render(&r, out, 48000, 6000.0);
    double on = unit_rms(out + 24000, 24000);
    e = aero_ears_at(10.0, 0.0, 0.0);
    aero_rotor_set_ears(&r, &e);
    render(&r, out, 48000, 6000.0);
    double plane = unit_rms(out + 24000, 24000);
    UNIT_CHECK(on < 1e-4 * plane && plane > 0.0,
               "on the axis %g Pa rms, in the disc plane %g Pa", on, plane);
    aero_rotor_free(&r);
}

/* a drone rotor (2 blades, 6000 rpm: blade passing 200 Hz) flying at
 * 30 m/s straight at a listener 300 m ahead, posed every 10 ms: the
 * blade-passing tone it hears is 200 / (1 - 30/343) Hz to 0.5 % */
UNIT_TEST(flyby_doppler)
{
    aero_rotor r;
    const double v = 30.0, f0 = 200.0;
    const int N = 96000, block = 480;
    float *out = malloc(sizeof(float) * N);
    float in[480];
    double q[4] = {1, 0, 0, 0};
    aero_rotor_init(&r, SR, 1, 1u);
    aero_rotor_set_ramp_ms(&r, 0.0);
    aero_rotor_set_noise_db(&r, -200.0); /* the tone alone */
    aero_ears e = aero_ears_at(0.0, 2.0, 0.0);
    aero_rotor_set_ears(&r, &e);
    for (int i = 0; i < block; i++)
        in[i] = 6000.0f;
    for (int b = 0; b * block < N; b++) {
        double p[3] = {-300.0 + v * b * block / SR, 0.0, 0.0};
        aero_rotor_set_pose_at(&r, p, q, b ? block / SR : -1.0, 0);
        aero_rotor_process(&r, in, (float *[]){out + b * block}, block);
    }
    /* the peak near the expected frequency, in 0.01 Hz steps over the
       second half (the source 270..255 m away: cos of the angle 0.99997) */
    double want = f0 / (1.0 - v / 343.0), best = 0.0, f_best = 0.0;
    for (double f = 0.9 * want; f < 1.1 * want; f += 0.01) {
        double a = tone_amplitude(out + N / 2, N / 2, f, 1);
        if (a > best) {
            best = a;
            f_best = f;
        }
    }
    UNIT_NEAR_REL(f_best, want, 0.005,
                  "blade passing heard from a rotor approaching at 30 m/s");
    double still = tone_amplitude(out + N / 2, N / 2, f0, 1);
    UNIT_CHECK(still < 0.1 * best,
               "little left at the rest frequency: %g vs %g Pa", still,
               best);
    aero_rotor_free(&r);
    free(out);
}

/* the power of x[0..n) in [lo, hi) Hz: Hann-windowed segments of 2048,
   their one-sided periodograms averaged (Welch) */
static double band_power(const float *x, int n, double lo, double hi)
{
    enum { L = 2048 };
    double sum = 0.0, w2 = 0.0;
    int segs = 0;
    for (int i = 0; i < L; i++) {
        double w = 0.5 - 0.5 * cos(2.0 * PI * i / L);
        w2 += w * w;
    }
    for (int s0 = 0; s0 + L <= n; s0 += L / 2, segs++)
        for (int k = (int)ceil(lo * L / SR); k < hi * L / SR && k < L / 2;
             k++) {
            double re = 0.0, im = 0.0;
            for (int i = 0; i < L; i++) {
                double w = (0.5 - 0.5 * cos(2.0 * PI * i / L)) * x[s0 + i];
                re += w * cos(2.0 * PI * k * i / L);
                im -= w * sin(2.0 * PI * k * i / L);
            }
            sum += 2.0 * (re * re + im * im) / ((double)L * w2);
        }
    return segs ? sum / segs : 0.0;
}

/* the broadband of one strip is the airfoil core's spectrum (Brooks et
 * al. 1989, airfoil_noise.h) for that section, flow and observer: one
 * blade of one strip (at 0.8 R = 0.8 m, 0.8 m of span, chord 0.1 m)
 * turning at 597 rpm (50 m/s) with the thrust that needs 4 deg of angle
 * of attack (thin airfoil C_L = 2 pi alpha), heard 5 m away on the axis
 * (there the directivity does not change as it turns and the tones are
 * silent): each octave 125 Hz .. 8 kHz within 20 dB of the loudest (the
 * ones heard) within 1.5 dB of the core's three thirds. An octave further
 * below its neighbours than the band-passes' skirts fall (12 dB per
 * octave) is held up by their leakage: it is printed, not judged */
UNIT_TEST(strip_broadband_is_bpm)
{
    const double U = 50.0, rs = 0.8, span = 0.8, chord = 0.1, d = 5.0;
    const double alpha = 4.0, omega = U / rs, rpm = omega * 60.0 / (2 * PI);
    const double cl = 2.0 * PI * alpha * PI / 180.0;
    const double thrust = cl * 0.5 * 1.225 * U * U * chord * span;
    const int N = 4 * 48000, skip = 24000;
    float *out = malloc(sizeof(float) * (N + skip));
    aero_rotor r;
    aero_rotor_init(&r, SR, 1, 7u);
    aero_rotor_set_ramp_ms(&r, 0.0);
    aero_rotor_set_blades(&r, 1);
    aero_rotor_set_radius(&r, 1.0);
    aero_rotor_set_strips(&r, 1);
    aero_rotor_set_chord(&r, chord);
    aero_rotor_set_thrust(&r, thrust);
    aero_rotor_set_torque(&r, 0.0);
    aero_rotor_set_design(&r, rpm);
    aero_ears e = aero_ears_at(0.0, 0.0, d);
    aero_rotor_set_ears(&r, &e);
    render(&r, out, N + skip, rpm);
    /* the core, for the section the strip is (rotor.c: tripped, a sharp
       trailing edge 0.5 % of the chord thick at 14 deg, the outermost
       strip's rounded tip) and the ear seen from it */
    aero_airfoil a = {(float)chord, (float)span, (float)(0.005 * chord),
                      14.0f, 1, AERO_AIRFOIL_TIP_ROUNDED, (float)alpha};
    aero_airfoil_flow f = {(float)U, (float)alpha, 343.0f, 1.81e-5f / 1.225f};
    aero_airfoil_observer o = {(float)sqrt(d * d + rs * rs), 90.0f,
                               (float)(atan2(d, -rs) * 180.0 / PI)};
    float hz[27], spl[AERO_BPM_MECHANISMS * 27], tot[27];
    aero_third_octave_bands(50.0f, 20000.0f, hz, 27);
    aero_airfoil_noise_spectrum(&a, &f, &o, hz, 27, spl);
    aero_airfoil_noise_total(spl, 27, tot);
    double oct[9] = {0}, loudest = 0.0;
    for (int k = 0; k < 27; k++)
        oct[k / 3] += 4e-10 * pow(10.0, 0.1 * tot[k]);
    for (int j = 1; j <= 7; j++)
        loudest = fmax(loudest, oct[j]);
    for (int j = 1; j <= 7; j++) { /* octaves 125 Hz .. 8 kHz */
        double want = oct[j], fc = hz[3 * j + 1];
        double got = band_power(out + skip, N, fc / sqrt(2.0),
                                fc * sqrt(2.0));
        double db = 10.0 * log10(got / want);
        if (want < 0.01 * loudest) {
            printf("  info  octave %.0f Hz, %.0f dB below the loudest: "
                   "%+.2f dB\n", fc, 10 * log10(loudest / want), db);
            continue;
        }
        UNIT_CHECK(fabs(db) <= 1.5, "octave %.0f Hz: %.1f dB, the core "
                   "%.1f dB (%+.2f dB, within 1.5)", fc,
                   10 * log10(got / 4e-10), 10 * log10(want / 4e-10), db);
    }
    aero_rotor_free(&r);
    free(out);
}

/* the depth of the amplitude modulation at the blade passing, dB: the
   energy in 32 phase bins of the blade passing (phase from the rotor's
   turn, known), summed over the periods, smoothed to its mean and first
   two harmonics of the blade passing (the max over min of the raw bins
   would add the noise's own scatter, some 2.5 dB over a few seconds of
   broadband), max over min */
static double am_depth(const float *x, int n, double bpf, double t0)
{
    enum { BINS = 32 };
    double e[BINS] = {0}, c[3] = {0}, s[3] = {0}, mx = 0.0, mn = 1e300;
    for (int i = 0; i < n; i++) {
        double ph = fmod((t0 + i / SR) * bpf, 1.0);
        e[(int)(ph * BINS) % BINS] += (double)x[i] * x[i];
    }
    for (int k = 0; k < 3; k++)
        for (int b = 0; b < BINS; b++) {
            c[k] += e[b] * cos(2.0 * PI * k * (b + 0.5) / BINS) / BINS;
            s[k] += e[b] * sin(2.0 * PI * k * (b + 0.5) / BINS) / BINS;
        }
    for (int j = 0; j < 360; j++) {
        double ph = 2.0 * PI * j / 360.0, v = c[0];
        for (int k = 1; k < 3; k++)
            v += 2.0 * (c[k] * cos(k * ph) + s[k] * sin(k * ph));
        mx = fmax(mx, v);
        mn = fmin(mn, v);
    }
    return mn > 0.0 ? 10.0 * log10(mx / mn) : 99.0;
}

/* a wind turbine of the size Oerlemans and Schepers (2009) predicted and
 * measured (the GE 2.3 MW prototype of Oerlemans et al. 2007: a 94 m
 * rotor of three blades on a 100 m tower; here 16 rpm, 300 kN of thrust,
 * in an 8 m/s wind), heard on the ground 200 m from the tower at angles
 * from straight downwind to straight upwind. The swish, an amplitude
 * modulation of the broadband at the blade passing (0.8 Hz), is their
 * conclusion's: from the trailing edge's directivity and convective
 * amplification, so that it is deepest crosswind (beside the rotor's
 * plane), where the average level is lowest, and shallowest upwind and
 * downwind (on the axis). That angular variation is what is judged:
 * the depth grows from downwind to crosswind and falls again to upwind,
 * and the level falls towards crosswind. The paper's figures of depth
 * were not at hand: the depths are printed, not judged against them
 * (with the report's D_h, which vanishes across each chord's plane, the
 * depth crosswind was 20-30 dB, far deeper than the few dB turbines are
 * reported to swish; see rotor.c's ear_envelope) */
UNIT_TEST(turbine_swish)
{
    const double rpm = 16.0, bpf = 3 * rpm / 60.0;
    const int N = 5 * 48000, skip = 48000;
    float *out = malloc(sizeof(float) * (N + skip));
    /* the hub 100 m up, the axis (the thrust on the rotor: downwind)
       along +x, the wind along +x */
    double pos[3] = {0.0, 0.0, 100.0}, q[4] = {cos(PI / 4), 0.0,
                                                sin(PI / 4), 0.0};
    enum { W = 5 };
    const double deg[W] = {0.0, 45.0, 75.0, 90.0, 180.0};
    double depth[W], level[W];
    for (int w = 0; w < W; w++) {
        aero_rotor r;
        const double a = deg[w] * PI / 180.0;
        const double where[3] = {200.0 * cos(a), 200.0 * sin(a), 1.5};
        aero_rotor_init(&r, SR, 1, 3u);
        aero_rotor_set_ramp_ms(&r, 0.0);
        aero_rotor_set_blades(&r, 3);
        aero_rotor_set_radius(&r, 47.0);
        aero_rotor_set_chord(&r, 2.0);
        aero_rotor_set_hub(&r, 0.1);
        aero_rotor_set_thrust(&r, 3e5);
        aero_rotor_set_torque(&r, 1.4e6);
        aero_rotor_set_design(&r, rpm);
        aero_rotor_set_pose_at(&r, pos, q, -1.0, 0);
        aero_rotor_set_wind(&r, (const double[3]){8.0, 0.0, 0.0});
        aero_ears e = aero_ears_at(where[0], where[1], where[2]);
        aero_rotor_set_ears(&r, &e);
        render(&r, out, N + skip, rpm);
        /* the phase of the blade passing heard: the sound left the hub
           r/c0 earlier */
        double d = sqrt(200.0 * 200.0 + (100.0 - where[2]) *
                                            (100.0 - where[2]));
        depth[w] = am_depth(out + skip, N, bpf, skip / SR - d / 343.0);
        level[w] = 20.0 * log10(unit_rms(out + skip, N) / 2e-5);
        printf("    ..    %3.0f degrees from downwind: swish %5.2f dB, "
               "level %5.1f dB\n", deg[w], depth[w], level[w]);
        aero_rotor_free(&r);
    }
    UNIT_CHECK(depth[0] < depth[1] && depth[1] < depth[2] &&
                   depth[2] < depth[3] && depth[4] < depth[2],
               "swish deepest crosswind: %.2f %.2f %.2f %.2f dB from "
               "downwind to crosswind, %.2f dB upwind (Oerlemans and "
               "Schepers 2009)", depth[0], depth[1], depth[2], depth[3],
               depth[4]);
    UNIT_CHECK(level[3] < level[0] && level[3] < level[4] &&
                   level[2] < level[1],
               "level lowest crosswind: %.1f dB downwind, %.1f crosswind, "
               "%.1f upwind (Oerlemans and Schepers 2009)", level[0],
               level[3], level[4]);
    free(out);
}

/* a blade's chord and twist per radius from a small text file: the
   shipped tables read; bad tables refused with the line, the old kept;
   the strips take the table's chord, which the sound follows */
UNIT_TEST(blade_table)
{
    aero_rotor_blade b;
    char err[200];
    static const char *bad[] = {
        "0.2 0.1 10\n0.1 0.1 10\n",            /* r/R falling */
        "0.2 0.1 10\n0.2 0.1 10\n",            /* not rising */
        "0.2 nan 10\n0.5 0.1 10\n",            /* NaN */
        "0.2 0.1 inf\n0.5 0.1 10\n",           /* Inf */
        "0.2 1e9 10\n0.5 0.1 10\n",            /* an absurd chord */
        "0.2 0.1 500\n0.5 0.1 10\n",           /* an absurd twist */
        "1.5 0.1 10\n0.5 0.1 10\n",            /* r/R beyond the tip */
        "0.2 0.1 10\n",                        /* one row */
        "0.2 0.1 10 4\n0.5 0.1 10\n",          /* four numbers */
        "0.2 0.1\n0.5 0.1 10\n",               /* two */
        "0.2 0.1 ten\n0.5 0.1 10\n",           /* a word */
        "",                                    /* nothing */
    };
    int refused = 0;
    for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++)
        refused += aero_rotor_blade_parse(bad[i], &b, err, sizeof(err)) != 0
                   && err[0];
    UNIT_CHECK(refused == (int)(sizeof(bad) / sizeof(bad[0])),
               "%d of %d bad tables refused, each with why", refused,
               (int)(sizeof(bad) / sizeof(bad[0])));
    /* too many rows */
    char *many = malloc(80 * 32), *p = many;
    for (int i = 0; i < 80; i++)
        p += sprintf(p, "%g 0.1 5\n", 0.01 * (i + 1));
    UNIT_CHECK(aero_rotor_blade_parse(many, &b, err, sizeof(err)) != 0,
               "80 rows refused: %s", err);
    free(many);
    UNIT_CHECK(aero_rotor_blade_parse("# c\n\n0.2 0.1 10 # root\n"
                                      " 1 0.05 2\r\n", &b, err,
                                      sizeof(err)) == 0 && b.n == 2 &&
                   b.chord[1] == 0.05,
               "comments, blank lines and CRLF: 2 rows (%s)", err);
    /* the shipped tables */
    static const char *shipped[] = {"abstractions/turbine.blade",
                                    "abstractions/propeller.blade"};
    for (int i = 0; i < 2; i++) {
        int k = aero_rotor_blade_load(shipped[i], &b, err, sizeof(err));
        UNIT_CHECK(k == 0 && b.n >= 2, "%s read: %d rows (%s)", shipped[i],
                   b.n, err);
    }
    UNIT_CHECK(aero_rotor_blade_load("/nonexistent/x.blade", &b, err,
                                     sizeof(err)) != 0,
               "a missing file refused: %s", err);
    /* a file too big, and one not text */
    char path[] = "/tmp/aero-blade-XXXXXX";
    int fd = mkstemp(path);
    if (fd >= 0) {
        FILE *f = fdopen(fd, "wb");
        for (int i = 0; i < AERO_ROTOR_BLADE_FILE_MAX / 8 + 8; i++)
            fputs("# pad..\n", f);
        fclose(f);
        UNIT_CHECK(aero_rotor_blade_load(path, &b, err, sizeof(err)) != 0,
                   "a file over %d bytes refused: %s",
                   AERO_ROTOR_BLADE_FILE_MAX, err);
        f = fopen(path, "wb");
        fwrite("0.2 0.1 10\n\0\0\0", 1, 14, f);
        fclose(f);
        UNIT_CHECK(aero_rotor_blade_load(path, &b, err, sizeof(err)) != 0,
                   "binary data refused: %s", err);
        remove(path);
    }
    /* the strips take the table; a bad one keeps it */
    aero_rotor r;
    float *out = malloc(sizeof(float) * 48000);
    aero_rotor_init(&r, SR, 1, 9u);
    aero_rotor_set_radius(&r, 0.95);
    aero_rotor_set_thrust(&r, 2000.0);
    aero_rotor_set_torque(&r, 400.0);
    aero_rotor_set_design(&r, 2400.0);
    aero_rotor_set_pose_at(&r, (const double[3]){0.0, 0.0, 0.0},
                           (const double[4]){1.0, 0.0, 0.0, 0.0}, -1.0, 0);
    aero_ears e = aero_ears_at(20.0, 0.0, 5.0);
    aero_rotor_set_ears(&r, &e);
    render(&r, out, 48000, 2400.0);
    double before = unit_rms(out + 24000, 24000);
    aero_rotor_blade_load("abstractions/propeller.blade", &b, err,
                          sizeof(err));
    int set = aero_rotor_set_blade(&r, &b);
    /* strip 4 of 8 from the hub at 0.2 R: r/R 0.65, the table's chord
       there halfway between 0.12 and 0.11 m */
    double c_mid = r.strip[r.strips / 2].chord;
    aero_rotor_blade worse = b;
    worse.r[1] = worse.r[0];
    int kept = aero_rotor_set_blade(&r, &worse) != 0 && r.has_blade &&
               r.strip[r.strips / 2].chord == c_mid;
    render(&r, out, 48000, 2400.0);
    double after = unit_rms(out + 24000, 24000);
    UNIT_CHECK(set == 0 && fabs(c_mid - 0.115) < 1e-9 && kept,
               "the propeller's table: mid strip (r/R %.2f) chord %.3f m "
               "(the table's 0.115), a bad table refused and the old kept",
               r.strip[r.strips / 2].r / 0.95, c_mid);
    UNIT_CHECK(isfinite(after) && fabs(20.0 * log10(after / before)) > 0.1,
               "the sound follows the blade: %.4f Pa rms with the uniform "
               "0.02 m chord, %.4f Pa with the table's", before, after);
    aero_rotor_free(&r);
    free(out);
}

/* NaN, Inf and out-of-range settings are refused; a NaN or huge rpm plays
   finite sound; any block size gives the same sound */
UNIT_TEST(bad_input)
{
    aero_rotor r, s;
    float in[1000], a[4800], b[4800];
    aero_rotor_init(&r, SR, 1, 1u);
    UNIT_CHECK(aero_rotor_set_blades(&r, NAN) && aero_rotor_set_blades(&r, 0) &&
                   aero_rotor_set_blades(&r, 2.5) &&
                   aero_rotor_set_radius(&r, INFINITY) &&
                   aero_rotor_set_thrust(&r, 1e30) &&
                   aero_rotor_set_strips(&r, 99) &&
                   aero_rotor_set_design(&r, 0) && r.blades == 2,
               "bad settings refused, the old kept");
    UNIT_CHECK(aero_rotor_set_struts(&r, NAN) && aero_rotor_set_struts(&r, 0) &&
                   aero_rotor_set_struts(&r, 2.5) &&
                   aero_rotor_set_struts(&r, 1e9) &&
                   aero_rotor_set_distortion(&r, NAN) &&
                   aero_rotor_set_distortion(&r, -1.5) &&
                   aero_rotor_set_distortion(&r, INFINITY) &&
                   aero_rotor_set_wake(&r, 0) &&
                   aero_rotor_set_wake(&r, NAN) &&
                   aero_rotor_set_wake(&r, 1e30) &&
                   r.struts == AERO_ROTOR_STRUTS_DEFAULT &&
                   r.distortion == 0.0 && r.loads == 0 &&
                   r.wake == AERO_ROTOR_WAKE_DEFAULT,
               "bad inflow distortions refused, the old kept");
    /* the strongest distortion allowed, narrowest wakes, most struts:
       finite (set here, before the speeds below) */
    aero_rotor_set_struts(&r, AERO_ROTOR_STRUTS_MAX);
    aero_rotor_set_distortion(&r, AERO_ROTOR_DISTORTION_MIN);
    aero_rotor_set_wake(&r, AERO_ROTOR_WAKE_MIN);
    for (int i = 0; i < 1000; i++)
        in[i] = i % 3 == 0 ? NAN : i % 3 == 1 ? 1e30f : -1e30f;
    int clamped = aero_rotor_process(&r, in, (float *[]){a}, 1000);
    int bad = 0;
    for (int i = 0; i < 1000; i++)
        bad += !(fabs(a[i]) < 1e6);
    UNIT_CHECK(bad == 0 && clamped, "NaN and huge rpm: finite (%d bad), "
               "clamp reported", bad);
    aero_rotor_free(&r);
    /* block sizes */
    aero_rotor_init(&r, SR, 1, 1u);
    aero_rotor_init(&s, SR, 1, 1u);
    for (int i = 0; i < 1000; i++)
        in[i] = 5000.0f;
    for (int i = 0; i < 4800; i += 64)
        aero_rotor_process(&r, in, (float *[]){a + i}, 64);
    for (int i = 0; i < 4800;) {
        int m = 1 + (i * 7) % 97;
        if (m > 4800 - i)
            m = 4800 - i;
        aero_rotor_process(&s, in, (float *[]){b + i}, m);
        i += m;
    }
    /* past the first chunk (the tones rise from 0 over it, whatever its
       length) */
    double diff = 0.0;
    for (int i = 480; i < 4800; i++)
        diff = fmax(diff, fabs(a[i] - b[i]));
    UNIT_CHECK(diff < 1e-3 * unit_rms(a, 4800),
               "blocks of 64 and of 1..97 samples: largest difference %g "
               "(rms %g)", diff, unit_rms(a, 4800));
    aero_rotor_free(&r);
    aero_rotor_free(&s);
}

/* --- unsteady loading: an inflow distortion (the wakes of N struts) --- */

/* the loading of a strip at radius rs and azimuth psi, as a fraction of
 * its steady loading, stated here from rotor.h's words alone: N Gaussian
 * dips of depth a, full width at half depth wake/rs in azimuth, centred
 * on psi = 2 pi j / N, their mean taken out; and its derivative in psi */
static void dip_load(double psi, double rs, int N, double a, double wake,
                     double *f, double *df)
{
    const double sd = wake / rs / (2.0 * sqrt(2.0 * log(2.0)));
    double g = 0.0, dg = 0.0;
    for (int j = 0; j < N; j++)
        for (int img = -4; img <= 4; img++) {
            double y = remainder(psi - 2.0 * PI * j / N, 2.0 * PI) +
                       2.0 * PI * img;
            double e = exp(-0.5 * y * y / (sd * sd));
            g += e;
            dg -= y / (sd * sd) * e;
        }
    *f = 1.0 - a * (g - N * sd * sqrt(2.0 * PI) / (2.0 * PI));
    *df = -a * dg;
}

/* The direct reference: the rotor's B blades, each strip a compact force
 * (on the air: -T_s along the axis, +D_s along the blade's motion, both
 * times dip_load at the blade's azimuth) turning at omega, heard at
 * distance d in direction (theta, phi) through the far field of a moving
 * point force (Lowson 1965):
 *   p = [ r_i (dF_i/dtau + F_i/(1 - M_r) dM_r/dtau)
 *         / (4 pi c0 r^2 (1 - M_r)^2) ]  at the retarded time,
 * the retarded time of each strip solved by Newton's method, J samples
 * over a revolution; then the DFT at harmonic n = mB as the renderer's
 * coefficients (c, s) of cos(n Psi), sin(n Psi), Psi at the hub's
 * retarded time. Nothing of Gutin's or Lowson's frequency-domain algebra
 * is used. */
static void direct_harmonic(const aero_rotor *r, int N, double a,
                            double wake, double omega, double theta,
                            double phi, double d, int m, double *c,
                            double *s)
{
    enum { J = 2048 };
    const int B = r->blades, n = m * B;
    const double T = 2.0 * PI / omega;
    const double X[3] = {d * sin(theta) * cos(phi),
                         d * sin(theta) * sin(phi), d * cos(theta)};
    double re = 0.0, im = 0.0;
    for (int j = 0; j < J; j++) {
        double t = j * T / J, p = 0.0;
        for (int b = 0; b < B; b++)
            for (int q = 0; q < r->strips; q++) {
                const aero_rotor_strip *sp = &r->strip[q];
                const double rs = sp->r;
                double tau = t - d / AERO_C0, y[3], v[3], acc[3], rv[3];
                double rr = d, rh[3], Mr = 0.0;
                for (int it = 0; it < 6; it++) {
                    double psi = omega * tau + 2.0 * PI * b / B;
                    y[0] = rs * cos(psi);
                    y[1] = rs * sin(psi);
                    y[2] = 0.0;
                    v[0] = -rs * omega * sin(psi);
                    v[1] = rs * omega * cos(psi);
                    v[2] = 0.0;
                    rr = 0.0;
                    for (int i = 0; i < 3; i++) {
                        rv[i] = X[i] - y[i];
                        rr += rv[i] * rv[i];
                    }
                    rr = sqrt(rr);
                    Mr = 0.0;
                    for (int i = 0; i < 3; i++) {
                        rh[i] = rv[i] / rr;
                        Mr += v[i] * rh[i] / AERO_C0;
                    }
                    /* g(tau) = tau + r/c0 - t, g' = 1 - M_r */
                    tau -= (tau + rr / AERO_C0 - t) / (1.0 - Mr);
                }
                double psi = omega * tau + 2.0 * PI * b / B, f, df;
                y[0] = rs * cos(psi);
                y[1] = rs * sin(psi);
                v[0] = -rs * omega * sin(psi);
                v[1] = rs * omega * cos(psi);
                acc[0] = -rs * omega * omega * cos(psi);
                acc[1] = -rs * omega * omega * sin(psi);
                acc[2] = v[2] = y[2] = 0.0;
                rr = 0.0;
                for (int i = 0; i < 3; i++) {
                    rv[i] = X[i] - y[i];
                    rr += rv[i] * rv[i];
                }
                rr = sqrt(rr);
                double rv_dot = 0.0;
                for (int i = 0; i < 3; i++) {
                    rh[i] = rv[i] / rr;
                    rv_dot += rh[i] * v[i];
                }
                Mr = rv_dot / AERO_C0;
                double dMr = 0.0; /* d(v . rh)/dtau / c0 */
                for (int i = 0; i < 3; i++)
                    dMr += (acc[i] * rh[i] +
                            v[i] * (-v[i] + rh[i] * rv_dot) / rr) / AERO_C0;
                dip_load(psi, rs, N, a, wake, &f, &df);
                const double Ts = sp->thrust, Ds = sp->drag;
                const double F[3] = {-f * Ds * sin(psi), f * Ds * cos(psi),
                                     -f * Ts};
                const double dF[3] = {
                    omega * (-df * Ds * sin(psi) - f * Ds * cos(psi)),
                    omega * (df * Ds * cos(psi) - f * Ds * sin(psi)),
                    omega * (-df * Ts)};
                double num = 0.0;
                for (int i = 0; i < 3; i++)
                    num += rh[i] * (dF[i] + F[i] * dMr / (1.0 - Mr));
                p += num / (4.0 * PI * AERO_C0 * rr * (1.0 - Mr) * (1.0 - Mr));
            }
        re += p * cos(n * omega * t) / J;
        im -= p * sin(n * omega * t) / J;
    }
    /* c - i s = 2 P_n e^{i n omega d / c0} */
    double ph = n * omega * d / AERO_C0;
    *c = 2.0 * (re * cos(ph) - im * sin(ph));
    *s = -2.0 * (re * sin(ph) + im * cos(ph));
}

/* a loading harmonic's coefficient a_sigma of dip_load (its Fourier
   cosine coefficient, by the trapezoidal rule over a period: exact to
   rounding for this smooth periodic function) */
static double load_harmonic(double rs, int N, double a, double wake,
                            int sigma)
{
    enum { K = 4096 };
    double sum = 0.0, f, df;
    for (int k = 0; k < K; k++) {
        double psi = 2.0 * PI * k / K;
        dip_load(psi, rs, N, a, wake, &f, &df);
        sum += f * cos(sigma * psi);
    }
    return 2.0 * sum / K;
}

/* A fan (5 blades, 15 cm, tip Mach 0.55) behind 1 strut (its loading
 * dipping by half in the wake) and 3 (rising by half): the
 * closed form's first three harmonics (Lowson 1965's loading harmonics
 * through J_{mB -+ kN}) against the direct time-domain sum above, on the
 * axis, at 30, 70 and 90 deg, at an azimuth off the struts'; and on the
 * axis against the compact-force law p = n Omega SUM_s B T_s |a_n,s|
 * / (4 pi c0 d) (Lowson and Ollerhead 1969: only sigma = n = mB reaches
 * the axis; with 3 struts only harmonics m with mB a multiple of 3, as
 * Tyler and Sofrin 1962's rule n - kN = 0 has it). Tolerance 1e-3 of
 * each harmonic's size: the two sides differ by far-field terms of order
 * R/d and c0/(n Omega d), below 1e-4 at d = 10 km, and by the loading
 * harmonics beyond AERO_ROTOR_LOADS (below 1e-6 here); a sign or order
 * slip in the unsteady terms is of the size of the terms themselves. */
UNIT_TEST(inflow_distortion_tones)
{
    const double rpm = 12000.0, d = 1e4, wake = 0.03;
    const double omega = rpm * 2.0 * PI / 60.0, phi = 0.6;
    const double angles[4] = {0.0, 30.0, 70.0, 90.0};
    const int struts[2] = {1, 3};
    aero_rotor *r = malloc(sizeof(*r));
    for (int st = 0; st < 2; st++) {
        const int N = struts[st];
        const double a = st ? -0.5 : 0.5; /* a dip, a rise */
        aero_rotor_init(r, SR, 1, 1u);
        aero_rotor_set_blades(r, 5);
        aero_rotor_set_radius(r, 0.15);
        aero_rotor_set_chord(r, 0.05);
        aero_rotor_set_hub(r, 0.25);
        aero_rotor_set_strips(r, 4);
        aero_rotor_set_thickness(r, 0.0); /* the loading alone */
        aero_rotor_set_thrust(r, 0.6);
        aero_rotor_set_torque(r, 0.08);
        aero_rotor_set_design(r, rpm);
        UNIT_CHECK(aero_rotor_set_struts(r, N) == 0 &&
                       aero_rotor_set_distortion(r, a) == 0 &&
                       aero_rotor_set_wake(r, wake) == 0,
                   "struts %d, distortion %g, wake %g m accepted", N, a,
                   wake);
        for (int i = 0; i < 4; i++) {
            double th = angles[i] * PI / 180.0;
            for (int m = 1; m <= 3; m++) {
                double c, s, cd, sd;
                aero_rotor_harmonic_at(r, m, omega, th, phi, d, &c, &s);
                direct_harmonic(r, N, a, wake, omega, th, phi, d, m, &cd,
                                &sd);
                double size = hypot(cd, sd), err = hypot(c - cd, s - sd);
                UNIT_CHECK(err <= 1e-3 * size + 1e-12,
                           "%d struts, theta %g deg, harmonic %d: closed "
                           "form (%.6g, %.6g) Pa, direct (%.6g, %.6g) Pa: "
                           "error %.2g of %.3g",
                           N, angles[i], m, c, s, cd, sd, err / size, size);
                if (i > 0)
                    continue;
                /* on the axis: the compact-force law */
                const int n = 5 * m;
                double sum = 0.0;
                for (int q = 0; q < r->strips; q++)
                    sum += 5 * r->strip[q].thrust *
                           (n % N ? 0.0 : load_harmonic(r->strip[q].r, N, a,
                                                        wake, n));
                double want = n * omega * fabs(sum) / (4.0 * PI * AERO_C0 * d);
                UNIT_CHECK(fabs(hypot(c, s) - want) <= 1e-3 * want + 1e-12,
                           "%d struts, on the axis, harmonic %d: %.6g Pa, "
                           "n Omega T a_n / (4 pi c0 d) = %.6g Pa",
                           N, m, hypot(c, s), want);
            }
        }
        aero_rotor_free(r);
    }
    free(r);
}

/* the renderer carries the distortion's tone: a desk fan (5 blades, 15 cm,
 * 1200 rpm) behind one strut heard 2 m away on its axis, where its steady
 * tones vanish, hums at 100 Hz at the closed form's level (0.1 dB), and
 * is silent there without the strut */
UNIT_TEST(inflow_distortion_render)
{
    const double rpm = 1200.0, d = 2.0;
    const int N = 48000;
    float *out = malloc(sizeof(float) * (N + 24000));
    aero_rotor *r = malloc(sizeof(*r));
    double hum[2];
    for (int on = 0; on < 2; on++) {
        aero_rotor_init(r, SR, 1, 1u);
        aero_rotor_set_ramp_ms(r, 0.0);
        aero_rotor_set_noise_db(r, -200.0); /* the tones alone */
        aero_rotor_set_blades(r, 5);
        aero_rotor_set_radius(r, 0.15);
        aero_rotor_set_chord(r, 0.05);
        aero_rotor_set_hub(r, 0.25);
        aero_rotor_set_thrust(r, 0.6);
        aero_rotor_set_torque(r, 0.08);
        aero_rotor_set_design(r, rpm);
        aero_rotor_set_distortion(r, on ? 0.5 : 0.0);
        aero_ears e = aero_ears_at(0.0, 0.0, d);
        aero_rotor_set_ears(r, &e);
        render(r, out, N + 24000, rpm);
        hum[on] = tone_amplitude(out + 24000, N, 100.0, 0);
        if (on) {
            double want =
                aero_rotor_harmonic_amplitude(r, 1, rpm * PI / 30.0, 0.0, d);
            UNIT_CHECK(fabs(20.0 * log10(hum[1] / want)) <= 0.1,
                       "on the axis 2 m away: 100 Hz at %.2f dB SPL, the "
                       "closed form %.2f dB", 20.0 * log10(hum[1] / 2.83e-5),
                       20.0 * log10(want / 2.83e-5));
        }
        aero_rotor_free(r);
    }
    UNIT_CHECK(hum[0] < 1e-4 * hum[1],
               "without the strut %g Pa, with it %g Pa", hum[0], hum[1]);
    free(r);
    free(out);
}

/* --- two instances at once (tests/unit/multi_instance.h) --- */
static void *mi_make(int variant)
{
    aero_rotor *r = calloc(1, sizeof(*r));
    double pos[3] = {0.1 * variant, 0.0, 0.0}, q[4] = {0.9, 0.1, 0.2, 0.3};
    aero_rotor_init(r, 44100.0, 1, 5u + variant);
    aero_rotor_set_blades(r, 2 + variant);
    aero_rotor_set_pose_at(r, pos, q, -1.0, 0);
    return r;
}
static void mi_run(void *r, const float *speed, float *out, int n)
{
    float rpm[UNIT_MI_BLOCK];
    for (int i = 0; i < n && i < UNIT_MI_BLOCK; i++)
        rpm[i] = 500.0f * speed[i];
    aero_rotor_process(r, rpm, (float *[]){out}, n);
}
static void mi_drop(void *r)
{
    aero_rotor_free(r);
    free(r);
}

/* --- a start and a jump without clicks ------------------------------------ */

/* a 30 cm two-bladed rotor at 3000 rpm from the first sample (its tones
   alone: noise has no smooth waveform to hear a click in), heard 3 m off
   its disc, rendered in blocks of 64 from before its first pose.
   PLACE: placed 10 m on at 0.7 s while sounding (7 m further), then
   steady there. *rough: the largest second difference over the whole
   render (STEADY: from 0.2 s on) */
enum { SPIN_STEADY, SPIN_START, SPIN_PLACE };

static double spin_clicks(int what, double *rough)
{
    const int total = (int)(1.2 * SR);
    const long skip = what == SPIN_STEADY ? (long)(0.2 * SR) : 0;
    float *out = calloc((size_t)total, sizeof(float)), in[64];
    double q[4] = {1, 0, 0, 0}, p0[3] = {0, 0, 0}, p1[3] = {-6, 8, 0};
    aero_rotor r;
    aero_rotor_init(&r, SR, 1, 3u);
    aero_rotor_set_radius(&r, 0.15);
    aero_rotor_set_noise_db(&r, -200.0);
    aero_ears e = aero_ears_at(3.0, 0.0, 0.5);
    aero_rotor_set_ears(&r, &e);
    for (int i = 0; i < 64; i++)
        in[i] = 3000.0f;
    aero_rotor_set_pose_at(&r, p0, q, -1.0, 0);
    for (int b = 0; b < total; b += 64) {
        if (what == SPIN_PLACE && b == (int)(0.7 * SR) / 64 * 64)
            aero_rotor_set_pose_at(&r, p1, q, -1.0, 17);
        aero_rotor_process(&r, in, (float *[]){out + b},
                           total - b < 64 ? total - b : 64);
    }
    aero_rotor_free(&r);
    double c = click_ratio(out + skip, total - skip, SR);
    *rough = second_difference_peak(out + skip, total - skip);
    free(out);
    return c;
}

/* A rotor that starts sounding or is placed while sounding (`place`, a
   pose after a pause) is heard without a click, as every moving object:
   over the whole render, from before the first sample, issue 48's click
   measure within the steady spin's + 0.5 (test_aeolian_texture.c's
   scatter between two renders), and no instant rougher than 1.1 times the
   steady spin's roughest (its tones' second difference s''; a smooth fade
   f over T = AERO_GHOST_FADE_S adds 2 f' s' + f'' s, at most (pi/T)/w +
   (pi/T)^2/(2 w^2) of a tone's own s'' at w: 16 % at the 100 Hz
   fundamental, 1.6 % at its tenth harmonic, which has more s''). Before the
   fix a place tore the sound: the old place's sound stopped at once and
   the first chunk at the new place was spread over the 20 ms of delay
   between, its second difference 7000 times the steady spin's (the click
   measure, which compares 2 ms with its neighbours, reads 1.26 there: the
   tear lasts longer than its neighbours). */
UNIT_TEST(start_and_place_without_clicks)
{
    static const char *name[] = {"", "started at 3000 rpm",
                                 "placed 10 m on while sounding"};
    double steady_rough, steady = spin_clicks(SPIN_STEADY, &steady_rough);
    UNIT_CHECK(steady < 3.0, "the steady spin is smooth: %.2f", steady);
    for (int g = SPIN_START; g <= SPIN_PLACE; g++) {
        double rough, c = spin_clicks(g, &rough);
        UNIT_CHECK(c <= steady + 0.5,
                   "%s: clicks %.2f over the whole render <= %.2f steady "
                   "+ 0.5", name[g], c, steady);
        UNIT_CHECK(rough <= 1.1 * steady_rough,
                   "%s: largest second difference %.3g <= 1.1 x the steady "
                   "spin's %.3g", name[g], rough, steady_rough);
    }
}

UNIT_TEST(multi_instance)
{
    unit_multi_instance("rotor~", "tones", mi_make, mi_run, mi_drop);
}

/* the object contract (CONTRIBUTING.md): init answers -1 for a sample
   rate it cannot use and the rotor still plays, at 48 kHz */
UNIT_TEST(unusable_sample_rate)
{
    aero_rotor r;
    float in[4096], out[4096];
    for (int i = 0; i < 4096; i++)
        in[i] = 6000.0f; /* rpm */
    UNIT_CHECK(aero_rotor_init(&r, NAN, 1, 1u) == -1,
               "init at a NaN sample rate answers -1");
    for (int i = 0; i < 4096; i += 64)
        aero_rotor_process(&r, in + i, (float *[]){out + i}, 64);
    double peak = unit_finite_peak(out, 4096);
    UNIT_CHECK(peak > 0.0, "and the rotor still sounds at 6000 rpm: peak %g Pa",
               peak);
    aero_rotor_free(&r);
}

UNIT_MAIN(UNIT_CASE(gutin_static_propeller), UNIT_CASE(silent_on_axis),
          UNIT_CASE(strip_broadband_is_bpm), UNIT_CASE(turbine_swish),
          UNIT_CASE(flyby_doppler), UNIT_CASE(blade_table),
          UNIT_CASE(bad_input), UNIT_CASE(multi_instance),
          UNIT_CASE(unusable_sample_rate),
          UNIT_CASE(inflow_distortion_tones),
          UNIT_CASE(inflow_distortion_render),
          UNIT_CASE(start_and_place_without_clicks))
