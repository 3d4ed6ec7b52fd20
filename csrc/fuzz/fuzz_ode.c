/*
 * fuzz_ode.c - the integrators: rr_ode_init, rr_ode_nfev and rr_ode_step on
 * a small test system with fuzzed settings, and rr_lu_factor / rr_lu_solve.
 *
 * The test system: y' = A y + c sin(t) + q y^3 (element-wise cube), n <= 32,
 * A's scale (the stiffness) 1e-3 .. 1e6; the Jacobian exact, scaled by a
 * factor (a W-method's approximate J), absent (finite differences) or
 * failing; the TR-BDF2 model the exact change of f.  Any callback may
 * return a warning or an error, or write a NaN, at a call the input names.
 * Settings: method, newton_iters, newton_tol, linear_tr, nq (with A's
 * first nq rows the [0 I 0] that nq promises, or not), ytyp, f or y NULL.
 *
 * Oracles: documented errors for bad settings; after an error y unchanged;
 * after a success y finite, at least the largest warning a callback gave,
 * nfev equal to rr_ode_nfev and to the calls made, njev 0 or 1 as jac is
 * given, nmev the model calls made (0 without a model); a callback's error
 * returned as it was; newton_err >= 0, and 0 for ROS2 and Euler.  LU:
 * with n from the input (including 0 and negative, over a one-element
 * buffer: the function must not read what n does not describe), finite
 * factors and pivots in range after success.
 */
#include "fuzz.h"

#define MAXN RR_ODE_MAXN

typedef struct {
    int n;
    double A[MAXN * MAXN], c[MAXN], q;
    double jac_scale;
    int calls, jac_calls, model_calls;   /* callbacks made */
    int bad_call, bad_status, bad_nan;   /* at callback number bad_call: return / write NaN */
    int worst_warn, first_err;
} sys;

/* A callback's status: the one the input asked for at its call number. */
static int callback_status(sys *c, double *out, int n)
{
    const int k = c->calls + c->jac_calls + c->model_calls - 1;
    int st = RR_OK;
    if (k == c->bad_call) {
        st = c->bad_status;
        if (c->bad_nan)
            out[n - 1] = NAN;
    }
    if (st > c->worst_warn)
        c->worst_warn = st;
    if (st < 0 && c->first_err == 0)
        c->first_err = st;
    return st;
}

static int f_cb(void *ctx, double t, const double *y, double *dydt)
{
    sys *c = (sys *)ctx;
    int i, j;
    c->calls++;
    for (i = 0; i < c->n; i++) {
        double s = c->c[i] * sin(t) + c->q * y[i] * y[i] * y[i];
        for (j = 0; j < c->n; j++)
            s += c->A[i * c->n + j] * y[j];
        dydt[i] = s;
    }
    return callback_status(c, dydt, c->n);
}

static int jac_cb(void *ctx, double t, const double *y, double *J)
{
    sys *c = (sys *)ctx;
    int i, j;
    (void)t;
    c->jac_calls++;
    for (i = 0; i < c->n; i++)
        for (j = 0; j < c->n; j++)
            J[i * c->n + j] = c->jac_scale
                              * (c->A[i * c->n + j] + (i == j ? 3.0 * c->q * y[i] * y[i] : 0.0));
    return callback_status(c, J, c->n * c->n);
}

static int model_cb(void *ctx, double t, const double *y0, const double *z, double *df)
{
    sys *c = (sys *)ctx;
    int i, j;
    (void)t;
    c->model_calls++;
    for (i = 0; i < c->n; i++) {
        double s = c->q * (z[i] * z[i] * z[i] - y0[i] * y0[i] * y0[i]);
        for (j = 0; j < c->n; j++)
            s += c->A[i * c->n + j] * (z[j] - y0[j]);
        df[i] = s;
    }
    return callback_status(c, df, c->n);
}

/* rr_ode_step's documented setting errors. */
static int settings_invalid(const rr_ode *s)
{
    int i;
    if (s->n < 1 || s->n > MAXN)
        return 1;
    if (s->method != RR_ODE_ROS2 && s->method != RR_ODE_TRBDF2 && s->method != RR_ODE_LINEULER)
        return 1;
    if (s->nq < 0 || s->nq > s->n / 2 || (s->linear_tr != 0 && s->linear_tr != 1))
        return 1;
    if (s->method == RR_ODE_TRBDF2
        && (s->newton_iters < 0 || s->newton_iters > RR_ODE_MAX_NEWTON || !(s->newton_tol > 0.0)))
        return 1;
    for (i = 0; i < s->n; i++)
        if (!(s->ytyp[i] > 0.0) || !isfinite(s->ytyp[i]))
            return 1;
    return 0;
}

static int all_finite(const double *v, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

static void check_lu(fz_in *in)
{
    const int n = fz_int(in, 1, MAXN);
    const int size = n >= 1 && n <= MAXN ? n : 1;
    double *A = fz_alloc((size_t)size * size * sizeof *A);
    double *b = fz_alloc((size_t)size * sizeof *b);
    int *piv = fz_alloc((size_t)size * sizeof *piv);
    const double scale = fz_log(in, 1e-3, 1e3);
    int i, st, extreme = 0;

    in->edges = fz_choice(in, 4) == 0;
    for (i = 0; i < size * size; i++)
        A[i] = scale * fz_lin(in, -1.0, 1.0);
    for (i = 0; i < size; i++)
        b[i] = fz_lin(in, -1.0, 1.0);
    in->edges = 1;
    /* known: a pivot below 1/DBL_MAX passes the singularity test (it is
     * relative to the largest entry) and its reciprocal is inf; entries
     * near DBL_MAX overflow the elimination */
    for (i = 0; i < size * size; i++)
        if (A[i] != 0.0 && !(fabs(A[i]) > 1e-290 && fabs(A[i]) < 1e290))
            extreme = 1;
    fz_note("rr_lu_factor(n = %d), A:", n);
    for (i = 0; i < size * size; i++)
        fz_note(" %.17g", A[i]);
    /* known: n < 1 is not refused; n * n overflows for large |n|, and a
     * negative n reads n * n entries of a buffer n does not describe */
    if (n > MAXN || fz_known("lu_n", n < 1)) {   /* n > MAXN: no buffer to match */
        free(A);
        free(b);
        free(piv);
        return;
    }
    st = rr_lu_factor(n, A, piv);
    fz_status("rr_lu_factor", st);
    if (st >= 0 && n >= 1 && n <= MAXN && !fz_known("lu_extreme", extreme)) {
        fz_finite_n("rr_lu_factor", st, "LU", A, n * n);
        for (i = 0; i < n; i++)
            if (piv[i] < i || piv[i] >= n)
                fz_fail("rr_lu_factor: piv[%d] = %d outside [%d, %d]", i, piv[i], i, n - 1);
        rr_lu_solve(n, A, piv, b);
    }
    free(A);
    free(b);
    free(piv);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    sys *c;
    rr_ode *s;
    double y[MAXN], ysave[MAXN], t, h, scale;
    const int big = fz_choice(&in, 8) == 0;
    int n, method, st, i, j, nsteps, k, jac_mode, nfev;
    rr_ode_jac jac;

    if (fz_choice(&in, 8) == 0) {
        check_lu(&in);
        return 0;
    }
    n = fz_int(&in, 1, big ? MAXN : 6);
    method = fz_int(&in, 0, 2);
    s = fz_alloc(sizeof *s);
    c = fz_alloc(sizeof *c);
    st = rr_ode_init(s, n, method);
    fz_status("rr_ode_init", st);
    fz_error("rr_ode_init", st, n < 1 || n > MAXN || method < 0 || method > 2,
             "n or the method is invalid");
    if (st < 0) {
        free(s);
        free(c);
        return 0;
    }
    if (fz_choice(&in, 2)) {
        s->newton_iters = fz_int(&in, 0, RR_ODE_MAX_NEWTON);
        s->newton_tol = fz_log(&in, 1e-12, 1.0);
        s->linear_tr = fz_int(&in, 0, 1);
        s->nq = fz_int(&in, 0, n / 2);
        s->model = fz_choice(&in, 2) ? model_cb : NULL;
        if (fz_choice(&in, 4) == 0)
            for (i = 0; i < n; i++)
                s->ytyp[i] = fz_log(&in, 1e-6, 1e3);
    }
    /* the system */
    c->n = n;
    scale = fz_log(&in, 1e-3, 1e6);
    in.edges = fz_choice(&in, 4) == 0;
    for (i = 0; i < n * n; i++)
        c->A[i] = scale * fz_lin(&in, -1.0, 1.0);
    for (i = 0; i < n; i++) {
        c->A[i * n + i] -= scale * fz_lin(&in, 0.0, 2.0);   /* mostly stable */
        c->c[i] = fz_lin(&in, -1.0, 1.0);
        y[i] = fz_lin(&in, -1.0, 1.0);
    }
    c->q = fz_choice(&in, 2) ? 0.0 : fz_slog(&in, 1e-3, 10.0);
    in.edges = 1;
    if (s->nq > 0 && s->nq <= n / 2 && fz_choice(&in, 4) != 0)
        for (i = 0; i < s->nq; i++)
            for (j = 0; j < n; j++)
                c->A[i * n + j] = j == s->nq + i ? 1.0 : 0.0;   /* positions' rows */
    jac_mode = fz_choice(&in, 4);
    c->jac_scale = jac_mode == 2 ? fz_lin(&in, 0.5, 2.0) : 1.0;
    jac = jac_mode == 0 ? NULL : jac_cb;
    c->bad_call = fz_choice(&in, 2) ? -1 : fz_range(&in, 0, 40);
    c->bad_status = fz_range(&in, RR_STATUS_MIN, RR_STATUS_MAX);
    c->bad_nan = fz_choice(&in, 4) == 0;
    t = fz_lin(&in, 0.0, 10.0);
    h = fz_log(&in, 1e-6, 1.0);
    nsteps = fz_range(&in, 1, 4);
    fz_note("n %d, method %d, newton_iters %d, newton_tol %.17g, linear_tr %d, nq %d, model %s, "
            "scale %.17g, q %.17g, jac mode %d scale %.17g, bad call %d status %d nan %d, "
            "t %.17g, h %.17g, %d steps; A:", n, method, s->newton_iters, s->newton_tol,
            s->linear_tr, s->nq, s->model ? "set" : "NULL", scale, c->q, jac_mode, c->jac_scale,
            c->bad_call, c->bad_status, c->bad_nan, t, h, nsteps);
    for (i = 0; i < n * n; i++)
        fz_note(" %.17g", c->A[i]);
    fz_note("; y:");
    for (i = 0; i < n; i++)
        fz_note(" %.17g", y[i]);

    for (k = 0; k < nsteps; k++) {
        const int null_arg = fz_choice(&in, 32);
        int calls0 = c->calls, jac0 = c->jac_calls, model0 = c->model_calls;
        const int invalid = settings_invalid(s) || !isfinite(t) || !isfinite(h) || !(h > 0.0)
                            || !all_finite(y, n) || null_arg == 0 || null_arg == 1;
        c->worst_warn = 0;
        c->first_err = 0;
        fz_note("; step %d (null arg %d)", k, null_arg);
        memcpy(ysave, y, sizeof y);
        /* known: the settings check computes 2 * nq, which overflows for
         * nq > INT_MAX / 2 */
        if (fz_known("nq_overflow", s->nq > INT_MAX / 2))
            break;
        nfev = rr_ode_nfev(s, jac != NULL);
        if (settings_invalid(s) && nfev != -1)
            fz_fail("rr_ode_nfev: %d for invalid settings", nfev);
        st = rr_ode_step(s, null_arg == 0 ? NULL : f_cb, jac, c, t, h, null_arg == 1 ? NULL : y);
        fz_status("rr_ode_step", st);
        fz_error("rr_ode_step", st, invalid, "an argument or a setting is invalid");
        if (c->first_err < 0 && st != c->first_err)
            fz_fail("rr_ode_step: a callback returned %d, the step %d", c->first_err, st);
        if (st < 0) {
            if (memcmp(y, ysave, sizeof y) != 0)
                fz_fail("rr_ode_step: error %d but y changed", st);
            continue;
        }
        fz_finite_n("rr_ode_step", st, "y", y, n);
        if (st < c->worst_warn)
            fz_fail("rr_ode_step: status %d below the callbacks' warning %d", st, c->worst_warn);
        if (s->nfev != nfev || s->nfev != c->calls - calls0)
            fz_fail("rr_ode_step: nfev %d, rr_ode_nfev %d, f called %d times", s->nfev, nfev,
                    c->calls - calls0);
        if (s->njev != (jac ? 1 : 0) || s->njev != c->jac_calls - jac0)
            fz_fail("rr_ode_step: njev %d with jac %s, called %d times", s->njev,
                    jac ? "given" : "NULL", c->jac_calls - jac0);
        if (s->nmev != c->model_calls - model0 || (!s->model && s->nmev != 0))
            fz_fail("rr_ode_step: nmev %d, model called %d times", s->nmev,
                    c->model_calls - model0);
        if (!(s->newton_err >= 0.0) || (s->method != RR_ODE_TRBDF2 && s->newton_err != 0.0))
            fz_fail("rr_ode_step: newton_err = %g for method %d", s->newton_err, s->method);
        t += h;
    }
    free(s);
    free(c);
    return 0;
}
