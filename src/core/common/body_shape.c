/* aero: closed 3D bodies (see body_shape.h). */
#include "body_shape.h"
#include "aero_air.h"
#include "aero_util.h"

#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SIZE_M 100.0

static int size_ok(double x)
{
    return x > 0.0 && x <= MAX_SIZE_M;
}

static void set_box(aero_body_shape *b, double x0, double y0, double z0,
                    double x1, double y1, double z1)
{
    b->lo[0] = x0;
    b->lo[1] = y0;
    b->lo[2] = z0;
    b->hi[0] = x1;
    b->hi[1] = y1;
    b->hi[2] = z1;
}

int aero_body_sphere(aero_body_shape *b, double radius, char *err,
                     size_t errlen)
{
    memset(b, 0, sizeof *b);
    if (!size_ok(radius)) {
        snprintf(err, errlen, "sphere radius %g m: must be > 0 and <= %g m",
                 radius, MAX_SIZE_M);
        return -1;
    }
    b->kind = AERO_BODY_SPHERE;
    b->radius = radius;
    set_box(b, -radius, -radius, -radius, radius, radius, radius);
    return 0;
}

int aero_body_capsule(aero_body_shape *b, double radius, double length,
                      char *err, size_t errlen)
{
    memset(b, 0, sizeof *b);
    if (!size_ok(radius) || !size_ok(length) || length < 2.0 * radius) {
        snprintf(err, errlen, "capsule radius %g m, length %g m: sizes > 0 "
                 "and <= %g m, length >= 2 radius", radius, length,
                 MAX_SIZE_M);
        return -1;
    }
    b->kind = AERO_BODY_CAPSULE;
    b->radius = radius;
    b->length = length;
    set_box(b, -radius, -radius, -0.5 * length, radius, radius,
            0.5 * length);
    return 0;
}

int aero_body_club(aero_body_shape *b, double r_handle, double r_tip,
                   double length, char *err, size_t errlen)
{
    memset(b, 0, sizeof *b);
    if (!size_ok(r_handle) || !size_ok(r_tip) || !size_ok(length) ||
        r_handle > r_tip || length < 4.0 * r_tip) {
        snprintf(err, errlen, "club handle radius %g m, tip radius %g m, "
                 "length %g m: sizes > 0 and <= %g m, handle <= tip, length "
                 ">= 4 tip radii", r_handle, r_tip, length, MAX_SIZE_M);
        return -1;
    }
    b->kind = AERO_BODY_CLUB;
    b->r_handle = r_handle;
    b->r_tip = r_tip;
    b->length = length;
    set_box(b, -r_tip, -r_tip, 0.0, r_tip, r_tip, length);
    return 0;
}

void aero_body_shape_free(aero_body_shape *b)
{
    free(b->vertices);
    free(b->triangles);
    memset(b, 0, sizeof *b);
}

/* --- mesh --------------------------------------------------------------- */

typedef struct {
    double *v;
    int nv, capv;
    int *t;
    int nt, capt;
} mesh_build;

static int push_vertex(mesh_build *m, const double *x)
{
    double *v = aero_grow(m->v, m->nv, &m->capv, 3 * sizeof(double));
    if (!v) return -1;
    m->v = v;
    memcpy(m->v + 3 * (size_t)m->nv, x, 3 * sizeof(double));
    m->nv++;
    return 0;
}

static int push_triangle(mesh_build *m, int a, int b, int c)
{
    int *t = aero_grow(m->t, m->nt, &m->capt, 3 * sizeof(int));
    if (!t) return -1;
    m->t = t;
    m->t[3 * (size_t)m->nt] = a;
    m->t[3 * (size_t)m->nt + 1] = b;
    m->t[3 * (size_t)m->nt + 2] = c;
    m->nt++;
    return 0;
}

static int starts_with_word(const char *p, const char *w)
{
    size_t n = strlen(w);
    return !strncmp(p, w, n) && (p[n] == 0 || isspace((unsigned char)p[n]));
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* every edge in exactly two triangles: 0, or -1 naming an open edge */
static int check_closed(const mesh_build *m, char *err, size_t errlen)
{
    size_t ne = 3 * (size_t)m->nt;
    uint64_t *e = malloc(sizeof(uint64_t) * (ne ? ne : 1));
    if (!e) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (int t = 0; t < m->nt; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = (uint32_t)m->t[3 * t + k];
            uint32_t b = (uint32_t)m->t[3 * t + (k + 1) % 3];
            if (a > b) {
                uint32_t s = a;
                a = b;
                b = s;
            }
            e[3 * (size_t)t + k] = ((uint64_t)a << 32) | b;
        }
    qsort(e, ne, sizeof(uint64_t), cmp_u64);
    for (size_t i = 0; i < ne;) {
        size_t j = i;
        while (j < ne && e[j] == e[i])
            j++;
        if (j - i != 2) {
            snprintf(err, errlen, "the mesh is not closed: edge %u-%u "
                     "belongs to %lu face%s (every edge must join exactly "
                     "two)", (unsigned)(e[i] >> 32) + 1,
                     (unsigned)(e[i] & 0xffffffffu) + 1,
                     (unsigned long)(j - i),
                     j - i == 1 ? "" : "s");
            free(e);
            return -1;
        }
        i = j;
    }
    free(e);
    return 0;
}

/* "v x y z": 0, or -1 with a message */
static int read_vertex(mesh_build *m, char *q, int line, char *err,
                       size_t errlen)
{
    double x[3];
    char *e = q + 1;
    for (int k = 0; k < 3; k++) {
        char *s = e;
        x[k] = strtod(s, &e);
        if (e == s || !isfinite(x[k]) || fabs(x[k]) > MAX_SIZE_M) {
            snprintf(err, errlen, "line %d: a vertex takes three "
                     "numbers within +-%g m", line, MAX_SIZE_M);
            return -1;
        }
    }
    if (m->nv >= AERO_BODY_MAX_MESH_VERTICES) {
        snprintf(err, errlen, "line %d: more than %d vertices", line,
                 AERO_BODY_MAX_MESH_VERTICES);
        return -1;
    }
    if (push_vertex(m, x)) {
        snprintf(err, errlen, "out of memory reading the mesh");
        return -1;
    }
    return 0;
}

/* "f i j k ..." (1-based, negative counts back, "/t/n" ignored), split
   into a fan of triangles: 0, or -1 with a message */
static int read_face(mesh_build *m, char *q, int line, char *err,
                     size_t errlen)
{
    int idx[64], k = 0;
    char *e = q + 1;
    for (;;) {
        char *s = e;
        long v;
        while (isspace((unsigned char)*s))
            s++;
        if (!*s)
            break;
        v = strtol(s, &e, 10);
        if (e == s || v == 0 || v > m->nv || v < -(long)m->nv) {
            snprintf(err, errlen, "line %d: a face's vertex index "
                     "must name one of the %d vertices so far",
                     line, m->nv);
            return -1;
        }
        while (*e && !isspace((unsigned char)*e)) /* "/t/n" */
            e++;
        if (k == 64) {
            snprintf(err, errlen, "line %d: a face of more than 64 "
                     "vertices", line);
            return -1;
        }
        idx[k++] = v > 0 ? (int)v - 1 : m->nv + (int)v;
    }
    if (k < 3) {
        snprintf(err, errlen, "line %d: a face needs at least 3 "
                 "vertices", line);
        return -1;
    }
    for (int i = 1; i + 1 < k; i++) {
        if (m->nt >= AERO_BODY_MAX_MESH_FACES) {
            snprintf(err, errlen, "line %d: more than %d triangles",
                     line, AERO_BODY_MAX_MESH_FACES);
            return -1;
        }
        if (push_triangle(m, idx[0], idx[i], idx[i + 1])) {
            snprintf(err, errlen, "out of memory reading the mesh");
            return -1;
        }
    }
    return 0;
}

/* one line of the OBJ subset: 0, or -1 with a message */
static int read_line(mesh_build *m, char *q, int line, char *err,
                     size_t errlen)
{
    while (isspace((unsigned char)*q))
        q++;
    if (!*q || *q == '#')
        return 0;
    if (starts_with_word(q, "vn") || starts_with_word(q, "vt") ||
        starts_with_word(q, "o") || starts_with_word(q, "g") ||
        starts_with_word(q, "s") || starts_with_word(q, "usemtl") ||
        starts_with_word(q, "mtllib"))
        return 0;
    if (starts_with_word(q, "v"))
        return read_vertex(m, q, line, err, errlen);
    if (starts_with_word(q, "f"))
        return read_face(m, q, line, err, errlen);
    snprintf(err, errlen, "line %d: expected 'v x y z' or 'f i j k' "
             "(got '%.40s')", line, q);
    return -1;
}

/* enough faces, none degenerate, the surface closed: 0, or -1 */
static int check_mesh(const mesh_build *m, char *err, size_t errlen)
{
    if (m->nt < 4 || m->nv < 4) {
        snprintf(err, errlen, "a closed mesh needs at least 4 vertices and 4 "
                 "faces (got %d and %d)", m->nv, m->nt);
        return -1;
    }
    for (int t = 0; t < m->nt; t++) {
        int a = m->t[3 * t], c = m->t[3 * t + 1], d = m->t[3 * t + 2];
        if (a == c || c == d || a == d) {
            snprintf(err, errlen, "face %d repeats a vertex", t + 1);
            return -1;
        }
    }
    return check_closed(m, err, errlen);
}

/* hands m's arrays to b and bounds them; a flat mesh is refused (and b
   freed): 0 or -1 */
static int take_mesh(aero_body_shape *b, const mesh_build *m, char *err,
                     size_t errlen)
{
    b->kind = AERO_BODY_MESH;
    b->vertices = m->v;
    b->triangles = m->t;
    b->n_vertices = m->nv;
    b->n_triangles = m->nt;
    for (int k = 0; k < 3; k++) {
        b->lo[k] = HUGE_VAL;
        b->hi[k] = -HUGE_VAL;
    }
    for (int i = 0; i < m->nv; i++)
        for (int k = 0; k < 3; k++) {
            double x = m->v[3 * (size_t)i + k];
            if (x < b->lo[k]) b->lo[k] = x;
            if (x > b->hi[k]) b->hi[k] = x;
        }
    for (int k = 0; k < 3; k++)
        if (!(b->hi[k] - b->lo[k] > 1e-6)) {
            snprintf(err, errlen, "the mesh is flat (extent %g m along %c)",
                     b->hi[k] - b->lo[k], "xyz"[k]);
            aero_body_shape_free(b);
            return -1;
        }
    return 0;
}

int aero_body_mesh_parse(aero_body_shape *b, const char *text, char *err,
                         size_t errlen)
{
    mesh_build m;
    const char *p = text;
    int line = 0;
    memset(b, 0, sizeof *b);
    memset(&m, 0, sizeof m);
    while (p && *p) {
        const char *end = strchr(p, '\n');
        size_t n = end ? (size_t)(end - p) : strlen(p);
        char buf[1024];
        line++;
        if (n >= sizeof buf) {
            snprintf(err, errlen, "line %d is longer than %lu characters",
                     line, (unsigned long)(sizeof buf - 1));
            goto fail;
        }
        memcpy(buf, p, n);
        buf[n] = 0;
        p = end ? end + 1 : NULL;
        if (read_line(&m, buf, line, err, errlen))
            goto fail;
    }
    if (check_mesh(&m, err, errlen))
        goto fail;
    return take_mesh(b, &m, err, errlen);
fail:
    free(m.v);
    free(m.t);
    memset(b, 0, sizeof *b);
    return -1;
}

int aero_body_mesh_load(aero_body_shape *b, const char *path, char *err,
                        size_t errlen)
{
    FILE *f = fopen(path, "rb");
    char *text;
    long n;
    int r;
    memset(b, 0, sizeof *b);
    if (!f) {
        snprintf(err, errlen, "can't open mesh %s", path);
        return -1;
    }
    if (fseek(f, 0, SEEK_END) || (n = ftell(f)) < 0 || n > 256L << 20 ||
        fseek(f, 0, SEEK_SET)) {
        snprintf(err, errlen, "can't read mesh %s (or larger than 256 MB)",
                 path);
        fclose(f);
        return -1;
    }
    text = malloc((size_t)n + 1);
    if (!text || fread(text, 1, (size_t)n, f) != (size_t)n) {
        snprintf(err, errlen, "can't read mesh %s", path);
        free(text);
        fclose(f);
        return -1;
    }
    fclose(f);
    text[n] = 0;
    if (memchr(text, 0, (size_t)n)) {
        snprintf(err, errlen, "%s is not a text mesh (it holds a NUL byte)",
                 path);
        free(text);
        return -1;
    }
    r = aero_body_mesh_parse(b, text, err, errlen);
    free(text);
    return r;
}

/* --- inside tests ---------------------------------------------------------- */

/* the club's radius at height z (0 <= z <= l - r_tip) */
static double club_radius(const aero_body_shape *b, double z)
{
    double z0 = 0.25 * b->length, z1 = b->length - b->r_tip, s;
    if (z <= z0)
        return b->r_handle;
    s = (z - z0) / (z1 - z0);
    if (s > 1.0) s = 1.0;
    s = s * s * (3.0 - 2.0 * s);
    return b->r_handle + (b->r_tip - b->r_handle) * s;
}

/* does the ray p + t dir (t > 0) cross triangle a b c (Moller and Trumbore
   1997) */
static int ray_crosses(const double *p, const double *dir, const double *a,
                       const double *bb, const double *c)
{
    double e1[3], e2[3], h[3], s[3], q[3], det, u, v, t;
    for (int k = 0; k < 3; k++) {
        e1[k] = bb[k] - a[k];
        e2[k] = c[k] - a[k];
        s[k] = p[k] - a[k];
    }
    h[0] = dir[1] * e2[2] - dir[2] * e2[1];
    h[1] = dir[2] * e2[0] - dir[0] * e2[2];
    h[2] = dir[0] * e2[1] - dir[1] * e2[0];
    det = e1[0] * h[0] + e1[1] * h[1] + e1[2] * h[2];
    if (fabs(det) < 1e-30)
        return 0;
    u = (s[0] * h[0] + s[1] * h[1] + s[2] * h[2]) / det;
    if (u < 0.0 || u > 1.0)
        return 0;
    q[0] = s[1] * e1[2] - s[2] * e1[1];
    q[1] = s[2] * e1[0] - s[0] * e1[2];
    q[2] = s[0] * e1[1] - s[1] * e1[0];
    v = (dir[0] * q[0] + dir[1] * q[1] + dir[2] * q[2]) / det;
    if (v < 0.0 || u + v > 1.0)
        return 0;
    t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
    return t > 0.0;
}

int aero_body_inside(const aero_body_shape *b, const double p[3])
{
    for (int k = 0; k < 3; k++)
        if (!(p[k] >= b->lo[k] && p[k] <= b->hi[k]))
            return 0;
    switch (b->kind) {
    case AERO_BODY_SPHERE:
        return p[0] * p[0] + p[1] * p[1] + p[2] * p[2] < b->radius * b->radius;
    case AERO_BODY_CAPSULE: {
        double half = 0.5 * b->length - b->radius;
        double z = p[2] > half ? p[2] - half : p[2] < -half ? p[2] + half : 0.0;
        return p[0] * p[0] + p[1] * p[1] + z * z < b->radius * b->radius;
    }
    case AERO_BODY_CLUB: {
        double rr = p[0] * p[0] + p[1] * p[1];
        double zc = b->length - b->r_tip;
        if (p[2] > zc) {
            double z = p[2] - zc;
            return rr + z * z < b->r_tip * b->r_tip;
        }
        {
            double r = club_radius(b, p[2]);
            return rr < r * r;
        }
    }
    case AERO_BODY_MESH: {
        /* a direction no axis-aligned mesh edge or face lies in */
        static const double dir[3] = {0.8164965809277261, 0.4082482904638631,
                                      0.4096440127487212};
        int crossings = 0;
        for (int t = 0; t < b->n_triangles; t++) {
            const int *v = b->triangles + 3 * (size_t)t;
            crossings ^= ray_crosses(p, dir, b->vertices + 3 * (size_t)v[0],
                                     b->vertices + 3 * (size_t)v[1],
                                     b->vertices + 3 * (size_t)v[2]);
        }
        return crossings;
    }
    }
    return 0;
}

double aero_body_reference_size(const aero_body_shape *b)
{
    switch (b->kind) {
    case AERO_BODY_SPHERE:
    case AERO_BODY_CAPSULE:
        return 2.0 * b->radius;
    case AERO_BODY_CLUB:
        return 2.0 * b->r_tip;
    case AERO_BODY_MESH:
        return fmax(b->hi[0] - b->lo[0], b->hi[1] - b->lo[1]);
    }
    return 1.0;
}

int aero_body_region(const aero_body_shape *b, const double p[3], int n)
{
    double f;
    int r;
    if (n <= 1)
        return 0;
    if (b->kind == AERO_BODY_SPHERE) /* sectors around the flow axis x */
        f = (atan2(p[1], p[2]) + AERO_PI) / (2.0 * AERO_PI);
    else
        f = (p[2] - b->lo[2]) / (b->hi[2] - b->lo[2]);
    if (!(f > 0.0))
        return 0;
    r = f >= 1.0 ? n - 1 : (int)(f * n);
    return r < n ? r : n - 1;
}

void aero_body_describe(const aero_body_shape *b, char *buf, size_t len)
{
    switch (b->kind) {
    case AERO_BODY_SPHERE:
        snprintf(buf, len, "sphere radius=%g", b->radius);
        break;
    case AERO_BODY_CAPSULE:
        snprintf(buf, len, "capsule radius=%g length=%g", b->radius,
                 b->length);
        break;
    case AERO_BODY_CLUB:
        snprintf(buf, len, "club handle=%g tip=%g length=%g", b->r_handle,
                 b->r_tip, b->length);
        break;
    case AERO_BODY_MESH:
        snprintf(buf, len, "mesh vertices=%d triangles=%d", b->n_vertices,
                 b->n_triangles);
        break;
    }
}
