/* aero: the negative control of the multi-instance check. Each object's
 * unit test runs two instances of its core interleaved and requires each
 * to match its lone run bit for bit (unit_multi_instance,
 * tests/unit/multi_instance.h; tests/robust/registered.sh requires such a
 * case for every object of AERO_OBJECTS). Here a "core" whose state hides
 * in a static variable, as a careless core would keep it, must fail that
 * same comparison: the check can fail. */
#include "multi_instance.h"

static double shared_phase;
static void *shared_make(int variant)
{
    double *f = calloc(1, sizeof(*f));
    *f = variant ? 0.03 : 0.01;
    shared_phase = 0.0;
    return f;
}
static void shared_run(void *s, const float *speed, float *out, int n)
{
    for (int i = 0; i < n; i++) {
        shared_phase += *(double *)s * (1.0 + speed[i]);
        out[i] = (float)sin(shared_phase);
    }
}
static void shared_drop(void *s) { free(s); }

UNIT_TEST(negative_control)
{
    int diff = unit_mi_differences(
        "static-state control",
        (unit_mi_core){shared_make, shared_run, shared_drop});
    UNIT_CHECK(diff > 0,
               "negative control: a core with static state is caught (%d "
               "samples differ)", diff);
}

UNIT_MAIN(UNIT_CASE(negative_control))
