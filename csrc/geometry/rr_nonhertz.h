/*
 * rr_nonhertz.h - a fast non-Hertzian, multi-patch contact of one wheel on
 * its roller, from a table per lateral shift built by the exact theory
 * (rr_nonhertz_table.h builds it; benchmarks/NONHERTZ_STUDY.md chose the
 * method and measured it: "The recommended method, for C").
 *
 * The table: rows at increasing lateral shifts y of the wheelset; per row
 * up to RR_NH_MAX_PATCHES patches; per patch its vertical gap g at the
 * row's zero-gap pose and, at RR_NH_NODES loads, the exact normal solution
 * as functions of the lowering e beyond g: q = N / e^1.5 (Hertz's law: q
 * nearly constant), the tangent plane (its reference point P = (0, PY, PZ)
 * in the rig frame and angle delta), the pressure's centroid (xc, yc) in
 * the plane from P, area / N^(2/3), peak / N^(1/3), a/b of the pressure's
 * second moments, and the exact linear creep coefficients about the
 * centroid K11 = -fx/cx, K22 = -fy/cy, K23 = -fy/cphi; at RR_NH_CORR of
 * the nodes the exact forces' departure from the calibrated ellipse (below)
 * over mu_ref N on a polar grid of normalised creepage.
 *
 * The run time, per wheel: the two rows around y each evaluated as if the
 * wheelset were at the row's shift, moving as it does at y (the caller
 * gives that motion), the results blended linearly in y (results, not node
 * data: the forces stay continuous where the rows' patches differ).  Per row: the
 * shared lowering dz from the vertical load Fz (sum over patches of
 * N_j(dz - g_j) cos(delta_j) + the creep forces' vertical share = Fz: a
 * bracketed secant on S^(2/3), the share fixed-point iterated); per patch
 * the creepages at the centroid, the calibrated ellipse (a/b from the
 * pressure; c^2 from K11, cy and the spin scaled so that the ellipse's
 * C22 and C23 are the patch's), rr_exact_table_forces on it, plus the
 * tabulated correction.  No allocation, no state: a few microseconds.
 *
 * Frame of a patch (rr_gap.h's): t1 = (1, 0, 0), t2 = (0, cos delta,
 * sigma sin delta), n = (0, -sigma sin delta, cos delta) into the wheel;
 * fx, fy on the wheel along t1, t2, mz about n at the centroid; with a
 * longitudinal shift or a yaw that frame turned about the roller's axis
 * (rr_nonhertz_frame).
 */
#ifndef RR_NONHERTZ_H
#define RR_NONHERTZ_H

#include "geometry/rr_creepage.h"

#define RR_NH_NODES 9          /* load nodes per patch */
#define RR_NH_CORR 2           /* of them, carrying a correction (RR_NH_CORR_NODE0, 1) */
#define RR_NH_CORR_NODE0 4
#define RR_NH_CORR_NODE1 6
#define RR_NH_U 4              /* the correction's radial nodes u = rho / (1 + rho) */
#define RR_NH_TH 8             /* and angles, 45 degrees apart from the cx axis */
#define RR_NH_MAX_PATCHES 2

/* Quantities per node, each RR_NH_NODES values (RR_NH_NODE). */
enum {
    RR_NH_E = 0,     /* lowering beyond the patch's gap [m], increasing, > 0 */
    RR_NH_Q = 1,     /* N / e^1.5 [N/m^1.5], > 0 */
    RR_NH_PY = 2,    /* the plane's reference point P, rig Y [m] */
    RR_NH_PZ = 3,    /* and Z [m] */
    RR_NH_DELTA = 4, /* the plane's angle [rad], |delta| < pi/2 */
    RR_NH_XC = 5,    /* the pressure's centroid from P along t1 [m] */
    RR_NH_YC = 6,    /* and along t2 [m] */
    RR_NH_AREA = 7,  /* contact area / N^(2/3) [m^2 / N^(2/3)], > 0 */
    RR_NH_PMAX = 8,  /* peak pressure / N^(1/3) [Pa / N^(1/3)], > 0 */
    RR_NH_AB = 9,    /* a/b of the pressure's moments, in [0.1, 10] */
    RR_NH_K11 = 10,  /* exact linear coefficients about the centroid [N], > 0 */
    RR_NH_K22 = 11,  /* [N] > 0 */
    RR_NH_K23 = 12,  /* [N m] */
    RR_NH_NQ = 13
};

/* One correction node: e, then R0[3] (zero creepage), then R[u][th][3]:
 * (fx, fy, mz about the centroid) of the exact theory less the calibrated
 * ellipse's, over mu_ref N (mz over mu_ref N times 1 m). */
#define RR_NH_CORR_LEN (4 + 3 * RR_NH_U * RR_NH_TH)
/* A patch: g, the node quantities (quantity-major), the correction nodes. */
#define RR_NH_PATCH_LEN (1 + RR_NH_NQ * RR_NH_NODES + RR_NH_CORR * RR_NH_CORR_LEN)
/* A row: y, patches, the zero-gap pose's z and roll, then the patches. */
#define RR_NH_ROW_HEAD 4
#define RR_NH_ROW_LEN (RR_NH_ROW_HEAD + RR_NH_MAX_PATCHES * RR_NH_PATCH_LEN)

/* Offsets in a row: patch j, node quantity q at node k; correction c. */
#define RR_NH_PATCH(j) (RR_NH_ROW_HEAD + (j) * RR_NH_PATCH_LEN)
#define RR_NH_NODE(q, k) (1 + (q) * RR_NH_NODES + (k))
#define RR_NH_CORR_AT(c) (1 + RR_NH_NQ * RR_NH_NODES + (c) * RR_NH_CORR_LEN)

/* The correction's radial nodes (RR_NH_U of them, increasing in (0, 1)). */
extern const double rr_nh_corr_u[RR_NH_U];

typedef struct {
    int nrows;            /* >= 2 */
    const double *rows;   /* nrows x RR_NH_ROW_LEN, y strictly increasing */
    double sigma;         /* +1 left wheel, -1 right */
    double R0;            /* the roller's nominal radius (its axis at Z = -R0) [m] */
    double G, nu;         /* the material the table was built for [Pa], [-] */
    double mu_ref;        /* the friction its correction was built at */
} rr_nh_table;

/*
 * rr_nonhertz_table_check - every row of t valid (the layout above: finite,
 * nodes increasing, loads and coefficients positive, a/b in range).
 *   status: 0 OK; RR_ERR_NULL, RR_ERR_TABLE (*bad_row, when bad_row is not
 *   NULL, the first row at fault, -1 for the header: nrows, sigma, R0, G,
 *   nu, mu_ref).
 */
int rr_nonhertz_table_check(const rr_nh_table *t, int *bad_row);

/*
 * rr_nonhertz_locate - the rows around y: row i and i + 1 with y_i <= y <=
 * y_{i+1}, weight w of row i + 1.  Status 0; RR_ERR_NULL, RR_ERR_NONFINITE
 * (y), RR_ERR_TABLE (y outside [y_0, y_last]).
 */
int rr_nonhertz_locate(const rr_nh_table *t, double y, int *row, double *w);

/* A patch's reference point and frame in the rig frame. */
typedef struct {
    double P[3], t1[3], t2[3], n[3];
} rr_nh_frame;

/*
 * rr_nonhertz_frame - a patch's frame turned by theta about the roller's
 * axis (the rig's law for a longitudinal shift and a yaw, rr_rig_contact.h):
 *   returns: *f: P = ((PZ + R0) sin theta, PY, (PZ + R0) cos theta - R0),
 *            t1 = (cos theta, 0, -sin theta), n = (cos delta sin theta,
 *            -sigma sin delta, cos delta cos theta), t2 = n x t1 (theta = 0:
 *            the frame above, P = (0, PY, PZ)).  No checks: the caller's
 *            numbers (a NaN gives NaN).
 */
void rr_nonhertz_frame(double PY, double PZ, double delta, double theta, double sigma,
                       double R0, rr_nh_frame *f);

/*
 * rr_nonhertz_creepages - Kalker's creepages at a patch's reference point
 * f->P in frame f: the slip of the wheel's material point P - pen n, the
 * wheelset's centre lowered by dz from ws->c, relative to the roller's at P
 * (angular velocity (0, -roller_spin, 0) about its axis at Z = -R0), over
 * the rolling speed (at least vmin).  k = (cx, cy, cphi, V).  Status 0 or
 * RR_ERR_RANGE (a result not finite).
 */
int rr_nonhertz_creepages(const rr_motion *ws, double roller_spin, double R0,
                          const rr_nh_frame *f, double pen, double dz, double vmin, double k[4]);

/* One wheel's state (rr_nonhertz_wheel). */
typedef struct {
    double y;             /* the wheelset's lateral shift [m] */
    double Fz;            /* the vertical load on the wheel [N], > 0 */
    double mu;            /* Coulomb friction, > 0 */
    double roller_spin;   /* the rollers' angular speed [rad/s] */
    double vmin;          /* least rolling speed for the creepages [m/s], > 0 */
    double x, yaw;        /* the wheelset's longitudinal shift [m] and yaw [rad]: each
                             patch's frame turned about the roller axis by the rig's
                             first-order law (rr_rig_contact.h) with the patch's delta,
                             r and R; 0, 0: the table's planes */
    rr_motion motion[2];  /* the wheelset's rigid motion at rows i and i + 1 of
                             rr_nonhertz_locate (c its centre, v, w): the rig's
                             pose at the row's shift moving with the state's own
                             rates (rr_rig_kinematics_rates_at, y_rates = y: the
                             vertical and roll rates vy gives at y itself, which
                             jump where the other wheel's contact does) */
} rr_nh_state;

/* One patch of the result: row i's and row i + 1's patch of the same
 * region blended (matched by place: in order where the rows have as many,
 * else the nearest); a patch only one row has enters with that row's
 * weight, at its place. */
typedef struct {
    double N;             /* normal load [N] */
    double fx, fy, mz;    /* creep forces on the wheel along t1, t2 [N], spin moment about
                             n at the centroid [N m] */
    double force[3];      /* fx t1 + fy t2 + N n, rig frame [N] */
    double t1[3], t2[3], n[3];  /* the patch's frame (the rows' blended, normalised) */
    double point[3];      /* the pressure's centroid, rig frame [m] */
    double delta;         /* the plane's angle [rad] */
    double cx, cy, cphi;  /* creepages at the centroid [-], [-], [rad/m] */
    double area, pmax;    /* contact area [m^2], peak pressure [Pa] */
    double a, b;          /* the calibrated ellipse's semi-axes [m] (its linear creep
                             coefficients the patch's: G a b C11 = K11) */
} rr_nh_patch;

typedef struct {
    int npatch;                          /* patches (the larger of the two rows') */
    rr_nh_patch patch[RR_NH_MAX_PATCHES];
    double force[3];                     /* the wheel's total contact force, rig frame [N] */
    double moment[3];                    /* its moment about the wheelset centre [N m] */
    double N;                            /* the patches' normal loads summed [N] */
    double area, pmax;                   /* summed area [m^2], the largest peak [Pa] */
    double centre[3];                    /* the load-weighted force centre [m] */
    double dz[2];                        /* the rows' lowering [m] */
    int row;                             /* row i */
    double w;                            /* the weight of row i + 1 */
    int table_calls;                     /* rr_exact_table_forces calls spent */
    double tz;                           /* the creep forces' vertical share the last row
                                            evaluated settled at [N] (a next call's seed) */
} rr_nh_result;

/*
 * rr_nonhertz_wheel - one wheel's contact from table t (above).
 *   status: 0 OK; RR_ERR_NULL, RR_ERR_NONFINITE (a state value), RR_ERR_LOAD
 *   (Fz <= 0), RR_ERR_FRICTION (mu <= 0), RR_ERR_SPEED (vmin <= 0),
 *   RR_ERR_TABLE (y beyond the table's rows; a row's patch count; a load
 *   that lowers a patch beyond twice its last node's lowering: the nodes
 *   are extrapolated by Hertz's law up to there, about 2.8 times the last
 *   node's load),
 *   RR_ERR_RANGE (the vertical balance did not settle, or a result not
 *   finite: a load far beyond the table's nodes), the statuses of rr_kalker
 *   and rr_exact_table_forces.  On error *out is NaN.
 */
int rr_nonhertz_wheel(const rr_nh_table *t, const rr_nh_state *s, rr_nh_result *out);

/*
 * rr_nonhertz_wheel_law - rr_nonhertz_wheel under Polach's falling law
 * (rr_friction.h) mu(w) = s->mu ((1 - A) exp(-B w) + A), taken per patch
 * at its rigid slip speed w = |(cx, cy)| V at the centroid (one mu a
 * patch, as FASTSIM's slip_speed "rigid" takes one a contact); A = 1 or
 * B = 0: Coulomb.  tz_seed: the creep forces' vertical share [N] the
 * vertical balance starts from (a previous evaluation's out->tz: a time
 * step's next state settles in one pass where it would take two; 0, or
 * not finite, or beyond Fz / 2: from 0); the result depends on it within
 * the balance's tolerance (1e-4 Fz).  A = 1, B = 0, tz_seed 0:
 * rr_nonhertz_wheel's doubles.
 *   status: rr_nonhertz_wheel's; RR_ERR_NONFINITE (A, B), RR_ERR_FRICTION
 *   (A outside (0, 1], B < 0).
 */
int rr_nonhertz_wheel_law(const rr_nh_table *t, const rr_nh_state *s, double A, double B,
                          double tz_seed, rr_nh_result *out);

#endif
