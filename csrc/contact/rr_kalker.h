/*
 * rr_kalker.h - Kalker's creep coefficients C11, C22, C23 of the linear
 * theory of rolling contact for a Hertzian ellipse.
 *
 * Reference: J. J. Kalker, Three-Dimensional Elastic Bodies in Rolling
 * Contact, Kluwer 1990, Table E.3 (values at g = 0.1 ... 1, nu = 0, 0.25,
 * 0.5) and the asymptotic formulas for g -> 0 of Kalker's thesis (1967) as
 * used by E. Vollebregt's CONTACT (m_hertz.f90, linrol).
 */
#ifndef RR_KALKER_H
#define RR_KALKER_H

typedef struct {
    double c11, c22, c23;
} rr_kalker_coeffs;

/*
 * rr_kalker - creep coefficients for ellipticity a/b and Poisson ratio nu.
 *   given:   a_over_b  semi-axis along the rolling direction over the
 *                      lateral one, > 0;  g = min(a/b, b/a)
 *            nu        Poisson ratio, 0 <= nu <= 0.5 (0.5: incompressible,
 *                      the table's third column)
 *   returns: *out, with the linear theory
 *              Fx = -G c^2 C11 xi,  Fy = -G c^2 C22 eta - G c^3 C23 phi,
 *              c = sqrt(ab)
 *   status:  0 OK; RR_ERR_NONFINITE, RR_ERR_GEOMETRY (a/b <= 0),
 *            RR_ERR_MATERIAL (nu outside [0, 0.5]), RR_ERR_RANGE (a/b so
 *            extreme that a coefficient overflows), RR_ERR_NULL (out NULL)
 *   Method: for 0.1 <= g <= 1, Table E.3 interpolated linearly in g on C at
 *   each tabulated nu, then a parabola through 1/C at nu = 0, 0.25, 0.5
 *   (exact at every node).  For g < 0.1, Kalker's asymptotic formulas; they
 *   meet the table at g = 0.1 within about 6 % (C23 for a << b as nu -> 0.5;
 *   C11 for a << b at nu = 0: 2.47 against 2.51).
 */
int rr_kalker(double a_over_b, double nu, rr_kalker_coeffs *out);

#endif
