/* aerotex: sound textures of moving air from a 2D flow solver.
 * Dobashi et al. 2003: the sound source function g = dF/dt of
 * an object is precomputed by fluid simulation and stored as a texture;
 * real-time objects only read it. See textures/README.md. */
#include "aerotex.h"
#include "texture.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void aerotex_error(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "aerotex: ");
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\n");
}

static const aerotex_command *const commands[] = {
    &aerotex_aeolian_command, &aerotex_cavity_command,
    &aerotex_vortex_command, &aerotex_object_command, &aerotex_info_command,
    &aerotex_tree_command, &aerotex_field_demo_command,
    &aerotex_auralize_command, &aerotex_airfoil_command};
#define NCOMMANDS (int)(sizeof commands / sizeof commands[0])

/* the commands whose directions, sections or speeds are spread over the
   ranks of a task farm */
static int farmed(const aerotex_command *c)
{
    return c == &aerotex_aeolian_command || c == &aerotex_cavity_command ||
           c == &aerotex_vortex_command || c == &aerotex_object_command;
}

static void usage(FILE *f)
{
    fprintf(f, "usage: aerotex <command> [options]\n");
    for (int k = 0; k < NCOMMANDS; k++)
        aerotex_usage(f, commands[k]);
    fprintf(f, "\n  aerotex help\n      this text\n");
}

static int aerotex_info(int argc, char **argv)
{
    aero_texture t;
    char err[512];
    const char *p;
    if (argc != 2) {
        aerotex_error("info takes one texture file");
        return 2;
    }
    if (aero_texture_load(argv[1], &t, err, sizeof err)) {
        aerotex_error("%s", err);
        return 1;
    }
    printf("file: %s\n", argv[1]);
    printf("frames=%d\nchannels=%d\nseconds=%.6g\n", t.frames, t.channels,
           t.frames / t.rate);
    /* every metadata line as it is stored */
    p = t.meta;
    while (p && *p) {
        const char *e = strchr(p, '\n');
        int n = e ? (int)(e - p) : (int)strlen(p);
        printf("%.*s\n", n, p);
        p = e ? e + 1 : NULL;
    }
    aerotex_print_matches(&t);
    aero_texture_free(&t);
    return 0;
}

const aerotex_command aerotex_info_command = {
    "info", "FILE.wav", "prints a texture's metadata and flow statistics",
    NULL, 0, NULL, aerotex_info};

static int dispatch(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "help") || !strcmp(argv[1], "--help") ||
        !strcmp(argv[1], "-h")) {
        usage(stdout);
        return 0;
    }
    for (int k = 0; k < NCOMMANDS; k++)
        if (!strcmp(argv[1], commands[k]->name)) {
            /* the commands without independent simulations run on rank 0
               of a task farm alone (aerotex_farm.c) */
            if (!farmed(commands[k]) && aerotex_farm_rank())
                return 0;
            return commands[k]->run(argc - 1, argv + 1);
        }
    aerotex_error("unknown command '%s' (try 'aerotex help')", argv[1]);
    return 2;
}

int main(int argc, char **argv)
{
    int status;
    aerotex_farm_init(&argc, &argv);
    status = dispatch(argc, argv);
    aerotex_farm_finalize();
    return status;
}
