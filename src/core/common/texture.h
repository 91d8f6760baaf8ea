/* aero: sound textures (Dobashi et al. 2003) as float WAV files via
 * libsndfile.
 *
 * Frames hold the sound source function g = dF/dt (N/(m s) per unit span
 * for 2D simulations) at the base speed v0, channels x, y, z per sampled
 * direction (channel 3 k + c is component c of direction k), in the flow
 * frame: x along the flow (drag), y across it (lift), z along the body axis.
 * A vortex texture (kind=vortex, Dobashi et al. 2004) instead holds one
 * channel per average flow speed: Q(u_k, t), the sound pressure at 1 m (Pa m),
 * with the speeds in the metadata `speeds=u1,u2,...` (increasing).
 * The comment string holds the metadata as "key=value" lines (see
 * textures/README.md). The file is a seamless loop: its ends are already
 * cross-faded, a player wraps the texture coordinate modulo `frames`. */
#ifndef AERO_TEXTURE_H
#define AERO_TEXTURE_H

#include <stddef.h>

/* The metadata the players read, parsed once: when a file is loaded and
 * whenever aero_texture_set changes it. A player takes a texture without
 * looking keys up by name. A missing number reads 0, a missing string "",
 * a missing list NULL. */
typedef struct {
    char kind[32];      /* aeolian, object, vortex, cavity; "" missing */
    char method[16];    /* how an object texture was made ("strip") */
    char shape[32];     /* an aeolian texture's section ("circle") */
    char span3d[32];    /* its spanwise model ("circle-calibrated") */
    char symmetry[32];  /* object textures: "sphere" or "axis" */
    double symmetry_deg; /* aeolian textures: the section's symmetry */
    double v0;          /* the speed it was made at, m/s */
    double diameter, length; /* m */
    double st, re, nu;  /* Strouhal and Reynolds numbers, viscosity m^2/s */
    double mirror;      /* 1: the flow angle's sign mirrors the lift */
    const char *diameters, *centres; /* object textures' lists, in meta
                                        (each ends at '\n'), or NULL */
} aero_texture_header;

typedef struct {
    int frames;       /* samples per channel */
    int channels;     /* 3 * directions */
    int directions;   /* 0 for a vortex texture */
    int regions;      /* object textures: point sources (regions) per
                         direction, channel 3 (k regions + l) + c; else 1 */
    double rate;      /* texture sample rate, Hz */
    float *data;      /* frames * channels, interleaved */
    double *angles;   /* flow angle of each direction in the body frame, deg */
    char *meta;       /* "key=value\n" lines */
    double *speeds;   /* vortex textures: the speed of each channel, m/s
                         (NULL otherwise) */
    aero_texture_header head; /* meta, parsed */
} aero_texture;

/* an empty texture of frames x (3 * directions) zeros; 0 or -1 */
int aero_texture_init(aero_texture *t, int frames, int directions, double rate);
/* the most point sources (directions x regions) of an object texture */
#define AERO_TEXTURE_MAX_SOURCES 4096

/* an empty object texture (kind=object, 3D bodies): frames x (3 *
   directions * regions) zeros, directions x regions at most
   AERO_TEXTURE_MAX_SOURCES; 0 or -1 */
int aero_texture_init_regions(aero_texture *t, int frames, int directions,
                              int regions, double rate);
/* an empty vortex texture: frames x nspeeds zeros, speeds copied (they
   must increase and be > 0; the `speeds` metadata is written from them);
   0 or -1 */
int aero_texture_init_speeds(aero_texture *t, int frames, int nspeeds,
                             const double *speeds, double rate);
/* reads and validates a texture: 0, or -1 with a message in err */
int aero_texture_load(const char *path, aero_texture *t, char *err,
                      size_t errlen);
/* the largest |sample| a flow can put in channel `channel` of t, from its
   metadata's body, speed and rate (texture.c says how and why): the
   loader refuses a file with a sample beyond it */
double aero_texture_ceiling(const aero_texture *t, int channel);
/* 0 when t is of the kind `want` ("object"); else -1 with a message that
   names its kind and the object that plays it ("not an object texture: it
   is a vortex texture, for [vortex~]") */
int aero_texture_wrong_kind(const aero_texture *t, const char *want,
                            char *err, size_t errlen);
/* writes it (float WAV, metadata in the comment): 0, or -1 with a message */
int aero_texture_save(const char *path, const aero_texture *t, char *err,
                      size_t errlen);
void aero_texture_free(aero_texture *t);

/* metadata: set (replaces) a value; get copies a value into buf (NULL
   when the key is missing); getd reads a number (def when missing) */
int aero_texture_set(aero_texture *t, const char *key, const char *value);
int aero_texture_setd(aero_texture *t, const char *key, double value);
const char *aero_texture_get(const aero_texture *t, const char *key,
                             char *buf, size_t len);
double aero_texture_getd(const aero_texture *t, const char *key, double def);

/* component c (0 x, 1 y, 2 z) of direction k at frame n (wrapped) */
float aero_texture_sample(const aero_texture *t, long n, int k, int c);

/* Blackman-windowed sinc low-pass of cut-off fc at t, 0 beyond the
   half-width w (t and w in one unit, fc in cycles per that unit; its sum
   over a window is ~1) */
double aero_texture_lowpass_kernel(double t, double fc, double w);

/* g = dF/dt from a force F sampled at the times t (s, increasing; the
   solver's steps), low-passed (Blackman-windowed sinc, cut-off 0.45 rate)
   and resampled at `rate` for nout samples from time t0; scale multiplies
   the result; out[k * stride] */
void aero_texture_resample_derivative(const double *t, const double *f,
                                      int n, double rate, double t0,
                                      double scale, float *out, int stride,
                                      int nout);
/* the same with the low-pass cut-off fc (Hz) given: below the source's
   own Nyquist rate when it is sampled more coarsely than the texture (3D
   solvers take larger steps), so its steps do not alias into the texture */
void aero_texture_resample_derivative_fc(const double *t, const double *f,
                                         int n, double rate, double fc,
                                         double t0, double scale, float *out,
                                         int stride, int nout);
/* loop length in [lmin, lmax] frames whose start and end match best over
   xfade frames (normalised cross-correlation over all channels); the
   signal x (frames x channels) must hold lmax + xfade frames */
int aero_texture_best_loop(const float *x, int channels, int lmin, int lmax,
                           int xfade);
/* makes the first len frames a seamless loop: frame n < xfade becomes
   (n / xfade) x[n] + (1 - n / xfade) x[len + n] */
void aero_texture_crossfade(float *x, int channels, int len, int xfade);

#endif
