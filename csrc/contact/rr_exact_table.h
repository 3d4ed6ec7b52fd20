/*
 * rr_exact_table.h - the exact theory's forces from a table (method
 * "exact_table"): the normalised forces of Kalker's exact theory, extrapolated
 * to the continuum, on four uniform axes, interpolated by Catmull-Rom cubics.
 *
 * For quasi-identical bodies and Coulomb friction fx / (mu N), fy / (mu N)
 * and mz / (mu N c) (c = sqrt(ab)) depend only on nu, a/b and
 *     x = cx C11 / s,  y = cy C22 / s,  z = cphi c C11 / s,  s = mu N / (G c^2)
 * (Kalker's coefficients).  Reversing all creepages reverses the forces and
 * the moment; mirroring the patch in y maps (x, y, z) to (x, -y, -z) and
 * (fx, fy, mz) to (fx, -fy, -mz); so the table holds z >= 0, x >= 0 only
 * (and y >= 0 where z = 0), at
 *     log(a/b),  alpha = atan2(hypot(x, y), z),  theta = atan2(y, x),
 *     u = R / (R + r0), R = |(x, y, z)|,
 * u = 0 no force, u = 1 full sliding (rollerrig/exact_table.py builds it).
 * Falling friction: mu taken at the rigid slip speed speed |(cx, cy)|, as
 * modified FASTSIM and CONTACT's FASTSIM do; the forces are then the
 * Coulomb table's at that mu.
 */
#ifndef RR_EXACT_TABLE_H
#define RR_EXACT_TABLE_H

#include "contact/rr_contact.h"
#include "contact/rr_kalker.h"

typedef struct {
    int n[4];             /* nodes along log(a/b), alpha, theta, u; each >= 4 */
    double lo[4], hi[4];  /* the axes' ends, lo < hi */
    double nu;            /* Poisson's ratio it holds */
    double r0;            /* u = R / (R + r0), r0 > 0 */
    int nx;               /* built from nx and 2 nx elements across (a record) */
    const float *v;       /* [n0][n1][n2][n3][3]: fx/(mu N), fy/(mu N), mz/(mu N c) */
} rr_exact_table;

/* the table shipped with the library (rr_exact_table_data.c): nu = 0.28 */
extern const rr_exact_table rr_exact_table_builtin;

/* RR_OK, or RR_ERR_PARAM (fewer than 4 nodes on an axis, lo >= hi, an end or
 * r0 not finite, r0 <= 0, more than 2^28 nodes), RR_ERR_NULL (t or t->v). */
int rr_exact_table_check(const rr_exact_table *t);

/*
 * rr_exact_table_forces - the forces of an ellipse problem from table t.
 *   status: RR_OK; the checks of rr_creep_prepare (RR_ERR_PATCH for a grid
 *   problem); RR_ERR_TABLE (a/b
 *   outside the table's range, nu more than 1e-9 from the table's);
 *   RR_ERR_RANGE (mu N or the saturation scale mu N / (G a b) not a normal
 *   double: inputs some 300 orders of magnitude from a contact's);
 *   rr_exact_table_check's.  |(fx, fy)| <= mu N holds (the interpolation's
 *   overshoot near full sliding is clipped).  Cost: 256 interpolation nodes.
 */
int rr_exact_table_forces(const rr_exact_table *t, const rr_contact_problem *p,
                          rr_forces *out);

/* rr_exact_table_forces with Kalker's coefficients of p's ellipse given
 * (k NULL: computed, as there), for a caller that has them already for
 * the same a/b and nu to rounding (the non-Hertzian patch calibrates its
 * ellipse by them): rr_creep_prepare_given's checks and status. */
int rr_exact_table_forces_kalker(const rr_exact_table *t, const rr_contact_problem *p,
                                 const rr_kalker_coeffs *k, rr_forces *out);

/* Not API: rr_exact_table_forces with the interpolation's sums in the
 * baseline build (on x86-64 with GCC or clang rr_exact_table_forces takes
 * an AVX2 build of them where the processor has it), for the test that
 * both give the same doubles. */
int rr_exact_table_forces_baseline(const rr_exact_table *t, const rr_contact_problem *p,
                                   rr_forces *out);

#endif
