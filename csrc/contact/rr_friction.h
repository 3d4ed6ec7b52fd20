/*
 * rr_friction.h - friction laws: Coulomb and Polach's falling friction.
 *
 * Reference: O. Polach, "Creep forces in simulations of traction vehicles
 * running on adhesion limit", Wear 258 (2005) 992-1000:
 *     mu(w) = mu0 [(1 - A) exp(-B w) + A],
 * w the magnitude of the slip velocity [m/s].  A = 1 (or B = 0) is Coulomb
 * friction.  CONTACT's exponential law is the same curve with
 * mu_kin = A mu0, mu_exp = (1 - A) mu0, half-value slip speed ln 2 / B.
 */
#ifndef RR_FRICTION_H
#define RR_FRICTION_H

typedef struct {
    double mu0;  /* static friction coefficient (at zero slip), > 0 */
    double A;    /* ratio of the limit friction at infinite slip to mu0, 0 < A <= 1 */
    double B;    /* exponential decay rate [s/m], >= 0 */
} rr_friction;

/* Largest mu0 and B accepted (no physical law comes near). */
#define RR_FRICTION_MAX 1e100

/*
 * rr_friction_check - 0 if the law is valid, else RR_ERR_NONFINITE,
 * RR_ERR_FRICTION (mu0 <= 0, A outside (0, 1], B < 0), RR_ERR_RANGE (mu0 or
 * B above RR_FRICTION_MAX: forces or slopes would overflow), RR_ERR_NULL.
 * A > 0 keeps mu positive at any slip speed.
 */
int rr_friction_check(const rr_friction *f);

/* 1 if the coefficient falls with slip (A < 1 and B > 0), else 0. */
int rr_friction_is_falling(const rr_friction *f);

/* mu at slip speed w >= 0 [m/s] (w may be +inf); NaN if f is NULL. */
double rr_friction_mu(const rr_friction *f, double w);

/* d mu / d w at slip speed w >= 0 [s/m]; <= 0; NaN if f is NULL. */
double rr_friction_dmu(const rr_friction *f, double w);

#endif
