/* rr_fastsim.c - FASTSIM (Kalker 1982) with blended and modified variants, and
 * their three descriptors (one algorithm). */
#include <float.h>
#include <math.h>
#include "util/rr_common.h"
#include "contact/rr_kalker.h"
#include "contact/rr_fastsim.h"

typedef struct {
    double L1, L2, L3;   /* flexibilities [m/Pa] after blending and modification */
} flex;

static void flexibilities(const rr_contact_problem *c, const rr_friction *fr, int method,
                          const rr_creep_opts *o, const rr_kalker_coeffs *k, flex *fl)
{
    const double a = c->a, b = c->b, G = c->G;
    double L[3];
    rr_kalker_flexibilities(a, b, G, k, L);
    fl->L1 = L[0];
    fl->L2 = L[1];
    fl->L3 = L[2];

    if (method == RR_METHOD_FASTSIM_BLENDED) {
        /* characteristic creepages mu0 N/(G c^2 C11), mu0 N/(G c^2 C22),
         * mu0 N/(G c^3 C23), c^2 = ab */
        const double ab = a * b, cc = sqrt(ab), sat = fr->mu0 * c->N / G;
        double w;
        if (o->v[RR_FASTSIM_BLEND_RULE] == RR_BLEND_CONTACT) {
            /* CONTACT's simpflex: |(cx, cy)| over |(ch_x, ch_y)|, no spin */
            const double chx = sat / (ab * k->c11), chy = sat / (ab * k->c22);
            w = hypot(c->cx, c->cy) / hypot(chx, chy) / 3.0;
        } else {
            /* each creepage over its own characteristic one, spin too */
            const double fx = c->cx * ab * k->c11 / sat;
            const double fy = c->cy * ab * k->c22 / sat;
            const double fp = c->cphi * ab * cc * k->c23 / sat;
            w = sqrt(fx * fx + fy * fy + fp * fp) / 3.0;
        }
        if (isnan(w)) {                 /* 0/0 from an extreme case: refused by the caller */
            fl->L1 = fl->L2 = fl->L3 = NAN;
            return;
        }
        if (w > 1.0)
            w = 1.0;
        if (w > 0.0) {
            const double pe = c->cphi * 3.0 * RR_PI * a / 32.0;
            const double x2 = c->cx * c->cx, y2 = c->cy * c->cy, p2 = pe * pe;
            const double L = (x2 + y2 + p2) / (x2 / fl->L1 + y2 / fl->L2 + p2 / fl->L3);
            fl->L1 += w * (L - fl->L1);
            fl->L2 += w * (L - fl->L2);
            fl->L3 += w * (L - fl->L3);
        }
    } else if (method == RR_METHOD_MODIFIED_FASTSIM) {
        double nphi = c->cy + c->cphi * a, mu, eps, kf;
        if (fabs(nphi) < fabs(c->cy))
            nphi = c->cy;
        mu = rr_friction_mu(fr, c->speed * hypot(c->cx, c->cy));
        const double k0 = o->v[RR_FASTSIM_K0], alpha_inf = o->v[RR_FASTSIM_ALPHA_INF];
        eps = RR_PI * G * a * b * k0 * k->c11 * hypot(c->cx, nphi) / (4.0 * mu * c->N);
        kf = k0 * (alpha_inf + (1.0 - alpha_inf) / (1.0 + o->v[RR_FASTSIM_BETA] * eps));
        fl->L1 /= kf;
        fl->L2 /= kf;
        fl->L3 /= kf;
    }
}

/* Newton iterations for the falling-friction bound; it converges in a few. */
#define FALLING_MAX_ITER 50

/* The friction law with its constants hoisted: mu(w) and dmu/dw(w) share one
 * exp and round exactly as rr_friction_mu and rr_friction_dmu do. */
typedef struct {
    double mu0, A, c1, nB, dk, Amu0, speed;
} law;

static void law_init(const rr_friction *fr, double speed, law *l)
{
    l->mu0 = fr->mu0;
    l->A = fr->A;
    l->c1 = 1.0 - fr->A;
    l->nB = -fr->B;
    l->dk = -fr->mu0 * (1.0 - fr->A) * fr->B;
    l->Amu0 = fr->A * fr->mu0;
    l->speed = speed;
}

/* Falling friction: the slip speed v = speed * s in a slipping element solves
 *   s = (Leff/step) (m - mu(speed s) pn),  m = |p*|.
 * The residual is convex and increasing past its root; Newton's method from
 * the kinetic bound (mu = A mu0) approaches the root from above.  The state
 * of one element's iteration, so that the elements of several rows can
 * iterate side by side. */
typedef struct {
    double s, ls, lps, pn, m, ftol;   /* s; Leff/step; Leff/step pn speed; pn; m; |f| tolerance */
    double g;                         /* result: the bound mu pn */
    int it;
} newton;

static void newton_init(const law *l, double pn, double m, double leff_step, newton *n)
{
    n->s = leff_step * (m - l->Amu0 * pn);
    n->ls = leff_step;
    n->lps = leff_step * pn * l->speed;
    n->pn = pn;
    n->m = m;
    n->ftol = 8e-16 * leff_step * m;
    n->it = 0;
}

/* One Newton step; 1 when done (n->g set), 0 to go on; *converged cleared
 * at the iteration cap. */
static int newton_step(const law *l, newton *n, int *converged)
{
    const double v = l->speed * n->s, e = exp(l->nB * v);
    const double mu = l->mu0 * (l->c1 * e + l->A);
    const double f = n->s - n->ls * (n->m - mu * n->pn);
    const double df = 1.0 + n->lps * (l->dk * e);
    double ds = df > 0.0 ? f / df : 0.0;
    int done;
    if (ds > n->s)
        ds = 0.5 * n->s;     /* never step below zero slip */
    n->s -= ds;
    /* f carries rounding noise of about eps * leff_step * m */
    done = fabs(ds) <= 1e-13 * n->s || fabs(f) <= n->ftol;
    if (!done && ++n->it < FALLING_MAX_ITER)
        return 0;
    if (!done)
        *converged = 0;
    /* the bound at the new s; with s unchanged, mu is the one at hand */
    n->g = (ds == 0.0 ? mu : l->mu0 * (l->c1 * exp(l->nB * (l->speed * n->s)) + l->A)) * n->pn;
    return 1;
}

/* Rows are marched in groups side by side: each element waits for its
 * upstream neighbour, so a row is one serial chain (through a square root
 * and a division where the element slips), and independent rows in lock
 * step let the processor overlap their chains and share vector
 * instructions: up to GROUP_VECS vectors of 2 (SSE2) or 4 (AVX) rows.
 * Every row still gets exactly the arithmetic of a march on its own, and all
 * sums are added row by row, in order, so the grouping changes no result. */
#define GROUP_VECS 5       /* rr_fastsim_kernel.h has a kernel for each of 1 .. 5 */

/* AVX: 4 rows per vector, compiled with a function-level target (no build
 * flag needed) and used where the processor and the system support it
 * (__builtin_cpu_supports checks both).  Only with SSE2 and doubles
 * evaluated as doubles, as the scalar march does; RR_FASTSIM_NO_AVX (or
 * RR_FASTSIM_NO_SSE2) leaves it out, for testing. */
#if !defined(RR_FASTSIM_NO_AVX) && !defined(RR_FASTSIM_NO_SSE2) && defined(__GNUC__) \
    && (defined(__x86_64__) || defined(__i386__)) && defined(__SSE2__) \
    && defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD == 0
#define RR_FASTSIM_AVX 1
#define GROUP (4 * GROUP_VECS)
#else
#define RR_FASTSIM_AVX 0
#define GROUP (2 * GROUP_VECS)
#endif

/* Groups set up once for both passes (the first 8 groups); further ones
 * twice. */
#define GROUP_CACHE 8

/* What the march of every row shares. */
typedef struct {
    const rr_contact_problem *c;
    const flex *fl;
    law lw;
    double scale, mu_bound;     /* pressure scale [Pa]; bound's friction coefficient */
    double inv_a;               /* 1/a: a product is cheaper than a quotient per element */
    double gx0, gy, gphi;       /* rigid slip per unit length over the flexibility */
    double h_rect;              /* element length on the rectangular grid */
    int nx, ny, strips, parabolic;
    int lanes;                  /* rows per vector: 4 with AVX, else 2 */
} march;

/* Rows j0 .. j0 + nr - 1 in lanes 0 .. nr - 1 (the lanes up to the group's
 * width past nr idle: outside the ellipse everywhere), and the range
 * [lo, hi) of elements outside which every row of the group is outside the
 * ellipse (such elements carry nothing: the march skips them). */
typedef struct {
    int j0, nr, width, lo, hi;
    double y[GROUP], w2[GROUP], aj[GROUP], h[GROUP], gxh[GROUP];
} group;

/* Element i of row k: centre x = ((nx - 1)/2 - i) h (the elements i and
 * nx - 1 - i at exactly -x and x, the middle one of an odd row at 0: the
 * grid is its own mirror image, so mirrored creepages give mirrored forces
 * to the rounding of their sums) and q = 1 - x^2/a^2 - y^2/b^2, inside if
 * q > 0.  The vector code below does the very same operations. */
static double elem_q(const march *m, const group *g, int k, int i, double *x)
{
    const double xc = (0.5 * (m->nx - 1) - i) * g->h[k], t = xc * m->inv_a;
    *x = xc;
    return g->w2[k] - t * t;
}

static int any_inside(const march *m, const group *g, int i)
{
    int k;
    for (k = 0; k < g->nr; k++) {
        double x;
        if (elem_q(m, g, k, i, &x) > 0.0)
            return 1;
    }
    return 0;
}

/* The group of rows from j0: as many as fit in up to GROUP_VECS vectors
 * (with 2 lanes 9 rows go in 10 lanes, one of them idle; with 4 lanes 9
 * rows go in 12, etc.). */
static void group_init(const march *m, int j0, group *g)
{
    const rr_contact_problem *c = m->c;
    const int left = m->ny - j0, nv = (left + m->lanes - 1) / m->lanes;
    const double inv_ny = 1.0 / m->ny;     /* products, not a quotient per row */
    int k;
    g->j0 = j0;
    g->width = m->lanes * (nv < GROUP_VECS ? nv : GROUP_VECS);
    g->nr = left < g->width ? left : g->width;
    for (k = 0; k < g->width; k++) {
        const int j = k < g->nr ? j0 + k : j0;
        /* y_j / b, rows j and ny - 1 - j at exactly -y and y */
        const double yh = (2.0 * j + 1.0 - m->ny) * inv_ny, w2 = 1.0 - yh * yh;
        const double aj = m->strips ? c->a * sqrt(w2) : c->a;
        g->y[k] = yh * c->b;
        g->w2[k] = k < g->nr ? w2 : -1.0;
        g->aj[k] = aj;
        g->h[k] = m->strips ? 2.0 * aj / m->nx : m->h_rect;
        g->gxh[k] = (m->gx0 - m->gphi * g->y[k]) * g->h[k];
    }
    for (g->lo = 0; g->lo < m->nx && !any_inside(m, g, g->lo); g->lo++)
        ;
    for (g->hi = m->nx; g->hi > g->lo && !any_inside(m, g, g->hi - 1); g->hi--)
        ;
}

/* ---- vectors of rows --------------------------------------------------------
 * v2: a pair of doubles, SSE2 where the compiler has it (any x86-64), else
 * a struct; v4: four doubles, AVX (its target brings no fused multiply-add).
 * All do the same IEEE operations, lane by lane, so the results do not
 * depend on which one runs (RR_FASTSIM_NO_SSE2 forces the struct, for
 * testing). */
#if !defined(RR_FASTSIM_NO_SSE2) \
    && (defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2))
#include <emmintrin.h>
typedef __m128d v2;
#define v2_set1 _mm_set1_pd
#define v2_add _mm_add_pd
#define v2_sub _mm_sub_pd
#define v2_mul _mm_mul_pd
#define v2_div _mm_div_pd
#define v2_sqrt _mm_sqrt_pd
#define v2_max _mm_max_pd        /* a > b ? a : b */
static v2 v2_load(const double *p) { return _mm_loadu_pd(p); }
static void v2_store(double *p, v2 a) { _mm_storeu_pd(p, a); }
#else
typedef struct { double a, b; } v2;
static v2 v2_mk(double a, double b) { v2 r; r.a = a; r.b = b; return r; }
static v2 v2_set1(double a) { return v2_mk(a, a); }
static v2 v2_add(v2 x, v2 y) { return v2_mk(x.a + y.a, x.b + y.b); }
static v2 v2_sub(v2 x, v2 y) { return v2_mk(x.a - y.a, x.b - y.b); }
static v2 v2_mul(v2 x, v2 y) { return v2_mk(x.a * y.a, x.b * y.b); }
static v2 v2_div(v2 x, v2 y) { return v2_mk(x.a / y.a, x.b / y.b); }
static v2 v2_sqrt(v2 x) { return v2_mk(sqrt(x.a), sqrt(x.b)); }
static v2 v2_load(const double *p) { return v2_mk(p[0], p[1]); }
static void v2_store(double *p, v2 x) { p[0] = x.a; p[1] = x.b; }
static v2 v2_max(v2 x, v2 y) { return v2_mk(x.a > y.a ? x.a : y.a, x.b > y.b ? x.b : y.b); }
#endif

/* Sums of one group per row, before the factor h dy. */
typedef struct {
    double sx[GROUP], sy[GROUP], sm[GROUP];
    int nslip, converged;
} sums;

/* A kernel inlined into its dispatcher, for each fixed width and grid: at
 * -O2 GCC would otherwise compile one kernel for all widths, its vectors in
 * memory (some 15 % slower at 20 x 20). */
#if defined(__GNUC__)
#define RR_FASTSIM_INLINE inline __attribute__((always_inline))
#else
#define RR_FASTSIM_INLINE inline
#endif

#define V v2
#define V_LANES 2
#define V_FN static
#include "contact/rr_fastsim_kernel.h"
#undef V
#undef V_LANES
#undef V_FN

#if RR_FASTSIM_AVX
#include <immintrin.h>
typedef __m256d v4;
#define v4_set1 _mm256_set1_pd
#define v4_add _mm256_add_pd
#define v4_sub _mm256_sub_pd
#define v4_mul _mm256_mul_pd
#define v4_div _mm256_div_pd
#define v4_sqrt _mm256_sqrt_pd
#define v4_max _mm256_max_pd     /* a > b ? a : b, as _mm_max_pd */
#define v4_load _mm256_loadu_pd
#define v4_store _mm256_storeu_pd

#define V v4
#define V_LANES 4
#define V_FN static __attribute__((target("avx")))
#include "contact/rr_fastsim_kernel.h"
#undef V
#undef V_LANES
#undef V_FN
#endif

/* 4 lanes where the processor and the system run AVX, else 2. */
static int fastsim_lanes(void)
{
#if RR_FASTSIM_AVX
    return __builtin_cpu_supports("avx") ? 4 : 2;
#else
    return 2;
#endif
}

/* The kernels of the march's vector width. */
static void pressure_dispatch(const march *m, const group *g, double *rows)
{
#if RR_FASTSIM_AVX
    if (m->lanes == 4) {
        pressure_dispatch_v4(m, g, rows);
        return;
    }
#endif
    pressure_dispatch_v2(m, g, rows);
}

static void coulomb_dispatch(const march *m, const group *g, sums *s)
{
#if RR_FASTSIM_AVX
    if (m->lanes == 4) {
        coulomb_dispatch_v4(m, g, s);
        return;
    }
#endif
    coulomb_dispatch_v2(m, g, s);
}

/* The march is exact in floating point, and the vector kernel's
 * sqrt(g*g) == g holds, when the bound's scale mu p lies in [1e-80, 1e100]
 * Pa and no element adds more than 1e150 Pa to a traction: inside the
 * ellipse q >= 2^-65 = 2.7e-20 (w2 >= 4.8e-4 > 2^-12 with at most 4096
 * rows, and q = w2 - t^2 > 0 is either >= w2/2 or, by Sterbenz's lemma, the
 * exact difference of two doubles >= 2^-13, a multiple of 2^-65), so every
 * bound g lies in [2e-100, 1e100] and every trial traction below 1e151:
 * the squares the slip test compares are normal numbers or exact zeros.
 * Physical cases lie far inside (mu p of 1e3 to 1e10 Pa, increments below
 * 1e12 Pa); outside, RR_ERR_RANGE.  Elements and rows of subnormal size are
 * refused too: their sums would lose their precision. */
static int march_in_range(const march *m, const flex *fl, double dy)
{
    const double ms = m->mu_bound * m->scale;
    const double inc = (fabs(m->gx0) + fabs(m->gphi) * m->c->b + fabs(m->gy)
                        + fabs(m->gphi) * m->c->a) * m->h_rect;
    if (!isnormal(fl->L1) || !isnormal(fl->L2) || !isnormal(fl->L3)
        || !isnormal(0.01 * m->h_rect) || !isnormal(dy))
        return 0;
    return ms >= 1e-80 && ms <= 1e100 && inc <= 1e150;
}

/* The march of a group, one element of each row at a time: any friction law,
 * optionally the traction field.  Kalker's explicit scheme: an element adds
 * the rigid slip at its centre times one element length to its upstream
 * neighbour's traction; the first element inside the contact starts from
 * zero. */
static void group_march(const march *m, const group *g, int local, rr_fastsim_field *field,
                        sums *s)
{
    double px[GROUP], py[GROUP];
    const int nr = g->nr;
    int i, k;
    for (k = 0; k < nr; k++)
        px[k] = py[k] = s->sx[k] = s->sy[k] = s->sm[k] = 0.0;
    s->nslip = 0;
    s->converged = 1;
    for (i = g->lo; i < g->hi; i++) {
        double tx[GROUP], ty[GROUP], pn[GROUP], gb[GROUP], mag[GROUP], xs[GROUP];
        int slip[GROUP], in[GROUP];
        newton nw[GROUP];
        unsigned long pending = 0;
        for (k = 0; k < nr; k++) {
            const double q = elem_q(m, g, k, i, &xs[k]);
            in[k] = q > 0.0;
            slip[k] = 0;
            pn[k] = 0.0;
            if (in[k]) {
                double m2;
                tx[k] = px[k] - g->gxh[k];
                ty[k] = py[k] - (m->gy + m->gphi * xs[k]) * g->h[k];
                m2 = tx[k] * tx[k] + ty[k] * ty[k];
                pn[k] = m->scale * (m->parabolic ? q : sqrt(q));
                gb[k] = m->mu_bound * pn[k];
                slip[k] = m2 > gb[k] * gb[k];
                if (slip[k]) {
                    mag[k] = sqrt(m2);
                    if (local) {
                        const double lx = m->fl->L1 * tx[k], ly = m->fl->L2 * ty[k];
                        newton_init(&m->lw, pn[k], mag[k],
                                    sqrt(lx * lx + ly * ly) / (mag[k] * g->h[k]), &nw[k]);
                        pending |= 1ul << k;
                    }
                }
            }
        }
        /* the Newton iterations of the slipping elements, side by side */
        while (pending)
            for (k = 0; k < nr; k++)
                if ((pending >> k & 1ul) && newton_step(&m->lw, &nw[k], &s->converged)) {
                    gb[k] = nw[k].g;
                    pending &= ~(1ul << k);
                }
        for (k = 0; k < nr; k++) {
            if (in[k]) {
                if (slip[k]) {
                    px[k] = tx[k] * (gb[k] / mag[k]);
                    py[k] = ty[k] * (gb[k] / mag[k]);
                    s->nslip++;
                } else {
                    px[k] = tx[k];
                    py[k] = ty[k];
                }
                s->sx[k] += px[k];
                s->sy[k] += py[k];
                s->sm[k] += xs[k] * py[k] - g->y[k] * px[k];
                if (field) {
                    const int idx = (g->j0 + k) * m->nx + (m->nx - 1 - i);
                    if (field->pn) field->pn[idx] = pn[k];
                    if (field->px) field->px[idx] = px[k];
                    if (field->py) field->py[idx] = py[k];
                    if (field->slip) field->slip[idx] = (signed char)slip[k];
                }
            } else {
                px[k] = py[k] = 0.0;        /* outside the ellipse: no contact */
            }
        }
    }
}

/* The field as if no element lay inside: positions, zero pressure and
 * traction; the march overwrites the inside. */
static void field_fill(const march *m, double dy, rr_fastsim_field *f)
{
    int j, i, k;
    for (j = 0; j < m->ny; j += k) {
        group g;
        group_init(m, j, &g);
        for (k = 0; k < g.nr; k++)
            for (i = 0; i < m->nx; i++) {
                const int idx = (j + k) * m->nx + (m->nx - 1 - i);
                double x;
                elem_q(m, &g, k, i, &x);
                if (f->x) f->x[idx] = x;
                if (f->y) f->y[idx] = g.y[k];
                if (f->area) f->area[idx] = g.h[k] * dy;
                if (f->pn) f->pn[idx] = 0.0;
                if (f->px) f->px[idx] = 0.0;
                if (f->py) f->py[idx] = 0.0;
                if (f->slip) f->slip[idx] = 0;
            }
        k = g.nr;
    }
}

/* The grid of valid options (1), or 0 where nx or ny is not a grid size. */
static int grid_of(const rr_creep_opts *o, int *nx, int *ny)
{
    const double x = o->v[RR_FASTSIM_NX], y = o->v[RR_FASTSIM_NY];
    if (!(x >= 1.0 && x <= RR_FASTSIM_MAX_GRID && x == floor(x) && y >= 1.0
          && y <= RR_FASTSIM_MAX_GRID && y == floor(y)))
        return 0;
    *nx = (int)x;
    *ny = (int)y;
    return 1;
}

/* The error path: NaN forces and, where its size is known, a NaN field. */
static int fail(int st, const rr_creep_opts *o, rr_forces *out, rr_fastsim_field *f)
{
    int nx = 0, ny = 0;
    if (out)
        rr_forces_nan(out);
    if (f && o && grid_of(o, &nx, &ny)) {
        const long n = (long)nx * ny;
        long i;
        for (i = 0; i < n; i++) {
            if (f->x) f->x[i] = NAN;
            if (f->y) f->y[i] = NAN;
            if (f->area) f->area[i] = NAN;
            if (f->pn) f->pn[i] = NAN;
            if (f->px) f->px[i] = NAN;
            if (f->py) f->py[i] = NAN;
            if (f->slip) f->slip[i] = 0;
        }
        f->nslip = 0;
    }
    return st;
}

static const rr_method_desc *variant(int method);

/* rr_fastsim for options checked by the registry (a FASTSIM variant's,
 * valid): the descriptors' entry points; the case and the law checked here */
static int fastsim_checked(const rr_contact_problem *c, const rr_creep_opts *o,
                           rr_forces *out, rr_fastsim_field *field)
{
    const rr_friction *fr;
    rr_kalker_coeffs k;
    flex fl;
    march m;
    group cache[GROUP_CACHE], tmp, *g;    /* the groups of the first rows, set up once */
    int nx = 0, ny = 0;
    double dy, S = 0.0, fx = 0.0, fy = 0.0, mz = 0.0;
    int st, j, n, falling, local, converged = 1, nslip = 0;

    if (!c || !o || !out)
        return fail(RR_ERR_NULL, o, out, field);
    st = rr_creep_prepare(c, &k);
    if (st < 0)
        return fail(st, o, out, field);
    fr = &c->friction;
    grid_of(o, &nx, &ny);
    flexibilities(c, fr, o->method, o, &k, &fl);
    falling = rr_friction_is_falling(fr);
    /* local: mu from each element's own slip speed; rigid: one mu at the
     * rigid slip speed |(cx, cy)| speed for the whole patch. */
    local = falling && o->v[RR_FASTSIM_SLIP_SPEED] == RR_SLIP_LOCAL;

    m.c = c;
    m.fl = &fl;
    law_init(fr, c->speed, &m.lw);
    m.mu_bound = falling && !local ? rr_friction_mu(fr, c->speed * hypot(c->cx, c->cy)) : fr->mu0;
    m.inv_a = 1.0 / c->a;
    m.gx0 = c->cx / fl.L1;
    m.gy = c->cy / fl.L2;
    m.gphi = c->cphi / fl.L3;
    m.h_rect = 2.0 * c->a / nx;
    m.nx = nx;
    m.ny = ny;
    m.strips = o->v[RR_FASTSIM_GRID] == RR_GRID_STRIPS;
    m.parabolic = o->v[RR_FASTSIM_BOUND] == RR_BOUND_PARABOLIC;
    m.lanes = fastsim_lanes();

    /* Rows j at y_j = -b + (j + 1/2) dy.  RR_GRID_RECT: every row spans the
     * ellipse's bounding box |x| <= a and elements outside the ellipse carry
     * nothing (CONTACT's potential contact area); RR_GRID_STRIPS: row j spans
     * its own chord |x| <= a_j (Kalker's strips).  Either way the pressure
     * at a centre is scale * q or scale * sqrt(q), q = 1 - x^2/a^2 - y^2/b^2,
     * with scale such that the pressure sums to N over the grid. */
    dy = 2.0 * c->b / ny;
    for (j = 0, n = 0; j < ny; j += g->nr, n++) {
        double rows[GROUP];
        int r;
        g = n < GROUP_CACHE ? &cache[n] : &tmp;
        group_init(&m, j, g);
        pressure_dispatch(&m, g, rows);
        for (r = 0; r < g->nr; r++)
            S += rows[r] * g->h[r];
    }
    /* N / (S dy), unless S dy is subnormal (semi-axes of 1e-92 and 1e-230
     * m): then dividing by each in turn keeps the pressure's digits */
    m.scale = fabs(S * dy) >= DBL_MIN ? c->N / (S * dy) : c->N / dy / S;
    if (!march_in_range(&m, &fl, dy))
        return fail(RR_ERR_RANGE, o, out, field);

    if (field)
        field_fill(&m, dy, field);
    for (j = 0, n = 0; j < ny; j += g->nr, n++) {
        sums s;
        int r;
        if (n < GROUP_CACHE) {
            g = &cache[n];
        } else {
            g = &tmp;
            group_init(&m, j, g);
        }
        if (local || field)
            group_march(&m, g, local, field, &s);
        else
            coulomb_dispatch(&m, g, &s);
        for (r = 0; r < g->nr; r++) {
            fx += s.sx[r] * g->h[r];
            fy += s.sy[r] * g->h[r];
            mz += s.sm[r] * g->h[r];
        }
        nslip += s.nslip;
        converged &= s.converged;
    }
    out->fx = fx * dy;
    out->fy = fy * dy;
    out->mz = mz * dy;
    if (field)
        field->nslip = nslip;
    if (!(isfinite(out->fx) && isfinite(out->fy) && isfinite(out->mz)))
        return fail(RR_ERR_RANGE, o, out, field);
    if (!converged && st == RR_OK)
        st = RR_WARN_NOT_CONVERGED;
    return st;
}

int rr_fastsim(const rr_contact_problem *p, const rr_creep_opts *o, rr_forces *out,
               rr_fastsim_field *field)
{
    const rr_method_desc *d;
    int st;

    if (!p || !o || !out)
        return fail(RR_ERR_NULL, o, out, field);
    d = variant(o->method);
    st = d ? rr_method_check(d, o, NULL) : RR_ERR_METHOD;
    if (st < 0)
        return fail(st, o, out, field);
    return fastsim_checked(p, o, out, field);
}

/* ---- the descriptors ---------------------------------------------------- */

static const char *const bound_names[] = {"parabolic", "elliptic", NULL};
static const char *const grid_names[] = {"rect", "strips", NULL};
static const char *const slip_names[] = {"local", "rigid", NULL};

/* the options every variant has, each at its index of rr_fastsim.h, then
 * modified FASTSIM's; slip_speed's default is set per variant */
#define FASTSIM_OPTS(slip_default)                                                          \
    [RR_FASTSIM_NX] = {"nx", RR_OPT_INT, "", 30.0, 1.0, RR_FASTSIM_MAX_GRID, 0, 0, NULL,   \
                       RR_ERR_GRID, "elements along x per row"},                            \
    [RR_FASTSIM_NY] = {"ny", RR_OPT_INT, "", 30.0, 1.0, RR_FASTSIM_MAX_GRID, 0, 0, NULL,   \
                       RR_ERR_GRID, "rows (strips) across the patch"},                      \
    [RR_FASTSIM_BOUND] = {"bound", RR_OPT_CHOICE, "", RR_BOUND_PARABOLIC, 0.0, 1.0, 0, 0,  \
                          bound_names, RR_ERR_METHOD,                                       \
                          "traction bound: parabolic (Kalker's) or elliptic (Hertzian)"},   \
    [RR_FASTSIM_GRID] = {"grid", RR_OPT_CHOICE, "", RR_GRID_RECT, 0.0, 1.0, 0, 0,          \
                         grid_names, RR_ERR_METHOD, "rows over the ellipse's bounding box " \
                         "(rect, CONTACT's) or each its own chord (strips, Kalker's: "      \
                         "converges faster)"},                                              \
    [RR_FASTSIM_SLIP_SPEED] = {"slip_speed", RR_OPT_CHOICE, "", slip_default, 0.0, 1.0, 0, \
                               0, slip_names, RR_ERR_METHOD, "falling friction at each "    \
                               "element's own slip speed (local) or at the rigid slip "     \
                               "speed (rigid)"}

static const rr_creep_option fastsim_opts[] = {FASTSIM_OPTS(RR_SLIP_LOCAL)};

static const char *const blend_names[] = {"contact", "spin", NULL};

/* The default: CONTACT's rule.  Scored against the exact theory (CONTACT's
 * 300 cases at 45 across, its 3220-case test table, the library's own 3000
 * Richardson cases), it is nearer than "spin" in the force with spin and
 * without (own cases, 30 x 30: p95 0.045 against 0.061 muN) and no worse
 * in Mz; and it is CONTACT's blended FASTSIM (tests/test_blend_rule.py). */
#define RR_BLEND_DEFAULT RR_BLEND_CONTACT
#define RR_BLEND_DOC                                                                     \
    "blend weight w = min(1, f/3): contact (CONTACT's simpflex, the default: "           \
    "f = |(cx, cy)|/|(ch_x, ch_y)|, no spin; nearer the exact theory) or spin "          \
    "(f = |(cx/ch_x, cy/ch_y, cphi/ch_phi)|)"

static const rr_creep_option blended_opts[] = {
    FASTSIM_OPTS(RR_SLIP_LOCAL),
    [RR_FASTSIM_BLEND_RULE] = {"blend_rule", RR_OPT_CHOICE, "", RR_BLEND_DEFAULT, 0.0, 1.0, 0,
                               0, blend_names, RR_ERR_METHOD, RR_BLEND_DOC},
};

/* modified FASTSIM was calibrated with friction at the rigid slip speed */
static const rr_creep_option modified_opts[] = {
    FASTSIM_OPTS(RR_SLIP_RIGID),
    [RR_FASTSIM_K0] = {"k0", RR_OPT_REAL, "", 0.54, 0.0, 1.0, 1, 0, NULL, RR_ERR_PARAM,
                       "initial slope over Kalker's"},
    [RR_FASTSIM_ALPHA_INF] = {"alpha_inf", RR_OPT_REAL, "", 0.02, 0.0, 1.0, 0, 0, NULL,
                              RR_ERR_PARAM, "slope reduction at large creepage"},
    [RR_FASTSIM_BETA] = {"beta", RR_OPT_REAL, "", 0.62, 0.0, HUGE_VAL, 0, 1, NULL,
                         RR_ERR_PARAM, "rate of the slope reduction with the creepage"},
};

static double fastsim_cost(const rr_creep_opts *o)
{
    return o->v[RR_FASTSIM_NX] * o->v[RR_FASTSIM_NY];
}

/* modified FASTSIM's small-creepage slope: k0 times the plain one's */
static double modified_slope(const rr_creep_opts *o)
{
    return o->v[RR_FASTSIM_K0];
}

static int fastsim_forces(const rr_contact_problem *p, const rr_creep_opts *o, double *work,
                          rr_forces *out)
{
    (void)work;
    return fastsim_checked(p, o, out, NULL);
}

/* the ellipse's field (a grid problem is refused before the shape is asked) */
static void fastsim_shape(const rr_creep_opts *o, const rr_grid *grid, int *rows, int *cols)
{
    (void)grid;
    *rows = (int)o->v[RR_FASTSIM_NY];
    *cols = (int)o->v[RR_FASTSIM_NX];
}

/* what the three variants share */
#define FASTSIM_ENTRIES                                                          \
    .saturates = 1, .cost = fastsim_cost, .workspace_len = rr_method_no_workspace, \
    .forces = fastsim_forces, .field_shape = fastsim_shape, .field = fastsim_checked

const rr_method_desc rr_method_fastsim = {
    .name = "fastsim",
    .doc = "FASTSIM, Kalker 1982: three flexibilities",
    .nopts = RR_COUNTOF(fastsim_opts),
    .opts = fastsim_opts,
    .slope_scale = rr_method_unit_slope,
    FASTSIM_ENTRIES,
};

const rr_method_desc rr_method_fastsim_blended = {
    .name = "fastsim_blended",
    .doc = "FASTSIM with flexibilities blended from three to one as the creepage grows "
           "(Vollebregt and Voltr 2023)",
    .nopts = RR_COUNTOF(blended_opts),
    .opts = blended_opts,
    .slope_scale = rr_method_unit_slope,
    FASTSIM_ENTRIES,
};

const rr_method_desc rr_method_modified_fastsim = {
    .name = "modified_fastsim",
    .doc = "modified FASTSIM (Spiryagin, Polach and Cole 2013): the slope reduced with the "
           "creepage",
    .nopts = RR_COUNTOF(modified_opts),
    .opts = modified_opts,
    .slope_scale = modified_slope,
    FASTSIM_ENTRIES,
};

/* The descriptor of a FASTSIM variant's number, else NULL. */
static const rr_method_desc *variant(int method)
{
    switch (method) {
    case RR_METHOD_FASTSIM:
        return &rr_method_fastsim;
    case RR_METHOD_FASTSIM_BLENDED:
        return &rr_method_fastsim_blended;
    case RR_METHOD_MODIFIED_FASTSIM:
        return &rr_method_modified_fastsim;
    default:
        return NULL;
    }
}
