/* fuzz: closed triangle meshes for aerotex object (aero_body_mesh_parse:
 * the OBJ subset of textures/README.md), then the queries the 3D solver
 * makes of the body: inside tests over its box, regions, reference size.
 * Seeds: the .obj files in fuzz/seeds/mesh/. */
#include "fuzz.h"

#include "body_shape.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1), err[512];
    aero_body_shape b;
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = 0;
    err[0] = 0;
    if (aero_body_mesh_parse(&b, text, err, sizeof(err))) {
        FUZZ_REQUIRE(err[0] != 0, "a refused mesh without a message");
        FUZZ_REQUIRE(!b.vertices && !b.triangles, "a refused mesh keeps "
                     "memory");
        free(text);
        return 0;
    }
    free(text);
    FUZZ_REQUIRE(b.n_triangles >= 4 && b.n_vertices >= 4,
                 "a mesh of %d triangles accepted", b.n_triangles);
    {
        double d = aero_body_reference_size(&b);
        FUZZ_REQUIRE(isfinite(d) && d > 0.0, "reference size %g", d);
    }
    for (int k = 0; k < 64 && b.n_triangles < 2000; k++) {
        double p[3];
        for (int a = 0; a < 3; a++)
            p[a] = b.lo[a] + (b.hi[a] - b.lo[a]) * ((k >> a) % 4) / 3.0;
        (void)aero_body_inside(&b, p);
        int r = aero_body_region(&b, p, 7);
        FUZZ_REQUIRE(r >= 0 && r < 7, "region %d of 7", r);
    }
    aero_body_shape_free(&b);
    return 0;
}
