/*
 * rr_rig.h - the roller rig in time: a suspended wheelset on two rigidly
 * joined rollers, the roller and wheelset drives with their PI speed
 * controllers and encoders, and the creepage controller, stepped in
 * real time (the seed paper's mechatronic model, sections 3-5).
 *
 * Plant (rig frame of rr_rig_contact.h: X forward, Y left, Z up):
 *   wheelset: longitudinal x (round the rollers: the tilt beta of eq. 5-6),
 *     lateral y, yaw, spin angle chi, with their rates vx, vy, yaw_rate,
 *     spin; its height and roll follow the contact constraint (the
 *     contact table); each axle box hangs on springs and dampers in x, y, z
 *     from the fixed frame, the vertical ones preloaded;
 *   rollers: one angle theta_r and speed (roller_spin), both rollers on
 *     one shaft with the roller motor;
 *   drives: the motor torques follow their references through a first-
 *     order lag (inverter and drive), T' = (T_ref - T)/tau.
 * Normal loads: the vertical force and the roll moment on the wheelset
 * balance at every instant (its vertical and roll accelerations, which
 * the constraint makes second order small, are left out):
 *     sum_j N_j n_j,z + tangential_z = preload + m g + 2 kz (z - z_ref) + 2 cz vz
 *     sum_j (arm_j x (N_j n_j + tangential_j))_x = 2 b^2 (kz roll + cz roll')
 * solved for N_left, N_right: the 3-D form of the paper's eq. 3-6 (the sec
 * alpha, sec beta and F_y tan alpha terms come from the contact frames).
 * The tangential forces enter through their ratio to the load at the
 * first solution, so each right-hand side costs one contact evaluation
 * per wheel.  A wheel that would need a negative load lifts off: an error.
 *
 * Equations of motion (sums over both contacts, forces of rr_rig_contact):
 *   m x''  = F_x - 2 kx x - 2 cx vx
 *   m y''  = F_y - 2 ky y - 2 cy vy
 *   Izz yaw'' = M_z - 2 b^2 (kx yaw + cx yaw_rate)
 *   Iyy spin' = M . axle + T_wheelset
 *   J_r roller_spin' = T_roller + sum_j ((p_j - O_r) x F_j)_y
 * with b the axle boxes' lateral half-spacing, O_r a point of the roller
 * axis.
 * Gyroscopic terms (gyro_inertia > 0, the wheelset's own spin inertia I_w:
 * a drive's rotor on the frame does not yaw with the axle): the axle a
 * turns with the frame rate w_f = (roll rate about the yawed X, yaw rate
 * about Z), so the spin's angular momentum I_w spin a changes at
 * I_w spin (w_f x a), about -I_w spin yaw_rate X + I_w spin roll_rate Z:
 *   Izz yaw'' = ... - I_w spin (w_f x a)_z     (roll_rate = droll/dy vy)
 * and the contacts' roll moment carries + I_w spin (w_f x a)_x besides
 * the springs' (the roll follows the constraint: a load transfer).  Both
 * vanish while the wheelset runs centred, as in the paper's scenario.
 * Track (track = 1): the rails move at the constant speed of the state's
 * roller_spin (its derivative, and the roller drive's effect, are zero):
 * with the contact table and R0 of a roller of very large radius (rollerrig
 * uses RR_RIG_TRACK_RADIUS) this is the wheelset on tangent track, carried
 * forward at the speed (docs/lateral_dynamics.md).
 *
 * Sampled-data control (period T): at each sample the encoders read the
 * angles, the creepage controller (eq. 13-16) sets the wheelset speed
 * reference, the PI controllers (eq. 10-11) set the torque references,
 * held until the next sample; the plant is then integrated over T in nsub
 * equal steps of a fixed-step L-stable method (rr_ode.h) with an
 * approximate Jacobian (springs exact, creep forces by the 2 x 2 tangent
 * of Kalker's simplified theory, the cubic law with falling friction):
 * every step costs the same.  The positions
 * x, y, yaw, chi, theta_r are the integrals of the next five states, which
 * the integrator's linear algebra exploits (rr_ode nq = 5: 7 unknowns
 * instead of 12).  TR-BDF2 with a linearly implicit trapezoidal stage and
 * one Newton iteration in the BDF2 stage sees the creep force's saturation
 * knee; with newton_model the iteration takes the simplified theory's
 * change of the forces over the step (the integrator's model), anchored at
 * the full method's forces at the step's start: one contact evaluation per
 * step (two with the full method in the iteration).
 */
#ifndef RR_RIG_H
#define RR_RIG_H

#include "rig/rr_control.h"
#include "util/rr_ode.h"
#include "rig/rr_rig_contact.h"

/* Plant state, in this order. */
enum rr_rig_state_index {
    RR_RIG_X = 0, RR_RIG_Y, RR_RIG_YAW, RR_RIG_CHI, RR_RIG_THETA_R,
    RR_RIG_VX, RR_RIG_VY, RR_RIG_YAW_RATE, RR_RIG_SPIN, RR_RIG_ROLLER_SPIN,
    RR_RIG_T_ROLLER, RR_RIG_T_WHEELSET,
    RR_RIG_NSTATE
};

/* The range of the control sample time T [s] (scenario.control_sample_time_s,
 * rollerrig.rig.MIN_DT and MAX_DT); within it rr_rig_check asks the drives'
 * sampled speed loops to be stable at T (rr_rig_speed_loops). */
#define RR_RIG_MIN_T 1e-6
#define RR_RIG_MAX_T 0.1

/* The radius [m] that stands for the rail's infinite one in track mode
 * (track = 1, rollerrig's track=True): the rollers' effects on the lateral
 * dynamics scale as r0/R (r0/R = 9.2e-5 for the scaled wheelset). */
#define RR_RIG_TRACK_RADIUS 1000.0

/* Most points of an adhesion schedule (rr_rig_adhesion). */
#define RR_RIG_MAX_SCHEDULE 256

/*
 * Adhesion that changes, as slide protection and traction control are
 * tested: the friction law (static coefficient mu0 and the falling law's A,
 * B: rr_friction.h) as a schedule in time and as a contaminated patch on
 * the roller circumference.
 *   Schedule: n points (t[i], mu0[i], A[i], B[i]), t non-decreasing; the law
 *   is linear between points, the first point's before them and the last's
 *   after; two points at one time make a step (the later holds from then).
 *   It is taken at each sample's start and held over the sample, as a
 *   sampled input is (rr_rig_write's command overrides mu0).  n = 0: the
 *   contact model's law throughout.
 *   Patch: length > 0 [m] of the circumference at radius R0, from start [m]
 *   (measured on the roller from the mark that is at the top at t = 0, in
 *   the direction the material runs into the contact when the roller spins
 *   forward), on the rollers of `rollers` (bit 0 left, bit 1 right).
 *   A contact at material position s on a roller with a patch has
 *   law = base + f (patch - base) (mu0, A and B each), f the fraction of
 *   the patch at s: 1 inside, 0 outside, linear over `edge` [m] centred on
 *   each edge (about the contact's length 2a, which passes over an edge
 *   gradually).  The position follows the roller angle in the state, so the
 *   patch passes under the wheel within a sample.
 */
typedef struct {
    int n;                                   /* schedule points, 0 to RR_RIG_MAX_SCHEDULE */
    double t[RR_RIG_MAX_SCHEDULE];           /* their times [s] */
    rr_friction law[RR_RIG_MAX_SCHEDULE];    /* mu0, A, B at those times */
    double patch_start;                      /* [m] */
    double patch_length;                     /* [m], 0 <= length <= 2 pi R0; 0: no patch */
    double patch_edge;                       /* [m], > 0 */
    rr_friction patch;                       /* the law inside the patch */
    int patch_rollers;                       /* 1 left, 2 right, 3 both */
} rr_rig_adhesion;

/*
 * A lateral force on the wheelset's centre in time (a disturbance that
 * pushes it towards flange contact): F(t) linear between the points, held
 * before the first and after the last, taken at each sample's start (as the
 * adhesion's schedule); n = 0: none.
 */
typedef struct {
    int n;                                   /* 0 to RR_RIG_MAX_SCHEDULE */
    double t[RR_RIG_MAX_SCHEDULE];           /* times, non-decreasing [s] */
    double f[RR_RIG_MAX_SCHEDULE];           /* the force along Y there [N] */
} rr_rig_lateral;

/* rr_rig_lateral_force - the force of l at time t (0 where l->n is 0). */
double rr_rig_lateral_force(const rr_rig_lateral *l, double t);

typedef struct {
    /* wheelset */
    double mass;             /* [kg] */
    double Iyy;              /* spin inertia with the braking drive referred to the axle [kg m^2] */
    double Izz;              /* yaw inertia [kg m^2] */
    double axlebox_y;        /* lateral half-spacing b of the axle boxes [m] */
    double kx, ky, kz;       /* spring stiffness per axle box [N/m] */
    double cx, cy, cz;       /* damping per axle box [N s/m] */
    double preload;          /* vertical spring preload, both boxes together [N] */
    double g;                /* gravity [m/s^2] */
    /* rollers */
    double roller_inertia;   /* both rollers, shaft and motor [kg m^2] */
    /* contact: table, R0, material, friction, creep method, vmin */
    rr_rig_contact_model contact;
    rr_rig_adhesion adhesion;                 /* changes of contact.friction */
    rr_rig_lateral lateral;                   /* a lateral force on the wheelset */
    /* drives and control */
    double T;                /* sample time of controllers and encoders [s] */
    int nsub;                /* plant steps per sample, >= 1 */
    int method;              /* enum rr_ode_method */
    int newton_iters;        /* TR-BDF2's Newton iterations per stage, 0..RR_ODE_MAX_NEWTON
                              * (0: linearly implicit, one contact evaluation per step) */
    int linear_tr;           /* 1: TR-BDF2's trapezoidal stage without them (rr_ode.h) */
    int newton_model;        /* 1: the iterations take the creep forces' change over the step
                              * from the simplified theory (the integrator's model, rr_ode.h):
                              * one contact evaluation per step */
    rr_pi_params roller_pi, wheelset_pi;      /* their T must equal T */
    double roller_tau, wheelset_tau;          /* drive lags [s], > 0 */
    rr_encoder_params roller_enc, wheelset_enc;
    rr_creepctl_params creepctl;              /* radii, alpha, beta, vmin, sense */
    /* lateral dynamics (docs/lateral_dynamics.md) */
    double gyro_inertia;     /* the wheelset's own spin inertia in the gyroscopic terms
                                [kg m^2], >= 0 (0: left out) */
    int track;               /* 1: tangent track, the rails' speed held (see above); 0: rig */
} rr_rig_params;

/*
 * The quantities recorded at the end of each sample, in this order: one
 * list gives both the enum (RR_REC_<ID>) and each field's name, unit and
 * meaning (rr_rig_record_field, rr_rig_params.h), so that a name cannot
 * drift from its index.  RR_RIG_RECORD(F) calls F(ID, name, unit, meaning)
 * once per field; the sample's status is always the last field.
 */
#define RR_RIG_RECORD(F)                                                                      \
    F(T, "time", "s", "time at the end of the sample")                                        \
    F(CREEPAGE, "creepage", "-", "longitudinal creepage cx of the contact model, mean of "    \
      "both contacts (Kalker's sign: > 0 braking, < 0 traction)")                             \
    F(XI_EST, "xi_est", "-", "the creepage controller's estimate from the encoders (eq. "     \
      "16), in the drive's sense (> 0)")                                                      \
    F(XI_REF, "xi_ref", "-", "the creepage target (> 0; NaN before the first target starts)") \
    F(ROLLER_SPEED, "roller_speed", "m/s", "roller surface speed, roller_spin R0")            \
    F(WHEELSET_SPEED, "wheelset_speed", "m/s", "wheel surface speed, spin r0")                \
    F(FX, "fx", "N", "longitudinal creep force on the wheelset, both wheels (on the wheel: "  \
      "< 0 braking, > 0 traction)")                                                           \
    F(FY, "fy", "N", "lateral creep force on the wheelset, both wheels")                      \
    F(N_LEFT, "normal_load_left", "N", "normal load of the left wheel")                       \
    F(N_RIGHT, "normal_load_right", "N", "normal load of the right wheel")                    \
    F(ADHESION, "adhesion", "-", "adhesion coefficient |fx| / (normal_load_left + "           \
      "normal_load_right)")                                                                   \
    F(T_ROLLER, "torque_roller", "N m", "roller drive torque (after its lag)")                \
    F(T_WHEELSET, "torque_wheelset", "N m", "wheelset drive torque (after its lag)")          \
    F(W_REF, "w_ref", "rad/s", "wheelset speed reference: the creepage controller's (eq. "    \
      "15) or a controller's of the caller; NaN while the wheelset's torque is commanded")    \
    F(X, "x", "m", "wheelset longitudinal position")                                          \
    F(Y, "y", "m", "wheelset lateral position (+: to the left)")                              \
    F(YAW, "yaw", "rad", "wheelset yaw angle")                                                \
    F(CX_LEFT, "creepage_left", "-", "longitudinal creepage of the left contact")             \
    F(CX_RIGHT, "creepage_right", "-", "longitudinal creepage of the right contact")          \
    F(TREF_ROLLER, "torque_ref_roller", "N m", "roller torque reference held over the "       \
      "sample")                                                                               \
    F(TREF_WHEELSET, "torque_ref_wheelset", "N m", "wheelset torque reference held over "     \
      "the sample")                                                                           \
    F(VX, "vx", "m/s", "wheelset longitudinal velocity")                                      \
    F(VY, "vy", "m/s", "wheelset lateral velocity")                                           \
    F(YAW_RATE, "yaw_rate", "rad/s", "wheelset yaw rate")                                     \
    F(SPIN, "spin", "rad/s", "wheelset angular speed about its axle")                         \
    F(ROLLER_SPIN, "roller_spin", "rad/s", "roller angular speed")                            \
    F(MU_LEFT, "mu_left", "-", "static friction coefficient at the left contact (the "        \
      "adhesion in effect: schedule, command, patch)")                                        \
    F(MU_RIGHT, "mu_right", "-", "static friction coefficient at the right contact")          \
    F(STATUS, "sample_status", "-", "status of the sample: 0 OK, > 0 warning, < 0 error "     \
      "(rollerrig.status_message)")

#define RR_REC_ENUM_(id, name, unit, meaning) RR_REC_##id,
enum rr_rig_record_index {
    RR_RIG_RECORD(RR_REC_ENUM_)
    RR_REC_COUNT
};

/* A contact's creep forces linearised at a state: the simplified theory's
 * coefficients and the creepages' dependence on the rates (rr_rig_jac). */
typedef struct {
    double f11, f22;               /* initial slopes G a b C11, G a b C22 [N] */
    double N, V;                   /* normal load [N], rolling speed [m/s] */
    rr_friction friction;          /* the contact's friction law there */
    double cx, cy;                 /* creepages there */
    double fx, fy;                 /* the simplified theory's forces there [N] */
    double D[4];                   /* and their tangent d f / d c (row-major 2 x 2) [N] */
    double ab, c11, c22;           /* a/b of the last Kalker lookup and its C11, C22: the
                                      lookup is skipped while a/b stays (a centred wheelset) */
    double dcx[RR_RIG_NSTATE];     /* d cx / d y, d cy / d y (linearised eq. 7-8) */
    double dcy[RR_RIG_NSTATE];
    double rx[RR_RIG_NSTATE];      /* d (dy/dt) per unit fx, fy on this contact */
    double ry[RR_RIG_NSTATE];
    int ok;                        /* 0: the contact has no usable coefficients */
} rr_rig_creep_lin;

/*
 * External control: how a drive is commanded at a sample (rr_rig_write).
 *   RR_CMD_BUILTIN  the rig's own controller: the roller's PI to a speed
 *                   reference [rad/s]; the wheelset's creepage controller
 *                   (eq. 13-16) to a creepage target (NaN: none, the
 *                   wheelset held at free rolling), then its PI
 *   RR_CMD_SPEED    a speed reference [rad/s] to the drive's PI (eq. 10-11)
 *   RR_CMD_TORQUE   a torque reference [N m] straight to the drive's lag,
 *                   clipped to its limit (the PI's Tmax)
 */
enum rr_rig_cmd_mode { RR_CMD_BUILTIN = 0, RR_CMD_SPEED = 1, RR_CMD_TORQUE = 2 };

typedef struct {
    int roller_mode;         /* enum rr_rig_cmd_mode (BUILTIN and SPEED are one for the roller) */
    double roller_ref;       /* its reference: speed [rad/s] or torque [N m] */
    int wheelset_mode;       /* enum rr_rig_cmd_mode */
    double wheelset_ref;     /* creepage target [-] (BUILTIN, controller's sense, NaN: none),
                                speed [rad/s] or torque [N m] */
    double mu0;              /* static friction coefficient over the sample; NaN: the
                                adhesion schedule's (or the contact model's) */
} rr_rig_command;

/* What a controller sees at a sample (rr_rig_read): the encoders and the drives. */
typedef struct {
    double t;                /* time of the sample [s] */
    double roller_count;     /* encoder counters (whole counts, cumulative) [-] */
    double wheelset_count;
    double roller_angle;     /* the quantised angles, count 2 pi / counts [rad] */
    double wheelset_angle;
    double roller_speed;     /* the encoders' speed estimates (eq. 12) [rad/s] */
    double wheelset_speed;
    double roller_torque;    /* the drives' torques, as a torque sensor reads them [N m] */
    double wheelset_torque;
    double xi_est;           /* eq. 16's creepage estimate from the encoders, in the
                                creepage controller's sense [-] */
} rr_rig_signals;

typedef struct {
    const rr_rig_params *p;
    /* the creep method's small-creepage slope scale (its registry's), taken
     * at rr_rig_init (its options checked there; the method saturates:
     * rr_rig_method_check) */
    double creep_slope_scale;
    /* the contact model p->contact, checked (and copied) at rr_rig_init
     * and rr_rig_rebind, not at each evaluation */
    rr_rig_contact_checked contact;
    /* the caller's workspace for the creep method (rr_rig_workspace_len),
     * given at rr_rig_init, kept by rr_rig_rebind */
    double *work;
    size_t work_len;
    double t;                      /* time [s] */
    double y[RR_RIG_NSTATE];       /* plant state */
    double z_ref;                  /* axle height at which the springs carry the preload [m] */
    /* references held between samples */
    double xi_ref;                 /* creepage target [-] */
    double Tref_roller, Tref_wheelset;
    int creep_control;             /* 1 while eq. 13-14 steer the wheelset */
    int phase;                     /* 1 after rr_rig_read, 2 after rr_rig_write; 0 after
                                      rr_rig_advance */
    double enc_w[2];               /* the last reading's speeds: roller, wheelset [rad/s] */
    double enc_xi;                 /* and its eq. 16 estimate [-] */
    rr_friction friction;          /* the base law held over the sample (schedule, command) */
    rr_pi_state roller_pi, wheelset_pi;
    rr_encoder_state roller_enc, wheelset_enc;
    rr_creepctl_state creepctl;
    rr_ode ode;
    /* the last contact evaluation, reused when the state is unchanged */
    double cache_y[RR_RIG_NSTATE];
    int cache_ok;
    rr_rig_pose pose;
    rr_wheel_contact w[2];
    /* the Jacobian's constant part, and the creep forces linearised at lin_y */
    double J0[RR_RIG_NSTATE * RR_RIG_NSTATE];
    rr_rig_creep_lin lin[2];
    double lin_y[RR_RIG_NSTATE];
    int lin_ok;
    int status;                    /* of the last step; < 0 stops stepping */
    int ready;                     /* 1 after a successful rr_rig_init */
} rr_rig;

/*
 * rr_rig_check - 0 if the parameters are usable, else RR_ERR_NONFINITE,
 * RR_ERR_PARAM (a mass, inertia, stiffness, damping, preload, sample time,
 * nsub, newton_iters or lag out of range, a controller's T differs from T,
 * or a drive's sampled speed loop is unstable at T: rr_rig_speed_loops),
 * RR_ERR_METHOD (a creep-force method the rig does not step with:
 * rr_rig_method_check), or the status of the contact model, controller or
 * encoder checks.
 */
int rr_rig_check(const rr_rig_params *p);

/*
 * rr_rig_method_check - RR_OK if the rig steps with the creep-force method
 * of o: a time-loop method, whose case has bounded work (not one solved
 * iteratively to a tolerance, the registry's iterative: the exact theory,
 * milliseconds to seconds a contact, its work not known before the step)
 * and one that keeps |F| <= mu N (the registry's saturates: not the linear
 * theory, whose force grows past mu N, an adhesion the rig would report as
 * measured); else RR_ERR_METHOD, or RR_ERR_NULL.  A method's workspace is
 * no reason: the rig gives it one (rr_rig_workspace_len).  The one rule:
 * rr_rig_check, the FMU's list of methods and rollerrig.METHODS[m].in_rig
 * follow it.
 */
int rr_rig_method_check(const rr_creep_opts *o);

/*
 * rr_rig_workspace_len - the doubles of workspace the rig of parameters p
 * needs for its creep method (rr_rig_contact_workspace_len of p->contact:
 * 0 for every method the rig steps with today), for rr_rig_init; 0 for
 * invalid parameters or NULL.
 */
size_t rr_rig_workspace_len(const rr_rig_params *p);

/*
 * rr_rig_speed_loops - the drives' sampled speed loops of p at p->T
 * (rr_control.h, rr_speed_loop): loops[0] the roller's (roller_pi on
 * roller_inertia through roller_tau), loops[1] the wheelset's (wheelset_pi
 * on Iyy through wheelset_tau, with eq. 13's creepctl.alpha around it).
 * Each drive turns its own inertia: the contact saturated, as under
 * creepage control (with the contact sticking the two inertias turn
 * together under both drives, a loop whose gain over inertia lies between
 * the two).  rr_rig_check asks both to be stable (rr_speed_loop_check);
 * rr_speed_loop_range gives the sample times at which each is.  No checks
 * (p, loops not NULL).
 */
void rr_rig_speed_loops(const rr_rig_params *p, rr_speed_loop loops[2]);

/*
 * rr_rig_init - (re)start the rig at free rolling: centred wheelset, rollers at
 * roller_speed [rad/s], the wheelset rolling freely on them, drives
 * holding the torques that balance the steady state, controllers primed
 * with these speeds, no creepage control (target 0) until rr_rig_step
 * gets a target.
 *   given:   p (kept by pointer: it must outlive the rig; its contact model
 *            is checked and copied here, the time step does not check it
 *            again: a change to it acts from rr_rig_rebind); roller_speed;
 *            work, work_len: the caller's workspace for the creep method,
 *            at least rr_rig_workspace_len(p) doubles (NULL, 0 where that
 *            is 0), kept by pointer (it must outlive the rig; one rig a
 *            workspace): no step allocates
 *   returns: *rig
 *   status:  rr_rig_check; RR_ERR_WORKSPACE (work too short); errors of the
 *            contact evaluation; RR_ERR_NULL.
 *   After a failed init every other rr_rig_ function returns its status (and
 *   NaN records); on a rig never initialised (zeroed memory) they return
 *   RR_ERR_NULL.  All of them return RR_ERR_NULL for a NULL argument.
 */
int rr_rig_init(const rr_rig_params *p, double roller_speed, double *work, size_t work_len,
                rr_rig *rig);

/*
 * rr_rig_read - the sampling instant's measurement, for a controller of the
 * caller's (software in the loop): the encoders read the angles; the
 * drives' torques and eq. 16's estimate.  Once per sample, before
 * rr_rig_write.
 *   given:   rig, at a sample's start (after rr_rig_init or rr_rig_advance)
 *   returns: *sig
 *   status:  0; RR_ERR_SEQUENCE (already read this sample); the rig's error
 *            if it cannot step; an encoder's error (nothing changes).  On
 *            error *sig is NaN.
 */
int rr_rig_read(rr_rig *rig, rr_rig_signals *sig);

/*
 * rr_rig_write - the sampling instant's action: the references the
 * drives hold until the next sample, from the command (the rig's own
 * controllers where a mode is RR_CMD_BUILTIN, from the speeds of this
 * sample's rr_rig_read), and the friction law over the sample.
 *   given:   rig after rr_rig_read; cmd
 *   status:  0; RR_ERR_SEQUENCE (no reading this sample, or a second
 *            command); RR_ERR_PARAM (an unknown mode); RR_ERR_NONFINITE (a
 *            reference NaN or infinite, but a BUILTIN creepage target NaN);
 *            RR_ERR_FRICTION (mu0 not positive); a controller's error.  On
 *            error nothing changes: the last sample's references hold, and
 *            rr_rig_write may be called again with another command.
 *   rr_rig_read, rr_rig_write with both modes BUILTIN and rr_rig_advance
 *   are rr_rig_step, bit for bit.
 */
int rr_rig_write(rr_rig *rig, const rr_rig_command *cmd);

/* rr_rig_command_builtin - the command of rr_rig_step: both drives BUILTIN,
 * mu0 NaN. */
void rr_rig_command_builtin(rr_rig_command *cmd, double roller_ref, double xi_ref);

/*
 * rr_rig_friction_at - the friction law the adhesion gives a contact: the
 * schedule at time t (p->contact.friction if it has no points), then the
 * patch at material position s [m] on roller `side` (0 left, 1 right); s
 * NaN: no patch.  No checks: for callers holding checked parameters.
 */
rr_friction rr_rig_friction_at(const rr_rig_params *p, double t, int side, double s);

/*
 * rr_rig_rebind - go on from the rig's state with the parameters p: after a
 * byte copy of an rr_rig (a co-simulation unit's state saved and restored:
 * the copy still points at the original's parameters), or after parameters
 * changed between samples (a tuned gain, the friction, the adhesion, the
 * creep method's options).  The rig takes p's pointer (p must outlive it),
 * its contact model (checked, a copy), the creep method's facts, the
 * integrator's settings and model and the Jacobian's constant part again,
 * and drops the contact evaluation it keeps; its state, controllers,
 * encoders and workspace go on as they are (a byte copy keeps the
 * original's workspace pointer: set rig->work, rig->work_len to the copy's
 * own before the rebind).
 *   given:   rig, initialised; p
 *   status:  0; rr_rig_check's; RR_ERR_WORKSPACE (p's method needs more
 *            workspace than the rig has); RR_ERR_RANGE (the Jacobian's
 *            constant part overflows); RR_ERR_NULL; the status of a rig
 *            that never started.  On error the rig is unchanged.
 */
int rr_rig_rebind(rr_rig *rig, const rr_rig_params *p);

/*
 * rr_rig_step - one sample: rr_rig_sample, then rr_rig_advance.
 *   given:   rig; roller_ref the roller speed reference [rad/s]; xi_ref the
 *            creepage target (controller's sense, the paper's positive
 *            numbers); when control starts, eq. 15's K is set to the
 *            present speed ratio, and eq. 13-14 move it to each target
 *            from there; xi_ref NaN: no creepage control (the wheelset is
 *            held at free rolling speed)
 *   returns: rec[RR_REC_COUNT], the state at the end of the sample
 *   status:  0, a warning, or an error (wheel off its roller, lift-off,
 *            NaN, a creep force beyond mu N: RR_ERR_FRICTION_LIMIT, for
 *            any method): the rig keeps its last good state and refuses to
 *            step on.
 */
int rr_rig_step(rr_rig *rig, double roller_ref, double xi_ref, double *rec);

/*
 * rr_rig_run - n samples with the references roller_ref[k], xi_ref[k]
 * into the caller's buffer rec[n * RR_REC_COUNT] (row k: sample k).
 *   returns: the number of samples done (n, or fewer: the run stopped at
 *            an error, whose record is row k = returned count); *status the
 *            worst status met (may be NULL); 0 with RR_ERR_PARAM for n < 0,
 *            RR_ERR_NULL for a NULL array (n > 0)
 */
long rr_rig_run(rr_rig *rig, long n, const double *roller_ref, const double *xi_ref,
                double *rec, int *status);

/*
 * rr_rig_sample - the sampling instant alone: encoders read the angles,
 * the creepage controller and the PI controllers set the references the
 * drives hold until the next sample (rr_rig_read and rr_rig_write with
 * rr_rig_command_builtin).  On error nothing changes.
 */
int rr_rig_sample(rr_rig *rig, double roller_ref, double xi_ref);

/*
 * rr_rig_advance - the plant over one sample (nsub fixed steps) with the
 * held references; rec as rr_rig_step.  On error the state is that of the
 * sample's start and the rig refuses to go on (rig->status < 0).
 */
int rr_rig_advance(rr_rig *rig, double *rec);

/* rr_rig_record - the record of the current state (one contact evaluation). */
int rr_rig_record(rr_rig *rig, double *rec);

/*
 * rr_rig_set_state - put the plant at (t, y) (e.g. the end of a sample
 * integrated by another solver, which ends the sample as rr_rig_advance
 * does); the controllers keep their states.
 *   status: 0, RR_ERR_NONFINITE
 */
int rr_rig_set_state(rr_rig *rig, double t, const double *y);

/*
 * rr_rig_rhs - the plant's right-hand side at (t, y) with the rig's held
 * torque references: dydt[RR_RIG_NSTATE]; for verification (e.g. against an
 * adaptive stiff solver between samples).  Contact outputs of the
 * evaluation in rig->pose, rig->w.
 */
int rr_rig_rhs(rr_rig *rig, double t, const double *y, double *dydt);

/* rr_rig_jac - the approximate Jacobian the integrator uses, J[n*n], n = RR_RIG_NSTATE. */
int rr_rig_jac(rr_rig *rig, double t, const double *y, double *J);

/*
 * The rig's full state between samples: everything rr_rig holds from one
 * sample's end to the next that the samples ahead depend on (the plant's
 * vector, the held references and friction law, the PI integrals, the
 * encoders' counters, the creepage controller), in this order, as doubles
 * (a flag or a counter as its whole number).  One list gives the enum
 * (RR_FS_<ID>) and the names (rr_rig_full_state_names).  Left out, as no
 * later sample reads them: the PI's last output (the held torque reference
 * itself), the quantised angles (count 2 pi / counts), the reading of a
 * sample in progress and the rig's caches (of its state: dropped on a set).
 */
#define RR_RIG_FULL_STATE(F)                                                                  \
    F(T, "t", "s", "time")                                                                    \
    F(X, "x", "m", "wheelset longitudinal position")                                          \
    F(Y, "y", "m", "wheelset lateral position")                                               \
    F(YAW, "yaw", "rad", "wheelset yaw angle")                                                \
    F(CHI, "chi", "rad", "wheelset spin angle (unwrapped)")                                   \
    F(THETA_R, "theta_r", "rad", "roller angle (unwrapped)")                                  \
    F(VX, "vx", "m/s", "wheelset longitudinal velocity")                                      \
    F(VY, "vy", "m/s", "wheelset lateral velocity")                                           \
    F(YAW_RATE, "yaw_rate", "rad/s", "wheelset yaw rate")                                     \
    F(SPIN, "spin", "rad/s", "wheelset angular speed")                                        \
    F(ROLLER_SPIN, "roller_spin", "rad/s", "roller angular speed")                            \
    F(T_ROLLER, "torque_roller", "N m", "roller drive torque (the lag's output)")             \
    F(T_WHEELSET, "torque_wheelset", "N m", "wheelset drive torque (the lag's output)")       \
    F(Z_REF, "z_ref", "m", "axle height at which the vertical springs carry the preload")     \
    F(TREF_ROLLER, "torque_ref_roller", "N m", "roller torque reference held")                \
    F(TREF_WHEELSET, "torque_ref_wheelset", "N m", "wheelset torque reference held")          \
    F(MU0, "mu0", "-", "friction law held over the sample: static coefficient")               \
    F(FRICTION_A, "friction_A", "-", "its falling law's A")                                   \
    F(FRICTION_B, "friction_B", "s/m", "its falling law's B")                                 \
    F(CREEP_CONTROL, "creep_control", "-", "1 while eq. 13-14 steer the wheelset, else 0")    \
    F(XI_REF, "xi_ref", "-", "creepage target (finite with creep_control 1, else NaN)")       \
    F(ROLLER_PI_INTEGRAL, "roller_pi_integral", "N m", "roller PI's integral term")           \
    F(ROLLER_PI_SATURATED, "roller_pi_saturated", "-", "its limiter at the last update: "     \
      "-1, 0, 1")                                                                             \
    F(WHEELSET_PI_INTEGRAL, "wheelset_pi_integral", "N m", "wheelset PI's integral term")     \
    F(WHEELSET_PI_SATURATED, "wheelset_pi_saturated", "-", "its limiter: -1, 0, 1")           \
    F(ROLLER_COUNT, "roller_count", "-", "roller encoder's counter (a whole number)")          \
    F(ROLLER_ENC_SPEED, "roller_enc_speed", "rad/s", "its last speed estimate")               \
    F(ROLLER_ENC_PRIMED, "roller_enc_primed", "-", "1 once it has a count to difference")     \
    F(WHEELSET_COUNT, "wheelset_count", "-", "wheelset encoder's counter (a whole number)")   \
    F(WHEELSET_ENC_SPEED, "wheelset_enc_speed", "rad/s", "its last speed estimate")           \
    F(WHEELSET_ENC_PRIMED, "wheelset_enc_primed", "-", "1 once it has a count")               \
    F(CREEPCTL_K, "creepctl_K", "-", "eq. 15's coefficient K, >= 0")                          \
    F(CREEPCTL_W_REF, "creepctl_w_ref", "rad/s", "wheelset speed reference (NaN while the "   \
      "wheelset's torque is commanded)")                                                      \
    F(CREEPCTL_XI_EST, "creepctl_xi_est", "-", "eq. 16's estimate at the last update")        \
    F(CREEPCTL_DXI, "creepctl_dxi", "-", "the target's error at the last update")

#define RR_FS_ENUM_(id, name, unit, meaning) RR_FS_##id,
enum rr_rig_full_state_index {
    RR_RIG_FULL_STATE(RR_FS_ENUM_)
    RR_FS_COUNT
};

/* rr_rig_full_state_len - RR_FS_COUNT, the full state's length. */
int rr_rig_full_state_len(void);

/* rr_rig_full_state_names, _units - the names and units of the full state,
 * arrays of rr_rig_full_state_len() strings in the order of the enum. */
const char *const *rr_rig_full_state_names(void);
const char *const *rr_rig_full_state_units(void);

/*
 * rr_rig_get_full_state - the rig's full state at a sample's end.
 *   given:   rig at a sample's boundary (after rr_rig_init, rr_rig_advance or
 *            a set; not between rr_rig_read and rr_rig_advance)
 *   returns: v[RR_FS_COUNT]
 *   status:  0; RR_ERR_SEQUENCE (a sample in progress); RR_ERR_NULL; the
 *            status of a rig that never started.  On error v is NaN.  A rig
 *            that refused to step on still gives its (last good) state.
 */
int rr_rig_get_full_state(const rr_rig *rig, double *v);

/*
 * rr_rig_set_full_state - put the rig at the full state v (a checkpoint
 * restored, a state perturbed for a linearisation): the samples from there
 * are bit for bit those that followed where v was taken (same parameters).
 *   given:   rig initialised, at a sample's boundary; v[RR_FS_COUNT]
 *   status:  0 or the plant's warning at v; RR_ERR_NONFINITE (a value NaN
 *            or infinite, but xi_ref NaN without creepage control and
 *            creepctl_w_ref NaN without it); RR_ERR_PARAM (a flag not one
 *            of its values, a counter not a whole number below 2^53, K < 0,
 *            xi_ref NaN with creep_control 1 or a number with 0,
 *            creepctl_w_ref NaN with creep_control 1); the friction law's
 *            check; the contact's error at the plant state (a wheel off its
 *            roller, lift-off); RR_ERR_SEQUENCE; RR_ERR_NULL.  On error
 *            nothing changes.  A set clears a refusal to step on (the rig
 *            goes on from v).
 */
int rr_rig_set_full_state(rr_rig *rig, const double *v);

/* Not API: what the sampled side (rr_rig.c) and the plant (rr_rig_plant.c)
 * take from each other.  rr_rig_usable: 0 if the rig can step, else the
 * failed rr_rig_init's status, or RR_ERR_NULL for a rig never initialised
 * (e.g. zeroed memory).  rr_rig_schedule_law: the adhesion schedule's law
 * at time t (p->contact.friction without points).  rr_rig_bind: what the
 * rig takes from its (checked) parameters besides its state: their pointer,
 * the contact model checked once (a copy, rr_rig_contact_bind with the
 * rig's workspace; its status where that refuses it, nothing changed), the
 * creep method's facts, the
 * integrator's settings and model, the
 * Jacobian's constant part; the contact evaluation it keeps is dropped;
 * RR_ERR_RANGE (nothing changed) where the constant part overflows (a
 * stiffness over a near-zero mass). */
int rr_rig_usable(const rr_rig *rig);
rr_friction rr_rig_schedule_law(const rr_rig_params *p, double t);
int rr_rig_bind(rr_rig *rig, const rr_rig_params *p);

#endif
