/* rr_rig_contact.c - contact evaluation of the wheelset on the rig's rollers. */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "rig/rr_rig_contact.h"

/* the model's nonhertz tables: one per side, valid, built for its roller
 * and material (G as rr_rig_params_from and rollerrig compute it: the same
 * doubles; a relative 1e-9 for a caller's own rounding) */
static int nonhertz_check(const rr_rig_contact_model *m)
{
    int k;
    for (k = 0; k < 2; k++) {
        const rr_nh_table *t = m->nonhertz[k];
        if (!t)
            return RR_ERR_NULL;
        if (rr_nonhertz_table_check(t, NULL) != RR_OK || t->sigma != (k == 0 ? 1.0 : -1.0)
            || !(fabs(t->R0 - m->R0) <= 1e-12 * m->R0) || !(fabs(t->G - m->G) <= 1e-9 * m->G)
            || !(fabs(t->nu - m->nu) <= 1e-12))
            return RR_ERR_TABLE;
    }
    return RR_OK;
}

/* rr_rig_contact_check, its creep method checked into *creep */
static int model_check(const rr_rig_contact_model *m, rr_creep_checked *creep)
{
    int st;
    if (!m)
        return RR_ERR_NULL;
    if (!m->table || !m->table->data)
        return RR_ERR_WORKSPACE;
    if (!isfinite(m->R0) || !isfinite(m->estar) || !isfinite(m->G) || !isfinite(m->nu)
        || !isfinite(m->vmin))
        return RR_ERR_NONFINITE;
    if (!(m->R0 > 0.0))
        return RR_ERR_GEOMETRY;
    if (!(m->estar > 0.0) || !(m->G > 0.0) || !(m->nu >= 0.0 && m->nu <= 0.5))
        return RR_ERR_MATERIAL;
    if (!(m->vmin > 0.0))
        return RR_ERR_SPEED;
    if ((st = rr_friction_check(&m->friction)) != RR_OK)
        return st;
    if ((st = rr_creep_check(creep, &m->creep, NULL)) != RR_OK)
        return st;
    if (m->patch != RR_RIG_PATCH_HERTZ && m->patch != RR_RIG_PATCH_NONHERTZ)
        return RR_ERR_PARAM;
    if (m->patch == RR_RIG_PATCH_NONHERTZ && (st = nonhertz_check(m)) != RR_OK)
        return st;
    /* a case solved iteratively to a tolerance (the exact theory) has no
     * bound on its work a time step could plan on */
    return creep->d->iterative ? RR_ERR_METHOD : RR_OK;
}

int rr_rig_contact_check(const rr_rig_contact_model *m)
{
    rr_creep_checked creep;
    return model_check(m, &creep);
}

size_t rr_rig_contact_workspace_len(const rr_rig_contact_model *m)
{
    rr_creep_checked creep;
    return model_check(m, &creep) == RR_OK ? creep.work_len : 0;
}

int rr_rig_contact_bind(rr_rig_contact_checked *k, const rr_rig_contact_model *m, double *work,
                        size_t work_len)
{
    int st;
    if (!k)
        return RR_ERR_NULL;
    k->ready = 0;
    if ((st = model_check(m, &k->creep)) == RR_OK && k->creep.work_len > 0
        && (!work || work_len < k->creep.work_len))
        st = RR_ERR_WORKSPACE;
    if (st != RR_OK) {
        k->creep.ready = 0;
        return st;
    }
    k->m = *m;
    k->work = work;
    k->work_len = work_len;
    k->ready = RR_RIG_CONTACT_READY;
    return RR_OK;
}

/* a successful rr_rig_contact_bind's */
static int bound(const rr_rig_contact_checked *k)
{
    return k && k->ready == RR_RIG_CONTACT_READY;
}

static void vec_nan(double *v, int n)
{
    int i;
    for (i = 0; i < n; i++)
        v[i] = NAN;
}

static void wheel_nan(rr_wheel_contact *w, int status)
{
    rr_contact_point *g = &w->geo;
    g->y = g->z = g->s_wheel = g->s_roller = g->r = g->R = g->delta = NAN;
    g->A = g->B = g->gap = g->ha = g->hb = g->hd = g->y2 = g->gap2 = NAN;
    g->two_point = 0;
    w->theta = w->N = NAN;
    w->friction.mu0 = w->friction.A = w->friction.B = NAN;
    vec_nan(w->frame.p, 3);
    vec_nan(w->frame.t1, 3);
    vec_nan(w->frame.t2, 3);
    vec_nan(w->n, 3);
    w->creep.cx = w->creep.cy = w->creep.cphi = w->creep.V = NAN;
    vec_nan(w->creep.slip, 3);
    w->hertz.a = w->hertz.b = w->hertz.p0 = w->hertz.delta = NAN;
    rr_forces_nan(&w->f);
    vec_nan(w->force, 3);
    vec_nan(w->moment, 3);
    w->status = status;
}

static void pose_nan(rr_rig_pose *p)
{
    p->state.x = p->state.y = p->state.yaw = p->state.vx = p->state.vy = NAN;
    p->state.yaw_rate = p->state.spin = p->state.roller_spin = NAN;
    vec_nan(p->c, 3);
    vec_nan(p->v, 3);
    vec_nan(p->w, 3);
    p->roll = p->roll_rate = p->beta = NAN;
}

/* v turned by angle t about the Y axis, moving +Z toward +X. */
static void turn_y(const double v[3], double t, double out[3])
{
    const double c = cos(t), s = sin(t);
    out[0] = c * v[0] + s * v[2];
    out[1] = v[1];
    out[2] = -s * v[0] + c * v[2];
}

/* The worse of two statuses: any error before any warning. */
static int worse(int a, int b)
{
    if (a < 0 || b < 0)
        return a < b ? a : b;
    return a > b ? a : b;
}

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* The wheelset's pose at state s whose lateral shift is y (the table's
 * pose tp and slopes there): centre on its circle about the roller axis,
 * constrained rates.  RR_ERR_GEOMETRY (|x| too large), RR_ERR_RANGE (rates
 * that overflow), pose NaN then. */
static int pose_of(const rr_rig_contact_model *m, const rr_rig_state *s, double y,
                   const rr_wheelset_pose *tp, const rr_wheelset_pose *slope, rr_rig_pose *pose)
{
    const double D = m->R0 + tp->z;    /* axle to roller axis, in the plane of the axle */
    double h, cy, sy, cr, sr, droll;
    if (!(fabs(s->x) < 0.5 * D)) {
        pose_nan(pose);
        return RR_ERR_GEOMETRY;       /* rolled a quarter of the way round: not a rig */
    }
    h = sqrt(D * D - s->x * s->x);
    pose->state = *s;
    pose->state.y = y;
    pose->beta = asin(s->x / D);
    pose->roll = tp->roll;
    pose->c[0] = s->x;
    pose->c[1] = y;
    pose->c[2] = h - m->R0;
    pose->v[0] = s->vx;
    pose->v[1] = s->vy;
    pose->v[2] = (D * slope->z * s->vy - s->x * s->vx) / h;
    droll = slope->roll * s->vy;
    pose->roll_rate = droll;
    cy = cos(s->yaw);
    sy = sin(s->yaw);
    cr = cos(tp->roll);
    sr = sin(tp->roll);
    /* spin about the axle R_z(yaw) R_x(roll) Y, roll about the yawed X, yaw about Z */
    pose->w[0] = -s->spin * sy * cr + droll * cy;
    pose->w[1] = s->spin * cy * cr + droll * sy;
    pose->w[2] = s->spin * sr + s->yaw_rate;
    if (!rr_all_finite(pose->v, 3) || !rr_all_finite(pose->w, 3)) {
        /* rates beyond ~1e300: the constrained rates overflow */
        pose_nan(pose);
        return RR_ERR_RANGE;
    }
    return RR_OK;
}

/* The table's slopes (d z / d y, d roll / d y) at y: the vertical and roll
 * rates a lateral speed gives there. */
static int slopes_at(const rr_rig_contact_model *m, double y, rr_wheelset_pose *slope)
{
    rr_wheelset_pose tp;
    rr_contact_point g[2];
    return rr_contact_table_lookup(m->table, y, &tp, slope, &g[0], &g[1]);
}

/* rr_rig_kinematics with st the model's status (RR_OK: checked), pose and w
 * not NULL, the rates' slopes taken at y_rates (s->y: the table's pose's) */
static int kinematics(const rr_rig_contact_model *m, int st, const rr_rig_state *s,
                      double y_rates, rr_rig_pose *pose, rr_wheel_contact w[2])
{
    rr_wheelset_pose tp, slope;
    rr_motion wheel, roller;
    double sy;
    int k;

    if (st == RR_OK && !(isfinite(s->x) && isfinite(s->y) && isfinite(s->yaw)
                         && isfinite(s->vx) && isfinite(s->vy) && isfinite(s->yaw_rate)
                         && isfinite(s->spin) && isfinite(s->roller_spin)
                         && isfinite(y_rates)))
        st = RR_ERR_NONFINITE;
    if (st == RR_OK)
        st = rr_contact_table_lookup(m->table, s->y, &tp, &slope, &w[0].geo, &w[1].geo);
    if (st == RR_OK && y_rates != s->y)
        st = slopes_at(m, y_rates, &slope);
    if (st == RR_OK)
        st = pose_of(m, s, s->y, &tp, &slope, pose);
    if (st < 0) {
        pose_nan(pose);
        wheel_nan(&w[0], st);
        wheel_nan(&w[1], st);
        return st;
    }
    sy = sin(s->yaw);

    wheel.c[0] = pose->c[0];
    wheel.c[1] = pose->c[1];
    wheel.c[2] = pose->c[2];
    roller.c[0] = 0.0;
    roller.c[1] = 0.0;
    roller.c[2] = -m->R0;
    for (k = 0; k < 3; k++) {
        wheel.v[k] = pose->v[k];
        wheel.w[k] = pose->w[k];
        roller.v[k] = 0.0;
    }
    roller.w[0] = roller.w[2] = 0.0;
    roller.w[1] = -s->roller_spin;

    for (k = 0; k < 2; k++) {
        rr_wheel_contact *c = &w[k];
        const rr_contact_point *g = &c->geo;
        const double sigma = k == 0 ? 1.0 : -1.0;
        const double arm = g->y - s->y;
        const double xj = s->x - arm * sy;
        const double rR = g->r + g->R;
        const double sd = sin(g->delta), cd = cos(g->delta);
        /* the table's point and frame in the plane of the axle, about the roller axis */
        const double p0[3] = {0.0, g->y, g->z + m->R0};
        const double t10[3] = {1.0, 0.0, 0.0};
        const double t20[3] = {0.0, cd, sigma * sd};
        double p[3], mean;
        int j;

        if (!(fabs(xj) < 0.5 * rR)) {
            wheel_nan(c, RR_ERR_GEOMETRY);
            continue;
        }
        c->theta = asin(xj / rR) + sigma * g->r * tan(g->delta) * s->yaw / rR;
        turn_y(p0, c->theta, p);
        p[2] -= m->R0;
        turn_y(t10, c->theta, c->frame.t1);
        turn_y(t20, c->theta, c->frame.t2);
        for (j = 0; j < 3; j++)
            c->frame.p[j] = p[j];
        /* material must enter at x = +a: t1 points where the contact travels
         * relative to the material, against the mean material velocity */
        {
            double vw[3], vr[3], d[3];
            for (j = 0; j < 3; j++)
                d[j] = p[j] - wheel.c[j];
            cross(wheel.w, d, vw);
            for (j = 0; j < 3; j++)
                d[j] = p[j] - roller.c[j];
            cross(roller.w, d, vr);
            mean = 0.0;
            for (j = 0; j < 3; j++)
                mean += (wheel.v[j] + vw[j] + vr[j]) * c->frame.t1[j];
        }
        if (mean > 0.0)
            for (j = 0; j < 3; j++) {
                c->frame.t1[j] = -c->frame.t1[j];
                c->frame.t2[j] = -c->frame.t2[j];
            }
        cross(c->frame.t1, c->frame.t2, c->n);
        st = rr_creepage(&wheel, &roller, &c->frame, m->vmin, &c->creep);
        if (st < 0) {
            wheel_nan(c, st);
            continue;
        }
        c->friction = m->friction;
        c->status = st;
    }
    return worse(w[0].status, w[1].status);
}

int rr_rig_kinematics(const rr_rig_contact_model *m, const rr_rig_state *s, rr_rig_pose *pose,
                      rr_wheel_contact w[2])
{
    if (!pose || !w)
        return RR_ERR_NULL;
    return kinematics(m, s ? rr_rig_contact_check(m) : RR_ERR_NULL, s, s ? s->y : 0.0, pose, w);
}

int rr_rig_kinematics_checked(const rr_rig_contact_checked *k, const rr_rig_state *s,
                              rr_rig_pose *pose, rr_wheel_contact w[2])
{
    if (!pose || !w)
        return RR_ERR_NULL;
    return kinematics(bound(k) ? &k->m : NULL, s && bound(k) ? RR_OK : RR_ERR_NULL, s,
                      s ? s->y : 0.0, pose, w);
}

int rr_rig_kinematics_rates_at(const rr_rig_contact_checked *k, const rr_rig_state *s,
                               double y_rates, rr_rig_pose *pose, rr_wheel_contact w[2])
{
    if (!pose || !w)
        return RR_ERR_NULL;
    return kinematics(bound(k) ? &k->m : NULL, s && bound(k) ? RR_OK : RR_ERR_NULL, s, y_rates,
                      pose, w);
}

/* Wheel k (0 left, 1 right) of a finished kinematics by the non-Hertzian
 * contact (rr_rig_contact.h, Patch) at the caller's normal load N; c->N,
 * c->friction set, N > 0; slope the table's at the state's y (its rates,
 * rr_rig_kinematics_rates_at).  Its status, c filled or not touched on
 * error. */
static int nonhertz_wheel(const rr_rig_contact_model *m, int k, double N,
                          const rr_rig_pose *pose, const rr_wheelset_pose *slope,
                          rr_wheel_contact *c)
{
    const rr_nh_table *t = m->nonhertz[k];
    const rr_rig_state *s = &pose->state;
    rr_nh_state ns;
    rr_nh_result r;
    double w, Nsum = 0.0, ab_sum = 0.0, Nmax = -1.0, ab = 1.0, scale;
    int i, j, st;

    if ((st = rr_friction_check(&c->friction)) != RR_OK)
        return st;
    ns.Fz = N * c->n[2];
    if (!(ns.Fz > 0.0))
        return RR_ERR_LOAD;                  /* the normal does not lift the wheel */
    if ((st = rr_nonhertz_locate(t, s->y, &i, &w)) < 0)
        return st;                           /* the wheelset beyond the table's rows */
    for (j = 0; j < 2; j++) {
        /* the wheelset's motion as if at row i + j's shift, with the rates
         * of its own (rr_rig_kinematics_rates_at) */
        rr_wheelset_pose tp;
        rr_contact_point g[2];
        rr_rig_pose pr;
        const double yr = t->rows[(size_t)(i + j) * RR_NH_ROW_LEN];
        if ((st = rr_contact_table_lookup(m->table, yr, &tp, NULL, &g[0], &g[1])) < 0
            || (st = pose_of(m, s, yr, &tp, slope, &pr)) < 0)
            return st;
        memcpy(ns.motion[j].c, pr.c, sizeof pr.c);
        memcpy(ns.motion[j].v, pr.v, sizeof pr.v);
        memcpy(ns.motion[j].w, pr.w, sizeof pr.w);
    }
    ns.y = s->y;
    ns.mu = c->friction.mu0;
    ns.roller_spin = s->roller_spin;
    ns.vmin = m->vmin;
    ns.x = s->x;
    ns.yaw = s->yaw;
    {
        /* the seed: the last evaluation's share, or, for that evaluation's own
         * state and load again, the seed it started from (the same doubles) */
        const double key[9] = {s->x, s->y, s->yaw, s->vx, s->vy, s->yaw_rate, s->spin,
                               s->roller_spin, N};
        const double seed = memcmp(key, c->nh_key, sizeof key) == 0 ? c->nh_seed : c->nh_tz;
        if ((st = rr_nonhertz_wheel_law(t, &ns, c->friction.A, c->friction.B, seed, &r)) < 0)
            return st;
        c->nh_seed = seed;
        c->nh_tz = r.tz;
        memcpy(c->nh_key, key, sizeof key);
    }
    c->f.fx = c->f.fy = c->f.mz = 0.0;
    for (j = 0; j < r.npatch; j++) {
        const rr_nh_patch *p = &r.patch[j];
        Nsum += p->N;
        c->f.fx += p->fx;
        c->f.fy += p->fy;
        c->f.mz += p->mz;
        ab_sum += p->a * p->b;
        if (p->N > Nmax) {
            Nmax = p->N;
            ab = p->a / p->b;
        }
    }
    if (!(Nsum > 0.0))
        return RR_ERR_RANGE;
    scale = N / Nsum;
    c->f.fx *= scale;
    c->f.fy *= scale;
    c->f.mz *= scale;
    c->hertz.a = sqrt(ab_sum * ab);
    c->hertz.b = sqrt(ab_sum / ab);
    c->hertz.p0 = r.pmax;
    c->hertz.delta = r.w == 0.0 ? r.dz[0] : r.w == 1.0 ? r.dz[1]
                                        : (1.0 - r.w) * r.dz[0] + r.w * r.dz[1];
    memcpy(c->force, r.force, sizeof r.force);
    memcpy(c->moment, r.moment, sizeof r.moment);
    memcpy(c->frame.p, r.centre, sizeof r.centre);
    return RR_OK;
}

/* rr_rig_contact_loads with the model's creep method checked into creep
 * (cst its status) and its workspace, m, N, pose and w not NULL */
static int loads(const rr_rig_contact_model *m, const rr_creep_checked *creep, int cst,
                 double *work, size_t work_len, const double N[2], const rr_rig_pose *pose,
                 rr_wheel_contact w[2])
{
    /* the non-Hertzian rows' rates: the table's slopes at the state's y,
     * once for both wheels (inside the table: its kinematics found y) */
    rr_wheelset_pose slope;
    const int sst = m->patch == RR_RIG_PATCH_NONHERTZ ? slopes_at(m, pose->state.y, &slope)
                                                      : RR_OK;
    int k;
    for (k = 0; k < 2; k++) {
        rr_wheel_contact *c = &w[k];
        rr_contact_problem cc;
        double arm[3];
        int j, sk;

        if (c->status < 0)
            continue;
        c->N = N[k];
        if (!isfinite(N[k])) {
            wheel_nan(c, RR_ERR_NONFINITE);
            continue;
        }
        if (!(N[k] > 0.0)) {
            wheel_nan(c, RR_ERR_LOAD);
            continue;
        }
        if (m->patch == RR_RIG_PATCH_NONHERTZ) {
            sk = cst < 0 ? cst : sst < 0 ? sst : nonhertz_wheel(m, k, N[k], pose, &slope, c);
            if (sk < 0)
                wheel_nan(c, sk);
            else if (!rr_all_finite(c->force, 3) || !rr_all_finite(c->moment, 3)
                     || !isnormal(c->hertz.a) || !isnormal(c->hertz.b))
                wheel_nan(c, RR_ERR_RANGE);
            continue;
        }
        if (!(c->geo.ha > 0.0 && c->geo.hb > 0.0)) {
            wheel_nan(c, RR_ERR_GEOMETRY);
            continue;
        }
        {
            /* Hertz from the table's ellipse per unit load: a ~ (N/E*)^(1/3) */
            const double q = N[k] / m->estar;
            const double s = isnormal(q) ? cbrt(q) : cbrt(N[k]) / cbrt(m->estar);
            c->hertz.a = c->geo.ha * s;
            c->hertz.b = c->geo.hb * s;
            c->hertz.delta = c->geo.hd * s * s;
            c->hertz.p0 = 1.5 * N[k] / (RR_PI * c->hertz.a * c->hertz.b);
            if (!isnormal(c->hertz.a) || !isnormal(c->hertz.b) || !isnormal(c->hertz.p0)
                || !isnormal(c->hertz.delta)) {
                wheel_nan(c, RR_ERR_RANGE);     /* load and modulus too extreme together */
                continue;
            }
        }
        cc.a = c->hertz.a;
        cc.b = c->hertz.b;
        cc.N = N[k];
        cc.G = m->G;
        cc.nu = m->nu;
        cc.cx = c->creep.cx;
        cc.cy = c->creep.cy;
        cc.cphi = c->creep.cphi;
        cc.speed = c->creep.V;
        cc.friction = c->friction;
        cc.patch = RR_PATCH_ELLIPSE;
        sk = cst < 0 ? cst : rr_creep_forces_checked(creep, &cc, work, work_len, NULL, &c->f);
        if (sk < 0) {
            wheel_nan(c, sk);
            continue;
        }
        if (sk > c->status)
            c->status = sk;
        for (j = 0; j < 3; j++) {
            c->force[j] = c->f.fx * c->frame.t1[j] + c->f.fy * c->frame.t2[j] + N[k] * c->n[j];
            arm[j] = c->frame.p[j] - pose->c[j];
        }
        cross(arm, c->force, c->moment);
        for (j = 0; j < 3; j++)
            c->moment[j] += c->f.mz * c->n[j];
        if (!rr_all_finite(c->force, 3) || !rr_all_finite(c->moment, 3))
            wheel_nan(c, RR_ERR_RANGE);     /* a load near the largest double */
    }
    return worse(w[0].status, w[1].status);
}

/* both wheels' loads refused: NULL pointers */
static int loads_null(rr_wheel_contact w[2])
{
    wheel_nan(&w[0], RR_ERR_NULL);
    wheel_nan(&w[1], RR_ERR_NULL);
    return RR_ERR_NULL;
}

int rr_rig_contact_loads(const rr_rig_contact_model *m, const double N[2], const rr_rig_pose *pose,
                         rr_wheel_contact w[2])
{
    rr_creep_checked creep;
    if (!w)
        return RR_ERR_NULL;
    if (!m || !N || !pose)
        return loads_null(w);
    return loads(m, &creep, rr_creep_check(&creep, &m->creep, NULL), NULL, 0, N, pose, w);
}

int rr_rig_contact_loads_checked(const rr_rig_contact_checked *k, const double N[2],
                                 const rr_rig_pose *pose, rr_wheel_contact w[2])
{
    if (!w)
        return RR_ERR_NULL;
    if (!bound(k) || !N || !pose)
        return loads_null(w);
    return loads(&k->m, &k->creep, RR_OK, k->work, k->work_len, N, pose, w);
}

/* the kinematics' status st: nothing valid (no pose), or go on to the loads */
static int no_loads(int st, const rr_rig_pose *pose)
{
    return st == RR_ERR_NULL || (st < 0 && !isfinite(pose->c[0]));
}

int rr_rig_contact(const rr_rig_contact_model *m, const rr_rig_state *s, const double N[2],
                   rr_rig_pose *pose, rr_wheel_contact w[2])
{
    int st = rr_rig_kinematics(m, s, pose, w);
    return no_loads(st, pose) ? st : rr_rig_contact_loads(m, N, pose, w);
}

int rr_rig_contact_eval_checked(const rr_rig_contact_checked *k, const rr_rig_state *s,
                                const double N[2], rr_rig_pose *pose, rr_wheel_contact w[2])
{
    int st = rr_rig_kinematics_checked(k, s, pose, w);
    return no_loads(st, pose) ? st : rr_rig_contact_loads_checked(k, N, pose, w);
}
