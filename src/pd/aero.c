/* aero: setup of the single-binary library (`-lib aero`, or a libpd app that
 * links every class statically): it only calls each class's setup, as
 * libpd_init() does for the objects it bundles. */
#include "aero_pd.h"

void aeolian_tilde_setup(void);
void cavity_tilde_setup(void);
void treebranch_tilde_setup(void);
void leafwave_tilde_setup(void);
void vortex_tilde_setup(void);
void fieldsound_tilde_setup(void);
void body_tilde_setup(void);

AERO_PD_EXPORT void aero_setup(void)
{
    aeolian_tilde_setup();
    cavity_tilde_setup();
    treebranch_tilde_setup();
    leafwave_tilde_setup();
    vortex_tilde_setup();
    fieldsound_tilde_setup();
    body_tilde_setup();
    post("aero: aerodynamic sound library loaded ([aeolian~] [cavity~] "
         "[treebranch~] [leafwave~] [vortex~] [fieldsound~] [body~])");
}
