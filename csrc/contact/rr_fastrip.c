/* rr_fastrip.c - FaStrip: strip theory per row with FASTSIM's slip
 * directions (Sichani, Enblom and Berg 2016), as CONTACT's modified FaStrip
 * (M=5), and its descriptor. */
#include <math.h>
#include "util/rr_common.h"
#include "contact/rr_kalker.h"
#include "contact/rr_fastrip.h"

/* What every row shares. */
typedef struct {
    double a, b, h, dy;          /* semi-axes; element length and width */
    double aa;                   /* the strip theory's semi-axis along x */
    double pn0, pmax;            /* pressure at the centre [Pa]; the strip theory's */
    double mu;
    double L1, L2, keff;         /* the FASTSIM part's flexibilities and slope factor */
    double wx0, wxy, wy0, wyx;   /* rigid slip times h: wx = wx0 + wxy y, wy = wy0 + wyx x */
    double xi, eta, phi;         /* the strip theory's dimensionless creepages */
    double one_nu;               /* 1 - nu */
    int nx, contact;
} strip_setup;

/* Element i's centre x and q = 1 - x^2/a^2 - y^2/b^2 (inside if q > 0).
 * Centres (and rows) as (i + 1/2 - n/2) h: mirror images exactly. */
static double elem_q(const strip_setup *s, int i, double w2, double *x)
{
    const double xc = (i + 0.5 - 0.5 * s->nx) * s->h, t = xc / s->a;
    *x = xc;
    return w2 - t * t;
}

/*
 * CONTACT's simpflex blending (Vollebregt and Voltr): the three
 * flexibilities move towards one, L = sum w_k^2 / sum (w_k^2 / L_k) over
 * (xi, eta, 3 pi a phi / 32), with weight |(xi, eta)| / |(ch_xi, ch_eta)| / 3
 * (at most 1; spin does not count), ch = mu N / (G c^2 C).  Both ratios are
 * homogeneous in the creepages, so they are taken of creepages scaled by
 * their largest (no underflow of the squares).
 */
static void blend(const rr_contact_problem *c, double mu, const rr_kalker_coeffs *k, double L[3])
{
    const double ps = c->cphi * 3.0 * RR_PI * c->a / 32.0;
    const double m = fmax(fabs(c->cx), fmax(fabs(c->cy), fabs(ps)));
    double x, y, p, Lc, crp, w;
    if (!(m > 0.0) || !isfinite(m))
        return;                  /* no creepage: nothing to blend (or refused later) */
    x = c->cx / m;
    y = c->cy / m;
    p = ps / m;
    Lc = (x * x + y * y + p * p) / (x * x / L[0] + y * y / L[1] + p * p / L[2]);
    /* ch_xi, ch_eta share mu N / (G ab): their ratio is 1/C11 : 1/C22 */
    crp = hypot(c->cx, c->cy) * c->G * c->a * c->b / (mu * c->N * hypot(1.0 / k->c11, 1.0 / k->c22));
    w = fmin(1.0, fmax(1e-10, crp) / 3.0);      /* CONTACT's floor of 1e-10 kept */
    L[0] += w * (Lc - L[0]);
    L[1] += w * (Lc - L[1]);
    L[2] += w * (Lc - L[2]);
}

/* Strip theory's half slip length d of a row at y (Kalker's strip theory with
 * the dimensionless creepages of modif_fastrip); HUGE_VAL: the row slides. */
static double slip_length(const strip_setup *s, double y)
{
    const double xi = s->xi - s->phi * y / s->aa, den = 1.0 - s->phi * s->phi;
    double disc, d;
    if (fabs(s->phi - 1.0) <= 1e-6)
        return HUGE_VAL;
    disc = s->eta * s->eta + den * xi * xi;
    if (!(disc >= 0.0))
        return HUGE_VAL;
    d = (sqrt(disc) + s->eta * s->phi) / den * s->aa / s->one_nu;
    return d < 0.0 || isnan(d) ? HUGE_VAL : d;
}

/* The antiderivative of sqrt(R^2 - (u - u0)^2), held constant outside
 * |u - u0| <= R (0 for R <= 0): differences of it at a cell's edges are the
 * cell's integral of a semi-ellipse, and neighbours share an edge. */
static double disc_prim(double R, double u0, double u)
{
    double p;
    if (!(R > 0.0))
        return 0.0;
    p = fmin(R, fmax(-R, u - u0));
    return 0.5 * (p * sqrt(fmax(0.0, R * R - p * p)) + R * R * asin(p / R));
}

/* One row y (w2 = 1 - y^2/b^2): its Fx, Fy, Mz sums (times dA later) added
 * to sums.  RR_FASTRIP_ELLIPSE: every element carries the average over its
 * cell of the strip theory's closed form and of the pressure (the trailing
 * edge's square-root traction of the linear limit sampled at centres would
 * converge at h^(1/2) only); RR_FASTRIP_CONTACT: their values at the
 * centres, as CONTACT. */
static void strip_row(const strip_setup *s, double y, double w2, double sums[3])
{
    double aj, d, xb, kap = 0.0, lam = 0.0, lamp = 0.0, ux = 0.0, uy = 0.0, x;
    int i, lo = -1, hi = -1, accept = 1;

    if (s->contact) {
        for (i = 0; i < s->nx; i++)
            if (elem_q(s, i, w2, &x) > 0.0) {
                if (lo < 0)
                    lo = i;
                hi = i;
            }
        if (lo < 0)
            return;
        /* the strip's half-length: the extent of its elements */
        aj = fmax(1e-13 * s->a, 0.5 * (hi - lo + 1) * s->h);
    } else {
        aj = s->a * sqrt(w2);
        /* the cells the chord [-aj, aj] overlaps */
        lo = (int)floor((s->a - aj) / s->h);
        hi = (int)ceil((s->a + aj) / s->h) - 1;
        lo = lo < 0 ? 0 : lo;
        hi = hi >= s->nx ? s->nx - 1 : hi;
        if (!(aj > 0.0) || hi < lo)
            return;
    }
    d = slip_length(s, y);
    xb = 2.0 * d - aj;           /* strip theory's slip zone: [-aj, xb] */
    if (d < HUGE_VAL) {
        const double sx = s->xi - s->phi * y / s->aa, sy = s->eta + s->phi * d / s->aa;
        const double nrm = sqrt(fmax(1e-20, sx * sx + sy * sy));
        kap = sx / nrm;
        lam = sy / nrm;
        lamp = lam - s->phi;
        /* the closed form holds only within the bound mu pmax (checked at
         * the centres, as CONTACT) */
        for (i = lo; i <= hi && accept; i++) {
            const double q = elem_q(s, i, w2, &x);
            if ((q > 0.0 || !s->contact) && x > xb) {
                const double sc = sqrt(fmax(0.0, aj * aj - x * x)) / s->aa;
                const double sa = sqrt(fmax(0.0, (aj - d) * (aj - d) - (x - d) * (x - d))) / s->aa;
                const double fx = kap * (sc - sa), fy = lam * sc - lamp * sa;
                accept = fx * fx + fy * fy <= 1.0;
            }
        }
    } else {
        xb = HUGE_VAL;
    }
    /* FASTSIM from the leading edge x = +a: material enters there.  Cell i
     * spans [e_i, e_(i+1)], e_i = (i - nx/2) h; fc, fa: the antiderivatives
     * of the chord's semi-ellipse and of the adhesion zone's at e_(i+1). */
    {
        const int adh = accept && d < HUGE_VAL && !s->contact;
        double fc = 0.0, fa = 0.0;
        if (!s->contact) {
            const double e = (hi + 1 - 0.5 * s->nx) * s->h;
            fc = disc_prim(aj, 0.0, e);
            fa = adh ? disc_prim(aj - d, d, e) : 0.0;
        }
        for (i = hi; i >= lo; i--) {
            const double q = elem_q(s, i, w2, &x);
            double px, py, pn, m, cnt = 0.0, sc = 0.0, sa = 0.0;
            if (s->contact) {
                pn = q > 0.0 ? s->pn0 * sqrt(q) : 0.0;
            } else {
                const double e = (i - 0.5 * s->nx) * s->h, fc_lo = disc_prim(aj, 0.0, e);
                cnt = fc - fc_lo;            /* [m^2]: over a h, times pn0, the pressure */
                if (adh) {
                    const double fa_lo = disc_prim(aj - d, d, e);
                    sa = fa - fa_lo;
                    sc = xb <= e ? cnt : (xb < e + s->h ? fc - disc_prim(aj, 0.0, xb) : 0.0);
                    fa = fa_lo;
                }
                fc = fc_lo;
                pn = s->pn0 * cnt / (s->a * s->h);
            }
            if (!(pn > 0.0)) {
                ux = uy = 0.0;
                continue;
            }
            ux -= s->wx0 + s->wxy * y;
            uy -= s->wy0 + s->wyx * x;
            px = ux * s->keff / s->L1;
            py = uy * s->keff / s->L2;
            m = sqrt(px * px + py * py);
            if (m > s->mu * pn) {
                px *= s->mu * pn / m;
                py *= s->mu * pn / m;
                ux = s->L1 * px / s->keff;
                uy = s->L2 * py / s->keff;
                m = s->mu * pn;
            }
            if (accept && s->contact) {
                if (x > xb) {
                    /* strip theory's adhesion zone */
                    const double c1 = sqrt(fmax(0.0, aj * aj - x * x)) / s->aa;
                    const double a1 = sqrt(fmax(0.0, (aj - d) * (aj - d) - (x - d) * (x - d)))
                                      / s->aa;
                    px = s->mu * s->pmax * kap * (c1 - a1);
                    py = s->mu * s->pmax * (lam * c1 - lamp * a1);
                } else if (m > 0.0) {
                    /* its slip zone: at the bound, along FASTSIM's traction */
                    px *= s->mu * pn / m;
                    py *= s->mu * pn / m;
                }
            } else if (accept) {
                /* the cell's averages: adhesion over (xb, e_(i+1)], slip over the rest */
                const double scale = s->mu * s->pmax / (s->aa * s->h);
                const double sl = fmax(0.0, cnt - sc);
                const double f = sl > 0.0 && m > 0.0 ? s->mu * s->pn0 * sl / (s->a * s->h * m)
                                                     : 0.0;
                px = scale * kap * (sc - sa) + f * px;
                py = scale * (lam * sc - lamp * sa) + f * py;
            }
            sums[0] += px;
            sums[1] += py;
            sums[2] += x * py - y * px;
        }
    }
}

/* rr_fastrip for options checked by the registry: the descriptor's entry
 * point; the case and the law checked here */
static int fastrip_checked(const rr_contact_problem *c, const rr_creep_opts *o,
                           rr_forces *out)
{
    const rr_friction *fr;
    rr_kalker_coeffs k;
    strip_setup s;
    double L[3], sums[3] = {0.0, 0.0, 0.0}, cc, facx, facy;
    int st, i, j, ny, ncon = 0, imin = -1, imax = -1, jmin = -1, jmax = -1;

    if (!c || !o || !out) {
        rr_forces_nan(out);
        return RR_ERR_NULL;
    }
    st = rr_creep_prepare(c, &k);
    fr = &c->friction;
    if (st == RR_OK && rr_friction_is_falling(fr))
        st = RR_ERR_FRICTION;         /* FaStrip as CONTACT: Coulomb's mu0 only */
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    s.a = c->a;
    s.b = c->b;
    s.nx = (int)o->v[RR_FASTRIP_NX];
    ny = (int)o->v[RR_FASTRIP_NY];
    s.h = 2.0 * c->a / s.nx;
    s.dy = 2.0 * c->b / ny;
    s.mu = fr->mu0;
    s.contact = o->v[RR_FASTRIP_GEOMETRY] == RR_FASTRIP_CONTACT;
    s.one_nu = 1.0 - c->nu;

    /* the grid's elements in contact (centre inside) and their extent */
    for (j = 0; j < ny; j++) {
        const double y = (j + 0.5 - 0.5 * ny) * s.dy, t = y / c->b, w2 = 1.0 - t * t;
        for (i = 0; i < s.nx; i++) {
            double x, q = elem_q(&s, i, w2, &x);
            if (q > 0.0) {
                ncon++;
                if (imin < 0 || i < imin) imin = i;
                if (i > imax) imax = i;
                if (jmin < 0) jmin = j;
                jmax = j;
            }
        }
    }
    if (ncon == 0) {
        /* cannot happen: the centre row's middle elements lie inside */
        rr_forces_nan(out);
        return RR_ERR_RANGE;
    }
    if (s.contact) {
        /* CONTACT's: Hertz's pressure at the centres; the strip theory on
         * the equivalent ellipse of the elements in contact (Kik and
         * Piotrowski: their area, the extent's aspect) */
        const double area = ncon * s.h * s.dy, len = (imax - imin + 1) * s.h;
        const double wid = (jmax - jmin + 1) * s.dy, r = sqrt(area / RR_PI);
        double bb;
        s.aa = r * sqrt(len / wid);
        bb = r * sqrt(wid / len);
        s.pn0 = 1.5 * c->N / (RR_PI * c->a * c->b);
        s.pmax = 1.5 * c->N / (RR_PI * s.aa * bb);
        cc = sqrt(s.aa * bb);
    } else {
        /* the pressure sums to N on the grid, and the strips share it */
        /* each row's load exactly: the integral of sqrt(q) over its chord is
         * pi a (1 - y^2/b^2) / 2; the pressure sums to N over the rows */
        double R = 0.0;
        for (j = 0; j < ny; j++) {
            const double t = (j + 0.5 - 0.5 * ny) * s.dy / c->b;
            R += 0.5 * RR_PI * c->a * (1.0 - t * t);
        }
        s.aa = c->a;
        s.pn0 = s.pmax = c->N / (R * s.dy);
        jmin = 0;
        jmax = ny - 1;
        cc = sqrt(c->a * c->b);
    }

    /* FASTSIM's part: Kalker's flexibilities (blended), CONTACT's slope
     * reduction with K0_MF, ALFAMF, BETAMF (1, 1, 1: none) */
    rr_kalker_flexibilities(c->a, c->b, c->G, &k, L);
    if (o->v[RR_FASTRIP_FLEX] == RR_FASTRIP_FLEX_BLENDED)
        blend(c, s.mu, &k, L);
    {
        const double k0 = o->v[RR_FASTRIP_K0], al = o->v[RR_FASTRIP_ALPHA_INF];
        double nphi = c->cy + c->cphi * s.aa, eps;
        if (fabs(nphi) < fabs(c->cy))
            nphi = c->cy;
        eps = c->G * RR_PI * cc * cc * k0 * k.c11 * hypot(c->cx, nphi)
              / (4.0 * s.mu * c->N);
        s.keff = al == 1.0 ? k0 : k0 * (al + (1.0 - al) / (1.0 + o->v[RR_FASTRIP_BETA] * eps));
    }
    s.L1 = L[0];
    s.L2 = L[1];
    facx = L[0] / L[2];
    facy = L[1] / L[2];
    /* rigid slip times h, spin scaled as in FASTSIM with three flexibilities;
     * CONTACT takes the spin's x at x + h/6 (its facphi) */
    s.wx0 = s.h * c->cx;
    s.wxy = -s.h * facx * c->cphi;
    s.wy0 = s.h * (c->cy + facy * c->cphi * s.h / 6.0);
    s.wyx = s.h * facy * c->cphi;
    /* dimensionless creepages of the strip theory: Kalker's coefficients
     * in place of the 2-D ones, so that the linear limit is Kalker's */
    s.xi = -2.0 * s.one_nu * c->G * k.c11 * c->cx / (RR_PI * RR_PI * s.mu * s.pmax);
    s.eta = -2.0 * s.one_nu * c->G * k.c22 * c->cy / (RR_PI * RR_PI * s.mu * s.pmax);
    s.phi = -1.5 * c->G * cc * k.c23 * c->cphi / (RR_PI * s.mu * s.pmax);
    if (!isnormal(s.L1) || !isnormal(s.L2) || !isnormal(L[2]) || !isnormal(s.h)
        || !isnormal(s.dy) || !isnormal(s.pmax) || !isnormal(s.pn0) || !(s.keff > 0.0)) {
        rr_forces_nan(out);
        return RR_ERR_RANGE;
    }

    for (j = jmin; j <= jmax; j++) {
        const double y = (j + 0.5 - 0.5 * ny) * s.dy, t = y / c->b;
        strip_row(&s, y, 1.0 - t * t, sums);
    }
    out->fx = sums[0] * s.h * s.dy;
    out->fy = sums[1] * s.h * s.dy;
    out->mz = sums[2] * s.h * s.dy;
    if ((int)o->v[RR_FASTRIP_GEOMETRY] == RR_FASTRIP_ELLIPSE) {
        /* the pressure sums to N: |F| <= mu N but for the rounding of the
         * sums in full sliding (1e-11), which is taken off */
        const double f = hypot(out->fx, out->fy), lim = s.mu * c->N;
        if (f > lim) {
            out->fx *= lim / f;
            out->fy *= lim / f;
        }
    }
    return rr_forces_checked(st, out);
}

int rr_fastrip(const rr_contact_problem *p, const rr_creep_opts *o, rr_forces *out)
{
    int st;

    if (!p || !o || !out) {
        rr_forces_nan(out);
        return RR_ERR_NULL;
    }
    if ((st = rr_method_check(&rr_method_fastrip, o, NULL)) < 0) {
        rr_forces_nan(out);
        return st;
    }
    return fastrip_checked(p, o, out);
}

/* ---- the descriptor ----------------------------------------------------- */

static const char *const flex_names[] = {"kalker", "blended", NULL};
static const char *const geometry_names[] = {"ellipse", "contact", NULL};

/* each option at its index of rr_fastrip.h; fields: name, type, unit, default, lo, hi,
 * lo_open, hi_open, choices, the status of a bad value, doc */
static const rr_creep_option fastrip_opts[] = {
    [RR_FASTRIP_NX] = {"nx", RR_OPT_INT, "", 30.0, 1.0, RR_FASTRIP_MAX_GRID, 0, 0, NULL,
                       RR_ERR_GRID, "elements along x per row"},
    [RR_FASTRIP_NY] = {"ny", RR_OPT_INT, "", 30.0, 1.0, RR_FASTRIP_MAX_GRID, 0, 0, NULL,
                       RR_ERR_GRID, "rows (strips) across the patch"},
    [RR_FASTRIP_FLEX] = {"flex", RR_OPT_CHOICE, "", RR_FASTRIP_FLEX_BLENDED, 0.0, 1.0, 0, 0,
                         flex_names, RR_ERR_METHOD, "FASTSIM part's flexibilities: kalker "
                         "(three) or blended towards one with the creepage (CONTACT as "
                         "shipped)"},
    [RR_FASTRIP_GEOMETRY] = {"geometry", RR_OPT_CHOICE, "", RR_FASTRIP_ELLIPSE, 0.0, 1.0, 0, 0,
                             geometry_names, RR_ERR_METHOD, "strips on the ellipse's chords, "
                             "pressure summing to N (ellipse), or CONTACT's element extents "
                             "and Hertz's peak (contact: |F| may pass mu N by 0.1 %)"},
    [RR_FASTRIP_K0] = {"k0", RR_OPT_REAL, "", 1.0, 0.0, 1.0, 1, 0, NULL, RR_ERR_PARAM,
                       "FASTSIM part's slope over Kalker's (CONTACT's K0_MF; 1: none)"},
    [RR_FASTRIP_ALPHA_INF] = {"alpha_inf", RR_OPT_REAL, "", 1.0, 0.0, 1.0, 0, 0, NULL,
                              RR_ERR_PARAM, "FASTSIM part's slope reduction at large "
                              "creepage (ALFAMF; 1: none)"},
    [RR_FASTRIP_BETA] = {"beta", RR_OPT_REAL, "", 1.0, 0.0, HUGE_VAL, 0, 1, NULL, RR_ERR_PARAM,
                         "rate of that reduction with the creepage (BETAMF)"},
};

/* the row scans: contact extent, bound check, march */
static double fastrip_cost(const rr_creep_opts *o)
{
    return 2.0 * o->v[RR_FASTRIP_NX] * o->v[RR_FASTRIP_NY];
}

static int fastrip_forces(const rr_contact_problem *p, const rr_creep_opts *o, double *work,
                          rr_forces *out)
{
    (void)work;
    return fastrip_checked(p, o, out);
}

/* The linear limit comes from the strip theory, whose flexibilities are
 * Kalker's: slope 1 whatever k0 (it scales only the FASTSIM part). */
const rr_method_desc rr_method_fastrip = {
    .name = "fastrip",
    .doc = "FaStrip (Sichani, Enblom and Berg 2016) as CONTACT's modified FaStrip: strip "
           "theory per row, FASTSIM's slip directions",
    .nopts = RR_COUNTOF(fastrip_opts),
    .opts = fastrip_opts,
    .saturates = 1,
    .cost = fastrip_cost,
    .slope_scale = rr_method_unit_slope,
    .workspace_len = rr_method_no_workspace,
    .forces = fastrip_forces,
    .coulomb_only = 1,
};
