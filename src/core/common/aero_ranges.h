/* aero: ranges and defaults of the settings the real-time players share,
 * stated once: the players check them and start with the defaults, the
 * hosts quote them in their messages. A player with its own range or
 * default names it in its header (AERO_<OBJECT>_<SETTING>_DEFAULT). */
#ifndef AERO_RANGES_H
#define AERO_RANGES_H

#define AERO_GAIN_DB_MIN -200.0
#define AERO_GAIN_DB_MAX 120.0
#define AERO_RAMP_MS_MIN 0.0 /* 0: a new value at once */
#define AERO_RAMP_MS_MAX 600000.0
/* the sample rate a player takes when the host's is not usable, until
   the host gives one (Pd: when the DSP starts), Hz */
#define AERO_SAMPLE_RATE_FALLBACK 44100.0

/* their defaults, which the players start with and the hosts quote */
#define AERO_GAIN_DB_DEFAULT 0.0 /* a gain of 1 */
#define AERO_RAMP_MS_DEFAULT 20.0

#endif
