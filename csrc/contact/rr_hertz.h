/*
 * rr_hertz.h - Hertz's solution for two elastic bodies in elliptic contact.
 *
 * Reference: K. L. Johnson, Contact Mechanics, Cambridge 1985, section 4.2,
 * eq. (4.33)-(4.41); elliptic integrals by Carlson's method (rr_elliptic.h).
 */
#ifndef RR_HERTZ_H
#define RR_HERTZ_H

typedef struct {
    double a;      /* semi-axis along x, the rolling direction [m] */
    double b;      /* semi-axis along y, lateral [m] */
    double p0;     /* peak pressure 3N/(2 pi a b) [Pa] */
    double delta;  /* approach of distant points of the two bodies [m] */
} rr_hertz_result;

/*
 * rr_estar - contact modulus E* with 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 [Pa].
 *   Returns NaN unless E1, E2 > 0 and 0 <= nu1, nu2 <= 0.5 (all finite) and
 *   E* is a positive double (a subnormal modulus would overflow 1/E).
 */
double rr_estar(double E1, double nu1, double E2, double nu2);

/*
 * rr_hertz - semi-axes, peak pressure and approach of a Hertzian contact.
 *   given:   A, B  curvature sums [1/m]: the gap is h = A x^2 + B y^2, so
 *                  A = (1/R1x + 1/R2x)/2 along the rolling direction and
 *                  B = (1/R1y + 1/R2y)/2 laterally; both > 0, either larger
 *            N     normal load [N], > 0
 *            estar contact modulus E* [Pa] (rr_estar), > 0
 *   returns: *out; the long axis lies along the smaller curvature sum
 *   status:  0 OK; RR_ERR_NONFINITE, RR_ERR_GEOMETRY (A or B <= 0, or a
 *            ratio max/min above 1e250),
 *            RR_ERR_LOAD (N <= 0), RR_ERR_MATERIAL (E* <= 0 or NaN),
 *            RR_ERR_RANGE (a, b, p0 or delta would overflow or underflow:
 *            curvatures, load and modulus too extreme together),
 *            RR_ERR_NULL (out NULL)
 *   The ellipticity k = minor/major solves
 *     max(A,B)/min(A,B) = (E(e)/k^2 - K(e)) / (K(e) - E(e)),  e^2 = 1 - k^2,
 *   written with Carlson's integrals so that no difference cancels; the
 *   solve is a safeguarded secant in ln k to full double precision.
 */
int rr_hertz(double A, double B, double N, double estar, rr_hertz_result *out);

/*
 * rr_hertz_bodies - rr_hertz for two bodies given by their moduli: E1, nu1
 *   and E2, nu2 as for rr_estar.  Bodies without a contact modulus are
 *   RR_ERR_MATERIAL whatever A, B and N are (the materials are judged
 *   first); otherwise as rr_hertz.  Outputs NaN on any error.
 */
int rr_hertz_bodies(double A, double B, double N, double E1, double nu1, double E2, double nu2,
                    rr_hertz_result *out);

/*
 * rr_hertz_curvatures - the inverse of rr_hertz: the curvature sums A (along
 * x) and B of the Hertzian contact with semi-axes a (along x) and b under
 * load N, contact modulus estar (Johnson eq. 3.64).  rr_hertz(A, B, N,
 * estar) gives a and b back.
 *   status: 0 OK; RR_ERR_NONFINITE, RR_ERR_GEOMETRY (a, b not positive
 *   normal numbers, or min/max below 1e-150), RR_ERR_LOAD (N <= 0),
 *   RR_ERR_MATERIAL (estar <= 0), RR_ERR_RANGE (A or B not a normal double),
 *   RR_ERR_NULL.  Outputs NaN on error.
 */
int rr_hertz_curvatures(double a, double b, double N, double estar, double *A, double *B);

#endif
