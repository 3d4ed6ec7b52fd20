/*
 * rr_elliptic.h - Carlson's symmetric elliptic integrals and the complete
 * elliptic integrals K and E built on them.
 *
 * Reference: B. C. Carlson, "Numerical computation of real or complex
 * elliptic integrals", Numerical Algorithms 10 (1995) 13-26.
 */
#ifndef RR_ELLIPTIC_H
#define RR_ELLIPTIC_H

/*
 * rr_carlson_rf_rd - R_F(x, y, z) and R_D(x, y, z) in one duplication loop.
 *   given:   x, y >= 0 (at most one of them zero), z > 0
 *   returns: *rf, *rd, relative error below 1e-15
 *   status:  0 OK; RR_ERR_NONFINITE or RR_ERR_GEOMETRY (invalid arguments)
 */
int rr_carlson_rf_rd(double x, double y, double z, double *rf, double *rd);

/*
 * rr_ellip_ke - complete elliptic integrals of the first and second kind,
 *   K(m) = R_F(0, 1-m, 1), E(m) = K - (m/3) R_D(0, 1-m, 1).
 *   given:   mc = 1 - m, the complementary parameter (k'^2), 0 < mc <= 1;
 *            passing mc rather than m keeps full precision as m -> 1.
 *   returns: *K, *E
 *   status:  0 OK; RR_ERR_NONFINITE or RR_ERR_GEOMETRY (mc outside (0, 1])
 */
int rr_ellip_ke(double mc, double *K, double *E);

#endif
