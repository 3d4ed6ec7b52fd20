/* rr_fastsim.c - FASTSIM (Kalker 1982) with blended and modified variants. */
#include <math.h>
#include "rr_common.h"
#include "rr_kalker.h"
#include "rr_fastsim.h"

/* Rows marched side by side (see rr_fastsim). */
#ifndef ROWS_AT_ONCE
#define ROWS_AT_ONCE 2
#endif

/* Newton iterations for the falling-friction bound; it converges in a few. */
#define FALLING_MAX_ITER 50

typedef struct {
    double L1, L2, L3;   /* flexibilities [m/Pa] after blending and modification */
} flex;

static void flexibilities(const rr_contact_case *c, const rr_friction *fr, int method,
                          const rr_creep_opts *o, const rr_kalker_coeffs *k, flex *fl)
{
    const double a = c->a, b = c->b, G = c->G;
    fl->L1 = 8.0 * a / (3.0 * k->c11 * G);
    fl->L2 = 8.0 * a / (3.0 * k->c22 * G);
    fl->L3 = RR_PI * a * sqrt(a / b) / (4.0 * k->c23 * G);

    if (method == RR_METHOD_FASTSIM_BLENDED) {
        const double ab = a * b, cc = sqrt(ab), sat = fr->mu0 * c->N / G;
        const double fx = c->cx * ab * k->c11 / sat;
        const double fy = c->cy * ab * k->c22 / sat;
        const double fp = c->cphi * ab * cc * k->c23 / sat;
        double w = sqrt(fx * fx + fy * fy + fp * fp) / 3.0;
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
        eps = RR_PI * G * a * b * o->k0 * k->c11 * hypot(c->cx, nphi) / (4.0 * mu * c->N);
        kf = o->k0 * (o->alpha_inf + (1.0 - o->alpha_inf) / (1.0 + o->beta * eps));
        fl->L1 /= kf;
        fl->L2 /= kf;
        fl->L3 /= kf;
    }
}

/* Falling friction: the slip speed v = speed * s in a slipping element solves
 *   s = (Leff/step) (m - mu(speed s) pn),  m = |p*|.
 * The residual is convex and increasing past its root; Newton's method from
 * the kinetic bound (mu = A mu0) approaches the root from above. */
static double falling_bound(const rr_friction *fr, double speed, double pn, double m,
                            double leff_step, int *converged)
{
    double s = leff_step * (m - fr->A * fr->mu0 * pn);
    int it;

    for (it = 0; it < FALLING_MAX_ITER; it++) {
        const double v = speed * s;
        const double f = s - leff_step * (m - rr_friction_mu(fr, v) * pn);
        const double df = 1.0 + leff_step * pn * speed * rr_friction_dmu(fr, v);
        double ds = df > 0.0 ? f / df : 0.0;
        if (ds > s)
            ds = 0.5 * s;     /* never step below zero slip */
        s -= ds;
        /* f carries rounding noise of about eps * leff_step * m */
        if (fabs(ds) <= 1e-13 * s || fabs(f) <= 8e-16 * leff_step * m)
            return rr_friction_mu(fr, speed * s) * pn;
    }
    *converged = 0;
    return rr_friction_mu(fr, speed * s) * pn;
}

/* What the march of every row shares. */
typedef struct {
    const rr_contact_case *c;
    const rr_friction *fr;
    const flex *fl;
    double scale, mu_bound;     /* pressure scale [Pa]; bound's friction coefficient */
    double inv_a;               /* 1/a: a product is cheaper than a quotient per element */
    int parabolic, local;       /* traction bound; falling friction at local slip */
    int converged, nslip;
    rr_fastsim_field *field;
    int nx;
} march;

/* One row of the grid and the state of its march. */
typedef struct {
    int j;
    double y, w2, aj, h;        /* position, 1 - y^2/b^2, half-length, element length */
    double gx, gy, gphi;        /* rigid slip per unit length over the flexibility */
    double px, py;              /* traction of the last element */
    double sx, sy, sm;          /* sums of px, py and x py - y px */
} row;

static void row_init(const march *m, const rr_creep_opts *o, int j, row *r)
{
    const rr_contact_case *c = m->c;
    const double yh = -1.0 + (2.0 * j + 1.0) / o->ny;
    r->j = j;
    r->w2 = 1.0 - yh * yh;
    r->y = yh * c->b;
    r->aj = o->grid == RR_GRID_STRIPS ? c->a * sqrt(r->w2) : c->a;
    r->h = 2.0 * r->aj / o->nx;
    r->gx = c->cx / m->fl->L1 - c->cphi * r->y / m->fl->L3;
    r->gy = c->cy / m->fl->L2;
    r->gphi = c->cphi / m->fl->L3;
    r->px = r->py = r->sx = r->sy = r->sm = 0.0;
}

/* Element i of a row.  Kalker's explicit scheme: an element adds the rigid
 * slip at its centre times one element length to its upstream neighbour's
 * traction; the first element inside the contact starts from zero. */
static void element(march *m, row *r, int i)
{
    const double x = r->aj - (i + 0.5) * r->h, t = x * m->inv_a, q = r->w2 - t * t;
    double pn = 0.0;
    int slip = 0;

    if (q > 0.0) {
        const double tx = r->px - r->gx * r->h;
        const double ty = r->py - (r->gy + r->gphi * x) * r->h;
        const double m2 = tx * tx + ty * ty;
        double g;
        pn = m->scale * (m->parabolic ? q : sqrt(q));
        g = m->mu_bound * pn;
        slip = m2 > g * g;
        if (slip) {
            const double mag = sqrt(m2);
            if (m->local) {
                const double lx = m->fl->L1 * tx, ly = m->fl->L2 * ty;
                g = falling_bound(m->fr, m->c->speed, pn, mag,
                                  sqrt(lx * lx + ly * ly) / (mag * r->h), &m->converged);
            }
            r->px = tx * (g / mag);
            r->py = ty * (g / mag);
            m->nslip++;
        } else {
            r->px = tx;
            r->py = ty;
        }
        r->sx += r->px;
        r->sy += r->py;
        r->sm += x * r->py - r->y * r->px;
    } else {
        r->px = r->py = 0.0;        /* outside the ellipse: no contact */
    }
    if (m->field) {
        rr_fastsim_field *f = m->field;
        const int idx = r->j * m->nx + (m->nx - 1 - i);
        if (f->x) f->x[idx] = x;
        if (f->y) f->y[idx] = r->y;
        if (f->pn) f->pn[idx] = pn;
        if (f->px) f->px[idx] = r->px;
        if (f->py) f->py[idx] = r->py;
        if (f->slip) f->slip[idx] = (signed char)slip;
    }
}

int rr_fastsim(const rr_contact_case *c, const rr_friction *fr, const rr_creep_opts *o,
               rr_forces *out, rr_fastsim_field *field)
{
    rr_kalker_coeffs k;
    flex fl;
    march m;
    const int nx = o->nx, ny = o->ny;
    double dy, inv_a, S = 0.0, scale, fx = 0.0, fy = 0.0, mz = 0.0, mu_bound;
    int st, i, j, falling, local, converged = 1, nslip = 0;

    st = rr_creep_opts_check(o);
    if (st == RR_OK && o->method != RR_METHOD_FASTSIM && o->method != RR_METHOD_FASTSIM_BLENDED
        && o->method != RR_METHOD_MODIFIED_FASTSIM)
        st = RR_ERR_METHOD;
    if (st == RR_OK)
        st = rr_creep_prepare(c, fr, &k);
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    flexibilities(c, fr, o->method, o, &k, &fl);
    falling = rr_friction_is_falling(fr);
    /* local: mu from each element's own slip speed; rigid: one mu at the
     * rigid slip speed |(cx, cy)| speed for the whole patch. */
    local = falling && o->slip_speed == RR_SLIP_LOCAL;
    mu_bound = falling && !local ? rr_friction_mu(fr, c->speed * hypot(c->cx, c->cy)) : fr->mu0;

    /* Rows j at y_j = -b + (j + 1/2) dy.  RR_GRID_RECT: every row spans the
     * ellipse's bounding box |x| <= a and elements outside the ellipse carry
     * nothing (CONTACT's potential contact area); RR_GRID_STRIPS: row j spans
     * its own chord |x| <= a_j (Kalker's strips).  Either way the pressure
     * at a centre is scale * q or scale * sqrt(q), q = 1 - x^2/a^2 - y^2/b^2,
     * with scale such that the pressure sums to N over the grid. */
    dy = 2.0 * c->b / ny;
    inv_a = 1.0 / c->a;
    for (j = 0; j < ny; j++) {
        const double yh = -1.0 + (2.0 * j + 1.0) / ny, w2 = 1.0 - yh * yh;
        const double aj = o->grid == RR_GRID_STRIPS ? c->a * sqrt(w2) : c->a;
        const double h = 2.0 * aj / nx;
        double row = 0.0;
        /* the same arithmetic as the march below, so both agree on which
         * elements lie inside the ellipse */
        for (i = 0; i < nx; i++) {
            const double x = aj - (i + 0.5) * h, t = x * inv_a, q = w2 - t * t;
            if (q > 0.0)
                row += o->bound == RR_BOUND_PARABOLIC ? q : sqrt(q);
        }
        S += row * h;
    }
    scale = c->N / (S * dy);

    m.c = c;
    m.fr = fr;
    m.fl = &fl;
    m.scale = scale;
    m.inv_a = inv_a;
    m.mu_bound = mu_bound;
    m.parabolic = o->bound == RR_BOUND_PARABOLIC;
    m.local = local;
    m.converged = 1;
    m.nslip = 0;
    m.field = field;
    m.nx = nx;
    /* Rows are independent: marching several at once lets the processor overlap
     * their serial chains (each element waits for its upstream neighbour);
     * the sums are still added row by row, in order. */
    for (j = 0; j < ny; j += ROWS_AT_ONCE) {
        row r[ROWS_AT_ONCE];
        const int nrow = ny - j < ROWS_AT_ONCE ? ny - j : ROWS_AT_ONCE;
        int k;
        for (k = 0; k < nrow; k++)
            row_init(&m, o, j + k, &r[k]);
        if (nrow == ROWS_AT_ONCE) {
            for (i = 0; i < nx; i++)
                for (k = 0; k < ROWS_AT_ONCE; k++)
                    element(&m, &r[k], i);
        } else {
            for (k = 0; k < nrow; k++)
                for (i = 0; i < nx; i++)
                    element(&m, &r[k], i);
        }
        for (k = 0; k < nrow; k++) {
            fx += r[k].sx * r[k].h;
            fy += r[k].sy * r[k].h;
            mz += r[k].sm * r[k].h;
        }
    }
    converged = m.converged;
    nslip = m.nslip;
    out->fx = fx * dy;
    out->fy = fy * dy;
    out->mz = mz * dy;
    if (field)
        field->nslip = nslip;
    if (!converged && st == RR_OK)
        st = RR_WARN_NOT_CONVERGED;
    return st;
}
