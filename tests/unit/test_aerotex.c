/* aero: the aerotex command line: bad arguments and impossible geometry
 * give a message and a non-zero exit; a tiny texture is made and read
 * back with `aerotex info`. Runs build/aerotex from the repository root. */
#include "unit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#define TOOL "build/aerotex"
#define OUT "build/tests/aerotex_out.txt"

/* exit status of the command, its stdout + stderr in OUT */
static int run(const char *args)
{
    char cmd[1024];
    int r;
    snprintf(cmd, sizeof cmd, "%s %s >%s 2>&1", TOOL, args, OUT);
    r = system(cmd);
    return WIFEXITED(r) ? WEXITSTATUS(r) : -1;
}

/* does OUT contain s? */
static int said(const char *s)
{
    char buf[16384]; /* the whole usage */
    size_t n;
    FILE *f = fopen(OUT, "r");
    if (!f) return 0;
    n = fread(buf, 1, sizeof buf - 1, f);
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

static int tool_built(void)
{
    FILE *f = fopen(TOOL, "r");
    if (!f)
        return 0;
    fclose(f);
    return 1;
}

UNIT_TEST(bad_arguments)
{
    if (!tool_built())
        UNIT_SKIP("%s not built", TOOL);
    UNIT_CHECK(run("help") == 0 && said("aeolian") && said("cavity"),
               "help lists the commands");
    bad("", "usage");
    bad("bogus", "unknown command");
    bad("aeolian --shape circle", "no output file");
    bad("aeolian --speed -3 -o x.wav", "out of range");
    bad("aeolian --speed fast -o x.wav", "not a number");
    bad("aeolian --shape triangle -o x.wav", "unknown shape");
    bad("aeolian --shape polygon /nonexistent.poly -o x.wav", "can't open");
    bad("aeolian --shape circle --directions 4 -o x.wav", "every direction");
    bad("aeolian --speed 200 -o x.wav", "Mach");
    bad("aeolian --diameter 0.5 --speed 50 -o x.wav", "beyond");
    bad("aeolian --grid 2 -o x.wav", "out of range");
    bad("aeolian --shape ellipse --aspect 0.02 --grid 16 -o x.wav", "thin");
    bad("aeolian --frobnicate -o x.wav", "unknown option");
    bad("aeolian --span3d sphere -o x.wav", "--span3d takes");
    bad("cavity --length 0.02 -o x.wav", "--depth");
    bad("cavity --length 0.02 --depth 1 -o x.wav", "depth/length");
    bad("cavity --length 0.02 --depth 0.01 --theta 0.003 -o x.wav",
        "thicker than 0.1 of the length");
    bad("cavity --length 0.02 --depth 0.01 --theta -1 -o x.wav",
        "out of range");
    bad("info /nonexistent.wav", "can't open");
    /* every command's options come from its table: the usage lists them,
       an error names the command and the option */
    UNIT_CHECK(run("help") == 0 && said("--speeds") && said("--mesh") &&
                   said("--leaf-width") && said("--threshold") &&
                   said("(default 16000)"),
               "help lists every command's options and defaults");
    bad("vortex --receivers 65 -o x.wav",
        "vortex: --receivers 65 is out of range [1, 64]");
    bad("vortex --source fog -o x.wav",
        "vortex: --source takes window or cells");
    bad("object --shape sphere --sources 2.5 -o x.wav",
        "object: --sources takes a whole number");
    /* --calibrate: the sphere's published St holds for Re 800-3e5; strip
       theory takes its St from the section */
    bad("object --shape sphere --speed 0.1 --calibrate sphere -o x.wav",
        "the published St 0.2 holds for Re 800-300000");
    bad("object --shape club --method strip --section textures/cylinder.wav "
        "--calibrate cylinder -o x.wav",
        "--method strip takes its St from the section");
    bad("object --shape sphere --calibrate cube -o x.wav",
        "--calibrate takes sphere, cylinder or none");
    bad("cavity --diameter 0.01 -o x.wav",
        "cavity: unknown option '--diameter'");
    bad("tree --depth 9 -o x.tree", "tree: --depth 9 is out of range");
    bad("auralize d --map 0 1 -1 1 --path p.txt -o x.wav",
        "auralize: --map -1 is out of range");
    remove(OUT);
}

UNIT_TEST(tiny_texture_info)
{
    if (!tool_built())
        UNIT_SKIP("%s not built", TOOL);
    {
        /* a tiny, coarse texture and its metadata */
        int r = run("aeolian --shape circle --re 80 --grid 8 --duration 0.01 "
                    "--settle 5 -q -o build/tests/aerotex_tiny.wav");
        UNIT_CHECK(r == 0, "tiny texture made (exit %d)", r);
        r = run("info build/tests/aerotex_tiny.wav");
        UNIT_CHECK(r == 0 && said("kind=aeolian") && said("re=80") &&
                       said("directions=1") && said("st=") &&
                       said("cells=8") && said("span3d=none") &&
                       said("command=aerotex aeolian"),
                   "info prints kind, Re, directions, St, cells, the "
                   "2D-to-3D method (none at Re 80: a 2D wake), command");
        remove("build/tests/aerotex_tiny.wav");
    }
    remove(OUT);
}

UNIT_TEST(cavity_inflow_layer)
{
    if (!tool_built())
        UNIT_SKIP("%s not built", TOOL);
    {
        /* a cavity with an inflow boundary layer: its thickness in the
           metadata and the report; too short a run to oscillate, and the
           report says what to change (the layer, not only the grid) */
        int r = run("cavity --length 0.02 --depth 0.01 --theta 0.001 "
                    "--grid 48 --duration 0.01 --settle 2 -q "
                    "-o build/tests/aerotex_cavity.wav");
        UNIT_CHECK(r == 0 && said("L/theta 20.0") &&
                       said("no self-sustained oscillation") &&
                       said("inflow layer at L/theta 20"),
                   "cavity --theta: the layer reported, and the silent "
                   "flow explained by it (exit %d)", r);
        r = run("info build/tests/aerotex_cavity.wav");
        UNIT_CHECK(r == 0 && said("kind=cavity") && said("theta=0.001"),
                   "info prints the cavity's theta");
        /* and the table of what it matches (textures/README.md) */
        UNIT_CHECK(r == 0 && said("| quantity | texture | published |") &&
                       said("| St_L of the shear-layer tone |") &&
                       said("Rossiter 1964"),
                   "info prints what the texture matches, with its source");
        remove("build/tests/aerotex_cavity.wav");
    }
    remove(OUT);
}

UNIT_TEST(urans_band_limit)
{
    if (!tool_built())
        UNIT_SKIP("%s not built", TOOL);
    {
        /* --span3d urans band limits every channel at what the grid
           resolves (src/core/solve/band_limit.h): 1 cm at 10 m/s on 8
           cells per d, 1.25 mm cells: 500-1000 Hz, in the metadata, the
           report and the table; --band-limit off leaves it out */
        int r = run("aeolian --shape square --diameter 0.01 --speed 10 "
                    "--grid 8 --span3d urans --duration 0.01 --settle 2 -q "
                    "-o build/tests/aerotex_urans.wav");
        UNIT_CHECK(r == 0 && said("band limit of the grid: 500 Hz passed, "
                                  "1000 Hz and above removed"),
                   "the band limit reported (exit %d)", r);
        r = run("info build/tests/aerotex_urans.wav");
        UNIT_CHECK(r == 0 && said("band_limit_pass=500") &&
                       said("band_limit_stop=1000") &&
                       said("| band limit: wavelengths of 16 to 8 cells"),
                   "info prints the band limit and its row");
        r = run("aeolian --shape square --diameter 0.01 --speed 10 "
                "--grid 8 --span3d urans --band-limit off --duration 0.01 "
                "--settle 2 -q -o build/tests/aerotex_urans.wav");
        UNIT_CHECK(r == 0 && !said("band limit"), "--band-limit off: none "
                   "(exit %d)", r);
        r = run("info build/tests/aerotex_urans.wav");
        UNIT_CHECK(r == 0 && !said("band_limit"), "and none in the file");
        bad("aeolian --band-limit 2000 -o x.wav", "--band-limit takes");
        remove("build/tests/aerotex_urans.wav");
    }
    remove(OUT);
}

UNIT_MAIN(UNIT_CASE(bad_arguments), UNIT_CASE(tiny_texture_info),
          UNIT_CASE(cavity_inflow_layer), UNIT_CASE(urans_band_limit))
