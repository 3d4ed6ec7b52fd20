/*
 * rr_spline.h - natural cubic splines for profile curves z(s).
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

#endif
