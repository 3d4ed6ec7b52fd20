/*
 * rr_kalker.h - Kalker's creep and spin coefficients C11, C22, C23, C33 of
 * the linear theory of rolling contact for a Hertzian ellipse.
 *
 * Reference: J. J. Kalker, Three-Dimensional Elastic Bodies in Rolling
 * Contact, Kluwer 1990, Table E.3 (values at g = 0.1 ... 1, nu = 0, 0.25,
 * 0.5); C11, C22, C23 as transcribed in E. Vollebregt's CONTACT
 * (m_hertz.f90, linrol), C33, which CONTACT does not carry, as transcribed
 * in OpenVSD (WRcontForce.cpp; a single transcription, checked against
 * nothing but the strip-theory limit below).  The asymptotic formulas for
 * g -> 0 of C11, C22, C23 are Kalker's thesis (1967) as used by CONTACT.
 */
#ifndef RR_KALKER_H
#define RR_KALKER_H

typedef struct {
    double c11, c22, c23, c33;
} rr_kalker_coeffs;

/*
 * rr_kalker - creep coefficients for ellipticity a/b and Poisson ratio nu.
 *   given:   a_over_b  semi-axis along the rolling direction over the
 *                      lateral one, > 0;  g = min(a/b, b/a)
 *            nu        Poisson ratio, 0 <= nu <= 0.5 (0.5: incompressible,
 *                      the table's third column)
 *   returns: *out, with the linear theory
 *              Fx = -G c^2 C11 xi,  Fy = -G c^2 C22 eta - G c^3 C23 phi,
 *              Mz = G c^3 C23 eta - G c^4 C33 phi,  c = sqrt(ab)
 *   status:  0 OK; RR_ERR_NONFINITE, RR_ERR_GEOMETRY (a/b <= 0),
 *            RR_ERR_MATERIAL (nu outside [0, 0.5]), RR_ERR_RANGE (a/b so
 *            extreme that a coefficient overflows: C23 for a/b beyond
 *            ~1e205, C33 for a subnormal a/b below ~5e-309), RR_ERR_NULL
 *            (out NULL); on an error all four are NaN
 *   Method: for 0.1 <= g <= 1, Table E.3 interpolated linearly in g on C at
 *   each tabulated nu, then a parabola through 1/C at nu = 0, 0.25, 0.5
 *   (exact at every node).  For g < 0.1, Kalker's asymptotic formulas for
 *   C11, C22, C23; they meet the table at g = 0.1 within about 6 % (C23 for
 *   a << b as nu -> 0.5; C11 for a << b at nu = 0: 2.47 against 2.51).
 *   CONTACT has no asymptote for C33, so below g = 0.1 it is continued,
 *   continuous at g = 0.1 and decreasing in a/b like the table:
 *     a << b: strip theory (each lateral strip a 2-D Carter contact under
 *       the creepage -phi y; it gives CONTACT's C11 and C22 asymptotes
 *       exactly) gives C33 ~ pi^2 / (16 (1 - nu) g); that plus the constant
 *       that makes it meet the table at g = 0.1 (+0.25, +0.06, -0.64 at nu =
 *       0, 0.25, 0.5: the leading term is 3.9 %, 0.7 %, 5.4 % off the
 *       table there).
 *     a >> b: C33 held at its value at g = 0.1.  A slender-contact estimate
 *       says C33 tends to a finite limit (pi/4 = 0.785 at nu = 0, against
 *       the table's 0.795 at g = 0.1), not to 0 like the simplified
 *       theory's 32/(15 pi) C23 g^(3/2); the limit for nu > 0 is not known
 *       here, and the table still falls there (0.341 to 0.228 from g = 0.2
 *       to 0.1 at nu = 0.5), so below g = 0.1 this C33 is likely an
 *       overestimate whose error grows with nu.
 */
int rr_kalker(double a_over_b, double nu, rr_kalker_coeffs *out);

/*
 * rr_kalker_flexibilities - the simplified theory's flexibilities [m/Pa]
 * that reproduce Kalker's linear theory (Kalker 1982, FASTSIM):
 *   L[0] = 8a / (3 C11 G), L[1] = 8a / (3 C22 G),
 *   L[2] = pi a sqrt(a/b) / (4 C23 G)   (spin)
 * for semi-axes a (rolling direction), b, modulus G and coefficients k.
 * No checks: the callers pass values they checked (NaN in, NaN out).
 */
void rr_kalker_flexibilities(double a, double b, double G, const rr_kalker_coeffs *k,
                             double L[3]);

#endif
