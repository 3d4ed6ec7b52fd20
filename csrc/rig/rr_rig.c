/*
 * rr_rig.c - the roller rig in time (rr_rig.h), its sampled side: the
 * checks of its parameters, its life (init, rebind), the record, the
 * encoders' reading, the commands and the built-in controllers' sample, the
 * advance over a sample by the integrator, runs, and a state set.  The
 * plant it integrates (adhesion, normal loads, contact evaluation, the
 * right-hand side, the Jacobian and the integrator's model) is
 * rr_rig_plant.c.
 */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "rig/rr_rig.h"

#define NS RR_RIG_NSTATE

static int positive(double v)
{
    return isfinite(v) && v > 0.0;
}

static int nonneg(double v)
{
    return isfinite(v) && v >= 0.0;
}

/* 0 if the adhesion's schedule and patch are usable on rollers of radius R0. */
static int adhesion_check(const rr_rig_adhesion *a, double R0)
{
    int i, st;
    if (a->n < 0 || a->n > RR_RIG_MAX_SCHEDULE)
        return RR_ERR_PARAM;
    for (i = 0; i < a->n; i++) {
        if (!isfinite(a->t[i]))
            return RR_ERR_NONFINITE;
        if (i > 0 && !(a->t[i] >= a->t[i - 1]))
            return RR_ERR_PARAM;
        if ((st = rr_friction_check(&a->law[i])) != RR_OK)
            return st;
    }
    if (!isfinite(a->patch_start) || !isfinite(a->patch_length) || !isfinite(a->patch_edge))
        return RR_ERR_NONFINITE;
    if (!(a->patch_length >= 0.0 && a->patch_length <= 2.0 * RR_PI * R0)
        || !(a->patch_edge > 0.0) || a->patch_rollers < 1 || a->patch_rollers > 3)
        return RR_ERR_PARAM;
    return a->patch_length > 0.0 ? rr_friction_check(&a->patch) : RR_OK;
}

/* 0 if the lateral force's points are usable. */
static int lateral_check(const rr_rig_lateral *l)
{
    int i;
    if (l->n < 0 || l->n > RR_RIG_MAX_SCHEDULE)
        return RR_ERR_PARAM;
    for (i = 0; i < l->n; i++) {
        if (!isfinite(l->t[i]) || !isfinite(l->f[i]))
            return RR_ERR_NONFINITE;
        if (i > 0 && !(l->t[i] >= l->t[i - 1]))
            return RR_ERR_PARAM;
    }
    return RR_OK;
}

int rr_rig_check(const rr_rig_params *p)
{
    int st;
    if (!p)
        return RR_ERR_NULL;
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
        || (p->linear_tr != 0 && p->linear_tr != 1)
        || (p->newton_model != 0 && p->newton_model != 1))
        return RR_ERR_PARAM;
    if (!isfinite(p->gyro_inertia))
        return RR_ERR_NONFINITE;
    if (!(p->gyro_inertia >= 0.0) || (p->track != 0 && p->track != 1))
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
    if ((st = rr_rig_method_check(&p->contact.creep)) != RR_OK
        || (st = adhesion_check(&p->adhesion, p->contact.R0)) != RR_OK
        || (st = lateral_check(&p->lateral)) != RR_OK)
        return st;
    {
        /* the drives' loops stable at T: gains, inertias, lags and sample
         * time that do not go together are a setting out of range */
        rr_speed_loop loops[2];
        int k;
        rr_rig_speed_loops(p, loops);
        for (k = 0; k < 2; k++)
            if ((st = rr_speed_loop_check(&loops[k])) != RR_OK)
                return st;
    }
    return RR_OK;
}

int rr_rig_method_check(const rr_creep_opts *o)
{
    int st;
    if (!o)
        return RR_ERR_NULL;
    if ((st = rr_creep_opts_check(o)) != RR_OK)
        return st;
    return !rr_creep_iterative(o) && rr_creep_saturates(o) ? RR_OK : RR_ERR_METHOD;
}

size_t rr_rig_workspace_len(const rr_rig_params *p)
{
    return p ? rr_rig_contact_workspace_len(&p->contact) : 0;
}

void rr_rig_speed_loops(const rr_rig_params *p, rr_speed_loop loops[2])
{
    loops[0].pi = p->roller_pi;
    loops[0].J = p->roller_inertia;
    loops[0].tau = p->roller_tau;
    loops[0].alpha = 0.0;
    loops[1].pi = p->wheelset_pi;
    loops[1].J = p->Iyy;
    loops[1].tau = p->wheelset_tau;
    loops[1].alpha = p->creepctl.alpha;
}

int rr_rig_usable(const rr_rig *rig)
{
    if (!rig || !rig->p)
        return RR_ERR_NULL;
    if (!rig->ready)
        return rig->status < 0 ? rig->status : RR_ERR_NULL;
    return RR_OK;
}

/* The record of a rig that cannot step: NaN, and the status. */
static int record_nan(double *rec, int st)
{
    int j;
    if (rec) {
        for (j = 0; j < RR_REC_COUNT; j++)
            rec[j] = NAN;
        rec[RR_REC_STATUS] = st;
    }
    return st;
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
    const rr_rig_params *p;
    const rr_wheel_contact *l, *r;
    const double *y;
    double dydt[NS];
    int status = rec ? rr_rig_usable(rig) : RR_ERR_NULL;

    if (status < 0)
        return record_nan(rec, status);
    p = rig->p;
    l = &rig->w[0];
    r = &rig->w[1];
    y = rig->y;
    status = rr_rig_rhs(rig, rig->t, y, dydt);
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
    rec[RR_REC_MU_LEFT] = l->friction.mu0;
    rec[RR_REC_MU_RIGHT] = r->friction.mu0;
    rec[RR_REC_STATUS] = status;
    if (status >= 0) {
        /* every field but the target (NaN without creepage control) and the
         * speed reference (NaN with the wheelset's torque commanded) is a
         * number; parameters near the largest double can overflow one */
        const double keep[2] = {rec[RR_REC_XI_REF], rec[RR_REC_W_REF]};
        rec[RR_REC_XI_REF] = rec[RR_REC_W_REF] = 0.0;
        if (!rr_all_finite(rec, RR_REC_COUNT)) {
            record_nan(rec, RR_ERR_RANGE);
            return RR_ERR_RANGE;
        }
        rec[RR_REC_XI_REF] = keep[0];
        rec[RR_REC_W_REF] = keep[1];
    }
    return status;
}

int rr_rig_init(const rr_rig_params *p, double roller_speed, double *work, size_t work_len,
                rr_rig *rig)
{
    rr_wheelset_pose tp;
    rr_contact_point cl, cr;
    double spin, dydt[NS];
    int st, j;

    if (!rig)
        return RR_ERR_NULL;
    memset(rig, 0, sizeof *rig);
    rig->p = p;
    rig->work = work;
    rig->work_len = work ? work_len : 0;
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
    rig->friction = rr_rig_schedule_law(p, 0.0);
    if ((st = rr_ode_init(&rig->ode, NS, p->method)) != RR_OK
        || (st = rr_pi_reset(&p->roller_pi, &rig->roller_pi, 0.0)) != RR_OK
        || (st = rr_pi_reset(&p->wheelset_pi, &rig->wheelset_pi, 0.0)) != RR_OK
        || (st = rr_encoder_reset(&p->roller_enc, &rig->roller_enc, roller_speed)) != RR_OK
        || (st = rr_encoder_reset(&p->wheelset_enc, &rig->wheelset_enc, spin)) != RR_OK
        || (st = rr_creepctl_init(&p->creepctl, &rig->creepctl, 1.0, roller_speed)) != RR_OK
        || (st = rr_rig_bind(rig, p)) != RR_OK)
        return rig->status = st;
    /* typical magnitudes: the integrator's finite-difference and Newton scales */
    rig->ode.ytyp[RR_RIG_X] = rig->ode.ytyp[RR_RIG_Y] = 1e-3;
    rig->ode.ytyp[RR_RIG_YAW] = 1e-3;
    rig->ode.ytyp[RR_RIG_CHI] = rig->ode.ytyp[RR_RIG_THETA_R] = 1.0;
    rig->ode.ytyp[RR_RIG_VX] = rig->ode.ytyp[RR_RIG_VY] = 1e-2;
    rig->ode.ytyp[RR_RIG_YAW_RATE] = 1e-2;
    rig->ode.ytyp[RR_RIG_SPIN] = rig->ode.ytyp[RR_RIG_ROLLER_SPIN] = fabs(spin) + 1.0;
    rig->ready = 1;
    st = rr_rig_rhs(rig, 0.0, rig->y, dydt);
    if (st < 0)
        rig->ready = 0;
    return rig->status = st < 0 ? st : RR_OK;
}

int rr_rig_rebind(rr_rig *rig, const rr_rig_params *p)
{
    int st = rig && p ? rr_rig_usable(rig) : RR_ERR_NULL;
    if (st != RR_OK)
        return st;
    if ((st = rr_rig_check(p)) != RR_OK)
        return st;
    return rr_rig_bind(rig, p);
}

static void signals_nan(rr_rig_signals *sig)
{
    if (sig)
        sig->t = sig->roller_count = sig->wheelset_count = sig->roller_angle
            = sig->wheelset_angle = sig->roller_speed = sig->wheelset_speed
            = sig->roller_torque = sig->wheelset_torque = sig->xi_est = NAN;
}

int rr_rig_read(rr_rig *rig, rr_rig_signals *sig)
{
    const rr_rig_params *p;
    rr_encoder_state encs[2];
    double w[2], xi = NAN;
    int st = sig ? rr_rig_usable(rig) : RR_ERR_NULL;

    if (st == RR_OK && rig->status < 0)
        st = rig->status;
    if (st == RR_OK && rig->phase != 0)
        st = RR_ERR_SEQUENCE;
    if (st < 0) {
        signals_nan(sig);
        return st;
    }
    p = rig->p;
    encs[0] = rig->roller_enc;
    encs[1] = rig->wheelset_enc;
    st = rr_encoder_update(&p->roller_enc, &rig->roller_enc, rig->y[RR_RIG_THETA_R], &w[0]);
    if (st == RR_OK)
        st = rr_encoder_update(&p->wheelset_enc, &rig->wheelset_enc, rig->y[RR_RIG_CHI], &w[1]);
    if (st == RR_OK)
        st = rr_creepctl_xi(&p->creepctl, w[1], w[0], &xi);
    if (st < 0) {
        rig->roller_enc = encs[0];
        rig->wheelset_enc = encs[1];
        signals_nan(sig);
        return st;
    }
    rig->enc_w[0] = w[0];
    rig->enc_w[1] = w[1];
    rig->enc_xi = xi;
    rig->phase = 1;
    sig->t = rig->t;
    sig->roller_count = rig->roller_enc.count;
    sig->wheelset_count = rig->wheelset_enc.count;
    sig->roller_angle = rig->roller_enc.theta_q;
    sig->wheelset_angle = rig->wheelset_enc.theta_q;
    sig->roller_speed = w[0];
    sig->wheelset_speed = w[1];
    sig->roller_torque = rig->y[RR_RIG_T_ROLLER];
    sig->wheelset_torque = rig->y[RR_RIG_T_WHEELSET];
    sig->xi_est = xi;
    return RR_OK;
}

void rr_rig_command_builtin(rr_rig_command *cmd, double roller_ref, double xi_ref)
{
    if (!cmd)
        return;
    cmd->roller_mode = cmd->wheelset_mode = RR_CMD_BUILTIN;
    cmd->roller_ref = roller_ref;
    cmd->wheelset_ref = xi_ref;
    cmd->mu0 = NAN;
}

/* A drive commanded by torque: the reference clipped to the drive's limit,
 * and its PI preset there, so that a switch back to speed is bumpless. */
static int torque_command(const rr_pi_params *pp, rr_pi_state *s, double torque, double *Tref)
{
    *Tref = fmin(pp->Tmax, fmax(-pp->Tmax, torque));
    return rr_pi_reset(pp, s, *Tref);
}

int rr_rig_write(rr_rig *rig, const rr_rig_command *cmd)
{
    const rr_rig_params *p;
    const double w_roller = rig ? rig->enc_w[0] : NAN, w_wheel = rig ? rig->enc_w[1] : NAN;
    double w_ref = NAN, Tref[2];
    rr_pi_state pis[2];
    rr_creepctl_state ccs;
    rr_friction law;
    int st = cmd ? rr_rig_usable(rig) : RR_ERR_NULL, cc;
    double xr;

    if (st == RR_OK && rig->status < 0)
        st = rig->status;
    if (st == RR_OK && rig->phase != 1)
        st = RR_ERR_SEQUENCE;
    if (st < 0)
        return st;
    if (cmd->roller_mode < RR_CMD_BUILTIN || cmd->roller_mode > RR_CMD_TORQUE
        || cmd->wheelset_mode < RR_CMD_BUILTIN || cmd->wheelset_mode > RR_CMD_TORQUE)
        return RR_ERR_PARAM;
    if (!isfinite(cmd->roller_ref) || isinf(cmd->wheelset_ref)
        || (isnan(cmd->wheelset_ref) && cmd->wheelset_mode != RR_CMD_BUILTIN) || isinf(cmd->mu0))
        return RR_ERR_NONFINITE;
    p = rig->p;
    law = rr_rig_schedule_law(p, rig->t);
    if (!isnan(cmd->mu0)) {
        law.mu0 = cmd->mu0;
        if ((st = rr_friction_check(&law)) != RR_OK)
            return st;
    }
    /* keep the controllers' states to restore them on failure */
    pis[0] = rig->roller_pi;
    pis[1] = rig->wheelset_pi;
    ccs = rig->creepctl;
    cc = rig->creep_control;
    xr = rig->xi_ref;

    if (cmd->wheelset_mode != RR_CMD_BUILTIN || isnan(cmd->wheelset_ref)) {
        /* no creepage control: the estimate for the record; the wheelset
         * held at free rolling (BUILTIN), or at the caller's reference */
        rig->creep_control = 0;
        rig->xi_ref = NAN;
        rig->creepctl.xi_est = rig->enc_xi;
        rig->creepctl.K = 1.0;
        w_ref = cmd->wheelset_mode == RR_CMD_BUILTIN ? w_roller * p->creepctl.r_r / p->creepctl.r_w
              : cmd->wheelset_mode == RR_CMD_SPEED ? cmd->wheelset_ref : NAN;
        rig->creepctl.w_ref = w_ref;
    } else {
        if (!rig->creep_control) {
            /* control starts from the wheelset's present speed ratio (eq.
             * 15); eq. 13-14 then move K to each new target at their own
             * pace, so that a change of target is a ramp, not a step the
             * drive cannot follow */
            st = rr_creepctl_init(&p->creepctl, &rig->creepctl,
                                  1.0 + p->creepctl.sense * rig->creepctl.xi_est, w_roller);
            rig->creep_control = 1;
        }
        rig->xi_ref = cmd->wheelset_ref;
        if (st == RR_OK)
            st = rr_creepctl_update(&p->creepctl, &rig->creepctl, cmd->wheelset_ref, w_wheel,
                                    w_roller, &w_ref);
    }
    if (st == RR_OK)
        st = cmd->roller_mode == RR_CMD_TORQUE
           ? torque_command(&p->roller_pi, &rig->roller_pi, cmd->roller_ref, &Tref[0])
           : rr_pi_update(&p->roller_pi, &rig->roller_pi, cmd->roller_ref, w_roller, &Tref[0]);
    if (st == RR_OK)
        st = cmd->wheelset_mode == RR_CMD_TORQUE
           ? torque_command(&p->wheelset_pi, &rig->wheelset_pi, cmd->wheelset_ref, &Tref[1])
           : rr_pi_update(&p->wheelset_pi, &rig->wheelset_pi, w_ref, w_wheel, &Tref[1]);
    if (st < 0) {
        rig->roller_pi = pis[0];
        rig->wheelset_pi = pis[1];
        rig->creepctl = ccs;
        rig->creep_control = cc;
        rig->xi_ref = xr;
        return st;
    }
    rig->Tref_roller = Tref[0];
    rig->Tref_wheelset = Tref[1];
    if (memcmp(&law, &rig->friction, sizeof law) != 0) {
        rig->friction = law;
        rig->cache_ok = rig->lin_ok = 0;    /* the contact forces change with it */
    }
    rig->phase = 2;
    return RR_OK;
}

int rr_rig_sample(rr_rig *rig, double roller_ref, double xi_ref)
{
    rr_rig_signals sig;
    rr_rig_command cmd;
    rr_encoder_state encs[2];
    double w[2], xi;
    int st;

    if ((st = rr_rig_usable(rig)) != RR_OK)
        return st;
    if (rig->status < 0)
        return rig->status;
    if (!isfinite(roller_ref) || isinf(xi_ref))
        return RR_ERR_NONFINITE;
    encs[0] = rig->roller_enc;
    encs[1] = rig->wheelset_enc;
    memcpy(w, rig->enc_w, sizeof w);
    xi = rig->enc_xi;
    if ((st = rr_rig_read(rig, &sig)) < 0)
        return st;
    rr_rig_command_builtin(&cmd, roller_ref, xi_ref);
    if ((st = rr_rig_write(rig, &cmd)) < 0) {
        /* nothing changes: the encoders as before the reading */
        rig->roller_enc = encs[0];
        rig->wheelset_enc = encs[1];
        memcpy(rig->enc_w, w, sizeof w);
        rig->enc_xi = xi;
        rig->phase = 0;
    }
    return st;
}

int rr_rig_advance(rr_rig *rig, double *rec)
{
    const rr_rig_params *p;
    double h, ysave[NS], t0;
    int st = rec ? rr_rig_usable(rig) : RR_ERR_NULL, i, worst = RR_OK;

    if (st < 0)
        return record_nan(rec, st);
    p = rig->p;
    h = p->T / p->nsub;
    t0 = rig->t;
    st = rig->status;

    if (st < 0) {
        rr_rig_record(rig, rec);
        rec[RR_REC_STATUS] = st;        /* the refusal's, not the state's */
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
        rig->phase = 0;
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
    rig->cache_ok = rig->lin_ok = 0;
    rr_rig_record(rig, rec);
    rig->status = st;
    rec[RR_REC_STATUS] = st;
    return st;
}

int rr_rig_step(rr_rig *rig, double roller_ref, double xi_ref, double *rec)
{
    int st = rec ? rr_rig_usable(rig) : RR_ERR_NULL;
    if (st < 0)
        return record_nan(rec, st);
    st = rr_rig_sample(rig, roller_ref, xi_ref);
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
    int worst = n < 0 ? RR_ERR_PARAM
              : n > 0 && (!roller_ref || !xi_ref || !rec) ? RR_ERR_NULL : rr_rig_usable(rig);
    if (worst < 0) {
        if (status)
            *status = worst;
        if (n > 0 && rec)
            record_nan(rec, worst);     /* row 0 says why nothing ran */
        return 0;
    }
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
    int j, st = y ? rr_rig_usable(rig) : RR_ERR_NULL;
    if (st < 0)
        return st;
    if (!isfinite(t))
        return RR_ERR_NONFINITE;
    for (j = 0; j < NS; j++)
        if (!isfinite(y[j]))
            return RR_ERR_NONFINITE;
    rig->t = t;
    memcpy(rig->y, y, sizeof rig->y);
    rig->cache_ok = rig->lin_ok = 0;
    rig->phase = 0;                 /* a sample's end: the next may be read */
    return RR_OK;
}
