/*
 * bench_nonhertz_runtime.c - the run time of the non-Hertzian method the
 * study recommends (benchmarks/NONHERTZ_STUDY.md), in C: one wheel's contact
 * from a table per lateral shift built by the exact solver.  A prototype for
 * timing and for checking the algorithm's description, not library code.
 *
 *   python benchmarks/study_nonhertz.py export --tag o0.1+c --pair miniprof --side left
 *   cc -O2 -std=c99 -I csrc benchmarks/bench_nonhertz_runtime.c \
 *      csrc/{util,contact,geometry,rig}/rr_*.c -lm -o bench_nonhertz_runtime
 *   ./bench_nonhertz_runtime benchmarks/out/nonhertz/table_miniprof_left.bin \
 *      benchmarks/out/nonhertz/cases_miniprof_left.bin [repeats]
 *
 * Per wheel: the two rows around y, each evaluated as if the wheelset were
 * at the row's shift (its pose and rates given), the results blended
 * linearly.  Per row: the shared lowering dz from the vertical load (a
 * bracketed secant on the patches' tabulated loads N(e) = e^1.5 q(e), then
 * the tangential forces' vertical share fixed-point iterated); per patch
 * the node data interpolated at e = dz - g, the creepages at its reference
 * point, the calibrated ellipse, rr_exact_table_forces, the tabulated
 * correction.  Prints one line of JSON: cases, the best and median time
 * per wheel [us], exact_table calls per wheel, and the largest difference
 * from the Python prototype's forces over mu N.
 *
 * The table file (little-endian doubles, written by study_nonhertz.py
 * export): magic 0x4e48, rows, K (approach nodes), nu, nth (correction's u
 * and theta nodes), ncn (nodes carrying a correction), sigma, R0, U[nu];
 * per row: y, patches; per patch: g, then K values each of e, q, P_Y, P_Z,
 * delta, xc, yc, area/N^(2/3), pmax/N^(1/3), a/b, K11, K22, K23; then per
 * correction node: e, R0[3], R[nu][nth][3] (over mu N).
 * The cases file: per case y, Fz, mu, roller_spin, row i, t, then for rows
 * i and i+1 the pose c[3], v[3], w[3]; then Python's force[3] and N.
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rollerrig.h"

#define KMAX 16
#define PMAX 4
#define UMAX 8
#define THMAX 16
#define CNMAX 4
#define NCASE 28
#ifndef TZ_TOL
#define TZ_TOL 1e-4 /* the tangential forces' vertical share: 1e-4 Fz moves the forces 1e-4 mu N */
#endif
#define TWO_PI 6.283185307179586

typedef struct {
    double g;
    double e[KMAX], q[KMAX], PY[KMAX], PZ[KMAX], delta[KMAX], xc[KMAX], yc[KMAX];
    double areaN[KMAX], pmaxN[KMAX], ab[KMAX], K11[KMAX], K22[KMAX], K23[KMAX];
    double ce[CNMAX], R0[CNMAX][3], R[CNMAX][UMAX][THMAX][3];
} patch_t;

typedef struct {
    double y;
    int np;
    patch_t p[PMAX];
} row_t;

typedef struct {
    int nrows, K, nu, nth, ncn;
    double sigma, R0, U[UMAX];
    row_t *rows;
} table_t;

typedef struct {
    double c[3], v[3], w[3];
} pose_t;

typedef struct {
    double force[3], N, area, pmax, vert;
} result_t;

static const double G = 8.2e10, NU = 0.28;
static long table_calls;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double *read_all(const char *path, long *n)
{
    FILE *f = fopen(path, "rb");
    double *d;
    long size;
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    fseek(f, 0, SEEK_SET);
    d = malloc((size_t)size);
    if (d && fread(d, 1, (size_t)size, f) != (size_t)size) {
        free(d);
        d = NULL;
    }
    fclose(f);
    *n = size / (long)sizeof(double);
    return d;
}

static int load_table(const char *path, table_t *t)
{
    long n, k = 0;
    double *d = read_all(path, &n);
    int i, j, a, b, c, m;
    if (!d || n < 8 || d[0] != 0x4e48)
        return -1;
    t->nrows = (int)d[1];
    t->K = (int)d[2];
    t->nu = (int)d[3];
    t->nth = (int)d[4];
    t->ncn = (int)d[5];
    t->sigma = d[6];
    t->R0 = d[7];
    k = 8;
    if (t->K > KMAX || t->nu > UMAX || t->nth > THMAX || t->ncn > CNMAX)
        return -1;
    for (i = 0; i < t->nu; i++)
        t->U[i] = d[k++];
    t->rows = calloc((size_t)t->nrows, sizeof *t->rows);
    if (!t->rows)
        return -1;
    for (i = 0; i < t->nrows; i++) {
        row_t *r = &t->rows[i];
        r->y = d[k++];
        r->np = (int)d[k++];
        if (r->np > PMAX)
            return -1;
        for (j = 0; j < r->np; j++) {
            patch_t *p = &r->p[j];
            double *arr[13] = {p->e, p->q, p->PY, p->PZ, p->delta, p->xc, p->yc, p->areaN,
                               p->pmaxN, p->ab, p->K11, p->K22, p->K23};
            p->g = d[k++];
            for (m = 0; m < 13; m++)
                for (a = 0; a < t->K; a++)
                    arr[m][a] = d[k++];
            for (c = 0; c < t->ncn; c++) {
                p->ce[c] = d[k++];
                for (m = 0; m < 3; m++)
                    p->R0[c][m] = d[k++];
                for (a = 0; a < t->nu; a++)
                    for (b = 0; b < t->nth; b++)
                        for (m = 0; m < 3; m++)
                            p->R[c][a][b][m] = d[k++];
            }
        }
    }
    free(d);
    return k == n ? 0 : -1;
}

/* interval k and weight t of v on nodes x[0..n-1] (held at the ends) */
static int locate(const double *x, int n, double v, double *t)
{
    int k = 0;
    if (v <= x[0]) {
        *t = 0.0;
        return 0;
    }
    if (v >= x[n - 1]) {
        *t = 1.0;
        return n - 2;
    }
    while (k < n - 2 && v > x[k + 1])
        k++;
    *t = (v - x[k]) / (x[k + 1] - x[k]);
    return k;
}

#define LERP(a, k, t) ((1.0 - (t)) * (a)[k] + (t) * (a)[(k) + 1])

/* a patch's normal load at lowering e beyond its gap */
static double load(const table_t *tb, const patch_t *p, double e, double *nz)
{
    double t;
    int k;
    if (e <= 0.0) {
        *nz = 1.0;
        return 0.0;
    }
    k = locate(p->e, tb->K, e, &t);
    *nz = cos(LERP(p->delta, k, t));
    return e * sqrt(e) * LERP(p->q, k, t);
}

/* one correction node's residual (over mu N) at normalised creepage (x, y) */
static void residual(const table_t *tb, const patch_t *p, int c, double x, double y, double r[3])
{
    const double rho = hypot(x, y), u = rho / (1.0 + rho);
    double th = atan2(y, x), kk, tj, tu, lo[3], hi[3];
    int j0, j1, i, m;
    if (th < 0.0)
        th += TWO_PI;
    kk = th / (TWO_PI / tb->nth);
    j0 = (int)floor(kk);
    tj = kk - j0;
    j0 %= tb->nth;
    j1 = (j0 + 1) % tb->nth;
    /* u between 0 (R0), the nodes U and 1 (no residual) */
    if (u <= tb->U[0]) {
        tu = u / tb->U[0];
        for (m = 0; m < 3; m++) {
            lo[m] = p->R0[c][m];
            hi[m] = (1 - tj) * p->R[c][0][j0][m] + tj * p->R[c][0][j1][m];
        }
    } else if (u >= tb->U[tb->nu - 1]) {
        tu = (u - tb->U[tb->nu - 1]) / (1.0 - tb->U[tb->nu - 1]);
        for (m = 0; m < 3; m++) {
            lo[m] = (1 - tj) * p->R[c][tb->nu - 1][j0][m] + tj * p->R[c][tb->nu - 1][j1][m];
            hi[m] = 0.0;
        }
    } else {
        i = 0;
        while (u > tb->U[i + 1])
            i++;
        tu = (u - tb->U[i]) / (tb->U[i + 1] - tb->U[i]);
        for (m = 0; m < 3; m++) {
            lo[m] = (1 - tj) * p->R[c][i][j0][m] + tj * p->R[c][i][j1][m];
            hi[m] = (1 - tj) * p->R[c][i + 1][j0][m] + tj * p->R[c][i + 1][j1][m];
        }
    }
    for (m = 0; m < 3; m++)
        r[m] = (1 - tu) * lo[m] + tu * hi[m];
}

/* one patch at lowering dz: its force (rig frame), load, area, peak and the
 * vertical component of its force */
static int patch_forces(const table_t *tb, const patch_t *p, double dz, const pose_t *ps,
                        double mu, double Wr, double out[7])
{
    const double e = dz - p->g, sig = tb->sigma;
    double t, d, sd, cd, PY, PZ, xc, yc, ab, K11, K22, K23, N, n[3], t2[3], q[3], r[3];
    double vw[3], vr[3], slip[3], V, cx, cy, cphi, cxc, cyc, c2, cc, sy, sp, muN, x, y;
    double corr[3], dd[3];
    rr_kalker_coeffs kc;
    rr_contact_problem cs;
    rr_forces f;
    int k, st, c, m;
    if (e <= 0.0) {
        memset(out, 0, 7 * sizeof out[0]);
        return 0;
    }
    k = locate(p->e, tb->K, e, &t);
    N = e * sqrt(e) * LERP(p->q, k, t);
    d = LERP(p->delta, k, t);
    sd = sin(d);
    cd = cos(d);
    PY = LERP(p->PY, k, t);
    PZ = LERP(p->PZ, k, t);
    xc = LERP(p->xc, k, t);
    yc = LERP(p->yc, k, t);
    ab = LERP(p->ab, k, t);
    K11 = LERP(p->K11, k, t);
    K22 = LERP(p->K22, k, t);
    K23 = LERP(p->K23, k, t);
    t2[0] = 0.0, t2[1] = cd, t2[2] = sig * sd;
    n[0] = 0.0, n[1] = -sig * sd, n[2] = cd;
    /* creepages at P: the wheel's point P - pen n, the centre lowered by dz */
    q[0] = 0.0 - e * cd * n[0] - ps->c[0];
    q[1] = PY - e * cd * n[1] - ps->c[1];
    q[2] = PZ - e * cd * n[2] - (ps->c[2] - dz);
    vw[0] = ps->v[0] + ps->w[1] * q[2] - ps->w[2] * q[1];
    vw[1] = ps->v[1] + ps->w[2] * q[0] - ps->w[0] * q[2];
    vw[2] = ps->v[2] + ps->w[0] * q[1] - ps->w[1] * q[0];
    r[0] = 0.0, r[1] = PY, r[2] = PZ + tb->R0;          /* P from the roller axis */
    vr[0] = -Wr * r[2];                                  /* (0, -Wr, 0) x r */
    vr[1] = 0.0;
    vr[2] = Wr * r[0];
    V = fabs(vw[0] + vr[0]) / 2.0;
    if (V < 1e-3)
        V = 1e-3;
    for (m = 0; m < 3; m++)
        slip[m] = vw[m] - vr[m];
    cx = slip[0] / V;
    cy = (slip[1] * t2[1] + slip[2] * t2[2]) / V;
    cphi = (ps->w[1] + Wr) * n[1] / V + ps->w[2] * n[2] / V;
    /* the calibrated ellipse at the pressure's centroid */
    cxc = cx - cphi * yc;
    cyc = cy + cphi * xc;
    if ((st = rr_kalker(ab, NU, &kc)) < 0)
        return st;
    c2 = K11 / (G * kc.c11);
    cc = sqrt(c2);
    sy = K22 / (G * c2 * kc.c22);
    sp = K23 / (G * c2 * cc * kc.c23);
    memset(&cs, 0, sizeof cs);          /* a zeroed problem is an ellipse */
    cs.a = cc * sqrt(ab);
    cs.b = cc / sqrt(ab);
    cs.N = N;
    cs.G = G;
    cs.nu = NU;
    cs.cx = cxc;
    cs.cy = sy * cyc;
    cs.cphi = sp * cphi;
    cs.speed = 0.0;
    cs.friction.mu0 = mu;
    cs.friction.A = 1.0;
    cs.friction.B = 0.0;
    table_calls++;
    if ((st = rr_exact_table_forces(&rr_exact_table_builtin, &cs, &f)) < 0)
        return st;
    /* the correction: linear in e between its nodes, held at the ends */
    muN = mu * N;
    x = K11 * cxc / muN;
    y = K22 * cyc / muN;
    if (e <= p->ce[0] || tb->ncn == 1) {
        residual(tb, p, 0, x, y, corr);
    } else if (e >= p->ce[tb->ncn - 1]) {
        residual(tb, p, tb->ncn - 1, x, y, corr);
    } else {
        c = 0;
        while (e > p->ce[c + 1])
            c++;
        t = (e - p->ce[c]) / (p->ce[c + 1] - p->ce[c]);
        residual(tb, p, c, x, y, corr);
        residual(tb, p, c + 1, x, y, dd);
        for (m = 0; m < 3; m++)
            corr[m] = (1 - t) * corr[m] + t * dd[m];
    }
    f.fx += muN * corr[0];
    f.fy += muN * corr[1];
    out[0] = f.fx;
    out[1] = f.fy * t2[1] + N * n[1];
    out[2] = f.fy * t2[2] + N * n[2];
    out[3] = N;
    out[4] = LERP(p->areaN, k, t) * cbrt(N * N);
    out[5] = LERP(p->pmaxN, k, t) * cbrt(N);
    out[6] = out[2];
    return 0;
}

/* the sum of the patches' normal loads' vertical parts at dz */
static double vertical_normal(const table_t *tb, const row_t *row, double dz)
{
    double s = 0.0, nz, N;
    int j;
    for (j = 0; j < row->np; j++) {
        N = load(tb, &row->p[j], dz - row->p[j].g, &nz);
        s += N * nz;
    }
    return s;
}

/* dz with vertical_normal(dz) = target: secant on S^(2/3), bracketed */
static double solve_dz(const table_t *tb, const row_t *row, double target, double dz)
{
    double d0 = 0.0, S0 = 0.0, lo = 0.0, hi = 0.0, S, step, f0, f1, tt = cbrt(target);
    int it, have = 0, hlo = 0, hhi = 0;
    for (it = 0; it < 60; it++) {
        S = vertical_normal(tb, row, dz);
        if (fabs(S - target) < 1e-10 * target)
            break;
        if (S < target && (!hlo || dz > lo))
            lo = dz, hlo = 1;
        if (S > target && (!hhi || dz < hi))
            hi = dz, hhi = 1;
        step = dz * pow(target / (S > 1e-3 * target ? S : 1e-3 * target), 2.0 / 3.0);
        if (have) {
            f0 = cbrt(S0) * cbrt(S0) - tt * tt;
            f1 = cbrt(S) * cbrt(S) - tt * tt;
            if (f1 != f0 && dz != d0)
                step = dz - f1 * (dz - d0) / (f1 - f0);
        }
        if (hlo && hhi && !(lo < step && step < hi))
            step = 0.5 * (lo + hi);
        d0 = dz, S0 = S, have = 1;
        dz = step;
    }
    return dz;
}

/* one row at vertical load Fz */
static int eval_row(const table_t *tb, const row_t *row, double Fz, const pose_t *ps, double mu,
                    double Wr, result_t *res)
{
    const patch_t *p0 = &row->p[0];
    double Tz = 0.0, dz, out[7], t, nz0, nz1, a0, a1;
    int it, j, m, k, st;
    /* a start: the primary patch's nodes, N cos(delta) = Fz */
    for (k = 0; k < tb->K - 2; k++)
        if (p0->e[k + 1] * sqrt(p0->e[k + 1]) * p0->q[k + 1] * cos(p0->delta[k + 1]) >= Fz)
            break;
    nz0 = cos(p0->delta[k]);
    nz1 = cos(p0->delta[k + 1]);
    a0 = p0->e[k] * sqrt(p0->e[k]) * p0->q[k] * nz0;
    a1 = p0->e[k + 1] * sqrt(p0->e[k + 1]) * p0->q[k + 1] * nz1;
    t = (Fz - a0) / (a1 - a0);
    dz = p0->g + p0->e[k] + t * (p0->e[k + 1] - p0->e[k]);
    for (it = 0; it < 20; it++) {
        double Tn;
        dz = solve_dz(tb, row, Fz - Tz, dz);
        memset(res, 0, sizeof *res);
        for (j = 0; j < row->np; j++) {
            if ((st = patch_forces(tb, &row->p[j], dz, ps, mu, Wr, out)) < 0)
                return st;
            for (m = 0; m < 3; m++)
                res->force[m] += out[m];
            res->N += out[3];
            res->area += out[4];
            res->pmax = out[5] > res->pmax ? out[5] : res->pmax;
        }
        /* the tangential forces' vertical share: total vertical less the normal loads' */
        Tn = res->force[2] - vertical_normal(tb, row, dz);
        if (fabs(Tn - Tz) < TZ_TOL * Fz) {
            Tz = Tn;
            break;
        }
        Tz = Tn;
    }
    return 0;
}

int main(int argc, char **argv)
{
    table_t tb;
    long n, nc, i;
    double *cs, times[101], worst = 0.0, worst_y = 0.0;
    int repeats = argc > 3 ? atoi(argv[3]) : 7, r, k;
    result_t *out;
    if (argc < 3 || load_table(argv[1], &tb) != 0) {
        fprintf(stderr, "usage: %s table.bin cases.bin [repeats]\n", argv[0]);
        return 1;
    }
    cs = read_all(argv[2], &n);
    if (!cs || n % NCASE || repeats < 1 || repeats > 101)
        return 1;
    nc = n / NCASE;
    out = calloc((size_t)nc, sizeof *out);
    for (r = 0; r < repeats; r++) {
        const double t0 = now();
        table_calls = 0;
        for (i = 0; i < nc; i++) {
            const double *c = cs + i * NCASE;
            const int row = (int)c[4];
            const double t = c[5];
            result_t a, b;
            pose_t p0, p1;
            memcpy(&p0, c + 6, sizeof p0);
            memcpy(&p1, c + 15, sizeof p1);
            if (eval_row(&tb, &tb.rows[row], c[1], &p0, c[2], c[3], &a) < 0
                || eval_row(&tb, &tb.rows[row + 1], c[1], &p1, c[2], c[3], &b) < 0)
                return 2;
            for (k = 0; k < 3; k++)
                out[i].force[k] = (1 - t) * a.force[k] + t * b.force[k];
            out[i].N = (1 - t) * a.N + t * b.N;
        }
        times[r] = (now() - t0) / (double)nc;
    }
    for (i = 0; i < nc; i++) {
        const double *c = cs + i * NCASE;
        const double d = sqrt(pow(out[i].force[0] - c[24], 2) + pow(out[i].force[1] - c[25], 2)
                              + pow(out[i].force[2] - c[26], 2)) / (c[2] * c[27]);
        if (d > worst) {
            worst = d;
            worst_y = c[0];
        }
    }
    for (r = 1; r < repeats; r++) {     /* sort */
        double v = times[r];
        k = r - 1;
        while (k >= 0 && times[k] > v) {
            times[k + 1] = times[k];
            k--;
        }
        times[k + 1] = v;
    }
    printf("{\"cases\": %ld, \"best_us\": %.3f, \"median_us\": %.3f, \"table_calls_per_wheel\": "
           "%.2f, \"max_diff_from_python_muN\": %.2e, \"at_y_mm\": %.2f}\n", nc, times[0] * 1e6,
           times[repeats / 2] * 1e6, (double)table_calls / (double)nc, worst, worst_y * 1e3);
    return 0;
}
