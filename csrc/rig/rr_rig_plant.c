/*
 * rr_rig_plant.c - the roller rig's plant (rr_rig.h): the adhesion in time
 * and on the roller, the normal loads from the contact constraint, the
 * contact evaluation of both wheels, the right-hand side, the Jacobian and
 * its constant part, the integrator's model (the simplified theory's
 * linearisation), and what the rig takes from its parameters (bind).  The
 * sampled side (checks, life, commands, controllers, steps) is rr_rig.c.
 */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "rig/rr_rig.h"

#define NS RR_RIG_NSTATE
/* a creep force may pass mu N by this share (rounding) before it is an error */
#define FRICTION_ROUNDING 1e-9
/* contact angles [rad] below which a contact is on the tread (the
 * Jacobian's conicity term: linearise) */
#define TREAD_ANGLE 0.1

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* The law a fraction f of the way from a to b (mu0, A and B each). */
static rr_friction blend(const rr_friction *a, const rr_friction *b, double f)
{
    rr_friction r;
    r.mu0 = a->mu0 + f * (b->mu0 - a->mu0);
    r.A = a->A + f * (b->A - a->A);
    r.B = a->B + f * (b->B - a->B);
    return r;
}

double rr_rig_lateral_force(const rr_rig_lateral *l, double t)
{
    int i = 0;
    if (!l || l->n <= 0 || l->n > RR_RIG_MAX_SCHEDULE)
        return 0.0;
    if (!(t >= l->t[0]))
        return l->f[0];
    while (i + 1 < l->n && l->t[i + 1] <= t)
        i++;
    if (i + 1 == l->n)
        return l->f[i];
    return l->f[i] + (t - l->t[i]) / (l->t[i + 1] - l->t[i]) * (l->f[i + 1] - l->f[i]);
}

rr_friction rr_rig_schedule_law(const rr_rig_params *p, double t)
{
    const rr_rig_adhesion *a = &p->adhesion;
    int i = 0;
    if (a->n <= 0)
        return p->contact.friction;
    if (!(t >= a->t[0]))
        return a->law[0];
    while (i + 1 < a->n && a->t[i + 1] <= t)
        i++;
    if (i + 1 == a->n)
        return a->law[i];
    return blend(&a->law[i], &a->law[i + 1], (t - a->t[i]) / (a->t[i + 1] - a->t[i]));
}

/* The fraction of the patch at material position s [m] (1 inside, 0
 * outside, linear across each edge), on a circumference of length C. */
static double patch_fraction(const rr_rig_adhesion *a, double C, double s)
{
    double u = fmod(s - a->patch_start, C), d;
    if (u < 0.0)
        u += C;
    /* signed distance to the nearer edge: > 0 inside, < 0 outside */
    if (u <= a->patch_length)
        d = fmin(u, a->patch_length - u);
    else
        d = -fmin(u - a->patch_length, C - u);
    return fmin(1.0, fmax(0.0, 0.5 + d / a->patch_edge));
}

/* law with the patch's share at material position s [m] of roller `side`. */
static rr_friction patched(const rr_rig_params *p, rr_friction law, int side, double s)
{
    const rr_rig_adhesion *a = &p->adhesion;
    if (a->patch_length > 0.0 && (side == 0 || side == 1) && (a->patch_rollers & (1 << side))
        && isfinite(s)) {
        const double f = patch_fraction(a, 2.0 * RR_PI * p->contact.R0, s);
        if (f >= 1.0)
            law = a->patch;             /* inside: the patch's law, exactly */
        else if (f > 0.0)
            law = blend(&law, &a->patch, f);
    }
    return law;
}

rr_friction rr_rig_friction_at(const rr_rig_params *p, double t, int side, double s)
{
    if (!p) {
        rr_friction none = {NAN, NAN, NAN};
        return none;
    }
    return patched(p, rr_rig_schedule_law(p, t), side, s);
}

/* The spin's gyroscopic moment at y (rr_rig.h): I_w spin (w_f x a), the
 * axle a and the frame's rate w_f (roll and yaw, the spin taken out) of the
 * pose; zero where gyro_inertia is. */
static void gyroscopic(const rr_rig_params *p, const rr_rig_pose *pose, const double *y,
                       double G[3])
{
    const double cy = cos(y[RR_RIG_YAW]), sy = sin(y[RR_RIG_YAW]);
    const double cr = cos(pose->roll), sr = sin(pose->roll);
    const double a[3] = {-sy * cr, cy * cr, sr};
    const double wf[3] = {pose->roll_rate * cy, pose->roll_rate * sy, y[RR_RIG_YAW_RATE]};
    const double h = p->gyro_inertia * y[RR_RIG_SPIN];
    int j;
    cross(wf, a, G);
    for (j = 0; j < 3; j++)
        G[j] *= h;
}

/* Solve [a b; c d] x = r; 0, or RR_ERR_LOAD if singular or a load is not positive. */
static int loads(double a, double b, double c, double d, double r0, double r1, double N[2])
{
    const double det = a * d - b * c;
    if (!(fabs(det) > 0.0))
        return RR_ERR_LOAD;
    N[0] = (d * r0 - b * r1) / det;
    N[1] = (a * r1 - c * r0) / det;
    return N[0] > 0.0 && N[1] > 0.0 ? RR_OK : RR_ERR_LOAD;
}

/* Coefficients of N_left, N_right in the vertical force and the roll
 * moment of the direction d_j (per unit load) acting at p_j. */
static void balance_row(const rr_rig_pose *pose, const rr_wheel_contact *w, const double d[3],
                        double extra_mx, double *fz, double *mx)
{
    double arm[3], m[3];
    int j;
    for (j = 0; j < 3; j++)
        arm[j] = w->frame.p[j] - pose->c[j];
    cross(arm, d, m);
    *fz = d[2];
    *mx = m[0] + extra_mx;
}

/* The contact at state y with the normal loads from the wheelset's vertical
 * and roll balance; fills rig->pose, rig->w.  Cached on y. */
static int contact_eval(rr_rig *rig, const double *y)
{
    const rr_rig_params *p = rig->p;
    rr_rig_state s;
    double Wz, Mx, fz[2], mx[2], N[2], N2[2];
    int k, st;

    if (rig->cache_ok && memcmp(rig->cache_y, y, sizeof rig->cache_y) == 0)
        return rig->w[0].status < rig->w[1].status ? rig->w[0].status : rig->w[1].status;
    rig->cache_ok = 0;
    s.x = y[RR_RIG_X];
    s.y = y[RR_RIG_Y];
    s.yaw = y[RR_RIG_YAW];
    s.vx = y[RR_RIG_VX];
    s.vy = y[RR_RIG_VY];
    s.yaw_rate = y[RR_RIG_YAW_RATE];
    s.spin = y[RR_RIG_SPIN];
    s.roller_spin = y[RR_RIG_ROLLER_SPIN];
    st = rr_rig_kinematics_checked(&rig->contact, &s, &rig->pose, rig->w);
    if (st < 0)
        return st;
    /* the friction at each contact: the held law, and the patch where the
     * contact's material position s = R0 (theta_r + theta) lies on it */
    for (k = 0; k < 2; k++)
        rig->w[k].friction = patched(p, rig->friction, k,
                                     p->contact.R0 * (y[RR_RIG_THETA_R] + rig->w[k].theta));

    /* what the contacts must carry: preload, weight, the springs' and
     * dampers' change, and their roll moment */
    {
        const double b2 = p->axlebox_y * p->axlebox_y;
        Wz = p->preload + p->mass * p->g + 2.0 * p->kz * (rig->pose.c[2] - rig->z_ref)
           + 2.0 * p->cz * rig->pose.v[2];
        Mx = 2.0 * b2 * (p->kz * rig->pose.roll + p->cz * rig->pose.roll_rate);
        if (p->gyro_inertia > 0.0) {
            /* the contacts also turn the spin's momentum: (d H/dt)_x */
            double G[3];
            gyroscopic(p, &rig->pose, y, G);
            Mx += G[0];
        }
    }
    for (k = 0; k < 2; k++)
        balance_row(&rig->pose, &rig->w[k], rig->w[k].n, 0.0, &fz[k], &mx[k]);
    if ((st = loads(fz[0], fz[1], mx[0], mx[1], Wz, Mx, N)) != RR_OK)
        return st;
    st = rr_rig_contact_loads_checked(&rig->contact, N, &rig->pose, rig->w);
    if (st < 0)
        return st;

    /* the tangential forces carry part of the load (the paper's F_y tan
     * alpha): rebalance with them in proportion to each load, then scale
     * the forces to the new loads (their ratio to the load held) */
    for (k = 0; k < 2; k++) {
        rr_wheel_contact *w = &rig->w[k];
        double d[3];
        int j;
        for (j = 0; j < 3; j++)
            d[j] = w->force[j] / N[k];
        balance_row(&rig->pose, w, d, w->f.mz * w->n[0] / N[k], &fz[k], &mx[k]);
    }
    if ((st = loads(fz[0], fz[1], mx[0], mx[1], Wz, Mx, N2)) != RR_OK)
        return st;
    for (k = 0; k < 2; k++) {
        rr_wheel_contact *w = &rig->w[k];
        const double f = N2[k] / N[k];
        int j;
        w->N = N2[k];
        w->f.fx *= f;
        w->f.fy *= f;
        w->f.mz *= f;
        for (j = 0; j < 3; j++) {
            w->force[j] *= f;
            w->moment[j] *= f;
        }
        /* whatever the method: a tangential force beyond mu N (mu(w) <= mu0,
         * rr_friction.h) is an error, never an adhesion the rig reports;
         * FRICTION_ROUNDING covers the rounding of the sums and the scaling */
        if (hypot(w->f.fx, w->f.fy) > w->friction.mu0 * w->N * (1.0 + FRICTION_ROUNDING))
            return RR_ERR_FRICTION_LIMIT;
    }
    memcpy(rig->cache_y, y, sizeof rig->cache_y);
    rig->cache_ok = 1;
    return st;
}

int rr_rig_rhs(rr_rig *rig, double t, const double *y, double *dydt)
{
    const rr_rig_params *p;
    double F[3] = {0.0, 0.0, 0.0}, M[3] = {0.0, 0.0, 0.0}, Mr = 0.0, axle[3];
    int k, j, st;
    (void)t;

    if (!dydt)
        return RR_ERR_NULL;
    st = y ? rr_rig_usable(rig) : RR_ERR_NULL;
    if (st == RR_OK && !rr_all_finite(y, NS))
        st = RR_ERR_NONFINITE;      /* angles and torques too, not only what the contact reads */
    if (st == RR_OK)
        st = contact_eval(rig, y);
    p = rig ? rig->p : NULL;
    if (st < 0) {
        for (j = 0; j < NS; j++)
            dydt[j] = NAN;
        return st;
    }
    for (k = 0; k < 2; k++) {
        const rr_wheel_contact *w = &rig->w[k];
        double r[3], m[3];
        for (j = 0; j < 3; j++) {
            F[j] += w->force[j];
            M[j] += w->moment[j];
        }
        /* the contact force's moment about the roller axis (0, y, -R0) */
        r[0] = w->frame.p[0];
        r[1] = 0.0;
        r[2] = w->frame.p[2] + p->contact.R0;
        cross(r, w->force, m);
        Mr += m[1];
    }
    {
        const double cy = cos(y[RR_RIG_YAW]), sy = sin(y[RR_RIG_YAW]);
        const double cr = cos(rig->pose.roll), sr = sin(rig->pose.roll);
        const double b2 = p->axlebox_y * p->axlebox_y;
        axle[0] = -sy * cr;
        axle[1] = cy * cr;
        axle[2] = sr;
        dydt[RR_RIG_X] = y[RR_RIG_VX];
        dydt[RR_RIG_Y] = y[RR_RIG_VY];
        dydt[RR_RIG_YAW] = y[RR_RIG_YAW_RATE];
        dydt[RR_RIG_CHI] = y[RR_RIG_SPIN];
        dydt[RR_RIG_THETA_R] = y[RR_RIG_ROLLER_SPIN];
        dydt[RR_RIG_VX] = (F[0] - 2.0 * (p->kx * y[RR_RIG_X] + p->cx * y[RR_RIG_VX])) / p->mass;
        /* the disturbance, at the sample's start (none: the sum untouched) */
        if (p->lateral.n > 0)
            F[1] += rr_rig_lateral_force(&p->lateral, rig->t);
        dydt[RR_RIG_VY] = (F[1] - 2.0 * (p->ky * y[RR_RIG_Y] + p->cy * y[RR_RIG_VY])) / p->mass;
        if (p->gyro_inertia > 0.0) {
            double G[3];
            gyroscopic(p, &rig->pose, y, G);
            M[2] -= G[2];
        }
        dydt[RR_RIG_YAW_RATE] = (M[2] - 2.0 * b2 * (p->kx * y[RR_RIG_YAW]
                                                    + p->cx * y[RR_RIG_YAW_RATE])) / p->Izz;
        dydt[RR_RIG_SPIN] = (M[0] * axle[0] + M[1] * axle[1] + M[2] * axle[2]
                             + y[RR_RIG_T_WHEELSET]) / p->Iyy;
        /* on track the rails keep their speed whatever the contact does */
        dydt[RR_RIG_ROLLER_SPIN] = p->track ? 0.0 : (y[RR_RIG_T_ROLLER] + Mr) / p->roller_inertia;
        dydt[RR_RIG_T_ROLLER] = (rig->Tref_roller - y[RR_RIG_T_ROLLER]) / p->roller_tau;
        dydt[RR_RIG_T_WHEELSET] = (rig->Tref_wheelset - y[RR_RIG_T_WHEELSET]) / p->wheelset_tau;
    }
    if (!rr_all_finite(dydt, NS)) {
        /* finite forces over a tiny mass or inertia, or a huge state */
        for (j = 0; j < NS; j++)
            dydt[j] = NAN;
        return RR_ERR_RANGE;
    }
    return st;
}

/* The Jacobian's part that does not depend on the state: the kinematic
 * rows, the springs and dampers, the drive torques and their lags. */
static void jac_const(const rr_rig_params *p, double *J)
{
    const double b2 = p->axlebox_y * p->axlebox_y;
    int j;

    for (j = 0; j < NS * NS; j++)
        J[j] = 0.0;
#define JJ(row, col) J[(row) * NS + (col)]
    JJ(RR_RIG_X, RR_RIG_VX) = 1.0;
    JJ(RR_RIG_Y, RR_RIG_VY) = 1.0;
    JJ(RR_RIG_YAW, RR_RIG_YAW_RATE) = 1.0;
    JJ(RR_RIG_CHI, RR_RIG_SPIN) = 1.0;
    JJ(RR_RIG_THETA_R, RR_RIG_ROLLER_SPIN) = 1.0;
    JJ(RR_RIG_VX, RR_RIG_X) = -2.0 * p->kx / p->mass;
    JJ(RR_RIG_VX, RR_RIG_VX) = -2.0 * p->cx / p->mass;
    JJ(RR_RIG_VY, RR_RIG_Y) = -2.0 * p->ky / p->mass;
    JJ(RR_RIG_VY, RR_RIG_VY) = -2.0 * p->cy / p->mass;
    JJ(RR_RIG_YAW_RATE, RR_RIG_YAW) = -2.0 * b2 * p->kx / p->Izz;
    JJ(RR_RIG_YAW_RATE, RR_RIG_YAW_RATE) = -2.0 * b2 * p->cx / p->Izz;
    JJ(RR_RIG_SPIN, RR_RIG_T_WHEELSET) = 1.0 / p->Iyy;
    JJ(RR_RIG_ROLLER_SPIN, RR_RIG_T_ROLLER) = p->track ? 0.0 : 1.0 / p->roller_inertia;
    JJ(RR_RIG_T_ROLLER, RR_RIG_T_ROLLER) = -1.0 / p->roller_tau;
    JJ(RR_RIG_T_WHEELSET, RR_RIG_T_WHEELSET) = -1.0 / p->wheelset_tau;
#undef JJ
}

/*
 * Creep forces of Kalker's simplified theory, the cubic law
 *     f = -F u/|u|,  F = mu N (1 - (1 - eps)^3),  eps = |u| / (3 mu N),
 * u = (f11 cx, f22 cy), with the falling friction mu at the rigid slip
 * speed |c| V (FASTSIM's creep curve to a few per cent); f = -u at zero
 * creepage.  D (may be NULL): the tangent d f / d c,
 * row-major 2 x 2: along u the curve's slope, across it F/|u| (a saturated
 * contact turns its force with the slip, it does not stiffen).
 */
static void simplified_forces(const rr_rig_creep_lin *l, double cx, double cy, double f[2],
                              double D[4])
{
    const double ux = l->f11 * cx, uy = l->f22 * cy, u = hypot(ux, uy), c = hypot(cx, cy);
    const double fc[2] = {l->f11, l->f22}, cc[2] = {cx, cy};
    double mu, dmu, e, s2, g3, F, dS[2], uh[2];
    int i, j;

    if (!(u > 0.0)) {
        f[0] = -ux;
        f[1] = -uy;
        if (D) {
            D[0] = -l->f11;
            D[3] = -l->f22;
            D[1] = D[2] = 0.0;
        }
        return;
    }
    mu = rr_friction_mu(&l->friction, c * l->V);
    e = u / (3.0 * mu * l->N);
    s2 = e < 1.0 ? (1.0 - e) * (1.0 - e) : 0.0;
    g3 = e < 1.0 ? 1.0 - s2 * (1.0 - e) : 1.0;
    F = mu * l->N * g3;
    uh[0] = ux / u;
    uh[1] = uy / u;
    f[0] = -F * uh[0];
    f[1] = -F * uh[1];
    if (!D)
        return;
    /* dF/dc_j = s2 uh_j f_jj + N V mu' (c_j/|c|) (g3 - 3 eps s2) */
    dmu = rr_friction_dmu(&l->friction, c * l->V);
    for (j = 0; j < 2; j++)
        dS[j] = s2 * uh[j] * fc[j] + l->N * l->V * dmu * (cc[j] / c) * (g3 - 3.0 * e * s2);
    for (i = 0; i < 2; i++)
        for (j = 0; j < 2; j++)
            D[2 * i + j] = -(dS[j] * uh[i] + F / u * ((i == j) - uh[i] * uh[j]) * fc[j]);
}

/* The creep forces linearised at y into rig->lin (cached on y). */
static int linearise(rr_rig *rig, const double *y)
{
    const rr_rig_params *p = rig->p;
    rr_contact_point cp[2], cm[2];
    double hy = 0.0;
    int k, st, pm_ok = 0;

    if (rig->lin_ok && memcmp(rig->lin_y, y, sizeof rig->lin_y) == 0)
        return RR_OK;
    rig->lin_ok = 0;
    st = contact_eval(rig, y);
    if (st < 0)
        return st;
    {
        /* the table's contacts just either side of the shift: the slope of
         * its interpolant there (what the right-hand side differentiates) */
        rr_wheelset_pose tp;
        const rr_contact_table *tab = p->contact.table;
        hy = 1e-4 * tab->dy;
        pm_ok = rr_contact_table_lookup(tab, y[RR_RIG_Y] + hy, &tp, NULL, &cp[0], &cp[1]) >= 0
             && rr_contact_table_lookup(tab, y[RR_RIG_Y] - hy, &tp, NULL, &cm[0], &cm[1]) >= 0;
    }
    for (k = 0; k < 2; k++) {
        const rr_wheel_contact *w = &rig->w[k];
        rr_rig_creep_lin *l = &rig->lin[k];
        const double ab = w->hertz.a / w->hertz.b;
        double gab, f[2];

        if (!(ab == l->ab && l->ok)) {
            rr_kalker_coeffs kc;
            l->ok = rr_kalker(ab, p->contact.nu, &kc) == RR_OK;
            if (!l->ok)
                continue;
            l->ab = ab;
            l->c11 = kc.c11;
            l->c22 = kc.c22;
        }
        /* the method's own initial slope over the linear theory's (its
         * descriptor's: Polach's (kA + kS)/2, modified FASTSIM's k0) */
        gab = p->contact.G * w->hertz.a * w->hertz.b * rig->creep_slope_scale;
        l->f11 = gab * l->c11;
        l->f22 = gab * l->c22;
        l->N = w->N;
        l->V = w->creep.V;
        l->friction = w->friction;
        l->cx = w->creep.cx;
        l->cy = w->creep.cy;
        {
            /* a: lateral arm to the wheelset centre; r, R: wheel and roller radii */
            const double a = w->frame.p[1] - rig->pose.c[1], r = w->geo.r, R = w->geo.R;
            int j;
            for (j = 0; j < NS; j++)
                l->dcx[j] = l->dcy[j] = l->rx[j] = l->ry[j] = 0.0;
            l->dcx[RR_RIG_VX] = 1.0 / l->V;
            l->dcx[RR_RIG_SPIN] = -r / l->V;
            l->dcx[RR_RIG_YAW_RATE] = -a / l->V;
            l->dcx[RR_RIG_ROLLER_SPIN] = R / l->V;
            l->dcy[RR_RIG_VY] = 1.0 / l->V;
            l->dcy[RR_RIG_YAW] = -1.0;
            l->rx[RR_RIG_VX] = 1.0 / p->mass;
            l->rx[RR_RIG_YAW_RATE] = -a / p->Izz;
            l->rx[RR_RIG_SPIN] = -r / p->Iyy;
            l->rx[RR_RIG_ROLLER_SPIN] = p->track ? 0.0 : R / p->roller_inertia;
            l->ry[RR_RIG_VY] = 1.0 / p->mass;
            /* the rolling radii's change with the shift: the conicity's
             * longitudinal creepage (eq. 7), the coupling of hunting, which
             * an explicit treatment turns into negative damping (at 60 m/s
             * on track, soft suspension: +1.3/s without it, -1.36/s with
             * it, -1.26/s linearised); on the tread only: across a flange
             * root the slope changes within a step, and one Newton
             * iteration with it overshoots */
            if (pm_ok && fabs(w->geo.delta) < TREAD_ANGLE)
                l->dcx[RR_RIG_Y] = (-y[RR_RIG_SPIN] * (cp[k].r - cm[k].r)
                                    + y[RR_RIG_ROLLER_SPIN] * (cp[k].R - cm[k].R))
                                   / (2.0 * hy * l->V);
        }
        simplified_forces(l, l->cx, l->cy, f, l->D);
        l->fx = f[0];
        l->fy = f[1];
    }
    memcpy(rig->lin_y, y, sizeof rig->lin_y);
    rig->lin_ok = 1;
    return RR_OK;
}

int rr_rig_jac(rr_rig *rig, double t, const double *y, double *J)
{
    int k, i, j, st;
    (void)t;

    if (!J || !y)
        return RR_ERR_NULL;
    if ((st = rr_rig_usable(rig)) != RR_OK)
        return st;
    if (!rr_all_finite(y, NS))
        return RR_ERR_NONFINITE;
    st = linearise(rig, y);
    if (st < 0)
        return st;
    memcpy(J, rig->J0, sizeof rig->J0);
    /* the creep forces' change d f = D d c, D the simplified theory's
     * tangent (the falling friction's slope included), d c from the
     * linearised eq. 7-8 (lin->dcx, dcy), per unit change of each rate
     * the creepages depend on.  A secant would put a spurious stiff mode in
     * the saturated contact and slow the braking transients at the 4 ms
     * step. */
    for (k = 0; k < 2; k++) {
        const rr_rig_creep_lin *l = &rig->lin[k];
        const double *D = l->D;
        if (!l->ok)
            continue;
        for (j = 0; j < NS; j++) {
            /* the forces' change per unit change of y_j */
            const double dfx = D[0] * l->dcx[j] + D[1] * l->dcy[j];
            const double dfy = D[2] * l->dcx[j] + D[3] * l->dcy[j];
            if (dfx == 0.0 && dfy == 0.0)
                continue;
            for (i = RR_RIG_VX; i <= RR_RIG_ROLLER_SPIN; i++)
                J[i * NS + j] += l->rx[i] * dfx + l->ry[i] * dfy;
        }
    }
    /* the constant part J0 is finite (checked at init); the creep rows may not be */
    if (!rr_all_finite(J + RR_RIG_VX * NS, (RR_RIG_ROLLER_SPIN - RR_RIG_VX + 1) * NS)) {
        for (j = 0; j < NS * NS; j++)
            J[j] = NAN;             /* rates near the largest double: 1/V, D overflow */
        return RR_ERR_RANGE;
    }
    return RR_OK;
}

/* The integrator's model (rr_ode_model): the state's change d = z - y0
 * through the constant part of J, and the creep forces' change from the
 * simplified theory at the creepages moved by the linearised eq. 7-8, the
 * geometry and normal loads held at y0.  Exact for the linear rows; the
 * full method's forces at y0 carry the rest (rr_ode adds f(y0)). */
static int model_cb(void *ctx, double t, const double *y0, const double *z, double *df)
{
    rr_rig *rig = (rr_rig *)ctx;
    double d[NS];
    int i, j, k, st;
    (void)t;

    st = linearise(rig, y0);
    if (st < 0)
        return st;
    for (j = 0; j < NS; j++)
        d[j] = z[j] - y0[j];
    for (i = 0; i < NS; i++) {
        double sum = 0.0;
        for (j = 0; j < NS; j++)
            sum += rig->J0[i * NS + j] * d[j];
        df[i] = sum;
    }
    for (k = 0; k < 2; k++) {
        const rr_rig_creep_lin *l = &rig->lin[k];
        double dcx = 0.0, dcy = 0.0, f[2];
        if (!l->ok)
            continue;
        for (j = 0; j < NS; j++) {
            dcx += l->dcx[j] * d[j];
            dcy += l->dcy[j] * d[j];
        }
        simplified_forces(l, l->cx + dcx, l->cy + dcy, f, NULL);
        for (i = 0; i < NS; i++)
            df[i] += l->rx[i] * (f[0] - l->fx) + l->ry[i] * (f[1] - l->fy);
    }
    return RR_OK;
}

int rr_rig_bind(rr_rig *rig, const rr_rig_params *p)
{
    double J0[NS * NS];
    rr_rig_contact_checked contact;
    int st;
    jac_const(p, J0);
    if (!rr_all_finite(J0, NS * NS))
        return RR_ERR_RANGE;
    /* zero first: the rig is compared and copied byte for byte (its
     * padding too), and nothing of it may be undefined */
    memset(&contact, 0, sizeof contact);
    if ((st = rr_rig_contact_bind(&contact, &p->contact, rig->work, rig->work_len)) != RR_OK)
        return st;                  /* not after rr_rig_check; nothing changed */
    memcpy(rig->J0, J0, sizeof J0);
    rig->contact = contact;
    rig->p = p;
    rig->creep_slope_scale = rr_creep_slope_scale(&p->contact.creep);
    rig->ode.method = p->method;
    rig->ode.newton_iters = p->newton_iters;
    rig->ode.linear_tr = p->linear_tr;
    rig->ode.model = p->newton_model ? model_cb : NULL;
    /* x, y, yaw, chi, theta_r are integrals of the next five states */
    rig->ode.nq = RR_RIG_VX;
    /* a warning flags a stage left off by more than 0.1 % of its typical
     * size (ytyp): a Newton iteration that does not contract.  With one
     * iteration rr_ode has no rate to estimate the error with and takes
     * the whole correction instead: crossing the creep force's knee (the
     * paper's first braking transient) that reaches 0.54 % while the step
     * stays within 0.5 % of a 20-substep, 3-iteration reference; so one
     * iteration warns at a correction of 2 %, four times that */
    rig->ode.newton_tol = p->newton_iters == 1 ? 2e-2 : 1e-3;
    rig->ode.ytyp[RR_RIG_T_ROLLER] = p->roller_pi.Tmax;
    rig->ode.ytyp[RR_RIG_T_WHEELSET] = p->wheelset_pi.Tmax;
    rig->cache_ok = rig->lin_ok = 0;
    return RR_OK;
}
