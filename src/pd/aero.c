/* aero: setup of the single-binary library (`-lib aero`, or a libpd app that
 * links every class statically): it only calls each class's setup, as
 * libpd_init() does for the objects it bundles. */
#include "m_pd.h"
#include "aero.h"

#include <string.h>

/* The one piece of process state in aero: the host's data folder (aero.h).
 * A host sets it before opening patches; objects only read it, when they
 * look for a file. Allowed by name in tests/robust/globals.sh. */
static char aero_data_dir[MAXPDSTRING];

void aero_set_data_path(const char *dir)
{
    size_t n = dir ? strlen(dir) : 0;
    if (n >= sizeof(aero_data_dir)) {
        pd_error(NULL, "aero: data path of %zu bytes is too long (max %zu): "
                 "unset", n, sizeof(aero_data_dir) - 1);
        n = 0;
    }
    memcpy(aero_data_dir, dir ? dir : "", n);
    aero_data_dir[n] = '\0';
}

const char *aero_data_path(void)
{
    return aero_data_dir[0] ? aero_data_dir : NULL;
}

void aeolian_tilde_setup(void);
void cavity_tilde_setup(void);
void treebranch_tilde_setup(void);
void leafwave_tilde_setup(void);
void vortex_tilde_setup(void);
void fieldsound_tilde_setup(void);
void body_tilde_setup(void);

void aero_setup(void)
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
