/* aero: setup of the single-binary library (`-lib aero`, or a libpd app that
 * links every class statically): it only calls each class's setup, as
 * libpd_init() does for the objects it bundles. */
#include "aero_pd.h"

/* every object, one line each: a new object joins the library here (the
 * builds, packages and Pd-side tests find src/pd/NAME~.c by themselves) */
#define AERO_OBJECTS(X)                                                    \
    X(aeolian) X(cavity) X(treebranch) X(leafwave) X(vortex) X(fieldsound) \
    X(body) X(rotor)

#define AERO_DECLARE(name) void name##_tilde_setup(void);
#define AERO_SETUP(name) name##_tilde_setup();
#define AERO_NAME(name) " [" #name "~]"

AERO_OBJECTS(AERO_DECLARE)

AERO_PD_EXPORT void aero_setup(void)
{
    AERO_OBJECTS(AERO_SETUP)
    post("aero: aerodynamic sound library loaded:" AERO_OBJECTS(AERO_NAME));
}
