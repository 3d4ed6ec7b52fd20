/*
 * fuzz_creepage.c - the kinematic creepages rr_creepage.
 *
 * Input: the wheel's and the roller's rigid-body motions (reference points
 * within 1 m, velocities to 50 m/s, angular velocities to 500 rad/s), the
 * contact frame (a point, and either an orthonormal pair from three angles
 * or nine free components), vmin (1e-4 .. 1 m/s).
 *
 * Oracles: documented errors (non-finite inputs, vmin <= 0, a frame off
 * orthonormal by more than 1e-9), NaN outputs on error, finite outputs
 * and V >= vmin on success.
 */
#include "fuzz.h"

static void decode_motion(fz_in *in, rr_motion *m)
{
    int k;
    for (k = 0; k < 3; k++) {
        m->c[k] = fz_lin(in, -1.0, 1.0);
        m->v[k] = fz_slog(in, 1e-6, 50.0);
        m->w[k] = fz_slog(in, 1e-6, 500.0);
    }
}

/* t1 from two angles, t2 orthogonal to it at a third; or free components
 * (near unit vectors when perturbed slightly, anywhere otherwise). */
static void decode_frame(fz_in *in, rr_contact_frame *f)
{
    int k;
    for (k = 0; k < 3; k++)
        f->p[k] = fz_lin(in, -1.0, 1.0);
    if (fz_choice(in, 4) != 0) {
        const double th = fz_lin(in, 0.0, RR_PI), ph = fz_lin(in, -RR_PI, RR_PI);
        const double ga = fz_lin(in, -RR_PI, RR_PI);
        const double t1[3] = {sin(th) * cos(ph), sin(th) * sin(ph), cos(th)};
        /* two unit vectors orthogonal to t1 */
        const double e1[3] = {cos(th) * cos(ph), cos(th) * sin(ph), -sin(th)};
        const double e2[3] = {-sin(ph), cos(ph), 0.0};
        for (k = 0; k < 3; k++) {
            f->t1[k] = t1[k];
            f->t2[k] = cos(ga) * e1[k] + sin(ga) * e2[k];
        }
        if (fz_choice(in, 8) == 0) {
            /* off orthonormal by a little, either side of the 1e-9 tolerance */
            k = fz_choice(in, 3);
            f->t2[k] += fz_slog(in, 1e-12, 1e-6);
        }
    } else {
        for (k = 0; k < 3; k++) {
            f->t1[k] = fz_lin(in, -1.0, 1.0);
            f->t2[k] = fz_lin(in, -1.0, 1.0);
        }
    }
}

static int all_finite(const double *v, int n)
{
    int k;
    for (k = 0; k < n; k++)
        if (!isfinite(v[k]))
            return 0;
    return 1;
}

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double max_abs(const double *v, int n)
{
    double m = 0.0;
    int k;
    for (k = 0; k < n; k++)
        m = fmax(m, fabs(v[k]));
    return m;
}

/* Known: positions, velocities or rates beyond about 1e100, or vmin below
 * 1e-100, overflow the cross products or the divisions by V: inf or NaN
 * creepages with status 0. */
static int known_extreme(const rr_motion *w, const rr_motion *r, const rr_contact_frame *f,
                         double vmin)
{
    const double m = fmax(fmax(fmax(max_abs(w->c, 3), max_abs(w->v, 3)),
                               fmax(max_abs(w->w, 3), max_abs(r->c, 3))),
                          fmax(fmax(max_abs(r->v, 3), max_abs(r->w, 3)), max_abs(f->p, 3)));
    return m > 1e100 || vmin < 1e-100;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    const char *fn = "rr_creepage";
    rr_motion wheel, roller;
    rr_contact_frame f;
    rr_creepages out;
    double vmin;
    int st, nonfinite, invalid;

    decode_motion(&in, &wheel);
    decode_motion(&in, &roller);
    decode_frame(&in, &f);
    vmin = fz_log(&in, 1e-4, 1.0);
    fz_note("wheel c (%.17g, %.17g, %.17g) v (%.17g, %.17g, %.17g) w (%.17g, %.17g, %.17g); "
            "roller c (%.17g, %.17g, %.17g) v (%.17g, %.17g, %.17g) w (%.17g, %.17g, %.17g); "
            "frame p (%.17g, %.17g, %.17g) t1 (%.17g, %.17g, %.17g) t2 (%.17g, %.17g, %.17g); "
            "vmin %.17g", wheel.c[0], wheel.c[1], wheel.c[2], wheel.v[0], wheel.v[1],
            wheel.v[2], wheel.w[0], wheel.w[1], wheel.w[2], roller.c[0], roller.c[1],
            roller.c[2], roller.v[0], roller.v[1], roller.v[2], roller.w[0], roller.w[1],
            roller.w[2], f.p[0], f.p[1], f.p[2], f.t1[0], f.t1[1], f.t1[2], f.t2[0], f.t2[1],
            f.t2[2], vmin);
    nonfinite = !all_finite(wheel.c, 3) || !all_finite(wheel.v, 3) || !all_finite(wheel.w, 3)
                || !all_finite(roller.c, 3) || !all_finite(roller.v, 3)
                || !all_finite(roller.w, 3) || !all_finite(f.p, 3) || !all_finite(f.t1, 3)
                || !all_finite(f.t2, 3) || !isfinite(vmin);
    /* the tolerance is the header's; a frame this close to it may go either way */
    invalid = nonfinite || !(vmin > 0.0) || fabs(dot(f.t1, f.t1) - 1.0) > 2e-9
              || fabs(dot(f.t2, f.t2) - 1.0) > 2e-9 || fabs(dot(f.t1, f.t2)) > 2e-9;

    memset(&out, 0x55, sizeof out);
    st = rr_creepage(&wheel, &roller, &f, vmin, &out);
    fz_status(fn, st);
    fz_error(fn, st, invalid, "an argument is invalid");
    if (nonfinite && st != RR_ERR_NONFINITE)
        fz_fail("%s: status %d for a non-finite argument (documented: RR_ERR_NONFINITE)", fn, st);
    if (st < 0) {
        if (!isnan(out.cx) || !isnan(out.cy) || !isnan(out.cphi) || !isnan(out.V)
            || !isnan(out.slip[0]) || !isnan(out.slip[1]) || !isnan(out.slip[2]))
            fz_fail("%s: error %d but the outputs are not NaN", fn, st);
        return 0;
    }
    if (fz_known("extreme", known_extreme(&wheel, &roller, &f, vmin)))
        return 0;
    FZ_FINITE(fn, st, out.cx);
    FZ_FINITE(fn, st, out.cy);
    FZ_FINITE(fn, st, out.cphi);
    FZ_FINITE(fn, st, out.V);
    fz_finite_n(fn, st, "slip", out.slip, 3);
    if (!(out.V >= vmin))
        fz_fail("%s: V = %.17g below vmin = %.17g", fn, out.V, vmin);
    return 0;
}
