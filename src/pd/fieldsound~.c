/* [fieldsound~]: field auralization of time-varying volume data (paper
 * 002) in real time. Thin Pd wrapper around src/core/field_sound: the
 * volume is preprocessed in a worker thread (no Pd calls in it), the
 * sources are swapped in by a clock in Pd's thread, perform only renders.
 *
 *   [fieldsound~ <volume dir> -listener x y z -speed fps ...]
 *   [fieldsound~ -demo 32]  the synthetic burst (32^3), no files
 *   outlet 1 (signal): sound pressure at the listener, Pa
 *   outlet 2: progress <0..1>, ready <active vertices> <seconds>, done
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* clock_gettime, pthreads */
#endif
#include "aero_pd.h"

#include "field_sound.h"

#include <pthread.h>
#include <time.h>

static t_class *fieldsound_tilde_class;

#define OBJ "[fieldsound~]"

/* one preprocessing run; shared with its worker under `lock` */
typedef struct field_job {
    pthread_mutex_t lock;
    int done_frames, total_frames;
    int finished;          /* 0 running, 1 ok, -1 failed */
    int cancel;
    char err[512];
    aero_volume_info info;
    aero_field_demo demo;
    int use_demo;
    aero_field_params par;
    aero_field_sources result;
    double seconds;
} field_job;

typedef struct _fieldsound_tilde {
    t_object x_obj;
    aero_field_render x_render;
    aero_field_sources x_sources;  /* what x_render plays */
    aero_field_params x_par;
    t_canvas *x_canvas;
    t_symbol *x_dir;               /* as given, or NULL for the demo */
    int x_demo_size;
    int x_sync, x_pending_play, x_reported_progress;
    field_job *x_job;
    pthread_t x_thread;
    int x_thread_live;
    int x_was_playing, x_clamped, x_warned_clamp, x_done;
    t_clock *x_poll, *x_report;
    t_outlet *x_out, *x_info;
    aero_pd_scratch x_scratch; /* float signals for a double Pd */
} t_fieldsound_tilde;

static double wall_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* --- the worker: core calls only ---------------------------------------- */

static int job_progress(void *ctx, int done, int total)
{
    field_job *j = ctx;
    int cancel;
    pthread_mutex_lock(&j->lock);
    j->done_frames = done;
    j->total_frames = total;
    cancel = j->cancel;
    pthread_mutex_unlock(&j->lock);
    return cancel;
}

static void job_run(field_job *j)
{
    double t0 = wall_seconds();
    char err[512] = "";
    int rc = aero_field_prepare(&j->info, j->use_demo ? &j->demo : NULL,
                                &j->par, &j->result, job_progress, j, err,
                                sizeof err);
    pthread_mutex_lock(&j->lock);
    j->seconds = wall_seconds() - t0;
    j->finished = rc ? -1 : 1;
    memcpy(j->err, err, sizeof err);
    pthread_mutex_unlock(&j->lock);
}

static void *job_thread(void *arg)
{
    job_run(arg);
    return NULL;
}

static void job_free(field_job *j)
{
    if (j->finished == 1)
        aero_field_sources_free(&j->result);
    pthread_mutex_destroy(&j->lock);
    freebytes(j, sizeof *j);
}

/* stops a running job (waits for its current frame) and frees it */
static void fieldsound_tilde_cancel(t_fieldsound_tilde *x)
{
    if (!x->x_job)
        return;
    pthread_mutex_lock(&x->x_job->lock);
    x->x_job->cancel = 1;
    pthread_mutex_unlock(&x->x_job->lock);
    if (x->x_thread_live)
        pthread_join(x->x_thread, NULL);
    x->x_thread_live = 0;
    job_free(x->x_job);
    x->x_job = NULL;
    clock_unset(x->x_poll);
}

static const char *fieldsound_tilde_name(t_fieldsound_tilde *x, char *buf,
                                         size_t len)
{
    if (x->x_dir)
        snprintf(buf, len, "%s", x->x_dir->s_name);
    else
        snprintf(buf, len, "demo burst %d^3", x->x_demo_size);
    return buf;
}

/* a finished job: install its sources (message domain, between DSP ticks,
 * so perform never sees a half-made set) */
static void fieldsound_tilde_install(t_fieldsound_tilde *x)
{
    field_job *j = x->x_job;
    char name[MAXPDSTRING];
    fieldsound_tilde_name(x, name, sizeof name);
    if (j->finished < 0) {
        pd_error(x, OBJ ": %s: %s", name, j->err);
    } else {
        aero_field_sources old = x->x_sources;
        x->x_sources = j->result;
        j->finished = 0; /* the sources are ours now */
        if (aero_field_render_set_sources(&x->x_render, &x->x_sources)) {
            pd_error(x, OBJ ": out of memory");
            aero_field_sources_free(&x->x_sources);
            aero_field_render_set_sources(&x->x_render, NULL);
        }
        aero_field_sources_free(&old);
        const aero_field_sources *s = &x->x_sources;
        post(OBJ ": %s: %d frames of %dx%dx%d preprocessed in %.3f s "
             "(%.2f ms per frame): %ld monopole, %ld dipole, %ld quadrupole "
             "source points, %d active vertices", name, j->info.frames,
             j->info.nx, j->info.ny, j->info.nz, j->seconds,
             1e3 * j->seconds / j->info.frames, s->points[1], s->points[2],
             s->points[3], s->count);
        t_atom a[2];
        SETFLOAT(a, (t_float)s->count);
        SETFLOAT(a + 1, (t_float)j->seconds);
        outlet_anything(x->x_info, gensym("ready"), 2, a);
        if (x->x_pending_play) {
            aero_field_render_play(&x->x_render);
            x->x_done = 0;
        }
    }
    x->x_pending_play = 0;
    if (x->x_thread_live)
        pthread_join(x->x_thread, NULL);
    x->x_thread_live = 0;
    job_free(j);
    x->x_job = NULL;
}

/* polls the worker: progress in the Pd window, then the swap */
static void fieldsound_tilde_poll(t_fieldsound_tilde *x)
{
    field_job *j = x->x_job;
    int finished, done, total;
    if (!j)
        return;
    pthread_mutex_lock(&j->lock);
    finished = j->finished;
    done = j->done_frames;
    total = j->total_frames;
    pthread_mutex_unlock(&j->lock);
    if (finished) {
        fieldsound_tilde_install(x);
        return;
    }
    if (total > 0) {
        int quarter = 4 * done / total;
        t_atom a;
        SETFLOAT(&a, (t_float)done / total);
        outlet_anything(x->x_info, gensym("progress"), 1, &a);
        if (quarter > x->x_reported_progress && quarter < 4) {
            char name[MAXPDSTRING];
            x->x_reported_progress = quarter;
            post(OBJ ": preprocessing %s: %d%% (%d of %d frames)",
                 fieldsound_tilde_name(x, name, sizeof name),
                 100 * done / total, done, total);
        }
    }
    clock_delay(x->x_poll, 50);
}

/* (re)starts preprocessing of the current volume with the current
 * parameters */
static void fieldsound_tilde_prepare(t_fieldsound_tilde *x)
{
    char err[512], name[MAXPDSTRING];
    fieldsound_tilde_cancel(x);
    if (!x->x_dir && x->x_demo_size <= 0)
        return;
    field_job *j = getbytes(sizeof *j);
    pthread_mutex_init(&j->lock, NULL);
    j->par = x->x_par;
    if (x->x_dir) {
        char dir[MAXPDSTRING], path[MAXPDSTRING], *base;
        const char *want = x->x_dir->s_name;
        snprintf(path, sizeof path, "%s/volume", want);
        int fd = canvas_open(x->x_canvas, path, ".txt", dir, &base,
                             MAXPDSTRING, 1);
        if (fd < 0) {
            pd_error(x, OBJ ": can't find volume '%s' (a directory with "
                     "volume.txt, next to the patch or on Pd's path)", want);
            job_free(j);
            return;
        }
        sys_close(fd);
        if (aero_volume_read_header(dir, &j->info, err, sizeof err)) {
            pd_error(x, OBJ ": %s", err);
            job_free(j);
            return;
        }
    } else {
        aero_field_demo_default(&j->demo);
        j->demo.size = x->x_demo_size;
        /* the same 1.28 m burst at any resolution */
        j->demo.spacing = 1.28 / x->x_demo_size;
        aero_field_demo_info(&j->demo, &j->info);
        j->use_demo = 1;
    }
    x->x_job = j;
    x->x_reported_progress = 0;
    post(OBJ ": preprocessing %s (%d frames of %dx%dx%d)%s",
         fieldsound_tilde_name(x, name, sizeof name), j->info.frames,
         j->info.nx, j->info.ny, j->info.nz,
         x->x_sync ? " in Pd's thread" : "");
    if (x->x_sync || pthread_create(&x->x_thread, NULL, job_thread, j)) {
        job_run(j);
        fieldsound_tilde_install(x);
        return;
    }
    x->x_thread_live = 1;
    clock_delay(x->x_poll, 20);
}

/* --- perform and its reports ----------------------------------------------- */

static void fieldsound_tilde_report(t_fieldsound_tilde *x)
{
    if (x->x_clamped && !x->x_warned_clamp) {
        pd_error(x, OBJ ": listener faster than Mach 0.3: its motion was "
                 "slowed down");
        x->x_warned_clamp = 1;
    }
    if (x->x_done) {
        x->x_done = 0;
        outlet_anything(x->x_info, gensym("done"), 0, NULL);
    }
}

static t_int *fieldsound_tilde_perform(t_int *w)
{
    t_fieldsound_tilde *x = (t_fieldsound_tilde *)(w[1]);
    t_sample *pd_out = (t_sample *)(w[2]);
    int n = (int)(w[3]);
    int playing = aero_field_render_process(
        &x->x_render, aero_pd_signal_out(&x->x_scratch, 1, pd_out), n);
    aero_pd_signal_done(&x->x_scratch, 1, pd_out);
    if ((x->x_was_playing && !playing && x->x_render.src) ||
        (x->x_render.clamped && !x->x_clamped)) {
        if (x->x_was_playing && !playing)
            x->x_done = 1;
        x->x_clamped = x->x_render.clamped;
        clock_delay(x->x_report, 0);
    }
    x->x_was_playing = playing;
    return w + 4;
}

static void fieldsound_tilde_dsp(t_fieldsound_tilde *x, t_signal **sp)
{
    if (aero_field_render_set_sample_rate(&x->x_render, sp[0]->s_sr))
        pd_error(x, OBJ ": bad sample rate %g", sp[0]->s_sr);
    if (aero_pd_scratch_prepare(&x->x_scratch, sp[0]->s_n)) {
        pd_error(x, OBJ ": out of memory: silent");
        dsp_add_zero(sp[0]->s_vec, sp[0]->s_n);
        return;
    }
    dsp_add(fieldsound_tilde_perform, 3, x, sp[0]->s_vec,
            (t_int)sp[0]->s_n);
}

/* --- messages -------------------------------------------------------------- */

static void fieldsound_tilde_open(t_fieldsound_tilde *x, t_symbol *dir)
{
    x->x_dir = dir;
    x->x_demo_size = 0;
    fieldsound_tilde_prepare(x);
}

static void fieldsound_tilde_demo(t_fieldsound_tilde *x, t_symbol *s,
                                  int argc, t_atom *argv)
{
    int size = 32;
    (void)s;
    if (argc >= 1) {
        if (argv[0].a_type != A_FLOAT ||
            aero_pd_whole(atom_getfloat(argv), 4, 128, &size)) {
            pd_error(x, OBJ ": demo size must be a whole number 4..128 "
                     "vertices, using 32");
            size = 32;
        }
    }
    x->x_dir = NULL;
    x->x_demo_size = size;
    fieldsound_tilde_prepare(x);
}

static void fieldsound_tilde_play(t_fieldsound_tilde *x)
{
    if (x->x_job) {
        x->x_pending_play = 1; /* as soon as it is ready */
        return;
    }
    if (!x->x_render.src) {
        pd_error(x, OBJ ": nothing to play (open a volume or 'demo')");
        return;
    }
    aero_field_render_play(&x->x_render);
}

static void fieldsound_tilde_stop(t_fieldsound_tilde *x)
{
    x->x_pending_play = 0;
    aero_field_render_stop(&x->x_render);
}

static void fieldsound_tilde_listener(t_fieldsound_tilde *x, t_symbol *s,
                                      int argc, t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_field_render_set_listener(&x->x_render, v[0], v[1], v[2]))
        pd_error(x, OBJ ": listener position must be finite, within 1e5 m");
}

static void fieldsound_tilde_speed(t_fieldsound_tilde *x, t_floatarg f)
{
    if (aero_field_render_set_speed(&x->x_render, f))
        pd_error(x, OBJ ": speed %g frames/s out of range (0..1e6]", f);
}

static void fieldsound_tilde_gain(t_fieldsound_tilde *x, t_floatarg f)
{
    if (aero_field_render_set_gain_db(&x->x_render, f))
        pd_error(x, OBJ ": gain %g dB out of range (-200..120)", f);
}

static void fieldsound_tilde_ramp(t_fieldsound_tilde *x, t_floatarg f)
{
    if (aero_field_render_set_ramp_ms(&x->x_render, f))
        pd_error(x, OBJ ": ramp %g ms out of range (0..600000)", f);
}

/* a changed parameter: check it, then preprocess again */
static void fieldsound_tilde_reparam(t_fieldsound_tilde *x,
                                     const aero_field_params *p)
{
    char err[256];
    if (aero_field_params_check(p, err, sizeof err)) {
        pd_error(x, OBJ ": %s: keeping the old setting", err);
        return;
    }
    x->x_par = *p;
    if (x->x_dir || x->x_demo_size > 0)
        fieldsound_tilde_prepare(x);
}

static void fieldsound_tilde_threshold(t_fieldsound_tilde *x, t_symbol *s,
                                       int argc, t_atom *argv)
{
    double v[3];
    aero_field_params p = x->x_par;
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    for (int t = 0; t < 3; t++)
        p.threshold[t] = v[t];
    fieldsound_tilde_reparam(x, &p);
}

static void fieldsound_tilde_map(t_fieldsound_tilde *x, t_symbol *s,
                                 int argc, t_atom *argv)
{
    double v[4];
    aero_field_params p = x->x_par;
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 4, v))
        return;
    p.in_lo = v[0], p.in_hi = v[1], p.rho_lo = v[2], p.rho_hi = v[3];
    fieldsound_tilde_reparam(x, &p);
}

static void fieldsound_tilde_zero(t_fieldsound_tilde *x, t_floatarg f)
{
    aero_field_params p = x->x_par;
    p.zero = f;
    fieldsound_tilde_reparam(x, &p);
}

static void fieldsound_tilde_vscale(t_fieldsound_tilde *x, t_floatarg f)
{
    aero_field_params p = x->x_par;
    p.vscale = f;
    fieldsound_tilde_reparam(x, &p);
}

static void fieldsound_tilde_log(t_fieldsound_tilde *x, t_floatarg f)
{
    aero_field_params p = x->x_par;
    p.log_input = f != 0;
    fieldsound_tilde_reparam(x, &p);
}

static void fieldsound_tilde_velocity(t_fieldsound_tilde *x, t_floatarg f)
{
    aero_field_params p = x->x_par;
    p.use_velocity = f != 0;
    fieldsound_tilde_reparam(x, &p);
}

/* --- creation --------------------------------------------------------- */

static int fieldsound_tilde_flag(void *obj, t_symbol *flag, int argc,
                                 t_atom *argv)
{
    t_fieldsound_tilde *x = obj;
    static const struct {
        const char *name;
        int count;
    } flags[] = {{"-listener", 3}, {"-speed", 1},  {"-gain", 1},
                 {"-ramp", 1},     {"-threshold", 3}, {"-map", 4},
                 {"-zero", 1},     {"-vscale", 1}, {"-log", 1},
                 {"-velocity", 1}, {"-demo", 1},   {"-sync", 0}};
    const char *f = flag->s_name;
    if (f[0] != '-')
        return 0;
    for (size_t k = 0; k < sizeof(flags) / sizeof(flags[0]); k++) {
        if (strcmp(f, flags[k].name))
            continue;
        int count = flags[k].count;
        if (argc < count) {
            pd_error(x, OBJ ": flag %s needs %d value(s)", f, count);
            return argc + 1;
        }
        for (int i = 0; i < count; i++)
            if (argv[i].a_type != A_FLOAT) {
                pd_error(x, OBJ ": flag %s needs numbers", f);
                return count + 1;
            }
        t_float v = count ? atom_getfloat(argv) : 0;
        t_symbol *name = gensym(f + 1);
        if (!strcmp(f, "-listener"))
            fieldsound_tilde_listener(x, name, 3, argv);
        else if (!strcmp(f, "-speed"))
            fieldsound_tilde_speed(x, v);
        else if (!strcmp(f, "-gain"))
            fieldsound_tilde_gain(x, v);
        else if (!strcmp(f, "-ramp"))
            fieldsound_tilde_ramp(x, v);
        else if (!strcmp(f, "-demo")) {
            if (aero_pd_whole(v, 4, 128, &x->x_demo_size)) {
                pd_error(x, OBJ ": demo size must be a whole number "
                         "4..128, using 32");
                x->x_demo_size = 32;
            }
        } else if (!strcmp(f, "-sync"))
            x->x_sync = 1;
        else {
            /* mapping flags: set without preprocessing (done once after
             * all flags are read) */
            aero_field_params p = x->x_par;
            char err[256];
            double d[4];
            for (int i = 0; i < count; i++)
                d[i] = atom_getfloat(argv + i);
            if (!strcmp(f, "-threshold"))
                p.threshold[0] = d[0], p.threshold[1] = d[1],
                p.threshold[2] = d[2];
            else if (!strcmp(f, "-map"))
                p.in_lo = d[0], p.in_hi = d[1], p.rho_lo = d[2],
                p.rho_hi = d[3];
            else if (!strcmp(f, "-zero"))
                p.zero = d[0];
            else if (!strcmp(f, "-vscale"))
                p.vscale = d[0];
            else if (!strcmp(f, "-log"))
                p.log_input = d[0] != 0;
            else if (!strcmp(f, "-velocity"))
                p.use_velocity = d[0] != 0;
            if (aero_field_params_check(&p, err, sizeof err))
                pd_error(x, OBJ ": %s: using the default", err);
            else
                x->x_par = p;
        }
        return count + 1;
    }
    return 0;
}

static void *fieldsound_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_fieldsound_tilde *x = (t_fieldsound_tilde *)pd_new(
        fieldsound_tilde_class);
    x->x_canvas = canvas_getcurrent();
    aero_field_params_default(&x->x_par);
    aero_field_render_init(&x->x_render, sys_getsr());
    aero_field_render_place_listener(&x->x_render, 1, 0, 0);
    x->x_poll = clock_new(x, (t_method)fieldsound_tilde_poll);
    x->x_report = clock_new(x, (t_method)fieldsound_tilde_report);
    x->x_out = outlet_new(&x->x_obj, &s_signal);
    x->x_info = outlet_new(&x->x_obj, 0);
    /* the volume directory is the first argument that is not a flag */
    if (argc > 0 && argv[0].a_type == A_SYMBOL &&
        argv[0].a_w.w_symbol->s_name[0] != '-') {
        x->x_dir = argv[0].a_w.w_symbol;
        argc--, argv++;
    }
    aero_pd_parse_flags(x, OBJ, "<volume dir> -listener -speed -gain -ramp "
                        "-threshold -map -zero -vscale -log -velocity -demo "
                        "-sync", fieldsound_tilde_flag, argc, argv);
    /* the listener starts where it was put, not ramped from (1, 0, 0) */
    aero_field_render_place_listener(&x->x_render, x->x_render.target[0],
                                     x->x_render.target[1],
                                     x->x_render.target[2]);
    if (x->x_dir)
        x->x_demo_size = 0;
    fieldsound_tilde_prepare(x);
    return x;
}

static void fieldsound_tilde_free(t_fieldsound_tilde *x)
{
    aero_pd_scratch_free(&x->x_scratch);
    fieldsound_tilde_cancel(x);
    clock_free(x->x_poll);
    clock_free(x->x_report);
    aero_field_render_free(&x->x_render);
    aero_field_sources_free(&x->x_sources);
    outlet_free(x->x_out);
    outlet_free(x->x_info);
}

void fieldsound_tilde_setup(void)
{
    fieldsound_tilde_class = class_new(
        gensym("fieldsound~"), (t_newmethod)(t_method)fieldsound_tilde_new,
        (t_method)fieldsound_tilde_free, sizeof(t_fieldsound_tilde),
        CLASS_DEFAULT, A_GIMME, 0);
    class_addmethod(fieldsound_tilde_class, (t_method)fieldsound_tilde_dsp,
                    gensym("dsp"), A_CANT, 0);
    static const struct {
        const char *name;
        t_method fn;
    } floats[] = {{"speed", (t_method)fieldsound_tilde_speed},
                  {"gain", (t_method)fieldsound_tilde_gain},
                  {"ramp", (t_method)fieldsound_tilde_ramp},
                  {"zero", (t_method)fieldsound_tilde_zero},
                  {"vscale", (t_method)fieldsound_tilde_vscale},
                  {"log", (t_method)fieldsound_tilde_log},
                  {"velocity", (t_method)fieldsound_tilde_velocity}};
    for (size_t k = 0; k < sizeof(floats) / sizeof(floats[0]); k++)
        class_addmethod(fieldsound_tilde_class, floats[k].fn,
                        gensym(floats[k].name), A_FLOAT, 0);
    class_addmethod(fieldsound_tilde_class,
                    (t_method)fieldsound_tilde_listener, gensym("listener"),
                    A_GIMME, 0);
    class_addmethod(fieldsound_tilde_class,
                    (t_method)fieldsound_tilde_threshold,
                    gensym("threshold"), A_GIMME, 0);
    class_addmethod(fieldsound_tilde_class, (t_method)fieldsound_tilde_map,
                    gensym("map"), A_GIMME, 0);
    class_addmethod(fieldsound_tilde_class, (t_method)fieldsound_tilde_open,
                    gensym("open"), A_SYMBOL, 0);
    class_addmethod(fieldsound_tilde_class, (t_method)fieldsound_tilde_demo,
                    gensym("demo"), A_GIMME, 0);
    class_addmethod(fieldsound_tilde_class, (t_method)fieldsound_tilde_play,
                    gensym("play"), 0);
    class_addmethod(fieldsound_tilde_class, (t_method)fieldsound_tilde_stop,
                    gensym("stop"), 0);
}
