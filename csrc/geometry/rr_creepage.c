/* rr_creepage.c - Kalker's kinematic creepages from two rigid-body motions. */
#include <math.h>
#include "util/rr_common.h"
#include "geometry/rr_creepage.h"

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Velocity of the body's material point at p. */
static void point_velocity(const rr_motion *m, const double p[3], double out[3])
{
    double r[3], wr[3];
    int k;
    for (k = 0; k < 3; k++)
        r[k] = p[k] - m->c[k];
    cross(m->w, r, wr);
    for (k = 0; k < 3; k++)
        out[k] = m->v[k] + wr[k];
}

static int all_finite(const double *x, int n)
{
    int k;
    for (k = 0; k < n; k++)
        if (!isfinite(x[k]))
            return 0;
    return 1;
}

static void set_nan(rr_creepages *out)
{
    out->cx = out->cy = out->cphi = out->V = NAN;
    out->slip[0] = out->slip[1] = out->slip[2] = NAN;
}

int rr_creepage(const rr_motion *wheel, const rr_motion *roller, const rr_contact_frame *f,
                double vmin, rr_creepages *out)
{
    double vw[3], vr[3], n[3], dw[3], V;
    int k;

    if (!out)
        return RR_ERR_NULL;
    if (!wheel || !roller || !f) {
        set_nan(out);
        return RR_ERR_NULL;
    }
    if (!all_finite(wheel->c, 3) || !all_finite(wheel->v, 3) || !all_finite(wheel->w, 3)
        || !all_finite(roller->c, 3) || !all_finite(roller->v, 3)
        || !all_finite(roller->w, 3) || !all_finite(f->p, 3) || !all_finite(f->t1, 3)
        || !all_finite(f->t2, 3) || !isfinite(vmin)) {
        set_nan(out);
        return RR_ERR_NONFINITE;
    }
    if (!(vmin > 0.0)) {
        set_nan(out);
        return RR_ERR_SPEED;
    }
    if (fabs(dot(f->t1, f->t1) - 1.0) > 1e-9 || fabs(dot(f->t2, f->t2) - 1.0) > 1e-9
        || fabs(dot(f->t1, f->t2)) > 1e-9) {
        set_nan(out);
        return RR_ERR_GEOMETRY;
    }
    point_velocity(wheel, f->p, vw);
    point_velocity(roller, f->p, vr);
    cross(f->t1, f->t2, n);
    for (k = 0; k < 3; k++) {
        out->slip[k] = vw[k] - vr[k];
        dw[k] = wheel->w[k] - roller->w[k];
    }
    V = 0.5 * fabs(dot(vw, f->t1) + dot(vr, f->t1));
    if (V < vmin)
        V = vmin;
    out->V = V;
    out->cx = dot(out->slip, f->t1) / V;
    out->cy = dot(out->slip, f->t2) / V;
    out->cphi = dot(dw, n) / V;
    if (!rr_all_finite(out->slip, 3)
        || !isfinite(0.0 * out->cx + 0.0 * out->cy + 0.0 * out->cphi + 0.0 * V)) {
        set_nan(out);               /* speeds over ~1e150 m/s, or a tiny vmin */
        return RR_ERR_RANGE;
    }
    return RR_OK;
}
