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
 *   status:  0 OK; RR_ERR_NONFINITE or RR_ERR_GEOMETRY (invalid arguments),
 *            RR_ERR_RANGE (a result beyond the double range: R_D ~ m^(-3/2)
 *            for arguments of size m; or the small arguments vanish beside
 *            the large), RR_ERR_NULL
 */
int rr_carlson_rf_rd(double x, double y, double z, double *rf, double *rd);

/*
 * rr_ellip_ke - complete elliptic integrals of the first and second kind,
 *   K(m) = R_F(0, 1-m, 1), E(m) = K - (m/3) R_D(0, 1-m, 1).
 *   given:   mc = 1 - m, the complementary parameter (k'^2), 0 < mc <= 1;
 *            passing mc rather than m keeps full precision as m -> 1.
 *   returns: *K, *E (for mc < 1e-150 their limits ln(4/sqrt(mc)) and 1,
 *            exact in double precision there)
 *   status:  0 OK; RR_ERR_NONFINITE or RR_ERR_GEOMETRY (mc outside (0, 1]),
 *            RR_ERR_NULL
 */
int rr_ellip_ke(double mc, double *K, double *E);

/*
 * rr_ellip_agm - K and the two differences Hertz needs, by the arithmetic-
 * geometric mean of 1 and the complementary modulus kc (Abramowitz and
 * Stegun 17.6): with e^2 = 1 - kc^2 and S = sum_{n>=1} 2^(n-1) c_n^2,
 *   K = pi / (2 AGM(1, kc)),
 *   (K - E) / K = e^2/2 + S,   (E - kc^2 K) / K = e^2/2 - S,
 * neither of which cancels as kc -> 1 (where K - E -> 0).  A handful of
 * square roots, against some twenty for R_F and R_D together.
 *   given:   0 < kc <= 1
 *   returns: *K, *d_lo = (K - E)/K, *d_hi = (E - kc^2 K)/K
 *   status:  0 OK; RR_ERR_NONFINITE or RR_ERR_GEOMETRY (kc outside (0, 1]),
 *            RR_ERR_NULL
 */
int rr_ellip_agm(double kc, double *K, double *d_lo, double *d_hi);

#endif
