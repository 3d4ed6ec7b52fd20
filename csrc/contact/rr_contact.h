/*
 * rr_contact.h - the inputs and outputs shared by every creep-force method.
 *
 * Conventions (Kalker's, as CONTACT's): x rolling direction, y lateral, z
 * the normal into the wheel; material enters the patch at x = +a.  The
 * creepages are the slip of the wheel relative to the roller (or rail)
 * divided by the rolling speed; with spin the rigid slip at (x, y) is
 * (cx - cphi y, cy + cphi x).  Forces act ON THE WHEEL: for small creepage
 * fx = -G a b C11 cx.  mz = sum of (x py - y px) dA about the patch centre.
 */
#ifndef RR_CONTACT_H
#define RR_CONTACT_H

typedef struct {
    double a, b;    /* semi-axes [m]: a along the rolling direction, b lateral */
    double N;       /* normal load [N] */
    double G;       /* combined shear modulus [Pa] */
    double nu;      /* combined Poisson ratio, 0 <= nu <= 0.5 */
    double cx, cy;  /* longitudinal and lateral creepage xi, eta [-] */
    double cphi;    /* spin creepage phi [rad/m] */
    double speed;   /* rolling speed [m/s] >= 0; needed (> 0) by falling friction */
} rr_contact_case;

typedef struct {
    double fx, fy;  /* tangential forces on the wheel [N] */
    double mz;      /* spin moment on the wheel about the patch centre [N m] */
} rr_forces;

/*
 * rr_contact_check - 0 if the case is valid, else RR_ERR_NONFINITE,
 * RR_ERR_GEOMETRY (a, b <= 0), RR_ERR_LOAD (N <= 0), RR_ERR_MATERIAL
 * (G <= 0, nu outside [0, 0.5]), RR_ERR_SPEED (speed < 0), RR_ERR_RANGE (a,
 * b, N or G subnormal: too few digits for a force) or RR_ERR_NULL.
 */
int rr_contact_check(const rr_contact_case *c);

/* Set all outputs to NaN (error path; f may be NULL). */
void rr_forces_nan(rr_forces *f);

/* st, or RR_ERR_RANGE with NaN forces where a success status would carry a
 * non-finite force (a result beyond the floating-point range). */
int rr_forces_checked(int st, rr_forces *f);

#endif
