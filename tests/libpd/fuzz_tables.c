/* aero-libpd-fuzz: hostile patches for one aero object, made from the
 * object's own method table (aero_pd_spec in src/pd/NAME~.c), driven
 * through Pd's parsing layer inside libpd: the creation flags go through
 * [NAME~ ...] as a patch would write them (aero_pd_parse_flags), the
 * messages through pd_typedmess as a message box sends them (Pd's own
 * argument checks, then the wrapper's). Values are hostile: NaN,
 * infinities, huge, negative, fractions where whole numbers are due,
 * symbols where numbers are, lists too short or too long, empty symbols,
 * unknown flags and selectors. After every message the object renders
 * blocks of a speed signal (itself sometimes NaN or huge); every output
 * sample must be finite, and nothing may crash.
 *
 * Built once per object by tests/libpd/run.sh with the wrapper included
 * (so its table, class and setup are at hand) and ASan/UBSan:
 *   cc -DAERO_FUZZ_WRAPPER='"cavity~.c"' -DAERO_FUZZ_NAME=cavity ...
 *
 *   aero-libpd-fuzz-NAME [-cases N] [-seed S] [-data DIR] [-patch DIR]
 *                        [CORPUS...]
 *
 * -data DIR: aero's data folder (textures/, trees/; default .), -patch
 * DIR: where fuzz-empty.pd is (default tests/libpd), -control 1: the
 * negative control, a [sig~] of NaN joins the output in the first case
 * that creates the object
 * (the run must then fail).
 *
 * First every line of each CORPUS file that names this object is
 * replayed, then N random cases from seed S (deterministic). A line is
 *   NAME~ creation atoms... ; selector atoms... ; selector atoms...
 * where a token strtod reads whole is a number ("nan", "inf", "1e39"
 * included), "" the empty symbol, anything else a symbol. Every case is
 * printed in that form before it runs, so the last line printed is the one
 * to add to the corpus when a case fails. Exit 0, or 1 at the first
 * non-finite sample (a crash ends the program). */
#include "z_libpd.h"
#include "m_imp.h" /* obj_nsiginlets, obj_nsigoutlets */
#include "aero.h"

#include AERO_FUZZ_WRAPPER /* its table, class and setup */

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FUZZ_CAT2(a, b) a##b
#define FUZZ_CAT(a, b) FUZZ_CAT2(a, b)
#define FUZZ_SPEC FUZZ_CAT(AERO_FUZZ_NAME, _tilde_spec)
#define FUZZ_SETUP FUZZ_CAT(AERO_FUZZ_NAME, _tilde_setup)
#define FUZZ_CLASS FUZZ_CAT(AERO_FUZZ_NAME, _tilde_class)

#define RATE 48000
#define MAX_ATOMS 64
#define MAX_MESSAGES 16

/* one case: the creation atoms and the messages after it */
typedef struct {
    int nnew;
    t_atom create[MAX_ATOMS];
    int nmsg;
    t_symbol *sel[MAX_MESSAGES];
    int nargs[MAX_MESSAGES];
    t_atom args[MAX_MESSAGES][MAX_ATOMS];
} fuzz_case;

typedef struct {
    t_canvas *canvas;
    uint32_t rng;
    long blocks, messages, created;
    int control; /* the negative control: a NaN in the output, once */
} fuzz_run;

/* what Pd printed: the wrapper's errors ("[NAME~]: ..."), those of Pd's
   own argument checks */
typedef struct {
    long object, pd;
} fuzz_log;

/* the print hook has no context pointer: the one count of this program */
static fuzz_log printed;

static void count_print(const char *s)
{
    char wrapper[MAXPDSTRING];
    snprintf(wrapper, sizeof wrapper, "[%s]", FUZZ_SPEC.name);
    if (strstr(s, "no method") || strstr(s, "Bad arguments"))
        printed.pd++;
    else if (strstr(s, wrapper))
        printed.object++;
}

static uint32_t next(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *s = x;
}

static int pick(fuzz_run *r, int n)
{
    return n > 0 ? (int)(next(&r->rng) % (uint32_t)n) : 0;
}

/* SETFLOAT and SETSYMBOL name their atom twice: these once */
static void set_float(t_atom *a, t_float f)
{
    SETFLOAT(a, f);
}

static void set_symbol(t_atom *a, t_symbol *s)
{
    SETSYMBOL(a, s);
}

/* --- hostile values -------------------------------------------------------- */

static t_float hostile_float(fuzz_run *r)
{
    static const double pool[] = {
        0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 3.0, 10.0, 440.0, 44100.0, -5.0,
        1e-30, -1e-30, 1e-45, 1e6, 1e10, -1e10, 1e30, -1e30, FLT_MAX,
        -FLT_MAX, 2147483648.0, -2147483649.0, 4294967296.0, 9.3e18,
        0.999999, 1.000001};
    switch (pick(r, 8)) {
    case 0: return (t_float)NAN;
    case 1: return (t_float)(pick(r, 2) ? INFINITY : -INFINITY);
    case 2: return (t_float)(pick(r, 2001) - 1000) / 10; /* -100..100 */
    case 3: return (t_float)pick(r, 16);
    default: return (t_float)pool[pick(r, (int)(sizeof pool / sizeof *pool))];
    }
}

static t_symbol *hostile_symbol(fuzz_run *r)
{
    static const char *const pool[] = {
        "", "-", "--", "nan", "inf", "-1", "cylinder", "cavity", "sphere",
        "club", "fire", "square", "sword", "small", "medium", "nope",
        "no/such/file", "../../../../etc/passwd", "%s%s%n", "$1",
        "trees/small", "tests/data/leafwave-bad.tree", "-stereo", "demo",
        "listener", "ears"};
    if (!pick(r, 20)) {
        char buf[1200];
        memset(buf, 'x', sizeof buf - 1);
        buf[sizeof buf - 1] = 0;
        return gensym(buf);
    }
    if (!pick(r, 3)) { /* one of the table's names, as a value */
        char buf[MAXPDSTRING];
        snprintf(buf, sizeof buf, "%s%s", pick(r, 2) ? "-" : "",
                 FUZZ_SPEC.methods[pick(r, FUZZ_SPEC.count)].name);
        return gensym(buf);
    }
    return gensym(pool[pick(r, (int)(sizeof pool / sizeof *pool))]);
}

/* the atoms a table entry takes, mostly of the right type, then spoiled:
   a symbol for a number, one atom short, a few too many */
static int hostile_args(fuzz_run *r, const aero_pd_method *m, t_atom *a,
                        int room)
{
    int want = m->args == AERO_PD_FLOAT || m->args == AERO_PD_SYMBOL ? 1
        : m->args == AERO_PD_LIST ? m->count : 0;
    int n = want, spoil = pick(r, 6);
    if (m->args == AERO_PD_LIST && want == 0) /* any length */
        n = pick(r, 9);
    else if (spoil == 0 && n > 0)
        n--;
    else if (spoil == 1)
        n += 1 + pick(r, 4);
    if (n > room)
        n = room;
    for (int i = 0; i < n; i++) {
        int symbol = m->args == AERO_PD_SYMBOL ? pick(r, 8) != 0
                                                : pick(r, 10) == 0;
        if (symbol)
            SETSYMBOL(a + i, hostile_symbol(r));
        else
            SETFLOAT(a + i, hostile_float(r));
    }
    return n;
}

/* --- cases ------------------------------------------------------------------ */

static int flag_entry(const aero_pd_method *m)
{
    return !(m->options & AERO_PD_MESSAGE_ONLY);
}

static void random_case(fuzz_run *r, fuzz_case *c)
{
    const aero_pd_spec *spec = &FUZZ_SPEC;
    int nflags = pick(r, 5);
    c->nnew = 0;
    if (spec->first && pick(r, 3)) /* the leading file argument */
        set_symbol(c->create + c->nnew++, hostile_symbol(r));
    for (int f = 0; f < nflags && c->nnew < MAX_ATOMS - 8; f++) {
        const aero_pd_method *m = spec->methods + pick(r, spec->count);
        char flag[MAXPDSTRING];
        if (!pick(r, 8)) { /* garbage where a flag is due */
            if (pick(r, 2))
                set_float(c->create + c->nnew++, hostile_float(r));
            else
                set_symbol(c->create + c->nnew++, hostile_symbol(r));
            continue;
        }
        if (!flag_entry(m))
            continue;
        snprintf(flag, sizeof flag, "-%s", m->name);
        set_symbol(c->create + c->nnew++, gensym(flag));
        c->nnew += hostile_args(r, m, c->create + c->nnew,
                                MAX_ATOMS - c->nnew);
    }
    c->nmsg = 1 + pick(r, MAX_MESSAGES - 1);
    for (int k = 0; k < c->nmsg; k++) {
        const aero_pd_method *m = spec->methods + pick(r, spec->count);
        switch (pick(r, 12)) {
        case 0: /* what a patch sends to any inlet */
            c->sel[k] = pick(r, 2) ? &s_float : &s_list;
            c->nargs[k] = pick(r, 4);
            for (int i = 0; i < c->nargs[k]; i++)
                SETFLOAT(c->args[k] + i, hostile_float(r));
            continue;
        case 1:
            c->sel[k] = pick(r, 2) ? &s_bang : &s_symbol;
            c->nargs[k] = 0;
            continue;
        case 2: /* a selector the object does not know */
            c->sel[k] = hostile_symbol(r);
            c->nargs[k] = pick(r, 3);
            for (int i = 0; i < c->nargs[k]; i++)
                SETFLOAT(c->args[k] + i, hostile_float(r));
            continue;
        default:
            break;
        }
        /* a SWITCH is a flag only: sent as a message it has no method */
        c->sel[k] = gensym(m->name);
        c->nargs[k] = hostile_args(r, m, c->args[k], MAX_ATOMS);
    }
}

static void print_atoms(FILE *f, const t_atom *a, int n)
{
    for (int i = 0; i < n; i++) {
        if (a[i].a_type == A_FLOAT)
            fprintf(f, " %.9g", (double)a[i].a_w.w_float);
        else if (!a[i].a_w.w_symbol->s_name[0])
            fprintf(f, " \"\"");
        else
            fprintf(f, " %s", a[i].a_w.w_symbol->s_name);
    }
}

static void print_case(FILE *f, const fuzz_case *c)
{
    fprintf(f, "%s", FUZZ_SPEC.name);
    print_atoms(f, c->create, c->nnew);
    for (int k = 0; k < c->nmsg; k++) {
        fprintf(f, " ; %s", c->sel[k]->s_name);
        print_atoms(f, c->args[k], c->nargs[k]);
    }
    fputc('\n', f);
    fflush(f);
}

/* a corpus line into c: 1 when it is for this object */
static int parse_case(char *line, fuzz_case *c)
{
    char *tok = strtok(line, " \t\r\n");
    int msg = -1;
    if (!tok || strcmp(tok, FUZZ_SPEC.name))
        return 0;
    c->nnew = c->nmsg = 0;
    while ((tok = strtok(NULL, " \t\r\n"))) {
        t_atom *a;
        char *end;
        double v;
        if (!strcmp(tok, ";")) {
            if (c->nmsg == MAX_MESSAGES)
                break;
            msg = c->nmsg++;
            c->sel[msg] = NULL;
            c->nargs[msg] = 0;
            continue;
        }
        if (msg >= 0 && !c->sel[msg]) {
            c->sel[msg] = gensym(tok);
            continue;
        }
        if (msg < 0 ? c->nnew == MAX_ATOMS : c->nargs[msg] == MAX_ATOMS)
            continue;
        a = msg < 0 ? c->create + c->nnew++ : c->args[msg] + c->nargs[msg]++;
        v = strtod(tok, &end);
        if (end != tok && !*end)
            SETFLOAT(a, (t_float)v);
        else
            SETSYMBOL(a, gensym(strcmp(tok, "\"\"") ? tok : ""));
    }
    for (int k = 0; k < c->nmsg; k++)
        if (!c->sel[k])
            c->sel[k] = &s_bang;
    return 1;
}

/* --- running a case ------------------------------------------------------- */

static t_gobj *last_object(t_canvas *canvas)
{
    t_gobj *g = canvas->gl_list;
    while (g && g->g_next)
        g = g->g_next;
    return g;
}

/* deletes what a case added after [adc~ 1] and [dac~ 1 2] */
static void clear_case(t_canvas *canvas)
{
    t_gobj *g;
    while ((g = canvas->gl_list) && g->g_next && g->g_next->g_next)
        glist_delete(canvas, last_object(canvas));
}

static void send_to(t_pd *to, const char *sel, int argc, t_atom *argv)
{
    pd_typedmess(to, gensym(sel), argc, argv);
}

/* `blocks` blocks of a speed signal: mostly a wind, sometimes hostile;
   0 when every output sample is finite */
static int render(fuzz_run *r, int blocks)
{
    float in[64], out[128];
    const int n = libpd_blocksize();
    for (int b = 0; b < blocks; b++) {
        int hostile = !pick(r, 6);
        for (int i = 0; i < n; i++)
            in[i] = hostile ? (float)hostile_float(r)
                            : (float)(pick(r, 400) / 10.0);
        libpd_process_float(1, in, out);
        r->blocks++;
        for (int i = 0; i < 2 * n; i++)
            if (!isfinite(out[i])) {
                fprintf(stderr, "FAIL %s: output sample %g (block %ld)\n",
                        FUZZ_SPEC.name, out[i], r->blocks);
                return -1;
            }
    }
    return 0;
}

/* the negative control: a [sig~] holding NaN, into the [dac~] */
static void control_nan(fuzz_run *r)
{
    t_atom a[4];
    t_gobj *g;
    SETFLOAT(a, 200), SETFLOAT(a + 1, 60), SETSYMBOL(a + 2, gensym("sig~"));
    send_to(&r->canvas->gl_pd, "obj", 3, a);
    g = last_object(r->canvas);
    SETFLOAT(a, 3), SETFLOAT(a + 1, 0), SETFLOAT(a + 2, 1);
    SETFLOAT(a + 3, 0);
    send_to(&r->canvas->gl_pd, "connect", 4, a);
    pd_float(&g->g_pd, (t_float)NAN);
    r->control = 0;
}

/* creates the object in the canvas beside [adc~ 1] and [dac~ 1 2], sends
   the messages with blocks rendered after each, deletes it: 0 or -1 */
static int run_case(fuzz_run *r, fuzz_case *c)
{
    t_atom obj[MAX_ATOMS + 3], link[4];
    t_gobj *g;
    t_object *ob;
    int status = 0;
    SETFLOAT(obj, 10);
    SETFLOAT(obj + 1, 60);
    SETSYMBOL(obj + 2, gensym(FUZZ_SPEC.name));
    memcpy(obj + 3, c->create, sizeof(t_atom) * (size_t)c->nnew);
    send_to(&r->canvas->gl_pd, "obj", 3 + c->nnew, obj);
    g = last_object(r->canvas);
    if (!g || *(t_pd *)g != FUZZ_CLASS) /* not created: a broken box */
        goto done;
    ob = pd_checkobject(&g->g_pd);
    r->created++;
    /* [adc~ 1] is object 0, [dac~ 1 2] object 1, this one object 2 */
    if (obj_nsiginlets(ob) > 0) {
        SETFLOAT(link, 0), SETFLOAT(link + 1, 0);
        SETFLOAT(link + 2, 2), SETFLOAT(link + 3, 0);
        send_to(&r->canvas->gl_pd, "connect", 4, link);
    }
    for (int o = 0; o < obj_nsigoutlets(ob) && o < 2; o++) {
        SETFLOAT(link, 2), SETFLOAT(link + 1, o);
        SETFLOAT(link + 2, 1), SETFLOAT(link + 3, o);
        send_to(&r->canvas->gl_pd, "connect", 4, link);
    }
    status = render(r, 2);
    for (int k = 0; k < c->nmsg && !status; k++) {
        pd_typedmess(&g->g_pd, c->sel[k], c->nargs[k], c->args[k]);
        r->messages++;
        if (r->control && k == c->nmsg / 2)
            control_nan(r);
        status = render(r, 1 + pick(r, 3));
    }
done:
    clear_case(r->canvas);
    return status;
}

int main(int argc, char **argv)
{
    const char *data = ".", *patch_dir = "tests/libpd";
    long cases = 100;
    fuzz_run r = {0};
    fuzz_case *c = malloc(sizeof *c);
    int i = 1, replayed = 0;
    uint32_t seed = 1;
    for (; i + 1 < argc && argv[i][0] == '-'; i += 2) {
        if (!strcmp(argv[i], "-cases"))
            cases = atol(argv[i + 1]);
        else if (!strcmp(argv[i], "-seed"))
            seed = (uint32_t)strtoul(argv[i + 1], NULL, 10);
        else if (!strcmp(argv[i], "-data"))
            data = argv[i + 1];
        else if (!strcmp(argv[i], "-patch"))
            patch_dir = argv[i + 1];
        else if (!strcmp(argv[i], "-control"))
            r.control = atoi(argv[i + 1]);
        else
            break;
    }
    if (!c || cases < 0) {
        fprintf(stderr, "usage: %s [-cases N] [-seed S] [-data DIR] "
                        "[-patch DIR] [CORPUS...]\n", argv[0]);
        return 2;
    }
    r.rng = seed ? seed : 1;
    libpd_set_printhook(count_print);
    libpd_init();
    FUZZ_SETUP();
    aero_set_data_path(data);
    libpd_add_to_search_path(data);
    libpd_init_audio(1, 2, RATE);
    /* an empty patch, then [adc~ 1] and [dac~ 1 2] in it */
    r.canvas = (t_canvas *)libpd_openfile("fuzz-empty.pd", patch_dir);
    if (!r.canvas) {
        fprintf(stderr, "%s: can't open %s/fuzz-empty.pd\n", argv[0],
                patch_dir);
        free(c);
        return 2;
    }
    {
        t_atom adc[4], dac[5];
        SETFLOAT(adc, 10), SETFLOAT(adc + 1, 10);
        SETSYMBOL(adc + 2, gensym("adc~")), SETFLOAT(adc + 3, 1);
        send_to(&r.canvas->gl_pd, "obj", 4, adc);
        SETFLOAT(dac, 10), SETFLOAT(dac + 1, 110);
        SETSYMBOL(dac + 2, gensym("dac~")), SETFLOAT(dac + 3, 1);
        SETFLOAT(dac + 4, 2);
        send_to(&r.canvas->gl_pd, "obj", 5, dac);
    }
    libpd_start_message(1);
    libpd_add_float(1.0f);
    libpd_finish_message("pd", "dsp");
    for (; i < argc; i++) { /* the corpus */
        FILE *f = fopen(argv[i], "r");
        char line[8192];
        if (!f) {
            fprintf(stderr, "%s: can't read %s\n", argv[0], argv[i]);
            free(c);
            return 2;
        }
        while (fgets(line, sizeof line, f)) {
            if (line[0] == '#' || !parse_case(line, c))
                continue;
            print_case(stdout, c);
            if (run_case(&r, c)) {
                free(c);
                return 1;
            }
            replayed++;
        }
        fclose(f);
    }
    for (long k = 0; k < cases; k++) {
        random_case(&r, c);
        print_case(stdout, c);
        if (run_case(&r, c)) {
            free(c);
            return 1;
        }
    }
    printf("%s: %d corpus and %ld random cases (seed %u): %ld created, "
           "%ld messages, %ld errors from the wrapper and %ld from Pd, "
           "%ld blocks, every sample finite\n",
           FUZZ_SPEC.name, replayed, cases, (unsigned)seed, r.created,
           r.messages, printed.object, printed.pd, r.blocks);
    free(c);
    return 0;
}
