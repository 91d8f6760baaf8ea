/* aerotex: vorticity snapshots as PNG images (libpng). A build without
 * libpng (-DAEROTEX_NO_PNG: Windows, where Debian has no libpng for
 * mingw) refuses --png when it parses the options (aerotex_common.c). */
#include "aerotex.h"

#ifndef AEROTEX_NO_PNG

#include <png.h>
#include <stdio.h>
#include <stdlib.h>

/* blue (clockwise) - white - red (anticlockwise), body in grey */
static void colour(float w, float solid, float wmax, unsigned char *rgb)
{
    float q = w / wmax, r, g, b;
    if (q > 1.0f) q = 1.0f;
    if (q < -1.0f) q = -1.0f;
    if (!(q == q)) q = 0.0f;
    r = q < 0.0f ? 1.0f + q : 1.0f;
    b = q > 0.0f ? 1.0f - q : 1.0f;
    g = q < 0.0f ? 1.0f + q : 1.0f - q;
    r = r * (1.0f - solid) + 0.35f * solid;
    g = g * (1.0f - solid) + 0.35f * solid;
    b = b * (1.0f - solid) + 0.35f * solid;
    rgb[0] = (unsigned char)(255.0f * r + 0.5f);
    rgb[1] = (unsigned char)(255.0f * g + 0.5f);
    rgb[2] = (unsigned char)(255.0f * b + 0.5f);
}

int aerotex_png_vorticity(const char *path, const float *w,
                          const float *solid, int nx, int ny, float wmax)
{
    FILE *f = fopen(path, "wb");
    png_structp png;
    png_infop info;
    unsigned char *row;
    if (!f)
        return -1;
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png ? png_create_info_struct(png) : NULL;
    row = malloc((size_t)nx * 3);
    if (!png || !info || !row || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, info ? &info : NULL);
        free(row);
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)nx, (png_uint_32)ny, 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int j = ny - 1; j >= 0; j--) {
        for (int i = 0; i < nx; i++)
            colour(w[(size_t)j * nx + i], solid[(size_t)j * nx + i], wmax,
                   row + 3 * i);
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(row);
    return fclose(f) ? -1 : 0;
}
#else
/* never reached: --png is refused before a solver runs */
int aerotex_png_vorticity(const char *path, const float *w,
                          const float *solid, int nx, int ny, float wmax)
{
    (void)path, (void)w, (void)solid, (void)nx, (void)ny, (void)wmax;
    return -1;
}
#endif
