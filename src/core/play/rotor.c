/* aero: a rotor's tones from Gutin's closed form per strip, heard from its
 * moving hub (see rotor.h). */
#include "rotor.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "aero_air.h"
#include "aero_lanes.h"
#include "airfoil_noise.h"
#include "ghost_fade.h"

/* area of a NACA four-digit section: 0.685 t c (Abbott & von Doenhoff
   1959), the strip's displaced volume per unit span */
#define SECTION_AREA 0.685
/* harmonics below this fraction of the strongest are not rendered */
#define HARMONIC_FLOOR 1e-4 /* -80 dB */
#define TWO_PI (2.0 * AERO_PI)

static void noise_bank(aero_rotor *r);

/* --- geometry ------------------------------------------------------------- */

/* the strips: centres of equal annuli from the hub to the tip; one strip
   at Gutin's (1936) effective radius 0.8 R. Thrust and drag per strip ~
   r^2 dr (the local dynamic pressure), summing to the rotor's thrust and
   torque over the B blades. */
/* the blade table at r/R = x: its chord (m) and twist (rad), linear
   between rows, held beyond the ends */
static void blade_at(const aero_rotor_blade *b, double x, double *chord,
                     double *twist)
{
    int i = 0;
    double f = 0.0;
    if (x <= b->r[0])
        i = 0;
    else if (x >= b->r[b->n - 1]) {
        i = b->n - 2;
        f = 1.0;
    } else {
        while (i < b->n - 2 && x > b->r[i + 1])
            i++;
        f = (x - b->r[i]) / (b->r[i + 1] - b->r[i]);
    }
    *chord = b->chord[i] + f * (b->chord[i + 1] - b->chord[i]);
    *twist = (b->twist[i] + f * (b->twist[i + 1] - b->twist[i])) * AERO_PI /
             180.0;
}

/* the inflow distortion's loading harmonics per strip (rotor.h): N
   Gaussian dips of depth a (a < 0: rises) and standard deviation
   sd = wake / (2.355 r_s) in azimuth; their sum's Fourier coefficient at
   order k N, its mean taken out, is
   a_k = -a N sd sqrt(2/pi) exp(-(k N sd)^2 / 2) (exact for the periodic
   sum of the Gaussians). Kept: k up to the last whose a_k reaches 1e-5 a
   at some strip (-100 dB) */
static void distortion_layout(aero_rotor *r)
{
    const int N = r->struts;
    const double a = r->distortion;
    r->loads = 0;
    for (int q = 0; q < r->strips; q++) {
        aero_rotor_strip *sp = &r->strip[q];
        const double sd = r->wake / (2.0 * sqrt(2.0 * log(2.0)) * sp->r);
        const double first = -a * N * sd * sqrt(2.0 / AERO_PI);
        for (int k = 1; k <= AERO_ROTOR_LOADS; k++) {
            const double x = k * N * sd;
            sp->load[k - 1] = a != 0.0 ? 0.5 * first * exp(-0.5 * x * x)
                                       : 0.0;
            if (fabs(sp->load[k - 1]) > 0.5e-5 * fabs(a) && k > r->loads)
                r->loads = k;
        }
    }
}

static void layout(aero_rotor *r)
{
    const int N = r->strips, B = r->blades;
    const double R = r->radius, h = r->hub;
    const double dr = R * (1.0 - h) / N;
    r->layout++; /* the strip sums are stale */
    double w_sum = 0.0, q_arm = 0.0;
    for (int s = 0; s < N; s++) {
        double rs = N == 1 ? 0.8 * R : R * (h + (1.0 - h) * (s + 0.5) / N);
        r->strip[s].r = rs;
        r->strip[s].thrust = rs * rs; /* weights for now */
        r->strip[s].chord = r->chord;
        r->strip[s].twist = 0.0;
        if (r->has_blade)
            blade_at(&r->blade, rs / R, &r->strip[s].chord,
                     &r->strip[s].twist);
        w_sum += rs * rs;
    }
    for (int s = 0; s < N; s++) {
        double w = r->strip[s].thrust / w_sum, c = r->strip[s].chord;
        r->strip[s].thrust = r->thrust * w / B;
        q_arm += w * r->strip[s].r;
        r->strip[s].volume = SECTION_AREA * r->thickness * c * c *
                             (N == 1 ? R * (1.0 - h) : dr);
    }
    /* the drag follows the same r^2 weights: D_s = Q w_s / (B sum w r) */
    for (int s = 0; s < N; s++) {
        double w = r->strip[s].r * r->strip[s].r / w_sum;
        r->strip[s].drag = r->torque * w / (B * q_arm);
    }
    distortion_layout(r);
}

/* --- the blade's table ------------------------------------------------------ */

static int blade_check(const aero_rotor_blade *b, char *err, size_t errlen)
{
    if (b->n < 2 || b->n > AERO_ROTOR_BLADE_ROWS_MAX) {
        snprintf(err, errlen, "%d rows (a blade takes 2..%d)", b->n,
                 AERO_ROTOR_BLADE_ROWS_MAX);
        return -1;
    }
    for (int i = 0; i < b->n; i++) {
        if (!(b->r[i] >= 0.0 && b->r[i] <= 1.0) ||
            !(b->chord[i] >= AERO_ROTOR_CHORD_MIN &&
              b->chord[i] <= AERO_ROTOR_CHORD_MAX) ||
            !(fabs(b->twist[i]) <= AERO_ROTOR_TWIST_MAX)) {
            snprintf(err, errlen, "row %d: r/R %g, chord %g m, twist %g "
                     "deg out of range (0..1, %g..%g m, -%g..%g deg)", i + 1,
                     b->r[i], b->chord[i], b->twist[i], AERO_ROTOR_CHORD_MIN,
                     AERO_ROTOR_CHORD_MAX, AERO_ROTOR_TWIST_MAX,
                     AERO_ROTOR_TWIST_MAX);
            return -1;
        }
        if (i > 0 && !(b->r[i] > b->r[i - 1])) {
            snprintf(err, errlen, "row %d: r/R %g does not rise from %g",
                     i + 1, b->r[i], b->r[i - 1]);
            return -1;
        }
    }
    return 0;
}

int aero_rotor_set_blade(aero_rotor *r, const aero_rotor_blade *b)
{
    char err[160];
    if (!b) {
        r->has_blade = 0;
        layout(r);
        return 0;
    }
    if (blade_check(b, err, sizeof(err)))
        return -1;
    r->blade = *b;
    r->has_blade = 1;
    layout(r);
    return 0;
}

int aero_rotor_blade_parse(const char *text, aero_rotor_blade *b, char *err,
                           size_t errlen)
{
    int line = 0;
    memset(b, 0, sizeof(*b));
    if (errlen)
        err[0] = 0;
    for (const char *p = text; *p;) {
        const char *end = strchr(p, '\n');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        char buf[256], *c, *q;
        double v[3];
        int k = 0;
        line++;
        if (len >= sizeof(buf)) {
            snprintf(err, errlen, "line %d: longer than %d characters", line,
                     (int)sizeof(buf) - 1);
            return -1;
        }
        memcpy(buf, p, len);
        buf[len] = 0;
        p += len + (end ? 1 : 0);
        if ((c = strchr(buf, '#')))
            *c = 0;
        for (c = buf; k <= 3;) {
            while (*c == ' ' || *c == '\t' || *c == '\r')
                c++;
            if (!*c)
                break;
            if (k == 3) {
                k = 4; /* a fourth field */
                break;
            }
            v[k] = strtod(c, &q);
            if (q == c || (*q && *q != ' ' && *q != '\t' && *q != '\r') ||
                !aero_is_finite(v[k])) {
                k = -1;
                break;
            }
            k++;
            c = q;
        }
        if (k == 0)
            continue; /* blank or a comment */
        if (k != 3) {
            snprintf(err, errlen, "line %d: not three finite numbers "
                     "(r/R chord twist_deg)", line);
            return -1;
        }
        if (b->n >= AERO_ROTOR_BLADE_ROWS_MAX) {
            snprintf(err, errlen, "line %d: more than %d rows", line,
                     AERO_ROTOR_BLADE_ROWS_MAX);
            return -1;
        }
        b->r[b->n] = v[0];
        b->chord[b->n] = v[1];
        b->twist[b->n] = v[2];
        b->n++;
        if (b->n >= 2 && blade_check(b, err, errlen)) {
            char why[160];
            snprintf(why, sizeof(why), "%s", err);
            snprintf(err, errlen, "line %d: %s", line, why);
            return -1;
        }
    }
    if (blade_check(b, err, errlen))
        return -1;
    if (errlen)
        err[0] = 0;
    return 0;
}

int aero_rotor_blade_load(const char *path, aero_rotor_blade *b, char *err,
                          size_t errlen)
{
    FILE *f = fopen(path, "rb");
    char *text;
    size_t n;
    memset(b, 0, sizeof(*b));
    if (!f) {
        snprintf(err, errlen, "can't open %s", path);
        return -1;
    }
    text = malloc(AERO_ROTOR_BLADE_FILE_MAX + 1);
    if (!text) {
        fclose(f);
        snprintf(err, errlen, "out of memory reading %s", path);
        return -1;
    }
    n = fread(text, 1, AERO_ROTOR_BLADE_FILE_MAX + 1, f);
    fclose(f);
    if (n > AERO_ROTOR_BLADE_FILE_MAX) {
        free(text);
        snprintf(err, errlen, "%s is larger than %d bytes: not a blade "
                 "table", path, AERO_ROTOR_BLADE_FILE_MAX);
        return -1;
    }
    text[n] = 0;
    if (memchr(text, 0, n)) {
        free(text);
        snprintf(err, errlen, "%s is not text (a blade table is lines of "
                 "r/R chord twist_deg)", path);
        return -1;
    }
    int k = aero_rotor_blade_parse(text, b, err, errlen);
    free(text);
    return k;
}

/* --- life cycle ------------------------------------------------------------ */

int aero_rotor_init(aero_rotor *r, double sample_rate, int n_ears,
                    uint32_t seed)
{
    static const double unturned[7] = {0, 0, 0, 1, 0, 0, 0};
    memset(r, 0, sizeof(*r));
    r->blades = AERO_ROTOR_BLADES_DEFAULT;
    r->strips = AERO_ROTOR_STRIPS_DEFAULT;
    r->radius = AERO_ROTOR_RADIUS_DEFAULT;
    r->chord = AERO_ROTOR_CHORD_DEFAULT;
    r->thickness = AERO_ROTOR_THICKNESS_DEFAULT;
    r->hub = AERO_ROTOR_HUB_DEFAULT;
    r->thrust = AERO_ROTOR_THRUST_DEFAULT;
    r->torque = AERO_ROTOR_TORQUE_DEFAULT;
    r->design_rpm = AERO_ROTOR_DESIGN_DEFAULT;
    r->noise_gain = pow(10.0, AERO_ROTOR_NOISE_DB_DEFAULT / 20.0);
    r->struts = AERO_ROTOR_STRUTS_DEFAULT;
    r->distortion = AERO_ROTOR_DISTORTION_DEFAULT;
    r->wake = AERO_ROTOR_WAKE_DEFAULT;
    layout(r);
    memcpy(r->pose, unturned, sizeof(unturned));
    aero_pose_path_jump(&r->path, 7, unturned);
    int sr_ok = sample_rate >= AERO_MOVING_SR_MIN &&
                sample_rate <= AERO_MOVING_SR_MAX;
    int k = aero_moving_player_init(&r->base, sr_ok ? sample_rate : 48000.0,
                                    n_ears, seed, AERO_ROTOR_CHUNK,
                                    AERO_ROTOR_MAX_DELAY_S);
    noise_bank(r);
    return k || !sr_ok ? -1 : 0;
}

void aero_rotor_free(aero_rotor *r)
{
    aero_moving_player_free(&r->base);
}

/* --- settings -------------------------------------------------------------- */

int aero_rotor_set_sample_rate(aero_rotor *r, double sr)
{
    int k = aero_moving_player_set_sample_rate(&r->base, sr);
    if (k == 1) {
        r->primed = 0; /* new rings: the sound starts again from 0 */
        memset(r->ghost, 0, sizeof(r->ghost));
        noise_bank(r);
    }
    return k < 0 ? -1 : 0;
}

/* a setting within lo..hi, then the strips laid out again */
static int set_geometry(aero_rotor *r, double *field, double v, double lo,
                        double hi)
{
    if (!(v >= lo && v <= hi))
        return -1;
    *field = v;
    layout(r);
    return 0;
}

static int set_whole(aero_rotor *r, int *field, double v, int lo, int hi)
{
    if (!(v >= lo && v <= hi) || v != floor(v))
        return -1;
    *field = (int)v;
    layout(r);
    return 0;
}

int aero_rotor_set_blades(aero_rotor *r, double blades)
{
    return set_whole(r, &r->blades, blades, AERO_ROTOR_BLADES_MIN,
                     AERO_ROTOR_BLADES_MAX);
}

int aero_rotor_set_strips(aero_rotor *r, double strips)
{
    return set_whole(r, &r->strips, strips, AERO_ROTOR_STRIPS_MIN,
                     AERO_ROTOR_STRIPS_MAX);
}

int aero_rotor_set_radius(aero_rotor *r, double m)
{
    return set_geometry(r, &r->radius, m, AERO_ROTOR_RADIUS_MIN,
                        AERO_ROTOR_RADIUS_MAX);
}

int aero_rotor_set_chord(aero_rotor *r, double m)
{
    return set_geometry(r, &r->chord, m, AERO_ROTOR_CHORD_MIN,
                        AERO_ROTOR_CHORD_MAX);
}

int aero_rotor_set_thickness(aero_rotor *r, double ratio)
{
    return set_geometry(r, &r->thickness, ratio, AERO_ROTOR_THICKNESS_MIN,
                        AERO_ROTOR_THICKNESS_MAX);
}

int aero_rotor_set_hub(aero_rotor *r, double ratio)
{
    return set_geometry(r, &r->hub, ratio, AERO_ROTOR_HUB_MIN,
                        AERO_ROTOR_HUB_MAX);
}

int aero_rotor_set_thrust(aero_rotor *r, double newton)
{
    return set_geometry(r, &r->thrust, newton, -AERO_ROTOR_THRUST_LIMIT,
                        AERO_ROTOR_THRUST_LIMIT);
}

int aero_rotor_set_torque(aero_rotor *r, double newton_metre)
{
    return set_geometry(r, &r->torque, newton_metre,
                        -AERO_ROTOR_TORQUE_LIMIT, AERO_ROTOR_TORQUE_LIMIT);
}

int aero_rotor_set_design(aero_rotor *r, double rpm)
{
    return set_geometry(r, &r->design_rpm, rpm, AERO_ROTOR_DESIGN_MIN,
                        AERO_ROTOR_DESIGN_MAX);
}

int aero_rotor_set_struts(aero_rotor *r, double struts)
{
    return set_whole(r, &r->struts, struts, AERO_ROTOR_STRUTS_MIN,
                     AERO_ROTOR_STRUTS_MAX);
}

int aero_rotor_set_distortion(aero_rotor *r, double dip)
{
    return set_geometry(r, &r->distortion, dip, AERO_ROTOR_DISTORTION_MIN,
                        AERO_ROTOR_DISTORTION_MAX);
}

int aero_rotor_set_wake(aero_rotor *r, double m)
{
    return set_geometry(r, &r->wake, m, AERO_ROTOR_WAKE_MIN,
                        AERO_ROTOR_WAKE_MAX);
}

int aero_rotor_set_noise_db(aero_rotor *r, double db)
{
    if (!(db >= AERO_ROTOR_NOISE_DB_MIN && db <= AERO_ROTOR_NOISE_DB_MAX))
        return -1;
    r->noise_gain = pow(10.0, db / 20.0);
    return 0;
}

int aero_rotor_set_gain_db(aero_rotor *r, double db)
{
    return aero_moving_player_set_gain_db(&r->base, db);
}

int aero_rotor_set_ramp_ms(aero_rotor *r, double ms)
{
    return aero_moving_player_set_ramp_ms(&r->base, ms);
}

int aero_rotor_set_wind(aero_rotor *r, const double w[3])
{
    return aero_moving_player_set_wind(&r->base, w);
}

int aero_rotor_set_ears(aero_rotor *r, const aero_ears *e)
{
    return aero_moving_player_set_ears(&r->base, e);
}

/* --- pose ------------------------------------------------------------------ */

/* a valid pose p: position, quaternion normalised (the shorter way round
   from the last) */
static void apply_pose(aero_rotor *r, double *p, double interval_s)
{
    const double *to = r->path.to;
    if (p[3] * to[3] + p[4] * to[4] + p[5] * to[5] + p[6] * to[6] < 0.0)
        for (int i = 3; i < 7; i++)
            p[i] = -p[i];
    if (!r->pose_set || interval_s < 0.0 || interval_s > 0.5) {
        r->jumped |= r->pose_set && r->primed;
        aero_pose_path_jump(&r->path, 7, p);
        memcpy(r->pose, p, 7 * sizeof(double));
        r->pose_set = 1;
        return;
    }
    if (!(interval_s >= 0.001))
        interval_s = 0.001;
    aero_pose_path_to(&r->path, p, interval_s * r->base.sample_rate);
}

int aero_rotor_set_pose_at(aero_rotor *r, const double pos[3],
                           const double quat[4], double interval_s,
                           int offset)
{
    aero_pose_event e, oldest;
    double n = sqrt(quat[0] * quat[0] + quat[1] * quat[1] +
                    quat[2] * quat[2] + quat[3] * quat[3]);
    if (!aero_position_ok(pos) || !aero_finite_within(quat, 4, 1e6) ||
        !(n > 1e-9) || !aero_is_finite(interval_s))
        return -1;
    for (int i = 0; i < 3; i++)
        e.x[i] = pos[i];
    for (int i = 0; i < 4; i++)
        e.x[3 + i] = quat[i] / n;
    e.has_extra = 0;
    e.interval_s = interval_s;
    e.offset = offset;
    if (aero_pose_queue_push(&r->queue, &e, &oldest))
        apply_pose(r, oldest.x, oldest.interval_s); /* full: at once */
    return 0;
}

void aero_rotor_orientation(const aero_rotor *r, double quat[4])
{
    const aero_pose_event *e = aero_pose_queue_back(&r->queue);
    for (int k = 0; k < 4; k++)
        quat[k] = e ? e->x[3 + k] : r->path.to[3 + k];
}

/* the pose at the chunk's end on the path, the quaternion normalised */
static void advance_pose(aero_rotor *r, int m)
{
    double n = 0.0;
    aero_pose_path_advance(&r->path, m);
    memcpy(r->pose, r->path.pos, sizeof(r->pose));
    for (int i = 3; i < 7; i++)
        n += r->pose[i] * r->pose[i];
    n = sqrt(n);
    for (int i = 3; i < 7; i++)
        r->pose[i] = n > 1e-12 ? r->pose[i] / n : (i == 3);
}

/* --- Gutin's harmonics ------------------------------------------------------- */

/* J_n(z), n >= 1: its power series where z^2/4 < (n + 1)/2 (each term
   at most half the last: no cancellation; the low orders and slow tips
   of most rotors), else Miller's backward recurrence (stable for the
   orders above z that a subsonic tip gives), normalised by
   J_0 + 2 SUM J_2k = 1 */
static double bessel_jn(int n, double z)
{
    if (!(z > 1e-9))
        return 0.0;
    const double q = 0.25 * z * z;
    if (q < 0.5 * (n + 1)) {
        double term = 1.0, sum = 0.0;
        for (int k = 1; k <= n; k++)
            term *= 0.5 * z / k;
        for (int k = 0; k < 60 && term != 0.0; k++) {
            sum += term;
            if (fabs(term) < 1e-8 * fabs(sum)) /* float output */
                break;
            term *= -q / ((k + 1.0) * (n + k + 1.0));
        }
        return sum;
    }
    int start = n + (int)sqrt(40.0 * (n + z)) + 10;
    start += start & 1;
    double next = 0.0, cur = 1e-30, norm = 0.0, jn = 0.0;
    for (int k = start; k > 0; k--) {
        double prev = 2.0 * k / z * cur - next; /* J_{k-1} */
        next = cur;
        cur = prev;
        if (k - 1 == n)
            jn = cur;
        if (k - 1 > 0 && (k - 1) % 2 == 0)
            norm += 2.0 * cur;
        if (fabs(cur) > 1e200) { /* rescale all so far */
            next *= 1e-200;
            cur *= 1e-200;
            norm *= 1e-200;
            jn *= 1e-200;
        }
    }
    norm += cur; /* J_0 */
    return jn / norm;
}

/* J_v(z) of any integer order: J_0, and J_{-v} = (-1)^v J_v */
static double bessel_jv(int v, double z)
{
    const int a = v < 0 ? -v : v;
    double j = a > 0 ? bessel_jn(a, z) : z > 1e-9 ? bessel_jn(0, z) : 1.0;
    return v < 0 && (a & 1) ? -j : j;
}

/* the largest order |v| whose J_v(z) may reach 1e-7 (-140 dB): beyond
   it |J_v(z)| <= (z/2)^|v| / |v|! <= (e z / (2|v|))^|v| is below that */
static int bessel_reach(double z)
{
    int a = 1;
    if (!(z > 1e-9))
        return 0;
    const double e = 2.718281828459045;
    while (a < 1000000 && a * log(e * z / (2.0 * a)) >= -16.0)
        a++;
    return a - 1;
}

/* the inflow distortion's strip sums of harmonic m (rotor.h): per loading
   harmonic k, orders nu = n - kN and n + kN, J_nu of the harmonic's own
   argument n x r_s / c0, weighted by a_k / 2; the drag's factor nu / n is
   the in-plane force's (the steady term's is 1) */
static void distortion_sums(const aero_rotor *r, double x, int m,
                            aero_rotor_sums *u)
{
    const int n = m * r->blades;
    const int reach =
        bessel_reach(n * x * r->strip[r->strips - 1].r / AERO_C0);
    for (int k = 1; k <= r->loads; k++) {
        for (int side = 0; side < 2; side++) {
            const int nu = side ? n + k * r->struts : n - k * r->struts;
            double t = 0.0, d = 0.0;
            if (abs(nu) <= reach)
                for (int q = 0; q < r->strips; q++) {
                    const aero_rotor_strip *sp = &r->strip[q];
                    double j = bessel_jv(nu, n * x * sp->r / AERO_C0) *
                               sp->load[k - 1];
                    t -= j * sp->thrust;
                    d += j * (double)nu / n * sp->drag * AERO_C0 / sp->r;
                }
            if (side) {
                u->thrust_hi[m - 1][k - 1] = t;
                u->drag_hi[m - 1][k - 1] = d;
            } else {
                u->thrust_lo[m - 1][k - 1] = t;
                u->drag_lo[m - 1][k - 1] = d;
            }
        }
    }
}

/* the strip sums of harmonic m (n = mB) at x = Omega sin(theta) into
   slot m - 1 of u: J_n(n x r_s / c0) times each strip's thrust, drag and
   volume */
static void strip_sums(const aero_rotor *r, double x, int m,
                       aero_rotor_sums *u)
{
    const int n = m * r->blades;
    double t = 0.0, d = 0.0, v = 0.0;
    for (int q = 0; q < r->strips; q++) {
        const aero_rotor_strip *sp = &r->strip[q];
        double jn = bessel_jn(n, n * x * sp->r / AERO_C0);
        t -= jn * sp->thrust;
        d += jn * sp->drag * AERO_C0 / sp->r;
        v += jn * sp->volume;
    }
    u->thrust[m - 1] = t;
    u->drag[m - 1] = d;
    u->volume[m - 1] = v;
    if (r->loads > 0)
        distortion_sums(r, x, m, u);
}

/* the coefficients of cos(n Psi) and sin(n Psi), n = mB, of the tone at
   distance d, cos(theta) ct in the rotor frame and e^{i g} = (cg, sg),
   g = n (phi - pi/2), angular speed omega > 0, from the strip sums u
   (rotor.h's formula); e^{i g0} = (c0, s0), g0 = phi - pi/2, turns the
   inflow distortion's terms (nu - n) g0 from the steady's */
static void harmonic_at(const aero_rotor *r, const aero_rotor_sums *u,
                        double omega, double ct, double cg, double sg,
                        double c0, double s0, double d, int m, double *c,
                        double *s)
{
    const int B = r->blades, n = m * B;
    const double load = (omega * 60.0 / TWO_PI) / r->design_rpm;
    const double k2 = load * load; /* loading ~ rpm^2 */
    double L = k2 * (u->thrust[m - 1] * ct + u->drag[m - 1] / omega);
    double K = n * omega * B / (4.0 * AERO_PI * AERO_C0 * d);
    double th = n * omega * AERO_RHO * AERO_C0 * u->volume[m - 1];
    if (r->loads <= 0) {
        *c = 2.0 * K * (-th * cg + L * sg);
        *s = 2.0 * K * (-L * cg - th * sg);
        return;
    }
    /* L + SUM_k (e^{-i kN g0} L_lo + e^{+i kN g0} L_hi) = Lr + i Li;
       e^{i kN g0} as powers of e^{i N g0} */
    double Lr = L, Li = 0.0, er = 1.0, ei = 0.0, nr = 1.0, ni = 0.0;
    for (int j = 0; j < r->struts; j++) {
        double t = nr * c0 - ni * s0;
        ni = nr * s0 + ni * c0;
        nr = t;
    }
    for (int k = 0; k < r->loads; k++) {
        double t = er * nr - ei * ni;
        ei = er * ni + ei * nr;
        er = t;
        double lo = k2 * (u->thrust_lo[m - 1][k] * ct +
                          u->drag_lo[m - 1][k] / omega);
        double hi = k2 * (u->thrust_hi[m - 1][k] * ct +
                          u->drag_hi[m - 1][k] / omega);
        Lr += (lo + hi) * er;
        Li += (hi - lo) * ei;
    }
    /* K e^{i g} (-i (Lr + i Li) - th) */
    *c = 2.0 * K * ((Li - th) * cg + Lr * sg);
    *s = 2.0 * K * ((Li - th) * sg - Lr * cg);
}

void aero_rotor_harmonic_at(const aero_rotor *r, int m, double omega,
                            double theta, double phi, double d, double *c,
                            double *s)
{
    *c = *s = 0.0;
    if (m < 1 || m > AERO_ROTOR_HARMONICS_MAX || !(omega > 0.0) ||
        !(d > 0.0))
        return;
    aero_rotor_sums *u = malloc(sizeof(*u)); /* 42 kB: not on the stack */
    if (!u)
        return;
    double g0 = phi - 0.5 * AERO_PI, g = m * r->blades * g0;
    strip_sums(r, omega * sin(theta), m, u);
    harmonic_at(r, u, omega, cos(theta), cos(g), sin(g), cos(g0), sin(g0),
                d, m, c, s);
    free(u);
}

double aero_rotor_harmonic_amplitude(const aero_rotor *r, int m,
                                     double omega, double theta, double d)
{
    double c, s;
    aero_rotor_harmonic_at(r, m, omega, theta, 0.0, d, &c, &s);
    return hypot(c, s);
}

/* the coefficients of harmonics 1..h at an ear: all below the Nyquist
   frequency, stopping past the strongest once they fall below
   HARMONIC_FLOOR of it (a subsonic tip's harmonics fall geometrically) */
static void ear_tones(aero_rotor *r, double omega, const double *ear,
                      const double *axes, aero_rotor_sums *u,
                      aero_rotor_ear *out)
{
    const double nyq = 0.45 * r->base.sample_rate * TWO_PI;
    const double w = fabs(omega);
    double v[3], d, x, y, zc, ct, st, phi, best = 0.0;
    int h_max;
    for (int i = 0; i < 3; i++)
        v[i] = ear[i] - r->pose[i];
    d = sqrt(aero_dot3(v, v));
    out->delay = d / AERO_C0 * r->base.sample_rate;
    memset(out->c, 0, sizeof(out->c));
    memset(out->s, 0, sizeof(out->s));
    out->h = 0;
    /* within the rotor's diameter the far field does not hold: heard as
       at that distance (exactly at the hub along the disc's x axis, where
       the tones are loudest) */
    if (aero_near_field(v, AERO_ROTOR_NEAR_RADII * r->radius, axes,
                        &r->base.near))
        d = sqrt(aero_dot3(v, v));
    x = aero_dot3(v, axes) / d;
    y = aero_dot3(v, axes + 3) / d;
    zc = aero_dot3(v, axes + 6) / d;
    ct = zc > 1.0 ? 1.0 : zc < -1.0 ? -1.0 : zc;
    st = sqrt(fmax(0.0, 1.0 - ct * ct));
    phi = atan2(y, x);
    if (omega < 0.0) /* turning the other way: the mirror image */
        phi = -phi;
    if (!(w > 1e-6))
        return;
    double below = nyq / (w * r->blades); /* harmonics under Nyquist */
    h_max = below < AERO_ROTOR_HARMONICS_MAX ? (int)below
                                             : AERO_ROTOR_HARMONICS_MAX;
    /* the strip sums, made again when Omega sin(theta) has moved */
    if (u->layout != r->layout ||
        !(fabs(w * st - u->key) <= AERO_ROTOR_SUMS_TOLERANCE * w * st)) {
        u->h = 0;
        u->key = w * st;
        u->layout = r->layout;
    }
    /* e^{i m B (phi - pi/2)}, harmonic by harmonic */
    const double g1 = r->blades * (phi - 0.5 * AERO_PI);
    const double rc = cos(g1), rs = sin(g1);
    const double c0 = r->loads > 0 ? cos(phi - 0.5 * AERO_PI) : 1.0;
    const double s0 = r->loads > 0 ? sin(phi - 0.5 * AERO_PI) : 0.0;
    double cg = 1.0, sg = 0.0;
    for (int m = 1; m <= h_max; m++) {
        double c1, s1, t = cg * rc - sg * rs;
        sg = cg * rs + sg * rc;
        cg = t;
        if (m > u->h) {
            strip_sums(r, u->key, m, u);
            u->h = m;
        }
        harmonic_at(r, u, w, ct, cg, sg, c0, s0, d, m, &c1, &s1);
        double a = hypot(c1, s1);
        out->c[m - 1] = c1;
        out->s[m - 1] = omega < 0.0 ? -s1 : s1;
        out->h = m;
        if (a > best)
            best = a;
        else if (m > 2 && a < HARMONIC_FLOOR * best)
            break;
    }
}

/* --- broadband: the blades' self-noise ------------------------------------- */

/* octave j's centre, the middle third of its three (IEC 61260's base-ten
   series from 50 Hz: 63 Hz .. 16 kHz) */
static double octave_hz(int j)
{
    return pow(10.0, (17 + 3 * j + 1) / 10.0);
}

/* the band-passes of the octaves under 0.45 sr, each two RBJ band-pass
   stages (0 dB peak, Q 0.9: -3 dB at the octave's edges, skirts falling
   12 dB per octave, so that a band's leakage into the next but one is
   small), and the inverse of their leakage: leak[j][i] the
   part of band-pass i's output power (white input) inside octave j, so
   that gains solving leak g^2 = P give each octave its power P_j */
static void noise_bank(aero_rotor *r);

int aero_rotor_set_seed(aero_rotor *r, uint32_t seed)
{
    r->base.rng = seed ? seed : 1u;
    for (int i = 0; i < AERO_ROTOR_LANES; i++)
        r->noise.rng[i] = aero_run_seed(r->base.rng, i) | 1u;
    return 0;
}

static void noise_bank(aero_rotor *r)
{
    aero_rotor_noise *z = &r->noise;
    const double sr = r->base.sample_rate, Q = 0.9;
    enum { K = AERO_ROTOR_BANDS, F = 2048 };
    double leak[K * K], inv[K * K];
    int n = 0;
    for (int i = 0; i < AERO_ROTOR_LANES; i++) {
        z->b0[i] = z->a1[i] = z->a2[i] = z->gain[i] = 0.0f;
        z->x1[i] = z->x2[i] = z->y1[i] = z->y2[i] = z->u1[i] = z->u2[i] = 0.0f;
        z->rng[i] = aero_run_seed(r->base.rng, i) | 1u;
    }
    while (n < K && octave_hz(n) * sqrt(2.0) < 0.45 * sr)
        n++;
    z->bands = n;
    z->cached = z->next = z->have = 0; /* the spectra kept: other bands */
    for (int i = 0; i < n; i++) {
        double w0 = TWO_PI * octave_hz(i) / sr, al = sin(w0) / (2.0 * Q);
        z->b0[i] = (float)(al / (1.0 + al));
        z->a1[i] = (float)(-2.0 * cos(w0) / (1.0 + al));
        z->a2[i] = (float)((1.0 - al) / (1.0 + al));
    }
    memset(leak, 0, sizeof(leak));
    for (int f = 0; f < F; f++) { /* the response on a grid to Nyquist */
        double hz = (f + 0.5) * 0.5 * sr / F, w = TWO_PI * hz / sr;
        int j = (int)floor(log2(hz / octave_hz(0)) + 0.5);
        if (j < 0 || j >= n)
            continue;
        for (int i = 0; i < n; i++) {
            double b0 = z->b0[i], a1 = z->a1[i], a2 = z->a2[i];
            /* |b0 (1 - e^{-2iw})|^2 / |1 + a1 e^{-iw} + a2 e^{-2iw}|^2 */
            double nr = 1.0 - cos(2 * w), ni = sin(2 * w);
            double dr = 1.0 + a1 * cos(w) + a2 * cos(2 * w);
            double di = -a1 * sin(w) - a2 * sin(2 * w);
            double h2 = b0 * b0 * (nr * nr + ni * ni) / (dr * dr + di * di);
            leak[j * K + i] += h2 * h2 / F; /* two stages */
        }
    }
    /* Gauss-Jordan on the n x n block (diagonally dominant) */
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++)
            inv[j * K + i] = i == j;
    for (int c = 0; c < n; c++) {
        double p = leak[c * K + c];
        for (int i = 0; i < n; i++) {
            leak[c * K + i] /= p;
            inv[c * K + i] /= p;
        }
        for (int j = 0; j < n; j++) {
            double f = leak[j * K + c];
            if (j == c)
                continue;
            for (int i = 0; i < n; i++) {
                leak[j * K + i] -= f * leak[c * K + i];
                inv[j * K + i] -= f * inv[c * K + i];
            }
        }
    }
    memcpy(z->unmix, inv, sizeof(inv));
    z->layout = -1; /* the spectrum is made again */
}

/* the span of one strip, m */
static double strip_span(const aero_rotor *r)
{
    return r->radius * (1.0 - r->hub) / (r->strips == 1 ? 1 : r->strips);
}

/* strip q of one blade as an airfoil section (Brooks et al. 1989): tripped
   (a rotor's blades in real air), a sharp trailing edge of the report's
   NACA 0012 angle, a rounded tip on the outermost strip */
static void strip_airfoil(const aero_rotor *r, int q, aero_airfoil *a)
{
    memset(a, 0, sizeof(*a));
    a->chord = (float)r->strip[q].chord;
    a->span = (float)strip_span(r);
    a->te_thickness = (float)(0.005 * r->strip[q].chord);
    a->te_angle_deg = 14.0f;
    a->tripped = 1;
    a->tip = q == r->strips - 1 ? AERO_AIRFOIL_TIP_ROUNDED
                                : AERO_AIRFOIL_NO_TIP;
}

/* each strip's self-noise at 1 m straight above it (D_h = 1) at angular
   speed w and axial inflow u, and the octave gains of their sum */
static void noise_spectrum_make(aero_rotor *r, double w, double u)
{
    aero_rotor_noise *z = &r->noise;
    enum { K = AERO_ROTOR_BANDS, T = AERO_ROTOR_THIRDS };
    float hz[T], spl[AERO_BPM_MECHANISMS * T], tot[T];
    double band[K], g2[K], sum = 0.0;
    aero_third_octave_bands(50.0f, 20000.0f, hz, T);
    memset(band, 0, sizeof(band));
    for (int q = 0; q < r->strips; q++) {
        const aero_rotor_strip *sp = &r->strip[q];
        aero_airfoil a;
        aero_airfoil_observer o = {1.0f, 90.0f, 90.0f};
        double U = hypot(w * sp->r, u), load = (w * 60.0 / TWO_PI) /
                                                r->design_rpm;
        /* the model's range: Mach below 0.5 */
        if (U > 0.45 * AERO_C0)
            U = 0.45 * AERO_C0;
        /* the angle of attack that carries the strip's thrust: thin
           airfoil C_L = 2 pi alpha */
        double cl = U > 1e-3 ? fabs(load * load * sp->thrust) /
                                   (0.5 * AERO_RHO * U * U * strip_span(r)
                                    * sp->chord)
                             : 0.0;
        double alpha = cl / TWO_PI * 180.0 / AERO_PI;
        aero_airfoil_flow f = {(float)U, (float)(alpha < 25.0 ? alpha : 25.0),
                               (float)AERO_C0, (float)AERO_NU};
        strip_airfoil(r, q, &a);
        a.tip_alpha_deg = f.alpha_deg;
        z->power[q] = 0.0;
        z->mach[q] = U / AERO_C0;
        z->alpha[q] = f.alpha_deg * AERO_PI / 180.0;
        if (U < 0.1 ||
            aero_airfoil_noise_spectrum(&a, &f, &o, hz, T, spl) != 0)
            continue;
        aero_airfoil_noise_total(spl, T, tot);
        for (int k = 0; k < T; k++) {
            double p = 4e-10 * pow(10.0, 0.1 * tot[k]); /* (20 uPa)^2 */
            z->power[q] += p;
            band[k / 3] += p;
        }
    }
    for (int j = 0; j < z->bands; j++)
        sum += band[j];
    for (int j = 0; j < z->bands; j++) {
        g2[j] = 0.0;
        for (int i = 0; i < z->bands; i++)
            g2[j] += z->unmix[j * K + i] * (sum > 0.0 ? band[i] / sum : 0.0);
    }
    for (int j = 0; j < K; j++)
        z->gain[j] = j < z->bands && g2[j] > 0.0 ? (float)sqrt(g2[j]) : 0.0f;
    /* the lanes beyond the bands stay silent (zero gains and filters) */
}

/* cos and sin of the strips' angles of attack (ear_envelope's chords),
   each time the spectrum's step changes */
static void alpha_trig(aero_rotor *r)
{
    aero_rotor_noise *z = &r->noise;
    for (int q = 0; q < r->strips; q++) {
        z->cos_alpha[q] = cos(z->alpha[q]);
        z->sin_alpha[q] = sin(z->alpha[q]);
    }
}

/* the self-noise spectrum at angular speed w and axial inflow u: made at
   the nearest speed of a grid of ratio 1 + AERO_ROTOR_NOISE_TOLERANCE
   (its shape moves with log U: its frequencies are off by at most half a
   step), kept for AERO_ROTOR_SPECTRA grid steps; the powers follow the
   speed from the grid's as U^5 and the Mach numbers as U (z->scale), the
   trailing edge's law (Brooks et al. 1989: SPL with 10 log M^5), so the
   level is not off */
static void noise_spectrum(aero_rotor *r, double w, double u)
{
    aero_rotor_noise *z = &r->noise;
    const double key = w * r->radius + fabs(u);
    const double ln_step = log1p(AERO_ROTOR_NOISE_TOLERANCE);
    if (z->layout != r->layout) {
        z->layout = r->layout;
        z->cached = z->next = z->have = 0;
    }
    if (z->psi_blades != r->blades) { /* the envelope's azimuths */
        const int B = r->blades;
        for (int j = 0; j < AERO_ROTOR_AZIMUTHS; j++)
            for (int b = 0; b < B; b++) {
                double psi = TWO_PI * ((double)j / (B * AERO_ROTOR_AZIMUTHS) +
                                       (double)b / B);
                z->psi_cos[j * B + b] = cos(psi);
                z->psi_sin[j * B + b] = sin(psi);
            }
        z->psi_blades = B;
    }
    if (!(key > 1e-6)) { /* still: silent, not kept */
        noise_spectrum_make(r, w, u);
        alpha_trig(r);
        z->scale = 1.0;
        z->have = 0;
        return;
    }
    const int step = (int)floor(log(key) / ln_step + 0.5);
    const double kq = exp(step * ln_step), f = kq / key;
    z->scale = key / kq;
    if (z->have && z->step == step)
        return;
    z->have = 1;
    z->step = step;
    for (int i = 0; i < z->cached; i++)
        if (z->cache_step[i] == step) {
            memcpy(z->gain, z->cache_gain[i], sizeof(z->gain));
            memcpy(z->power, z->cache_power[i], sizeof(z->power));
            memcpy(z->mach, z->cache_mach[i], sizeof(z->mach));
            memcpy(z->alpha, z->cache_alpha[i], sizeof(z->alpha));
            alpha_trig(r);
            return;
        }
    noise_spectrum_make(r, w * f, u * f);
    alpha_trig(r);
    int i = z->next;
    z->next = (z->next + 1) % AERO_ROTOR_SPECTRA;
    if (z->cached < AERO_ROTOR_SPECTRA)
        z->cached++;
    z->cache_step[i] = step;
    memcpy(z->cache_gain[i], z->gain, sizeof(z->gain));
    memcpy(z->cache_power[i], z->power, sizeof(z->power));
    memcpy(z->cache_mach[i], z->mach, sizeof(z->mach));
    memcpy(z->cache_alpha[i], z->alpha, sizeof(z->alpha));
}

/* the axial flow through the disc (along the thrust axis, m/s): the wind
 * along the axis u plus the induced velocity w of momentum theory,
 * -T = 2 rho A w |u + w| (T the thrust on the rotor along the axis at this
 * speed, so -T on the air; Glauert 1935). A rotor taking energy from the
 * wind (a turbine: T along u) slows it by a = -w/u up to momentum
 * theory's limit 1/2 (beyond it the wake is turbulent and the theory does
 * not hold); a propeller or fan adds to it (in hover w = sqrt(T/(2 rho
 * A))). */
static double disc_flow(const aero_rotor *r, double omega, double u)
{
    const double load = (fabs(omega) * 60.0 / TWO_PI) / r->design_rpm;
    const double T = r->thrust * load * load;
    const double k = -T / (2.0 * AERO_RHO * AERO_PI * r->radius * r->radius);
    if (k * u < 0.0) { /* slowing the wind: w = -a u */
        double ct = -4.0 * k / (u * u); /* C_T = T / (rho A u^2 / 2) */
        double a = ct < 1.0 ? 0.5 * (1.0 - sqrt(1.0 - ct)) : 0.5;
        return u * (1.0 - a);
    }
    /* adding to it: w |u + w| = k with u + w of k's sign */
    double w = k >= 0.0 ? 0.5 * (-u + sqrt(u * u + 4.0 * k))
                        : 0.5 * (-u - sqrt(u * u - 4.0 * k));
    return u + w;
}

/* the broadband's envelope at an ear over one blade passing: the
 * strips' self-noise powers heard through a half-plane trailing edge's
 * directivity (Ffowcs Williams and Hall 1970) with the convective
 * amplification of Brooks et al.'s (1989) D_h (loudest towards the
 * blade's leading edge as it comes) and 1/r^2, summed over blades and
 * strips (incoherent), at AERO_ROTOR_AZIMUTHS rotor positions; env: the
 * amplitude's mean, then its cos and sin harmonics of B Psi. The report's
 * D_h = 2 sin^2(Theta/2) sin^2(Phi), Theta from the chord and Phi the
 * angle of the ear's projection across the span from it, vanishes across
 * the whole plane of the chord, where a listener beside a turbine's disc
 * nearly always is (a swish of 20-30 dB); the half-plane's own solution
 * vanishes only on the wake's side of it, and equals D_h at mid-span.
 * Each strip's chord is set as a blade's twist sets it: at its angle of
 * attack alpha (the one that carries its thrust) from the air's flow past
 * it, that flow its motion Omega r and the axial flow through the disc
 * u_d (disc_flow: the wind less a turbine's induction, or plus a
 * propeller's), at the local flow angle phi = atan(u_d / (Omega r)); the
 * chord turned from the flow away from the lift (a turbine's chord at
 * phi - alpha from the disc, a propeller's at phi + alpha); with a blade
 * table, at the table's twist from the disc instead. Each strip is
 * heard when its sound arrives: at the azimuth it had (d_s - d_hub)/c0
 * before the hub's sound (its retarded time), one fixed-point step
 * (Omega R / c0 < 1). */
/* ear_envelope's table of cos (2 pi k / 8) holds for 8 azimuths */
typedef char aero_rotor_azimuths_are_8[AERO_ROTOR_AZIMUTHS == 8 ? 1 : -1];

/* the strips' constants for ear_envelope: the retarded step's factor,
   the chord's components, Mach number and a fifth of it, power, radius
   squared and doubled (float: see strips_power) */
typedef struct {
    float kq[AERO_ROTOR_STRIPS_MAX], cws[AERO_ROTOR_STRIPS_MAX],
        aws[AERO_ROTOR_STRIPS_MAX], Ms[AERO_ROTOR_STRIPS_MAX],
        M5[AERO_ROTOR_STRIPS_MAX], Ps[AERO_ROTOR_STRIPS_MAX],
        R2[AERO_ROTOR_STRIPS_MAX], R2x[AERO_ROTOR_STRIPS_MAX];
    int n;
} aero_rotor_strip_terms;

/* each strip's chord downstream, in (e_t, axis): the flow's direction
   (-cos phi, sin phi) turned by alpha away from the lift
   lift (sin phi, cos phi); the normal (span x chord) follows. w the
   angular speed, ud the axial flow through the disc, rdh 1 / (d_hub c0) */
static void strip_terms(const aero_rotor *r, double w, double ud, double rdh,
                        aero_rotor_strip_terms *t)
{
    const aero_rotor_noise *z = &r->noise;
    const double s5 = z->scale * z->scale * z->scale * z->scale * z->scale;
    const double lift = r->thrust < 0.0 ? -1.0 : 1.0;
    t->n = r->strips;
    for (int q = 0; q < r->strips; q++) {
        const double rq = r->strip[q].r;
        double wt = w * rq, W = sqrt(wt * wt + ud * ud);
        double cf = W > 0.0 ? wt / W : 1.0, sf = W > 0.0 ? ud / W : 0.0;
        double ca = z->cos_alpha[q], sa = z->sin_alpha[q];
        double cw = -ca * cf - sa * lift * sf, aw = ca * sf - sa * lift * cf;
        if (r->has_blade) { /* the table's twist: the leading edge into
                               the flow through the disc */
            double tw = r->strip[q].twist;
            cw = -cos(tw);
            aw = (ud < 0.0 ? -1.0 : 1.0) * sin(tw);
        }
        t->cws[q] = (float)cw;
        t->aws[q] = (float)aw;
        t->kq[q] = (float)(w * rq * rdh);
        t->Ms[q] = (float)(z->mach[q] * z->scale);
        t->M5[q] = 0.2f * t->Ms[q];
        t->Ps[q] = (float)(z->power[q] * s5);
        t->R2[q] = (float)(rq * rq);
        t->R2x[q] = (float)(2.0 * rq);
    }
}

/* one blade's strips heard at the ear, (vr0, vt0) the ear along its span
   and its motion, vz along the axis, v2 = |v|^2: their powers added to P
   (the blades before it), in order.
   Branch-free over the strips, each term to its own slot (it vectorises;
   the terms are summed in order below, so the sum is the same on every
   compiler): a strip at the ear or silent adds 0. In float, four strips
   to a SIMD register: the distance from the strip as d^2 = |v|^2 - 2 r
   v_r + r^2 (no difference of the large |v|^2 and v_r^2), so float's
   1e-7 holds at any range the rings hold; the floors as comparisons, not
   fmax (a library call the loop cannot vectorise) */
static float strips_power(const aero_rotor_strip_terms *t, float P,
                          float vr0, float vt0, float vz, float v2)
{
    float term[AERO_ROTOR_STRIPS_MAX];
    for (int q = 0; q < t->n; q++) {
        /* the retarded azimuth: turned back by Omega (d - d_hub)/c0
           (sense-wise), d - d_hub = -r vr / d_hub in the far field; cos
           and sin of that step by series (the step below 1 rad: its error
           under 1e-3), its coefficients multiplied, not divided (the
           divider, which the square roots need, is this loop's
           bottleneck) */
        float tq = t->kq[q] * vr0, t2 = tq * tq;
        float ct1 = 1.0f - t2 * (0.5f - t2 * (1.0f / 24.0f));
        float st1 = tq * (1.0f - t2 * (1.0f / 6.0f - t2 * (1.0f / 120.0f)));
        float vr = ct1 * vr0 + st1 * vt0; /* psi turned by t */
        float vt = ct1 * vt0 - st1 * vr0;
        float d2 = (v2 + t->R2[q]) - t->R2x[q] * vr;
        d2 = d2 > 1e-6f ? d2 : 1e-6f;
        float vx = t->cws[q] * vt + t->aws[q] * vz;
        float vn = t->cws[q] * vz - t->aws[q] * vt;
        /* the distance off the span's line */
        float h2 = vx * vx + vn * vn;
        float h = sqrtf(h2 > 1e-12f ? h2 : 1e-12f);
        /* the half-plane's directivity about its edge (Ffowcs Williams
           and Hall 1970): 2 sin^2(theta/2) of the azimuth theta about the
           span from the wake, times sin(psi) of the angle from the span,
           = (h - vx) / d; the report's D_h at mid-span. Its convective
           factors of the angle from the chord, cos = vx / d */
        float id = 1.0f / sqrtf(d2);
        float ct = vx * id, c1 = 1.0f + t->M5[q] * ct;
        term[q] = t->Ps[q] * (h - vx) * id /
                  ((1.0f + t->Ms[q] * ct) * c1 * c1 * d2);
    }
    for (int q = 0; q < t->n; q++)
        P += term[q];
    return P;
}

/* the envelope's mean, then its cos and sin harmonics of B Psi, from its
   amplitude a[] at the AERO_ROTOR_AZIMUTHS rotor positions */
static void envelope_harmonics(const double *a, double *env)
{
    enum { NA = AERO_ROTOR_AZIMUTHS };
    /* cos and sin of multiples of 2 pi / NA (NA = 8) */
    static const double c8[8] = {1.0, 0.70710678118654752, 0.0,
                                 -0.70710678118654752, -1.0,
                                 -0.70710678118654752, 0.0,
                                 0.70710678118654752};
    for (int k = 0; k <= AERO_ROTOR_ENVELOPE; k++) {
        double c = 0.0, s = 0.0;
        for (int j = 0; j < NA; j++) {
            c += a[j] * c8[(k * j) % NA];
            s += a[j] * c8[(k * j + 6) % NA]; /* sin x = cos(x - pi/2) */
        }
        if (k == 0)
            env[0] = c / NA;
        else {
            env[2 * k - 1] = 2.0 * c / NA;
            env[2 * k] = 2.0 * s / NA;
        }
    }
}

static void ear_envelope(const aero_rotor *r, double omega, double u,
                         const double *ear, const double *axes, double *env)
{
    enum { NA = AERO_ROTOR_AZIMUTHS };
    const aero_rotor_noise *z = &r->noise;
    const int B = r->blades;
    const double sense = omega < 0.0 ? -1.0 : 1.0, w = fabs(omega);
    aero_rotor_strip_terms terms;
    double a[NA], rel[3];
    aero_near seen = {0, 0.0}; /* ear_tones reports it */
    for (int i = 0; i < 3; i++)
        rel[i] = ear[i] - r->pose[i];
    aero_near_field(rel, AERO_ROTOR_NEAR_RADII * r->radius, axes, &seen);
    const double vz = aero_dot3(rel, axes + 6), v2 = aero_dot3(rel, rel);
    const double vp1 = aero_dot3(rel, axes), vp2 = aero_dot3(rel, axes + 3);
    const double rdh = v2 > 0.0 ? 1.0 / (sqrt(v2) * AERO_C0) : 0.0;
    strip_terms(r, w, disc_flow(r, omega, u), rdh, &terms);
    for (int j = 0; j < NA; j++) {
        float P = 0.0f;
        for (int b = 0; b < B; b++) {
            /* psi = 2 pi (j / (B NA) + b / B) (noise_spectrum's table) */
            const double cp0 = z->psi_cos[j * B + b];
            const double sp0 = z->psi_sin[j * B + b];
            /* the ear in the disc's polar frame at psi: along the span
               and along the motion */
            const float vr0 = (float)(cp0 * vp1 + sp0 * vp2);
            const float vt0 = (float)(sense * (-sp0 * vp1 + cp0 * vp2));
            P = strips_power(&terms, P, vr0, vt0, (float)vz, (float)v2);
        }
        a[j] = r->noise_gain * sqrt((double)P);
    }
    envelope_harmonics(a, env);
}

/* lanes i0.. of the self-noise: the band-passes' coefficients and state,
   four lanes to a SIMD register (aero_lanes.h), held in registers over a
   chunk */
typedef struct {
    lane4 b0, a1, a2, g, x1, x2, y1, y2, u1, u2;
    lane4u rng;
} noise_regs;

static inline void regs_load(const aero_rotor_noise *z, int i0,
                             noise_regs *q)
{
    memcpy(&q->b0, z->b0 + i0, sizeof(lane4));
    memcpy(&q->a1, z->a1 + i0, sizeof(lane4));
    memcpy(&q->a2, z->a2 + i0, sizeof(lane4));
    memcpy(&q->g, z->gain + i0, sizeof(lane4));
    memcpy(&q->x1, z->x1 + i0, sizeof(lane4));
    memcpy(&q->x2, z->x2 + i0, sizeof(lane4));
    memcpy(&q->y1, z->y1 + i0, sizeof(lane4));
    memcpy(&q->y2, z->y2 + i0, sizeof(lane4));
    memcpy(&q->u1, z->u1 + i0, sizeof(lane4));
    memcpy(&q->u2, z->u2 + i0, sizeof(lane4));
    memcpy(&q->rng, z->rng + i0, sizeof(lane4u));
}

static inline void regs_store(aero_rotor_noise *z, int i0,
                              const noise_regs *q)
{
    memcpy(z->x1 + i0, &q->x1, sizeof(lane4));
    memcpy(z->x2 + i0, &q->x2, sizeof(lane4));
    memcpy(z->y1 + i0, &q->y1, sizeof(lane4));
    memcpy(z->y2 + i0, &q->y2, sizeof(lane4));
    memcpy(z->u1 + i0, &q->u1, sizeof(lane4));
    memcpy(z->u2 + i0, &q->u2, sizeof(lane4));
    memcpy(z->rng + i0, &q->rng, sizeof(lane4u));
}

/* one sample of four lanes: the two band-pass stages fed white noise
   (xorshift32 to [-1, 1), times sqrt 3: unit variance), weighted by the
   gains: y = b0 (x - x2) - a1 y1 - a2 y2, and u of y the same */
static inline lane4 regs_step(noise_regs *q)
{
    lane4 x = l4_mul(l4_splat(1.7320508f), l4_uniform(&q->rng));
    lane4 y = l4_sub(l4_sub(l4_mul(q->b0, l4_sub(x, q->x2)),
                            l4_mul(q->a1, q->y1)),
                     l4_mul(q->a2, q->y2));
    lane4 u = l4_sub(l4_sub(l4_mul(q->b0, l4_sub(y, q->y2)),
                            l4_mul(q->a1, q->u1)),
                     l4_mul(q->a2, q->u2));
    q->x2 = q->x1;
    q->x1 = x;
    q->y2 = q->y1;
    q->y1 = y;
    q->u2 = q->u1;
    q->u1 = u;
    return l4_mul(q->g, u);
}

/* lanes i0..i0+3 (and i0+4..i0+7 when `eight`: their outputs added lane
   by lane to the first four's, both recursions interleaved) over m
   samples, into acc (set when `first`, else added) */
static inline void noise_lanes(aero_rotor_noise *z, int i0, int eight,
                               float (*acc)[4], int m, int first)
{
    noise_regs p, q;
    regs_load(z, i0, &p);
    if (eight)
        regs_load(z, i0 + 4, &q);
    for (int j = 0; j < m; j++) {
        lane4 w = regs_step(&p);
        if (eight)
            w = l4_add(w, regs_step(&q));
        if (!first) {
            lane4 a;
            memcpy(&a, acc[j], sizeof(a));
            w = l4_add(a, w);
        }
        memcpy(acc[j], &w, sizeof(w));
    }
    regs_store(z, i0, &p);
    if (eight)
        regs_store(z, i0 + 4, &q);
}

/* m samples of the rotor's unit-power self-noise spectrum: each octave
   band-pass fed its own white noise (the bands overlap: one noise through
   all would add their outputs coherently where they overlap, and the
   powers the gains were solved for would not add), weighted by its gain.
   The lanes in use: the bands rounded up to four (at 44.1 and 48 kHz 8
   of the 12; the lanes beyond are silent), four at a time; their sum in
   a fixed order written out (the same on every compiler, no
   reassociation): lanes i, i + 4, i + 8 into quarter i, then the
   quarters pairwise */
typedef char aero_rotor_lanes_are_12[AERO_ROTOR_LANES == 12 ? 1 : -1];
static void noise_chunk(aero_rotor *r, float *out, int m)
{
    aero_rotor_noise *z = &r->noise;
    float acc[AERO_ROTOR_CHUNK][4];
    if (z->bands > 4)
        noise_lanes(z, 0, 1, acc, m, 1);
    else
        noise_lanes(z, 0, 0, acc, m, 1);
    if (z->bands > 8)
        noise_lanes(z, 8, 0, acc, m, 0);
    for (int j = 0; j < m; j++)
        out[j] = (acc[j][0] + acc[j][2]) + (acc[j][1] + acc[j][3]);
}

/* --- processing ---------------------------------------------------------------- */

/* a ramp's value after m samples (a chunk, or less where a pose splits
   it) */
static double ramp_after(aero_ramp *r, int m)
{
    if (r->left > 0.0)
        aero_glide_values(&r->value, &r->target, 1,
                          aero_glide_fraction(&r->left, m));
    return r->value;
}

/* four harmonics of a chunk's tones (radiate): their coefficients of
   cos and sin and those coefficients' steps a sample, their phasors and
   those phasors' turns a sample */
typedef struct {
    lane4 c, s, dc, ds, zr, zi, tr, ti;
} tone4;
typedef char aero_rotor_harmonics_by_4[AERO_ROTOR_HARMONICS_MAX % 4 == 0
                                       ? 1 : -1];

/* a chunk's glide (radiate): the broadband's envelope, its mean and its
   harmonics B psi and 2 B psi as coefficients of the first two
   harmonics' phasors (lanes 0 and 1 of ec and es, lanes 2 and 3 zero),
   their steps a sample, and the arrival time of each sample on the ring */
typedef struct {
    float ev0, dev0;
    lane4 ec, es, dec, des;
    const float *shape; /* a fade per sample, or NULL */
    float *ring;
    long mask;
    double at, step;
} glide;

/* m samples of one ear: the broadband noise under its envelope (when
   `hiss`) plus nb fours of harmonics (nb >= 1: the envelope turns with
   the first four's phasors), onto the ring. hiss and nb constants where
   this is inlined (radiate), so that the compiler keeps the harmonics in
   registers. The sums in a fixed order written out (the same on every
   compiler, no reassociation): harmonic k into quarter k % 4, the
   quarters pairwise; the envelope's mean plus its two harmonics */
static inline void radiate_run(glide *gl, const tone4 *bank, const int nb,
                               const int hiss, const float *noise, int m)
{
    tone4 b[AERO_ROTOR_HARMONICS_MAX / 4];
    float ev0 = gl->ev0;
    lane4 ec = gl->ec, es = gl->es;
    const lane4 dec = gl->dec, des = gl->des;
    const float dev0 = gl->dev0;
    const double step = gl->step;
    float *ring = gl->ring;
    const float *shape = gl->shape;
    const long mask = gl->mask;
    double at = gl->at;
    for (int i = 0; i < nb; i++)
        b[i] = bank[i];
    for (int j = 0; j < m; j++) {
        float v = 0.0f;
        if (hiss) {
            lane4 pe = l4_add(l4_mul(ec, b[0].zr), l4_mul(es, b[0].zi));
            float env = ev0 + (l4_get(pe, 0) + l4_get(pe, 1));
            v = (env > 0.0f ? env : 0.0f) * noise[j];
            ev0 += dev0;
            ec = l4_add(ec, dec);
            es = l4_add(es, des);
        }
        lane4 q = l4_splat(0.0f);
        for (int i = 0; i < nb; i++) {
            tone4 *p = &b[i];
            q = l4_add(q, l4_add(l4_mul(p->c, p->zr), l4_mul(p->s, p->zi)));
            lane4 wr = l4_sub(l4_mul(p->zr, p->tr), l4_mul(p->zi, p->ti));
            p->zi = l4_add(l4_mul(p->zr, p->ti), l4_mul(p->zi, p->tr));
            p->zr = wr;
            p->c = l4_add(p->c, p->dc);
            p->s = l4_add(p->s, p->ds);
        }
        v += (l4_get(q, 0) + l4_get(q, 2)) + (l4_get(q, 1) + l4_get(q, 3));
        aero_arrivals_add_span(ring, mask, at, step,
                               shape ? v * shape[j] : v);
        at += step;
    }
}

/* the chunk's glide from then to now at ear e: its place in the ring and
   step (the delay's), the broadband envelope's mean and first two
   harmonics and their steps a sample */
static void glide_begin(glide *gl, const aero_rotor *r,
                        const aero_rotor_ear *then, const aero_rotor_ear *now,
                        double gain0, double gain1, const float *shape, int e,
                        int m)
{
    const double inv_m = 1.0 / m;
    float ec[4] = {0}, es[4] = {0}, dec[4] = {0}, des[4] = {0};
    gl->shape = shape;
    gl->ring = r->base.arrivals.ring[e];
    gl->mask = r->base.arrivals.mask;
    gl->step = 1.0 + (now->delay - then->delay) * inv_m;
    gl->at = (double)r->base.arrivals.head + then->delay;
    gl->ev0 = (float)(gain0 * then->env[0]);
    gl->dev0 = (float)((gain1 * now->env[0] - gain0 * then->env[0]) * inv_m);
    for (int k = 0; k < 2; k++) {
        ec[k] = (float)(gain0 * then->env[2 * k + 1]);
        es[k] = (float)(gain0 * then->env[2 * k + 2]);
        dec[k] = (float)((gain1 * now->env[2 * k + 1] -
                          gain0 * then->env[2 * k + 1]) * inv_m);
        des[k] = (float)((gain1 * now->env[2 * k + 2] -
                          gain0 * then->env[2 * k + 2]) * inv_m);
    }
    memcpy(&gl->ec, ec, sizeof(lane4));
    memcpy(&gl->es, es, sizeof(lane4));
    memcpy(&gl->dec, dec, sizeof(lane4));
    memcpy(&gl->des, des, sizeof(lane4));
}

/* the tone bank of the chunk, nb fours of harmonics: each harmonic's
   coefficients gliding from then to now, and its phasor e^{i n psi0} with
   its step e^{i n dpsi} for n = (k+1) B, as powers of the first, in
   double (each product's rounding 1e-16: 40 of them far below float's)
   instead of four cos and sin a harmonic */
static void tone_bank(tone4 *bank, int nb, const aero_rotor_ear *then,
                      const aero_rotor_ear *now, double gain0, double gain1,
                      double B, double psi0, double dpsi, int m)
{
    enum { H = AERO_ROTOR_HARMONICS_MAX };
    const double inv_m = 1.0 / m;
    float c[H], s[H], dc[H], ds[H], zr[H], zi[H], tr[H], ti[H];
    const double z1r = cos(B * psi0), z1i = sin(B * psi0);
    const double t1r = cos(B * dpsi), t1i = sin(B * dpsi);
    double znr = z1r, zni = z1i, tnr = t1r, tni = t1i;
    for (int k = 0; k < 4 * nb; k++) {
        c[k] = (float)(gain0 * then->c[k]);
        s[k] = (float)(gain0 * then->s[k]);
        dc[k] = (float)((gain1 * now->c[k] - gain0 * then->c[k]) * inv_m);
        ds[k] = (float)((gain1 * now->s[k] - gain0 * then->s[k]) * inv_m);
        zr[k] = (float)znr;
        zi[k] = (float)zni;
        tr[k] = (float)tnr;
        ti[k] = (float)tni;
        double a = znr * z1r - zni * z1i, b = tnr * t1r - tni * t1i;
        zni = znr * z1i + zni * z1r;
        znr = a;
        tni = tnr * t1i + tni * t1r;
        tnr = b;
    }
    for (int i = 0; i < nb; i++) {
        memcpy(&bank[i].c, c + 4 * i, sizeof(lane4));
        memcpy(&bank[i].s, s + 4 * i, sizeof(lane4));
        memcpy(&bank[i].dc, dc + 4 * i, sizeof(lane4));
        memcpy(&bank[i].ds, ds + 4 * i, sizeof(lane4));
        memcpy(&bank[i].zr, zr + 4 * i, sizeof(lane4));
        memcpy(&bank[i].zi, zi + 4 * i, sizeof(lane4));
        memcpy(&bank[i].tr, tr + 4 * i, sizeof(lane4));
        memcpy(&bank[i].ti, ti + 4 * i, sizeof(lane4));
    }
}

/* the tones of one ear over m samples: the coefficients and the delay
   glide from then to now, the phase turns from psi0 by dpsi a sample.
   Each harmonic keeps its own phasor e^{i (k+1) B psi}, turned by its own
   step (set exactly in double at each chunk): the harmonics are
   independent, four to a SIMD register (aero_lanes.h). shape (NULL:
   none): a fade's factor per sample, smooth where a glide per chunk would
   kink. hiss: the broadband noise heard (else not evaluated) */
static void radiate(aero_rotor *r, const aero_rotor_ear *then,
                    const aero_rotor_ear *now, double gain0, double gain1,
                    double psi0, double dpsi, const float *noise,
                    const float *shape, int hiss, int e, int m)
{
    const int h = then->h > now->h ? then->h : now->h;
    /* the harmonics in fours (those beyond h silent: 0 coefficients), at
       least one four (the envelope's phasors) */
    const int nb = h > 4 ? (h + 3) / 4 : 1;
    tone4 bank[AERO_ROTOR_HARMONICS_MAX / 4];
    glide gl;
    glide_begin(&gl, r, then, now, gain0, gain1, shape, e, m);
    tone_bank(bank, nb, then, now, gain0, gain1, r->blades, psi0, dpsi, m);
    /* a subsonic tip's harmonics fall fast (a drone's: 5 above -80 dB):
       the common counts with theirs fixed */
    if (hiss)
        switch (nb) {
        case 1:
            radiate_run(&gl, bank, 1, 1, noise, m);
            break;
        case 2:
            radiate_run(&gl, bank, 2, 1, noise, m);
            break;
        case 3:
            radiate_run(&gl, bank, 3, 1, noise, m);
            break;
        default:
            radiate_run(&gl, bank, nb, 1, noise, m);
        }
    else
        switch (nb) {
        case 1:
            radiate_run(&gl, bank, 1, 0, noise, m);
            break;
        case 2:
            radiate_run(&gl, bank, 2, 0, noise, m);
            break;
        default:
            radiate_run(&gl, bank, nb, 0, noise, m);
        }
}

/* the rotor's axes in the world: e1, e2 and the thrust axis, from the
   pose's quaternion */
static void rotor_axes(const aero_rotor *r, double *axes)
{
    static const double unit[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int k = 0; k < 3; k++)
        aero_quat_rotate(r->pose + 3, unit[k], axes + 3 * k);
}

/* the speed of rotation over a chunk, rad per sample, each sample's rpm
   clamped to the tip Mach limit (NaN as 0); sets *clamped */
static double chunk_turn(const aero_rotor *r, const float *rpm, int m,
                         int *clamped)
{
    const double max_rpm = AERO_ROTOR_MACH_TIP_MAX * AERO_C0 /
                           r->radius * 60.0 / TWO_PI;
    double sum = 0.0;
    if (!rpm)
        return 0.0;
    for (int j = 0; j < m; j++) {
        double v = rpm[j];
        if (!(v == v))
            v = 0.0;
        if (v > max_rpm || v < -max_rpm) {
            v = v > 0.0 ? max_rpm : -max_rpm;
            *clamped = 1;
        }
        sum += v;
    }
    return sum / m * TWO_PI / 60.0 / r->base.sample_rate;
}

/* a jump while sounding: the sound where the rotor was goes on there as a
   ghost (the oldest replaced when all are fading) */
static void leave_ghost(aero_rotor *r, double level)
{
    aero_rotor_ghost *g = &r->ghost[0];
    for (int k = 1; k < AERO_ROTOR_GHOSTS && g->active; k++)
        if (!r->ghost[k].active || r->ghost[k].samples > g->samples)
            g = &r->ghost[k];
    memcpy(g->ear, r->then, sizeof(g->ear));
    g->level = level;
    g->samples = 0.0;
    g->active = 1;
}

/* a fade's factors over the m samples after t (samples since it began):
   ghost_fade.h's half cosine falling (out) or rising (!out); 0 when done */
static int fade_shape(double t, int m, double sr, int out, float *shape)
{
    if (!(t < AERO_GHOST_FADE_S * sr))
        return 0;
    for (int j = 0; j < m; j++) {
        double f = aero_ghost_fade(t + j + 1, sr, 1.0);
        shape[j] = (float)(out ? f : 1.0 - f);
    }
    return 1;
}

/* the ghosts' next m samples: their tones and envelope held, at their
   delays, fading out */
static void radiate_ghosts(aero_rotor *r, double gain0, double gain1,
                           double dpsi, const float *noise, int hiss, int m)
{
    float shape[AERO_ROTOR_CHUNK];
    for (int k = 0; k < AERO_ROTOR_GHOSTS; k++) {
        aero_rotor_ghost *g = &r->ghost[k];
        if (!g->active)
            continue;
        g->active = fade_shape(g->samples, m, r->base.sample_rate, 1, shape);
        g->samples += m;
        if (!g->active)
            continue;
        for (int e = 0; e < r->base.n_ears; e++)
            radiate(r, &g->ear[e], &g->ear[e], gain0 * g->level,
                    gain1 * g->level, r->psi, dpsi, noise, shape, hiss, e,
                    m);
    }
}

/* one chunk of m samples */
static void chunk(aero_rotor *r, const float *rpm, int m)
{
    aero_rotor_ear now[AERO_EARS_MAX];
    double ear[3], axes[9], wind[3], gain_then = r->base.gain.value, gain;
    double dpsi = chunk_turn(r, rpm, m, &r->base.clamped);
    double omega = dpsi * r->base.sample_rate;
    float noise[AERO_ROTOR_CHUNK];
    const double sr = r->base.sample_rate;
    /* the first chunk or the first at a new place: the sound fades in
       (from 0 at the start, as the ghost of the old place fades out) */
    const int fresh = !r->primed || r->jumped;
    if (fresh) {
        if (r->jumped)
            leave_ghost(r, r->fade_in < AERO_GHOST_FADE_S * sr
                               ? 1.0 - aero_ghost_fade(r->fade_in, sr, 1.0)
                               : 1.0);
        r->fade_in = 0.0;
        r->jumped = 0;
    }
    float shape[AERO_ROTOR_CHUNK];
    const int fading = fade_shape(r->fade_in, m, sr, 0, shape);
    r->fade_in += m;
    advance_pose(r, m);
    rotor_axes(r, axes);
    for (int i = 0; i < 3; i++)
        wind[i] = ramp_after(&r->base.wind[i], m);
    double u_axis = aero_dot3(wind, axes + 6);
    /* -noise at its floor: the tones alone, without the noise's cost */
    const int hiss = r->noise_gain > 1e-9;
    /* the self-noise's spectrum and envelope every
       AERO_ROTOR_ENVELOPE_SAMPLES (5.3 ms at 48 kHz, whatever the host's
       block and so the chunk), held between: they move with the geometry
       and the speed, slowly against a chunk, and cost more than the
       tones (a rotor spinning up from rest crosses a spectrum's speed
       step every few chunks) */
    const int due = r->envelope_due <= 0 || fresh;
    if (hiss) {
        if (due)
            noise_spectrum(r, fabs(omega), u_axis);
        noise_chunk(r, noise, m);
    } else
        memset(noise, 0, sizeof(noise));
    gain = ramp_after(&r->base.gain, m);
    radiate_ghosts(r, gain_then, gain, dpsi, noise, hiss, m);
    for (int e = 0; e < r->base.n_ears; e++) {
        for (int i = 0; i < 3; i++)
            ear[i] = ramp_after(&r->base.ear[3 * e + i], m);
        ear_tones(r, omega, ear, axes, &r->sums[e], &now[e]);
        if (!hiss)
            memset(now[e].env, 0, sizeof(now[e].env));
        else if (due)
            ear_envelope(r, omega, u_axis, ear, axes, now[e].env);
        else
            memcpy(now[e].env, r->then[e].env, sizeof(now[e].env));
        if (fresh) /* at its place from the start: no glide from the old */
            r->then[e] = now[e];
        radiate(r, &r->then[e], &now[e], gain_then, gain, r->psi, dpsi,
                noise, fading ? shape : NULL, hiss, e, m);
        r->then[e] = now[e];
    }
    r->envelope_due = due ? AERO_ROTOR_ENVELOPE_SAMPLES - m
                          : r->envelope_due - m;
    r->primed = 1;
    r->psi = fmod(r->psi + dpsi * m, TWO_PI);
    if (r->psi < 0.0)
        r->psi += TWO_PI;
}

int aero_rotor_process(aero_rotor *r, const float *rpm, float *const *out,
                       int n)
{
    r->base.clamped = 0;
    if (aero_moving_player_silent(&r->base, out, n))
        return 0;
    for (int done = 0; done < n;) {
        int m = n - done < AERO_ROTOR_CHUNK ? n - done : AERO_ROTOR_CHUNK;
        /* the poses due at this sample, then a chunk up to the next */
        while ((m = aero_pose_queue_until(&r->queue, done, m)) == 0) {
            aero_pose_event e = *aero_pose_queue_front(&r->queue);
            aero_pose_queue_pop(&r->queue);
            apply_pose(r, e.x, e.interval_s);
            m = n - done < AERO_ROTOR_CHUNK ? n - done : AERO_ROTOR_CHUNK;
        }
        /* read this chunk of rpm before writing that of out (Pd may pass
           the same buffer) */
        chunk(r, rpm ? rpm + done : NULL, m);
        aero_arrivals_take(&r->base.arrivals, out, done, m);
        done += m;
    }
    aero_pose_queue_elapse(&r->queue, n);
    return r->base.clamped;
}
