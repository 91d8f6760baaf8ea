/* aerotex: the option tables (aerotex.h) turned into parsers, defaults and
 * usage text, so that a command states each option once. */
#include "aerotex.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define FIELD(job, o, type) ((type *)((char *)(job) + (o)->at))

int aerotex_number(const char *cmd, const char *opt, int argc, char **argv,
                   int *i, double lo, double hi, double *x)
{
    char *end;
    if (*i + 1 >= argc) {
        aerotex_error("%s: %s needs a value", cmd, opt);
        return -1;
    }
    (*i)++;
    *x = strtod(argv[*i], &end);
    if (end == argv[*i] || *end || !isfinite(*x)) {
        aerotex_error("%s: %s: '%s' is not a number", cmd, opt, argv[*i]);
        return -1;
    }
    if (*x < lo || *x > hi) {
        aerotex_error("%s: %s %g is out of range [%g, %g]", cmd, opt, *x, lo,
                      hi);
        return -1;
    }
    return 0;
}

/* "a|b|c" as "a, b or c" */
static void say_choices(char *buf, size_t len, const char *choices)
{
    const char *last = strrchr(choices, '|');
    size_t used = 0;
    buf[0] = 0;
    for (const char *p = choices; *p && used + 5 < len; p++) {
        if (*p != '|')
            buf[used++] = *p;
        else
            used += (size_t)snprintf(buf + used, len - used, "%s",
                                     p == last ? " or " : ", ");
    }
    buf[used < len ? used : len - 1] = 0;
}

/* the index of word among "a|b|c", or -1 */
static int choice_index(const char *choices, const char *word)
{
    size_t n = strlen(word);
    int k = 0;
    for (const char *p = choices; p; k++) {
        const char *bar = strchr(p, '|');
        size_t m = bar ? (size_t)(bar - p) : strlen(p);
        if (m == n && !strncmp(p, word, n))
            return k;
        p = bar ? bar + 1 : NULL;
    }
    return -1;
}

/* a whole number into the destination of o */
static int read_whole(const char *cmd, const aerotex_option *o, void *job,
                      int argc, char **argv, int *i)
{
    const int seed = o->kind == AEROTEX_SEED;
    double x;
    if (aerotex_number(cmd, o->name, argc, argv, i, seed ? 0.0 : o->lo,
                       seed ? 4294967295.0 : o->hi, &x))
        return -1;
    if (x != floor(x)) {
        aerotex_error("%s: %s takes a whole number", cmd, o->name);
        return -1;
    }
    if (seed)
        *FIELD(job, o, uint32_t) = (uint32_t)x;
    else
        *FIELD(job, o, int) = (int)x;
    return 0;
}

/* one option at argv[*i]: 0 or -1 */
static int read_option(const char *cmd, const aerotex_option *o, void *job,
                       int argc, char **argv, int *i)
{
    char list[256];
    double x;
    int k;
    switch (o->kind) {
    case AEROTEX_NUMBER:
        if (aerotex_number(cmd, o->name, argc, argv, i, o->lo, o->hi, &x))
            return -1;
        *FIELD(job, o, double) = x;
        return 0;
    case AEROTEX_POSITIVE:
        if (aerotex_number(cmd, o->name, argc, argv, i, -HUGE_VAL, o->hi, &x))
            return -1;
        if (!(x > 0.0)) {
            aerotex_error("%s: %s %g is out of range (0, %g]", cmd, o->name,
                          x, o->hi);
            return -1;
        }
        *FIELD(job, o, double) = x;
        return 0;
    case AEROTEX_WHOLE:
    case AEROTEX_SEED:
        return read_whole(cmd, o, job, argc, argv, i);
    case AEROTEX_TEXT:
        if (*i + 1 >= argc) {
            aerotex_error("%s: %s needs a value (%s)", cmd, o->name, o->value);
            return -1;
        }
        *FIELD(job, o, const char *) = argv[++*i];
        return 0;
    case AEROTEX_CHOICE:
        k = *i + 1 < argc ? choice_index(o->value, argv[*i + 1]) : -1;
        if (k < 0) {
            say_choices(list, sizeof list, o->value);
            aerotex_error("%s: %s takes %s, not '%s'", cmd, o->name, list,
                          *i + 1 < argc ? argv[*i + 1] : "");
            return -1;
        }
        *FIELD(job, o, int) = k;
        ++*i;
        return 0;
    case AEROTEX_SWITCH:
        *FIELD(job, o, int) = (int)o->lo;
        return 0;
    case AEROTEX_CUSTOM:
        return o->parse(job, cmd, argc, argv, i);
    }
    return -1;
}

void aerotex_defaults(const aerotex_command *cmd, void *job)
{
    memset(job, 0, cmd->job_size);
    for (const aerotex_option *o = cmd->options; o && o->name; o++) {
        if (isnan(o->def))
            continue;
        switch (o->kind) {
        case AEROTEX_NUMBER:
        case AEROTEX_POSITIVE:
            *FIELD(job, o, double) = o->def;
            break;
        case AEROTEX_SEED:
            *FIELD(job, o, uint32_t) = (uint32_t)o->def;
            break;
        case AEROTEX_WHOLE:
        case AEROTEX_CHOICE:
        case AEROTEX_SWITCH:
            *FIELD(job, o, int) = (int)o->def;
            break;
        default:
            break;
        }
    }
    if (cmd->init)
        cmd->init(job);
}

/* An output (-o FILE or DIR, --png DIR) is checked before any work: its
   folder must exist and be writable, so a typing error fails at once, not
   after a simulation of minutes. 0, or -1 reported. */
static int check_output(const char *cmd, const char *opt, const char *path)
{
    char dir[4096];
    struct stat st;
    size_t n = strlen(path);
    while (n > 1 && path[n - 1] == '/') /* "out/" is the folder out */
        n--;
    if (n >= sizeof(dir)) {
        aerotex_error("%s: %s: path too long", cmd, opt);
        return -1;
    }
    memcpy(dir, path, n);
    dir[n] = 0;
    char *slash = strrchr(dir, '/');
    if (!slash)
        strcpy(dir, ".");
    else if (slash == dir)
        dir[1] = 0;
    else
        *slash = 0;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        aerotex_error("%s: can't write '%s' (%s): the folder '%s' does not "
                      "exist", cmd, path, opt, dir);
        return -1;
    }
    if (access(dir, W_OK) != 0) {
        aerotex_error("%s: can't write '%s' (%s): the folder '%s' is not "
                      "writable", cmd, path, opt, dir);
        return -1;
    }
    return 0;
}

static int check_outputs(const aerotex_command *cmd, void *job)
{
    for (const aerotex_option *o = cmd->options; o && o->name; o++)
        if (o->kind == AEROTEX_TEXT &&
            (!strcmp(o->name, "-o") || !strcmp(o->name, "--png"))) {
            const char *path = *FIELD(job, o, const char *);
            if (path && check_output(cmd->name, o->name, path))
                return -1;
        }
    return 0;
}

int aerotex_parse(const aerotex_command *cmd, void *job, int argc,
                  char **argv)
{
    const aerotex_option *positional = NULL;
    for (const aerotex_option *o = cmd->options; o && o->name; o++)
        if (!o->name[0])
            positional = o;
    for (int i = 1; i < argc; i++) {
        const aerotex_option *o = cmd->options;
        while (o && o->name && (!o->name[0] || strcmp(o->name, argv[i])))
            o++;
        if (o && o->name) {
            if (read_option(cmd->name, o, job, argc, argv, &i))
                return -1;
        } else if (positional && argv[i][0] != '-') {
            if (positional->parse(job, cmd->name, argc, argv, &i))
                return -1;
        } else {
            aerotex_error("%s: unknown option '%s' (see 'aerotex help')",
                          cmd->name, argv[i]);
            return -1;
        }
    }
    return check_outputs(cmd, job);
}

/* " (default X)" for o, from the job after the defaults */
static void say_default(char *buf, size_t len, const aerotex_option *o,
                        const void *job)
{
    buf[0] = 0;
    if (o->shown) {
        if (o->shown[0])
            snprintf(buf, len, " (default %s)", o->shown);
        return;
    }
    switch (o->kind) {
    case AEROTEX_NUMBER:
    case AEROTEX_POSITIVE:
        snprintf(buf, len, " (default %g)", *FIELD(job, o, const double));
        break;
    case AEROTEX_WHOLE:
        snprintf(buf, len, " (default %d)", *FIELD(job, o, const int));
        break;
    case AEROTEX_SEED:
        snprintf(buf, len, " (default %u)",
                 (unsigned)*FIELD(job, o, const uint32_t));
        break;
    case AEROTEX_CHOICE: {
        /* the k-th choice */
        const char *p = o->value;
        for (int k = *FIELD(job, o, const int); k > 0 && p; k--) {
            p = strchr(p, '|');
            if (p) p++;
        }
        if (p)
            snprintf(buf, len, " (default %.*s)", (int)strcspn(p, "|"), p);
        break;
    }
    default:
        break;
    }
}

void aerotex_usage(FILE *f, const aerotex_command *cmd)
{
    void *job = cmd->job_size ? malloc(cmd->job_size) : NULL;
    if (job)
        aerotex_defaults(cmd, job);
    fprintf(f, "\n  aerotex %s %s\n", cmd->name, cmd->synopsis);
    for (const char *p = cmd->about; p && *p;) {
        size_t n = strcspn(p, "\n");
        fprintf(f, "      %.*s\n", (int)n, p);
        p += n + (p[n] == '\n');
    }
    for (const aerotex_option *o = cmd->options; job && o && o->name; o++) {
        char head[128], def[160];
        const char *p = o->help;
        if (!o->name[0] || !o->help)
            continue;
        if (o->value)
            snprintf(head, sizeof head, "%s <%s>", o->name, o->value);
        else
            snprintf(head, sizeof head, "%s", o->name);
        say_default(def, sizeof def, o, job);
        if (strlen(head) > 20) /* the help on the next line */
            fprintf(f, "      %s\n", head);
        for (int line = 0; *p || line == 0; line++) {
            size_t n = strcspn(p, "\n");
            int last = p[n] == 0, wrap = last && 27 + n + strlen(def) > 78;
            fprintf(f, "      %-20s %.*s%s\n",
                    line || strlen(head) > 20 ? "" : head, (int)n, p,
                    last && !wrap ? def : "");
            if (wrap && def[0])
                fprintf(f, "      %-20s%s\n", "", def);
            p += n + !last;
        }
    }
    free(job);
}
