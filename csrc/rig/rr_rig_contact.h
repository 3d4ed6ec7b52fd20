/*
 * rr_rig_contact.h - one contact evaluation of the rig's wheelset on its two
 * rollers: contact table lookup, the contact point and frame in the rig,
 * the Hertz ellipse, the kinematic creepages and the creep forces, returned
 * as forces and moments on the wheelset in the rig's coordinates.  Fixed
 * cost, no allocation: what the time step calls twice per right-hand side.
 *
 * Rig frame (rr_geometry.h): X forward, Y left, Z up; Z = 0 at the top of
 * a roller of radius R0; the rollers share one axis, the line (X, Z) =
 * (0, -R0).  Motions: the wheelset turns about its axle (pointing left) at
 * `spin` [rad/s], > 0 moving the bottoms of its wheels backward (rolling
 * forward); the rollers turn at `roller_spin` [rad/s] with angular velocity
 * -roller_spin Y, > 0 moving their tops backward.  Free rolling: spin r =
 * roller_spin R at each contact.
 *
 * Placement.  The contact table gives, for the lateral shift y, the axle
 * height z and roll with both wheels touching, and each contact point in
 * the plane of the axle (x = 0).  Everything else follows from the rollers
 * being bodies of revolution:
 *   - a longitudinal shift x turns the wheelset about the roller axis by
 *     beta = asin(x / (R0 + z)) (the tilt of the seed paper's eq. 5-6): the
 *     centre sits at (x, y, sqrt((R0 + z)^2 - x^2) - R0), the geometry is
 *     that of the table turned by beta;
 *   - a yaw psi moves wheel j's centre to x_j = x - a_j sin psi (a_j its
 *     contact point's lateral arm) and, on a coned profile, the point
 *     around the wheel by sigma r tan(delta) psi: the contact point lies
 *     at the angle theta_j = asin(x_j/(r+R)) + sigma r tan(delta) psi/(r+R)
 *     around the roller axis (sigma = +1 left, -1 right), from the
 *     tangency of the two surfaces to first order in psi.  On a rail
 *     (R -> oo) the point leads the wheel centre by sigma r tan(delta) psi,
 *     the classic result; on rollers the whole offset is scaled by R/(r+R).
 *     Other quantities change at second order in psi.
 * The contact frame is the table's frame turned by theta_j: t1 the
 * roller's circumferential direction (reversed if the rig runs backward,
 * so that material always enters at x = +a), n the common normal into the
 * wheel, t2 = n x t1 (lateral, toward +Y when running forward).
 *
 * Constraint rates: the vertical velocity of the centre and the roll rate
 * follow from vx, vy through the table's slopes dz/dy, droll/dy.
 *
 * Normal loads come from the caller (the rig model's normal contact).
 *
 * Patch (rr_rig_contact_model.patch).  RR_RIG_PATCH_HERTZ: one Hertz
 * ellipse at the rigid contact point, its creep forces by the model's
 * method.  RR_RIG_PATCH_NONHERTZ: each wheel by rr_nonhertz_wheel_law
 * (geometry/rr_nonhertz.h) from the caller's table of its side, the
 * wheel's vertical load N n_z (the load the caller gives along the rigid
 * contact's normal n, the rig's balance as on Hertz), the wheelset's
 * motion at the two rows around y (this file's pose at x, each row's
 * shift, yaw and the state's rates) and the wheel's friction law (Polach's
 * falling law per patch at its rigid slip speed); the model's creep
 * method is not used.  The wheel's results then: force, moment the
 * patches' totals; frame.p the load-weighted force centre (the point the
 * rig's balance and roller moment take the force at); f the patches'
 * creep forces and spin moments summed, times N / (their normal loads
 * summed) (the wheel's traction per unit load at the caller's N: |f| <=
 * mu N); hertz a, b the calibrated ellipse of the patch carrying the most
 * load, scaled to the patches' summed a b (the integrator's model,
 * rr_rig.h), p0 the largest peak pressure, delta the blended lowering;
 * creep, geo, t1, t2, n those of the rigid contact point.
 */
#ifndef RR_RIG_CONTACT_H
#define RR_RIG_CONTACT_H

#include "contact/rr_creep.h"
#include "geometry/rr_creepage.h"
#include "geometry/rr_geometry.h"
#include "contact/rr_hertz.h"
#include "geometry/rr_nonhertz.h"

/* The contact patch model (rr_rig_contact_model.patch). */
enum rr_rig_patch { RR_RIG_PATCH_HERTZ = 0, RR_RIG_PATCH_NONHERTZ = 1 };

typedef struct {
    const rr_contact_table *table;  /* geometry against lateral shift */
    double R0;          /* roller radius at the rig's Z = 0 [m] */
    double estar;       /* contact modulus E* [Pa] (rr_estar) */
    double G, nu;       /* combined shear modulus [Pa] and Poisson ratio */
    rr_friction friction;
    rr_creep_opts creep;
    double vmin;        /* least rolling speed for the creepages [m/s] (rr_creepage.h) */
    int patch;          /* enum rr_rig_patch: RR_RIG_PATCH_HERTZ (0, a zeroed model's) */
    const rr_nh_table *nonhertz[2];  /* RR_RIG_PATCH_NONHERTZ: the left (sigma +1) and
                                        right (sigma -1) wheels' tables, the caller's (they
                                        must outlive the model); unused on Hertz */
} rr_rig_contact_model;

typedef struct {
    double x, y;        /* wheelset centre: longitudinal and lateral position [m] */
    double yaw;         /* about Z [rad] */
    double vx, vy;      /* their rates [m/s] */
    double yaw_rate;    /* [rad/s] */
    double spin;        /* wheelset angular speed about its axle [rad/s] */
    double roller_spin; /* rollers' angular speed [rad/s] */
} rr_rig_state;

typedef struct {
    rr_rig_state state; /* the state this is the pose of */
    double c[3];        /* wheelset centre in the rig [m] */
    double roll;        /* roll angle [rad], > 0 lifting the left wheel */
    double roll_rate;   /* its rate, from the constraint [rad/s] */
    double beta;        /* turn about the roller axis [rad], > 0 forward */
    double v[3];        /* centre velocity incl. the constrained vertical rate [m/s] */
    double w[3];        /* angular velocity of the wheelset [rad/s] */
} rr_rig_pose;

typedef struct {
    rr_contact_point geo;   /* the table's geometry (in the plane of the axle) */
    double theta;           /* angle of the contact point around the roller axis [rad] */
    rr_contact_frame frame; /* contact point, t1, t2 in the rig */
    double n[3];            /* unit normal t1 x t2, into the wheel */
    rr_creepages creep;     /* cx, cy, cphi, rolling speed V */
    double N;               /* normal load [N] */
    rr_friction friction;   /* the friction law at this contact: the model's, set by
                               rr_rig_kinematics; a caller may change it before
                               rr_rig_contact_loads (the rig's changing adhesion) */
    rr_hertz_result hertz;  /* a, b, p0 */
    rr_forces f;            /* creep forces on the wheel along t1, t2; spin moment about n */
    double force[3];        /* contact force on the wheelset, rig frame [N] */
    double moment[3];       /* its moment about the wheelset centre [N m] */
    double nh_tz;           /* RR_RIG_PATCH_NONHERTZ: the creep forces' vertical share
                               the wheel's balance settled at [N], and the seed the next
                               rr_rig_contact_loads on this w starts from (0: none; the
                               rig keeps it from step to step, rr_nonhertz_wheel_law) */
    double nh_seed;         /* the seed that evaluation started from */
    double nh_key[9];       /* and its state and load (x, y, yaw, vx, vy, yaw_rate, spin,
                               roller_spin, N): the same state and load again start from
                               the same seed, the same doubles (a rig's re-evaluation after
                               a rebind or a restored co-simulation state) */
    int status;             /* this wheel's status */
} rr_wheel_contact;

/*
 * rr_rig_contact_check - 0 if the model is usable, else RR_ERR_WORKSPACE
 * (no table), RR_ERR_NONFINITE, RR_ERR_GEOMETRY (R0 <= 0), RR_ERR_MATERIAL
 * (E*, G not positive, nu outside [0, 0.5]), RR_ERR_FRICTION, RR_ERR_SPEED
 * (vmin <= 0), rr_creep_opts_check, RR_ERR_METHOD (a method that solves
 * each case iteratively to a tolerance, the exact theory: milliseconds to
 * seconds a case, its work not known before a step: not a time-step
 * method; rr_creep_iterative), RR_ERR_NULL; on RR_RIG_PATCH_NONHERTZ
 * RR_ERR_NULL (a table missing), RR_ERR_TABLE (a table not valid,
 * rr_nonhertz_table_check, or not the model's: its sigma, R0, G or nu),
 * and RR_ERR_PARAM for a patch that is neither.
 */
int rr_rig_contact_check(const rr_rig_contact_model *m);

/*
 * rr_rig_contact_workspace_len - the doubles of workspace the model's
 * creep method needs for a wheel's problem (the ellipse; the wheels take
 * turns in it), 0 for a method that needs none or an invalid model
 * (rr_creep_workspace_len).
 */
size_t rr_rig_contact_workspace_len(const rr_rig_contact_model *m);

/*
 * rr_rig_contact_checked - a contact model checked once, for many
 * evaluations (the rig's time step, a batch of states): rr_rig_contact_check
 * at rr_rig_contact_bind, then rr_rig_kinematics_checked,
 * rr_rig_contact_loads_checked and rr_rig_contact_eval_checked check only
 * what changes per evaluation (the state, the loads, each wheel's problem
 * and friction law).  It keeps a copy of the model (whose table must
 * outlive it) and the caller's workspace for the creep method (which must
 * outlive it too): a changed model takes effect at the next
 * rr_rig_contact_bind.
 */
typedef struct {
    rr_rig_contact_model m;          /* the model, a checked copy */
    rr_creep_checked creep;          /* its creep method, checked */
    double *work;                    /* the caller's workspace for it, or NULL */
    size_t work_len;                 /* its doubles */
    unsigned ready;                  /* RR_RIG_CONTACT_READY once bound */
} rr_rig_contact_checked;

#define RR_RIG_CONTACT_READY 0x52524343u

/*
 * rr_rig_contact_bind - m checked (rr_rig_contact_check) and copied to *k,
 * with the caller's workspace work of work_len doubles for the creep method
 * (NULL, 0 for a method that needs none: rr_rig_contact_workspace_len).
 *   status:  RR_OK; rr_rig_contact_check's, RR_ERR_WORKSPACE (work shorter
 *            than the method needs), or RR_ERR_NULL, with *k not ready (the
 *            *_checked functions refuse it with RR_ERR_NULL).
 */
int rr_rig_contact_bind(rr_rig_contact_checked *k, const rr_rig_contact_model *m, double *work,
                        size_t work_len);

/*
 * rr_rig_kinematics - pose, contact points and frames, creepages (no loads).
 *   given:   m the model; s the wheelset and roller state
 *   returns: *pose; w[0] left, w[1] right wheel: geo, theta, frame, n, creep
 *            (the load fields are left untouched)
 *   status:  0 OK; RR_ERR_NONFINITE (a NaN or infinite state),
 *            RR_ERR_GEOMETRY (y outside the table: a wheel off its roller;
 *            |x| too large), RR_ERR_RANGE (rates so large that the pose's
 *            velocities overflow), errors of rr_creepage, RR_ERR_NULL.
 *            Outputs NaN on error.
 */
int rr_rig_kinematics(const rr_rig_contact_model *m, const rr_rig_state *s, rr_rig_pose *pose,
                      rr_wheel_contact w[2]);

/*
 * rr_rig_kinematics_rates_at - rr_rig_kinematics_checked with the vertical
 * and roll rates that the lateral speed s->vy gives at shift y_rates, not
 * at s->y (the table's slopes there): the wheelset as if at s->y, moving as
 * it does at y_rates.  The non-Hertzian contact evaluates its table's rows
 * so (rr_nonhertz.h: the motion at rows i, i + 1 of a state at y_rates):
 * where the other wheel's contact point jumps between two rows, the
 * wheelset's rates jump with it (S1002 at +6.27 mm, its left flank: at 1
 * cm/s the right wheel's lateral creepage goes from 0.003 to 0.018), and
 * the rows' own rates, blended, missed that by up to 0.37 mu N.
 *   status:  rr_rig_kinematics_checked's; RR_ERR_NONFINITE also for
 *            y_rates, RR_ERR_GEOMETRY for y_rates outside the table.
 *            y_rates = s->y gives rr_rig_kinematics_checked's doubles.
 */
int rr_rig_kinematics_rates_at(const rr_rig_contact_checked *k, const rr_rig_state *s,
                               double y_rates, rr_rig_pose *pose, rr_wheel_contact w[2]);

/*
 * rr_rig_contact - the whole contact evaluation of both wheels.
 *   given:   m; s; N[0], N[1] the normal loads of the left and right
 *            wheel [N]
 *   returns: *pose, w[0..1] complete: Hertz ellipse from the table's
 *            curvature sums, creep forces of that ellipse problem by
 *            m->creep's method (without workspace: a method that needs one
 *            is RR_ERR_WORKSPACE here, rr_rig_contact_eval_checked gives it
 *            the bound one), and the force and moment on the wheelset,
 *            force = fx t1 + fy t2 + N n, moment = (p - c) x force + mz n.
 *   status:  the worse of the two wheels' (errors < 0 before warnings);
 *            each wheel's own in w[k].status, so one bad wheel leaves the
 *            other's results valid.  rr_rig_kinematics, rr_hertz
 *            (RR_ERR_LOAD for N <= 0), rr_creep_forces_work, RR_ERR_RANGE (a load
 *            so extreme that the ellipse or a force overflows).  On
 *            RR_RIG_PATCH_NONHERTZ instead of Hertz's and the method's: the
 *            wheel's friction law's (rr_friction_check), RR_ERR_LOAD (N n_z
 *            not positive), RR_ERR_TABLE (y beyond the wheel's table rows),
 *            rr_nonhertz_wheel_law's, RR_ERR_RANGE.
 */
int rr_rig_contact(const rr_rig_contact_model *m, const rr_rig_state *s, const double N[2],
                   rr_rig_pose *pose, rr_wheel_contact w[2]);

/*
 * rr_rig_contact_loads - the second half of rr_rig_contact: Hertz, creep
 * forces, force and moment for the wheels of a finished rr_rig_kinematics
 * (wheels with an error status are skipped), so that a caller can choose
 * the loads from the contact frames (the rig model's normal-load balance)
 * and each wheel's friction law (w[k].friction, checked by the creep-force
 * method: RR_ERR_FRICTION, RR_ERR_NONFINITE or RR_ERR_RANGE for that wheel).
 *   status:  as rr_rig_contact
 */
int rr_rig_contact_loads(const rr_rig_contact_model *m, const double N[2], const rr_rig_pose *pose,
                         rr_wheel_contact w[2]);

/*
 * rr_rig_kinematics_checked, rr_rig_contact_eval_checked,
 * rr_rig_contact_loads_checked - rr_rig_kinematics, rr_rig_contact and
 * rr_rig_contact_loads of the model bound to k, not checked again: the
 * same doubles and statuses, and RR_ERR_NULL (outputs NaN) where k is not
 * a successful rr_rig_contact_bind's.
 */
int rr_rig_kinematics_checked(const rr_rig_contact_checked *k, const rr_rig_state *s,
                              rr_rig_pose *pose, rr_wheel_contact w[2]);
int rr_rig_contact_eval_checked(const rr_rig_contact_checked *k, const rr_rig_state *s,
                                const double N[2], rr_rig_pose *pose, rr_wheel_contact w[2]);
int rr_rig_contact_loads_checked(const rr_rig_contact_checked *k, const double N[2],
                                 const rr_rig_pose *pose, rr_wheel_contact w[2]);

#endif
