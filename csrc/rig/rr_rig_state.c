/*
 * rr_rig_state.c - the rig's full state between samples (rr_rig.h,
 * RR_RIG_FULL_STATE): its names, and its get and checked set, for
 * checkpoints and the closed loop's linearisation.
 */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "rig/rr_rig.h"

#define FS_NAME_(id, name, unit, meaning) name,
#define FS_UNIT_(id, name, unit, meaning) unit,
static const char *const fs_names[] = {RR_RIG_FULL_STATE(FS_NAME_)};
static const char *const fs_units[] = {RR_RIG_FULL_STATE(FS_UNIT_)};
RR_STATIC_ASSERT(RR_COUNTOF(fs_names) == RR_FS_COUNT, full_state_names_complete);
/* the plant's vector sits at RR_FS_X.. in the plant's own order */
RR_STATIC_ASSERT(RR_FS_T_WHEELSET - RR_FS_X == RR_RIG_T_WHEELSET, full_state_plant_order);

/* counters are whole numbers below 2^53, where a double holds each exactly */
#define FS_MAX_COUNT 9007199254740992.0

int rr_rig_full_state_len(void)
{
    return RR_FS_COUNT;
}

const char *const *rr_rig_full_state_names(void)
{
    return fs_names;
}

const char *const *rr_rig_full_state_units(void)
{
    return fs_units;
}

static void get(const rr_rig *rig, double *v)
{
    v[RR_FS_T] = rig->t;
    memcpy(v + RR_FS_X, rig->y, sizeof rig->y);
    v[RR_FS_Z_REF] = rig->z_ref;
    v[RR_FS_TREF_ROLLER] = rig->Tref_roller;
    v[RR_FS_TREF_WHEELSET] = rig->Tref_wheelset;
    v[RR_FS_MU0] = rig->friction.mu0;
    v[RR_FS_FRICTION_A] = rig->friction.A;
    v[RR_FS_FRICTION_B] = rig->friction.B;
    v[RR_FS_CREEP_CONTROL] = rig->creep_control;
    v[RR_FS_XI_REF] = rig->xi_ref;
    v[RR_FS_ROLLER_PI_INTEGRAL] = rig->roller_pi.integral;
    v[RR_FS_ROLLER_PI_SATURATED] = rig->roller_pi.saturated;
    v[RR_FS_WHEELSET_PI_INTEGRAL] = rig->wheelset_pi.integral;
    v[RR_FS_WHEELSET_PI_SATURATED] = rig->wheelset_pi.saturated;
    v[RR_FS_ROLLER_COUNT] = rig->roller_enc.count;
    v[RR_FS_ROLLER_ENC_SPEED] = rig->roller_enc.w;
    v[RR_FS_ROLLER_ENC_PRIMED] = rig->roller_enc.primed;
    v[RR_FS_WHEELSET_COUNT] = rig->wheelset_enc.count;
    v[RR_FS_WHEELSET_ENC_SPEED] = rig->wheelset_enc.w;
    v[RR_FS_WHEELSET_ENC_PRIMED] = rig->wheelset_enc.primed;
    v[RR_FS_CREEPCTL_K] = rig->creepctl.K;
    v[RR_FS_CREEPCTL_W_REF] = rig->creepctl.w_ref;
    v[RR_FS_CREEPCTL_XI_EST] = rig->creepctl.xi_est;
    v[RR_FS_CREEPCTL_DXI] = rig->creepctl.dxi;
}

/* v into the rig, unchecked; what the rig derives from it follows (the PI's
 * output is the held reference, the quantised angle count 2 pi / counts, as
 * rr_encoder_update makes them), and its caches of the state are dropped. */
static void put(rr_rig *rig, const double *v)
{
    const rr_rig_params *p = rig->p;
    rig->t = v[RR_FS_T];
    memcpy(rig->y, v + RR_FS_X, sizeof rig->y);
    rig->z_ref = v[RR_FS_Z_REF];
    rig->Tref_roller = rig->roller_pi.u = v[RR_FS_TREF_ROLLER];
    rig->Tref_wheelset = rig->wheelset_pi.u = v[RR_FS_TREF_WHEELSET];
    rig->friction.mu0 = v[RR_FS_MU0];
    rig->friction.A = v[RR_FS_FRICTION_A];
    rig->friction.B = v[RR_FS_FRICTION_B];
    rig->creep_control = (int)v[RR_FS_CREEP_CONTROL];
    rig->xi_ref = v[RR_FS_XI_REF];
    rig->roller_pi.integral = v[RR_FS_ROLLER_PI_INTEGRAL];
    rig->roller_pi.saturated = (int)v[RR_FS_ROLLER_PI_SATURATED];
    rig->wheelset_pi.integral = v[RR_FS_WHEELSET_PI_INTEGRAL];
    rig->wheelset_pi.saturated = (int)v[RR_FS_WHEELSET_PI_SATURATED];
    rig->roller_enc.count = v[RR_FS_ROLLER_COUNT];
    rig->roller_enc.theta_q = v[RR_FS_ROLLER_COUNT] * (2.0 * RR_PI / p->roller_enc.counts);
    rig->roller_enc.w = v[RR_FS_ROLLER_ENC_SPEED];
    rig->roller_enc.primed = (int)v[RR_FS_ROLLER_ENC_PRIMED];
    rig->wheelset_enc.count = v[RR_FS_WHEELSET_COUNT];
    rig->wheelset_enc.theta_q
        = v[RR_FS_WHEELSET_COUNT] * (2.0 * RR_PI / p->wheelset_enc.counts);
    rig->wheelset_enc.w = v[RR_FS_WHEELSET_ENC_SPEED];
    rig->wheelset_enc.primed = (int)v[RR_FS_WHEELSET_ENC_PRIMED];
    rig->creepctl.K = v[RR_FS_CREEPCTL_K];
    rig->creepctl.w_ref = v[RR_FS_CREEPCTL_W_REF];
    rig->creepctl.xi_est = v[RR_FS_CREEPCTL_XI_EST];
    rig->creepctl.dxi = v[RR_FS_CREEPCTL_DXI];
    rig->cache_ok = rig->lin_ok = 0;
}

int rr_rig_get_full_state(const rr_rig *rig, double *v)
{
    int j, st = v ? rr_rig_usable(rig) : RR_ERR_NULL;
    if (st == RR_OK && rig->phase != 0)
        st = RR_ERR_SEQUENCE;
    if (st != RR_OK) {
        if (v)
            for (j = 0; j < RR_FS_COUNT; j++)
                v[j] = NAN;
        return st;
    }
    get(rig, v);
    return RR_OK;
}

static int is_flag(double v, double lo, double hi)
{
    return v == floor(v) && v >= lo && v <= hi;
}

static int is_count(double v)
{
    return v == floor(v) && fabs(v) < FS_MAX_COUNT;
}

/* 0 if v is a state the rig can hold (the plant's contact aside). */
static int full_state_check(const double *v)
{
    rr_friction law;
    int j, st;
    for (j = 0; j < RR_FS_COUNT; j++)
        if (!isfinite(v[j]) && !(isnan(v[j]) && (j == RR_FS_XI_REF || j == RR_FS_CREEPCTL_W_REF)))
            return RR_ERR_NONFINITE;
    if (!is_flag(v[RR_FS_CREEP_CONTROL], 0.0, 1.0)
        || !is_flag(v[RR_FS_ROLLER_PI_SATURATED], -1.0, 1.0)
        || !is_flag(v[RR_FS_WHEELSET_PI_SATURATED], -1.0, 1.0)
        || !is_flag(v[RR_FS_ROLLER_ENC_PRIMED], 0.0, 1.0)
        || !is_flag(v[RR_FS_WHEELSET_ENC_PRIMED], 0.0, 1.0)
        || !is_count(v[RR_FS_ROLLER_COUNT]) || !is_count(v[RR_FS_WHEELSET_COUNT])
        || !(v[RR_FS_CREEPCTL_K] >= 0.0))
        return RR_ERR_PARAM;
    /* a target while, and only while, eq. 13-14 steer; and then a reference */
    if (v[RR_FS_CREEP_CONTROL] == 1.0
            ? isnan(v[RR_FS_XI_REF]) || isnan(v[RR_FS_CREEPCTL_W_REF])
            : !isnan(v[RR_FS_XI_REF]))
        return RR_ERR_PARAM;
    law.mu0 = v[RR_FS_MU0];
    law.A = v[RR_FS_FRICTION_A];
    law.B = v[RR_FS_FRICTION_B];
    if ((st = rr_friction_check(&law)) != RR_OK)
        return st;
    return RR_OK;
}

int rr_rig_set_full_state(rr_rig *rig, const double *v)
{
    double old[RR_FS_COUNT], dydt[RR_RIG_NSTATE];
    int st = v ? rr_rig_usable(rig) : RR_ERR_NULL;
    if (st == RR_OK && rig->phase != 0)
        st = RR_ERR_SEQUENCE;
    if (st != RR_OK || (st = full_state_check(v)) != RR_OK)
        return st;
    get(rig, old);
    put(rig, v);
    /* the plant must be where the contact holds: its right-hand side there */
    st = rr_rig_rhs(rig, rig->t, rig->y, dydt);
    if (st >= 0 && !rr_all_finite(dydt, RR_RIG_NSTATE))
        st = RR_ERR_RANGE;
    if (st < 0) {
        put(rig, old);
        return st;
    }
    rig->status = st;
    return st;
}
