/*
 * rr_rig_params.h - the declaration of the rig's parameters, its scenario
 * and its outputs: the one source of their names, units, defaults, ranges
 * and origins.
 *
 * rr_rig_param_at(i) walks a const table with one row per parameter of the
 * seed paper's rig (Bosso et al., the Politecnico di Torino 1/5 roller rig):
 * its name as in rollerrig/data/rig_default.toml ("wheelset.mass_kg"), unit,
 * type, default (as a number and as TOML text), range, origin (where the
 * value comes from: "paper ...", "scaled ...", "cited ...", "choice ...")
 * and where it lands in rr_rig_config, the flat struct of primary values.
 * rollerrig/data/rig_default.toml is generated from this table (the Python
 * binding exports it; tests/test_rig_params.py checks that the shipped file
 * is current); docs/parameters.md gives the derivations.
 *
 * From primary values to the rig: rr_rig_params_from derives rr_rig_params
 * (spin inertia plus drive inertia, E* and G from E and nu, the creepage
 * controller's sense, the friction law's A and B, ...).  A C program gets
 * the paper's rig with
 *
 *     rr_rig_config c;  rr_rig_geometry g;  rr_rig_params p;
 *     rr_rig_config_default(&c);                 (the paper's values, 4 ms)
 *     rr_rig_geometry_from(&c, &g);
 *     rr_rig_table_build(&g, data, ..., work, ..., &t, NULL);   (rr_tables.h)
 *     rr_rig_params_from(&c, &t, &p);            (table, calibrated radii)
 *     rr_rig_init(&p, c.roller_speed / c.roller_radius, work, rr_rig_workspace_len(&p),
 *                 &rig);                         (work NULL where that is 0)
 *
 * (examples/rig_paper.c runs the paper's scenario so, bitwise as
 * rollerrig.simulate()), or rr_rig_params_default(&p) and then
 * rr_rig_params_set_table(&p, &t).
 *
 * or, to change a value first, rr_rig_config_default, rr_rig_config_set*,
 * rr_rig_params_from.  On real profiles (wheelset.profile, roller.profile
 * and their _right rows set to "points"), the caller gives the points:
 *
 *     rr_rig_config_set_choice(&c, "wheelset.profile", "points");  (and the roller's)
 *     rr_rig_geometry_from(&c, &g);
 *     rr_rig_profiles_from(&c, &pr);              (scales, gauge; the slots to give)
 *     pr.wheel = wheel_points;  pr.roller = roller_points;        (rr_tables.h)
 *     rr_rig_table_build_profiles(&g, &pr, data, ..., work,
 *                                 rr_rig_profiles_work_len(&pr), &t, NULL);
 *
 * and goes on as above (examples/rig_paper.c takes them as files).  The scenario (roller speed, targets and their start
 * times, duration, sample time) is part of rr_rig_config: rr_rig_samples
 * and rr_rig_schedule give the paper's run sample by sample.
 *
 * Rows flagged creep (contact.creep_method, fastsim_*, polach_kA, kS) are the
 * creep-force method and its options: declared here with their defaults and
 * origins, but checked and applied through rr_creep_opts (rr_creep.h), not
 * through rr_rig_config.  Each creep row but contact.creep_method declares
 * the method's option it sets (its option column: contact.fastsim_nx sets
 * "nx"), given to the chosen method where it has that option; the C rig's
 * default method, the FMU's creep variables and rollerrig.rig read it there.
 *
 * Statuses: RR_ERR_NULL for a NULL pointer, RR_ERR_PARAM for an unknown name,
 * a value of the wrong type (a fraction for an integer, an unknown choice,
 * a creep row given to rr_rig_config_set*) or out of its range,
 * RR_ERR_NONFINITE for NaN or an infinity.  Nothing here allocates or keeps
 * state.
 */
#ifndef RR_RIG_PARAMS_H
#define RR_RIG_PARAMS_H

#include <stddef.h>
#include "rig/rr_rig.h"
#include "geometry/rr_tables.h"

enum rr_rig_param_type {
    RR_RIG_REAL = 0,   /* a finite double in [lo, hi] (ends open if lo_open, hi_open) */
    RR_RIG_INT,        /* an integer in [lo, hi], stored as int */
    RR_RIG_FLAG,       /* 0 (false) or 1 (true), stored as int */
    RR_RIG_CHOICE,     /* one of choices[] by index, stored as int */
    RR_RIG_LIST        /* 1 to RR_RIG_MAX_LIST doubles (0 to it where the default is
                          empty), each in [lo, hi], an rr_rig_list */
};

#define RR_RIG_MAX_LIST RR_RIG_MAX_SCHEDULE

typedef struct {
    int n;
    double v[RR_RIG_MAX_LIST];
} rr_rig_list;

/* The primary values of the rig and its scenario, one member per row. */
typedef struct {
    /* scenario */
    double roller_speed;        /* roller surface speed [m/s] */
    rr_rig_list targets;        /* creepage targets (magnitudes) */
    rr_rig_list target_start;   /* their start times [s] */
    double duration;            /* [s] */
    double mu0;
    int drive_mode;             /* index: braking, traction */
    double T;                   /* control sample time [s] */
    double g;                   /* [m/s^2] */
    int track;                  /* 1: the wheelset on tangent track (rr_rig.h, track) */
    /* wheelset */
    double mass, spin_inertia, yaw_inertia, wheel_radius, contact_half_spacing,
        axlebox_half_spacing;
    int wheel_profile;          /* index: conical, points */
    int wheel_profile_right;    /* index: "" (the left's), points */
    double wheel_scale, conicity, profile_half_width;
    int gyroscopic;             /* 1: the spinning wheelset's gyroscopic moments (rr_rig.h) */
    /* roller */
    double roller_radius;
    int roller_profile;         /* index: crowned cylinder, points */
    int roller_profile_right;   /* index: "" (the left's), points */
    double roller_scale, gauge, crown_radius, roller_inertia;
    /* suspension, per axle box; preload of both boxes */
    double kx, ky, kz, cx, cy, cz, preload;
    /* contact */
    double E, nu;
    int friction_law;           /* index: polach_falling, coulomb */
    double polach_A, polach_B, vmin;
    /* drives */
    double roller_kp, roller_ki, roller_tmax, roller_tau;
    int roller_counts;
    double wheelset_kp, wheelset_ki, wheelset_tmax, wheelset_tau;
    int wheelset_counts;
    double drive_inertia;
    /* creepage controller */
    double ctl_alpha, ctl_beta, ctl_vmin;
    /* integration */
    int ode_method;             /* index: trbdf2, ros2, lineuler */
    int newton_iterations, linear_first_stage, newton_model, substeps;
    double table_half_range;
    int table_rows;
    double profile_smoothing;   /* read by the file readers (rollerrig), not by the C rig */
    /* adhesion: the schedule's lists (A, B empty: the contact's), the patch */
    rr_rig_list schedule_t, schedule_mu0, schedule_A, schedule_B;
    double patch_start, patch_length, patch_mu0, patch_A, patch_B, patch_edge;
    int patch_rollers;          /* index: both, left, right */
    /* disturbance: a lateral force in time */
    rr_rig_list lateral_t, lateral_f;
    /* the contact's patch (issue 24): index hertz, nonhertz; the non-Hertzian
     * table's source ("" built, "file") and build settings, read by rollerrig
     * (a C caller gives the tables: rr_rig_params_set_nonhertz) */
    int contact_patch;
    int nonhertz_table;
    double nonhertz_half_range, nonhertz_row_spacing;
    int nonhertz_elements;
} rr_rig_config;

typedef struct {
    const char *name;           /* "section.key" of rig_default.toml */
    const char *unit;           /* "-" dimensionless, "" for a name or a flag */
    int type;                   /* enum rr_rig_param_type */
    double value;               /* default: REAL, INT, FLAG (0, 1), CHOICE (index) */
    const char *text;           /* the default as TOML text */
    double lo, hi;              /* range of REAL, INT and of each LIST entry */
    int lo_open, hi_open;
    const char *const *choices; /* CHOICE: the names, NULL-terminated */
    const double *list;         /* LIST: the default entries */
    int nlist;
    long offset;                /* of the member in rr_rig_config; -1 for a creep row */
    int creep;                  /* 1: the creep-force method or an option of it (see above) */
    const char *option;         /* a creep row's option of the method ("nx"); NULL for
                                   contact.creep_method and every other row */
    const char *origin;         /* where the default comes from */
} rr_rig_param;

/* A section of the parameter file: its name and a note on all its rows. */
typedef struct {
    const char *name;
    const char *note;           /* "" when none */
} rr_rig_section;

/* A key the parameters no longer have (it acted on nothing), and why. */
typedef struct {
    const char *name;           /* "section.key", or a whole "section" */
    const char *reason;
} rr_rig_retired;

/* A named output: record fields (RR_REC_*), the per-wheel contact block. */
typedef struct {
    const char *name;
    int width;                  /* consecutive doubles: 1, or 3 for a vector */
    long offset;                /* of the member in rr_wheel_contact (wheel fields; -1 else) */
    const char *unit;
    const char *meaning;
} rr_rig_field;

/* The tables: count and row i (NULL out of range), row by name (NULL if unknown). */
int rr_rig_param_count(void);
const rr_rig_param *rr_rig_param_at(int i);
const rr_rig_param *rr_rig_param_find(const char *name);
int rr_rig_section_count(void);
const rr_rig_section *rr_rig_section_at(int i);
int rr_rig_retired_count(void);
const rr_rig_retired *rr_rig_retired_at(int i);

/* rr_rig_param_choice - the index of `choice` among a CHOICE row's names, or -1. */
int rr_rig_param_choice(const rr_rig_param *row, const char *choice);

/* rr_rig_config_default - every member at its row's default.  RR_ERR_NULL. */
int rr_rig_config_default(rr_rig_config *c);

/*
 * rr_rig_config_set - set the REAL, INT, FLAG or CHOICE (by index) row `name`
 * to v, checked against its range; rr_rig_config_set_choice a CHOICE row by
 * name; rr_rig_config_set_list a LIST row to v[0..n-1].  On error nothing
 * changes.
 */
int rr_rig_config_set(rr_rig_config *c, const char *name, double v);
int rr_rig_config_set_choice(rr_rig_config *c, const char *name, const char *choice);
int rr_rig_config_set_list(rr_rig_config *c, const char *name, int n, const double *v);

/* What a problem of rr_rig_config_report breaks (rr_rig_problem.rule; there). */
enum rr_rig_rule {
    RR_RIG_RULE_RANGE = 0, RR_RIG_RULE_COUNT, RR_RIG_RULE_INCREASING, RR_RIG_RULE_NONDECREASING,
    RR_RIG_RULE_BEFORE, RR_RIG_RULE_SAMPLE, RR_RIG_RULE_CIRCUMFERENCE, RR_RIG_RULE_LOOP,
    RR_RIG_RULE_SUM
};

/* One problem of a configuration: the row at fault and what it breaks. */
typedef struct {
    const char *key;            /* the row's name (static storage) */
    const char *other;          /* the other row of a rule between two, or NULL */
    int status;                 /* RR_ERR_PARAM, RR_ERR_NONFINITE (a NaN or infinity in a
                                   range), RR_ERR_RANGE (SUM) */
    int rule;                   /* enum rr_rig_rule */
    int entry;                  /* a list's entry (from 0), LOOP's drive, or -1 */
    double value;               /* the value at fault (see the rules) */
    double lo, hi;              /* the bounds it breaks (see the rules) */
} rr_rig_problem;

/* Most problems one configuration can have: one per row and one per rule
 * (checked where the table is declared). */
#define RR_RIG_MAX_PROBLEMS 128

/*
 * rr_rig_config_report - every problem of c, each with its row, status and
 * rule, in the order of the rows, then of the rules between them:
 * each row out of its range (one problem per row: a list's first entry at
 * fault), then the scenario (one start time per target, increasing, the
 * last before the duration; at least one sample in the duration), the
 * adhesion (one mu0 per schedule time, one A and B each or none, the times
 * non-decreasing; the patch no longer than the roller's circumference), the
 * drives' sampled speed loops stable at the sample time
 * (rr_rig_config_speed_loops), the wheelset's inertia with its drive's
 * finite.  A rule is judged only where the rows it reads are in range (a
 * bad list is not also miscounted).  The first cap problems go to out[]
 * (caller memory; RR_RIG_MAX_PROBLEMS always suffice).
 *   returns: the number of problems (0: c is a rig), which may exceed cap
 *   status:  RR_ERR_NULL (c NULL, or out NULL with cap > 0)
 * Each problem's rule, and what its value, other row and bounds are then:
 *   RANGE          the row's own range: a scalar's value (an INT or FLAG
 *                  that is not a whole number, a CHOICE's index out of its
 *                  names) with lo, hi its range (a CHOICE 0 .. names - 1);
 *                  a LIST's entry `entry` with lo, hi the entries' range, or
 *                  with entry -1 its length (value) outside lo .. hi entries
 *   COUNT          one entry per entry of `other`: value the row's entries,
 *                  hi other's; lo 0 where none would do too (the schedule's
 *                  A and B), else NaN
 *   INCREASING     the entries increase (scenario.target_start_s): entry the
 *                  first that does not, value it
 *   NONDECREASING  the entries do not decrease (adhesion.schedule_times_s)
 *   BEFORE         the last entry before `other`, the duration: value the
 *                  entry, hi the duration
 *   SAMPLE         at least one sample: value (the duration) >= lo, `other`
 *                  (the sample time), within 1e-9 of it
 *   CIRCUMFERENCE  at most the circumference of `other` (roller.radius_m):
 *                  hi = 2 pi R
 *   LOOP           the sampled speed loop of drive `entry` (0 the roller's,
 *                  1 the wheelset's) is unstable at this sample time (row
 *                  scenario.control_sample_time_s): value its largest pole's
 *                  |z|, lo .. hi the sample times in [RR_RIG_MIN_T,
 *                  RR_RIG_MAX_T] at which it is stable (NaN, NaN: none;
 *                  rr_speed_loop_range); judged where the sample time, the
 *                  inertias, both drives' gains, torque limits and lags and
 *                  creepage_controller.alpha are in range
 *   SUM            the row plus `other` is not a finite double (Iyy, the
 *                  wheelset's inertia with its drive's): value the sum,
 *                  status RR_ERR_RANGE
 */
int rr_rig_config_report(const rr_rig_config *c, rr_rig_problem *out, int cap);

/*
 * rr_rig_config_check - rr_rig_config_report's first problem: 0 if there is
 * none, else its status, and *bad (may be NULL) its row's name.  A speed
 * loop unstable at the sample time is RR_ERR_PARAM with *bad
 * "scenario.control_sample_time_s" (the message's range:
 * rr_rig_config_speed_loops, rr_speed_loop_range).
 */
int rr_rig_config_check(const rr_rig_config *c, const char **bad);

/*
 * rr_rig_config_put - store v in the scalar row `name` as rr_rig_config_set
 * does but unchecked, so that rr_rig_config_report judges it with every
 * other value (the binding's report of a whole parameter set);
 * rr_rig_config_put_list a LIST row's n entries.  A value the member cannot
 * hold is not stored: its status (RR_ERR_PARAM: an INT, FLAG or CHOICE value
 * not a whole number in int's range, more than RR_RIG_MAX_LIST entries or
 * fewer than none; RR_ERR_NONFINITE: NaN or an infinity for an INT, FLAG or
 * CHOICE), with *p (may be NULL) its RANGE problem.  RR_ERR_PARAM for an
 * unknown name, a creep row or a row of the other kind (*p untouched);
 * RR_ERR_NULL.
 */
int rr_rig_config_put(rr_rig_config *c, const char *name, double v, rr_rig_problem *p);
int rr_rig_config_put_list(rr_rig_config *c, const char *name, int n, const double *v,
                           rr_rig_problem *p);

/*
 * rr_rig_config_speed_loops - the drives' sampled speed loops of primary
 * values, as rr_rig_speed_loops gives them for rr_rig_params_from's
 * parameters: for the message of a refused sample time
 * (rr_speed_loop_range over [RR_RIG_MIN_T, RR_RIG_MAX_T]).  No checks of c.
 * Status: RR_ERR_NULL.
 */
int rr_rig_config_speed_loops(const rr_rig_config *c, rr_speed_loop loops[2]);

/*
 * rr_rig_params_from - the rig's parameters of checked primary values:
 * mass, inertias (Iyy = wheelset.spin_inertia + wheelset_drive.drive_inertia),
 * springs, dampers, preload, g; the contact model's R0 = roller.radius_m,
 * E* = E / (2 (1 - nu^2)) and G = E / (2 (1 + nu)) (wheel and roller of one
 * material), mu0, the falling law's A, B (coulomb: A = 1, B = 0), vmin; the
 * adhesion's schedule and patch (rr_rig_adhesion; coulomb: A = 1, B = 0
 * there too); the sample time T of the PI controllers and encoders; the
 * integrator; the
 * creepage controller (sense from scenario.drive_mode) with the nominal
 * radii wheelset.wheel_radius_m, roller.radius_m; the creep-force method at
 * the rows' defaults (FASTSIM, contact.fastsim_nx x fastsim_ny, rigid slip
 * speed): set p->contact.creep afterwards for another method.  With t not
 * NULL, rr_rig_params_set_table(p, t) follows.  Status: rr_rig_config_check's
 * (p zeroed), RR_ERR_RANGE (p zeroed: a derived value overflows, e.g. the
 * sum of two inertias each near DBL_MAX), RR_ERR_NULL.
 */
int rr_rig_params_from(const rr_rig_config *c, const rr_contact_table *t, rr_rig_params *p);

/*
 * rr_rig_params_set_table - the contact table the rig reads, and eq. 15-16's
 * radii r_w, r_r at the centred wheelset's rolling radii (a calibrated rig):
 * the table's row at y = 0.  Status of the lookup; RR_ERR_NULL.
 */
int rr_rig_params_set_table(rr_rig_params *p, const rr_contact_table *t);

/*
 * rr_rig_params_set_nonhertz - the non-Hertzian contact's tables the rig
 * reads on contact.patch = "nonhertz" (rr_rig_contact.h, Patch): left
 * (sigma +1) and right (sigma -1), the caller's (they must outlive p; built
 * for the rig's profiles, scale, roller radius and material: rollerrig's
 * rig_nonhertz_table, or rr_nonhertz_row per row), checked at rr_rig_init.
 * Status: RR_ERR_NULL.
 */
int rr_rig_params_set_nonhertz(rr_rig_params *p, const rr_nh_table *left,
                               const rr_nh_table *right);

/*
 * rr_rig_params_default - the paper's rig at the defaults (sample time
 * scenario.control_sample_time_s, 4 ms): rr_rig_params_from of the default
 * config with no table.  The caller must then give the contact table:
 * rr_rig_params_set_table (p->contact.table is NULL, and r_w, r_r the
 * nominal radii, until then).  For another sample time set it in an
 * rr_rig_config and use rr_rig_params_from (T is also in the PI and encoder
 * parameters).  Status: RR_ERR_NULL.
 */
int rr_rig_params_default(rr_rig_params *p);

/*
 * rr_rig_geometry_from - the geometry of the rig's contact table
 * (rr_rig_table_build): radii, profile half width, cone angle
 * atan(wheelset.conicity), crown, contact half spacing, table half range and
 * rows.  Status: RR_ERR_NULL.
 */
int rr_rig_geometry_from(const rr_rig_config *c, rr_rig_geometry *g);

/*
 * rr_rig_profiles_from - the real profiles' settings of c for
 * rr_rig_table_build_profiles (rr_tables.h): the scales
 * (wheelset.profile_scale, roller.profile_scale) and the gauge
 * (roller.gauge_m); each slot n = 0 where its row names the analytic
 * profile (or, for a _right row, ""), n = -1 where it says "points": the
 * caller then sets the slot's points (until then rr_rig_profiles_check
 * answers RR_ERR_NULL for it).  No checks of c.  Status: RR_ERR_NULL.
 */
int rr_rig_profiles_from(const rr_rig_config *c, rr_rig_profiles *pr);

/* rr_rig_samples - samples of the scenario: round(duration / T), at least 1; 0 for NULL. */
long rr_rig_samples(const rr_rig_config *c);

/*
 * rr_rig_schedule - the references of sample k (which starts at t = k T):
 * roller_ref = roller_speed / roller_radius [rad/s]; xi_ref = the target of
 * the last start time <= t, NaN before the first (no creepage control), as
 * rollerrig.rig.schedule.  Status: RR_ERR_NULL, RR_ERR_PARAM for k < 0,
 * RR_ERR_RANGE (both NaN) where roller_ref overflows (a radius near 0).
 */
int rr_rig_schedule(const rr_rig_config *c, long k, double *roller_ref, double *xi_ref);

/* The record fields of rr_rig_step, in the order of enum rr_rig_record_index. */
const rr_rig_field *rr_rig_record_field(int i);   /* NULL unless 0 <= i < RR_REC_COUNT */

/*
 * The per-wheel contact block: the rr_wheel_contact members a caller (the
 * binding) stores as RR_WHEEL_NVALUES consecutive doubles, field by field
 * (offset, width).  One list gives the fields and both counts:
 * RR_WHEEL_FIELDS(F) calls F(name, width, member, unit, meaning) once per
 * field, member the rr_wheel_contact member it reads.
 */
#define RR_WHEEL_FIELDS(F)                                                                    \
    F("p", 3, frame.p, "m", "contact point in the rig")                                       \
    F("theta", 1, theta, "rad", "its angle round the roller axis from the top")               \
    F("t1", 3, frame.t1, "-", "rolling direction (unit, rig frame)")                          \
    F("t2", 3, frame.t2, "-", "lateral direction in the contact plane")                       \
    F("n", 3, n, "-", "normal t1 x t2, into the wheel")                                       \
    F("cx", 1, creep.cx, "-", "longitudinal creepage")                                        \
    F("cy", 1, creep.cy, "-", "lateral creepage")                                             \
    F("cphi", 1, creep.cphi, "rad/m", "spin creepage")                                        \
    F("V", 1, creep.V, "m/s", "rolling speed used for the creepages")                         \
    F("N", 1, N, "N", "normal load")                                                          \
    F("a", 1, hertz.a, "m", "contact ellipse semi-axis along t1")                             \
    F("b", 1, hertz.b, "m", "contact ellipse semi-axis along t2")                             \
    F("p0", 1, hertz.p0, "Pa", "peak pressure")                                               \
    F("fx", 1, f.fx, "N", "creep force on the wheel along t1")                                \
    F("fy", 1, f.fy, "N", "creep force on the wheel along t2")                                \
    F("mz", 1, f.mz, "N m", "spin moment on the wheel about n")                               \
    F("force", 3, force, "N", "contact force on the wheelset, rig frame")                     \
    F("moment", 3, moment, "N m", "its moment about the wheelset centre")                     \
    F("r", 1, geo.r, "m", "wheel rolling radius")                                             \
    F("R", 1, geo.R, "m", "roller radius at the contact")                                     \
    F("delta", 1, geo.delta, "rad", "contact angle")                                          \
    F("s_wheel", 1, geo.s_wheel, "m", "profile coordinate of the contact point on the wheel") \
    F("s_roller", 1, geo.s_roller, "m", "profile coordinate of the contact point on the "     \
      "roller")

#define RR_WHEEL_ONE_(name, width, member, unit, meaning) +1
#define RR_WHEEL_WIDTH_(name, width, member, unit, meaning) +(width)
#define RR_WHEEL_NFIELDS (0 RR_WHEEL_FIELDS(RR_WHEEL_ONE_))
#define RR_WHEEL_NVALUES (0 RR_WHEEL_FIELDS(RR_WHEEL_WIDTH_))
const rr_rig_field *rr_wheel_field(int i);        /* NULL unless 0 <= i < RR_WHEEL_NFIELDS */

/* rr_wheel_store - the block of w into v[RR_WHEEL_NVALUES]; stride between values. */
void rr_wheel_store(const rr_wheel_contact *w, double *v, long stride);

#endif
