/* aero: [aeolian~]'s engine: the Strouhal/Reynolds model of a cylinder
 * (aeolian_model) or, once a texture is given, a stick played from it
 * (stick_texture). The choice lives here, as cavity_model holds its own
 * texture mode, so a host drives one object either way.
 *
 * Life cycle: init, set_* (each setter reaches both engines, so a switch
 * of mode keeps every setting), process, free. The texture engine is made
 * the first time it is needed (a texture, a pose, wind, roll, n,
 * exponent): model-mode objects, the common case by the hundred, do not
 * pay for its delay rings. No globals. */
#ifndef AERO_AEOLIAN_H
#define AERO_AEOLIAN_H

#include "aeolian_model.h"
#include "aeolian_texture.h"

typedef struct {
    aero_aeolian_model model;
    aero_stick_texture *stick; /* texture engine, NULL until needed */
    int n_ears;
    int diameter_set;          /* a diameter was given: the texture uses it */
} aero_aeolian;

/* 0, or -1 when the sample rate is not usable (44.1 kHz is taken) */
int aero_aeolian_init(aero_aeolian *a, double sample_rate, int n_ears,
                      uint32_t seed);
void aero_aeolian_free(aero_aeolian *a);

/* 1 while a texture plays, else 0 (the model) */
int aero_aeolian_texture_mode(const aero_aeolian *a);

/* Takes ownership of a loaded aeolian texture: 0, or -1 with a message in
 * err (the texture is not taken). NULL returns to the model. */
int aero_aeolian_set_texture(aero_aeolian *a, aero_texture *t, char *err,
                             size_t errlen);

/* Setters: 0 accepted, -1 invalid or out of memory (the previous value
 * stays). Ranges: see aeolian_model.h and stick_texture.h. */
int aero_aeolian_set_sample_rate(aero_aeolian *a, double sr);
int aero_aeolian_set_diameter(aero_aeolian *a, double d);
int aero_aeolian_set_length(aero_aeolian *a, double l);
int aero_aeolian_set_gain_db(aero_aeolian *a, double db);
int aero_aeolian_set_ramp_ms(aero_aeolian *a, double ms);
void aero_aeolian_set_seed(aero_aeolian *a, uint32_t seed);
int aero_aeolian_set_ears(aero_aeolian *a, const aero_ears *e);
/* texture-mode controls (they make the texture engine) */
int aero_aeolian_set_pose(aero_aeolian *a, const double end_a[3],
                          const double end_b[3], double interval_s);
int aero_aeolian_set_reference(aero_aeolian *a, const double x[3]);
int aero_aeolian_set_wind(aero_aeolian *a, const double w[3]);
int aero_aeolian_set_roll_deg(aero_aeolian *a, double deg);
int aero_aeolian_set_sources(aero_aeolian *a, int n);
int aero_aeolian_set_exponent(aero_aeolian *a, double e);

/* n samples from the engine in use; see aero_aeolian_model_process.
 * Returns 1 if a speed was clamped. */
int aero_aeolian_process(aero_aeolian *a, const float *speed,
                         float *const *out, int n);

#endif
