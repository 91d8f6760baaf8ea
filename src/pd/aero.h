/* aero for host programs that link it into themselves (a libpd app: games,
 * plugins, plugdata): after libpd_init(), call aero_setup() once to register
 * every aero class. docs/libpd.md says how to build
 * and link: every .c file of src/pd (the classes; aero_pd.c, which defines
 * the data path below; aero.c). */
#ifndef AERO_H
#define AERO_H

/* registers [aeolian~] [cavity~] [treebranch~] [leafwave~] [vortex~]
 * [fieldsound~] [body~]: once per process, after libpd_init() */
void aero_setup(void);

/* The folder that holds aero's data: its textures/ and trees/ folders
 * (the aero folder of a release, or a copy in the app's assets). A host
 * has no install folder to find them in: patches find textures and trees
 * next to themselves, on Pd's search path, in $AERO_DATA, then here.
 * Call it after aero_setup() and before opening patches (it is not locked
 * against objects that read it); NULL or "" unsets it. The path is copied
 * (at most 999 bytes; longer ones are refused and unset it). */
void aero_set_data_path(const char *dir);

/* the folder set by aero_set_data_path(), or NULL when none is set */
const char *aero_data_path(void);

#endif
