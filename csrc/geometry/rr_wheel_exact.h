/*
 * rr_wheel_exact.h - one wheel of the rig solved by Kalker's exact theory
 * on its own non-Hertzian patch: the undeformed distance from the profiles
 * (rr_gap.h), the load along the patch's normal or the wheel's vertical
 * load, the creepages from the wheelset's and the roller's rigid motions,
 * the exact solver (rr_exact.h).  rollerrig.rig_exact is this function
 * (rollerrig/rig/exact.py says the same at length).
 *
 * The steps (CONTACT's, and rig_exact's since it was written in Python):
 *   - the approach: passes = 2, a first solve on a coarse grid (n/2
 *     across, elements twice dx, dy where those are given) at the zero-gap
 *     pose with the rigid contact point's plane, sized from Hertz's approach
 *     at the contact point (or the approach given); passes = 1, Hertz's (or
 *     the one given);
 *   - the patch at the loaded pose (the wheelset lowered from its zero-gap
 *     height by the approach over cos(delta), delta the rigid contact
 *     point's: the load moves the wheelset vertically, as CONTACT's), its
 *     reference CONTACT's weighted one at that approach, covering where
 *     h <= 1.1 times it (1.03 on elements of given dx, dy: they stand on
 *     the same lattice whatever the cover); a contact that reaches the
 *     grid's edge, or an
 *     approach beyond what the grid covers, is solved again on a grid
 *     sized from the approach found (cover 1.3), at most four times;
 *   - the vertical load Fz: N iterated on that grid until the contact
 *     force's vertical component N n_z + fy t2_z is Fz to the solver's
 *     tolerance tol, at least 1e-7 (a secant on the fixed point
 *     N = (Fz - fy t2_z)/n_z), then, where the approach found differs from
 *     the one the grid was built for by more than 1 %, the patch rebuilt at
 *     the pose of the load found and the balance solved again on it (such
 *     a grid is left once its balance is within 1e-3 of Fz; within
 *     1 % the grid is kept: on CONTACT's 72 roller cases that moved the
 *     forces by 2.8e-4 mu N at most on 0.4 mm elements, 1.2e-3 on n = 40,
 *     whose elements follow the approach in size, and their departures from
 *     CONTACT's not at all, for a third fewer patches and solves).
 * Creepages: given (at the patch's reference point, in its frame), or
 * Kalker's from the rigid motions: the slip of the wheel's material point
 * at P - pen n (CONTACT's Q: pen the pose's interpenetration along n; the
 * wheelset's centre lowered with the pose) relative to the roller's at P,
 * over the rolling speed (at least vmin).  The frame is rollerrig.rig_contact's
 * at zero yaw and longitudinal shift: fx, fy, mz on the wheel along t1, t2,
 * about n at P.
 *
 * Each solve on the loaded grids after the first starts from the last
 * one's solution (rr_exact_solve_from: on the same grid as it is, onto a
 * rebuilt grid interpolated at the same points of the rig), N changing by
 * under 1 % from step to step: on CONTACT's 72 roller cases (0.4 mm) such
 * a solve takes 5.5 normal and 7 tangential products on average (2 to 18)
 * where one from the solver's own starts takes 17 and 18.  (The coarse
 * pass's pressure, on elements twice as large, starts the loaded grid worse
 * than the solver's own start: that solve starts cold.)
 * The results are the cold starts' to the solver's tolerance (cold_start
 * gives those, rebuilds the grid at the load found whatever the approach's
 * change and balances the load to 1e-7: the doubles before the savings).
 *
 * No allocation: the caller's workspace (rr_wheel_exact_workspace_len for
 * the largest grid it allows, zero-filled before its first use, as the
 * solver's), h buffer and fields; a grid beyond them is RR_ERR_WORKSPACE
 * with the sizes needed, before anything is written past them.  The
 * workspace keeps the kernel spectra of the coarse pass's grid, of the
 * loaded grid and of the contact's box from call to call (each in its own
 * share, keyed by its sizes): the next call of a sweep, whose grids often
 * have the same sizes, builds none of them again.  Pass it unchanged
 * between calls, or zero-filled; h_len and field_len may change from call
 * to call (they move the shares: the workspace remembers how the last call
 * carved it, and a call carved otherwise builds what it keeps anew).
 */
#ifndef RR_WHEEL_EXACT_H
#define RR_WHEEL_EXACT_H

#include <stddef.h>
#include "contact/rr_exact.h"
#include "geometry/rr_creepage.h"
#include "geometry/rr_geometry.h"
#include "geometry/rr_gap.h"

typedef struct {
    const rr_wheel_roller *pair;  /* this wheel's side: profiles and placement */
    double y_ws;                  /* the wheelset's lateral shift [m] */
    rr_wheelset_pose pose0;       /* rr_wheelset_contact's zero-gap pose at y_ws */
    rr_contact_point point;       /* and this side's contact point there */
    double N, Fz;                 /* the normal load [N], or (N = 0) the vertical load [N] */
    double E, nu;                 /* both bodies' modulus [Pa] and Poisson ratio */
    double mu;                    /* Coulomb friction */
    int creep_given;              /* 1: cx, cy, cphi; 0: from the motions */
    double cx, cy, cphi;          /* [-], [-], [rad/m] */
    rr_motion wheelset;           /* the wheelset's rigid motion at the zero-gap pose (c its
                                     centre; rr_rig_kinematics' pose c, v, w) */
    double roller_spin;           /* the rollers' angular speed [rad/s] (their angular
                                     velocity -roller_spin Y, about the axis Z = -R0) */
    double vmin;                  /* least rolling speed for the creepages [m/s], > 0 */
    rr_gap_opts gap;              /* the patch: reference, n, dx, dy, combine; approach (0:
                                     Hertz's) and cover of the first (or only) estimate */
    double z, roll;               /* NaN: the pose's (loaded or zero-gap); else these */
    int loaded;                   /* 1: h at the loaded pose; 0: at the zero-gap one */
    int passes;                   /* 1 or 2 (above) */
    double tol;                   /* the solver's (rr_exact_problem) */
    int maxit;
    double spin_shift;
    const rr_interrupt *interrupt;
    int cold_start;               /* 0: every solve after the first starts from the last
                                     solution (rr_exact_solve_from; mapped onto a new
                                     grid; a grid kept within 1 % of the approach
                                     found, the balance to tol); 1: each from the
                                     solver's own starts, the grid always rebuilt, the
                                     balance to 1e-7 (the doubles before) */
} rr_wheel_exact_problem;

/* rollerrig.rig_exact's defaults: N = Fz = 0 (the caller's), E 2.1e11,
 * nu 0.28, creepages given (0), vmin 1e-3, rr_gap_opts_default, z and
 * roll NaN, loaded, two passes, tol 1e-6, maxit 5000, spin_shift 1/6, warm
 * starts (cold_start 0). */
void rr_wheel_exact_default(rr_wheel_exact_problem *pb);

/* Why a solve failed (rr_wheel_exact_result.why). */
enum rr_wheel_exact_why {
    RR_WHEEL_EXACT_OK = 0,
    RR_WHEEL_EXACT_GAP = 1,      /* the patch could not be built: patch.why says why */
    RR_WHEEL_EXACT_HERTZ = 2,    /* Hertz's approach at the contact point (its status) */
    RR_WHEEL_EXACT_SOLVE = 3,    /* the exact solver (its status; N, cx, cy, cphi the case's) */
    RR_WHEEL_EXACT_EDGE = 4,     /* the contact keeps reaching the grid's edge */
    RR_WHEEL_EXACT_SETTLE = 5,   /* the normal load for Fz did not settle */
    RR_WHEEL_EXACT_CREEP = 6     /* the creepages (rr_creepage's status) */
};

typedef struct {
    rr_exact_result sol;     /* the final case's solution */
    rr_gap_patch patch;      /* its patch: grid, frame, regions (h in the caller's buffer) */
    double cx, cy, cphi, V;  /* creepages used [-], [-], [rad/m], rolling speed [m/s] (0
                                where the creepages were given) */
    double N;                /* normal load [N] */
    double force[3];         /* the contact force on the wheel, rig frame: fx t1 + fy t2 +
                                fn n [N] */
    double z, roll;          /* the pose h was built at */
    double lowered;          /* how far that lies below the zero-gap height [m] */
    double approach, cover;  /* what the final grid was sized for */
    int passes;              /* grids solved */
    int builds;              /* patches built */
    int why;                 /* rr_wheel_exact_why of a failure */
    int fail_pass;           /* 1 if the failure was the first, coarse pass's */
    double fail_N;           /* the load of the failing build or solve */
    size_t need;             /* RR_ERR_WORKSPACE: doubles of workspace the grid needs */
} rr_wheel_exact_result;

/* Doubles of workspace for grids up to mx x my (the profile samples, the
 * solver's for the loaded grids and a third more for the coarse pass's,
 * the last solution and its map onto the next grid); 0 if pb is
 * NULL, its element sizes invalid or a size outside [1, RR_EXACT_MAX_GRID]. */
size_t rr_wheel_exact_workspace_len(const rr_wheel_exact_problem *pb, int mx, int my);

/*
 * rr_wheel_exact - the wheel solved as above.
 *   given:   pb; work of work_len doubles (zero-filled before its first
 *            use); h of h_len doubles; field (may be NULL) with arrays of
 *            field_len values each (NULL ones not wanted)
 *   returns: *res; h and field of the final grid (res->patch.grid: row j
 *            at j mx)
 *   status:  0 OK, RR_WARN_NOT_CONVERGED (a solve hit maxit); errors with
 *            res->why: RR_ERR_NULL, RR_ERR_NONFINITE, RR_ERR_LOAD (N and Fz
 *            both or neither positive), RR_ERR_MATERIAL, RR_ERR_FRICTION,
 *            RR_ERR_SPEED (vmin), RR_ERR_PARAM (passes, the gap's options),
 *            RR_ERR_WORKSPACE (a grid beyond work, h or field: res->need and
 *            res->patch.grid say what it needs), the statuses of
 *            rr_gap_build (why GAP), rr_hertz (HERTZ), rr_exact_solve
 *            (SOLVE), rr_creepage's (CREEP), RR_ERR_RANGE (why EDGE,
 *            SETTLE), RR_ERR_INTERRUPTED.
 */
int rr_wheel_exact(const rr_wheel_exact_problem *pb, double *work, size_t work_len, double *h,
                   size_t h_len, const rr_exact_field *field, size_t field_len,
                   rr_wheel_exact_result *res);

#endif
