/* Unit tests of src/core/common/body_shape and src/core/solve/body_flow:
 * closed 3D bodies (analytic shapes and meshes, with the errors a bad mesh
 * must give), and the 3D flow past a sphere: its volume and frontal area,
 * a divergence-free flow, a wake that sheds (its published drag and
 * Strouhal number are not reached: see sphere_flow). */
/* aero-test: slow */
#include <stdlib.h>
#include <string.h>

#include "aero_air.h"
#include "body_flow.h"
#include "unit.h"

/* a unit cube [0,1]^3 as text; drop_face removes one triangle (open) */
static char *cube(double size, int drop_face)
{
    static const int f[12][3] = {{1, 2, 3}, {1, 3, 4}, {5, 7, 6}, {5, 8, 7},
                                 {1, 5, 6}, {1, 6, 2}, {2, 6, 7}, {2, 7, 3},
                                 {3, 7, 8}, {3, 8, 4}, {4, 8, 5}, {4, 5, 1}};
    char *s = malloc(4096);
    size_t used = 0;
    used += (size_t)snprintf(s + used, 4096 - used, "# a cube\no cube\n");
    for (int v = 0; v < 8; v++)
        used += (size_t)snprintf(s + used, 4096 - used, "v %g %g %g\n",
                                 size * ((v == 1 || v == 2 || v == 5 ||
                                          v == 6)),
                                 size * ((v == 2 || v == 3 || v == 6 ||
                                          v == 7)),
                                 size * (v >= 4));
    for (int k = 0; k < 12; k++)
        if (k != drop_face)
            used += (size_t)snprintf(s + used, 4096 - used, "f %d %d %d\n",
                                     f[k][0], f[k][1], f[k][2]);
    return s;
}

/* volume of a body by sampling its box on an n^3 lattice */
static double sampled_volume(const aero_body_shape *b, int n)
{
    double cell[3], v = 0.0;
    for (int k = 0; k < 3; k++)
        cell[k] = (b->hi[k] - b->lo[k]) / n;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            for (int k = 0; k < n; k++) {
                double p[3] = {b->lo[0] + (i + 0.5) * cell[0],
                               b->lo[1] + (j + 0.5) * cell[1],
                               b->lo[2] + (k + 0.5) * cell[2]};
                v += aero_body_inside(b, p);
            }
    return v * cell[0] * cell[1] * cell[2];
}

UNIT_TEST(shapes)
{
    aero_body_shape b;
    char err[256], *text;

    /* analytic shapes: volumes */
    aero_body_sphere(&b, 0.05, err, sizeof err);
    UNIT_NEAR_REL(sampled_volume(&b, 80), 4.0 / 3.0 * AERO_PI * 1.25e-4, 0.01,
                  "sphere r 5 cm: volume 4/3 pi r^3");
    aero_body_capsule(&b, 0.02, 0.3, err, sizeof err);
    UNIT_NEAR_REL(sampled_volume(&b, 100),
                  AERO_PI * 4e-4 * 0.26 + 4.0 / 3.0 * AERO_PI * 8e-6, 0.01,
                  "capsule: cylinder plus two half spheres");
    aero_body_club(&b, 0.0125, 0.03, 0.8, err, sizeof err);
    {
        double v = sampled_volume(&b, 120);
        double thin = AERO_PI * 0.0125 * 0.0125 * 0.77;
        double fat = AERO_PI * 0.03 * 0.03 * 0.77;
        UNIT_CHECK(v > thin && v < fat, "club volume %g m^3 lies between "
                   "its handle's cylinder (%g) and its tip's (%g)", v, thin,
                   fat);
    }
    UNIT_CHECK(aero_body_sphere(&b, 0.0, err, sizeof err) == -1 &&
                   aero_body_sphere(&b, NAN, err, sizeof err) == -1 &&
                   aero_body_capsule(&b, 0.1, 0.1, err, sizeof err) == -1 &&
                   aero_body_club(&b, 0.05, 0.03, 0.8, err, sizeof err) == -1,
               "zero/NaN radius, a capsule shorter than its width, a club "
               "thicker at the handle are refused (%s)", err);

    /* a mesh: the cube, inside by ray parity */
    text = cube(0.1, -1);
    err[0] = 0;
    UNIT_CHECK(aero_body_mesh_parse(&b, text, err, sizeof err) == 0,
               "a closed cube mesh parses (%s)", err);
    {
        double in[3] = {0.05, 0.05, 0.05}, out[3] = {0.15, 0.05, 0.05};
        double edge[3] = {0.05, 0.05, 0.0999};
        UNIT_CHECK(aero_body_inside(&b, in) && !aero_body_inside(&b, out) &&
                       aero_body_inside(&b, edge),
                   "inside and outside of the cube");
        UNIT_NEAR_REL(sampled_volume(&b, 40), 1e-3, 0.01, "cube volume");
    }
    aero_body_shape_free(&b);
    free(text);

    /* bad meshes: clear errors */
    text = cube(0.1, 3);
    UNIT_CHECK(aero_body_mesh_parse(&b, text, err, sizeof err) == -1 &&
                   strstr(err, "not closed"),
               "an open mesh: %s", err);
    free(text);
    UNIT_CHECK(aero_body_mesh_parse(&b, "v 0 0 0\nv 1 0 0\nf 1 2 9\n", err,
                                    sizeof err) == -1 &&
                   strstr(err, "line 3"),
               "a face naming a missing vertex: %s", err);
    UNIT_CHECK(aero_body_mesh_parse(&b, "v 0 0 0\nhello\n", err,
                                    sizeof err) == -1 &&
                   strstr(err, "line 2"),
               "an unknown line: %s", err);
    UNIT_CHECK(aero_body_mesh_parse(&b, "v 0 0 nan\n", err, sizeof err) ==
                       -1 && strstr(err, "line 1"),
               "a NaN vertex: %s", err);
    UNIT_CHECK(aero_body_mesh_parse(&b, "", err, sizeof err) == -1,
               "an empty mesh: %s", err);
    UNIT_CHECK(aero_body_mesh_load(&b, "/nonexistent.obj", err, sizeof err) ==
                       -1 && strstr(err, "can't open"),
               "a missing file: %s", err);
    UNIT_CHECK(aero_body_mesh_parse(&b, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                    "f 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n",
                                    err, sizeof err) == -1 &&
                   strstr(err, "flat"),
               "a flat (zero-volume) mesh: %s", err);
}

/* the sphere of Dobashi et al. 2003 (radius 5 cm) at v0 = 10 m/s on a coarse grid */
UNIT_TEST(sphere_flow)
{
    aero_body_shape b;
    aero_body_flow_params p;
    aero_body_flow_stats st;
    char err[256];
    const double rate = 4000.0;
    const int nout = 1600; /* 0.4 s: 5.2 periods of the measured 13 Hz */
    float *out = calloc(3 * (size_t)nout, sizeof(float));
    double d = 0.1, rms_lat = 0.0, rms_drag = 0.0;
    int ok;
    aero_body_sphere(&b, 0.05, err, sizeof err);
    aero_body_flow_defaults(&p, &b);
    p.cell = d / 8.0;
    /* eps h / d = 0.15 at 8 cells per d, the confinement the first sphere
       texture had (body_flow.h's default 1.5 sheds more weakly here) */
    p.confinement = 1.2;
    p.settle = 20.0 * d / p.speed;
    ok = aero_body_flow_simulate(&p, rate, out, 3, nout, &st, NULL, 0, NULL,
                                 err, sizeof err) == 0;
    UNIT_CHECK(ok, "sphere flow ran: grid %d x %d x %d, %ld steps (%s)",
               st.nx, st.ny, st.nz, st.steps, ok ? "" : err);
    if (!ok) {
        free(out);
        return;
    }
    UNIT_NEAR_REL(st.solid_volume, 4.0 / 3.0 * AERO_PI * 1.25e-4, 0.02,
                  "voxelised sphere volume (3^3 samples per cell)");
    UNIT_NEAR_REL(st.frontal_area, AERO_PI * 0.0025, 0.03,
                  "frontal area pi r^2");
    UNIT_CHECK(st.max_div < 1e-3 * p.speed, "divergence-free after the "
               "projection: max |div u| h = %g m/s", st.max_div);
    /* Not asserted here: the published sphere (drag coefficient 0.4-0.55
       and Strouhal number 0.17-0.22 in the subcritical range of the
       texture's Re 6.8e4; Achenbach 1972, J. Fluid Mech. 54, and 1974, J.
       Fluid Mech. 62). On this coarse grid the numerical viscosity makes
       the flow a sphere's near its shedding onset (Cd 0.76, St 0.13 here;
       Johnson & Patel 1999, J. Fluid Mech. 378: Cd 0.66, St 0.137 at Re
       300), and no grid a texture can afford reaches the subcritical
       values (textures/README.md), so the windows that were widened
       around this run's figures are gone. What is checked: it sheds. */
    printf("  Cd %.3f, St %.3f (f %.1f Hz), Cl rms %.3f\n", st.cd, st.st,
           st.f_peak, st.cl_rms);
    UNIT_CHECK(st.cl_rms > 0.01, "the wake sheds: rms lateral force "
               "coefficient %.3f", st.cl_rms);
    /* g = dF/dt: at 90 deg the flow arrives along sample x, so x is the
       drag and y, z the lateral force */
    for (int m = 0; m < nout; m++) {
        rms_drag += out[3 * m] * (double)out[3 * m];
        rms_lat += out[3 * m + 1] * (double)out[3 * m + 1] +
                   out[3 * m + 2] * (double)out[3 * m + 2];
    }
    UNIT_CHECK(rms_lat > 0.0 && rms_drag > 0.0,
               "g = dF/dt is non-zero (rms lateral %g, drag %g N/s)",
               sqrt(rms_lat / nout), sqrt(rms_drag / nout));
    free(out);
}

UNIT_MAIN(UNIT_CASE(shapes), UNIT_CASE(sphere_flow))
