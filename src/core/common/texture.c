/* aero: sound texture files and the signal steps that make them
 * (see texture.h). */
#include "texture.h"
#include "aero_air.h"
#include "aero_util.h"

#include <math.h>
#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int aero_texture_init(aero_texture *t, int frames, int directions, double rate)
{
    return aero_texture_init_regions(t, frames, directions, 1, rate);
}

int aero_texture_init_regions(aero_texture *t, int frames, int directions,
                              int regions, double rate)
{
    memset(t, 0, sizeof *t);
    if (frames < 1 || directions < 1 || regions < 1 ||
        (long)directions * regions > AERO_TEXTURE_MAX_SOURCES ||
        !(rate > 0.0))
        return -1;
    t->frames = frames;
    t->directions = directions;
    t->regions = regions;
    t->channels = 3 * directions * regions;
    t->rate = rate;
    t->data = calloc((size_t)frames * t->channels, sizeof(float));
    t->angles = calloc((size_t)directions, sizeof(double));
    t->meta = calloc(1, 1);
    if (!t->data || !t->angles || !t->meta) {
        aero_texture_free(t);
        return -1;
    }
    return 0;
}

int aero_texture_init_speeds(aero_texture *t, int frames, int nspeeds,
                             const double *speeds, double rate)
{
    char buf[64];
    memset(t, 0, sizeof *t);
    if (frames < 1 || nspeeds < 1 || !(rate > 0.0))
        return -1;
    for (int k = 0; k < nspeeds; k++)
        if (!(speeds[k] > 0.0) || (k && !(speeds[k] > speeds[k - 1])))
            return -1;
    t->frames = frames;
    t->channels = nspeeds;
    t->rate = rate;
    t->data = calloc((size_t)frames * nspeeds, sizeof(float));
    t->speeds = malloc(sizeof(double) * nspeeds);
    t->meta = calloc(1, 1);
    if (!t->data || !t->speeds || !t->meta) {
        aero_texture_free(t);
        return -1;
    }
    memcpy(t->speeds, speeds, sizeof(double) * nspeeds);
    aero_texture_set(t, "kind", "vortex");
    {
        /* the list, comma-separated */
        size_t len = 1;
        char *list;
        for (int k = 0; k < nspeeds; k++)
            len += (size_t)snprintf(buf, sizeof buf, "%.9g,", speeds[k]);
        list = malloc(len);
        if (!list) {
            aero_texture_free(t);
            return -1;
        }
        list[0] = 0;
        for (int k = 0; k < nspeeds; k++) {
            snprintf(buf, sizeof buf, "%s%.9g", k ? "," : "", speeds[k]);
            strcat(list, buf);
        }
        aero_texture_set(t, "speeds", list);
        free(list);
    }
    return 0;
}

void aero_texture_free(aero_texture *t)
{
    AERO_FREE_ALL(t->data, t->speeds, t->angles, t->meta);
    memset(t, 0, sizeof *t);
}

/* start of the line "key=..." in meta, or NULL */
static const char *find_key(const char *meta, const char *key)
{
    size_t kl = strlen(key);
    const char *p = meta;
    while (p && *p) {
        if (strncmp(p, key, kl) == 0 && p[kl] == '=')
            return p;
        p = strchr(p, '\n');
        if (p) p++;
    }
    return NULL;
}

static const char *value_of(const aero_texture *t, const char *key);

/* t->head from t->meta: once per change of the metadata */
static void parse_head(aero_texture *t)
{
    aero_texture_header *h = &t->head;
    memset(h, 0, sizeof *h);
    aero_texture_get(t, "kind", h->kind, sizeof h->kind);
    aero_texture_get(t, "method", h->method, sizeof h->method);
    aero_texture_get(t, "shape", h->shape, sizeof h->shape);
    aero_texture_get(t, "span3d", h->span3d, sizeof h->span3d);
    aero_texture_get(t, "symmetry", h->symmetry, sizeof h->symmetry);
    h->symmetry_deg = aero_texture_getd(t, "symmetry", 0.0);
    h->v0 = aero_texture_getd(t, "v0", 0.0);
    h->diameter = aero_texture_getd(t, "diameter", 0.0);
    h->length = aero_texture_getd(t, "length", 0.0);
    h->st = aero_texture_getd(t, "st", 0.0);
    h->re = aero_texture_getd(t, "re", 0.0);
    h->nu = aero_texture_getd(t, "nu", 0.0);
    h->mirror = aero_texture_getd(t, "mirror", 0.0);
    h->diameters = value_of(t, "diameters");
    h->centres = value_of(t, "centres");
}

int aero_texture_set(aero_texture *t, const char *key, const char *value)
{
    const char *old = find_key(t->meta ? t->meta : "", key);
    size_t len = t->meta ? strlen(t->meta) : 0;
    size_t add = strlen(key) + strlen(value) + 2;
    char *m;
    if (strchr(key, '=') || strchr(key, '\n') || strchr(value, '\n'))
        return -1;
    m = malloc(len + add + 1);
    if (!m)
        return -1;
    if (old) {
        /* drop the old line */
        const char *end = strchr(old, '\n');
        size_t pre = (size_t)(old - t->meta);
        memcpy(m, t->meta, pre);
        m[pre] = 0;
        if (end) strcat(m, end + 1);
    } else {
        memcpy(m, t->meta ? t->meta : "", len + 1);
    }
    strcat(m, key);
    strcat(m, "=");
    strcat(m, value);
    strcat(m, "\n");
    free(t->meta);
    t->meta = m;
    parse_head(t);
    return 0;
}

int aero_texture_setd(aero_texture *t, const char *key, double value)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%.9g", value);
    return aero_texture_set(t, key, buf);
}

/* the value of key, in place (it ends at '\n'), or NULL */
static const char *value_of(const aero_texture *t, const char *key)
{
    const char *p = t->meta ? find_key(t->meta, key) : NULL;
    return p ? p + strlen(key) + 1 : NULL;
}

const char *aero_texture_get(const aero_texture *t, const char *key,
                             char *buf, size_t len)
{
    const char *v = value_of(t, key);
    size_t n;
    if (!v || !len)
        return NULL;
    n = strcspn(v, "\n");
    if (n >= len) n = len - 1;
    memcpy(buf, v, n);
    buf[n] = 0;
    return buf;
}

double aero_texture_getd(const aero_texture *t, const char *key, double def)
{
    const char *v = value_of(t, key);
    char *end;
    double x;
    if (!v)
        return def;
    x = strtod(v, &end);
    return (end == v) ? def : x;
}

float aero_texture_sample(const aero_texture *t, long n, int k, int c)
{
    long m = n % t->frames;
    if (m < 0) m += t->frames;
    return t->data[(size_t)m * t->channels + 3 * k + c];
}

int aero_texture_save(const char *path, const aero_texture *t, char *err,
                      size_t errlen)
{
    SF_INFO info;
    SNDFILE *f;
    sf_count_t n;
    aero_texture tmp;
    int bad;
    memset(&info, 0, sizeof info);
    info.samplerate = (int)lrint(t->rate);
    info.channels = t->channels;
    info.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
    if (fabs(info.samplerate - t->rate) > 1e-9 * t->rate) {
        snprintf(err, errlen, "texture rate %g Hz is not an integer", t->rate);
        return -1;
    }
    /* the frame count goes into the metadata too: a reader detects a
       truncated file by it */
    memset(&tmp, 0, sizeof tmp);
    tmp.meta = malloc(strlen(t->meta ? t->meta : "") + 1);
    if (!tmp.meta) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    strcpy(tmp.meta, t->meta ? t->meta : "");
    aero_texture_setd(&tmp, "frames", t->frames);
    f = sf_open(path, SFM_WRITE, &info);
    if (!f) {
        snprintf(err, errlen, "can't write %s: %s", path, sf_strerror(NULL));
        free(tmp.meta);
        return -1;
    }
    /* no PEAK chunk: it holds the time of writing, so that two runs of
       the same command would not give the same file */
    sf_command(f, SFC_SET_ADD_PEAK_CHUNK, NULL, SF_FALSE);
    bad = sf_set_string(f, SF_STR_COMMENT, tmp.meta);
    free(tmp.meta);
    if (bad ||
        sf_set_string(f, SF_STR_SOFTWARE, "aero aerotex")) {
        snprintf(err, errlen, "can't store the metadata in %s: %s", path,
                 sf_strerror(f));
        sf_close(f);
        return -1;
    }
    n = sf_writef_float(f, t->data, t->frames);
    if (n != t->frames) {
        snprintf(err, errlen, "can't write %s: %s", path, sf_strerror(f));
        sf_close(f);
        return -1;
    }
    if (sf_close(f)) {
        snprintf(err, errlen, "can't close %s", path);
        return -1;
    }
    return 0;
}

/* the comma-separated angle list of the metadata */
static int parse_angles(aero_texture *t)
{
    const char *p = value_of(t, "angles");
    if (!p) {
        /* start + step form */
        double a0 = aero_texture_getd(t, "angle_start", 0.0);
        double da = aero_texture_getd(t, "angle_step", 0.0);
        for (int k = 0; k < t->directions; k++)
            t->angles[k] = a0 + k * da;
        return 0;
    }
    for (int k = 0; k < t->directions; k++) {
        char *end;
        t->angles[k] = strtod(p, &end);
        if (end == p || !isfinite(t->angles[k]))
            return -1;
        p = end;
        if (k < t->directions - 1) {
            if (*p != ',') return -1;
            p++;
        }
    }
    return (*p == '\n' || *p == 0) ? 0 : -1;
}

/* frames= and rate= against the file's own: t->frames and t->rate set, 0;
   or -1 with a message */
static int take_size(aero_texture *t, const SF_INFO *in, const char *path,
                     char *err, size_t errlen)
{
    if (aero_texture_getd(t, "frames", (double)in->frames) != in->frames) {
        snprintf(err, errlen, "%s is truncated: %ld of %g frames", path,
                 (long)in->frames, aero_texture_getd(t, "frames", 0.0));
        return -1;
    }
    t->frames = (int)in->frames;
    t->rate = aero_texture_getd(t, "rate", (double)in->samplerate);
    if (!(t->rate > 0.0) || fabs(t->rate - in->samplerate) > 0.5) {
        snprintf(err, errlen, "%s: rate=%g does not match the file's %d Hz",
                 path, t->rate, in->samplerate);
        return -1;
    }
    return 0;
}

/* t->frames x t->channels samples from f into t->data, every one finite:
   0, or -1 with a message */
static int read_samples(SNDFILE *f, aero_texture *t, const char *path,
                        char *err, size_t errlen)
{
    if (sf_readf_float(f, t->data, t->frames) != t->frames) {
        snprintf(err, errlen, "%s is truncated (expected %d frames)", path,
                 t->frames);
        return -1;
    }
    for (size_t k = 0; k < (size_t)t->frames * t->channels; k++)
        if (!isfinite(t->data[k])) {
            snprintf(err, errlen, "%s holds a non-finite sample at frame %ld",
                     path, (long)(k / t->channels));
            return -1;
        }
    return 0;
}

/* speeds=: n increasing positive speeds into t->speeds: 0, or -1 */
static int read_speeds(aero_texture *t, int n, const char *path, char *err,
                       size_t errlen)
{
    const char *p = value_of(t, "speeds");
    t->speeds = malloc(sizeof(double) * (n > 0 ? n : 1));
    if (!t->speeds) {
        snprintf(err, errlen, "out of memory reading %s", path);
        return -1;
    }
    for (int k = 0; k < n; k++) {
        char *end;
        t->speeds[k] = p ? strtod(p, &end) : 0.0;
        if (!p || end == p || !(t->speeds[k] > 0.0) ||
            !isfinite(t->speeds[k]) ||
            (k && !(t->speeds[k] > t->speeds[k - 1])) ||
            (k < n - 1 && *end != ',') ||
            (k == n - 1 && *end != '\n' && *end)) {
            snprintf(err, errlen, "%s: speeds= must list %d increasing "
                     "positive speeds, one per channel", path, n);
            return -1;
        }
        p = end + 1;
    }
    return 0;
}

/* the rest of a vortex texture's load (meta read; the file is reopened):
   one channel per speed, speeds= increasing and positive */
static int check_ceiling(const aero_texture *t, const char *path, char *err,
                         size_t errlen);

static int load_vortex(const char *path, aero_texture *t, const SF_INFO *in,
                       char *err, size_t errlen)
{
    SF_INFO info;
    SNDFILE *f = NULL;
    const int n = in->channels;
    memset(&info, 0, sizeof info);
    if (read_speeds(t, n, path, err, errlen) ||
        take_size(t, in, path, err, errlen))
        goto fail;
    t->channels = n;
    t->directions = 0;
    t->data = malloc(sizeof(float) * (size_t)t->frames * n);
    f = sf_open(path, SFM_READ, &info);
    if (!t->data || !f) {
        snprintf(err, errlen, "can't read %s", path);
        goto fail;
    }
    if (read_samples(f, t, path, err, errlen) ||
        check_ceiling(t, path, err, errlen))
        goto fail;
    sf_close(f);
    return 0;
fail:
    if (f) sf_close(f);
    aero_texture_free(t);
    return -1;
}

/* --- the physical ceiling of a texture's samples ---------------------------
 * A file holds finite floats that no flow could have made (a corrupt or
 * hostile file: 3e38 is finite). Each sample is held to the most that the
 * metadata's body and speed allow, times a margin; the shipped textures sit
 * 120 (square.wav) to 20000 times below their bound (test_texture.c checks
 * at least 100), a corrupt sample many decades above it.
 *
 * Force textures (aeolian, cavity: g = dF/dt per unit span, N/(m s);
 * object: N/s per region): the force is at most 0.5 rho v0^2 A C_F with
 * A = d (per unit span) or the body's frontal box d x (d + 2 max|centre|)
 * (object), and C_F <= AERO_TEXTURE_FORCE_COEFF_MAX, five times the largest
 * fluctuating force coefficients of bluff sections in the measured data
 * (about 2: a square cylinder, Lyn et al. 1995; a plate broadside, Fage
 * and Johansen 1927; a circular cylinder's peak lift, Norberg 2003). A
 * signal band-limited to rate/2 changes at most pi rate times its largest
 * value (Bernstein's inequality), so |g| <= pi rate F_max. d is the
 * diameter (cavity: its length), 10 m when the file does not say (the
 * largest body [aeolian~] takes).
 *
 * Vortex textures (Q(u, t), Pa at 1 m): Howe's compact vortex sound
 * (Howe 2003) Q = rho / (12 pi c0^2) d3/dt3 INT y (y x omega) dy scales as
 * rho u^4 L / (12 pi c0^2) for eddies of the box L at speed u; the margin
 * AERO_TEXTURE_VORTEX_MARGIN covers eddies smaller than the box and the
 * peaks of a turbulent signal (fire.wav peaks at 11 to 16 times the
 * scaling). L is the metadata's box, 100 m when missing (the longest
 * [vortex~] length). And no Q beyond 1 atm x 1 m (101325 Pa m): no sound
 * in air exceeds the ambient pressure. */
#define AERO_TEXTURE_FORCE_COEFF_MAX 10.0
#define AERO_TEXTURE_VORTEX_MARGIN 1e4
#define AERO_TEXTURE_AMBIENT_PA 101325.0

/* the largest distance of an object texture's region centres from its
   origin ("x,y,z;x,y,z..."), 0 when there are none */
static double centres_reach(const char *c)
{
    double reach = 0.0;
    while (c && *c && *c != '\n') {
        double v[3] = {0, 0, 0};
        for (int k = 0; k < 3; k++) {
            char *end;
            v[k] = strtod(c, &end);
            if (end == c)
                return reach;
            c = end;
            if (*c == ',')
                c++;
        }
        double r = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (r > reach && r < 1e6)
            reach = r;
        if (*c == ';')
            c++;
    }
    return reach;
}

double aero_texture_ceiling(const aero_texture *t, int channel)
{
    char kind[32];
    double rho = aero_texture_getd(t, "rho", AERO_RHO);
    if (!(rho > 0.0 && rho < 100.0))
        rho = AERO_RHO;
    if (!aero_texture_get(t, "kind", kind, sizeof kind))
        kind[0] = '\0';
    if (t->speeds) {
        double c0 = aero_texture_getd(t, "c0", AERO_C0);
        double box = aero_texture_getd(t, "box", 100.0);
        double u = t->speeds[channel];
        if (!(c0 > 1.0 && c0 < 1e4))
            c0 = AERO_C0;
        if (!(box > 0.0 && box <= 100.0))
            box = 100.0;
        double q = AERO_TEXTURE_VORTEX_MARGIN * rho * u * u * u * u * box /
                   (12.0 * AERO_PI * c0 * c0);
        return q < AERO_TEXTURE_AMBIENT_PA ? q : AERO_TEXTURE_AMBIENT_PA;
    }
    double v0 = aero_texture_getd(t, "v0", 0.0);
    double d = aero_texture_getd(t, "diameter",
                                 aero_texture_getd(t, "length", 10.0));
    if (!(d > 0.0 && d <= 10.0))
        d = 10.0;
    double area = d;
    if (!strcmp(kind, "object"))
        area = d * (d + 2.0 * centres_reach(value_of(t, "centres")));
    return AERO_PI * t->rate * 0.5 * rho * v0 * v0 * area *
           AERO_TEXTURE_FORCE_COEFF_MAX;
}

/* every sample within its channel's ceiling: 0, or -1 naming the first
   one beyond; and the loop's cross-fade, when stated, within the file */
static int check_ceiling(const aero_texture *t, const char *path, char *err,
                         size_t errlen)
{
    double xfade = aero_texture_getd(t, "xfade", 0.0);
    if (!(xfade >= 0.0 && xfade <= t->frames)) {
        snprintf(err, errlen, "%s: xfade=%g frames is not within the file's "
                 "%d frames", path, xfade, t->frames);
        return -1;
    }
    for (int c = 0; c < t->channels; c++) {
        double lim = aero_texture_ceiling(t, c);
        for (long n = 0; n < t->frames; n++) {
            double y = t->data[(size_t)n * t->channels + c];
            if (fabs(y) <= lim)
                continue;
            if (t->speeds)
                snprintf(err, errlen, "%s: channel %d (%g m/s), frame %ld: "
                         "%g Pa at 1 m is beyond what a flow of that speed "
                         "can make (at most %.3g: Howe's vortex sound "
                         "scaling; see texture.c)", path, c + 1,
                         t->speeds[c], n, y, lim);
            else
                snprintf(err, errlen, "%s: channel %d, frame %ld: %g is "
                         "beyond what its body at v0 = %g m/s can make (at "
                         "most %.3g %s: a force coefficient of %g at every "
                         "frequency up to rate/2; see texture.c)", path,
                         c + 1, n, y,
                         aero_texture_getd(t, "v0", 0.0), lim,
                         strstr(t->meta, "kind=object") ? "N/s" : "N/(m s)",
                         AERO_TEXTURE_FORCE_COEFF_MAX);
            return -1;
        }
    }
    return 0;
}

/* opens a texture file and copies its metadata into t->meta (one key per
   line, ending in a newline): the file, or NULL with a message */
static SNDFILE *open_texture(const char *path, aero_texture *t,
                             SF_INFO *info, char *err, size_t errlen)
{
    SNDFILE *f = sf_open(path, SFM_READ, info);
    const char *c;
    if (!f) {
        snprintf(err, errlen, "can't open texture %s: %s", path,
                 sf_strerror(NULL));
        return NULL;
    }
    c = sf_get_string(f, SF_STR_COMMENT);
    if (!c || !strstr(c, "kind=")) {
        snprintf(err, errlen, "%s is not an aero texture (no metadata)", path);
        sf_close(f);
        return NULL;
    }
    if (info->frames < 2 || info->frames > 100000000 ||
        info->samplerate <= 0) {
        snprintf(err, errlen, "%s: bad texture size (%ld frames at %d Hz)",
                 path, (long)info->frames, info->samplerate);
        sf_close(f);
        return NULL;
    }
    t->meta = malloc(strlen(c) + 2);
    if (!t->meta) {
        snprintf(err, errlen, "out of memory reading %s", path);
        sf_close(f);
        return NULL;
    }
    strcpy(t->meta, c);
    if (t->meta[0] && t->meta[strlen(t->meta) - 1] != '\n')
        strcat(t->meta, "\n");
    parse_head(t);
    return f;
}

/* directions= and regions= against the channels (3 per direction and
   region): 0, or -1 with a message */
static int read_layout(aero_texture *t, int channels, const char *path,
                       char *err, size_t errlen)
{
    /* range before the cast: the file may say directions=1e300 */
    double dirs_value = aero_texture_getd(t, "directions", 0.0);
    double regions_value = aero_texture_getd(t, "regions", 1.0);
    int dirs = dirs_value >= 1.0 && dirs_value <= 1e6 ? (int)dirs_value : 0;
    int regions = regions_value >= 1.0 &&
                          regions_value <= AERO_TEXTURE_MAX_SOURCES &&
                          regions_value == floor(regions_value)
                      ? (int)regions_value : 0;
    if (dirs < 1 || regions < 1 ||
        (double)channels != 3.0 * dirs * regions) {
        snprintf(err, errlen,
                 "%s: %d channels do not match directions=%d regions=%d (3 "
                 "per direction and region)", path, channels, dirs,
                 regions);
        return -1;
    }
    t->channels = channels;
    t->directions = dirs;
    t->regions = regions;
    return 0;
}

int aero_texture_load(const char *path, aero_texture *t, char *err,
                      size_t errlen)
{
    SF_INFO info;
    SNDFILE *f;
    char kind[32];
    memset(t, 0, sizeof *t);
    memset(&info, 0, sizeof info);
    if (!(f = open_texture(path, t, &info, err, errlen))) {
        aero_texture_free(t);
        return -1;
    }
    if (aero_texture_get(t, "kind", kind, sizeof kind) &&
        !strcmp(kind, "vortex")) {
        sf_close(f);
        return load_vortex(path, t, &info, err, errlen);
    }
    if (read_layout(t, info.channels, path, err, errlen) ||
        take_size(t, &info, path, err, errlen))
        goto fail;
    t->data = malloc(sizeof(float) * (size_t)t->frames * t->channels);
    t->angles = malloc(sizeof(double) * t->directions);
    if (!t->data || !t->angles) {
        snprintf(err, errlen, "out of memory reading %s", path);
        goto fail;
    }
    if (read_samples(f, t, path, err, errlen))
        goto fail;
    if (parse_angles(t)) {
        snprintf(err, errlen, "%s: bad angles= list", path);
        goto fail;
    }
    if (!(aero_texture_getd(t, "v0", 0.0) > 0.0)) {
        snprintf(err, errlen, "%s: missing or bad v0", path);
        goto fail;
    }
    if (check_ceiling(t, path, err, errlen))
        goto fail;
    sf_close(f);
    return 0;
fail:
    sf_close(f);
    aero_texture_free(t);
    return -1;
}

double aero_texture_lowpass_kernel(double t, double fc, double w)
{
    double x = 2.0 * fc * t, s, q;
    if (fabs(t) >= w)
        return 0.0;
    s = fabs(x) < 1e-12 ? 1.0 : sin(AERO_PI * x) / (AERO_PI * x);
    q = AERO_PI * (t / w + 1.0); /* 0 .. 2 pi over the window */
    return 2.0 * fc * s * (0.42 - 0.5 * cos(q) + 0.08 * cos(2.0 * q));
}

void aero_texture_resample_derivative(const double *t, const double *f,
                                      int n, double rate, double t0,
                                      double scale, float *out, int stride,
                                      int nout)
{
    aero_texture_resample_derivative_fc(t, f, n, rate, 0.45 * rate, t0, scale,
                                        out, stride, nout);
}

void aero_texture_resample_derivative_fc(const double *t, const double *f,
                                         int n, double rate, double fc,
                                         double t0, double scale, float *out,
                                         int stride, int nout)
{
    const double w = 8.0 / fc;
    int lo = 0;
    for (int k = 0; k < nout; k++) {
        double tk = t0 + k / rate, acc = 0.0;
        while (lo < n - 1 && t[lo + 1] < tk - w)
            lo++;
        /* g = dF/dt = (F[m+1] - F[m]) / (t[m+1] - t[m]) at the midpoint,
           weighted by its interval: the interval cancels */
        for (int m = lo; m < n - 1 && t[m] <= tk + w; m++)
            acc += (f[m + 1] - f[m]) *
                   aero_texture_lowpass_kernel(tk - 0.5 * (t[m] + t[m + 1]),
                                               fc, w);
        out[(size_t)k * stride] = (float)(acc * scale);
    }
}

int aero_texture_best_loop(const float *x, int channels, int lmin, int lmax,
                           int xfade)
{
    int best = lmin;
    double bestc = -2.0;
    for (int l = lmin; l <= lmax; l++) {
        double sab = 0.0, saa = 0.0, sbb = 0.0, c;
        for (int n = 0; n < xfade; n++)
            for (int ch = 0; ch < channels; ch++) {
                double a = x[(size_t)n * channels + ch];
                double b = x[(size_t)(l + n) * channels + ch];
                sab += a * b;
                saa += a * a;
                sbb += b * b;
            }
        c = (saa > 0.0 && sbb > 0.0) ? sab / sqrt(saa * sbb) : 0.0;
        if (c > bestc) {
            bestc = c;
            best = l;
        }
    }
    return best;
}

void aero_texture_crossfade(float *x, int channels, int len, int xfade)
{
    for (int n = 0; n < xfade; n++) {
        float w = (float)n / (float)xfade;
        for (int ch = 0; ch < channels; ch++) {
            size_t a = (size_t)n * channels + ch, b = (size_t)(len + n) * channels + ch;
            x[a] = w * x[a] + (1.0f - w) * x[b];
        }
    }
}

/* --- the wrong kind of texture --------------------------------------------- */

int aero_texture_wrong_kind(const aero_texture *t, const char *want,
                            char *err, size_t errlen)
{
    static const char *const players[][2] = {
        {"aeolian", "[aeolian~]"}, {"object", "[body~]"},
        {"vortex", "[vortex~]"}, {"cavity", "[cavity~]"}};
    const char *kind = t->head.kind, *player = NULL;
    if (!strcmp(kind, want))
        return 0;
    for (size_t k = 0; k < sizeof players / sizeof *players; k++)
        if (!strcmp(kind, players[k][0]))
            player = players[k][1];
    if (player)
        snprintf(err, errlen, "not %s %s texture: it is %s %s texture, for "
                 "%s", want[0] == 'a' || want[0] == 'o' ? "an" : "a", want,
                 kind[0] == 'a' || kind[0] == 'o' ? "an" : "a", kind, player);
    else
        snprintf(err, errlen, "not %s %s texture (kind=%s)",
                 want[0] == 'a' || want[0] == 'o' ? "an" : "a", want,
                 kind[0] ? kind : "missing");
    return -1;
}
