/* fuzz: aerotex's command line (the option tables of `aerotex aeolian` and
 * `aerotex cavity`, src/tools/aerotex_run.c, read by
 * src/tools/aerotex_options.c). The input is split at NUL and newline
 * bytes into argv; the first byte picks the subcommand. Only the parser
 * runs (a valid command line would start a flow simulation).
 * Seeds: fuzz/seeds/aerotex_args/ (the command lines of textures/make.sh). */
#include "fuzz.h"

#include <stdarg.h>

/* the option tables, static in aerotex_run.c */
#include "../src/tools/aerotex_run.c"

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
    argv[argc++] = data[0] & 1 ? "cavity" : "aeolian";
    char *p = text, *end = text + size - 1;
    while (p < end && argc < 255) {
        argv[argc++] = p;
        while (p < end && *p && *p != '\n')
            p++;
        *p++ = 0;
    }
    argv[argc] = NULL;
    aeolian_job j;
    if (aerotex_job_parse(data[0] & 1 ? &aerotex_cavity_command
                                      : &aerotex_aeolian_command,
                          &j, argc, argv) == 0) {
        FUZZ_REQUIRE(j.job.out != NULL, "accepted without an output file");
        FUZZ_REQUIRE(j.directions == floor(j.directions) &&
                         j.directions >= 1 && j.directions <= 360,
                     "directions %d accepted", j.directions);
        FUZZ_REQUIRE(isfinite(j.v0) && isfinite(j.job.duration) &&
                         isfinite(j.job.rate),
                     "a non-finite number accepted");
    }
    free(text);
    return 0;
}
