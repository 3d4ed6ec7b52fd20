/*
 * core.h - what the files of the binding share (private to rollerrig._core).
 *
 * The binding of the rollerrig C core, rollerrig._core, is these files,
 * compiled into one extension (setup.py):
 *   module.c       the module: its function table, the registry's and the
 *                  rig's declarations exported as tuples, PyInit__core
 *   batch.c        the one batch loop (run_batch), the 1-D float64 inputs
 *                  and outputs of every batch call, Ctrl-C within a case,
 *                  the exact solver's workspaces kept between calls
 *   options.c      a creep-force method and its options from Python
 *                  keywords, checked once (parse_opts, CreepOptions)
 *   contact.c      Hertz, Kalker's coefficients, creep forces, traction fields
 *   exact.c        the exact theory: its problem, its solver, its table
 *   geometry.c     contact search, contact tables, profile splines and tables
 *   gap.c          the undeformed distance of a wheel on its roller (rr_gap), and
 *                  one wheel solved by the exact theory on it (rr_wheel_exact)
 *   nonhertz.c     the non-Hertzian contact's table rows and one wheel from them
 *                  (rr_nonhertz_table, rr_nonhertz)
 *   rig_contact.c  the rig's contact model over arrays of states
 *   rig.c          the rig in time (the Rig type), its schedule and speed loops
 *   rig_profiles.c the rig's contact table on real profiles (rig_profile_table)
 *   rig_config.c   every problem of the rig's parameters (rig_config_report)
 *
 * Thin by design: no physics here.  Every batch call takes 1-D float64
 * arrays, each of length n or 1 (a length-1 array is broadcast; any stride
 * is accepted), allocates the outputs, runs its C kernel through the one
 * batch loop (run_batch: the GIL released around chunks of cases, Ctrl-C
 * checked between chunks, and within a case that may take seconds through
 * the core's interrupt hook: interrupt_hook), and returns the outputs
 * with an int8 status array (0 OK, > 0 warning, < 0 error with NaN
 * results).  Broadcasting of general shapes, argument names in messages
 * and the conversion of statuses into exceptions live in rollerrig/.
 */
#ifndef ROLLERRIG_CORE_H
#define ROLLERRIG_CORE_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
/* one NumPy API table for the whole extension: module.c imports it */
#define PY_ARRAY_UNIQUE_SYMBOL rollerrig_core_ARRAY_API
#ifndef CORE_IMPORT_ARRAY
#define NO_IMPORT_ARRAY
#endif
#include <numpy/arrayobject.h>

#include "rollerrig.h"

/* Shared between the binding's files, not exported from the extension. */
#if defined(__GNUC__)
#define CORE_PRIVATE __attribute__((visibility("hidden")))
#else
#define CORE_PRIVATE
#endif

/* ------------------------------------------------------------- batch.c */

/* Work per GIL release: about this many FASTSIM elements, or cases for the
 * cheap methods, so that Ctrl-C is noticed within milliseconds. */
#define CHUNK_WORK 65536

/* One input array: its bytes and stride. */
typedef struct {
    const char *data;
    npy_intp stride;   /* bytes; 0 for a broadcast length-1 array */
} input;

#define IN(arg, i) (*(const double *)((arg).data + (i) * (arg).stride))
#define OUT(obj) ((double *)PyArray_DATA((PyArrayObject *)(obj)))
#define OUT8(obj) ((npy_int8 *)PyArray_DATA((PyArrayObject *)(obj)))

/* The inputs objs[0..count) (1-D float64 arrays named names[]) into in[],
 * their common length into *n (0 for none); 0, or -1 with a ValueError. */
CORE_PRIVATE int parse_inputs(const char *func, PyObject *const *objs,
                              const char *const *names, int count, npy_intp *n, input *in);

/* New 1-D outputs: ndouble float64 arrays, then the int8 status array at
 * out[ndouble]; returns 0, or -1 with an exception set. */
CORE_PRIVATE int new_outputs(npy_intp n, int ndouble, PyObject **out);

/* The outputs as a tuple, which takes over their references. */
CORE_PRIVATE PyObject *outputs_tuple(PyObject **out, int count);

/* Drops the references of out[0..count) (NULL ones skipped). */
CORE_PRIVATE void release(PyObject **out, int count);

/* A batch kernel: computes cases [start, stop) of its context, without the
 * GIL (it may touch no Python object); a nonzero return stops the batch
 * there (a table build's first error). */
typedef int (*batch_kernel)(void *ctx, npy_intp start, npy_intp stop);

/* The one batch loop of the binding: kernel over cases [0, n) in chunks of
 * about CHUNK_WORK units of work (cost units a case), the GIL released
 * around each chunk, Ctrl-C checked between chunks (and by a kernel's
 * interrupt hook within them).  0, or -1 with the exception of the signal
 * handler set. */
CORE_PRIVATE int run_batch(batch_kernel kernel, void *ctx, npy_intp n, double cost);

/* Ctrl-C within one long case: the hook the core polls (batch.c). */
typedef struct {
    rr_interrupt hook;     /* what the core gets */
    double next;           /* the time of the next check [s] */
    int stopped;           /* a handler raised: every later poll stops too */
} interrupt_hook;

/* The hook, first checked INTERRUPT_PERIOD from now; call with the GIL
 * held, hand &h->hook to the core while the GIL is released. */
CORE_PRIVATE void interrupt_hook_init(interrupt_hook *h);

/* The exact solver's workspaces (batch.c), kept from call to call, a pool
 * per kind of call (their layouts differ): one of at least len doubles
 * (*got its length), zero-filled where new, NULL without memory; and given
 * back (freed, or kept for a later call of the kind).  Both with the GIL
 * held. */
enum { WORK_EXACT = 0, WORK_WHEEL = 1, WORK_KINDS = 2 };
CORE_PRIVATE double *work_take(int kind, size_t len, size_t *got);
CORE_PRIVATE void work_give(int kind, double *w, size_t len);

/* A Python integer as a C int: 0, or -1 with a ValueError naming func and
 * name where it is not an integer or lies outside [lo, hi] (a value beyond
 * the C int range is never wrapped or clamped into it). */
CORE_PRIVATE int int_arg(PyObject *v, const char *func, const char *name, long lo, long hi,
                         int *out);

/* An elementwise batch: its inputs, its double outputs and status, and for
 * creep_forces the method's options. */
#define MAX_IN 12
#define MAX_OUT 4
typedef struct {
    input in[MAX_IN];
    double *out[MAX_OUT];
    npy_int8 *st;
    rr_creep_checked creep;  /* creep_forces: the method and its options, checked */
    double *work;          /* the method's workspace (creep_forces), NULL if none */
    size_t work_len;
    interrupt_hook stop;   /* creep_forces: Ctrl-C within a case */
} elementwise;

/* The elementwise call func(*arrays): nin input arrays from args[first:], named
 * names[], nout float64 outputs and the int8 status computed by kernel at
 * cost units a case; (outputs..., status), or NULL with an exception. */
CORE_PRIVATE PyObject *elementwise_call(const char *func, PyObject *args, int first,
                                        const char *const *names, int nin, int nout,
                                        batch_kernel kernel, elementwise *b, double cost);

/* ----------------------------------------------------------- options.c */

/* ", ".join of the quoted names */
CORE_PRIVATE PyObject *quoted_names(const char *const *names, int n);

/* The method and its options from keywords: method= a name of the registry,
 * every other keyword (but own, the call's own keyword, or NULL) an option of
 * that method; then the method's constraints across options, checked once
 * into *k (rr_creep_check: the kernels take it as checked).  0, or -1 with a
 * ValueError naming the method, the option, its range and the value. */
CORE_PRIVATE int parse_opts(PyObject *kwargs, const char *func, const char *own,
                            rr_creep_checked *k);

/* CreepOptions(**options): a method and its options, parsed and checked
 * once (rr_creep_check), for repeated calls: creep_forces1, and the batch
 * calls given one (call_opts; check_creep_options makes one).  Immutable. */
typedef struct {
    PyObject_HEAD
    rr_creep_checked k;
    int ready;
} CreepOptionsObject;

/* 1 if a call's first argument is a CreepOptions (its arrays follow), else 0 */
CORE_PRIVATE int opts_first(PyObject *args);

/* The method and options of a call: a CreepOptions as its first positional
 * argument (then no keywords), else parse_opts of its keywords, into *k.
 * The index of the call's first array (1 or 0), or -1 with an exception. */
CORE_PRIVATE int call_opts(PyObject *args, PyObject *kwargs, const char *func,
                           rr_creep_checked *k);

CORE_PRIVATE extern PyTypeObject CreepOptionsType;

CORE_PRIVATE PyObject *py_check_creep_options(PyObject *self, PyObject *args);

/* ----------------------------------------------------------- contact.c */

/* The arrays of one creep-force case, in the order of the calls' arguments. */
#define NCASE 12
CORE_PRIVATE extern const char *const case_names[NCASE];

/* Case i of the NCASE inputs in[]: an ellipse problem (its grid untouched). */
CORE_PRIVATE void load_case(const input *in, npy_intp i, rr_contact_problem *c);

/* The case's argument (case_names) holding a member of its problem (enum
 * rr_problem_field), or NULL where none does (RR_PF_NONE, the grid's). */
CORE_PRIVATE const char *case_blame(int field);

CORE_PRIVATE PyObject *py_hertz(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_hertz1(PyObject *self, PyObject *const *args, Py_ssize_t nargs);
CORE_PRIVATE PyObject *py_kalker(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_creep_forces(PyObject *self, PyObject *args, PyObject *kwargs);
CORE_PRIVATE PyObject *py_creep_forces1(PyObject *self, PyObject *const *args, Py_ssize_t nargs);
CORE_PRIVATE PyObject *py_fastsim_field(PyObject *self, PyObject *args, PyObject *kwargs);
CORE_PRIVATE PyObject *py_creep_blame(PyObject *self, PyObject *const *args, Py_ssize_t nargs);

/* ------------------------------------------------------------- exact.c */

CORE_PRIVATE PyObject *py_exact_table_builtin(PyObject *self, PyObject *unused);
CORE_PRIVATE PyObject *py_exact_hertz_problem(PyObject *self, PyObject *args, PyObject *kwargs);
CORE_PRIVATE PyObject *py_exact_field(PyObject *self, PyObject *args, PyObject *kwargs);
CORE_PRIVATE PyObject *py_exact_solve(PyObject *self, PyObject *args);

/* ---------------------------------------------------------- geometry.c */

/* The table from its Python parts: rows as a 1-D float64 array; 0, or -1
 * with a ValueError naming func. */
CORE_PRIVATE int parse_table(PyObject *obj, double y0, double dy, const char *func,
                             rr_contact_table *t);

/* The two wheel-roller pairs of a RigGeometry (its _arrays(): knots,
 * values and second derivatives of four profiles, then its _params():
 * r0, R0, wheel_y, roller_y per side), parsed by PAIR_FORMAT; prof[]
 * keeps the NPROF arrays alive (release them).  0, or -1 with an
 * exception naming func. */
#define NPROF 12
#define PAIR_FORMAT "OOOOOOOOOOOO(dddddddd)"
#define PAIR_ARGS(pobj, par) &pobj[0], &pobj[1], &pobj[2], &pobj[3], &pobj[4], &pobj[5], \
    &pobj[6], &pobj[7], &pobj[8], &pobj[9], &pobj[10], &pobj[11], &par[0], &par[1], &par[2], \
    &par[3], &par[4], &par[5], &par[6], &par[7]
CORE_PRIVATE int parse_pairs(PyObject *const *pobj, const double *par, const char *func,
                             PyArrayObject **prof, rr_wheel_roller *pair);

CORE_PRIVATE PyObject *py_wheelset_contact(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_contact_table(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_table_lookup(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_spline_fit(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_analytic_profile(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_profile_table(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_rig_table(PyObject *self, PyObject *args);

/* --------------------------------------------------------------- gap.c */

CORE_PRIVATE PyObject *py_gap_build(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_wheel_exact(PyObject *self, PyObject *args);

/* ---------------------------------------------------------- nonhertz.c */

CORE_PRIVATE PyObject *py_nonhertz_row(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_nonhertz_check(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_nonhertz_wheel(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_nonhertz_locate(PyObject *self, PyObject *args);
CORE_PRIVATE int add_nonhertz(PyObject *m);

/* ------------------------------------------------ rig_contact.c, rig.c */

CORE_PRIVATE PyObject *py_rig_contact(PyObject *self, PyObject *args, PyObject *kwargs);
CORE_PRIVATE PyObject *py_rig_row_kinematics(PyObject *self, PyObject *args);

CORE_PRIVATE extern PyTypeObject RigType;

CORE_PRIVATE PyObject *py_rig_schedule(PyObject *self, PyObject *args);
CORE_PRIVATE PyObject *py_rig_speed_loops(PyObject *self, PyObject *arg);
/* rig_profiles.c */
CORE_PRIVATE PyObject *py_rig_profile_table(PyObject *self, PyObject *args);
/* rig_config.c */
CORE_PRIVATE PyObject *py_rig_config_report(PyObject *self, PyObject *arg);

#endif
