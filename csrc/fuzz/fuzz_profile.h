/*
 * fuzz_profile.h - a wheel's or a roller's profile decoded from the input,
 * for the targets that search contacts on them (fuzz_geometry.c,
 * fuzz_gap.c, fuzz_nonhertz_row.c), and a pair on two of them: its base shape (a cone of slope tan(alpha), a circular
 * crown of radius rho) on min_points .. FZ_PROFILE_POINTS points over a
 * width from the input, that shape with a perturbation of each point, or a
 * free point list (increments and heights).  Include after fuzz.h.
 */
#ifndef FUZZ_PROFILE_H
#define FUZZ_PROFILE_H

#define FZ_PROFILE_POINTS 80

typedef struct {
    int n;
    double s[FZ_PROFILE_POINTS], z[FZ_PROFILE_POINTS], m[FZ_PROFILE_POINTS];
} fz_profile;

/* 0 and the spline in p, or rr_spline_init's (nonzero) status; the points
 * noted in full where note_points (a reproducer's context). */
static int fz_decode_profile(fz_in *in, fz_profile *p, int roller, int min_points,
                             int note_points)
{
    const int mode = fz_choice(in, 4);
    const int n = fz_range(in, min_points, FZ_PROFILE_POINTS);
    double work[FZ_PROFILE_POINTS];
    int i;
    p->n = n;
    if (mode <= 1) {
        const double shape = roller ? fz_log(in, 0.01, 1.0) : fz_lin(in, -0.1, 0.3);
        const double half = (roller ? 0.9 * shape : 0.05) * fz_lin(in, 0.05, 1.0);
        const double amp = mode == 1 ? fz_log(in, 1e-12, 1e-3) : 0.0;
        for (i = 0; i < n; i++) {
            const double s = -half + 2.0 * half * i / (n - 1);
            p->s[i] = s;
            p->z[i] = roller ? sqrt(shape * shape - s * s) - shape : s * tan(shape);
            if (mode == 1)
                p->z[i] += amp * fz_lin(in, -1.0, 1.0);
        }
    } else {
        in->edges = mode == 2;
        p->s[0] = fz_lin(in, -0.05, 0.0);
        p->z[0] = fz_lin(in, -0.005, 0.005);
        for (i = 1; i < n; i++) {
            p->s[i] = p->s[i - 1] + fz_log(in, 1e-4, 5e-3);
            p->z[i] = fz_lin(in, -0.005, 0.005);
        }
        in->edges = 1;
    }
    fz_note("%s profile mode %d, %d points", roller ? "roller" : "wheel", mode, n);
    for (i = 0; note_points && i < n; i++)
        fz_note(" (%.17g, %.17g)", p->s[i], p->z[i]);
    fz_note("; ");
    return rr_spline_init(n, p->s, p->z, p->m, work);
}

/* The pair's splines: profiles w and r (their arrays, not copies). */
static inline void fz_attach_profiles(const fz_profile *w, const fz_profile *r,
                                      rr_wheel_roller *p)
{
    p->wheel.n = w->n;
    p->wheel.s = w->s;
    p->wheel.z = w->z;
    p->wheel.m = w->m;
    p->roller.n = r->n;
    p->roller.s = r->s;
    p->roller.z = r->z;
    p->roller.m = r->m;
}

/* The pair on profiles w and r: radii, places and side (now and then not
 * +-1) from the input. */
static inline void fz_set_pair(fz_in *in, const fz_profile *w, const fz_profile *r,
                               rr_wheel_roller *p)
{
    fz_attach_profiles(w, r, p);
    p->r0 = fz_log(in, 0.02, 0.5);
    p->R0 = fz_log(in, 0.02, 0.9);
    p->wheel_y = fz_lin(in, 0.05, 0.8);
    p->roller_y = p->wheel_y + fz_lin(in, -0.005, 0.005);
    p->side = fz_choice(in, 16) == 0 ? fz_int(in, -2, 2) : 1;
    fz_note("pair r0 %.17g R0 %.17g wheel_y %.17g roller_y %.17g side %d; ", p->r0, p->R0,
            p->wheel_y, p->roller_y, p->side);
}

#endif
