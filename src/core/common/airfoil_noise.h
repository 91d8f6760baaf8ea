/* aero: airfoil self-noise, the semi-empirical model of Brooks, Pope and
 * Marcolini (Brooks et al. 1989, NASA RP-1218, "BPM"): the one-third-
 * octave sound pressure level of each noise mechanism of an airfoil
 * section of span L in a uniform flow, heard in the far field.
 *
 * The mechanisms (the report's sections 5 and 7):
 *   turbulent boundary layer, trailing edge (TBL-TE): the pressure side
 *     and the suction side, each scaled on its displacement thickness;
 *   separation (the angle-of-attack term of TBL-TE), which takes over
 *     when the section stalls;
 *   laminar boundary layer vortex shedding (LBL-VS), for an untripped
 *     boundary layer at low Reynolds number;
 *   trailing-edge bluntness vortex shedding, from the thickness h and
 *     solid angle Psi of the trailing edge;
 *   tip vortex formation noise, for a section that ends in a free tip.
 * Each is a level 10 log10(thickness M^5 L D / r^2) plus spectral shape
 * and amplitude functions of Strouhal number, Reynolds number and angle
 * fitted to NACA 0012 sections of 2.5-61 cm chord at 31.7-71.3 m/s
 * (chord Reynolds numbers 5.5e4-3e6) in an open jet; outside that range
 * the functions are extrapolated as written.
 *
 * Units: SI throughout (m, m/s, m^2/s, Hz), angles in degrees; levels in
 * dB re 20 uPa. Host independent, no globals, no allocation. */
#ifndef AERO_AIRFOIL_NOISE_H
#define AERO_AIRFOIL_NOISE_H

enum aero_bpm_mechanism {
    AERO_BPM_TBL_PRESSURE, /* TBL-TE, pressure side */
    AERO_BPM_TBL_SUCTION,  /* TBL-TE, suction side */
    AERO_BPM_SEPARATION,   /* TBL-TE angle-of-attack (separation) term */
    AERO_BPM_LBL_VS,       /* laminar boundary layer vortex shedding */
    AERO_BPM_BLUNTNESS,    /* trailing-edge bluntness vortex shedding */
    AERO_BPM_TIP,          /* tip vortex formation */
    AERO_BPM_MECHANISMS
};

/* a level for "this mechanism makes no sound here" (instead of -inf, so
   sums and comparisons stay finite) */
#define AERO_BPM_SILENT_DB (-200.0f)

/* the report's speed of sound and kinematic viscosity (its figures'
   conditions) */
#define AERO_BPM_REPORT_C0 340.46f
#define AERO_BPM_REPORT_NU 1.4529e-5f

enum aero_airfoil_tip {
    AERO_AIRFOIL_NO_TIP,      /* both ends in the flow's span: no tip noise */
    AERO_AIRFOIL_TIP_ROUNDED, /* a rounded tip (the report's measured one) */
    AERO_AIRFOIL_TIP_FLAT     /* a square-cut tip */
};

typedef struct {
    float chord;          /* c, m (> 0) */
    float span;           /* L, wetted span of the section, m (> 0) */
    float te_thickness;   /* h, trailing-edge thickness, m (>= 0; 0 = sharp:
                             no bluntness noise) */
    float te_angle_deg;   /* Psi, solid angle between the surfaces at the
                             trailing edge, deg (0..90; the report's
                             NACA 0012 is 14 deg) */
    int tripped;          /* 1: boundary layer tripped (turbulent from the
                             leading edge), 0: untripped (natural
                             transition; LBL-VS possible) */
    int tip;              /* enum aero_airfoil_tip */
    float tip_alpha_deg;  /* alpha_tip, deg: the tip's angle of attack
                             (flat tip: the loading-corrected alpha'_tip
                             of the report) */
} aero_airfoil;

typedef struct {
    float speed;     /* U, m/s (> 0, Mach < 0.5) */
    float alpha_deg; /* alpha*, effective angle of attack, deg; its sign
                        says which side is the suction side, the model
                        uses |alpha*| (0..25 as fitted; clamped there) */
    float c0;        /* speed of sound, m/s (> 0) */
    float nu;        /* kinematic viscosity, m^2/s (> 0) */
} aero_airfoil_flow;

/* the observer from the trailing edge, in the report's frame: x along the
   chord downstream, y along the span, z normal to the chord. theta_e is
   the angle from x, phi_e the angle of the (y, z) plane's projection from
   y; theta = phi = 90 deg is straight above the section. */
typedef struct {
    float r;         /* r_e, m (> 0) */
    float theta_deg; /* Theta_e, deg */
    float phi_deg;   /* Phi_e, deg */
} aero_airfoil_observer;

/* the boundary-layer thicknesses at the trailing edge (m): the report's
   zero-angle correlations (tripped and untripped) and their
   angle corrections (tripped and untripped) */
typedef struct {
    float delta0, delta_star0;   /* at zero angle */
    float delta_p, delta_star_p; /* pressure side */
    float delta_s, delta_star_s; /* suction side */
} aero_boundary_layer;

/* 0, or -1 (bad input: out zeroed) */
int aero_airfoil_boundary_layer(const aero_airfoil *a,
                                const aero_airfoil_flow *f,
                                aero_boundary_layer *out);

/* the report's directivity functions, mach = U / c0:
   high-frequency (a half-plane's trailing edge, with convective
   amplification; the convection Mach number of the wake 0.8 M) and
   low-frequency (a compact dipole) */
double aero_airfoil_directivity_high(double mach, double theta_deg,
                                     double phi_deg);
double aero_airfoil_directivity_low(double mach, double theta_deg,
                                    double phi_deg);

/* the one-third-octave level of each mechanism at each band centre:
   spl_db[m * n_bands + k] for mechanism m (enum aero_bpm_mechanism) at
   band_hz[k] (> 0). 0, or -1 (bad input: every level AERO_BPM_SILENT_DB).
   Never NaN or Inf. */
int aero_airfoil_noise_spectrum(const aero_airfoil *a,
                                const aero_airfoil_flow *f,
                                const aero_airfoil_observer *o,
                                const float *band_hz, int n_bands,
                                float *spl_db);

/* the energy sum of the mechanisms' levels in each band: total_db[k] */
void aero_airfoil_noise_total(const float *spl_db, int n_bands,
                              float *total_db);

/* the standard one-third-octave centre frequencies (IEC 61260's base-ten
   series, 10^(n/10) Hz, exact rather than the rounded names) from
   lo_hz to hi_hz (a band named by an end counts: 20 Hz gives 19.95 Hz):
   how many written to band_hz (at most max) */
int aero_third_octave_bands(float lo_hz, float hi_hz, float *band_hz,
                            int max);

#endif
