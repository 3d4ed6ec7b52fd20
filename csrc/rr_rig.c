/* rr_rig.c - the roller rig in time: plant, normal loads, sampled control. */
#include <math.h>
#include <string.h>
#include "rr_common.h"
#include "rr_rig.h"

#define NS RR_RIG_NSTATE

static int positive(double v)
{
    return isfinite(v) && v > 0.0;
}

static int nonneg(double v)
{
    return isfinite(v) && v >= 0.0;
}

int rr_rig_check(const rr_rig_params *p)
{
    int st;
    if (!positive(p->mass) || !positive(p->Iyy) || !positive(p->Izz)
        || !positive(p->axlebox_y) || !positive(p->roller_inertia) || !nonneg(p->g)
        || !nonneg(p->kx) || !nonneg(p->ky) || !nonneg(p->kz) || !nonneg(p->cx)
        || !nonneg(p->cy) || !nonneg(p->cz) || !nonneg(p->preload)
        || !positive(p->T) || !positive(p->roller_tau) || !positive(p->wheelset_tau))
        return (isfinite(p->mass) && isfinite(p->Iyy) && isfinite(p->Izz)
                && isfinite(p->axlebox_y) && isfinite(p->roller_inertia) && isfinite(p->g)
                && isfinite(p->kx) && isfinite(p->ky) && isfinite(p->kz) && isfinite(p->cx)
                && isfinite(p->cy) && isfinite(p->cz) && isfinite(p->preload)
                && isfinite(p->T) && isfinite(p->roller_tau) && isfinite(p->wheelset_tau))
                   ? RR_ERR_PARAM : RR_ERR_NONFINITE;
    if (p->nsub < 1 || p->nsub > 1000)
        return RR_ERR_PARAM;
    if (p->method != RR_ODE_ROS2 && p->method != RR_ODE_TRBDF2 && p->method != RR_ODE_LINEULER)
        return RR_ERR_METHOD;
    if (p->newton_iters < 0 || p->newton_iters > RR_ODE_MAX_NEWTON
        || (p->linear_tr != 0 && p->linear_tr != 1))
        return RR_ERR_PARAM;
    if ((st = rr_rig_contact_check(&p->contact)) != RR_OK
        || (st = rr_pi_check(&p->roller_pi)) != RR_OK
        || (st = rr_pi_check(&p->wheelset_pi)) != RR_OK
        || (st = rr_encoder_check(&p->roller_enc)) != RR_OK
        || (st = rr_encoder_check(&p->wheelset_enc)) != RR_OK
        || (st = rr_creepctl_check(&p->creepctl)) != RR_OK)
        return st;
    /* every sampled element runs at the one sample time */
    if (p->roller_pi.T != p->T || p->wheelset_pi.T != p->T || p->roller_enc.T != p->T
        || p->wheelset_enc.T != p->T)
        return RR_ERR_PARAM;
    return RR_OK;
}

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
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
    st = rr_rig_kinematics(&p->contact, &s, &rig->pose, rig->w);
    if (st < 0)
        return st;

    /* what the contacts must carry: preload, weight, the springs' and
     * dampers' change, and their roll moment */
    {
        const double b2 = p->axlebox_y * p->axlebox_y;
        Wz = p->preload + p->mass * p->g + 2.0 * p->kz * (rig->pose.c[2] - rig->z_ref)
           + 2.0 * p->cz * rig->pose.v[2];
        Mx = 2.0 * b2 * (p->kz * rig->pose.roll + p->cz * rig->pose.roll_rate);
    }
    for (k = 0; k < 2; k++)
        balance_row(&rig->pose, &rig->w[k], rig->w[k].n, 0.0, &fz[k], &mx[k]);
    if ((st = loads(fz[0], fz[1], mx[0], mx[1], Wz, Mx, N)) != RR_OK)
        return st;
    st = rr_rig_contact_loads(&p->contact, N, &rig->pose, rig->w);
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
    }
    memcpy(rig->cache_y, y, sizeof rig->cache_y);
    rig->cache_ok = 1;
    return st;
}

int rr_rig_rhs(rr_rig *rig, double t, const double *y, double *dydt)
{
    const rr_rig_params *p = rig->p;
    double F[3] = {0.0, 0.0, 0.0}, M[3] = {0.0, 0.0, 0.0}, Mr = 0.0, axle[3];
    int k, j, st;
    (void)t;

    st = contact_eval(rig, y);
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
        dydt[RR_RIG_VY] = (F[1] - 2.0 * (p->ky * y[RR_RIG_Y] + p->cy * y[RR_RIG_VY])) / p->mass;
        dydt[RR_RIG_YAW_RATE] = (M[2] - 2.0 * b2 * (p->kx * y[RR_RIG_YAW]
                                                    + p->cx * y[RR_RIG_YAW_RATE])) / p->Izz;
        dydt[RR_RIG_SPIN] = (M[0] * axle[0] + M[1] * axle[1] + M[2] * axle[2]
                             + y[RR_RIG_T_WHEELSET]) / p->Iyy;
        dydt[RR_RIG_ROLLER_SPIN] = (y[RR_RIG_T_ROLLER] + Mr) / p->roller_inertia;
        dydt[RR_RIG_T_ROLLER] = (rig->Tref_roller - y[RR_RIG_T_ROLLER]) / p->roller_tau;
        dydt[RR_RIG_T_WHEELSET] = (rig->Tref_wheelset - y[RR_RIG_T_WHEELSET]) / p->wheelset_tau;
    }
    return st;
}

int rr_rig_jac(rr_rig *rig, double t, const double *y, double *J)
{
    const rr_rig_params *p = rig->p;
    const double b2 = p->axlebox_y * p->axlebox_y;
    int k, j, st;
    (void)t;

    st = contact_eval(rig, y);
    if (st < 0)
        return st;
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
    JJ(RR_RIG_ROLLER_SPIN, RR_RIG_T_ROLLER) = 1.0 / p->roller_inertia;
    JJ(RR_RIG_T_ROLLER, RR_RIG_T_ROLLER) = -1.0 / p->roller_tau;
    JJ(RR_RIG_T_WHEELSET, RR_RIG_T_WHEELSET) = -1.0 / p->wheelset_tau;

    /* creep forces f = -D c with D the tangent of Kalker's simplified
     * theory (the cubic law F = mu N (1 - (1 - eps)^3), eps = |(f11 cx,
     * f22 cy)| / (3 mu N), f11 = G a b C11: FASTSIM's creep curve to a few
     * per cent) with the falling friction's slope at the rigid slip speed,
     * and the creepages' derivatives of the linearised eq. 7-8.  A secant
     * would put a spurious stiff mode in the saturated contact and slow
     * the braking transients at the 4 ms step. */
    for (k = 0; k < 2; k++) {
        const rr_wheel_contact *w = &rig->w[k];
        rr_kalker_coeffs kc;
        double gab, f11, f22, d11, d22, V, a, r, R, c, mu, eps, s2, g3;
        if (rr_kalker(w->hertz.a / w->hertz.b, p->contact.nu, &kc) < 0)
            continue;
        /* the methods' own initial slopes: Polach's (kA + kS)/2 of the
         * linear theory, modified FASTSIM's k0 */
        gab = p->contact.G * w->hertz.a * w->hertz.b
            * (p->contact.creep.method == RR_METHOD_POLACH
                   ? 0.5 * (p->contact.creep.kA + p->contact.creep.kS)
                   : p->contact.creep.method == RR_METHOD_MODIFIED_FASTSIM
                         ? p->contact.creep.k0 : 1.0);
        f11 = gab * kc.c11;
        f22 = gab * kc.c22;
        c = hypot(w->creep.cx, w->creep.cy);
        mu = rr_friction_mu(&p->contact.friction, c * w->creep.V);
        /* the linear theory never saturates: its tangent is f11, f22 everywhere */
        eps = p->contact.creep.method == RR_METHOD_LINEAR
                  ? 0.0 : hypot(f11 * w->creep.cx, f22 * w->creep.cy) / (3.0 * mu * w->N);
        s2 = eps < 1.0 ? (1.0 - eps) * (1.0 - eps) : 0.0;
        g3 = eps < 1.0 ? 1.0 - s2 * (1.0 - eps) : 1.0;
        d11 = f11 * s2;
        d22 = f22 * s2;
        if (c > 0.0) {
            const double fall = w->N * g3 * w->creep.V
                              * rr_friction_dmu(&p->contact.friction, c * w->creep.V);
            d11 += fall * (w->creep.cx / c) * (w->creep.cx / c);
            d22 += fall * (w->creep.cy / c) * (w->creep.cy / c);
        }
        V = w->creep.V;
        a = w->frame.p[1] - rig->pose.c[1];
        r = w->geo.r;
        R = w->geo.R;
        /* d fx = -d11 (d vx - r d spin - a d yaw_rate + R d roller_spin) / V */
        {
            const int cols[4] = {RR_RIG_VX, RR_RIG_SPIN, RR_RIG_YAW_RATE, RR_RIG_ROLLER_SPIN};
            const double dc[4] = {1.0 / V, -r / V, -a / V, R / V};
            int c;
            for (c = 0; c < 4; c++) {
                const double dfx = -d11 * dc[c];
                JJ(RR_RIG_VX, cols[c]) += dfx / p->mass;
                JJ(RR_RIG_YAW_RATE, cols[c]) += -a * dfx / p->Izz;
                JJ(RR_RIG_SPIN, cols[c]) += -r * dfx / p->Iyy;
                JJ(RR_RIG_ROLLER_SPIN, cols[c]) += R * dfx / p->roller_inertia;
            }
        }
        /* d fy = -d22 (d vy / V - d yaw) */
        JJ(RR_RIG_VY, RR_RIG_VY) += -d22 / V / p->mass;
        JJ(RR_RIG_VY, RR_RIG_YAW) += d22 / p->mass;
    }
#undef JJ
    return RR_OK;
}

static int rhs_cb(void *ctx, double t, const double *y, double *dydt)
{
    return rr_rig_rhs((rr_rig *)ctx, t, y, dydt);
}

static int jac_cb(void *ctx, double t, const double *y, double *J)
{
    return rr_rig_jac((rr_rig *)ctx, t, y, J);
}

int rr_rig_record(rr_rig *rig, double *rec)
{
    const rr_rig_params *p = rig->p;
    const rr_wheel_contact *l = &rig->w[0], *r = &rig->w[1];
    const double *y = rig->y;
    double dydt[NS];
    const int status = rr_rig_rhs(rig, rig->t, y, dydt);
    rec[RR_REC_T] = rig->t;
    rec[RR_REC_CREEPAGE] = 0.5 * (l->creep.cx + r->creep.cx);
    rec[RR_REC_XI_EST] = rig->creepctl.xi_est;
    rec[RR_REC_XI_REF] = rig->creep_control ? rig->xi_ref : NAN;
    rec[RR_REC_ROLLER_SPEED] = y[RR_RIG_ROLLER_SPIN] * p->contact.R0;
    rec[RR_REC_WHEELSET_SPEED] = y[RR_RIG_SPIN] * p->creepctl.r_w;
    rec[RR_REC_FX] = l->f.fx + r->f.fx;
    rec[RR_REC_FY] = l->f.fy + r->f.fy;
    rec[RR_REC_N_LEFT] = l->N;
    rec[RR_REC_N_RIGHT] = r->N;
    rec[RR_REC_ADHESION] = fabs(l->f.fx + r->f.fx) / (l->N + r->N);
    rec[RR_REC_T_ROLLER] = y[RR_RIG_T_ROLLER];
    rec[RR_REC_T_WHEELSET] = y[RR_RIG_T_WHEELSET];
    rec[RR_REC_W_REF] = rig->creepctl.w_ref;
    rec[RR_REC_X] = y[RR_RIG_X];
    rec[RR_REC_Y] = y[RR_RIG_Y];
    rec[RR_REC_YAW] = y[RR_RIG_YAW];
    rec[RR_REC_CX_LEFT] = l->creep.cx;
    rec[RR_REC_CX_RIGHT] = r->creep.cx;
    rec[RR_REC_TREF_ROLLER] = rig->Tref_roller;
    rec[RR_REC_TREF_WHEELSET] = rig->Tref_wheelset;
    rec[RR_REC_VX] = y[RR_RIG_VX];
    rec[RR_REC_VY] = y[RR_RIG_VY];
    rec[RR_REC_YAW_RATE] = y[RR_RIG_YAW_RATE];
    rec[RR_REC_SPIN] = y[RR_RIG_SPIN];
    rec[RR_REC_ROLLER_SPIN] = y[RR_RIG_ROLLER_SPIN];
    rec[RR_REC_STATUS] = status;
    return status;
}

int rr_rig_init(const rr_rig_params *p, double roller_speed, rr_rig *rig)
{
    rr_wheelset_pose tp;
    rr_contact_point cl, cr;
    double spin, dydt[NS];
    int st, j;

    memset(rig, 0, sizeof *rig);
    rig->p = p;
    rig->status = RR_ERR_PARAM;
    if ((st = rr_rig_check(p)) != RR_OK)
        return rig->status = st;
    if (!isfinite(roller_speed))
        return rig->status = RR_ERR_NONFINITE;
    if ((st = rr_contact_table_lookup(p->contact.table, 0.0, &tp, 0, &cl, &cr)) != RR_OK)
        return rig->status = st;
    /* free rolling on the centred wheelset; the springs carry the preload there */
    spin = roller_speed * cl.R / cl.r;
    rig->z_ref = tp.z;
    for (j = 0; j < NS; j++)
        rig->y[j] = 0.0;
    rig->y[RR_RIG_SPIN] = spin;
    rig->y[RR_RIG_ROLLER_SPIN] = roller_speed;
    rig->xi_ref = NAN;
    rig->creep_control = 0;
    if ((st = rr_ode_init(&rig->ode, NS, p->method)) != RR_OK
        || (st = rr_pi_reset(&p->roller_pi, &rig->roller_pi, 0.0)) != RR_OK
        || (st = rr_pi_reset(&p->wheelset_pi, &rig->wheelset_pi, 0.0)) != RR_OK
        || (st = rr_encoder_reset(&p->roller_enc, &rig->roller_enc, roller_speed)) != RR_OK
        || (st = rr_encoder_reset(&p->wheelset_enc, &rig->wheelset_enc, spin)) != RR_OK
        || (st = rr_creepctl_init(&p->creepctl, &rig->creepctl, 1.0, roller_speed)) != RR_OK)
        return rig->status = st;
    rig->ode.newton_iters = p->newton_iters;
    rig->ode.linear_tr = p->linear_tr;
    /* x, y, yaw, chi, theta_r are integrals of the next five states */
    rig->ode.nq = RR_RIG_VX;
    /* a warning flags a stage left off by more than 0.1 % of its typical
     * size (ytyp below): a Newton iteration that does not contract, not
     * the one-iteration solve's usual residue */
    rig->ode.newton_tol = 1e-3;
    /* typical magnitudes: the integrator's finite-difference and Newton scales */
    rig->ode.ytyp[RR_RIG_X] = rig->ode.ytyp[RR_RIG_Y] = 1e-3;
    rig->ode.ytyp[RR_RIG_YAW] = 1e-3;
    rig->ode.ytyp[RR_RIG_CHI] = rig->ode.ytyp[RR_RIG_THETA_R] = 1.0;
    rig->ode.ytyp[RR_RIG_VX] = rig->ode.ytyp[RR_RIG_VY] = 1e-2;
    rig->ode.ytyp[RR_RIG_YAW_RATE] = 1e-2;
    rig->ode.ytyp[RR_RIG_SPIN] = rig->ode.ytyp[RR_RIG_ROLLER_SPIN] = fabs(spin) + 1.0;
    rig->ode.ytyp[RR_RIG_T_ROLLER] = p->roller_pi.Tmax;
    rig->ode.ytyp[RR_RIG_T_WHEELSET] = p->wheelset_pi.Tmax;
    st = rr_rig_rhs(rig, 0.0, rig->y, dydt);
    return rig->status = st < 0 ? st : RR_OK;
}

int rr_rig_sample(rr_rig *rig, double roller_ref, double xi_ref)
{
    const rr_rig_params *p = rig->p;
    double w_wheel, w_roller, w_ref = NAN;
    rr_pi_state pis[2];
    rr_encoder_state encs[2];
    rr_creepctl_state ccs;
    int st, cc = rig->creep_control;
    double xr = rig->xi_ref;

    if (rig->status < 0)
        return rig->status;
    if (!isfinite(roller_ref) || isinf(xi_ref))
        return RR_ERR_NONFINITE;
    /* keep the controllers' states to restore them on failure */
    pis[0] = rig->roller_pi;
    pis[1] = rig->wheelset_pi;
    encs[0] = rig->roller_enc;
    encs[1] = rig->wheelset_enc;
    ccs = rig->creepctl;

    st = rr_encoder_update(&p->roller_enc, &rig->roller_enc, rig->y[RR_RIG_THETA_R], &w_roller);
    if (st == RR_OK)
        st = rr_encoder_update(&p->wheelset_enc, &rig->wheelset_enc, rig->y[RR_RIG_CHI],
                               &w_wheel);
    if (st == RR_OK) {
        if (isnan(xi_ref)) {
            /* no creepage control: the wheelset is held at free rolling speed */
            rig->creep_control = 0;
            rig->xi_ref = NAN;
            st = rr_creepctl_xi(&p->creepctl, w_wheel, w_roller, &rig->creepctl.xi_est);
            rig->creepctl.K = 1.0;
            rig->creepctl.w_ref = w_ref = w_roller * p->creepctl.r_r / p->creepctl.r_w;
        } else {
            if (!rig->creep_control) {
                /* control starts from the wheelset's present speed ratio
                 * (eq. 15); eq. 13-14 then move K to each new target at
                 * their own pace, so that a change of target is a ramp,
                 * not a step the drive cannot follow */
                st = rr_creepctl_init(&p->creepctl, &rig->creepctl,
                                      1.0 + p->creepctl.sense * rig->creepctl.xi_est, w_roller);
                rig->creep_control = 1;
            }
            rig->xi_ref = xi_ref;
            if (st == RR_OK)
                st = rr_creepctl_update(&p->creepctl, &rig->creepctl, xi_ref, w_wheel,
                                        w_roller, &w_ref);
        }
    }
    if (st == RR_OK)
        st = rr_pi_update(&p->roller_pi, &rig->roller_pi, roller_ref, w_roller,
                          &rig->Tref_roller);
    if (st == RR_OK)
        st = rr_pi_update(&p->wheelset_pi, &rig->wheelset_pi, w_ref, w_wheel,
                          &rig->Tref_wheelset);
    if (st < 0) {
        rig->roller_pi = pis[0];
        rig->wheelset_pi = pis[1];
        rig->roller_enc = encs[0];
        rig->wheelset_enc = encs[1];
        rig->creepctl = ccs;
        rig->creep_control = cc;
        rig->xi_ref = xr;
        return st;
    }
    return RR_OK;
}

int rr_rig_advance(rr_rig *rig, double *rec)
{
    const rr_rig_params *p = rig->p;
    double h = p->T / p->nsub, ysave[NS], t0 = rig->t;
    int st = rig->status, i, worst = RR_OK;

    if (st < 0) {
        rr_rig_record(rig, rec);
        return st;
    }
    memcpy(ysave, rig->y, sizeof ysave);
    for (i = 0; i < p->nsub; i++) {
        st = rr_ode_step(&rig->ode, rhs_cb, jac_cb, rig, t0 + i * h, h, rig->y);
        if (st < 0)
            break;
        if (st > worst)
            worst = st;
    }
    if (st >= 0) {
        rig->t = t0 + p->T;
        st = rr_rig_record(rig, rec);      /* the outputs at the sample's end */
        if (st >= 0) {
            rig->status = st > worst ? st : worst;
            rec[RR_REC_STATUS] = rig->status;
            return rig->status;
        }
    }
    /* a failed sample: back to its start, and no further stepping */
    memcpy(rig->y, ysave, sizeof ysave);
    rig->t = t0;
    rig->cache_ok = 0;
    rr_rig_record(rig, rec);
    rig->status = st;
    rec[RR_REC_STATUS] = st;
    return st;
}

int rr_rig_step(rr_rig *rig, double roller_ref, double xi_ref, double *rec)
{
    int st = rr_rig_sample(rig, roller_ref, xi_ref);
    if (st < 0) {
        rr_rig_record(rig, rec);
        rec[RR_REC_STATUS] = st;
        return st;
    }
    return rr_rig_advance(rig, rec);
}

long rr_rig_run(rr_rig *rig, long n, const double *roller_ref, const double *xi_ref,
                double *rec, int *status)
{
    long k;
    int worst = RR_OK;
    for (k = 0; k < n; k++) {
        const int st = rr_rig_step(rig, roller_ref[k], xi_ref[k], rec + k * RR_REC_COUNT);
        if (st < 0) {
            worst = st;
            break;
        }
        if (st > worst)
            worst = st;
    }
    if (status)
        *status = worst;
    return k;
}

int rr_rig_set_state(rr_rig *rig, double t, const double *y)
{
    int j;
    if (!isfinite(t))
        return RR_ERR_NONFINITE;
    for (j = 0; j < NS; j++)
        if (!isfinite(y[j]))
            return RR_ERR_NONFINITE;
    rig->t = t;
    memcpy(rig->y, y, sizeof rig->y);
    rig->cache_ok = 0;
    return RR_OK;
}
