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

/* The data folder a host set with aero_set_data_path() (src/pd/aero.h,
 * defined in aero.c), or NULL. A weak reference: the one-class externals
 * are built without aero.c, and no host calls them, so there it is NULL. */
#if defined(__ELF__) || defined(__APPLE__)
const char *aero_data_path(void) __attribute__((weak));
static inline const char *aero_pd_host_data_path(void)
{
    return aero_data_path ? aero_data_path() : NULL;
}
#else
static inline const char *aero_pd_host_data_path(void) { return NULL; }
#endif

/* 0 when DIR/FOLDER/NAME+EXT is a readable file (its path in `path`) */
static inline int aero_pd_try_data_dir(const char *dir, const char *folder,
                                       const char *name, const char *ext,
                                       char *path, size_t len)
{
    if (!dir || !*dir ||
        snprintf(path, len, "%s/%s/%s%s", dir, folder, name, ext) >= (int)len)
        return -1;
    FILE *f = fopen(path, "rb");
    if (!f)
        return -1;
    fclose(f);
    return 0;
}

/* Finds a data file (a texture in textures/, a tree in trees/), in this
 * order (README, "Embedding"):
 *   1. next to the patch, its [declare -path] folders and Pd's search path
 *      (canvas_open; a libpd host adds folders with libpd_add_to_search_path)
 *   2. DIR/`folder` for DIR in the AERO_DATA environment variable
 *   3. DIR/`folder` for the DIR a host set with aero_set_data_path()
 *   4. `folder` in the folder aero was loaded from (class_gethelpdir: the
 *      installed library; empty for classes a host registers itself).
 * `ext` (".wav") is appended unless the name has it. Writes the full path
 * and returns 0 when found; else -1 with the places it tried written to
 * `path`, for the caller's error message. */
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
    const char *env = getenv("AERO_DATA"), *host = aero_pd_host_data_path();
    const char *helpdir = class_gethelpdir(cls);
    if (!aero_pd_try_data_dir(env, folder, name, ext, path, len) ||
        !aero_pd_try_data_dir(host, folder, name, ext, path, len) ||
        !aero_pd_try_data_dir(helpdir, folder, name, ext, path, len))
        return 0;
    /* not found: say where it looked */
    t_symbol *patchdir = canvas ? canvas_getdir(canvas) : NULL;
    snprintf(path, len,
             "next to the patch (%s), in its declared paths and Pd's search "
             "path; in $AERO_DATA/%s (%s%s); in aero_set_data_path()/%s "
             "(%s%s); in aero's own %s/ (%s)",
             patchdir && *patchdir->s_name ? patchdir->s_name : "no folder",
             folder, env && *env ? "AERO_DATA=" : "", env && *env ? env :
             "not set", folder, host && *host ? "set to " : "",
             host && *host ? host : "not set", folder,
             helpdir && *helpdir ? helpdir : "no install folder: registered "
             "by a host");
    return -1;
}

/* a texture (.wav): next to the patch, on the path, then in textures/ */
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

#endif
