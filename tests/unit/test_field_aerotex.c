/* aero: `aerotex field-demo` and `aerotex auralize` on the command line:
 * bad arguments, paths and volumes give a message and a non-zero exit; a
 * small burst written to disk and heard at 3 m and 6 m along one line
 * falls by 1/r; a moving listener renders. Runs build/aerotex from the
 * repository root; files in build/tests/field-cli/. */
#include "unit.h"

#include <math.h>
#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#define TOOL "build/aerotex"
#define DIR "build/tests/field-cli"
#define OUT DIR "/out.txt"

static int run(const char *args)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "%s %s >%s 2>&1", TOOL, args, OUT);
    int r = system(cmd);
    return WIFEXITED(r) ? WEXITSTATUS(r) : -1;
}

static int said(const char *s)
{
    char buf[16384];
    FILE *f = fopen(OUT, "r");
    if (!f)
        return 0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    return strstr(buf, s) != NULL;
}

static void bad(const char *args, const char *msg)
{
    int r = run(args);
    UNIT_CHECK(r != 0 && said(msg), "'aerotex %s' -> exit %d, says '%s'",
               args, r, msg);
}

static void text(const char *path, const char *t)
{
    FILE *f = fopen(path, "w");
    fputs(t, f);
    fclose(f);
}

static double rms_of(const char *path, double *seconds)
{
    SF_INFO info;
    memset(&info, 0, sizeof info);
    SNDFILE *f = sf_open(path, SFM_READ, &info);
    if (!f)
        return -1;
    float *x = malloc(sizeof(float) * info.frames);
    sf_count_t n = sf_readf_float(f, x, info.frames);
    sf_close(f);
    double s = 0;
    int bad_samples = 0;
    for (sf_count_t i = 0; i < n; i++) {
        if (!isfinite(x[i]))
            bad_samples++;
        s += (double)x[i] * x[i];
    }
    free(x);
    *seconds = (double)n / info.samplerate;
    return bad_samples ? -1 : sqrt(s / (n ? n : 1));
}

/* the tool built, the output folder and the listener paths of both cases */
static int prepare(void)
{
    FILE *f = fopen(TOOL, "r");
    if (!f)
        return 0;
    fclose(f);
    mkdir("build/tests", 0777);
    mkdir(DIR, 0777);
    text(DIR "/p3.txt", "# 3 m along x\n0 3 0 0\n");
    text(DIR "/p6.txt", "0 6 0 0\n");
    return 1;
}

UNIT_TEST(bad_arguments)
{
    if (!prepare())
        UNIT_SKIP("%s not built", TOOL);
    UNIT_CHECK(run("help") == 0 && said("field-demo") && said("auralize"),
               "help lists field-demo and auralize");
    bad("field-demo", "no output directory");
    bad("field-demo --size 2 -o " DIR "/x", "out of range");
    bad("field-demo --frames many -o " DIR "/x", "not a number");
    bad("field-demo --bogus -o " DIR "/x", "unknown option");
    bad("auralize", "no volume directory");
    bad("auralize " DIR "/burst -o " DIR "/a.wav", "no listener path");
    bad("auralize " DIR "/burst --path p.txt", "no output file");
    bad("auralize " DIR "/burst --path /nonexistent.txt -o " DIR "/a.wav",
        "can't open path file");
    text(DIR "/badpath.txt", "0 1 2\n");
    bad("auralize " DIR "/burst --path " DIR "/badpath.txt -o " DIR "/a.wav",
        "'t x y z'");
    text(DIR "/backpath.txt", "1 0 0 3\n0.5 0 0 3\n");
    bad("auralize " DIR "/burst --path " DIR "/backpath.txt -o " DIR
        "/a.wav", "goes back");
    bad("auralize " DIR "/nowhere --path " DIR "/p3.txt -o " DIR "/a.wav",
        "can't open");
    bad("auralize " DIR "/burst --path " DIR "/p3.txt --threshold 1 0 1 -o "
        DIR "/a.wav", "out of range");
}

UNIT_TEST(burst_auralized)
{
    if (!prepare())
        UNIT_SKIP("%s not built", TOOL);
    /* a small burst on disk: 20^3, 24 frames */
    int r = run("field-demo --size 20 --frames 24 --spacing 0.064 -q -o " DIR
                "/burst");
    UNIT_CHECK(r == 0 && said("wrote"), "field-demo writes a volume (exit %d)",
               r);
    /* the same volume with a truncated frame and a broken header */
    mkdir(DIR "/cut", 0777);
    system("cp " DIR "/burst/volume.txt " DIR "/cut/ && for k in 0 1 2 3 4 5 "
           "6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23; do "
           "cp " DIR "/burst/frame000$(printf %02d $k).f32 " DIR "/cut/; "
           "done && head -c 1000 " DIR "/burst/frame00005.f32 >" DIR
           "/cut/frame00005.f32");
    bad("auralize " DIR "/cut --path " DIR "/p3.txt -q -o " DIR "/a.wav",
        "frame00005.f32 is 1000 bytes, expected 32000");
    mkdir(DIR "/broken", 0777);
    text(DIR "/broken/volume.txt", "aero-volume 1\ndims 20 20 20\n"
         "spacing 0.1 0.1\n");
    bad("auralize " DIR "/broken --path " DIR "/p3.txt -o " DIR "/a.wav",
        "'spacing' needs three lengths");

    /* 1/r along one line: 6 m is 6.02 dB below 3 m (the sources spread
     * over +-0.6 m: < 0.3 dB of curvature at 3 m); same duration */
    double s3, s6, d3, d6;
    r = run("auralize " DIR "/burst --path " DIR "/p3.txt --duration 0.12 -q "
            "-o " DIR "/r3.wav");
    r |= run("auralize " DIR "/burst --path " DIR "/p6.txt --duration 0.12 -q "
             "-o " DIR "/r6.wav");
    s3 = rms_of(DIR "/r3.wav", &d3);
    s6 = rms_of(DIR "/r6.wav", &d6);
    UNIT_CHECK(r == 0 && s3 > 0 && s6 > 0 && fabs(d3 - 0.12) < 1e-3,
               "auralize renders 0.12 s at 3 m and 6 m (%g, %g Pa rms)", s3,
               s6);
    UNIT_CHECK(fabs(20 * log10(s6 / s3) + 6.02) < 0.5,
               "3 m -> 6 m: %.2f dB (1/r: -6.02 +- 0.5)",
               20 * log10(s6 / s3));
    /* a listener walking through the burst at 5 m/s; stats printed */
    text(DIR "/walk.txt", "0 -1 0.2 0\n0.4 1 0.2 0\n");
    r = run("auralize " DIR "/burst --path " DIR "/walk.txt -q -o " DIR
            "/walk.wav");
    double sw = rms_of(DIR "/walk.wav", &d3);
    UNIT_CHECK(r == 0 && sw > 0 && d3 >= 0.4 && said("us per sample") &&
                   said("ms per frame") && said("monopole"),
               "moving listener: %.3f s rendered, finite, timings printed",
               d3);
    /* the per-sample reference gives the same file */
    r = run("auralize " DIR "/burst --path " DIR "/walk.txt -q --direct -o "
            DIR "/walkd.wav");
    double swd = rms_of(DIR "/walkd.wav", &d6);
    UNIT_CHECK(r == 0 && fabs(swd - sw) <= 1e-5 * sw,
               "--direct (per-sample sum) agrees: %g vs %g Pa rms", swd, sw);
}

UNIT_MAIN(UNIT_CASE(bad_arguments), UNIT_CASE(burst_auralized))
