/* aero: time-varying 3D volume data for field auralization (Shin and Bajaj).
 *
 * On disk a volume is a directory:
 *
 *   DIR/volume.txt      plain-text header, one `key values` per line,
 *                       '#' starts a comment:
 *       aero-volume 1                 (first line: format and version)
 *       dims 64 64 64                 vertices along x, y, z
 *       spacing 0.02 0.02 0.02        vertex spacing, metres
 *       origin -0.63 -0.63 -0.63      position of vertex (0,0,0), metres
 *                                     (optional, default 0 0 0)
 *       rate 1000                     volume frames per second of the data
 *       frames 48                     number of frames
 *       fields density                `density`, or `density vx vy vz`
 *                                     (velocity in m/s)
 *       files frame%05d.f32           printf pattern of the frame files
 *                                     (optional, this is the default)
 *   DIR/frame00000.f32 ...  one file per frame: the fields one after the
 *                       other, each nx*ny*nz raw little-endian float32,
 *                       x fastest, then y, then z. No header, so a frame
 *                       file must be exactly 4*fields*nx*ny*nz bytes.
 *
 * The density is the field value before the acoustic mapping (field_sound.h
 * maps it to air density). Also here: the synthetic demo sequence (an
 * expanding burst with turbulence) that `aerotex field-demo` writes. */
#ifndef AERO_FIELD_VOLUME_H
#define AERO_FIELD_VOLUME_H

#include <stddef.h>
#include <stdint.h>

#define AERO_VOLUME_HEADER "volume.txt"
#define AERO_VOLUME_MAX_DIM 1024
#define AERO_VOLUME_PATH 1024

typedef struct aero_volume_info {
    int nx, ny, nz;       /* vertices per axis */
    int frames;
    double spacing[3];    /* m */
    double origin[3];     /* m */
    double rate;          /* frames per second */
    int fields;           /* 1: density, 4: density vx vy vz */
    char dir[AERO_VOLUME_PATH];
    char pattern[64];     /* frame file name pattern (one %d) */
} aero_volume_info;

/* vertices in one frame */
static inline size_t aero_volume_count(const aero_volume_info *v)
{
    return (size_t)v->nx * v->ny * v->nz;
}

/* Reads and checks DIR/volume.txt. 0, or -1 with a message in err. */
int aero_volume_read_header(const char *dir, aero_volume_info *v, char *err,
                            size_t errlen);
/* Reads frame k into data (fields * count floats, host order). Checks the
 * file's size first: a truncated or oversized frame is an error. */
int aero_volume_read_frame(const aero_volume_info *v, int k, float *data,
                           char *err, size_t errlen);
/* Checks that frame k's file is there with the size the header implies
 * (before allocating for a volume: a header is a few bytes, what it
 * claims may be tens of GB). 0, or -1 with a message. */
int aero_volume_check_frame(const aero_volume_info *v, int k, char *err,
                            size_t errlen);
/* Writes v's header into v->dir (which must exist), and one frame. */
int aero_volume_write_header(const aero_volume_info *v, char *err,
                             size_t errlen);
int aero_volume_write_frame(const aero_volume_info *v, int k,
                            const float *data, char *err, size_t errlen);

/* The synthetic sequence: a spherical burst in the middle of a cube of
 * `size`^3 vertices, a shell of compressed gas expanding at `shell_speed`
 * and thinning out, a hot core that decays, and turbulence (a sum of
 * random Fourier modes drifting in time, seeded) riding on the shell. */
/* its size a host offers, vertices along an edge */
#define AERO_FIELD_DEMO_SIZE_MIN 4
#define AERO_FIELD_DEMO_SIZE_MAX 128
#define AERO_FIELD_DEMO_SIZE_DEFAULT 32

typedef struct aero_field_demo {
    int size, frames;
    double spacing, rate;
    double shell_speed;   /* m/s */
    int velocity;         /* also write vx vy vz */
    uint32_t seed;
} aero_field_demo;

/* Defaults: 64^3, 48 frames, 2 cm spacing, 1000 frames/s, shell at
 * 15 m/s, density only, seed 1. */
void aero_field_demo_default(aero_field_demo *d);
/* The header of the demo (dir left empty). */
void aero_field_demo_info(const aero_field_demo *d, aero_volume_info *v);
/* Frame k of the demo into data (v.fields * count floats). */
void aero_field_demo_frame(const aero_field_demo *d, int k, float *data);

#endif
