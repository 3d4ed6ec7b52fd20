/*
 * rr_fmu.h - the roller rig as a co-simulation unit, independent of any FMI
 * version: its variables (value references, names, units, descriptions,
 * types, causality, variability, start values and ranges), getting and
 * setting them with range checks, the unit's life (instantiated,
 * initialisation, stepping, terminated, failed), a step over whole control
 * samples, reset, and copies of its state.  The FMI 2.0 and 3.0 adapters
 * (rollerrig/data/fmi/) are thin wrappers over these functions;
 * rr_fmu_xml.h writes the modelDescription.xml of the same variables.
 *
 * Variables, in this order (their value references, "vr", in brackets):
 *   time [0]                   the independent variable [s]
 *   parameters, one per row of the rig's declaration (rr_rig_params.h) in
 *     its order [1000 + row]; a LIST row is one parameter per entry, as
 *     many as the start configuration holds, "scenario.targets[1]", ...
 *     [100000 + 1000 row + entry]; the creep rows (contact.creep_method,
 *     fastsim_nx, ...) with the registry's names and ranges;
 *   control parameters [1 + i]: control.roller_mode (scenario, speed,
 *     torque), control.wheelset_mode (scenario, creepage, speed, torque, free),
 *     control.mu_source (adhesion, input), control.start (rolling, rest);
 *   inputs [100 + i]: roller_speed_ref [rad/s], roller_torque_ref [N m],
 *     creepage_ref [-], wheelset_speed_ref [rad/s], wheelset_torque_ref
 *     [N m], mu [-];
 *   outputs: the rig's record but its time [200 + record index]
 *     (rr_rig_record_field: creepage, xi_est, ..., mu_left, mu_right,
 *     sample_status), the encoders at the present time [300 + i]
 *     (encoder.roller_count, ...), and each wheel's contact block
 *     (rr_wheel_field: left.p[1], ..., left.N, ..., right.s_roller)
 *     [400 + value index, 500 + value index].
 *
 * How the rig is driven at each control sample k (time k T from the start):
 *   roller:   scenario  its PI to rr_rig_schedule's speed (scenario.roller_speed_m_s)
 *             speed     its PI to the input roller_speed_ref
 *             torque    the input roller_torque_ref straight to the drive
 *   wheelset: scenario  the creepage controller to rr_rig_schedule's target
 *             creepage  the creepage controller to the input creepage_ref
 *             speed     its PI to the input wheelset_speed_ref
 *             torque    the input wheelset_torque_ref straight to the drive
 *             free      no creepage control: its PI to free rolling at the
 *                       roller's measured speed (rr_rig_write's NaN target)
 *   friction: adhesion  the [adhesion] schedule and patch (scenario.mu0 without)
 *             input     the input mu as the static coefficient mu0 (a patch
 *                       still applies on top)
 * (rr_rig_write's RR_CMD_BUILTIN, RR_CMD_SPEED, RR_CMD_TORQUE and mu0).  At
 * the defaults (scenario, scenario, adhesion, rolling) a run is
 * rollerrig.simulate()'s of the same parameters, bit for bit: the same
 * rr_rig_read, rr_rig_write, rr_rig_advance as rr_rig_step, with the
 * references of rr_rig_schedule.
 *
 * The inputs are discrete: the rig's controllers sample them at each sample
 * (the references held over it, as a sampled controller does) and a step
 * over several samples holds them over all.
 *
 * Outputs belong to the unit's present time: the record of the last sample
 * (its end), the contact blocks of the same evaluation, and the encoders
 * read at that instant (the next sample's measurement, taken at the end of
 * each step; rr_rig_write then uses it).
 *
 * Variability: the parameters are fixed but those the rig reads afresh at
 * every sample (tunable: the scenario's roller speed, targets and start
 * times, mu0 and the falling law, the PI gains, the creepage controller's
 * alpha, beta and speed floor, the adhesion schedule and patch, and the
 * control modes); a tunable change takes effect at the next step.
 *
 * Memory: the unit allocates two things, the contact table's rows
 * (rr_rig_table_build) and its rig's workspace for the creep method
 * (rr_rig_workspace_len; none for the methods the rig steps with today),
 * through the caller's functions, when it initialises (rr_fmu_exit_init,
 * the outputs asked in initialisation mode, rr_fmu_restore of a state of
 * another geometry or method).  rr_fmu_do_step allocates nothing.  No
 * globals: instances are independent.
 *
 * Statuses (rr_common.h): 0, > 0 a warning, < 0 an error; every error and
 * warning leaves a message in rr_fmu_message(m) naming the variable, value
 * and rule, or the sample and the reason.  RR_ERR_SEQUENCE: a call in the
 * wrong state; RR_ERR_PARAM: an unknown value reference, a variable of
 * another type, a value out of range, a step that is not a whole multiple
 * of the sample time; the rig's own statuses when it cannot start or step.
 */
#ifndef RR_FMU_H
#define RR_FMU_H

#include <stddef.h>
#include "rig/rr_rig_params.h"

/* value references (see above) */
#define RR_FMU_VR_TIME 0u
#define RR_FMU_VR_CONTROL 1u
#define RR_FMU_VR_INPUT 100u
#define RR_FMU_VR_RECORD 200u
#define RR_FMU_VR_ENCODER 300u
#define RR_FMU_VR_WHEEL 400u        /* left; right at + RR_FMU_VR_WHEEL_SIDE */
#define RR_FMU_VR_WHEEL_SIDE 100u
#define RR_FMU_VR_PARAM 1000u
#define RR_FMU_VR_LIST 100000u      /* + RR_FMU_VR_LIST_ROW row + entry */
#define RR_FMU_VR_LIST_ROW 1000u

/* longest message, and longest variable name (with its index) */
#define RR_FMU_MSG_LEN 512
#define RR_FMU_NAME_LEN 96

enum rr_fmu_control {
    RR_FMU_ROLLER_MODE = 0, RR_FMU_WHEELSET_MODE, RR_FMU_MU_SOURCE, RR_FMU_START,
    RR_FMU_NCONTROL
};
enum rr_fmu_roller_mode { RR_FMU_ROLLER_SCENARIO = 0, RR_FMU_ROLLER_SPEED, RR_FMU_ROLLER_TORQUE };
enum rr_fmu_wheelset_mode {
    RR_FMU_WHEELSET_SCENARIO = 0, RR_FMU_WHEELSET_CREEPAGE, RR_FMU_WHEELSET_SPEED,
    RR_FMU_WHEELSET_TORQUE, RR_FMU_WHEELSET_FREE
};
enum rr_fmu_mu_source { RR_FMU_MU_ADHESION = 0, RR_FMU_MU_INPUT };
enum rr_fmu_start { RR_FMU_START_ROLLING = 0, RR_FMU_START_REST };

enum rr_fmu_input {
    RR_FMU_IN_ROLLER_SPEED = 0, RR_FMU_IN_ROLLER_TORQUE, RR_FMU_IN_CREEPAGE,
    RR_FMU_IN_WHEELSET_SPEED, RR_FMU_IN_WHEELSET_TORQUE, RR_FMU_IN_MU,
    RR_FMU_NINPUT
};

/* the encoders' outputs (rr_rig_signals) */
enum rr_fmu_encoder {
    RR_FMU_ENC_ROLLER_COUNT = 0, RR_FMU_ENC_WHEELSET_COUNT, RR_FMU_ENC_ROLLER_ANGLE,
    RR_FMU_ENC_WHEELSET_ANGLE, RR_FMU_ENC_ROLLER_SPEED, RR_FMU_ENC_WHEELSET_SPEED,
    RR_FMU_ENC_XI_EST,
    RR_FMU_NENCODER
};

enum rr_fmu_type { RR_FMU_REAL = 0, RR_FMU_INTEGER, RR_FMU_BOOLEAN, RR_FMU_ENUMERATION };
enum rr_fmu_causality { RR_FMU_INDEPENDENT = 0, RR_FMU_PARAMETER, RR_FMU_INPUT, RR_FMU_OUTPUT };
enum rr_fmu_variability { RR_FMU_CONTINUOUS = 0, RR_FMU_DISCRETE, RR_FMU_FIXED, RR_FMU_TUNABLE };

/* the unit's life */
enum rr_fmu_mode {
    RR_FMU_INSTANTIATED = 0, RR_FMU_INITIALIZATION, RR_FMU_STEPPING, RR_FMU_TERMINATED,
    RR_FMU_FAILED
};

/* the creep rows of the rig's declaration (contact.creep_method, fastsim_nx, ...) */
#define RR_FMU_MAX_CREEP 8

/*
 * The parameters: the rig's primary values, the creep rows' values (in the
 * declaration's order; contact.creep_method as the registry's number, a
 * choice as the index of its name) and the control parameters.
 */
typedef struct {
    rr_rig_config c;
    double creep[RR_FMU_MAX_CREEP];
    int control[RR_FMU_NCONTROL];
} rr_fmu_config;

/* One variable (rr_fmu_var_at, rr_fmu_var_find). */
typedef struct {
    unsigned vr;
    const char *prefix;         /* "" or a wheel's "left." / "right." */
    const char *base;           /* the name, or with entry >= 0 its stem: base[entry + 1] */
    int entry;                  /* -1, or the list entry / vector component (from 0) */
    const char *unit;           /* "" none, "-" dimensionless (the XML's "1") */
    const char *description;
    int type;                   /* enum rr_fmu_type */
    int causality;              /* enum rr_fmu_causality */
    int variability;            /* enum rr_fmu_variability */
    double lo, hi;              /* range of a REAL or INTEGER (-inf, inf: none) */
    int lo_open, hi_open;       /* 1: the end itself is refused */
    /* where it lives (private) */
    int kind, index;
    const rr_rig_param *row;
} rr_fmu_var;

/* Allocation for the contact table, the caller's (the FMI adapter's). */
typedef void *(*rr_fmu_alloc)(void *ctx, size_t bytes);
typedef void (*rr_fmu_free)(void *ctx, void *p);

/* What a saved FMU state holds (rr_fmu_save): everything that changes. */
typedef struct {
    rr_fmu_config cfg;              /* the parameters now */
    double in[RR_FMU_NINPUT];       /* the inputs now */
    rr_rig_params p;                /* the rig's, derived from cfg (valid if ready) */
    rr_rig rig;
    double rec[RR_REC_COUNT];       /* the record of the present time */
    rr_rig_signals sig;             /* the encoders read at the present time */
    long k;                         /* samples done */
    double t0;                      /* the start time [s] */
    int mode;                       /* enum rr_fmu_mode */
    int ready;                      /* p, rig, rec, sig of cfg */
    int retune;                     /* a tunable parameter changed since */
    int failed_status;              /* the status that failed the unit (mode FAILED) */
} rr_fmu_state;

typedef struct {
    rr_fmu_state s;
    rr_fmu_config start;            /* the start values */
    const char *const *type_names;  /* the adapter's names of the four types, for messages */
    /* the contact table of geometry g, its rows in table_data */
    rr_contact_table table;
    rr_rig_geometry g;
    int table_ok;
    double *table_data;
    long table_cap;                 /* doubles allocated */
    double table_work[RR_RIG_TABLE_WORK_LEN];
    /* real profiles: the points the unit was given (rr_fmu_set_profiles; the
     * caller's arrays), those of the table held, their build's workspace */
    rr_rig_profiles points, table_pr;
    double *profile_work;
    long profile_work_cap;              /* doubles allocated */
    /* the non-Hertzian contact's tables the unit was given
     * (rr_fmu_set_nonhertz; their rows the caller's), nonhertz_ok: both held */
    rr_nh_table nonhertz[2];
    int nonhertz_ok;
    /* the rig's workspace for its creep method (rr_rig_workspace_len) */
    double *rig_work;
    size_t rig_work_cap;            /* doubles allocated */
    rr_fmu_alloc alloc;
    rr_fmu_free release;
    void *mem_ctx;
    char msg[RR_FMU_MSG_LEN];
} rr_fmu;

/*
 * rr_fmu_config_default - the rig's defaults (rr_rig_config_default, the
 * creep rows' defaults), controls at scenario, scenario, adhesion, rolling.
 * Status: RR_ERR_NULL.
 */
int rr_fmu_config_default(rr_fmu_config *f);

/*
 * rr_fmu_config_set - set the scalar parameter `name` (a rig row of type
 * REAL, INT, FLAG or CHOICE by index, a creep row - contact.creep_method by
 * the registry's number -, or a control parameter "control.roller_mode"
 * ...) to v, checked against its range; _set_choice by the choice's name;
 * _set_list a LIST row to v[0..n-1] (rr_rig_config_set_list).  On error
 * nothing changes.  Status: RR_ERR_PARAM (unknown name, bad value),
 * RR_ERR_NONFINITE, RR_ERR_NULL.
 */
int rr_fmu_config_set(rr_fmu_config *f, const char *name, double v);
int rr_fmu_config_set_choice(rr_fmu_config *f, const char *name, const char *choice);
int rr_fmu_config_set_list(rr_fmu_config *f, const char *name, int n, const double *v);

/*
 * rr_fmu_creep_opts - the creep-force method and options of f: the method
 * of contact.creep_method, every other creep row given as the option it
 * declares (rr_rig_param.option) where the method has it (as rollerrig.rig
 * does), then rr_creep_opts_check.  *bad (may be NULL): the row at fault.  Status:
 * rr_creep_opts_check's, RR_ERR_METHOD (a method not for a time step).
 */
int rr_fmu_creep_opts(const rr_fmu_config *f, rr_creep_opts *o, const char **bad);

/*
 * The variables of a unit whose start configuration is `start` (the LIST
 * rows give as many variables as it holds entries): their count, the i-th
 * in the order above, and the one of value reference vr.  Status: 0,
 * RR_ERR_PARAM (i out of range, vr unknown), RR_ERR_NULL.
 */
int rr_fmu_var_count(const rr_fmu_config *start);
int rr_fmu_var_at(const rr_fmu_config *start, int i, rr_fmu_var *v);
int rr_fmu_var_find(const rr_fmu_config *start, unsigned vr, rr_fmu_var *v);

/* rr_fmu_format_number - x with the fewest digits (15 to 17) that read back
 * as x, "nan", "inf" or "-inf", into buf[len] (messages, XML). */
void rr_fmu_format_number(double x, char *buf, size_t len);

/* rr_fmu_var_name - the variable's full name ("left.p[1]") into buf[len]; its length. */
int rr_fmu_var_name(const rr_fmu_var *v, char *buf, size_t len);

/*
 * rr_fmu_var_item - item i of an ENUMERATION variable: its *name and
 * *value (1: there is an item i, 0: none, the end of the list); the value
 * is the variable's value for it (a choice's index, the registry's number
 * of a creep method).
 */
int rr_fmu_var_item(const rr_fmu_var *v, int i, const char **name, int *value);

/*
 * rr_fmu_var_start - the start value of v in `start` (a BOOLEAN as 0 or 1,
 * an ENUMERATION as its value); 0, or RR_ERR_PARAM (no start value: an
 * output or the time; *x NaN).
 */
int rr_fmu_var_start(const rr_fmu_config *start, const rr_fmu_var *v, double *x);

/*
 * rr_fmu_init - a new unit at the start values (copied): instantiated.
 * alloc, release (and ctx passed to them) allocate the contact table;
 * type_names (kept by pointer; NULL: "Real", "Integer", "Boolean",
 * "Enumeration") name the types in messages.  Status: RR_ERR_NULL.
 * rr_fmu_release - free what the unit allocated (m stays usable: a later
 * initialisation allocates again).
 */
int rr_fmu_init(rr_fmu *m, const rr_fmu_config *start, rr_fmu_alloc alloc, rr_fmu_free release,
                void *ctx, const char *const *type_names);
void rr_fmu_release(rr_fmu *m);

/*
 * rr_fmu_set_profiles - the points of the real profiles the configuration's
 * profile rows may say "points" for (wheelset.profile, roller.profile and
 * their _right rows; rr_tables.h's rr_rig_profiles): each slot with n > 0
 * is kept (by pointer: the arrays must outlive the unit, as the generated
 * data of an FMU does), the others hold none.  A row that says "points"
 * where the unit holds none fails the initialisation.  Call it after
 * rr_fmu_init (which holds none), before the initialisation.  Status:
 * RR_ERR_NULL; rr_rig_profiles_check's for the slots given (the unit then
 * holds none); RR_ERR_SEQUENCE after rr_fmu_enter_init.
 */
int rr_fmu_set_profiles(rr_fmu *m, const rr_rig_profiles *pr);

/*
 * rr_fmu_set_nonhertz - the non-Hertzian contact's tables (left, right) the
 * configuration's contact.patch = "nonhertz" reads (rr_rig_params_set_nonhertz;
 * the generated data of an FMU built from such a scenario): the headers
 * copied, the rows kept by pointer (they must outlive the unit); left and
 * right NULL: none (contact.patch = "nonhertz" then fails the
 * initialisation).  Call it after rr_fmu_init, before the initialisation.
 * Status: RR_ERR_NULL (one of the two NULL); RR_ERR_TABLE (a table not valid,
 * rr_nonhertz_table_check; the unit then holds none); RR_ERR_SEQUENCE after
 * rr_fmu_enter_init.
 */
int rr_fmu_set_nonhertz(rr_fmu *m, const rr_nh_table *left, const rr_nh_table *right);

/* The message of the last error or warning ("" after success). */
const char *rr_fmu_message(const rr_fmu *m);

/*
 * The unit's life.  rr_fmu_enter_init(m, t0): instantiated -> initialisation,
 * the start time t0 [s] (the rig's clock starts at 0 there).
 * rr_fmu_exit_init: -> stepping, the rig built from the parameters (table,
 * rr_rig_params_from, rr_rig_init, the encoders read).
 * rr_fmu_do_step(m, t, h): round(h / T) samples (T the control sample
 * time); t must be the unit's time (t0 + k T within 1e-3 T: a master adding
 * up its steps drifts by rounding) and h a whole multiple of T (within
 * 1e-6 T and the rounding of a difference of two times): else RR_ERR_PARAM
 * and nothing happens.  A
 * rig error at a sample stops the step there (the unit's time is that
 * sample's start, its outputs of that state) and fails the unit: further
 * steps are refused until rr_fmu_reset or rr_fmu_restore.  A command the
 * rig refuses at the step's first sample (an input NaN, mu not positive)
 * changes nothing: the step may be repeated with other inputs.  Warnings
 * (an integrator stage left off) are passed on, the step done.
 * rr_fmu_terminate: -> terminated.  rr_fmu_reset: -> instantiated at the
 * start values (the table is kept for a later initialisation).
 */
int rr_fmu_enter_init(rr_fmu *m, double t0);
int rr_fmu_exit_init(rr_fmu *m);
int rr_fmu_do_step(rr_fmu *m, double t, double h);
int rr_fmu_terminate(rr_fmu *m);
int rr_fmu_reset(rr_fmu *m);

/* rr_fmu_time - the unit's present time t0 + (the rig's clock) [s]. */
double rr_fmu_time(const rr_fmu *m);

/*
 * rr_fmu_get, rr_fmu_set - the value of variable vr as a double (an
 * INTEGER or ENUMERATION a whole number, a BOOLEAN 0 or 1), `type` the
 * caller's type (enum rr_fmu_type), which must be the variable's.
 * set: parameters and inputs only; a fixed parameter before stepping, a
 * tunable one and an input until terminated; the value checked against
 * the variable's range (RR_ERR_PARAM, RR_ERR_NONFINITE: NaN and infinities
 * are refused for every variable, inputs and start values included;
 * nothing changes).
 * get: parameters and inputs always; the time and the outputs from
 * initialisation on (the rig is built then if it is not yet).
 */
int rr_fmu_get(rr_fmu *m, int type, unsigned vr, double *v);
int rr_fmu_set(rr_fmu *m, int type, unsigned vr, double v);

/*
 * rr_fmu_save - a copy of everything that changes into *st (no pointer
 * into m is kept).  rr_fmu_restore - m as saved in st, from any unit of the
 * same start configuration and build (also a copy made in another process
 * and passed as bytes: its pointers are remade here; a state of another
 * geometry rebuilds the table).  Status: RR_ERR_NULL; restore: the table's
 * errors, RR_ERR_PARAM (a state that is not one: its mode out of range).
 */
int rr_fmu_save(const rr_fmu *m, rr_fmu_state *st);
int rr_fmu_restore(rr_fmu *m, const rr_fmu_state *st);

/* Not API: what the unit (rr_fmu_unit.c) takes from its variables and
 * configuration (rr_fmu.c).  What a variable is (rr_fmu_var.kind); the
 * present value of a parameter or input variable from a configuration and
 * inputs (in may be NULL: an input is NaN), an output's or the time's from
 * the unit's state; the inputs' start values of a start configuration; an
 * input's name ("" out of range); v set to x in f or in (an input), checked
 * as its row or option says (rr_rig_config_set, the creep option's range),
 * the status. */
enum rr_fmu_kind {
    RR_FMU_K_TIME = 0, RR_FMU_K_PARAM, RR_FMU_K_LIST, RR_FMU_K_CREEP, RR_FMU_K_CONTROL,
    RR_FMU_K_INPUT, RR_FMU_K_RECORD, RR_FMU_K_ENCODER, RR_FMU_K_WHEEL
};
double rr_fmu_value(const rr_fmu_config *f, const double *in, const rr_fmu_var *v);
double rr_fmu_output(const rr_fmu_state *s, const rr_fmu_var *v);
void rr_fmu_input_starts(const rr_fmu_config *f, double *in);
const char *rr_fmu_input_name(int i);
int rr_fmu_store(rr_fmu_config *f, double *in, const rr_fmu_var *v, double x);

#endif
