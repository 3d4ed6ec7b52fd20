/*
 * rr_creep_opts.h - the bottom of the creep-force methods: the options of a
 * method call, the descriptor every method publishes (its name, options,
 * cost, slope, entry points), and what all methods share.
 *
 * Layering: rr_creep_opts.h <- each method (rr_linear.h, rr_fastsim.h,
 * rr_polach.h, ...) <- rr_creep.h (the registry of rr_methods.def and the
 * dispatcher).  No method includes the registry; the registry includes
 * no method header (it only names the descriptors).
 */
#ifndef RR_CREEP_OPTS_H
#define RR_CREEP_OPTS_H

#include <stddef.h>
#include "util/rr_common.h"
#include "contact/rr_contact.h"
#include "contact/rr_kalker.h"

/* The methods' numbers, in the order of rr_methods.def: RR_METHOD_LINEAR,
 * RR_METHOD_FASTSIM, ...; RR_METHOD_COUNT of them. */
enum rr_method {
#define RR_METHOD(tag, desc) RR_METHOD_##tag,
#include "contact/rr_methods.def"
#undef RR_METHOD
    RR_METHOD_COUNT
};

/* Most options any method may have. */
#define RR_CREEP_MAX_OPTS 16

/*
 * The options of one call: the method's number and its option values, v[i]
 * the value of the method's option i (its descriptor's opts[i]; each method
 * names its indices in its header, e.g. RR_FASTSIM_NX).  Integers and
 * choices are stored as doubles holding an integer (a choice: the index of
 * its name).  Fill with rr_creep_opts_default, change with
 * rr_creep_opts_set (by name) or v[index], check with rr_creep_opts_check
 * (rr_creep.h).
 */
typedef struct {
    int method;
    double v[RR_CREEP_MAX_OPTS];
} rr_creep_opts;

enum rr_opt_type {
    RR_OPT_INT = 0,      /* an integer in [lo, hi] (ends per lo_open, hi_open) */
    RR_OPT_REAL = 1,     /* a finite real in the range */
    RR_OPT_CHOICE = 2    /* one of choices[]: the value is the name's index */
};

typedef struct {
    const char *name;              /* as given by keyword: "nx", "k0", ... */
    int type;                      /* enum rr_opt_type */
    const char *unit;              /* "" for a dimensionless number or a choice */
    double def;                    /* default (a choice: the index) */
    double lo, hi;                 /* valid range; -HUGE_VAL/HUGE_VAL for none */
    int lo_open, hi_open;          /* 1: the end itself is excluded */
    const char *const *choices;    /* RR_OPT_CHOICE: the names, NULL-terminated */
    int status;                    /* status of a value outside the range:
                                      RR_ERR_GRID, RR_ERR_PARAM, RR_ERR_METHOD */
    const char *doc;               /* one line */
} rr_creep_option;

/*
 * The traction field of one evaluation (methods that have one: FASTSIM's
 * variants): every pointer either NULL (not wanted) or an array of
 * rows * cols elements (the method's field_shape).  Element (i, j) is stored
 * at j * cols + i, rows j along y, i along increasing x; elements outside
 * the ellipse have zero pressure and traction.
 */
typedef struct {
    double *x, *y;        /* element centre [m] */
    double *area;         /* element area [m^2] */
    double *pn;           /* pressure [Pa] */
    double *px, *py;      /* tangential traction on the wheel [Pa] */
    signed char *slip;    /* 1 slip, 0 adhesion */
    int nslip;            /* output: number of slipping elements */
} rr_traction_field;

/*
 * A method's descriptor: all the rest of the library and the binding know
 * of a method.  Entry points take a contact problem (rr_contact.h) of a
 * patch the method takes (takes_grid), the options already checked by
 * rr_method_check (and the method's check hook) and the caller's workspace
 * of workspace_len doubles for the problem's size; they still check the
 * problem, and return RR_ERR_NULL for NULL pointers.
 */
typedef struct {
    const char *name;                   /* "fastsim" */
    const char *doc;                    /* one line */
    int nopts;                          /* <= RR_CREEP_MAX_OPTS */
    const rr_creep_option *opts;
    int saturates;                      /* 1: |F| <= mu N; 0: no friction limit (linear theory) */
    /* cross-option constraints beyond each option's range (NULL: none):
     * RR_OK, or a status with *bad the offending option's index */
    int (*check)(const rr_creep_opts *o, int *bad);
    const char *check_doc;              /* the constraint, for messages ("0 < kS <= kA <= 1") */
    /* work of one case in units of one FASTSIM element (1 for a closed form): chunk sizes */
    double (*cost)(const rr_creep_opts *o);
    /* small-creepage slope over the linear theory's, for the rig's
     * linearisation (Polach: (kA + kS)/2) */
    double (*slope_scale)(const rr_creep_opts *o);
    /* doubles of caller workspace one call needs on a problem of grid
     * (NULL: the ellipse's); 0: none */
    size_t (*workspace_len)(const rr_creep_opts *o, const rr_grid *grid);
    int (*forces)(const rr_contact_problem *p, const rr_creep_opts *o, double *work,
                  rr_forces *out);
    /* NULL, or the traction field's rows, columns (of a problem of grid;
     * NULL: the ellipse's) and the evaluation with it */
    void (*field_shape)(const rr_creep_opts *o, const rr_grid *grid, int *rows, int *cols);
    int (*field)(const rr_contact_problem *p, const rr_creep_opts *o, rr_forces *out,
                 rr_traction_field *field);
    /* 1: Coulomb friction only (a falling law is RR_ERR_FRICTION); 0 (the
     * default of a descriptor that leaves it out): any law */
    int coulomb_only;
    /* NULL (the default of a descriptor that leaves it out), or forces with
     * the caller's interrupt hook (rr_common.h), for a method whose one case
     * may take seconds (the exact theory on a fine grid) */
    int (*forces_interruptible)(const rr_contact_problem *p, const rr_creep_opts *o,
                                double *work, const rr_interrupt *stop, rr_forces *out);
    /* 1: grid problems too (RR_PATCH_GRID: the exact theory); 0 (left out):
     * the ellipse only, a grid problem is RR_ERR_PATCH */
    int takes_grid;
    /* 1: one case is solved iteratively to a tolerance (the exact theory:
     * milliseconds to seconds, its work set by convergence, not known
     * before a time step): not a time-loop method, the rig refuses it;
     * 0 (left out): a case of bounded work (closed forms, FASTSIM's march,
     * a table) */
    int iterative;
    /* NULL (left out), or the member of a valid problem to blame for a
     * status the method gave it on its own terms (rr_creep_blame;
     * exact_table: RR_ERR_TABLE, a/b or nu) */
    int (*blame)(const rr_contact_problem *p, const rr_creep_opts *o, int st);
} rr_method_desc;

/* Helpers for descriptors: a cost of 1 and a slope scale of 1, and no workspace. */
double rr_method_unit_cost(const rr_creep_opts *o);
double rr_method_unit_slope(const rr_creep_opts *o);
size_t rr_method_no_workspace(const rr_creep_opts *o, const rr_grid *grid);

/* The index of d's option named name, or -1 (also for NULL arguments). */
int rr_method_option(const rr_method_desc *d, const char *name);

/*
 * rr_method_option_check - RR_OK if x is a valid value of option op, else
 * RR_ERR_NONFINITE (a real NaN or infinite), op->status (out of range, not
 * an integer for an integer option, not a choice's index; NaN too) or
 * RR_ERR_NULL.
 */
int rr_method_option_check(const rr_creep_option *op, double x);

/*
 * rr_method_check - the options o->v checked against d's descriptors, in
 * the order of d->opts, then d's check hook: RR_OK, or the first failing
 * status with *bad (may be NULL) the option's index (-1 when d or o is
 * NULL).  o->method is not looked at.
 */
int rr_method_check(const rr_method_desc *d, const rr_creep_opts *o, int *bad);

/*
 * rr_creep_prepare - the checks every frictional method of the ellipse
 * starts with, then Kalker's coefficients of the ellipse.
 *   status: RR_ERR_PATCH (a grid problem), rr_contact_problem_check,
 *   RR_ERR_SPEED (falling friction needs speed > 0), RR_ERR_RANGE (mu0 N
 *   not a normal double), rr_kalker, RR_ERR_RANGE (a/b not a normal
 *   double), RR_ERR_NULL.
 */
int rr_creep_prepare(const rr_contact_problem *p, rr_kalker_coeffs *k);

/* rr_creep_prepare with Kalker's coefficients given (a caller that has
 * them for the same a/b and nu, to rounding): its checks, then *k =
 * *given; RR_ERR_PARAM where a given coefficient is not finite and
 * positive. */
int rr_creep_prepare_given(const rr_contact_problem *p, const rr_kalker_coeffs *given,
                           rr_kalker_coeffs *k);

/* Kalker's coefficients of a checked ellipse problem; RR_ERR_RANGE (NaN
 * coefficients) where a/b is not a normal double (semi-axes some 300
 * orders of magnitude apart). */
int rr_creep_kalker(const rr_contact_problem *p, rr_kalker_coeffs *k);

/* rr_contact_problem_check of an ellipse problem (RR_ERR_PATCH for a grid
 * one, RR_ERR_NULL for NULL): the check of the ellipse methods' public
 * functions. */
int rr_creep_ellipse_check(const rr_contact_problem *p);

#endif
