/*
 * rr_creep.h - creep forces of a Hertzian contact by the method of choice:
 * Kalker's linear theory, FASTSIM and its variants, Polach's method.
 *
 * Every method takes an rr_contact_case (rr_contact.h: semi-axes, load,
 * material, creepages, rolling speed), a friction law (rr_friction.h) and
 * options, and returns the forces on the wheel.
 */
#ifndef RR_CREEP_H
#define RR_CREEP_H

#include "contact/rr_contact.h"
#include "contact/rr_friction.h"
#include "contact/rr_kalker.h"

enum rr_method {
    RR_METHOD_LINEAR = 0,           /* Kalker's linear theory: no saturation */
    RR_METHOD_FASTSIM = 1,          /* Kalker 1982: three flexibilities */
    RR_METHOD_FASTSIM_BLENDED = 2,  /* flexibilities blended from three to one
                                       (Vollebregt and Voltr 2023) */
    RR_METHOD_MODIFIED_FASTSIM = 3, /* Spiryagin, Polach and Cole 2013 */
    RR_METHOD_POLACH = 4            /* Polach 1999/2005, with spin */
};
#define RR_METHOD_COUNT 5

enum rr_bound {
    RR_BOUND_PARABOLIC = 0,  /* Kalker's original: p ~ 1 - x^2/a^2 - y^2/b^2 */
    RR_BOUND_ELLIPTIC = 1    /* Hertzian: p ~ sqrt(1 - x^2/a^2 - y^2/b^2) */
};

enum rr_grid {
    RR_GRID_RECT = 0,    /* nx x ny elements on the ellipse's bounding box; those
                            outside the ellipse are empty (CONTACT's grid) */
    RR_GRID_STRIPS = 1   /* ny strips, each cut into nx elements along its own
                            chord (Kalker's strips; converges faster) */
};

enum rr_slip_speed {
    RR_SLIP_LOCAL = 0,  /* falling friction at each element's own slip speed */
    RR_SLIP_RIGID = 1   /* one friction value at the rigid slip speed
                           |(cx, cy)| speed (Spiryagin et al. 2013, CONTACT) */
};

/* Largest FASTSIM grid dimension accepted (elements along x or strips). */
#define RR_FASTSIM_MAX_GRID 4096

typedef struct {
    int method;                   /* enum rr_method */
    int nx, ny;                   /* FASTSIM: elements along x per row, number of rows */
    int bound;                    /* FASTSIM: enum rr_bound */
    int grid;                     /* FASTSIM: enum rr_grid */
    int slip_speed;               /* FASTSIM with falling friction: enum rr_slip_speed */
    double k0, alpha_inf, beta;   /* modified FASTSIM: flexibility divided by
                                     k0 (alpha_inf + (1 - alpha_inf)/(1 + beta eps)) */
    double kA, kS;                /* Polach: adhesion and slip reduction factors */
} rr_creep_opts;

/*
 * rr_creep_opts_default - defaults for a method: a 30 x 30 rectangular grid
 * with the parabolic bound (Kalker's original); falling friction at the local slip
 * speed, except for modified FASTSIM, whose slope reduction was calibrated
 * with friction at the rigid slip speed; modified FASTSIM's k0 = 0.54,
 * alpha_inf = 0.02, beta = 0.62 (the example of CONTACT's user guide and
 * Spiryagin et al. 2013); Polach's kA = kS = 1 (his 1999 method).
 */
void rr_creep_opts_default(int method, rr_creep_opts *o);

/*
 * rr_creep_opts_check - 0, or RR_ERR_METHOD (method, bound, grid or
 * slip_speed unknown), RR_ERR_GRID (nx, ny outside [1, RR_FASTSIM_MAX_GRID]),
 * RR_ERR_NONFINITE,
 * RR_ERR_PARAM (k0 outside (0, 1], alpha_inf outside [0, 1], beta < 0,
 * not 0 < kS <= kA <= 1: Polach's condition, which keeps |F| <= mu N).  Only the fields the method uses are checked.
 */
int rr_creep_opts_check(const rr_creep_opts *o);

/*
 * rr_creep_prepare - the checks every frictional method starts with, then
 * Kalker's coefficients of the case.
 *   status: rr_contact_check, rr_friction_check, RR_ERR_SPEED (falling
 *   friction needs speed > 0), rr_kalker.
 */
int rr_creep_prepare(const rr_contact_case *c, const rr_friction *fr, rr_kalker_coeffs *k);

/*
 * rr_linear - Kalker's linear theory.
 *   fx = -G c^2 C11 cx,  fy = -G c^2 C22 cy - G c^3 C23 cphi,
 *   mz = G c^3 C23 cy - G c^4 C33 cphi,  c = sqrt(ab).
 *   Kalker's C33 is not in our source table (Kalker 1990, Table E.3 as
 *   transcribed has C11, C22, C23 only); C33 is taken from the simplified
 *   theory with flexibility L3, C33 = 32/(15 pi) C23 (b/a)^(3/2).
 *   status: as rr_contact_check; RR_ERR_RANGE where a force overflows (the
 *   linear theory does not saturate); RR_ERR_NULL.
 */
int rr_linear(const rr_contact_case *c, rr_forces *out);

/*
 * rr_polach - Polach's creep-force method with spin.
 *   References: O. Polach, "A fast wheel-rail forces calculation computer
 *   code", Vehicle System Dynamics 33 Suppl. (1999) 728-739; O. Polach,
 *   Wear 258 (2005) 992-1000 (reduction factors kA, kS, falling friction).
 *   With s_yC = cy + cphi a if that grows |cy| (else cy), s_C = |(cx, s_yC)|,
 *   mu = mu(speed s_C), eps = pi G a b C s_C / (4 N mu),
 *   C = |(C11 cx, C22 cy)| / |(cx, cy)|:
 *     F = 2 N mu / pi [kA eps / (1 + (kA eps)^2) + atan(kS eps)],
 *     fx = -F cx / s_C, fy = -F cy / s_C + F_yS (Polach's spin force).
 *   The force lies along (cx, cy); for small pure cx, pure cy or pure spin
 *   it reproduces Kalker's linear theory times (kA + kS)/2 (with both cx
 *   and cy only its magnitude does).  0 < kS <= kA <= 1 (Polach 2005).
 *   The method gives no spin moment: mz = 0.  The spin force is added
 *   without a bound of its own, so the sum is kept on the friction limit:
 *   |(fx, fy)| <= mu N, mu at the slip speed s_C speed.
 *   status: rr_contact_check, rr_friction_check, RR_ERR_PARAM, RR_ERR_SPEED
 *   (falling friction with speed 0), RR_ERR_RANGE (a force beyond the
 *   floating-point range), RR_ERR_NULL.
 */
int rr_polach(const rr_contact_case *c, const rr_friction *fr, double kA, double kS,
              rr_forces *out);

/*
 * rr_creep_forces - dispatch to the method named in o->method.
 *   The linear theory ignores friction (but refuses an invalid law, as
 *   every method does); FASTSIM variants call rr_fastsim (rr_fastsim.h)
 *   without a traction field.
 */
int rr_creep_forces(const rr_contact_case *c, const rr_friction *fr,
                    const rr_creep_opts *o, rr_forces *out);

#endif
