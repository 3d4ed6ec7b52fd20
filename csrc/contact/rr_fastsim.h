/*
 * rr_fastsim.h - Kalker's FASTSIM and its variants.
 *
 * References:
 *   J. J. Kalker, "A fast algorithm for the simplified theory of rolling
 *   contact", Vehicle System Dynamics 11 (1982) 1-13 (three flexibilities,
 *   parabolic traction bound, strip-wise march from the leading edge);
 *   E. Vollebregt, P. Voltr, "Improved accuracy for FASTSIM using one or
 *   three flexibility values", Vehicle System Dynamics 61 (2023) 309
 *   (blending from three flexibilities to one as the creepage grows);
 *   M. Spiryagin, O. Polach, C. Cole, "Creep force modelling for rail
 *   traction vehicles based on the Fastsim algorithm", Vehicle System
 *   Dynamics 51 (2013) 1765-1783 (modified FASTSIM).
 *
 * Discretisation: ny rows of width 2b/ny at y_j = -b + (j + 1/2) 2b/ny, each
 * cut into nx equal elements of length h_j with pressure and traction at
 * their centres.  o->grid chooses the rows' extent: RR_GRID_RECT, the
 * ellipse's bounding box |x| <= a (elements outside the ellipse are empty;
 * CONTACT's potential contact area), or RR_GRID_STRIPS, each row's own
 * chord |x| <= a_j = a sqrt(1 - y_j^2/b^2) (Kalker's strips, which converge
 * faster).  The march goes from the leading edge (x = +a): each element
 * adds its rigid slip (taken at its centre) times one element length to
 * its upstream neighbour's traction, the first element inside the contact
 * to zero traction.  This is
 * Kalker's explicit scheme, first order in the grid: on RR_GRID_STRIPS the
 * initial slope is the linear theory's times (1 + 1/nx)(1 + 1/(2 ny^2));
 * on RR_GRID_RECT short rows have fewer elements and the excess is larger
 * and irregular (+6 % at 30 x 30), as in CONTACT's FASTSIM.  The
 * pressure at the element centres is scaled so that it sums to N on the
 * grid: full sliding then gives exactly |F| = mu N.
 *
 * Falling friction, o->slip_speed == RR_SLIP_LOCAL: in a slipping element
 * the slip displacement is L (p - p*), p* the adhesion trial traction, so
 * the slip speed is speed * L_eff (|p*| - g) / h; g = mu(slip speed) p is
 * solved by Newton's method from the kinetic bound (the residual is convex,
 * so the iteration converges monotonically to its unique root).
 * RR_SLIP_RIGID: one mu at the rigid slip speed |(cx, cy)| speed.
 */
#ifndef RR_FASTSIM_H
#define RR_FASTSIM_H

#include "contact/rr_creep_opts.h"

/* The FASTSIM variants' options in rr_creep_opts.v (descriptors
 * rr_method_fastsim, rr_method_fastsim_blended: the first five;
 * rr_method_modified_fastsim: all eight). */
enum {
    RR_FASTSIM_NX = 0,          /* elements along x per row, 1 .. RR_FASTSIM_MAX_GRID */
    RR_FASTSIM_NY = 1,          /* rows (strips), 1 .. RR_FASTSIM_MAX_GRID */
    RR_FASTSIM_BOUND = 2,       /* enum rr_bound */
    RR_FASTSIM_GRID = 3,        /* enum rr_grid */
    RR_FASTSIM_SLIP_SPEED = 4,  /* falling friction: enum rr_slip_speed */
    RR_FASTSIM_K0 = 5,          /* modified: flexibility divided by */
    RR_FASTSIM_ALPHA_INF = 6,   /*   k0 (alpha_inf + (1 - alpha_inf)/(1 + beta eps)) */
    RR_FASTSIM_BETA = 7
};

/* Blended FASTSIM's sixth option (rr_method_fastsim_blended only; the same
 * index as modified FASTSIM's k0, another method's option). */
enum { RR_FASTSIM_BLEND_RULE = 5 };   /* enum rr_blend_rule */

enum rr_blend_rule {
    RR_BLEND_CONTACT = 0,  /* CONTACT's simpflex: w = |(cx, cy)| / |(ch_x, ch_y)| / 3 */
    RR_BLEND_SPIN = 1      /* w = |(cx/ch_x, cy/ch_y, cphi/ch_phi)| / 3 */
};

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

/* The traction field: nx * ny elements (rr_creep_opts.h). */
typedef rr_traction_field rr_fastsim_field;

/*
 * rr_fastsim - creep forces by FASTSIM.
 *   given:   p   the contact problem (the ellipse); o the options with
 *                o->method one of RR_METHOD_FASTSIM, RR_METHOD_FASTSIM_BLENDED,
 *                RR_METHOD_MODIFIED_FASTSIM (the defaults: 30 x 30, RR_GRID_RECT,
 *                RR_BOUND_PARABOLIC, RR_SLIP_LOCAL but RR_SLIP_RIGID for modified
 *                FASTSIM, whose slope reduction was calibrated so; k0 = 0.54,
 *                alpha_inf = 0.02, beta = 0.62 after CONTACT's user guide and
 *                Spiryagin et al. 2013)
 *            field  NULL, or buffers for the traction field
 *   returns: *out (and *field)
 *   status:  0 OK; RR_WARN_NOT_CONVERGED (falling-friction iteration hit
 *            its cap in some element; results usable); errors as
 *            rr_creep_prepare (RR_ERR_PATCH for a grid problem,
 *            rr_contact_problem_check's), rr_method_check,
 *            RR_ERR_METHOD (not a FASTSIM method), RR_ERR_SPEED (falling
 *            friction with speed 0), RR_ERR_RANGE (the bound mu p outside
 *            [1e-80, 1e100] Pa, a rigid-slip increment over 1e150 Pa per
 *            element, elements of subnormal size: no physical case),
 *            RR_ERR_NULL (p, o or out NULL).  On error the forces and
 *            the field (where o gives its size) are NaN.
 *   Flexibilities (Kalker 1982): L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G),
 *   L3 = pi a sqrt(a/b)/(4 C23 G).
 *   Blended: with characteristic creepages ch_x = mu0 N / (G c^2 C11),
 *   ch_y = mu0 N / (G c^2 C22), ch_phi = mu0 N / (G c^3 C23), the weight
 *   w = min(1, f/3) blends each L_i toward the single flexibility
 *   L = (cx^2 + cy^2 + pe^2)/(cx^2/L1 + cy^2/L2 + pe^2/L3), pe = 3 pi a cphi/32
 *   (spin enters L under either rule), L_i' = (1 - w) L_i + w L, where
 *   o->v[RR_FASTSIM_BLEND_RULE] chooses f:
 *     RR_BLEND_CONTACT (the default): f = |(cx, cy)| / |(ch_x, ch_y)|, no
 *       spin (CONTACT's m_hertz simpflex, as shipped: its blended FASTSIM
 *       to the plain FASTSIM's grid-convention level, p95 0.01 mu N at 45
 *       across); nearer the exact theory than RR_BLEND_SPIN, with spin and
 *       without (tests/test_blend_rule.py);
 *     RR_BLEND_SPIN: f = |(cx/ch_x, cy/ch_y, cphi/ch_phi)|, each creepage
 *       over its own characteristic one, spin too (the library's rule
 *       before issue 14).
 *   Either f is dimensionless (independent of the unit of length).  CONTACT
 *   also floors f at 1e-10 and the denominator of L at 1e-14 (its units);
 *   here w = 0 leaves the L_i as they are (a weight of 3e-11 changes no
 *   force beyond rounding), and a creepage below 1e-154, whose square
 *   underflows, still makes L 0/0 (NaN forces: the fuzzers' known
 *   "blended").
 *   Modified: all L_i divided by k = k0 (alpha_inf + (1-alpha_inf)/(1 + beta eps)),
 *   eps = pi G a b k0 C11 |(cx, cy + a cphi)| / (4 mu N) with mu at the
 *   rigid slip speed (CONTACT's fastsim_params).
 */
int rr_fastsim(const rr_contact_problem *p, const rr_creep_opts *o, rr_forces *out,
               rr_fastsim_field *field);

#endif
