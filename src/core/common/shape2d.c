/* aero: 2D cross-sections as signed distance functions (see shape2d.h). */
#include "shape2d.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void shape_clear(aero_shape2d *s)
{
    memset(s, 0, sizeof *s);
}

void aero_shape2d_circle(aero_shape2d *s, double d)
{
    shape_clear(s);
    s->kind = AERO_SHAPE_CIRCLE;
    s->size = d;
    s->a = s->b = 0.5 * d;
}

void aero_shape2d_square(aero_shape2d *s, double d)
{
    shape_clear(s);
    s->kind = AERO_SHAPE_SQUARE;
    s->size = d;
    s->a = s->b = 0.5 * d;
}

void aero_shape2d_ellipse(aero_shape2d *s, double d, double aspect)
{
    shape_clear(s);
    s->kind = AERO_SHAPE_ELLIPSE;
    s->size = d;
    s->a = 0.5 * d;
    s->b = 0.5 * d * aspect;
}

void aero_shape2d_cavity(aero_shape2d *s, double l, double h)
{
    shape_clear(s);
    s->kind = AERO_SHAPE_CAVITY;
    s->size = l;
    s->a = l;
    s->b = h;
}

/* shoelace area and centroid of a closed polygon */
static double polygon_centroid(const double *x, const double *y, int n,
                               double *cx, double *cy)
{
    double a = 0.0, sx = 0.0, sy = 0.0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        double c = x[i] * y[j] - x[j] * y[i];
        a += c;
        sx += (x[i] + x[j]) * c;
        sy += (y[i] + y[j]) * c;
    }
    a *= 0.5;
    if (fabs(a) > 0.0) {
        *cx = sx / (6.0 * a);
        *cy = sy / (6.0 * a);
    }
    return a;
}

/* do segments p1-p2 and p3-p4 properly cross? */
static int segments_cross(double x1, double y1, double x2, double y2,
                          double x3, double y3, double x4, double y4)
{
    double d1 = (x4 - x3) * (y1 - y3) - (y4 - y3) * (x1 - x3);
    double d2 = (x4 - x3) * (y2 - y3) - (y4 - y3) * (x2 - x3);
    double d3 = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1);
    double d4 = (x2 - x1) * (y4 - y1) - (y2 - y1) * (x4 - x1);
    return d1 * d2 < 0.0 && d3 * d4 < 0.0;
}

int aero_shape2d_polygon(aero_shape2d *s, const double *x, const double *y,
                         int n, double d, char *err, size_t errlen)
{
    double cx = 0.0, cy = 0.0, xmin, xmax, area, scale;
    shape_clear(s);
    if (n < 3) {
        snprintf(err, errlen, "polygon needs at least 3 vertices, got %d", n);
        return -1;
    }
    for (int i = 0; i < n; i++)
        /* beyond 1e9 (in the file's unit) the centroid's sums overflow */
        if (!(fabs(x[i]) <= 1e9) || !(fabs(y[i]) <= 1e9)) {
            snprintf(err, errlen, "polygon vertex %d is not a finite number "
                     "within 1e9", i + 1);
            return -1;
        }
    for (int i = 0; i < n; i++)
        for (int j = i + 2; j < n; j++) {
            if (i == 0 && j == n - 1)
                continue;
            if (segments_cross(x[i], y[i], x[(i + 1) % n], y[(i + 1) % n],
                               x[j], y[j], x[(j + 1) % n], y[(j + 1) % n])) {
                snprintf(err, errlen,
                         "polygon edges %d and %d cross each other", i + 1,
                         j + 1);
                return -1;
            }
        }
    area = polygon_centroid(x, y, n, &cx, &cy);
    xmin = xmax = x[0];
    for (int i = 1; i < n; i++) {
        if (x[i] < xmin) xmin = x[i];
        if (x[i] > xmax) xmax = x[i];
    }
    if (!(xmax - xmin > 0.0) || !(fabs(area) > 1e-6 * (xmax - xmin) * (xmax - xmin))) {
        snprintf(err, errlen, "polygon has no area");
        return -1;
    }
    scale = d > 0.0 ? d / (xmax - xmin) : 1.0;
    s->px = malloc(sizeof(double) * n);
    s->py = malloc(sizeof(double) * n);
    if (!s->px || !s->py) {
        aero_shape2d_free(s);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    s->kind = AERO_SHAPE_POLYGON;
    s->npts = n;
    for (int i = 0; i < n; i++) {
        s->px[i] = (x[i] - cx) * scale;
        s->py[i] = (y[i] - cy) * scale;
    }
    s->size = (xmax - xmin) * scale;
    /* extreme coordinates (1e163 beside 30) made the
     * radius Inf and the solver's grid nonsense: the outline must fit in
     * a circle of 1000 widths */
    double r = aero_shape2d_radius(s);
    if (!(r > 0.0 && r <= 1e3 * s->size) || !isfinite(s->size)) {
        aero_shape2d_free(s);
        snprintf(err, errlen, "polygon is degenerate (radius %g for a width "
                 "of %g)", r, (xmax - xmin) * scale);
        return -1;
    }
    return 0;
}

int aero_shape2d_load_poly(aero_shape2d *s, const char *path, double d,
                           char *err, size_t errlen)
{
    char line[512];
    int n = 0, cap = 64, lineno = 0, r;
    double *x, *y;
    FILE *f = fopen(path, "r");
    shape_clear(s);
    if (!f) {
        snprintf(err, errlen, "can't open polygon file %s: %s", path,
                 strerror(errno));
        return -1;
    }
    x = malloc(sizeof(double) * cap);
    y = malloc(sizeof(double) * cap);
    while (x && y && fgets(line, sizeof line, f)) {
        char *p = line, *end;
        double a, b;
        lineno++;
        while (*p == ' ' || *p == '\t') p++;
        if (*p == '#' || *p == '\n' || *p == '\r' || *p == 0)
            continue;
        a = strtod(p, &end);
        if (end == p) goto bad;
        p = end;
        while (*p == ' ' || *p == '\t' || *p == ',') p++;
        b = strtod(p, &end);
        if (end == p) goto bad;
        if (n == cap) {
            double *nx2, *ny2;
            cap *= 2;
            nx2 = realloc(x, sizeof(double) * cap);
            if (nx2) x = nx2;
            ny2 = realloc(y, sizeof(double) * cap);
            if (ny2) y = ny2;
            if (!nx2 || !ny2) break;
        }
        x[n] = a;
        y[n] = b;
        n++;
        continue;
    bad:
        snprintf(err, errlen, "%s:%d: expected two numbers \"x y\"", path,
                 lineno);
        free(x);
        free(y);
        fclose(f);
        return -1;
    }
    fclose(f);
    if (!x || !y) {
        free(x);
        free(y);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    /* a closing vertex equal to the first is allowed */
    if (n > 3 && x[n - 1] == x[0] && y[n - 1] == y[0])
        n--;
    r = aero_shape2d_polygon(s, x, y, n, d, err, errlen);
    if (r && strncmp(err, "polygon", 7) == 0) {
        char tmp[256];
        snprintf(tmp, sizeof tmp, "%s", err);
        snprintf(err, errlen, "%s: %s", path, tmp);
    }
    free(x);
    free(y);
    return r;
}

void aero_shape2d_free(aero_shape2d *s)
{
    free(s->px);
    free(s->py);
    s->px = s->py = NULL;
    s->npts = 0;
}

/* exact signed distance of an axis-aligned box of half sides (a, b) */
static double box_distance(double x, double y, double a, double b)
{
    double qx = fabs(x) - a, qy = fabs(y) - b;
    double ox = qx > 0.0 ? qx : 0.0, oy = qy > 0.0 ? qy : 0.0;
    double in = qx > qy ? qx : qy;
    return sqrt(ox * ox + oy * oy) + (in < 0.0 ? in : 0.0);
}

static double polygon_distance(const aero_shape2d *s, double x, double y)
{
    double best = 1e300;
    int inside = 0;
    for (int i = 0, j = s->npts - 1; i < s->npts; j = i++) {
        double ax = s->px[j], ay = s->py[j], bx = s->px[i], by = s->py[i];
        double ex = bx - ax, ey = by - ay, wx = x - ax, wy = y - ay;
        double t = (wx * ex + wy * ey) / (ex * ex + ey * ey);
        double dx, dy, dd;
        if (t < 0.0) t = 0.0;
        if (t > 1.0) t = 1.0;
        dx = wx - t * ex;
        dy = wy - t * ey;
        dd = dx * dx + dy * dy;
        if (dd < best) best = dd;
        /* crossing number, ray towards +x */
        if ((ay > y) != (by > y) && x < ax + (y - ay) * ex / ey)
            inside = !inside;
    }
    return inside ? -sqrt(best) : sqrt(best);
}

double aero_shape2d_distance(const aero_shape2d *s, double x, double y)
{
    switch (s->kind) {
    case AERO_SHAPE_CIRCLE:
        return sqrt(x * x + y * y) - s->a;
    case AERO_SHAPE_SQUARE:
        return box_distance(x, y, s->a, s->b);
    case AERO_SHAPE_ELLIPSE: {
        /* first-order distance f / |grad f| of f = sqrt((x/a)^2+(y/b)^2) - 1 */
        double u = x / s->a, v = y / s->b, r = sqrt(u * u + v * v);
        double gx, gy;
        if (r < 1e-12)
            return -(s->a < s->b ? s->a : s->b);
        gx = u / (r * s->a);
        gy = v / (r * s->b);
        return (r - 1.0) / sqrt(gx * gx + gy * gy);
    }
    case AERO_SHAPE_POLYGON:
        return polygon_distance(s, x, y);
    case AERO_SHAPE_CAVITY: {
        /* wall y < 0 without the box 0 < x < l, -h < y < 0. The box is
           extended above the wall (to y = h) so that its top side, the
           open mouth at y = 0, is not a boundary: with the box ending at
           y = 0 the distance there was 0, the nodes along the mouth were
           half solid and the forcing damped the shear layer's flapping */
        double wall = y;
        double hole = box_distance(x - 0.5 * s->a, y, 0.5 * s->a, s->b);
        return wall > -hole ? wall : -hole;
    }
    }
    return 1e300;
}

double aero_shape2d_radius(const aero_shape2d *s)
{
    switch (s->kind) {
    case AERO_SHAPE_CIRCLE:
        return s->a;
    case AERO_SHAPE_SQUARE:
        return sqrt(s->a * s->a + s->b * s->b);
    case AERO_SHAPE_ELLIPSE:
        return s->a > s->b ? s->a : s->b;
    case AERO_SHAPE_POLYGON: {
        double r = 0.0;
        for (int i = 0; i < s->npts; i++) {
            double q = sqrt(s->px[i] * s->px[i] + s->py[i] * s->py[i]);
            if (q > r) r = q;
        }
        return r;
    }
    case AERO_SHAPE_CAVITY:
        return sqrt(s->a * s->a + s->b * s->b);
    }
    return 0.0;
}

double aero_shape2d_frontal(const aero_shape2d *s, double alpha)
{
    double nx = -sin(alpha), ny = cos(alpha);
    switch (s->kind) {
    case AERO_SHAPE_CIRCLE:
        return s->size;
    case AERO_SHAPE_SQUARE:
        return 2.0 * (s->a * fabs(nx) + s->b * fabs(ny));
    case AERO_SHAPE_ELLIPSE:
        return 2.0 * sqrt(s->a * s->a * nx * nx + s->b * s->b * ny * ny);
    case AERO_SHAPE_POLYGON: {
        double lo = 1e300, hi = -1e300;
        for (int i = 0; i < s->npts; i++) {
            double q = s->px[i] * nx + s->py[i] * ny;
            if (q < lo) lo = q;
            if (q > hi) hi = q;
        }
        return hi - lo;
    }
    case AERO_SHAPE_CAVITY:
        return s->b;
    }
    return 0.0;
}

const char *aero_shape2d_name(const aero_shape2d *s)
{
    static const char *names[] = {"circle", "square", "ellipse", "polygon",
                                  "cavity"};
    return names[s->kind];
}
