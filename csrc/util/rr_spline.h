/*
 * rr_spline.h - cubic splines for profile curves z(s): the interpolating
 * spline of the profiles (rr_spline_fit, the numbers of
 * rollerrig.profiles.Profile, which calls it) and its evaluation.
 *
 * A cubic spline has a continuous second derivative, so the profile
 * curvature that the Hertz module needs is continuous along the profile;
 * the seed paper's parabolic (piecewise quadratic) interpolation makes it
 * jump at every point.  Reference: C. de Boor, A Practical Guide to
 * Splines, 1978, ch. IV (natural end conditions: z'' = 0 at both ends).
 */
#ifndef RR_SPLINE_H
#define RR_SPLINE_H

typedef struct {
    int n;             /* number of knots, >= 2 */
    const double *s;   /* knots, strictly increasing [m] */
    const double *z;   /* values at the knots [m] */
    const double *m;   /* second derivatives at the knots (rr_spline_init) [1/m] */
} rr_spline;

/*
 * rr_spline_init - second derivatives of the natural cubic spline.
 *   given:   n >= 2 knots s (strictly increasing) and values z; work, a
 *            caller buffer of n doubles
 *   returns: m[n], the second derivatives at the knots
 *   status:  0 OK; RR_ERR_NONFINITE, RR_ERR_GEOMETRY (n < 2 or s not
 *            strictly increasing), RR_ERR_WORKSPACE (m or work NULL),
 *            RR_ERR_RANGE (a second derivative overflows), RR_ERR_NULL (s or
 *            z NULL)
 */
int rr_spline_init(int n, const double *s, const double *z, double *m, double *work);

/*
 * rr_spline_check - 0 if sp is a usable spline: pointers set, n >= 2, knots
 * strictly increasing, all values finite; else RR_ERR_NULL,
 * RR_ERR_GEOMETRY or RR_ERR_NONFINITE.  O(n): for callers that take a
 * spline from elsewhere (rr_contact_search checks its profiles with it).
 */
int rr_spline_check(const rr_spline *sp);

/*
 * rr_spline_eval - value and first two derivatives at s (binary search).
 *   status:  0 OK; RR_ERR_GEOMETRY (s outside [s_0, s_(n-1)]: off the
 *            profile; or n < 2), RR_ERR_NONFINITE, RR_ERR_NULL (sp, its
 *            arrays or z NULL); outputs NaN on error.
 *   d1, d2 may be NULL.  The knots are not checked here (O(1) per call):
 *   rr_spline_check does that once.
 */
int rr_spline_eval(const rr_spline *sp, double s, double *z, double *d1, double *d2);

/*
 * rr_spline_eval_at - rr_spline_eval with a hint: *k is the knot interval
 * of the last evaluation (-1: none), updated; a scan along s then finds its
 * interval in O(1) instead of by bisection.  Same results.
 */
int rr_spline_eval_at(const rr_spline *sp, double s, int *k, double *z, double *d1, double *d2);

/* End conditions of rr_spline_fit. */
enum rr_spline_end {
    RR_SPLINE_NOT_A_KNOT = 0,  /* z''' continuous at the second and the last-but-one knot */
    RR_SPLINE_NATURAL = 1      /* z'' = 0 at both ends */
};

/* Points of a fitted profile spline, as rollerrig.profiles.MIN_POINTS and
 * MAX_POINTS (more than any measured profile has). */
#define RR_SPLINE_MIN_POINTS 4
#define RR_SPLINE_MAX_POINTS 100000

/*
 * rr_spline_fit - the C2 cubic spline through (y_i, z_i), the one
 * rollerrig.profiles.Profile uses (it calls this function): the node slopes
 * s_i from the continuity of z'' (a tridiagonal system, the not-a-knot end
 * rows eliminated into their neighbours so that it stays diagonally
 * dominant), then on [y_i, y_i+1], t = y - y_i,
 *     z = z_i + t (s_i + t (c2_i + t c3_i)).
 *   given:   n in [RR_SPLINE_MIN_POINTS, RR_SPLINE_MAX_POINTS] points, y
 *            strictly increasing; end an rr_spline_end; work, n doubles
 *   returns: slope[n], c2[n-1], c3[n-1]
 *   status:  0 OK; RR_ERR_NULL (y or z NULL), RR_ERR_WORKSPACE (slope, c2,
 *            c3 or work NULL), RR_ERR_PARAM (n out of range, end unknown),
 *            RR_ERR_NONFINITE, RR_ERR_GEOMETRY (y not strictly increasing),
 *            RR_ERR_RANGE (a coefficient not finite: points far too close
 *            for their values, an interval so long, beyond 5e102, that
 *            its cube overflows, or a term c2 h^2 or c3 h^3 that overflows
 *            over its interval; or, at the other end, a coefficient or slope
 *            that underflows below DBL_MIN and keeps too few digits to give
 *            the spline).  On error the outputs it can reach are NaN.
 */
int rr_spline_fit(int n, const double *y, const double *z, int end, double *slope,
                  double *c2, double *c3, double *work);

/*
 * rr_spline_knot_d2 - the second derivatives at the knots of a fitted
 * spline, as its coefficients give them (2 c2_i at y_i, 2 c2 + 6 c3 h at
 * the last knot): the m of an rr_spline for the same curve.
 *   status:  0 OK; RR_ERR_NULL (y, c2 or c3 NULL), RR_ERR_WORKSPACE (d2
 *            NULL), RR_ERR_PARAM (n out of range), RR_ERR_RANGE (a second
 *            derivative not finite: coefficients near DBL_MAX; d2 NaN)
 */
int rr_spline_knot_d2(int n, const double *y, const double *c2, const double *c3, double *d2);

#endif
