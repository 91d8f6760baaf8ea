/* [fieldsound~]: field auralization of time-varying volume data (paper
 * 002) in real time. Thin Pd wrapper around src/core/play/fieldsound: the
 * volume is preprocessed in a worker thread (no Pd calls in it), the
 * sources are swapped in by a clock in Pd's thread, perform only renders.
 *
 *   [fieldsound~ <volume dir> -listener x y z -speed fps ...]
 *   [fieldsound~ -demo 32]  the synthetic burst (32^3), no files
 *   outlet 1 (signal): sound pressure at the listener, Pa
 *   outlet 2: progress <0..1>, ready <active vertices> <seconds>, done
 */
#include "aero_pd.h"
#include "s_stuff.h" /* audio_isopen */

#include "field_job.h"

static t_class *fieldsound_tilde_class;

#define OBJ "[fieldsound~]"

typedef struct _fieldsound_tilde {
    t_object x_obj;
    aero_pd_base x_base;           /* canvas and table; own outlets */
    aero_fieldsound x_core;
    aero_field_sources x_sources;  /* what x_core plays */
    aero_field_params x_par;
    int x_creating;                /* flags read: preprocess once, after */
    t_symbol *x_dir;               /* as given, or NULL for the demo */
    int x_demo_size;
    int x_sync, x_pending_play, x_reported_progress;
    aero_field_job *x_job;         /* preprocessing in a worker thread */
    aero_volume_info x_job_info;   /* what it preprocesses */
    int x_was_playing, x_clamped, x_warned_clamp, x_done;
    t_clock *x_poll, *x_report;
    t_outlet *x_out, *x_info;
} t_fieldsound_tilde;

/* stops a running job (waits for its current frame) */
static void fieldsound_tilde_cancel(t_fieldsound_tilde *x)
{
    aero_field_job_cancel(x->x_job);
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
    char name[MAXPDSTRING], err[512];
    aero_field_sources fresh;
    double seconds;
    const aero_volume_info *info = &x->x_job_info;
    fieldsound_tilde_name(x, name, sizeof name);
    int rc = aero_field_job_take(x->x_job, &fresh, &seconds, err, sizeof err);
    x->x_job = NULL;
    if (rc) {
        pd_error(x, OBJ ": %s: %s", name, err);
        x->x_pending_play = 0;
        return;
    }
    aero_field_sources old = x->x_sources;
    x->x_sources = fresh;
    if (aero_fieldsound_set_sources(&x->x_core, &x->x_sources)) {
        pd_error(x, OBJ ": out of memory");
        aero_field_sources_free(&x->x_sources);
        aero_fieldsound_set_sources(&x->x_core, NULL);
    }
    aero_field_sources_free(&old);
    const aero_field_sources *s = &x->x_sources;
    post(OBJ ": %s: %d frames of %dx%dx%d preprocessed in %.3f s "
         "(%.2f ms per frame): %ld monopole, %ld dipole, %ld quadrupole "
         "source points, %d active vertices", name, info->frames, info->nx,
         info->ny, info->nz, seconds, 1e3 * seconds / info->frames,
         s->points[1], s->points[2], s->points[3], s->count);
    t_atom a[2];
    SETFLOAT(a, (t_float)s->count);
    SETFLOAT(a + 1, (t_float)seconds);
    outlet_anything(x->x_info, gensym("ready"), 2, a);
    if (x->x_pending_play) {
        aero_fieldsound_play(&x->x_core);
        x->x_done = 0;
    }
    x->x_pending_play = 0;
}

/* polls the worker: progress in the Pd window, then the swap */
static void fieldsound_tilde_poll(t_fieldsound_tilde *x)
{
    int done, total;
    if (!x->x_job)
        return;
    if (aero_field_job_poll(x->x_job, &done, &total)) {
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
    aero_field_demo demo, *use_demo = NULL;
    aero_volume_info *info = &x->x_job_info;
    fieldsound_tilde_cancel(x);
    if (!x->x_dir && x->x_demo_size <= 0)
        return;
    if (x->x_dir) {
        char dir[MAXPDSTRING], path[MAXPDSTRING], *base;
        const char *want = x->x_dir->s_name;
        snprintf(path, sizeof path, "%s/volume", want);
        int fd = canvas_open(x->x_base.canvas, path, ".txt", dir, &base,
                             MAXPDSTRING, 1);
        if (fd < 0) {
            pd_error(x, OBJ ": can't find volume '%s' (a directory with "
                     "volume.txt, next to the patch or on Pd's path)", want);
            return;
        }
        sys_close(fd);
        if (aero_volume_read_header(dir, info, err, sizeof err)) {
            pd_error(x, OBJ ": %s", err);
            return;
        }
    } else {
        aero_field_demo_default(&demo);
        demo.size = x->x_demo_size;
        /* the same 1.28 m burst at any resolution */
        demo.spacing = 1.28 / x->x_demo_size;
        aero_field_demo_info(&demo, info);
        use_demo = &demo;
    }
    x->x_reported_progress = 0;
    /* -sync blocks Pd's thread: only without an audio device (batch
       renders, tests), where no one hears the wait; with audio running
       it would be a dropout of the whole Pd, so the worker prepares */
    int block = x->x_sync && !audio_isopen();
    post(OBJ ": preprocessing %s (%d frames of %dx%dx%d)%s",
         fieldsound_tilde_name(x, name, sizeof name), info->frames,
         info->nx, info->ny, info->nz,
         block ? " in Pd's thread"
               : x->x_sync ? " in a worker (-sync: audio is running)" : "");
    x->x_job = aero_field_job_start(info, use_demo, &x->x_par, !block);
    if (!x->x_job) {
        pd_error(x, OBJ ": out of memory");
        return;
    }
    int done, total;
    if (aero_field_job_poll(x->x_job, &done, &total))
        fieldsound_tilde_install(x);
    else
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

static int fieldsound_tilde_process(void *obj, const float *in,
                                    float *const *out, int n)
{
    t_fieldsound_tilde *x = obj;
    /* the near-field policy: reported once (the last block's record) */
    aero_pd_near(&x->x_base, &x->x_core.near);
    (void)in;
    int playing = aero_fieldsound_process(&x->x_core, out[0], n);
    if ((x->x_was_playing && !playing &&
         aero_fieldsound_has_sources(&x->x_core)) ||
        (aero_fieldsound_clamped(&x->x_core) && !x->x_clamped)) {
        if (x->x_was_playing && !playing)
            x->x_done = 1;
        x->x_clamped = aero_fieldsound_clamped(&x->x_core);
        clock_delay(x->x_report, 0);
    }
    x->x_was_playing = playing;
    return 0; /* its own report: the listener, not a flow, is too fast */
}

static void fieldsound_tilde_dsp(t_fieldsound_tilde *x, t_signal **sp)
{
    if (aero_fieldsound_set_sample_rate(&x->x_core, sp[0]->s_sr))
        aero_pd_rate_failed(&x->x_base, sp[0]->s_sr);
    aero_pd_dsp(&x->x_base, sp, 0, fieldsound_tilde_process);
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
    int size = AERO_FIELD_DEMO_SIZE_DEFAULT;
    (void)s;
    if (argc >= 1) {
        if (argv[0].a_type != A_FLOAT ||
            aero_pd_whole_of(&x->x_base, "demo", atom_getfloat(argv),
                             &size)) {
            /* the demo still runs, at its default size: not "flag -demo
               ignored" */
            const char *flag = x->x_base.flag;
            x->x_base.flag = NULL;
            aero_pd_refused(&x->x_base, "demo", atom_getfloat(argv));
            x->x_base.flag = flag;
            size = AERO_FIELD_DEMO_SIZE_DEFAULT;
        }
    }
    x->x_demo_size = size;
    if (x->x_creating) /* a volume folder given too wins */
        return;
    x->x_dir = NULL;
    fieldsound_tilde_prepare(x);
}

static void fieldsound_tilde_play(t_fieldsound_tilde *x)
{
    if (x->x_job) {
        x->x_pending_play = 1; /* as soon as it is ready */
        return;
    }
    if (!aero_fieldsound_has_sources(&x->x_core)) {
        pd_error(x, OBJ ": nothing to play (open a volume or 'demo')");
        return;
    }
    aero_fieldsound_play(&x->x_core);
}

static void fieldsound_tilde_stop(t_fieldsound_tilde *x)
{
    x->x_pending_play = 0;
    aero_fieldsound_stop(&x->x_core);
}

static void fieldsound_tilde_listener(t_fieldsound_tilde *x, t_symbol *s,
                                      int argc, t_atom *argv)
{
    aero_ears e;
    if (aero_pd_ears(&x->x_base, s, argc, argv, &e) &&
        aero_fieldsound_set_ears(&x->x_core, &e))
        aero_pd_bad_ears(&x->x_base, e.n);
}

AERO_PD_SETTER(fieldsound_tilde, t_fieldsound_tilde, speed, x_core,
               aero_fieldsound_set_speed)
AERO_PD_SETTER(fieldsound_tilde, t_fieldsound_tilde, gain, x_core,
               aero_fieldsound_set_gain_db)
AERO_PD_SETTER(fieldsound_tilde, t_fieldsound_tilde, ramp, x_core,
               aero_fieldsound_set_ramp_ms)

/* A volume parameter set (the core's setter accepted it): preprocess
   again. The setters below take the object itself (its first member, as
   Pd hands it) for AERO_PD_SETTER, and refuse with the params unchanged. */
static int fieldsound_tilde_reparam(t_fieldsound_tilde *x, int rc)
{
    if (!rc && !x->x_creating && (x->x_dir || x->x_demo_size > 0))
        fieldsound_tilde_prepare(x);
    return rc;
}

#define FIELDSOUND_PARAM(msg, type, setter)                                \
    static int fieldsound_tilde_set_##msg(t_object *o, type v)             \
    {                                                                      \
        t_fieldsound_tilde *x = (t_fieldsound_tilde *)o;                   \
        return fieldsound_tilde_reparam(x, setter(&x->x_par, v));          \
    }
FIELDSOUND_PARAM(zero, double, aero_field_params_set_zero)
FIELDSOUND_PARAM(vscale, double, aero_field_params_set_vscale)
FIELDSOUND_PARAM(log, int, aero_field_params_set_log)
FIELDSOUND_PARAM(velocity, int, aero_field_params_set_velocity)

AERO_PD_SETTER(fieldsound_tilde, t_fieldsound_tilde, zero, x_obj,
               fieldsound_tilde_set_zero)
AERO_PD_SETTER(fieldsound_tilde, t_fieldsound_tilde, vscale, x_obj,
               fieldsound_tilde_set_vscale)
AERO_PD_SETTER_WHOLE(fieldsound_tilde, t_fieldsound_tilde, log, x_obj,
                     fieldsound_tilde_set_log)
AERO_PD_SETTER_WHOLE(fieldsound_tilde, t_fieldsound_tilde, velocity, x_obj,
                     fieldsound_tilde_set_velocity)

static void fieldsound_tilde_threshold(t_fieldsound_tilde *x, t_symbol *s,
                                       int argc, t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (fieldsound_tilde_reparam(
            x, aero_field_params_set_threshold(&x->x_par, v)))
        aero_pd_refused_list(&x->x_base, "threshold");
}

static void fieldsound_tilde_map(t_fieldsound_tilde *x, t_symbol *s,
                                 int argc, t_atom *argv)
{
    double v[4];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 4, v))
        return;
    if (fieldsound_tilde_reparam(
            x, aero_field_params_set_map(&x->x_par, v[0], v[1], v[2], v[3])))
        aero_pd_refused_list(&x->x_base, "map");
}

/* --- creation --------------------------------------------------------- */

static const aero_pd_method fieldsound_tilde_methods[] = {
    {"sync", AERO_PD_SWITCH, 0, NULL, 0, AERO_PD_NO_RULE},
    {"listener", AERO_PD_LIST, 3, (t_method)fieldsound_tilde_listener, 0,
     AERO_PD_NO_RULE},
    {"speed", AERO_PD_FLOAT, 0, (t_method)fieldsound_tilde_speed, 0,
     AERO_PD_RANGE(AERO_FIELD_SPEED_MIN, AERO_FIELD_SPEED_MAX, "frames/s")},
    {"gain", AERO_PD_FLOAT, 0, (t_method)fieldsound_tilde_gain, 0,
     AERO_PD_GAIN},
    {"ramp", AERO_PD_FLOAT, 0, (t_method)fieldsound_tilde_ramp, 0,
     AERO_PD_RAMP},
    /* the volume's parameters (field_prepare.h), each preprocessed again */
    {"threshold", AERO_PD_LIST, 3, (t_method)fieldsound_tilde_threshold, 0,
     AERO_PD_RANGE_NOTE(AERO_FIELD_THRESHOLD_MIN, AERO_FIELD_THRESHOLD_MAX,
                        NULL, "monopole kg/m^3/s, dipole and quadrupole "
                        "kg/m^3/s^2, each above the minimum")},
    {"map", AERO_PD_LIST, 4, (t_method)fieldsound_tilde_map, 0,
     AERO_PD_RANGE_NOTE(AERO_FIELD_RHO_MIN, AERO_FIELD_RHO_MAX, "kg/m^3",
                        "in_lo in_hi rho_lo rho_hi: a finite input range, "
                        "not empty, to densities in this range")},
    {"zero", AERO_PD_FLOAT, 0, (t_method)fieldsound_tilde_zero, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_FIELD_ZERO_MIN, AERO_FIELD_ZERO_MAX,
                            AERO_FIELD_ZERO_DEFAULT, NULL,
                            "of each threshold")},
    {"vscale", AERO_PD_FLOAT, 0, (t_method)fieldsound_tilde_vscale, 0,
     AERO_PD_RANGE_DEF(-AERO_FIELD_VSCALE_MAX, AERO_FIELD_VSCALE_MAX,
                       AERO_FIELD_VSCALE_DEFAULT, "m/s per kg/m^4")},
    {"log", AERO_PD_FLOAT, 0, (t_method)fieldsound_tilde_log, 0,
     AERO_PD_ON_OFF(AERO_FIELD_LOG_DEFAULT)},
    {"velocity", AERO_PD_FLOAT, 0, (t_method)fieldsound_tilde_velocity, 0,
     AERO_PD_ON_OFF(AERO_FIELD_VELOCITY_DEFAULT)},
    {"demo", AERO_PD_LIST, 1, (t_method)fieldsound_tilde_demo, 0,
     AERO_PD_RANGE_NOTE(AERO_FIELD_DEMO_SIZE_MIN, AERO_FIELD_DEMO_SIZE_MAX,
                        "vertices", "a whole number; the demo runs at "
                        AERO_PD_STR(AERO_FIELD_DEMO_SIZE_DEFAULT)
                        " vertices")},
    {"open", AERO_PD_SYMBOL, 0, (t_method)fieldsound_tilde_open,
     AERO_PD_MESSAGE_ONLY, AERO_PD_NO_RULE},
    {"play", AERO_PD_BANG, 0, (t_method)fieldsound_tilde_play,
     AERO_PD_MESSAGE_ONLY, AERO_PD_NO_RULE},
    {"stop", AERO_PD_BANG, 0, (t_method)fieldsound_tilde_stop,
     AERO_PD_MESSAGE_ONLY, AERO_PD_NO_RULE},
};

static const aero_pd_spec fieldsound_tilde_spec = {
    "fieldsound~", fieldsound_tilde_methods,
    AERO_PD_COUNT(fieldsound_tilde_methods), "<volume dir>"};

static void *fieldsound_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_fieldsound_tilde *x = (t_fieldsound_tilde *)pd_new(
        fieldsound_tilde_class);
    aero_pd_base_init(&x->x_base, x, &fieldsound_tilde_spec, argc, argv);
    /* no flow to clamp (the listener's speed and `done` are x_report's);
       the base's clock stays for the output guard's report */
    aero_field_params_default(&x->x_par);
    if (aero_fieldsound_init(&x->x_core, sys_getsr(), 1,
                             aero_pd_default_seed()))
        aero_pd_init_failed(&x->x_base, sys_getsr());
    aero_ears start = aero_ears_at(1, 0, 0);
    aero_fieldsound_place_ears(&x->x_core, &start);
    x->x_poll = clock_new(x, (t_method)fieldsound_tilde_poll);
    x->x_report = clock_new(x, (t_method)fieldsound_tilde_report);
    x->x_out = outlet_new(&x->x_obj, &s_signal);
    x->x_info = outlet_new(&x->x_obj, 0);
    /* the volume directory is the first argument that is not a flag */
    x->x_dir = aero_pd_first_symbol(&argc, &argv);
    x->x_sync = aero_pd_has_flag("-sync", argc, argv);
    x->x_creating = 1;
    aero_pd_parse_flags(&x->x_base, argc, argv);
    x->x_creating = 0;
    /* the listener starts where it was put, not ramped from (1, 0, 0) */
    memcpy(start.pos[0], aero_fieldsound_target(&x->x_core),
           sizeof start.pos[0]);
    aero_fieldsound_place_ears(&x->x_core, &start);
    if (x->x_dir)
        x->x_demo_size = 0;
    fieldsound_tilde_prepare(x);
    return x;
}

static void fieldsound_tilde_free(t_fieldsound_tilde *x)
{
    fieldsound_tilde_cancel(x);
    aero_pd_base_free(&x->x_base);
    clock_free(x->x_poll);
    clock_free(x->x_report);
    aero_fieldsound_free(&x->x_core);
    aero_field_sources_free(&x->x_sources);
    outlet_free(x->x_out);
    outlet_free(x->x_info);
}

AERO_PD_EXPORT void fieldsound_tilde_setup(void)
{
    fieldsound_tilde_class = aero_pd_class_new(
        &fieldsound_tilde_spec, (t_newmethod)(t_method)fieldsound_tilde_new,
        (t_method)fieldsound_tilde_free, sizeof(t_fieldsound_tilde), -1,
        (t_method)fieldsound_tilde_dsp);
}
