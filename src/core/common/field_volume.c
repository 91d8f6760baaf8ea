/* aero: volume data for field auralization: the directory format and the
 * synthetic burst (see field_volume.h). */
#include "field_volume.h"

#include "aero_air.h"
#include "aero_util.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int host_is_little_endian(void)
{
    const uint16_t one = 1;
    return *(const unsigned char *)&one == 1;
}

static void swap_floats(float *x, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        unsigned char *b = (unsigned char *)&x[i], t;
        t = b[0], b[0] = b[3], b[3] = t;
        t = b[1], b[1] = b[2], b[2] = t;
    }
}

/* the pattern must hold exactly one integer conversion and no '/' */
static int pattern_ok(const char *p)
{
    int conversions = 0;
    if (strchr(p, '/'))
        return 0;
    for (const char *c = p; *c; c++) {
        if (*c != '%')
            continue;
        if (c[1] == '%') {
            c++;
            continue;
        }
        c++;
        while (*c == '0' || (*c >= '1' && *c <= '9'))
            c++;
        if (*c != 'd')
            return 0;
        conversions++;
    }
    return conversions == 1;
}

static int frame_path(const aero_volume_info *v, int k, char *path,
                      size_t len)
{
    char name[128];
    snprintf(name, sizeof name, v->pattern, k);
    return snprintf(path, len, "%s/%s", v->dir, name) < (int)len ? 0 : -1;
}

/* reads n numbers after the key; 0 when exactly n were there */
static int numbers(char *rest, double *x, int n)
{
    char *end;
    for (int i = 0; i < n; i++) {
        x[i] = strtod(rest, &end);
        if (end == rest || !aero_is_finite(x[i]))
            return -1;
        rest = end;
    }
    while (*rest == ' ' || *rest == '\t')
        rest++;
    return *rest ? -1 : 0;
}

/* the keys a header must hold, marked as they are read */
enum {
    HAVE_DIMS = 1,
    HAVE_SPACING = 2,
    HAVE_RATE = 4,
    HAVE_FRAMES = 8,
    HAVE_FIELDS = 16
};

/* cuts the comment and the blanks off a header line and splits it into its
 * key and the rest; 0 for a line with nothing left */
static int split_line(char *line, char **key, char **rest)
{
    char *c = strchr(line, '#');
    if (c)
        *c = 0;
    c = line + strlen(line);
    while (c > line && (c[-1] == '\n' || c[-1] == '\r' || c[-1] == ' ' ||
                        c[-1] == '\t'))
        *--c = 0;
    *key = line;
    while (**key == ' ' || **key == '\t')
        (*key)++;
    if (!**key)
        return 0;
    c = *key;
    while (*c && *c != ' ' && *c != '\t')
        c++;
    if (*c)
        *c++ = 0;
    while (*c == ' ' || *c == '\t')
        c++;
    *rest = c;
    return 1;
}

static int read_magic(const char *key, const char *rest, char *msg,
                      size_t len)
{
    if (!strcmp(key, "aero-volume") && !strcmp(rest, "1"))
        return 0;
    aero_say(msg, len, "not an aero volume header (the first line must be "
                       "'aero-volume 1')");
    return -1;
}

/* reads the value of one key into v and marks it in *have; 0, or -1 with
 * what is wrong in msg */
static int read_key(aero_volume_info *v, const char *key, char *rest,
                    int *have, char *msg, size_t len)
{
    double x[4];
    if (!strcmp(key, "dims")) {
        if (numbers(rest, x, 3) || x[0] < 2 || x[1] < 2 || x[2] < 2 ||
            x[0] > AERO_VOLUME_MAX_DIM || x[1] > AERO_VOLUME_MAX_DIM ||
            x[2] > AERO_VOLUME_MAX_DIM || x[0] != floor(x[0]) ||
            x[1] != floor(x[1]) || x[2] != floor(x[2])) {
            aero_say(msg, len, "'dims' needs three whole numbers in 2..%d",
                     AERO_VOLUME_MAX_DIM);
            return -1;
        }
        v->nx = (int)x[0], v->ny = (int)x[1], v->nz = (int)x[2];
        *have |= HAVE_DIMS;
    } else if (!strcmp(key, "spacing")) {
        if (numbers(rest, x, 3) || x[0] <= 0 || x[1] <= 0 || x[2] <= 0 ||
            x[0] > 1e4 || x[1] > 1e4 || x[2] > 1e4) {
            aero_say(msg, len, "'spacing' needs three lengths in metres, > 0");
            return -1;
        }
        memcpy(v->spacing, x, sizeof v->spacing);
        *have |= HAVE_SPACING;
    } else if (!strcmp(key, "origin")) {
        if (numbers(rest, x, 3) || fabs(x[0]) > 1e6 || fabs(x[1]) > 1e6 ||
            fabs(x[2]) > 1e6) {
            aero_say(msg, len, "'origin' needs three coordinates in metres");
            return -1;
        }
        memcpy(v->origin, x, sizeof v->origin);
    } else if (!strcmp(key, "rate")) {
        if (numbers(rest, x, 1) || x[0] <= 0 || x[0] > 1e6) {
            aero_say(msg, len, "'rate' needs frames per second, "
                               "0 < rate <= 1e6");
            return -1;
        }
        v->rate = x[0];
        *have |= HAVE_RATE;
    } else if (!strcmp(key, "frames")) {
        if (numbers(rest, x, 1) || x[0] < 1 || x[0] > 1e6 ||
            x[0] != floor(x[0])) {
            aero_say(msg, len, "'frames' needs a whole number >= 1");
            return -1;
        }
        v->frames = (int)x[0];
        *have |= HAVE_FRAMES;
    } else if (!strcmp(key, "fields")) {
        if (!strcmp(rest, "density"))
            v->fields = 1;
        else if (!strcmp(rest, "density vx vy vz"))
            v->fields = 4;
        else {
            aero_say(msg, len, "'fields' must be 'density' or "
                               "'density vx vy vz', not '%s'", rest);
            return -1;
        }
        *have |= HAVE_FIELDS;
    } else if (!strcmp(key, "files")) {
        if (strlen(rest) >= sizeof v->pattern || !pattern_ok(rest)) {
            aero_say(msg, len, "'files' needs a file name pattern with one "
                               "%%d, e.g. frame%%05d.f32");
            return -1;
        }
        strcpy(v->pattern, rest);
    } else {
        aero_say(msg, len, "unknown key '%s' (keys: dims spacing origin rate "
                           "frames fields files)", key);
        return -1;
    }
    return 0;
}

/* reads the header lines; 0, or -1 with "path:line: what" in err */
static int read_lines(FILE *f, const char *path, aero_volume_info *v,
                      int *have, int *lines, char *err, size_t errlen)
{
    char line[512], msg[640];
    while (fgets(line, sizeof line, f)) {
        char *key, *rest;
        int bad;
        ++*lines;
        if (!split_line(line, &key, &rest))
            continue;
        if (*lines == 1 ||
            (!(*have & HAVE_DIMS) && !strcmp(key, "aero-volume")))
            bad = read_magic(key, rest, msg, sizeof msg);
        else
            bad = read_key(v, key, rest, have, msg, sizeof msg);
        if (bad) {
            aero_say(err, errlen, "%s:%d: %s", path, *lines, msg);
            return -1;
        }
    }
    return 0;
}

int aero_volume_read_header(const char *dir, aero_volume_info *v, char *err,
                            size_t errlen)
{
    char path[AERO_VOLUME_PATH + 32];
    int have = 0, lines = 0, rc;
    FILE *f;
    memset(v, 0, sizeof *v);
    strcpy(v->pattern, "frame%05d.f32");
    if (strlen(dir) >= sizeof v->dir) {
        aero_say(err, errlen, "volume directory name too long");
        return -1;
    }
    strcpy(v->dir, dir);
    snprintf(path, sizeof path, "%s/%s", dir, AERO_VOLUME_HEADER);
    if (!(f = fopen(path, "r"))) {
        aero_say(err, errlen, "can't open %s: %s", path, strerror(errno));
        return -1;
    }
    rc = read_lines(f, path, v, &have, &lines, err, errlen);
    fclose(f);
    if (rc)
        return -1;
    if (lines == 0) {
        aero_say(err, errlen, "%s is empty", path);
        return -1;
    }
    if (have != (HAVE_DIMS | HAVE_SPACING | HAVE_RATE | HAVE_FRAMES |
                 HAVE_FIELDS)) {
        aero_say(err, errlen, "%s: missing %s", path,
                 !(have & HAVE_DIMS)      ? "'dims'"
                 : !(have & HAVE_SPACING) ? "'spacing'"
                 : !(have & HAVE_RATE)    ? "'rate'"
                 : !(have & HAVE_FRAMES)  ? "'frames'"
                                          : "'fields'");
        return -1;
    }
    return 0;
}

/* opens frame k and checks its size: the file, or NULL with a message */
static FILE *open_frame(const aero_volume_info *v, int k, char *err,
                        size_t errlen)
{
    char path[AERO_VOLUME_PATH + 160];
    size_t n = aero_volume_count(v) * (size_t)v->fields;
    long want = (long)(n * sizeof(float)), size;
    if (k < 0 || k >= v->frames) {
        aero_say(err, errlen, "frame %d out of range 0..%d", k, v->frames - 1);
        return NULL;
    }
    if (frame_path(v, k, path, sizeof path)) {
        aero_say(err, errlen, "frame file name too long");
        return NULL;
    }
    FILE *f = fopen(path, "rb");
    if (!f) {
        aero_say(err, errlen, "can't open frame %d: %s: %s", k, path,
                 strerror(errno));
        return NULL;
    }
    if (fseek(f, 0, SEEK_END) || (size = ftell(f)) < 0 ||
        fseek(f, 0, SEEK_SET)) {
        aero_say(err, errlen, "can't read %s", path);
        fclose(f);
        return NULL;
    }
    if (size != want) {
        aero_say(err, errlen, "%s is %ld bytes, expected %ld (%d field(s) of "
                 "%dx%dx%d float32)%s", path, size, want, v->fields, v->nx,
                 v->ny, v->nz, size < want ? ": truncated" : ": too long");
        fclose(f);
        return NULL;
    }
    return f;
}

int aero_volume_check_frame(const aero_volume_info *v, int k, char *err,
                            size_t errlen)
{
    FILE *f = open_frame(v, k, err, errlen);
    if (!f)
        return -1;
    fclose(f);
    return 0;
}

int aero_volume_read_frame(const aero_volume_info *v, int k, float *data,
                           char *err, size_t errlen)
{
    char path[AERO_VOLUME_PATH + 160];
    size_t n = aero_volume_count(v) * (size_t)v->fields;
    FILE *f = open_frame(v, k, err, errlen);
    if (!f)
        return -1;
    frame_path(v, k, path, sizeof path);
    size_t got = fread(data, sizeof(float), n, f);
    fclose(f);
    if (got != n) {
        aero_say(err, errlen, "%s: read %lu of %lu values", path,
                 (unsigned long)got, (unsigned long)n);
        return -1;
    }
    if (!host_is_little_endian())
        swap_floats(data, n);
    return 0;
}

int aero_volume_write_header(const aero_volume_info *v, char *err,
                             size_t errlen)
{
    char path[AERO_VOLUME_PATH + 32];
    snprintf(path, sizeof path, "%s/%s", v->dir, AERO_VOLUME_HEADER);
    FILE *f = fopen(path, "w");
    if (!f) {
        aero_say(err, errlen, "can't write %s: %s", path, strerror(errno));
        return -1;
    }
    fprintf(f, "aero-volume 1\n"
            "# field volume for aero (Shin and Bajaj): raw little-endian float32\n"
            "dims %d %d %d\nspacing %.9g %.9g %.9g\norigin %.9g %.9g %.9g\n"
            "rate %.9g\nframes %d\nfields %s\nfiles %s\n",
            v->nx, v->ny, v->nz, v->spacing[0], v->spacing[1], v->spacing[2],
            v->origin[0], v->origin[1], v->origin[2], v->rate, v->frames,
            v->fields == 4 ? "density vx vy vz" : "density", v->pattern);
    if (fclose(f)) {
        aero_say(err, errlen, "can't write %s", path);
        return -1;
    }
    return 0;
}

int aero_volume_write_frame(const aero_volume_info *v, int k,
                            const float *data, char *err, size_t errlen)
{
    char path[AERO_VOLUME_PATH + 160];
    size_t n = aero_volume_count(v) * (size_t)v->fields, put;
    if (frame_path(v, k, path, sizeof path)) {
        aero_say(err, errlen, "frame file name too long");
        return -1;
    }
    FILE *f = fopen(path, "wb");
    if (!f) {
        aero_say(err, errlen, "can't write %s: %s", path, strerror(errno));
        return -1;
    }
    if (host_is_little_endian()) {
        put = fwrite(data, sizeof(float), n, f);
    } else {
        put = 0;
        for (size_t i = 0; i < n; i++) {
            float x = data[i];
            swap_floats(&x, 1);
            put += fwrite(&x, sizeof x, 1, f);
        }
    }
    if (fclose(f) || put != n) {
        aero_say(err, errlen, "can't write %s", path);
        return -1;
    }
    return 0;
}

/* --- the synthetic burst ------------------------------------------------ */

#define DEMO_MODES 16

void aero_field_demo_default(aero_field_demo *d)
{
    d->size = 64;
    d->frames = 48;
    d->spacing = 0.02;
    d->rate = 1000;
    d->shell_speed = 15;
    d->velocity = 0;
    d->seed = 1;
}

void aero_field_demo_info(const aero_field_demo *d, aero_volume_info *v)
{
    memset(v, 0, sizeof *v);
    v->nx = v->ny = v->nz = d->size;
    v->frames = d->frames;
    for (int a = 0; a < 3; a++) {
        v->spacing[a] = d->spacing;
        /* the burst's centre at the world origin */
        v->origin[a] = -0.5 * (d->size - 1) * d->spacing;
    }
    v->rate = d->rate;
    v->fields = d->velocity ? 4 : 1;
    strcpy(v->pattern, "frame%05d.f32");
}

typedef struct {
    double k[3], dir[3], omega, phase, amp;
} demo_mode;

/* the turbulence's Fourier modes, the same for every frame of one seed:
 * wavelengths 4..16 spacings, drifting at 60..300 Hz, amplitude ~ k^-5/6
 * (a Kolmogorov-like velocity spectrum), each velocity mode across its
 * wave vector (divergence-free) */
static void demo_modes(const aero_field_demo *d, demo_mode *m)
{
    uint32_t rng = d->seed ? d->seed * 2654435761u : 1u;
    double norm = 0;
    if (!rng)
        rng = 1;
    for (int i = 0; i < DEMO_MODES; i++) {
        double u[3], len = 0, lambda, kk, c[3], cl = 0;
        do {
            len = 0;
            for (int a = 0; a < 3; a++)
                u[a] = aero_uniform(&rng), len += u[a] * u[a];
        } while (len < 0.01 || len > 1);
        len = sqrt(len);
        lambda = d->spacing * (4 + 12 * 0.5 * (1 + aero_uniform(&rng)));
        kk = 2 * AERO_PI / lambda;
        for (int a = 0; a < 3; a++)
            m[i].k[a] = kk * u[a] / len;
        /* a direction across k: k x (a random vector) */
        double r[3] = {aero_uniform(&rng), aero_uniform(&rng),
                       aero_uniform(&rng)};
        c[0] = u[1] * r[2] - u[2] * r[1];
        c[1] = u[2] * r[0] - u[0] * r[2];
        c[2] = u[0] * r[1] - u[1] * r[0];
        for (int a = 0; a < 3; a++)
            cl += c[a] * c[a];
        cl = sqrt(cl) + 1e-12;
        for (int a = 0; a < 3; a++)
            m[i].dir[a] = c[a] / cl;
        m[i].omega = 2 * AERO_PI * (60 + 120 * (1 + aero_uniform(&rng)));
        m[i].phase = AERO_PI * aero_uniform(&rng);
        m[i].amp = pow(kk * d->spacing, -5.0 / 6.0);
        norm += m[i].amp * m[i].amp;
    }
    norm = 1 / sqrt(0.5 * norm);
    for (int i = 0; i < DEMO_MODES; i++)
        m[i].amp *= norm;
}

void aero_field_demo_frame(const aero_field_demo *d, int k, float *data)
{
    demo_mode modes[DEMO_MODES];
    aero_volume_info v;
    const double t = k / d->rate, h = d->spacing;
    const double r0 = 2 * h, radius = r0 + d->shell_speed * t;
    const double width = 2 * h + 0.15 * radius;
    /* mass in the shell is conserved as it spreads: ~1/R^2 */
    const double shell = 2.0 * (r0 / radius) * (r0 / radius);
    const double core = -0.4 * exp(-t * d->rate / 12.0);
    const double turb = 0.25;
    const size_t n = (size_t)d->size * d->size * d->size;
    demo_modes(d, modes);
    aero_field_demo_info(d, &v);
    for (int z = 0; z < d->size; z++)
        for (int y = 0; y < d->size; y++)
            for (int x = 0; x < d->size; x++) {
                size_t i = x + (size_t)d->size * (y + (size_t)d->size * z);
                double p[3] = {v.origin[0] + x * h, v.origin[1] + y * h,
                               v.origin[2] + z * h};
                double r = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                double s = (r - radius) / width;
                double env = exp(-s * s);
                double rho = AERO_RHO + shell * env +
                             core * exp(-(r / radius) * (r / radius) * 4);
                double vel[3] = {0, 0, 0};
                if (env > 1e-4) {
                    double sum = 0;
                    for (int j = 0; j < DEMO_MODES; j++) {
                        const demo_mode *m = &modes[j];
                        double c = m->amp * cos(m->k[0] * p[0] +
                                                m->k[1] * p[1] +
                                                m->k[2] * p[2] +
                                                m->omega * t + m->phase);
                        sum += c;
                        for (int a = 0; a < 3; a++)
                            vel[a] += c * m->dir[a];
                    }
                    rho += turb * shell * env * sum;
                }
                if (rho < 0.05)
                    rho = 0.05;
                data[i] = (float)rho;
                if (d->velocity) {
                    /* the shell's outward motion plus the turbulence */
                    for (int a = 0; a < 3; a++) {
                        double radial = r > 1e-9 ? p[a] / r : 0;
                        data[i + (size_t)(a + 1) * n] =
                            (float)(env * (d->shell_speed * radial +
                                           0.3 * d->shell_speed * vel[a]));
                    }
                }
            }
}
