/* fuzz: aerotex's command line (the option tables of every command, read
 * by src/tools/aerotex_options.c). The input is split at NUL and newline
 * bytes into argv; the first byte picks the command: bits 1-2 give
 * aeolian (bit 0: cavity), vortex, object or auralize. Only the parser
 * runs (a valid command line would start a simulation).
 * Seeds: fuzz/seeds/aerotex_args/ (the command lines of textures/make.sh). */
/* aero-fuzz: sources src/tools/aerotex_png.c src/tools/aerotex_common.c */
/* aero-fuzz: sources src/tools/aerotex_aeolian.c src/tools/aerotex_cavity.c */
/* aero-fuzz: sources src/tools/aerotex_section.c src/tools/aerotex_options.c */
/* aero-fuzz: sources src/tools/aerotex_vortex.c src/tools/aerotex_object.c */
/* aero-fuzz: sources src/tools/aerotex_field.c src/tools/aerotex_farm.c */
#include "fuzz.h"

#include <stdarg.h>

/* the job of aeolian and cavity (aerotex_section.h); the commands'
   tables come with their sources (the aero-fuzz lines above) */
#include "../src/tools/aerotex_section.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* aerotex.c's message function (its main() is not wanted here) */
void aerotex_error(const char *fmt, ...)
{
    (void)fmt;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1 || size > 4096)
        return 0;
    char *text = malloc(size + 1);
    char *argv[256];
    int argc = 0;
    if (!text)
        return 0;
    memcpy(text, data + 1, size - 1);
    text[size - 1] = 0;
    const aerotex_command *const pick[4] = {
        data[0] & 1 ? &aerotex_cavity_command : &aerotex_aeolian_command,
        &aerotex_vortex_command, &aerotex_object_command,
        &aerotex_auralize_command};
    const aerotex_command *cmd = pick[(data[0] >> 1) & 3];
    argv[argc++] = (char *)cmd->name;
    char *p = text, *end = text + size - 1;
    while (p < end && argc < 255) {
        argv[argc++] = p;
        while (p < end && *p && *p != '\n')
            p++;
        *p++ = 0;
    }
    argv[argc] = NULL;
    if (cmd == &aerotex_auralize_command) {
        /* not a texture job: parsed into its own job */
        void *job = malloc(cmd->job_size);
        if (job) {
            aerotex_defaults(cmd, job);
            aerotex_parse(cmd, job, argc, argv);
        }
        free(job);
    } else if (cmd->job_size == sizeof(aeolian_job)) {
        aeolian_job j;
        if (aerotex_job_parse(cmd, &j, argc, argv) == 0) {
            FUZZ_REQUIRE(j.job.out != NULL, "accepted without an output file");
            FUZZ_REQUIRE(j.directions >= 1 && j.directions <= 360,
                         "directions %d accepted", j.directions);
            FUZZ_REQUIRE(isfinite(j.v0) && isfinite(j.job.duration) &&
                             isfinite(j.job.rate),
                         "a non-finite number accepted");
        }
    } else {
        /* vortex, object: a job that starts with an aerotex_job */
        aerotex_job *job = malloc(cmd->job_size);
        if (job && aerotex_job_parse(cmd, job, argc, argv) == 0)
            FUZZ_REQUIRE(job->out != NULL && isfinite(job->duration) &&
                             isfinite(job->rate) && job->threads >= 1,
                         "a bad job accepted");
        free(job);
    }
    free(text);
    return 0;
}
