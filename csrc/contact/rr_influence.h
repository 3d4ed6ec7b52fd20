/*
 * rr_influence.h - influence coefficients of the elastic half-space for
 * piecewise-constant tractions on a rectangular grid (Kalker's exact theory).
 *
 * Two quasi-identical bodies (the same material, or (1-2nu1)/G1 =
 * (1-2nu2)/G2): the normal and tangential problems decouple and only four
 * coefficients are used.  For a unit traction on the element centred at the
 * origin (size dx x dy) the displacement difference u = u1 - u2 at the
 * centre of element (kx, ky) is A(kx, ky)/G, with (Love 1929; Kalker 1990,
 * ch. 1; the primitives integrated over the element, [[F]] the sum over its
 * four corners with signs + - - +):
 *   A_nn = (1-nu)/pi [[X log(Y+r) + Y log(X+r)]]
 *   A_xx = 1/pi [[(1-nu) X log(Y+r) + Y log(X+r)]]
 *   A_yy = 1/pi [[X log(Y+r) + (1-nu) Y log(X+r)]]
 *   A_xy = A_yx = -nu/pi [[r]]
 * All are in metres.  A_nn, A_xx, A_yy are even in kx and ky; A_xy is odd
 * in both.  The three primitives' boxes are what this module tabulates:
 *   ta = [[X log(Y+r)]],  tb = [[Y log(X+r)]],  tr = [[r]],
 * so that every coefficient, for any nu, is a sum of them.
 */
#ifndef RR_INFLUENCE_H
#define RR_INFLUENCE_H

/*
 * rr_influence_boxes - ta, tb, tr at the offsets kx = 0 .. nkx - 1,
 * ky = 0 .. nky - 1 (one quadrant: the other three follow by symmetry),
 * stored at ky * nkx + kx.
 *   given:   nkx, nky >= 1; dx, dy > 0 [m], finite, dx/dy within 1e-6 .. 1e6
 *   returns: ta, tb, tr [m]; tr is odd-odd, so it holds the value for
 *            kx, ky >= 0 (use sign(kx) sign(ky) elsewhere; 0 on the axes)
 *   status:  0 OK; RR_ERR_GRID (nkx, nky < 1), RR_ERR_GEOMETRY (dx, dy not
 *            positive, or too elongated), RR_ERR_NONFINITE, RR_ERR_NULL
 *   work: none.  Costs (nkx + 1) (nky + 1) corner evaluations (two
 *   logarithms and a square root each).
 */
int rr_influence_boxes(int nkx, int nky, double dx, double dy, double *ta, double *tb,
                       double *tr);

/* One coefficient set at one offset, from the primitives directly (a slow,
 * plain reference for the tables): an[0..3] = A_nn, A_xx, A_yy, A_xy [m]. */
int rr_influence_at(int kx, int ky, double dx, double dy, double nu, double an[4]);

#endif
