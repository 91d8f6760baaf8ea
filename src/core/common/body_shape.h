/* aero: closed 3D bodies for the 3D object textures (Dobashi et al. 2003, sec.
 * 5.2.1: a club, a sphere on a wire, the ends of a thrown stick).
 *
 * Body coordinates (metres):
 *   sphere   radius r, centred at the origin;
 *   capsule  a cylinder of radius r with hemispherical ends, its axis
 *            along z, overall length l, centred at the origin;
 *   club     a tapered body of revolution along +z from the handle end
 *            (z = 0, flat) to the tip (z = l, a hemispherical cap of the
 *            tip radius): radius r_handle up to 0.25 l, then a smooth
 *            (smoothstep) swell to r_tip at l - r_tip;
 *   mesh     a closed triangle mesh read from a plain-text file, the
 *            subset of the Wavefront OBJ format that describes geometry:
 *                # comment
 *                v x y z              one vertex per line (metres)
 *                f i j k [l ...]      a face: 1-based vertex indices
 *                                     (negative: counted from the end;
 *                                     "i/t/n" forms keep i); polygons are
 *                                     fanned into triangles
 *            lines starting with vn, vt, o, g, s, usemtl, mtllib are
 *            ignored, anything else is an error naming the line. The
 *            mesh must be closed (every edge shared by exactly two
 *            faces): inside is decided by the parity of ray crossings.
 *
 * The body's axis is z: regions are slices along z, except for a sphere,
 * where they are sectors around the flow axis (body x, the flow direction
 * of a sphere texture). No globals. */
#ifndef AERO_BODY_SHAPE_H
#define AERO_BODY_SHAPE_H

#include <stddef.h>

typedef enum {
    AERO_BODY_SPHERE = 0,
    AERO_BODY_CAPSULE,
    AERO_BODY_CLUB,
    AERO_BODY_MESH
} aero_body_kind;

#define AERO_BODY_MAX_MESH_VERTICES 200000
#define AERO_BODY_MAX_MESH_FACES 400000

typedef struct {
    aero_body_kind kind;
    double radius;          /* sphere, capsule */
    double length;          /* capsule, club: overall length along z */
    double r_handle, r_tip; /* club */
    int n_vertices, n_triangles;   /* mesh */
    double *vertices;       /* 3 per vertex */
    int *triangles;         /* 3 (0-based) per triangle */
    double lo[3], hi[3];    /* bounding box */
} aero_body_shape;

/* analytic shapes: 0, or -1 with a message (sizes must be > 0 and
   <= 100 m; a capsule's length >= 2 r, a club's >= 4 r_tip, r_handle <=
   r_tip) */
int aero_body_sphere(aero_body_shape *b, double radius, char *err,
                     size_t errlen);
int aero_body_capsule(aero_body_shape *b, double radius, double length,
                      char *err, size_t errlen);
int aero_body_club(aero_body_shape *b, double r_handle, double r_tip,
                   double length, char *err, size_t errlen);
/* a mesh from text (the format above): 0, or -1 with a message naming
   the line or the open edge */
int aero_body_mesh_parse(aero_body_shape *b, const char *text, char *err,
                         size_t errlen);
/* the same from a file */
int aero_body_mesh_load(aero_body_shape *b, const char *path, char *err,
                        size_t errlen);
void aero_body_shape_free(aero_body_shape *b);

/* 1 if the body-frame point p lies inside */
int aero_body_inside(const aero_body_shape *b, const double p[3]);

/* the reference size d of the body (Strouhal and Reynolds numbers):
   sphere and capsule 2 r, club 2 r_tip, mesh the largest extent across z */
double aero_body_reference_size(const aero_body_shape *b);
/* the region (0..n-1) of a body-frame point, n regions */
int aero_body_region(const aero_body_shape *b, const double p[3], int n);
/* a short description, e.g. "sphere r=0.05" */
void aero_body_describe(const aero_body_shape *b, char *buf, size_t len);

#endif
