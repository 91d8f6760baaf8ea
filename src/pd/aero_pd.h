/* aero: helpers shared by the Pd wrappers (header-only, static: each
 * external is built from its own source file). */
#ifndef AERO_PD_H
#define AERO_PD_H

#include "m_pd.h"
#include "g_canvas.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A default seed that differs between objects but is the same every time
 * the patch is loaded: from $0 and the object's index in its canvas. */
static inline uint32_t aero_pd_default_seed(void)
{
    t_glist *canvas = canvas_getcurrent();
    uint32_t seed = 1;
    if (canvas) {
        t_symbol *dollar0 = canvas_realizedollar(canvas, gensym("$0"));
        seed += (uint32_t)atoi(dollar0->s_name) * 7919u;
        for (t_gobj *g = canvas->gl_list; g; g = g->g_next)
            seed += 104729u;
    }
    return seed;
}

/* A number from a patch as a 32-bit seed: any finite value wraps; NaN,
 * infinities and beyond +-9.2e18 give 0 (converting those to an integer
 * type is undefined behaviour in C; UBSan caught it, issue 10). */
static inline uint32_t aero_pd_seed(t_float f)
{
    if (!(f > -9.2e18f && f < 9.2e18f))
        return 0;
    return (uint32_t)(int64_t)f;
}

/* A number from a patch as a whole number in lo..hi: 0 with *n set, else
 * -1. NaN, infinities, fractions and numbers out of range are refused
 * before any conversion (a float outside int's range converted to int is
 * undefined behaviour: [vortex~ n inf], [leafwave~ voices nan] and
 * [fieldsound~ demo nan] did that, issue 10). */
static inline int aero_pd_whole(t_float f, int lo, int hi, int *n)
{
    if (!(f >= lo && f <= hi) || f != floor(f))
        return -1;
    *n = (int)f;
    return 0;
}

/* exactly `want` numbers from a message, else an error naming the object */
static inline int aero_pd_floats(void *x, const char *obj, const char *what,
                                 int argc, const t_atom *argv, int want,
                                 double *v)
{
    if (argc != want) {
        pd_error(x, "%s: '%s' takes %d numbers, got %d", obj, what, want,
                 argc);
        return -1;
    }
    for (int i = 0; i < want; i++) {
        if (argv[i].a_type != A_FLOAT) {
            pd_error(x, "%s: '%s' takes numbers only", obj, what);
            return -1;
        }
        v[i] = argv[i].a_w.w_float;
    }
    return 0;
}

/* Reads creation flags: `flag(x, symbol, argc, argv)` handles one flag and
 * returns how many atoms it used (0: unknown). Anything unknown is reported
 * with the object's name and the list of its flags, then skipped. */
typedef int (*aero_pd_flag_fn)(void *x, t_symbol *flag, int argc,
                               t_atom *argv);

static inline void aero_pd_parse_flags(void *x, const char *obj,
                                       const char *known, aero_pd_flag_fn flag,
                                       int argc, t_atom *argv)
{
    while (argc > 0) {
        int used = 0;
        if (argv->a_type == A_SYMBOL)
            used = flag(x, argv->a_w.w_symbol, argc - 1, argv + 1);
        if (!used) {
            char buf[MAXPDSTRING];
            atom_string(argv, buf, sizeof(buf));
            pd_error(x, "%s: unknown argument '%s' ignored (flags: %s)", obj,
                     buf, known);
            used = 1;
        }
        if (used > argc)
            used = argc;
        argc -= used;
        argv += used;
    }
}

/* Finds a data file as DESIGN.md says: next to the patch and on Pd's
 * search path (canvas_open), then in the library's own `folder` (textures,
 * trees). `ext` (".wav") is appended unless the name has it. Writes the
 * full path; 0 when found. */
static inline int aero_pd_find_file(const t_canvas *canvas,
                                    const t_class *cls, const char *name,
                                    const char *ext, const char *folder,
                                    char *path, size_t len)
{
    char dir[MAXPDSTRING], *base;
    size_t n = strlen(name), e = strlen(ext);
    if (n > e && !strcmp(name + n - e, ext))
        ext = "";
    int fd = canvas_open(canvas, name, ext, dir, &base, MAXPDSTRING, 1);
    if (fd >= 0) {
        sys_close(fd);
        return snprintf(path, len, "%s/%s", dir, base) < (int)len ? 0 : -1;
    }
    snprintf(path, len, "%s/%s/%s%s", class_gethelpdir(cls), folder, name,
             ext);
    FILE *f = fopen(path, "rb");
    if (f) {
        fclose(f);
        return 0;
    }
    return -1;
}

/* a texture (.wav) next to the patch, on the path or in textures/ */
static inline int aero_pd_find_texture(const t_canvas *canvas,
                                       const t_class *cls, const char *name,
                                       char *path, size_t len)
{
    return aero_pd_find_file(canvas, cls, name, ".wav", "textures", path,
                             len);
}

/* a tree file (.tree) the same way, or in trees/ ([treebranch~],
 * [leafwave~]) */
static inline int aero_pd_find_tree(const t_canvas *canvas,
                                    const t_class *cls, const char *name,
                                    char *path, size_t len)
{
    return aero_pd_find_file(canvas, cls, name, ".tree", "trees", path, len);
}

/* --- signals at the wrapper boundary ---------------------------------------
 * The core computes in float. A double-precision Pd (PD_FLOATSIZE 64) hands
 * perform double buffers, so each wrapper converts its input signal into
 * float scratch and its float results back. The scratch is allocated in the
 * dsp method, never in perform. With single precision t_sample is float and
 * all of this passes Pd's own buffers through. */
#define AERO_PD_SIGNALS 3 /* an inlet and up to two outlets */

typedef struct aero_pd_scratch {
    float *buf; /* AERO_PD_SIGNALS blocks of n floats (double Pd only) */
    int n;
} aero_pd_scratch;

#if PD_FLOATSIZE == 32
static inline int aero_pd_scratch_prepare(aero_pd_scratch *s, int n)
{
    s->n = n;
    return 0;
}
static inline void aero_pd_scratch_free(aero_pd_scratch *s) { (void)s; }
static inline const float *aero_pd_signal_in(aero_pd_scratch *s, int slot,
                                             const t_sample *in)
{
    (void)s;
    (void)slot;
    return in;
}
static inline float *aero_pd_signal_out(aero_pd_scratch *s, int slot,
                                        t_sample *out)
{
    (void)s;
    (void)slot;
    return out;
}
static inline void aero_pd_signal_done(const aero_pd_scratch *s, int slot,
                                       t_sample *out)
{
    (void)s;
    (void)slot;
    (void)out;
}
#else
/* in the dsp method: room for n frames per signal; 0, or -1 when out of
 * memory (then the wrapper must not add its perform routine) */
static inline int aero_pd_scratch_prepare(aero_pd_scratch *s, int n)
{
    if (s->buf && s->n == n)
        return 0;
    if (s->buf)
        freebytes(s->buf, sizeof(float) * AERO_PD_SIGNALS * (size_t)s->n);
    s->n = 0;
    s->buf = n > 0 ? getbytes(sizeof(float) * AERO_PD_SIGNALS * (size_t)n)
                   : NULL;
    if (!s->buf)
        return -1;
    s->n = n;
    return 0;
}
static inline void aero_pd_scratch_free(aero_pd_scratch *s)
{
    if (s->buf)
        freebytes(s->buf, sizeof(float) * AERO_PD_SIGNALS * (size_t)s->n);
    s->buf = NULL;
    s->n = 0;
}
/* the input signal `in` as floats in scratch block `slot` */
static inline const float *aero_pd_signal_in(aero_pd_scratch *s, int slot,
                                             const t_sample *in)
{
    float *f = s->buf + (size_t)slot * (size_t)s->n;
    for (int i = 0; i < s->n; i++)
        f[i] = (float)in[i];
    return f;
}
/* where the core writes the output for `out`: scratch block `slot` */
static inline float *aero_pd_signal_out(aero_pd_scratch *s, int slot,
                                        t_sample *out)
{
    (void)out;
    return s->buf + (size_t)slot * (size_t)s->n;
}
/* after the core ran: scratch block `slot` back into Pd's `out` */
static inline void aero_pd_signal_done(const aero_pd_scratch *s, int slot,
                                       t_sample *out)
{
    const float *f = s->buf + (size_t)slot * (size_t)s->n;
    for (int i = 0; i < s->n; i++)
        out[i] = f[i];
}
#endif

#endif
