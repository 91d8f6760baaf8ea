/* aero: ranges of the settings the real-time players share, stated once:
 * the players check them, the hosts quote them in their messages. A
 * player with its own range names it in its header. */
#ifndef AERO_RANGES_H
#define AERO_RANGES_H

#define AERO_GAIN_DB_MIN -200.0
#define AERO_GAIN_DB_MAX 120.0
#define AERO_RAMP_MS_MAX 600000.0 /* ramps from 0 ms */

#endif
