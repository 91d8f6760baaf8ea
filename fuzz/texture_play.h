/* aero fuzz: what a loaded texture must satisfy, and the players that
 * take one ([aeolian~]'s moving stick, [cavity~], [body~]) rendering it
 * finitely. */
#ifndef AERO_FUZZ_TEXTURE_PLAY_H
#define AERO_FUZZ_TEXTURE_PLAY_H

#include "fuzz.h"

#include "body.h"
#include "cavity.h"
#include "aeolian.h"
#include "texture.h"

/* loads the texture at path (twice: each player takes ownership of its
 * copy) and plays it; returns 1 if it loaded */
static int fuzz_texture_check(const char *path)
{
    char err[512];
    aero_texture *t = calloc(1, sizeof(*t));
    if (!t)
        return 0;
    err[0] = 0;
    if (aero_texture_load(path, t, err, sizeof(err))) {
        FUZZ_REQUIRE(err[0] != 0, "a refused texture without a message");
        FUZZ_REQUIRE(!t->data && !t->meta && !t->angles,
                     "a refused texture keeps memory");
        free(t);
        return 0;
    }
    /* an aeolian/cavity texture: 3 channels per direction; an object
     * texture: 3 per direction and region; a vortex texture: no
     * directions, one channel per (finite) speed */
    int vortex = t->directions == 0;
    FUZZ_REQUIRE(t->frames >= 2 && t->rate > 0.0 &&
                     (vortex ? t->channels >= 1 && t->speeds != NULL
                             : t->regions >= 1 &&
                                   t->channels ==
                                       3 * t->directions * t->regions),
                 "loaded texture with %d frames, %d directions, %d channels",
                 t->frames, t->directions, t->channels);
    FUZZ_REQUIRE(fuzz_finite(t->data, t->frames * t->channels),
                 "loaded texture holds a non-finite sample");
    for (int k = 0; k < t->directions; k++)
        FUZZ_REQUIRE(isfinite(t->angles[k]), "angle %d not finite", k);
    char buf[64];
    aero_texture_get(t, "kind", buf, sizeof(buf));
    aero_texture_get(t, "", buf, 1);
    for (int k = 0; vortex && k < t->channels; k++)
        FUZZ_REQUIRE(isfinite(t->speeds[k]) && t->speeds[k] > 0.0,
                     "speed %d not finite and positive", k);
    if (!vortex)
        (void)aero_texture_sample(t, -12345, t->directions - 1, 2);

    /* the moving stick ([aeolian~] in texture mode) */
    aero_aeolian stick;
    if (!aero_aeolian_init(&stick, 44100.0, 2, 1)) {
        if (aero_aeolian_set_texture(&stick, t, err, sizeof(err))) {
            aero_texture_free(t);
            free(t);
        }
        t = NULL;
        double wind[3] = {12.0, 3.0, 0.0};
        aero_aeolian_set_wind(&stick, wind);
        float speed[256], l[256], r[256];
        float *out[2] = {l, r};
        for (int i = 0; i < 256; i++)
            speed[i] = (float)(i % 64);
        for (int b = 0; b < 4; b++) {
            aero_aeolian_process(&stick, speed, out, 256);
            FUZZ_REQUIRE(fuzz_finite(l, 256) && fuzz_finite(r, 256),
                         "stick texture player output not finite");
        }
    }
    aero_aeolian_free(&stick);
    if (t) {
        aero_texture_free(t);
        free(t);
    }

    /* the moving 3D body */
    t = calloc(1, sizeof(*t));
    if (t && !aero_texture_load(path, t, err, sizeof(err))) {
        aero_body *body = calloc(1, sizeof(*body));
        if (body && !aero_body_init(body, 44100.0, 2, 1)) {
            if (!aero_body_set_texture(body, t, err, sizeof(err)))
                t = NULL; /* the player frees it */
            double wind[3] = {12.0, 3.0, 1.0}, q[4] = {0.9, 0.1, 0.3, 0.2};
            double p[3] = {0.0, 0.0, 0.0};
            aero_body_set_wind(body, wind);
            float speed[256], l[256], r[256];
            float *out[2] = {l, r};
            for (int i = 0; i < 256; i++)
                speed[i] = (float)(i % 64);
            for (int b = 0; b < 4; b++) {
                p[0] = 0.05 * b;
                aero_body_set_pose(body, p, q, 256 / 44100.0);
                aero_body_process(body, speed, out, 256);
                FUZZ_REQUIRE(fuzz_finite(l, 256) && fuzz_finite(r, 256),
                             "body texture player output not finite");
            }
            aero_body_free(body);
        }
        free(body);
    }
    if (t) {
        aero_texture_free(t);
        free(t);
    }

    /* the cavity */
    t = calloc(1, sizeof(*t));
    if (t && !aero_texture_load(path, t, err, sizeof(err))) {
        aero_cavity cav;
        aero_cavity_init(&cav, 48000.0, 1, 1);
        if (aero_cavity_set_texture(&cav, t, err, sizeof(err)))
            aero_texture_free(t); /* refused: still ours */
        else
            t = NULL;             /* the model frees it */
        float speed[256], out[256];
        for (int i = 0; i < 256; i++)
            speed[i] = (float)(i % 50);
        for (int b = 0; b < 4; b++) {
            aero_cavity_process(&cav, speed, (float *[]){out}, 256);
            FUZZ_REQUIRE(fuzz_finite(out, 256),
                         "cavity texture player output not finite");
        }
        aero_cavity_free(&cav);
    } else if (t) {
        aero_texture_free(t);
    }
    free(t);
    return 1;
}

#endif
