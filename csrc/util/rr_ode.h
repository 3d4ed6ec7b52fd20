/*
 * rr_ode.h - fixed-step, L-stable integrators for small stiff systems
 * y' = f(t, y), n <= RR_ODE_MAXN, for a real-time loop.
 *
 * Every step of a given method, n and Jacobian source costs the same: a
 * fixed number of f evaluations (below), at most one Jacobian, one dense LU
 * factorisation with partial pivoting of W = I - gamma h J and a fixed number
 * of triangular solves.  No step size control, no allocation (all work
 * arrays are inside the caller-owned rr_ode, about 18 kB), no globals.
 *
 * Methods (gamma multiplies h J in the iteration matrix W = I - gamma h J):
 *
 *   RR_ODE_ROS2 - the two-stage Rosenbrock-W method of J. G. Verwer,
 *     E. J. Spee, J. G. Blom, W. Hundsdorfer, "A second-order Rosenbrock
 *     method applied to photochemical dispersion problems", SIAM J. Sci.
 *     Comput. 20 (1999) 1456-1480:
 *         W k1 = f(t, y)
 *         W k2 = f(t + h, y + h k1) - 2 k1
 *         y1   = y + h (3/2 k1 + 1/2 k2),      gamma = 1 + 1/sqrt(2).
 *     Order 2 for ANY matrix J (a W-method) in the classical sense
 *     (h |J| small); L-stable when J is the exact Jacobian.  In the stiff
 *     regime (h |lambda| >> 1) a J whose stiff block is off (e.g. d f_fast /
 *     d y_fast by 20 %) drops the order to 1 (measured on van der Pol), but
 *     the step stays stable: with J = (1 + e) df/dy, |R(inf)| < 1 for all
 *     e > -0.85 (R(inf) = 1 + 2 s + s^2/2, s = -1/(gamma (1 + e))).
 *     df/dt is not used: with a stiff t-dependent forcing (Prothero-Robinson)
 *     the order drops to 1; appending t to the state (t' = 1, with its
 *     Jacobian column) restores 2.
 *     Cost: 2 f + 1 Jacobian + 1 LU + 2 solves.
 *
 *   RR_ODE_TRBDF2 - TR-BDF2 of R. E. Bank, W. M. Coughran, W. Fichtner,
 *     E. H. Grosse, D. J. Rose, R. K. Smith, IEEE Trans. CAD 4 (1985) 436,
 *     in the one-matrix form of M. E. Hosea, L. F. Shampine, "Analysis and
 *     implementation of TR-BDF2", Appl. Numer. Math. 20 (1996) 21-37
 *     (Simulink's ode23tb): an ESDIRK with gamma_TR = 2 - sqrt(2),
 *     d = gamma_TR / 2 = 1 - sqrt(2)/2, w = sqrt(2)/4,
 *         z2 = y + h (d f(t, y) + d f(t + gamma_TR h, z2))        (trapezoid)
 *         z3 = y + h (w f(t, y) + w f2 + d f(t + h, z3))          (BDF2)
 *         y1 = z3                      (stiffly accurate, L-stable, order 2)
 *     Both stages share W = I - d h J.  Each stage starts with a
 *     predictor correction that needs no f evaluation (z2: from y with
 *     f(t, y); z3: from z2 with f2), then takes exactly s->newton_iters
 *     simplified-Newton iterations with the true residual.  With
 *     newton_iters = 0 the step is linearly implicit: TR-BDF2 applied to
 *     the linearisation f(t, y) + J (z - y), one f evaluation per step,
 *     the stability function of TR-BDF2 (L-stable with the exact J) and
 *     order 2 with the exact Jacobian of an autonomous f (the dropped
 *     terms are O(|z - y|^2) = O(h^2) inside an O(h) stage), 1 otherwise;
 *     newton_err is then 0.  It is fragile where f has a sharp knee (a
 *     creep force saturating): a step that crosses the knee trusts the
 *     slope on its near side and may oscillate about it.  With linear_tr =
 *     1 only the trapezoidal stage is taken linearly, and the BDF2 stage,
 *     which gives y1, iterates newton_iters times with the true f: that
 *     sees such a knee at 1 + newton_iters evaluations.  f2 =
 *     (z2 - y)/(d h) - f(t, y) is the derivative implied by the trapezoidal
 *     equation (Hosea & Shampine), not a fresh f(z2).  The step warns if
 *     the estimated error left in a stage, newton_err, exceeds newton_tol
 *     (the "last correction not small" test).  The fixed iteration count
 *     needs a good J on the stiff modes: with J off by a factor 2 at
 *     h |lambda| = 50 the iteration diverges (and warns); ROS2 does not.
 *     With a model (s->model, see rr_ode_model) the iterations take
 *     f(t, z) = f(t0, y0) + model(t, y0, z) in place of f: a simplified
 *     Newton with a cheap residual, which sees a knee the model has (the
 *     rig: the simplified theory's creep curve anchored at the full
 *     method's value at y0) at one f evaluation per step.  The stages then
 *     solve the model's equations, not f's: the step is as accurate as the
 *     model's change over it.
 *     Cost: 1 + 2 newton_iters f (1 + newton_iters with linear_tr; 1 with a
 *     model, plus as many model calls) + 1 Jacobian + 1 LU + 2
 *     (newton_iters + 1) solves (1 fewer per TR stage iteration left out).
 *
 * Second-order structure: with s->nq > 0 the first nq states are positions
 * whose derivatives are the next nq states, y_i' = y_{nq+i} (i < nq), as in
 * mechanics (RADAU5's M1 = M2 = nq).  Those rows of J are then taken as
 * exactly [0 I 0] and the linear algebra works on n - nq unknowns: the LU
 * costs ((n - nq)/n)^3 of the full one (12 states, nq = 5: 0.2).
 *
 *   RR_ODE_LINEULER - linearly implicit Euler, W k = f(t, y), y1 = y + h k,
 *     gamma = 1: order 1 for any J, L-stable with the exact Jacobian
 *     (with J = (1 + e) df/dy, R(inf) = 1 - 1/(1 + e): stable for e > -0.5).
 *     Cost: 1 f + 1 Jacobian + 1 LU + 1 solve.
 *
 * Jacobian: jac != NULL is called once per step at (t, y); it may be
 * approximate (see each method).  jac == NULL: forward differences, column
 * j with increment delta_j = sqrt(DBL_EPSILON) max(|y_j|, s->ytyp[j]), at
 * the cost of n more f evaluations (f(t, y) is shared with the first
 * stage).
 */
#ifndef RR_ODE_H
#define RR_ODE_H

#define RR_ODE_MAXN 32
#define RR_ODE_MAX_NEWTON 10

enum rr_ode_method {
    RR_ODE_ROS2 = 0,      /* Rosenbrock-W, order 2, L-stable; cheapest order 2 */
    RR_ODE_TRBDF2 = 1,    /* TR-BDF2, order 2, L-stable, fixed Newton count */
    RR_ODE_LINEULER = 2   /* linearly implicit Euler, order 1, L-stable */
};

/*
 * Right-hand side f(t, y) -> dydt[0..n-1], and Jacobian
 * J[i*n + j] = d f_i / d y_j (row-major, n*n).  ctx is passed through
 * untouched.  Return 0, a warning > 0 (passed on by rr_ode_step), or an
 * error < 0 (the step stops and returns it, y unchanged).
 */
typedef int (*rr_ode_rhs)(void *ctx, double t, const double *y, double *dydt);
typedef int (*rr_ode_jac)(void *ctx, double t, const double *y, double *J);

/*
 * A cheap model of f's change over a step (TR-BDF2, optional): df ~
 * f(t, z) - f(t0, y0), y0 being the state at the step's start t0.  Same
 * status convention as f.
 */
typedef int (*rr_ode_model)(void *ctx, double t, const double *y0, const double *z,
                            double *df);

/*
 * Integrator state, owned by the caller (stack, static or embedded in a
 * larger struct).  rr_ode_init sets every field; the settings may be
 * changed between steps, the rest is private.
 */
typedef struct {
    /* settings */
    int n;                       /* dimension, 1..RR_ODE_MAXN */
    int method;                  /* enum rr_ode_method */
    int newton_iters;            /* TR-BDF2: f-evaluating iterations per stage,
                                  * 0..RR_ODE_MAX_NEWTON (default 2); with 1,
                                  * newton_err is the last correction itself;
                                  * 0: linearly implicit (see above) */
    double newton_tol;           /* TR-BDF2: bound on newton_err, else the step
                                  * warns (default 1e-6) */
    int linear_tr;               /* TR-BDF2: 1 = no Newton iteration in the
                                  * trapezoidal stage (default 0) */
    int nq;                      /* second-order structure: y_i' = y_{nq+i} for
                                  * i < nq, 0 <= 2 nq <= n (default 0: none) */
    rr_ode_model model;          /* TR-BDF2: NULL (default), or the Newton
                                  * iterations take f(t, z) = f(t0, y0) +
                                  * model(t, y0, z): one f per step (above) */
    double ytyp[RR_ODE_MAXN];    /* typical magnitude of each y_i (> 0, in y's
                                  * units; default 1): finite-difference
                                  * increment floor and Newton test scale */
    /* statistics of the last step (also after an error) */
    int nfev;                    /* f evaluations */
    int nmev;                    /* model calls */
    int njev;                    /* jac calls (0 or 1) */
    double newton_err;           /* TR-BDF2: estimated error left in the stage
                                  * values after the last iteration, in the
                                  * norm max_i |e_i| / (|z_i| + ytyp_i), the
                                  * larger of the two stages (inf if the
                                  * iteration does not contract); else 0 */
    /* work arrays */
    double W[RR_ODE_MAXN * RR_ODE_MAXN];  /* J, then its LU factors (nq = 0) */
    double M[RR_ODE_MAXN * RR_ODE_MAXN];  /* nq > 0: LU factors of the reduced matrix */
    double g;                    /* gamma h of the factored matrix */
    double y0[RR_ODE_MAXN];      /* copy of y at the start of the step */
    double f0[RR_ODE_MAXN];      /* f(t, y0) */
    double k1[RR_ODE_MAXN];
    double k2[RR_ODE_MAXN];
    double z[RR_ODE_MAXN];
    double r[RR_ODE_MAXN];
    int piv[RR_ODE_MAXN];
} rr_ode;

/*
 * rr_ode_init - set up *s for n equations with the given method and the
 * default settings (newton_iters 2, newton_tol 1e-6, linear_tr 0, nq 0,
 * model NULL, ytyp 1).
 *   status:  0 OK; RR_ERR_PARAM (n outside 1..RR_ODE_MAXN), RR_ERR_NULL,
 *            RR_ERR_METHOD (unknown method).  On error *s is not usable.
 */
int rr_ode_init(rr_ode *s, int n, int method);

/*
 * rr_ode_nfev - f evaluations one step of rr_ode_step makes for these
 * settings (jac_given: 1 if a jac callback is passed, 0 for finite
 * differences); -1 if the settings are invalid.  The count is exact: it
 * does not depend on t, y, h or f.
 */
int rr_ode_nfev(const rr_ode *s, int jac_given);

/*
 * rr_ode_step - advance y from t to t + h by one step of s->method.
 *   given:   f   right-hand side; jac its (possibly approximate) Jacobian
 *                or NULL for forward differences; ctx passed to both
 *            t   time at the start of the step; h > 0 step [s]
 *            y   state at t, n values (in), state at t + h (out)
 *   status:  0 OK; RR_WARN_NOT_CONVERGED (TR-BDF2: the Newton error
 *            estimate newton_err exceeded newton_tol; y is still advanced),
 *            or the largest warning returned by f or jac;
 *            errors, with y left unchanged (not NaN: it is the integrator's
 *            state, and the caller may retry with a smaller h):
 *            RR_ERR_NULL (s, f or y NULL), RR_ERR_PARAM (h not > 0, or bad
 *            settings: n, newton_iters, newton_tol <= 0, linear_tr, nq,
 *            ytyp <= 0), RR_ERR_METHOD, RR_ERR_NONFINITE (t, h or y not
 *            finite, or f, J or W not finite), RR_ERR_RANGE (the new y
 *            overflows), RR_ERR_SINGULAR (W = I - gamma h J singular to
 *            working precision), or the status < 0 returned by f or jac.
 */
int rr_ode_step(rr_ode *s, rr_ode_rhs f, rr_ode_jac jac, void *ctx, double t, double h,
                double *y);

/*
 * rr_lu_factor, rr_lu_solve - dense LU with partial pivoting, in place.
 *   A is n x n row-major; on return it holds L (unit diagonal, below) and
 *   U, U's diagonal as its reciprocals; piv[k] is the row swapped with row k at elimination step k.
 *   rr_lu_factor status: 0 OK; RR_ERR_SINGULAR if a pivot is not larger than
 *   n DBL_EPSILON times the largest |A_ij| (or A is zero); RR_ERR_NONFINITE;
 *   RR_ERR_PARAM (n outside 1..RR_ODE_MAXN); RR_ERR_RANGE (the factors
 *   overflow: entries near the largest double); RR_ERR_NULL.  rr_lu_solve does
 *   nothing for NULL arguments or pivots that rr_lu_factor cannot have made.
 *   rr_lu_solve overwrites b (n values) with the solution of A x = b.
 */
int rr_lu_factor(int n, double *A, int *piv);
void rr_lu_solve(int n, const double *LU, const int *piv, double *b);

#endif
