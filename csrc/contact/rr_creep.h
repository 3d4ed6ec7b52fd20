/*
 * rr_creep.h - the creep-force methods' registry and dispatcher.
 *
 * Every method (rr_methods.def: Kalker's linear theory, FASTSIM and its
 * variants, Polach's method) publishes a descriptor (rr_method_desc,
 * rr_creep_opts.h): its name, its options with their types, defaults and
 * ranges, its cost, its small-creepage slope and its entry points.  This
 * header finds them by number or name, fills and checks options from
 * them, and dispatches a call to the method named in the options.  Every
 * method takes a contact problem (rr_contact_problem, rr_contact.h: the
 * Hertz ellipse, or for a method that takes it an undeformed distance on a
 * grid; the friction law inside), options and the caller's workspace, and
 * returns the forces on the wheel.
 */
#ifndef RR_CREEP_H
#define RR_CREEP_H

#include "contact/rr_creep_opts.h"

/* The number of methods (RR_METHOD_COUNT). */
int rr_method_count(void);

/* Method i's descriptor, or NULL where i is not in [0, rr_method_count()). */
const rr_method_desc *rr_method_get(int i);

/* The number of the method called name, RR_ERR_METHOD if none is, RR_ERR_NULL. */
int rr_method_find(const char *name);

/*
 * rr_creep_opts_default - o->method = method and every option its default:
 * a 30 x 30 rectangular grid with the parabolic bound (Kalker's original);
 * falling friction at the local slip speed, except for modified FASTSIM,
 * whose slope reduction was calibrated with friction at the rigid slip
 * speed; modified FASTSIM's k0 = 0.54, alpha_inf = 0.02, beta = 0.62 (the
 * example of CONTACT's user guide and Spiryagin et al. 2013); Polach's
 * kA = kS = 1 (his 1999 method).  The values past the method's options are
 * NaN.  Status: RR_OK, RR_ERR_METHOD (method unknown: o->method is set all
 * the same, every value NaN), RR_ERR_NULL.
 */
int rr_creep_opts_default(rr_creep_opts *o, int method);

/*
 * rr_creep_opts_set - the option called name of o's method set to value:
 * RR_OK; RR_ERR_METHOD (o->method unknown), RR_ERR_PARAM (the method has
 * no such option), or the option's own status (rr_method_option_check:
 * RR_ERR_NONFINITE, or out of range: RR_ERR_GRID for nx, ny, RR_ERR_METHOD
 * for a choice, RR_ERR_PARAM for a real), o unchanged; RR_ERR_NULL.
 * Constraints across options (Polach's kS <= kA) wait for rr_creep_opts_check.
 */
int rr_creep_opts_set(rr_creep_opts *o, const char *name, double value);

/*
 * rr_creep_opts_check - 0, or RR_ERR_METHOD (method unknown, or a choice -
 * bound, grid, slip_speed - not one of its names), RR_ERR_GRID (nx, ny not
 * an integer in [1, RR_FASTSIM_MAX_GRID]), RR_ERR_NONFINITE (a real option),
 * RR_ERR_PARAM (k0 outside (0, 1], alpha_inf outside [0, 1], beta < 0, not
 * 0 < kS <= kA <= 1: Polach's condition, which keeps |F| <= mu N),
 * RR_ERR_NULL.  Only the method's own options are checked, in the order of
 * its descriptor (the first bad one decides the status), then its
 * constraints across options.
 * rr_creep_opts_check_at: the same, *bad (may be NULL) the index of the
 * offending option, -1 where none is to blame (the method unknown).
 */
int rr_creep_opts_check(const rr_creep_opts *o);
int rr_creep_opts_check_at(const rr_creep_opts *o, int *bad);

/* For valid options (else 0, NaN): the work of one case in FASTSIM elements
 * (1 for a closed form: chunk sizes), whether the method saturates
 * (|F| <= mu N; the linear theory does not), the small-creepage slope over
 * the linear theory's (the rig's linearisation), whether it takes grid
 * problems, whether it solves a case iteratively (not a time-loop method:
 * the descriptor's iterative), and the doubles of workspace
 * rr_creep_forces_work needs on a problem of grid (NULL: the ellipse's; a
 * workspace for a grid serves a smaller one; 0 also for a grid the method
 * does not take). */
double rr_creep_cost(const rr_creep_opts *o);
int rr_creep_saturates(const rr_creep_opts *o);
double rr_creep_slope_scale(const rr_creep_opts *o);
int rr_creep_takes_grid(const rr_creep_opts *o);
int rr_creep_iterative(const rr_creep_opts *o);
size_t rr_creep_workspace_len(const rr_creep_opts *o, const rr_grid *grid);

/*
 * rr_creep_checked - a method with its options, checked once for many
 * calls (a batch of cases, the rig's time step): the constant part of a
 * call, checked by rr_creep_check, so that rr_creep_forces_checked checks
 * only what changes from call to call, the problem.  Read-only: a changed
 * option needs rr_creep_check again.
 */
typedef struct {
    rr_creep_opts o;             /* the options, a checked copy */
    const rr_method_desc *d;     /* their method's descriptor */
    size_t work_len;             /* rr_creep_workspace_len of the ellipse */
    double cost;                 /* rr_creep_cost */
    unsigned ready;              /* RR_CREEP_READY once checked */
} rr_creep_checked;

#define RR_CREEP_READY 0x52524350u

/*
 * rr_creep_check - o checked as rr_creep_opts_check_at does (*bad, may be
 * NULL: the offending option's index, -1 if none is to blame) into *k.
 *   status:  RR_OK; rr_creep_opts_check's, or RR_ERR_NULL, with *k not
 *            ready (rr_creep_forces_checked refuses it).
 */
int rr_creep_check(rr_creep_checked *k, const rr_creep_opts *o, int *bad);

/*
 * rr_creep_forces_checked - rr_creep_forces_interruptible with the options
 * of a successful rr_creep_check: the problem checked by the method, the
 * options not again.  The same doubles and statuses, but RR_ERR_NULL
 * (forces NaN) for a k that rr_creep_check did not set or refused.
 */
int rr_creep_forces_checked(const rr_creep_checked *k, const rr_contact_problem *p,
                            double *work, size_t work_len, const rr_interrupt *stop,
                            rr_forces *out);

/*
 * rr_creep_forces - dispatch problem p to the method named in o->method,
 * after rr_creep_opts_check.  A patch the method does not take (a grid
 * problem, where the descriptor's takes_grid is 0) is RR_ERR_PATCH; the
 * method checks the rest of the problem.  The linear theory ignores
 * friction (but refuses an invalid law, as every method does); FASTSIM
 * variants call rr_fastsim (rr_fastsim.h) without a traction field.  A
 * method that needs workspace for p (rr_creep_workspace_len > 0) gets
 * RR_ERR_WORKSPACE here: call rr_creep_forces_work with work of at least
 * that many doubles.  On error the forces are NaN.
 */
int rr_creep_forces(const rr_contact_problem *p, const rr_creep_opts *o, rr_forces *out);
int rr_creep_forces_work(const rr_contact_problem *p, const rr_creep_opts *o, double *work,
                         size_t work_len, rr_forces *out);

/*
 * rr_creep_forces_interruptible - rr_creep_forces_work with the caller's
 * interrupt hook stop (NULL: none; rr_common.h), polled by a method whose
 * one case may take seconds (the descriptor's forces_interruptible: the
 * exact theory) and ignored by the others, whose cases are short: the
 * caller checks between them.  A hook that asks to stop gives
 * RR_ERR_INTERRUPTED (forces NaN); one that never does, the doubles of
 * rr_creep_forces_work.
 */
int rr_creep_forces_interruptible(const rr_contact_problem *p, const rr_creep_opts *o,
                                  double *work, size_t work_len, const rr_interrupt *stop,
                                  rr_forces *out);

/*
 * rr_creep_field - the forces with the traction field, for methods that
 * have one (descriptor field_shape: rows x cols elements); RR_ERR_METHOD
 * for the others, RR_ERR_PATCH for a patch the method does not take
 * (forces NaN), else as the method's field entry point.
 */
int rr_creep_field(const rr_contact_problem *p, const rr_creep_opts *o, rr_forces *out,
                   rr_traction_field *field);

/*
 * rr_creep_blame - the member of problem p (enum rr_problem_field) to
 * blame for the status st that the method of k gave it: RR_PF_PATCH for
 * RR_ERR_PATCH where the method does not take p's patch;
 * rr_contact_problem_check's member where that check gives st itself;
 * for what a method asks of a valid problem on its own terms, RR_PF_SPEED
 * for RR_ERR_SPEED (falling friction at rest), RR_PF_FRICTION_A for
 * RR_ERR_FRICTION (a falling law, a Coulomb-only method), then the
 * method's own (descriptor's blame: exact_table's a/b or nu); RR_PF_NONE
 * where no one member is to blame (st >= 0, a result out of range, an
 * unready k).  For the messages of a caller that names its arguments.
 */
int rr_creep_blame(const rr_creep_checked *k, const rr_contact_problem *p, int st);

#endif
