/* fuzz: polygon files for aerotex (aero_shape2d_load_poly: lines "x y",
 * '#' comments), then the queries the flow solver makes of the shape.
 * Seeds: the .poly files in textures/ and fuzz/seeds/polygon/. */
/* aero-fuzz: seeds textures/?*.poly */
#include "fuzz.h"

#include "shape2d.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[64], err[512];
    int fd = fuzz_file(data, size, path, sizeof(path));
    if (fd < 0)
        return 0;
    for (int scaled = 0; scaled < 2; scaled++) {
        aero_shape2d s;
        err[0] = 0;
        if (aero_shape2d_load_poly(&s, path, scaled ? 0.02 : 0.0, err,
                                   sizeof(err))) {
            FUZZ_REQUIRE(err[0] != 0, "a refused polygon without a message");
            FUZZ_REQUIRE(!s.px && !s.py, "a refused polygon keeps memory");
            continue;
        }
        FUZZ_REQUIRE(s.npts >= 3, "polygon of %d vertices accepted", s.npts);
        double r = aero_shape2d_radius(&s);
        FUZZ_REQUIRE(isfinite(r) && r > 0.0, "polygon radius %g", r);
        FUZZ_REQUIRE(isfinite(s.size) && s.size > 0.0, "polygon size %g",
                     s.size);
        for (int k = 0; k < 8; k++) {
            double a = k * 0.785398163, f = aero_shape2d_frontal(&s, a);
            double d = aero_shape2d_distance(&s, r * cos(a), r * sin(a));
            FUZZ_REQUIRE(isfinite(f) && f >= 0.0, "frontal width %g", f);
            FUZZ_REQUIRE(isfinite(d), "distance %g", d);
        }
        aero_shape2d_free(&s);
    }
    fuzz_file_close(fd);
    return 0;
}
