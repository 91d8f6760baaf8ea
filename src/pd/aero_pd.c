/* aero: the skeleton every Pd wrapper shares (see aero_pd.h). Built into
 * each external and into the single-binary library. */
#include "aero_pd.h"
#include "aero.h"

#include "aero_air.h"
#include "moving_player.h"

#include <limits.h>
#include <sys/stat.h>

/* --- the table ----------------------------------------------------------- */

t_class *aero_pd_class_new(const aero_pd_spec *spec, t_newmethod new_fn,
                           t_method free_fn, size_t size, int f_offset,
                           t_method dsp_fn)
{
    t_class *c = class_new(gensym(spec->name), new_fn, free_fn, size,
                           CLASS_DEFAULT, A_GIMME, 0);
    if (f_offset >= 0)
        class_domainsignalin(c, f_offset);
    class_addmethod(c, dsp_fn, gensym("dsp"), A_CANT, 0);
    for (int k = 0; k < spec->count; k++) {
        const aero_pd_method *m = spec->methods + k;
        t_symbol *sel = gensym(m->name);
        switch (m->args) {
        case AERO_PD_BANG:
            class_addmethod(c, m->fn, sel, A_NULL);
            break;
        case AERO_PD_FLOAT:
            class_addmethod(c, m->fn, sel, A_FLOAT, A_NULL);
            break;
        case AERO_PD_SYMBOL:
            class_addmethod(c, m->fn, sel, A_SYMBOL, A_NULL);
            break;
        case AERO_PD_LIST:
            class_addmethod(c, m->fn, sel, A_GIMME, A_NULL);
            break;
        case AERO_PD_SWITCH:
            break;
        }
    }
    class_sethelpsymbol(c, gensym(spec->name));
    return c;
}

/* the flags of an object, for an error message: "-d -l -gain ..." */
static void flag_list(const aero_pd_spec *spec, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = 0;
    if (spec->first)
        used += snprintf(buf, len, "%s", spec->first);
    for (int k = 0; k < spec->count && used < len; k++) {
        if (spec->methods[k].options & AERO_PD_MESSAGE_ONLY)
            continue;
        used += snprintf(buf + used, len - used, "%s-%s", used ? " " : "",
                         spec->methods[k].name);
    }
}

static const aero_pd_method *find_flag(const aero_pd_spec *spec,
                                       const t_atom *a)
{
    if (a->a_type != A_SYMBOL || a->a_w.w_symbol->s_name[0] != '-')
        return NULL;
    for (int k = 0; k < spec->count; k++)
        if (!(spec->methods[k].options & AERO_PD_MESSAGE_ONLY) &&
            !strcmp(a->a_w.w_symbol->s_name + 1, spec->methods[k].name))
            return spec->methods + k;
    return NULL;
}

typedef void (*bang_fn)(void *x);
typedef void (*float_fn)(void *x, t_floatarg f);
typedef void (*symbol_fn)(void *x, t_symbol *s);
typedef void (*list_fn)(void *x, t_symbol *s, int argc, t_atom *argv);

/* One flag with the atoms after it: calls its method (when `apply`) and
 * returns how many atoms it used, itself included. */
static int apply_flag(aero_pd_base *b, const aero_pd_method *m, int argc,
                      t_atom *argv, int apply)
{
    void *x = b->owner;
    const char *obj = b->obj;
    int want = m->args == AERO_PD_FLOAT || m->args == AERO_PD_SYMBOL ? 1
        : m->args == AERO_PD_LIST ? m->count : 0;
    int have = 0;
    while (have < want && have < argc &&
           argv[have].a_type == (m->args == AERO_PD_SYMBOL ? A_SYMBOL
                                                             : A_FLOAT))
        have++;
    if (have < want) {
        if (apply)
            pd_error(x, "%s: flag -%s needs %d %s", obj, m->name, want,
                     m->args == AERO_PD_SYMBOL ? "name"
                     : want == 1 ? "number" : "numbers");
        return 1 + have;
    }
    if (!apply)
        return 1 + want;
    b->flag = m->name; /* a refusal now says what the object keeps */
    switch (m->args) {
    case AERO_PD_BANG:
        ((bang_fn)m->fn)(x);
        break;
    case AERO_PD_FLOAT:
        ((float_fn)m->fn)(x, atom_getfloat(argv));
        break;
    case AERO_PD_SYMBOL:
        ((symbol_fn)m->fn)(x, argv[0].a_w.w_symbol);
        break;
    case AERO_PD_LIST:
        ((list_fn)m->fn)(x, gensym(m->name), want, argv);
        break;
    case AERO_PD_SWITCH:
        break;
    }
    b->flag = NULL;
    return 1 + want;
}

/* did a flag before `at` set what m sets (the same method: -L, -length)? */
static int set_before(const aero_pd_spec *spec, const t_atom *argv,
                      const t_atom *at, const aero_pd_method *m)
{
    for (; argv < at; argv++) {
        const aero_pd_method *k = find_flag(spec, argv);
        if (k && k->fn == m->fn)
            return 1;
    }
    return 0;
}

/* one pass over the flags: the EARLY ones (early = 1) or the others */
static void flag_pass(aero_pd_base *b, int argc, t_atom *argv, int early)
{
    const aero_pd_spec *spec = b->spec;
    void *x = b->owner;
    const char *name = b->obj;
    t_atom *all = argv;
    while (argc > 0) {
        const aero_pd_method *m = find_flag(spec, argv);
        int used = 1;
        if (m) {
            b->flag_again = set_before(spec, all, argv, m);
            used = apply_flag(b, m, argc - 1, argv + 1,
                              !(m->options & AERO_PD_EARLY) == !early);
        } else if (!early) {
            char buf[MAXPDSTRING], flags[MAXPDSTRING];
            atom_string(argv, buf, sizeof(buf));
            flag_list(spec, flags, sizeof(flags));
            pd_error(x, "%s: unknown argument '%s' ignored (flags: %s)",
                     name, buf, flags);
        }
        if (used > argc)
            used = argc;
        argc -= used;
        argv += used;
    }
}

void aero_pd_parse_flags(aero_pd_base *b, int argc, t_atom *argv)
{
    flag_pass(b, argc, argv, 1);
    flag_pass(b, argc, argv, 0);
}

int aero_pd_has_flag(const char *name, int argc, const t_atom *argv)
{
    for (int i = 0; i < argc; i++)
        if (argv[i].a_type == A_SYMBOL &&
            !strcmp(argv[i].a_w.w_symbol->s_name, name))
            return 1;
    return 0;
}

t_symbol *aero_pd_first_symbol(int *argc, t_atom **argv)
{
    if (*argc > 0 && (*argv)[0].a_type == A_SYMBOL &&
        (*argv)[0].a_w.w_symbol->s_name[0] != '-') {
        t_symbol *s = (*argv)[0].a_w.w_symbol;
        (*argc)--;
        (*argv)++;
        return s;
    }
    return NULL;
}

/* --- the base -------------------------------------------------------------- */

static void base_report(aero_pd_base *b)
{
    if (b->clamped && !b->warned_clamp) {
        if (b->clamp_words)
            pd_error(b->owner, "%s: %s (the model does not hold beyond)",
                     b->obj, b->clamp_words);
        else
            pd_error(b->owner, "%s: flow speed above Mach 0.3 clamped to %g "
                     "m/s (the model does not hold there)", b->obj,
                     AERO_MACH_LIMIT * AERO_C0);
        b->warned_clamp = 1;
    }
    if (b->ceiling_hit && !b->warned_ceiling) {
        pd_error(b->owner, "%s: output beyond %g Pa (1 atm, 194 dB SPL: no "
                 "sound in air reaches it) clamped, NaN set to 0: a corrupt "
                 "file or a runaway state (this is reported once)", b->obj,
                 (double)AERO_PD_CEILING_PA);
        b->warned_ceiling = 1;
    }
    if (b->near_hit && !b->warned_near) {
        pd_error(b->owner, "%s: listener within %g m of the source: heard "
                 "as at %g m (the far field does not hold closer)", b->obj,
                 b->near_m, b->near_m);
        b->warned_near = 1;
    }
}

void aero_pd_base_init(aero_pd_base *b, void *owner, const aero_pd_spec *spec,
                       int argc, const t_atom *argv)
{
    memset(b, 0, sizeof(*b));
    b->owner = owner;
    b->spec = spec;
    b->canvas = canvas_getcurrent();
    for (int k = 0; k < spec->count; k++)
        if (spec->methods[k].args == AERO_PD_SWITCH &&
            !strcmp(spec->methods[k].name, "stereo"))
            b->stereo = aero_pd_has_flag("-stereo", argc, argv);
    b->clock = clock_new(b, (t_method)base_report);
    /* "[name]" for messages: a symbol too, so it outlives this call */
    char buf[MAXPDSTRING];
    snprintf(buf, sizeof(buf), "[%s]", spec->name);
    b->obj = gensym(buf)->s_name;
}

void aero_pd_base_outlets(aero_pd_base *b)
{
    b->out[0] = outlet_new(b->owner, &s_signal);
    if (b->stereo)
        b->out[1] = outlet_new(b->owner, &s_signal);
}

void aero_pd_base_free(aero_pd_base *b)
{
    if (b->scratch)
        freebytes(b->scratch, sizeof(float) * (size_t)b->scratch_n);
    if (b->clock)
        clock_free(b->clock);
    for (int i = 0; i < 2; i++)
        if (b->out[i])
            outlet_free(b->out[i]);
}

/* --- perform ---------------------------------------------------------------- */

/* the last guard (aero_pd.h): 1 when it changed a sample */
static int aero_pd_guard(float *out, int n)
{
    const float c = AERO_PD_CEILING_PA;
    int hit = 0;
    for (int i = 0; i < n; i++) {
        float y = out[i];
        if (!(y >= -c && y <= c)) { /* NaN fails both */
            out[i] = y > c ? c : y < -c ? -c : 0.0f;
            hit = 1;
        }
    }
    return hit;
}

static void aero_pd_guard_outputs(aero_pd_base *b, float *const *out, int n)
{
    int hit = 0;
    for (int c = 0; c < 2; c++)
        if (out[c])
            hit |= aero_pd_guard(out[c], n);
    if (hit && !b->ceiling_hit) {
        b->ceiling_hit = 1;
        if (b->clock)
            clock_delay(b->clock, 0);
    }
}

static t_int *aero_pd_perform(t_int *w)
{
    aero_pd_base *b = (aero_pd_base *)(w[1]);
    t_sample *in = (t_sample *)(w[2]);
    t_sample *pd_out[2] = {(t_sample *)(w[3]), (t_sample *)(w[4])};
    int n = (int)(w[5]);
#if PD_FLOATSIZE == 32
    float *out[2] = {pd_out[0], pd_out[1]};
    if (b->process(b->owner, in, out, n))
        aero_pd_clamped(b);
    aero_pd_guard_outputs(b, out, n);
#else
    float *f_in = b->scratch, *out[2] = {b->scratch + n, NULL};
    if (pd_out[1])
        out[1] = b->scratch + 2 * n;
    for (int i = 0; in && i < n; i++)
        f_in[i] = (float)in[i];
    if (b->process(b->owner, in ? f_in : NULL, out, n))
        aero_pd_clamped(b);
    aero_pd_guard_outputs(b, out, n);
    for (int c = 0; c < 2; c++)
        for (int i = 0; pd_out[c] && i < n; i++)
            pd_out[c][i] = out[c][i];
#endif
    return w + 6;
}

void aero_pd_dsp(aero_pd_base *b, t_signal **sp, int inlet,
                 aero_pd_process process)
{
    int n = sp[0]->s_n;
    t_signal **outs = sp + (inlet ? 1 : 0);
    b->process = process;
#if PD_FLOATSIZE != 32
    if (b->scratch_n != 3 * n) {
        if (b->scratch)
            freebytes(b->scratch, sizeof(float) * (size_t)b->scratch_n);
        b->scratch = getbytes(sizeof(float) * 3 * (size_t)n);
        b->scratch_n = b->scratch ? 3 * n : 0;
    }
    if (!b->scratch) {
        pd_error(b->owner, "%s: out of memory: silent", b->obj);
        for (int c = 0; c < (b->stereo ? 2 : 1); c++)
            dsp_add_zero(outs[c]->s_vec, n);
        return;
    }
#endif
    dsp_add(aero_pd_perform, 5, b, inlet ? sp[0]->s_vec : NULL,
            outs[0]->s_vec, b->stereo ? outs[1]->s_vec : NULL, (t_int)n);
}

/* --- refusals ------------------------------------------------------------- */

const aero_pd_rule *aero_pd_rule_of(const aero_pd_base *b, const char *name)
{
    for (int k = 0; b->spec && k < b->spec->count; k++)
        if (!strcmp(b->spec->methods[k].name, name))
            return &b->spec->methods[k].rule;
    return NULL;
}

/* " (0.0001..100 m; default 0.02 m; note)" from a rule, "" when it
   states nothing */
static void rule_text(const aero_pd_rule *r, char *buf, size_t len)
{
    const char *sp = r && r->unit ? " " : "", *unit = r && r->unit ? r->unit
                                                                    : "";
    size_t used = 0;
    buf[0] = '\0';
    if (!r || (r->lo == r->hi && !r->note && !r->has_def))
        return;
    used += snprintf(buf + used, len - used, " (");
    if (r->lo != r->hi && used < len)
        used += snprintf(buf + used, len - used, "%g..%g%s%s", r->lo, r->hi,
                         sp, unit);
    if (r->has_def && used < len)
        used += snprintf(buf + used, len - used, "%sdefault %g%s%s",
                         r->lo != r->hi ? "; " : "", r->def, sp, unit);
    if (r->note && used < len)
        used += snprintf(buf + used, len - used, "%s%s",
                         r->lo != r->hi || r->has_def ? "; " : "", r->note);
    if (used < len)
        snprintf(buf + used, len - used, ")");
}

/* after a refusal from a creation flag: what the object keeps instead */
static void kept_text(const aero_pd_base *b, const aero_pd_rule *r,
                      char *buf, size_t len)
{
    buf[0] = '\0';
    if (b->flag)
        snprintf(buf, len, ": flag -%s ignored%s", b->flag,
                 r && r->has_def && !b->flag_again ? ", the default stays"
                                                   : "");
}

void aero_pd_refused(const aero_pd_base *b, const char *name, t_float f)
{
    const aero_pd_rule *r = aero_pd_rule_of(b, name);
    char range[MAXPDSTRING], kept[MAXPDSTRING];
    rule_text(r, range, sizeof(range));
    kept_text(b, r, kept, sizeof(kept));
    pd_error(b->owner, "%s: %s %g%s%s out of range%s%s", b->obj, name, f,
             r && r->unit ? " " : "", r && r->unit ? r->unit : "", range,
             kept);
}

void aero_pd_refused_list(const aero_pd_base *b, const char *name)
{
    const aero_pd_rule *r = aero_pd_rule_of(b, name);
    char range[MAXPDSTRING], kept[MAXPDSTRING];
    rule_text(r, range, sizeof(range));
    kept_text(b, r, kept, sizeof(kept));
    pd_error(b->owner, "%s: %s out of range%s%s", b->obj, name, range, kept);
}

int aero_pd_seed_of(const aero_pd_base *b, t_float f, uint32_t *seed)
{
    if (!(f > -HUGE_VAL && f < HUGE_VAL)) {
        aero_pd_refused(b, "seed", f);
        return -1;
    }
    *seed = aero_pd_seed(f);
    return 0;
}

void aero_pd_init_failed(const aero_pd_base *b, double sr)
{
    if (sr > 0.0 && sr < HUGE_VAL)
        pd_error(b->owner, "%s: out of memory: silent", b->obj);
    else
        pd_error(b->owner, "%s: sample rate %g not usable: the core's "
                 "default rate until the DSP starts", b->obj, sr);
}

void aero_pd_rate_failed(const aero_pd_base *b, double sr)
{
    pd_error(b->owner, "%s: sample rate %g refused (out of range, or out of "
             "memory)", b->obj, sr);
}

double aero_pd_at_bound(const aero_pd_base *b, const char *name, t_float f)
{
    const aero_pd_rule *r = aero_pd_rule_of(b, name);
    if (r && r->lo != r->hi) {
        if ((float)f == (float)r->lo)
            return r->lo;
        if ((float)f == (float)r->hi)
            return r->hi;
    }
    return f;
}

int aero_pd_whole_of(const aero_pd_base *b, const char *name, t_float f,
                     int *n)
{
    const aero_pd_rule *r = aero_pd_rule_of(b, name);
    if (!r || !(r->lo >= INT_MIN && r->hi <= INT_MAX))
        return -1;
    return aero_pd_whole(f, (int)r->lo, (int)r->hi, n);
}

int aero_pd_ears(aero_pd_base *b, t_symbol *s, int argc, const t_atom *argv,
                 aero_ears *e)
{
    int ears = strcmp(s->s_name, "ears") ? 1 : 2;
    if (ears == 1 && b->stereo) {
        pd_error(b->owner, "%s: created with -stereo: use 'ears lx ly lz rx "
                 "ry rz'", b->obj);
        return 0;
    }
    if (ears == 2 && !b->stereo) {
        pd_error(b->owner, "%s: 'ears' needs -stereo; use 'listener x y z'",
                 b->obj);
        return 0;
    }
    if (aero_pd_floats(b->owner, b->obj, s->s_name, argc, argv, 3 * ears,
                       &e->pos[0][0]))
        return 0;
    return e->n = ears;
}

void aero_pd_bad_ears(aero_pd_base *b, int ears)
{
    pd_error(b->owner, "%s: %s out of range (-%g..%g m; finite)", b->obj,
             ears == 2 ? "ears" : "listener", AERO_POSITION_LIMIT,
             AERO_POSITION_LIMIT);
}

/* --- wind ----------------------------------------------------------------- */

void aero_pd_wind_init(aero_pd_wind *w)
{
    w->dir[0] = 1.0;
    w->dir[1] = w->dir[2] = 0.0;
}

double aero_pd_wind_message(aero_pd_base *b, aero_pd_wind *w, t_symbol *s,
                            int argc, const t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(b->owner, b->obj, s->s_name, argc, argv, 3, v))
        return -1.0;
    double speed = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(speed <= AERO_MOVING_WIND_MAX)) { /* NaN fails too */
        aero_pd_refused_list(b, s->s_name);
        return -1.0;
    }
    if (speed > 0.0)
        for (int k = 0; k < 3; k++)
            w->dir[k] = v[k] / speed;
    return speed;
}

/* --- a core rebuilt in a worker and swapped in ----------------------------- */

static void swap_poll(aero_pd_swap *s);

void aero_pd_swap_init(aero_pd_swap *s, void *owner,
                       void (*finish)(void *owner),
                       void (*free_core)(void *core))
{
    memset(s, 0, sizeof(*s));
    s->owner = owner;
    s->finish = finish;
    s->free_core = free_core;
    s->poll = clock_new(s, (t_method)swap_poll);
}

void aero_pd_swap_drop_old(aero_pd_swap *s)
{
    if (s->old) {
        s->free_core(s->old);
        free(s->old);
        s->old = NULL;
    }
}

void aero_pd_swap_free(aero_pd_swap *s, void (*drop_load)(void *load))
{
    clock_free(s->poll);
    if (s->job)
        aero_load_job_abandon(s->job, drop_load);
    s->job = NULL;
    aero_pd_swap_drop_old(s);
}

int aero_pd_swap_small(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && st.st_size < AERO_PD_SWAP_SMALL_FILE;
}

/* Pd's logical time running well ahead of the real one: batch mode (or
   no audio device), where nobody hears a wait and renders must not
   depend on how fast the worker was */
static int swap_batch(const aero_pd_swap *s)
{
    double logical = clock_gettimesince(s->logical) * 0.001;
    return sys_getrealtime() - s->real < 0.5 * logical;
}

static void swap_poll(aero_pd_swap *s)
{
    /* faded out, or not fading at all (DSP is off) */
    if (s->old && (s->fade >= s->fade_len || s->fade == s->fade_seen))
        aero_pd_swap_drop_old(s);
    s->fade_seen = s->fade;
    if (s->job && (aero_load_job_done(s->job) || swap_batch(s)))
        s->finish(s->owner);
    if (s->job || s->old)
        clock_delay(s->poll, AERO_PD_SWAP_POLL_MS);
}

int aero_pd_swap_start(aero_pd_swap *s, aero_load_fn fn, void *load,
                       int now)
{
    s->load = load;
    s->job = aero_load_job_start(fn, load, !now);
    if (!s->job) {
        s->load = NULL;
        return -1;
    }
    if (now) {
        s->finish(s->owner);
        aero_pd_swap_drop_old(s); /* nothing played yet: no fade */
        return 0;
    }
    s->logical = clock_getlogicaltime();
    s->real = sys_getrealtime();
    clock_delay(s->poll, AERO_PD_SWAP_WAIT_MS);
    return 0;
}

void *aero_pd_swap_take(aero_pd_swap *s)
{
    void *load = s->load;
    aero_load_job_finish(s->job);
    s->job = NULL;
    s->load = NULL;
    return load;
}

void *aero_pd_swap_fade_slot(aero_pd_swap *s, size_t size, double sr)
{
    aero_pd_swap_drop_old(s);
    s->old = malloc(size);
    s->fade = s->fade_seen = 0;
    s->fade_len = (int)(AERO_PD_SWAP_FADE_MS * 0.001 * sr);
    return s->old;
}

/* --- the host's data folder (aero.h) -------------------------------------- */

/* The one piece of process state in aero: the folder a libpd host set with
 * aero_set_data_path(), before opening patches; objects only read it, when
 * they look for a file (aero_pd_find_file). Allowed by name in
 * tests/robust/globals.sh. */
static char aero_data_dir[MAXPDSTRING];

void aero_set_data_path(const char *dir)
{
    size_t n = dir ? strlen(dir) : 0;
    if (n >= sizeof(aero_data_dir)) {
        pd_error(NULL, "aero: data path of %lu bytes is too long (max %lu): "
                 "unset", (unsigned long)n,
                 (unsigned long)(sizeof(aero_data_dir) - 1));
        n = 0;
    }
    memcpy(aero_data_dir, dir ? dir : "", n);
    aero_data_dir[n] = '\0';
}

const char *aero_data_path(void)
{
    return aero_data_dir[0] ? aero_data_dir : NULL;
}

/* --- files ----------------------------------------------------------------- */

/* 0 when DIR/FOLDER/NAME+EXT is a readable file (its path in `path`) */
static int try_data_dir(const char *dir, const char *folder, const char *name,
                        const char *ext, char *path, size_t len)
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

int aero_pd_find_file(const t_canvas *canvas, const t_class *cls,
                      const char *name, const char *ext, const char *folder,
                      char *path, size_t len)
{
    char dir[MAXPDSTRING], *base;
    size_t n = strlen(name), e = strlen(ext);
    if (n > e && !strcmp(name + n - e, ext))
        ext = "";
    int fd = canvas_open(canvas, name, ext, dir, &base, MAXPDSTRING, 1);
    if (fd < 0 && *ext) /* "x.wav" given for a tree: found, then refused */
        fd = canvas_open(canvas, name, "", dir, &base, MAXPDSTRING, 1);
    if (fd >= 0) {
        sys_close(fd);
        return snprintf(path, len, "%s/%s", dir, base) < (int)len ? 0 : -1;
    }
    const char *env = getenv("AERO_DATA"), *host = aero_data_path();
    const char *helpdir = class_gethelpdir(cls);
    if (!try_data_dir(env, folder, name, ext, path, len) ||
        !try_data_dir(host, folder, name, ext, path, len) ||
        !try_data_dir(helpdir, folder, name, ext, path, len))
        return 0;
    /* not found: say where it looked */
    t_symbol *patchdir = canvas ? canvas_getdir(canvas) : NULL;
    int full = snprintf(path, len,
             "next to the patch (%s), in its declared paths and Pd's search "
             "path; in $AERO_DATA/%s (%s%s); in aero_set_data_path()/%s "
             "(%s%s); in aero's own %s/ (%s)",
             patchdir && *patchdir->s_name ? patchdir->s_name : "no folder",
             folder, env && *env ? "AERO_DATA=" : "", env && *env ? env :
             "not set", folder, host && *host ? "set to " : "",
             host && *host ? host : "not set", folder,
             helpdir && *helpdir ? helpdir : "no install folder: registered "
             "by a host");
    if (full >= (int)len && len > 4)
        memcpy(path + len - 4, "...", 4); /* long paths: the list is cut */
    return -1;
}

/* --- textures -------------------------------------------------------------- */

/* is `name` (as given: absolute, or next to the patch) a folder? */
static int is_folder(const t_canvas *canvas, const char *name)
{
    char path[MAXPDSTRING];
    struct stat st;
    t_symbol *dir = canvas ? canvas_getdir((t_canvas *)canvas) : NULL;
    if (name[0] == '/' || !dir || !*dir->s_name)
        snprintf(path, sizeof(path), "%s", name);
    else
        snprintf(path, sizeof(path), "%s/%s", dir->s_name, name);
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* what a refused file leaves: the file that plays, or the fallback */
static const char *after_refusal(const aero_pd_base *b, const char *what,
                                 const char *fallback, char *buf, size_t len)
{
    if (!b->has_file)
        return fallback;
    snprintf(buf, len, "the previous %s stays", what);
    return buf;
}

void aero_pd_no_file(const aero_pd_base *b, const char *what,
                     const char *message)
{
    if (!b->has_file && !b->file_tried)
        post("%s: no %s given: silent until '%s NAME'", b->obj, what,
             message);
}

void aero_pd_load_texture(aero_pd_base *b, t_class *cls, t_symbol *name,
                          aero_pd_set_texture set, void *core,
                          const char *fallback)
{
    b->file_tried = 1;
    char path[MAXPDSTRING], err[MAXPDSTRING + 256], kept[64];
    const char *after = after_refusal(b, "texture", fallback, kept,
                                      sizeof(kept));
    int found = !aero_pd_find_texture(b->canvas, cls, name->s_name, path,
                                      sizeof(path));
    if ((found && is_folder(NULL, path)) ||
        (!found && is_folder(b->canvas, name->s_name))) {
        pd_error(b->owner, "%s: texture '%s' is a folder, not a texture "
                 "file: %s", b->obj, found ? path : name->s_name, after);
        return;
    }
    if (!found) {
        pd_error(b->owner, "%s: can't find texture '%s' (looked %s): %s",
                 b->obj, name->s_name, path, after);
        return;
    }
    aero_texture *t = calloc(1, sizeof(*t));
    if (!t || aero_texture_load(path, t, err, sizeof(err)) ||
        set(core, t, err, sizeof(err))) {
        /* the loader's messages name the file; the core's do not */
        if (t && strstr(err, path))
            pd_error(b->owner, "%s: %s: %s", b->obj, err, after);
        else
            pd_error(b->owner, "%s: texture %s: %s: %s", b->obj, path,
                     t ? err : "out of memory", after);
        if (t)
            aero_texture_free(t);
        free(t);
        if (!b->has_file)
            set(core, NULL, err, sizeof(err));
        return;
    }
    b->has_file = 1;
}

/* --- trees ------------------------------------------------------------------ */

/* the bad lines of a read, kept for the report (the read may run in a
   worker, which must not call Pd) */
static void tree_bad_line(void *ctx, int line, const char *message)
{
    aero_pd_tree_file *r = ctx;
    if (r->count < AERO_PD_TREE_LINES_SHOWN) {
        r->line[r->count] = line;
        snprintf(r->message[r->count], sizeof(r->message[0]), "%s", message);
    }
    r->count++;
}

/* a file that is not text: a NUL in its first bytes (a WAV, an image) */
static int is_binary(const char *path)
{
    unsigned char buf[512];
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(buf, 1, sizeof(buf), f) : 0;
    if (f)
        fclose(f);
    return memchr(buf, 0, n) != NULL;
}

int aero_pd_tree_find(aero_pd_base *b, t_class *cls, t_symbol *name,
                      aero_pd_tree_file *r)
{
    char kept[64];
    const char *after = after_refusal(b, "tree", "silent", kept, sizeof(kept));
    memset(r, 0, sizeof(*r));
    b->file_tried = 1;
    int found = !aero_pd_find_tree(b->canvas, cls, name->s_name, r->path,
                                   sizeof(r->path));
    if ((found && is_folder(NULL, r->path)) ||
        (!found && is_folder(b->canvas, name->s_name))) {
        pd_error(b->owner, "%s: tree '%s' is a folder, not a tree file: %s",
                 b->obj, found ? r->path : name->s_name, after);
        return -1;
    }
    if (!found) {
        pd_error(b->owner, "%s: can't find tree '%s' (looked %s): %s",
                 b->obj, name->s_name, r->path, after);
        return -1;
    }
    if (is_binary(r->path)) {
        pd_error(b->owner, "%s: %s is not a tree file (binary data; a tree is "
                 "text, trees/README.md): %s", b->obj, r->path, after);
        return -1;
    }
    return 0;
}

int aero_pd_tree_read(aero_pd_tree_file *r, aero_tree *t)
{
    r->bad = aero_tree_load(r->path, t, tree_bad_line, r, r->err,
                            sizeof(r->err));
    return r->bad;
}

int aero_pd_tree_report(aero_pd_base *b, const aero_pd_tree_file *r)
{
    char kept[64];
    const char *after = after_refusal(b, "tree", "silent", kept, sizeof(kept));
    int shown = r->count < AERO_PD_TREE_LINES_SHOWN
        ? r->count : AERO_PD_TREE_LINES_SHOWN;
    for (int i = 0; i < shown; i++)
        pd_error(b->owner, "%s: %s:%d: %s (line skipped)", b->obj, r->path,
                 r->line[i], r->message[i]);
    if (r->count > AERO_PD_TREE_LINES_SHOWN)
        pd_error(b->owner, "%s: %s: %d more bad lines not shown", b->obj,
                 r->path, r->count - AERO_PD_TREE_LINES_SHOWN);
    if (r->bad) {
        pd_error(b->owner, "%s: %s: %s", b->obj, r->err, after);
        return -1;
    }
    b->has_file = 1;
    return 0;
}

int aero_pd_load_tree(aero_pd_base *b, t_class *cls, t_symbol *name,
                      aero_tree *t)
{
    aero_pd_tree_file *r = malloc(sizeof(*r));
    int bad;
    if (!r) {
        pd_error(b->owner, "%s: out of memory reading a tree: silent",
                 b->obj);
        return -1;
    }
    bad = aero_pd_tree_find(b, cls, name, r);
    if (!bad) {
        aero_pd_tree_read(r, t);
        bad = aero_pd_tree_report(b, r);
    }
    free(r);
    return bad;
}

/* --- numbers --------------------------------------------------------------- */

uint32_t aero_pd_default_seed(void)
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

int aero_pd_pose(aero_pd_base *b, aero_pd_pose_clock *c, t_symbol *s,
                 int argc, const t_atom *argv, const double current[4],
                 double pos[3], double q[4], double *interval, int *offset)
{
    double v[7];
    if (argc != 3 && argc != 6 && argc != 7) {
        pd_error(b->owner, "%s: '%s' takes x y z, x y z rx ry rz (rotation "
                 "vector, deg) or x y z qw qx qy qz (quaternion), got %d "
                 "numbers", b->obj, s->s_name, argc);
        return -1;
    }
    if (aero_pd_floats(b->owner, b->obj, s->s_name, argc, argv, argc, v))
        return -1;
    if (argc == 3)
        memcpy(q, current, 4 * sizeof(double));
    else if (argc == 6) {
        if (!(fabs(v[3]) < 1e9 && fabs(v[4]) < 1e9 && fabs(v[5]) < 1e9)) {
            aero_pd_refused_list(b, s->s_name);
            return -1;
        }
        aero_quat_from_rotvec(v + 3, q);
    } else
        memcpy(q, v + 3, 4 * sizeof(double));
    memcpy(pos, v, 3 * sizeof(double));
    /* place: a jump, no motion */
    *interval = aero_pd_pose_clock_pose(c, !strcmp(s->s_name, "place"),
                                        offset);
    return 0;
}

int aero_pd_floats(void *x, const char *obj, const char *what, int argc,
                   const t_atom *argv, int want, double *v)
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
