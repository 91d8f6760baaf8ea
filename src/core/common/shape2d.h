/* aero: 2D cross-sections for the flow solver (circle, square, ellipse,
 * polygon, rectangular cavity in a wall) as signed distance functions.
 * A shape lives in its own body frame: centred on the origin, x along its
 * chord. Negative distance = inside the solid. */
#ifndef AERO_SHAPE2D_H
#define AERO_SHAPE2D_H

#include <stddef.h>

typedef enum {
    AERO_SHAPE_CIRCLE,
    AERO_SHAPE_SQUARE,
    AERO_SHAPE_ELLIPSE,
    AERO_SHAPE_POLYGON,
    AERO_SHAPE_CAVITY
} aero_shape_kind;

typedef struct {
    aero_shape_kind kind;
    double size;     /* reference length d, m: diameter, side, major axis,
                        polygon extent across x or cavity length */
    double a, b;     /* ellipse semi-axes / cavity length, depth (m) */
    int npts;        /* polygon vertices (body frame, m) */
    double *px, *py;
} aero_shape2d;

/* circle of diameter d, square of side d, ellipse of axes d x (d * aspect) */
void aero_shape2d_circle(aero_shape2d *s, double d);
void aero_shape2d_square(aero_shape2d *s, double d);
void aero_shape2d_ellipse(aero_shape2d *s, double d, double aspect);
/* cavity of length l and depth h in a wall y < 0, mouth from x = 0 to l */
void aero_shape2d_cavity(aero_shape2d *s, double l, double h);
/* polygon from n vertices (copied), recentred on its centroid and scaled
 * so that its largest width equals d (d <= 0 keeps the given size);
 * returns 0, or -1 with a message for a degenerate polygon */
int aero_shape2d_polygon(aero_shape2d *s, const double *x, const double *y,
                         int n, double d, char *err, size_t errlen);
/* polygon file: lines "x y" (any unit), '#' comments; see textures/README.md */
int aero_shape2d_load_poly(aero_shape2d *s, const char *path, double d,
                           char *err, size_t errlen);
void aero_shape2d_free(aero_shape2d *s);

/* signed distance of body-frame point (x, y), m */
double aero_shape2d_distance(const aero_shape2d *s, double x, double y);
/* radius of the smallest origin-centred circle holding the shape, m */
double aero_shape2d_radius(const aero_shape2d *s);
/* frontal width across a flow at angle alpha (rad, body frame), m */
double aero_shape2d_frontal(const aero_shape2d *s, double alpha);
const char *aero_shape2d_name(const aero_shape2d *s);

#endif
