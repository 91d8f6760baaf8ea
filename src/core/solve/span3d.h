/* aero: from the flow past a 2D section to what a real 3D body at the same
 * Reynolds number radiates (issue 19).
 *
 * A 2D simulation keeps the wake coherent along the whole span: above
 * Re ~ 200, where real wakes turn three-dimensional (Williamson 1996), it
 * sheds too fast and with a lift several times the measured sectional one.
 * The correction here is calibrated on the circular cylinder, the one
 * section with published data over the whole range: the solver's own
 * circle at the texture's Re and grid is compared with Roshko's (1954)
 * St(Re) and Norberg's (2003) sectional C_L'(Re), and the two ratios
 *     frequency_scale = St_Roshko(Re) / St_2D,circle
 *     force_scale     = C_L'_Norberg(Re) / C_L'_2D,circle
 * are applied to the force history of every shape made at that Re and
 * grid (time stretched by 1/frequency_scale, force times force_scale), so
 * the texture's g = dF/dt grows by their product. The spanwise correlation
 * length (~3-5 d, Norberg 2003) is the player's: it spaces incoherent
 * sources ~3 d apart (aeolian.h), as model mode does.
 * Below Re 190 the real wake is two-dimensional and nothing is changed. */
#ifndef AERO_SPAN3D_H
#define AERO_SPAN3D_H

/* the wake stays two-dimensional up to Re ~ 190 (Williamson 1996) */
#define AERO_SPAN3D_RE_2D 190.0

typedef struct {
    double re;
    double st_2d, cl_rms_2d;   /* the 2D solver's circle at re, same grid */
    double st_ref, cl_rms_ref; /* Roshko 1954, Norberg 2003 at re */
    double frequency_scale, force_scale; /* 1, 1 when not applied */
    int applied;
} aero_span3d;

/* fills c from the 2D circle's spectral St and rms lift coefficient; 0, or
 * -1 (c left at the identity) when the circle did not shed */
int aero_span3d_calibrate(aero_span3d *c, double re, double st_2d_circle,
                          double cl_rms_2d_circle);
/* the identity (no correction) */
void aero_span3d_none(aero_span3d *c, double re);

/* Strouhal number of the spectral peak of a coefficient history c(t),
 * t in d/U (increasing, about uniformly stepped): Welch average of three
 * Hann-windowed half-length segments, scanned finely between St_min and
 * St_max, the peak refined by a parabola: the strongest tonal maximum
 * inside the scan (10 x above its neighbourhood), not the edge or the
 * falling spectrum of a slow drift. 0 when the history is too short or
 * flat. */
double aero_spectral_st(const double *t, const double *c, int n,
                        double st_min, double st_max);

#endif
