/*
 * _core.c - the CPython binding of the rollerrig C core.
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
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <numpy/arrayobject.h>

#include <stddef.h>
#include <string.h>
#include <time.h>

#include "rollerrig.h"

/* Work per GIL release: about this many FASTSIM elements, or cases for the
 * cheap methods, so that Ctrl-C is noticed within milliseconds. */
#define CHUNK_WORK 65536

typedef struct {
    const char *data;
    npy_intp stride;   /* bytes; 0 for a broadcast length-1 array */
} input;

#define IN(arg, i) (*(const double *)((arg).data + (i) * (arg).stride))

/* Check one input (1-D float64 array) and fold its length into *n:
 * *n < 0 means not yet known; length 1 broadcasts against anything. */
static int get_input(PyObject *obj, const char *func, const char *name, npy_intp *n,
                     input *out)
{
    PyArrayObject *arr;
    npy_intp len;

    if (!PyArray_Check(obj)) {
        PyErr_Format(PyExc_TypeError, "%s: %s must be a numpy array, got %.100s", func, name,
                     Py_TYPE(obj)->tp_name);
        return -1;
    }
    arr = (PyArrayObject *)obj;
    if (PyArray_TYPE(arr) != NPY_DOUBLE || PyArray_NDIM(arr) != 1) {
        PyErr_Format(PyExc_ValueError, "%s: %s must be a 1-D float64 array, got %d-D %R",
                     func, name, PyArray_NDIM(arr), (PyObject *)PyArray_DESCR(arr));
        return -1;
    }
    len = PyArray_DIM(arr, 0);
    if (len != 1) {
        if (*n >= 0 && *n != 1 && *n != len) {
            PyErr_Format(PyExc_ValueError, "%s: %s has length %zd, expected %zd or 1", func,
                         name, (Py_ssize_t)len, (Py_ssize_t)*n);
            return -1;
        }
        *n = len;
    } else if (*n < 0) {
        *n = 1;
    }
    out->data = PyArray_BYTES(arr);
    out->stride = len == 1 ? 0 : PyArray_STRIDE(arr, 0);
    return 0;
}

/* Recheck that every input matches the final length (an early length-1
 * input may precede the first long one). */
static int check_lengths(const char *func, PyObject *const *objs, const char *const *names,
                         int count, npy_intp n)
{
    int k;
    for (k = 0; k < count; k++) {
        npy_intp len = PyArray_DIM((PyArrayObject *)objs[k], 0);
        if (len != 1 && len != n) {
            PyErr_Format(PyExc_ValueError, "%s: %s has length %zd, expected %zd or 1", func,
                         names[k], (Py_ssize_t)len, (Py_ssize_t)n);
            return -1;
        }
    }
    return 0;
}

static int parse_inputs(const char *func, PyObject *const *objs, const char *const *names,
                        int count, npy_intp *n, input *in)
{
    int k;
    *n = -1;
    for (k = 0; k < count; k++)
        if (get_input(objs[k], func, names[k], n, &in[k]) < 0)
            return -1;
    if (*n < 0)
        *n = 0;
    return check_lengths(func, objs, names, count, *n);
}

/* New 1-D outputs: ndouble float64 arrays, then the int8 status array at
 * out[ndouble]; returns 0, or -1 with an exception set. */
static int new_outputs(npy_intp n, int ndouble, PyObject **out)
{
    int k;
    for (k = 0; k <= ndouble; k++) {
        out[k] = PyArray_SimpleNew(1, &n, k < ndouble ? NPY_DOUBLE : NPY_INT8);
        if (!out[k])
            return -1;
    }
    return 0;
}

/* The outputs as a tuple, which takes over their references. */
static PyObject *outputs_tuple(PyObject **out, int count)
{
    PyObject *t = PyTuple_New(count);
    int k;
    if (!t)
        return NULL;
    for (k = 0; k < count; k++) {
        PyTuple_SET_ITEM(t, k, out[k]);
        out[k] = NULL;
    }
    return t;
}

static void release(PyObject **out, int count)
{
    int k;
    for (k = 0; k < count; k++)
        Py_XDECREF(out[k]);
}

/* A batch kernel: computes cases [start, stop) of its context, without the
 * GIL (it may touch no Python object); a nonzero return stops the batch
 * there (a table build's first error). */
typedef int (*batch_kernel)(void *ctx, npy_intp start, npy_intp stop);

/* The one batch loop of the binding: kernel over cases [0, n) in chunks of
 * about CHUNK_WORK units of work (cost units a case), the GIL released
 * around each chunk, Ctrl-C checked between chunks (and by a kernel's
 * interrupt hook within them).  0, or -1 with the exception of the signal
 * handler set. */
static int run_batch(batch_kernel kernel, void *ctx, npy_intp n, double cost)
{
    npy_intp start, chunk = cost >= 1.0 ? (npy_intp)(CHUNK_WORK / cost) : CHUNK_WORK;
    int stop = 0;
    if (chunk < 1)
        chunk = 1;
    for (start = 0; start < n && !stop; start += chunk) {
        const npy_intp end = n - start > chunk ? start + chunk : n;
        Py_BEGIN_ALLOW_THREADS
        stop = kernel(ctx, start, end);
        Py_END_ALLOW_THREADS
        if (PyErr_Occurred() || PyErr_CheckSignals() < 0)
            return -1;
    }
    return 0;
}

/* Ctrl-C within one long case (the exact theory on a fine grid: seconds to
 * minutes a case): the core polls its interrupt hook (rr_interrupt) between
 * FFT products, without the GIL; the hook takes the GIL back at most every
 * INTERRUPT_PERIOD seconds to run Python's signal handlers (as shapely's
 * long loops do), and a handler's exception (KeyboardInterrupt) stops the
 * case with RR_ERR_INTERRUPTED, the exception left set for the caller. */
#define INTERRUPT_PERIOD 0.1

typedef struct {
    rr_interrupt hook;     /* what the core gets */
    double next;           /* the time of the next check [s] */
    int stopped;           /* a handler raised: every later poll stops too */
} interrupt_hook;

/* a clock for the period: monotonic where POSIX has one */
static double seconds_now(void)
{
#if defined(CLOCK_MONOTONIC)
    struct timespec t;
    if (clock_gettime(CLOCK_MONOTONIC, &t) == 0)
        return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
#endif
    return (double)clock() / CLOCKS_PER_SEC;
}

static int poll_signals(void *ctx)
{
    interrupt_hook *h = ctx;
    if (!h->stopped && seconds_now() >= h->next) {
        PyGILState_STATE g = PyGILState_Ensure();
        h->stopped = PyErr_CheckSignals() < 0;
        PyGILState_Release(g);
        h->next = seconds_now() + INTERRUPT_PERIOD;
    }
    return h->stopped;
}

/* The hook, first checked INTERRUPT_PERIOD from now; call with the GIL
 * held, hand &h->hook to the core while the GIL is released. */
static void interrupt_hook_init(interrupt_hook *h)
{
    h->hook.poll = poll_signals;
    h->hook.ctx = h;
    h->stopped = 0;
    h->next = seconds_now() + INTERRUPT_PERIOD;
}

/* A Python integer as a C int: 0, or -1 with a ValueError naming func and
 * name where it is not an integer or lies outside [lo, hi] (a value beyond
 * the C int range is never wrapped or clamped into it). */
static int int_arg(PyObject *v, const char *func, const char *name, long lo, long hi,
                   int *out)
{
    int overflow = 0;
    long x;
    if (!PyLong_Check(v) || PyBool_Check(v)) {
        PyErr_Format(PyExc_ValueError, "%s: %s must be an integer, got %R", func, name, v);
        return -1;
    }
    x = PyLong_AsLongAndOverflow(v, &overflow);
    if (x == -1 && PyErr_Occurred())
        return -1;
    if (overflow || x < lo || x > hi) {
        PyErr_Format(PyExc_ValueError, "%s: %s must be an integer from %ld to %ld, got %R",
                     func, name, lo, hi, v);
        return -1;
    }
    *out = (int)x;
    return 0;
}

#define OUT(obj) ((double *)PyArray_DATA((PyArrayObject *)(obj)))
#define OUT8(obj) ((npy_int8 *)PyArray_DATA((PyArrayObject *)(obj)))

/* ---------------------------------------------------------------- hertz */

/* An elementwise batch: its inputs, its double outputs and status, and for
 * creep_forces the method's options. */
#define MAX_IN 12
#define MAX_OUT 4
typedef struct {
    input in[MAX_IN];
    double *out[MAX_OUT];
    npy_int8 *st;
    rr_creep_opts o;
    double *work;          /* the method's workspace (creep_forces), NULL if none */
    size_t work_len;
    interrupt_hook stop;   /* creep_forces: Ctrl-C within a case */
} elementwise;

/* The elementwise call func(*arrays): nin input arrays from args, named
 * names[], nout float64 outputs and the int8 status computed by kernel at
 * cost units a case; (outputs..., status), or NULL with an exception. */
static PyObject *elementwise_call(const char *func, PyObject *args, const char *const *names,
                                  int nin, int nout, batch_kernel kernel, elementwise *b,
                                  double cost)
{
    PyObject *objs[MAX_IN], *out[MAX_OUT + 1] = {NULL, NULL, NULL, NULL, NULL}, *res;
    npy_intp n;
    int k;
    if (!PyTuple_Check(args) || PyTuple_GET_SIZE(args) != nin) {
        PyErr_Format(PyExc_TypeError, "%s: expected %d arrays (%s, ...)", func, nin, names[0]);
        return NULL;
    }
    for (k = 0; k < nin; k++)
        objs[k] = PyTuple_GET_ITEM(args, k);
    if (parse_inputs(func, objs, names, nin, &n, b->in) < 0 || new_outputs(n, nout, out) < 0)
        goto fail;
    for (k = 0; k < nout; k++)
        b->out[k] = OUT(out[k]);
    b->st = OUT8(out[nout]);
    if (run_batch(kernel, b, n, cost) < 0)
        goto fail;
    if ((res = outputs_tuple(out, nout + 1)) != NULL)
        return res;
fail:
    release(out, nout + 1);
    return NULL;
}

/* ---------------------------------------------------------------- hertz */

static int hertz_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    elementwise *b = ctx;
    npy_intp i;
    for (i = start; i < stop; i++) {
        rr_hertz_result h;
        b->st[i] = (npy_int8)rr_hertz_bodies(IN(b->in[0], i), IN(b->in[1], i), IN(b->in[2], i),
                                             IN(b->in[3], i), IN(b->in[4], i), IN(b->in[5], i),
                                             IN(b->in[6], i), &h);
        b->out[0][i] = h.a;
        b->out[1][i] = h.b;
        b->out[2][i] = h.p0;
        b->out[3][i] = h.delta;
    }
    return 0;
}

static PyObject *py_hertz(PyObject *self, PyObject *args)
{
    static const char *const names[] = {"A", "B", "N", "E1", "nu1", "E2", "nu2"};
    elementwise b;
    (void)self;
    return elementwise_call("hertz", args, names, 7, 4, hertz_kernel, &b, 1.0);
}

/* hertz1(A, B, N, E1, nu1, E2, nu2) -> (a, b, p0, delta, status): one case
 * from Python numbers, the scalar path. */
static PyObject *py_hertz1(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    double v[7];
    rr_hertz_result h;
    int k, st;
    (void)self;
    if (nargs != 7) {
        PyErr_SetString(PyExc_TypeError, "hertz1: expected 7 numbers");
        return NULL;
    }
    for (k = 0; k < 7; k++) {
        v[k] = PyFloat_CheckExact(args[k]) ? PyFloat_AS_DOUBLE(args[k])
                                           : PyFloat_AsDouble(args[k]);
        if (v[k] == -1.0 && PyErr_Occurred())
            return NULL;
    }
    st = rr_hertz_bodies(v[0], v[1], v[2], v[3], v[4], v[5], v[6], &h);
    return Py_BuildValue("(ddddi)", h.a, h.b, h.p0, h.delta, st);
}

/* --------------------------------------------------------------- kalker */

static int kalker_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    elementwise *b = ctx;
    npy_intp i;
    for (i = start; i < stop; i++) {
        rr_kalker_coeffs k;
        b->st[i] = (npy_int8)rr_kalker(IN(b->in[0], i), IN(b->in[1], i), &k);
        b->out[0][i] = k.c11;
        b->out[1][i] = k.c22;
        b->out[2][i] = k.c23;
        b->out[3][i] = k.c33;
    }
    return 0;
}

/* The built-in exact-theory table: (shape, lo, hi, nu, r0, nx, the bytes of
 * its float32 values). */
static PyObject *py_exact_table_builtin(PyObject *self, PyObject *unused)
{
    const rr_exact_table *t = &rr_exact_table_builtin;
    const Py_ssize_t n = (Py_ssize_t)t->n[0] * t->n[1] * t->n[2] * t->n[3] * 3;
    (void)self;
    (void)unused;
    return Py_BuildValue("(iiii)(dddd)(dddd)ddiy#", t->n[0], t->n[1], t->n[2], t->n[3], t->lo[0],
                         t->lo[1], t->lo[2], t->lo[3], t->hi[0], t->hi[1], t->hi[2], t->hi[3],
                         t->nu, t->r0, t->nx, (const char *)t->v,
                         n * (Py_ssize_t)sizeof(float));
}

static PyObject *py_kalker(PyObject *self, PyObject *args)
{
    static const char *const names[] = {"a_over_b", "nu"};
    elementwise b;
    (void)self;
    return elementwise_call("kalker_coefficients", args, names, 2, 4, kalker_kernel, &b, 1.0);
}

/* --------------------------------------------------------- creep forces */

#define NCASE 12
static const char *const case_names[NCASE] = {"cx", "cy", "cphi", "a", "b", "N",
                                              "mu", "G", "nu", "speed", "A", "B"};

static void load_case(const input *in, npy_intp i, rr_contact_case *c, rr_friction *fr)
{
    c->cx = IN(in[0], i);
    c->cy = IN(in[1], i);
    c->cphi = IN(in[2], i);
    c->a = IN(in[3], i);
    c->b = IN(in[4], i);
    c->N = IN(in[5], i);
    fr->mu0 = IN(in[6], i);
    c->G = IN(in[7], i);
    c->nu = IN(in[8], i);
    c->speed = IN(in[9], i);
    fr->A = IN(in[10], i);
    fr->B = IN(in[11], i);
}

/* ---- creep-force options, parsed from the registry's descriptors ------- */

/* ", ".join of the quoted names */
static PyObject *quoted_names(const char *const *names, int n)
{
    PyObject *list = PyList_New(0), *sep, *res = NULL;
    int k;
    if (!list)
        return NULL;
    for (k = 0; k < n; k++) {
        PyObject *q = PyUnicode_FromFormat("'%s'", names[k]);
        if (!q || PyList_Append(list, q) < 0) {
            Py_XDECREF(q);
            Py_DECREF(list);
            return NULL;
        }
        Py_DECREF(q);
    }
    if ((sep = PyUnicode_FromString(", ")) != NULL) {
        res = PyUnicode_Join(sep, list);
        Py_DECREF(sep);
    }
    Py_DECREF(list);
    return res;
}

static PyObject *method_names(void)
{
    const char *names[RR_METHOD_COUNT];
    int k;
    for (k = 0; k < rr_method_count(); k++)
        names[k] = rr_method_get(k)->name;
    return quoted_names(names, rr_method_count());
}

static PyObject *option_names(const rr_method_desc *d)
{
    const char *names[RR_CREEP_MAX_OPTS];
    int k;
    for (k = 0; k < d->nopts; k++)
        names[k] = d->opts[k].name;
    return quoted_names(names, d->nopts);
}

static int choice_count(const rr_creep_option *op)
{
    int n = 0;
    while (op->choices[n])
        n++;
    return n;
}

/* A range end as Python writes the number ("1", "0.54", "inf"). */
static PyObject *number_str(double x)
{
    char *t = PyOS_double_to_string(x, 'r', 0, 0, NULL);
    PyObject *r;
    if (!t)
        return NULL;
    r = PyUnicode_FromString(t);
    PyMem_Free(t);
    return r;
}

/* ValueError: "func: name must be <what the option takes>, got value" */
static int option_error(const char *func, const rr_creep_option *op, PyObject *value)
{
    PyObject *lo = NULL, *hi = NULL, *names = NULL;
    if (op->type == RR_OPT_CHOICE) {
        if ((names = quoted_names(op->choices, choice_count(op))) != NULL)
            PyErr_Format(PyExc_ValueError, "%s: %s must be one of %U (or None: the default), "
                         "got %R", func, op->name, names, value);
    } else if ((lo = number_str(op->lo)) != NULL && (hi = number_str(op->hi)) != NULL) {
        PyErr_Format(PyExc_ValueError, "%s: %s must be %s in %s%U, %U%s, got %R", func, op->name,
                     op->type == RR_OPT_INT ? "an integer" : "a real number",
                     op->lo_open ? "(" : "[", lo, hi, op->hi_open ? ")" : "]", value);
    }
    Py_XDECREF(lo);
    Py_XDECREF(hi);
    Py_XDECREF(names);
    return -1;
}

/* One option's value from Python: None (the default), a choice's name, an
 * integer (never wrapped: 2**32 + 1 stays out of range) or a real; 0, or
 * -1 with a ValueError naming the option, its range and the value. */
static int option_value(PyObject *v, const char *func, const rr_creep_option *op, double *out)
{
    double x;
    if (v == Py_None) {
        *out = op->def;
        return 0;
    }
    if (op->type == RR_OPT_CHOICE) {
        int k;
        const char *name = PyUnicode_Check(v) ? PyUnicode_AsUTF8(v) : NULL;
        if (PyUnicode_Check(v) && !name)
            return -1;
        for (k = 0; name && op->choices[k]; k++)
            if (strcmp(name, op->choices[k]) == 0) {
                *out = k;
                return 0;
            }
        return option_error(func, op, v);
    }
    if (PyBool_Check(v) || PyUnicode_Check(v) || PyBytes_Check(v))
        return option_error(func, op, v);
    if (op->type == RR_OPT_INT) {
        PyObject *i;
        long n;
        int overflow = 0;
        if (!PyIndex_Check(v))
            return option_error(func, op, v);
        if (!(i = PyNumber_Index(v)))
            return -1;
        n = PyLong_AsLongAndOverflow(i, &overflow);
        Py_DECREF(i);
        if (n == -1 && PyErr_Occurred())
            return -1;
        if (overflow || n < -(1L << 30) || n > (1L << 30))
            return option_error(func, op, v);
        x = (double)n;
    } else {
        x = PyFloat_AsDouble(v);
        if (x == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();          /* not a number, or an int beyond the doubles */
            return option_error(func, op, v);
        }
    }
    if (rr_method_option_check(op, x) != RR_OK)
        return option_error(func, op, v);
    *out = x;
    return 0;
}

/* The method and its options from keywords: method= a name of the registry,
 * every other keyword (but own, the call's own keyword, or NULL) an option of
 * that method; then the method's constraints across options.  0, or -1 with
 * a ValueError naming the method, the option, its range and the value. */
static int parse_opts(PyObject *kwargs, const char *func, const char *own, rr_creep_opts *o)
{
    PyObject *v = kwargs ? PyDict_GetItemString(kwargs, "method") : NULL, *key, *names;
    const rr_method_desc *d;
    const char *mname = v && PyUnicode_Check(v) ? PyUnicode_AsUTF8(v) : NULL;
    Py_ssize_t pos = 0;
    int method, bad, st;

    if (v && PyUnicode_Check(v) && !mname)
        return -1;
    method = mname ? rr_method_find(mname) : RR_ERR_METHOD;
    if (method < 0) {
        if ((names = method_names()) != NULL) {
            if (v)
                PyErr_Format(PyExc_ValueError, "%s: method must be one of %U, got %R", func,
                             names, v);
            else
                PyErr_Format(PyExc_ValueError, "%s: method is required (one of %U)", func,
                             names);
            Py_DECREF(names);
        }
        return -1;
    }
    d = rr_method_get(method);
    rr_creep_opts_default(o, method);
    while (kwargs && PyDict_Next(kwargs, &pos, &key, &v)) {
        const char *name = PyUnicode_Check(key) ? PyUnicode_AsUTF8(key) : NULL;
        int i;
        if (!name)
            return PyErr_Occurred() ? -1 : (PyErr_SetString(PyExc_TypeError, "keywords must "
                                                            "be strings"), -1);
        if (strcmp(name, "method") == 0 || (own && strcmp(name, own) == 0))
            continue;
        if ((i = rr_method_option(d, name)) < 0) {
            if ((names = option_names(d)) != NULL) {
                if (d->nopts > 0)
                    PyErr_Format(PyExc_ValueError, "%s: method '%s' has no option %s (its "
                                 "options: %U), got %s=%R", func, d->name, name, names, name, v);
                else
                    PyErr_Format(PyExc_ValueError, "%s: method '%s' has no options, got %s=%R",
                                 func, d->name, name, v);
                Py_DECREF(names);
            }
            return -1;
        }
        if (option_value(v, func, &d->opts[i], &o->v[i]) < 0)
            return -1;
    }
    st = rr_creep_opts_check_at(o, &bad);
    if (st < 0) {
        /* each option passed its own range: a constraint across options */
        PyObject *got = PyUnicode_FromString(""), *part;
        int k;
        for (k = 0; got && k < d->nopts; k++) {
            PyObject *num = number_str(o->v[k]);
            part = num ? PyUnicode_FromFormat("%s%s = %U", k ? ", " : "", d->opts[k].name, num)
                       : NULL;
            Py_XDECREF(num);
            if (!part) {
                Py_CLEAR(got);
                break;
            }
            PyUnicode_Append(&got, part);
            Py_DECREF(part);
        }
        if (got) {
            PyErr_Format(PyExc_ValueError, "%s: %s must satisfy %s (method '%s'), got %U: %s",
                         func, bad >= 0 ? d->opts[bad].name : "the options",
                         d->check_doc ? d->check_doc : "the method's constraints", d->name, got,
                         rr_status_message(st));
            Py_DECREF(got);
        }
        return -1;
    }
    return 0;
}

/* check_creep_options(func, options): the options (a dict with method=)
 * checked as every call checks them, messages naming func; None, or a
 * ValueError. */
static PyObject *py_check_creep_options(PyObject *self, PyObject *args)
{
    const char *func;
    PyObject *d;
    rr_creep_opts o;
    (void)self;
    if (!PyArg_ParseTuple(args, "sO!:check_creep_options", &func, &PyDict_Type, &d))
        return NULL;
    if (parse_opts(d, func, NULL, &o) < 0)
        return NULL;
    Py_RETURN_NONE;
}

static int creep_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    elementwise *b = ctx;
    npy_intp i;
    for (i = start; i < stop; i++) {
        rr_contact_case c;
        rr_friction fr;
        rr_forces f;
        load_case(b->in, i, &c, &fr);
        b->st[i] = (npy_int8)rr_creep_forces_interruptible(&c, &fr, &b->o, b->work, b->work_len,
                                                           &b->stop.hook, &f);
        b->out[0][i] = f.fx;
        b->out[1][i] = f.fy;
        b->out[2][i] = f.mz;
        if (b->stop.stopped)
            return 1;         /* Ctrl-C: the exception is set, the batch ends */
    }
    return 0;
}

static PyObject *py_creep_forces(PyObject *self, PyObject *args, PyObject *kwargs)
{
    elementwise b;
    PyObject *res;
    (void)self;
    if (parse_opts(kwargs, "creep_forces", NULL, &b.o) < 0)
        return NULL;
    /* one workspace for the whole batch, zero-filled: a method may keep
     * what it can reuse from one case to the next there (the exact
     * solver's kernel spectra); each call, so each thread, has its own */
    b.work_len = rr_creep_workspace_len(&b.o);
    b.work = NULL;
    if (b.work_len > 0 && !(b.work = PyMem_Calloc(b.work_len, sizeof(double))))
        return PyErr_NoMemory();
    interrupt_hook_init(&b.stop);
    res = elementwise_call("creep_forces", args, case_names, NCASE, 3, creep_kernel, &b,
                           rr_creep_cost(&b.o));
    PyMem_Free(b.work);
    return res;
}

/* CreepOptions(**options): a method and its options, parsed and checked
 * once, for repeated scalar calls (creep_forces1). Immutable. */
typedef struct {
    PyObject_HEAD
    rr_creep_opts o;
    int ready;
} CreepOptionsObject;

static int CreepOptions_init(CreepOptionsObject *self, PyObject *args, PyObject *kwargs)
{
    self->ready = 0;
    if (PyTuple_GET_SIZE(args) != 0) {
        PyErr_SetString(PyExc_TypeError, "CreepOptions: options are keywords only");
        return -1;
    }
    if (parse_opts(kwargs, "creep_forces", NULL, &self->o) < 0)
        return -1;
    self->ready = 1;
    return 0;
}

static PyTypeObject CreepOptionsType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "rollerrig._core.CreepOptions",
    .tp_basicsize = sizeof(CreepOptionsObject),
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "CreepOptions(method=..., <options>): checked options for creep_forces1",
    .tp_init = (initproc)CreepOptions_init,
    .tp_new = PyType_GenericNew,
};

/* creep_forces1(opts, cx, cy, cphi, a, b, N, mu, G, nu, speed, A, B)
 * -> (fx, fy, mz, status): one case from Python numbers, the scalar path
 * (no arrays: the GIL is kept, a case takes microseconds at most). */
static PyObject *py_creep_forces1(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    double v[NCASE];
    rr_contact_case c;
    rr_friction fr;
    rr_forces f;
    int k, st;
    (void)self;
    if (nargs != NCASE + 1 || !PyObject_TypeCheck(args[0], &CreepOptionsType)
        || !((CreepOptionsObject *)args[0])->ready) {
        PyErr_Format(PyExc_TypeError, "creep_forces1: expected a CreepOptions and %d numbers",
                     NCASE);
        return NULL;
    }
    for (k = 0; k < NCASE; k++) {
        PyObject *x = args[k + 1];
        v[k] = PyFloat_CheckExact(x) ? PyFloat_AS_DOUBLE(x) : PyFloat_AsDouble(x);
        if (v[k] == -1.0 && PyErr_Occurred())
            return NULL;
    }
    c.cx = v[0];
    c.cy = v[1];
    c.cphi = v[2];
    c.a = v[3];
    c.b = v[4];
    c.N = v[5];
    fr.mu0 = v[6];
    c.G = v[7];
    c.nu = v[8];
    c.speed = v[9];
    fr.A = v[10];
    fr.B = v[11];
    {
        const rr_creep_opts *o = &((CreepOptionsObject *)args[0])->o;
        const size_t work_len = rr_creep_workspace_len(o);
        if (work_len == 0) {
            st = rr_creep_forces(&c, &fr, o, &f);
        } else {
            /* a method with a workspace is a long computation: the GIL is let
             * go, Ctrl-C noticed within the case */
            double *work = PyMem_Calloc(work_len, sizeof(double));
            interrupt_hook stop;
            if (!work)
                return PyErr_NoMemory();
            interrupt_hook_init(&stop);
            Py_BEGIN_ALLOW_THREADS
            st = rr_creep_forces_interruptible(&c, &fr, o, work, work_len, &stop.hook, &f);
            Py_END_ALLOW_THREADS
            PyMem_Free(work);
            if (stop.stopped)
                return NULL;
        }
    }
    return Py_BuildValue("(dddi)", f.fx, f.fy, f.mz, st);
}

typedef struct {
    rr_contact_case c;
    rr_friction fr;
    const rr_creep_opts *o;
    rr_forces f;
    rr_fastsim_field field;
    int st;
} fastsim_field_call;

static int fastsim_field_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    fastsim_field_call *k = ctx;
    (void)start;
    (void)stop;
    k->st = rr_creep_field(&k->c, &k->fr, k->o, &k->f, &k->field);
    return 0;
}

/* One case with its traction field (methods that have one, as the registry
 * says), arrays of shape (rows, cols) of the method's field_shape. */
static PyObject *py_fastsim_field(PyObject *self, PyObject *args, PyObject *kwargs)
{
    PyObject *objs[NCASE], *arr[7] = {NULL, NULL, NULL, NULL, NULL, NULL, NULL};
    input in[NCASE];
    rr_creep_opts o;
    const rr_method_desc *d;
    fastsim_field_call call;
    npy_intp n, dims[2];
    int k, rows, cols;
    (void)self;

    if (PyTuple_GET_SIZE(args) != NCASE) {
        PyErr_Format(PyExc_TypeError, "fastsim_field: expected %d arrays", NCASE);
        return NULL;
    }
    for (k = 0; k < NCASE; k++)
        objs[k] = PyTuple_GET_ITEM(args, k);
    if (parse_opts(kwargs, "fastsim_field", NULL, &o) < 0)
        return NULL;
    d = rr_method_get(o.method);
    if (!d->field) {
        const char *names[RR_METHOD_COUNT];
        PyObject *list;
        int m = 0;
        for (k = 0; k < rr_method_count(); k++)
            if (rr_method_get(k)->field)
                names[m++] = rr_method_get(k)->name;
        if ((list = quoted_names(names, m)) != NULL) {
            PyErr_Format(PyExc_ValueError, "fastsim_field: method must have a traction field "
                         "(%U), got '%s'", list, d->name);
            Py_DECREF(list);
        }
        return NULL;
    }
    if (parse_inputs("fastsim_field", objs, case_names, NCASE, &n, in) < 0)
        return NULL;
    if (n != 1) {
        PyErr_Format(PyExc_ValueError, "fastsim_field: one case expected, got %zd",
                     (Py_ssize_t)n);
        return NULL;
    }
    d->field_shape(&o, &rows, &cols);
    dims[0] = rows;
    dims[1] = cols;
    for (k = 0; k < 7; k++) {
        arr[k] = PyArray_SimpleNew(2, dims, k != 5 ? NPY_DOUBLE : NPY_INT8);
        if (!arr[k])
            goto fail;
    }
    call.field.x = OUT(arr[0]);
    call.field.y = OUT(arr[1]);
    call.field.pn = OUT(arr[2]);
    call.field.px = OUT(arr[3]);
    call.field.py = OUT(arr[4]);
    call.field.slip = (signed char *)PyArray_DATA((PyArrayObject *)arr[5]);
    call.field.area = OUT(arr[6]);
    load_case(in, 0, &call.c, &call.fr);
    call.o = &o;
    if (run_batch(fastsim_field_kernel, &call, 1, 1.0) < 0)
        goto fail;
    return Py_BuildValue("(dddiNNNNNNN)", call.f.fx, call.f.fy, call.f.mz, call.st, arr[0],
                         arr[1], arr[2], arr[3], arr[4], arr[5], arr[6]);
fail:
    release(arr, 7);
    return NULL;
}


/* ------------------------------------------------------------ exact theory */

/* exact_hertz_problem(<as creep_forces, one case>, method="exact", <options>)
 * -> (status, mx, my, dx, dy, x0, y0, A, B, N, G, nu, mu, cx, cy, cphi,
 * spin_shift, tol, maxit): the problem rr_exact_solve gets for a Hertzian
 * case (rr_exact_hertz_problem), for exact_solve and its field. */
static PyObject *py_exact_hertz_problem(PyObject *self, PyObject *args, PyObject *kwargs)
{
    PyObject *objs[NCASE];
    input in[NCASE];
    rr_creep_opts o;
    rr_contact_case c;
    rr_friction fr;
    rr_exact_problem pb;
    npy_intp n;
    int k, st;
    (void)self;

    if (PyTuple_GET_SIZE(args) != NCASE) {
        PyErr_Format(PyExc_TypeError, "exact_hertz_problem: expected %d arrays", NCASE);
        return NULL;
    }
    for (k = 0; k < NCASE; k++)
        objs[k] = PyTuple_GET_ITEM(args, k);
    if (parse_opts(kwargs, "exact_field", NULL, &o) < 0)
        return NULL;
    if (o.method != RR_METHOD_EXACT) {
        PyErr_Format(PyExc_ValueError, "exact_field: method must be 'exact', got '%s'",
                     rr_method_get(o.method)->name);
        return NULL;
    }
    if (parse_inputs("exact_field", objs, case_names, NCASE, &n, in) < 0)
        return NULL;
    if (n != 1) {
        PyErr_Format(PyExc_ValueError, "exact_field: one case expected, got %zd",
                     (Py_ssize_t)n);
        return NULL;
    }
    load_case(in, 0, &c, &fr);
    st = rr_exact_hertz_problem(&c, &fr, &o, &pb);
    return Py_BuildValue("(iiidddddddddddddddi)", st, pb.grid.mx, pb.grid.my, pb.grid.dx,
                         pb.grid.dy, pb.grid.x0, pb.grid.y0, pb.A, pb.B, pb.N, pb.G, pb.nu,
                         pb.mu, pb.cx, pb.cy, pb.cphi, pb.spin_shift, pb.tol, pb.maxit);
}

typedef struct {
    rr_exact_problem pb;
    double *work;
    size_t work_len;
    rr_exact_result res;
    rr_exact_field field;
    interrupt_hook stop;
    int st;
} exact_call;

static int exact_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    exact_call *k = ctx;
    (void)start;
    (void)stop;
    k->st = rr_exact_solve(&k->pb, k->work, k->work_len, &k->res, &k->field);
    return 0;
}

/* exact_solve(mx, my, dx, dy, x0, y0, h, A, B, N, G, nu, mu, cx, cy, cphi,
 * spin_shift, tol, maxit) -> (status, (fx, fy, mz, fn, delta, area, pmax,
 * ncontact, nslip, normal_products, tang_products, newton_steps,
 * normal_residual, tang_residual), pn, px, py, sx, sy, state): one case of
 * rr_exact_solve with its fields, arrays of shape (my, mx); h None for the
 * Hertzian A x^2 + B y^2, else an array of my x mx values. */
static PyObject *py_exact_solve(PyObject *self, PyObject *args)
{
    exact_call call;
    rr_exact_problem *pb = &call.pb;
    PyObject *hobj, *arr[6] = {NULL, NULL, NULL, NULL, NULL, NULL}, *res;
    PyArrayObject *h = NULL;
    npy_intp dims[2];
    int k;
    (void)self;

    memset(&call, 0, sizeof call);
    if (!PyArg_ParseTuple(args, "iiddddOdddddddddddi:exact_solve", &pb->grid.mx, &pb->grid.my,
                          &pb->grid.dx, &pb->grid.dy, &pb->grid.x0, &pb->grid.y0, &hobj,
                          &pb->A, &pb->B, &pb->N, &pb->G, &pb->nu, &pb->mu, &pb->cx, &pb->cy,
                          &pb->cphi, &pb->spin_shift, &pb->tol, &pb->maxit))
        return NULL;
    if (pb->grid.mx < 1 || pb->grid.my < 1 || pb->grid.mx > RR_EXACT_MAX_GRID
        || pb->grid.my > RR_EXACT_MAX_GRID) {
        PyErr_Format(PyExc_ValueError, "exact_solve: the grid must have 1 to %d elements a "
                     "side, got %d x %d", RR_EXACT_MAX_GRID, pb->grid.mx, pb->grid.my);
        return NULL;
    }
    dims[0] = pb->grid.my;
    dims[1] = pb->grid.mx;
    if (hobj != Py_None) {
        h = (PyArrayObject *)PyArray_FROMANY(hobj, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
        if (!h)
            return NULL;
        if (PyArray_DIM(h, 0) != dims[0] || PyArray_DIM(h, 1) != dims[1]) {
            PyErr_Format(PyExc_ValueError, "exact_solve: h must have shape (%d, %d) (my, mx), "
                         "got (%zd, %zd)", pb->grid.my, pb->grid.mx,
                         (Py_ssize_t)PyArray_DIM(h, 0), (Py_ssize_t)PyArray_DIM(h, 1));
            Py_DECREF(h);
            return NULL;
        }
        pb->h = (const double *)PyArray_DATA(h);
    }
    for (k = 0; k < 6; k++)
        if (!(arr[k] = PyArray_SimpleNew(2, dims, k < 5 ? NPY_DOUBLE : NPY_INT8)))
            goto fail;
    call.field.pn = OUT(arr[0]);
    call.field.px = OUT(arr[1]);
    call.field.py = OUT(arr[2]);
    call.field.sx = OUT(arr[3]);
    call.field.sy = OUT(arr[4]);
    call.field.state = (signed char *)PyArray_DATA((PyArrayObject *)arr[5]);
    call.work_len = rr_exact_workspace_len(pb->grid.mx, pb->grid.my);
    if (!(call.work = PyMem_Calloc(call.work_len, sizeof(double)))) {
        PyErr_NoMemory();
        goto fail;
    }
    interrupt_hook_init(&call.stop);
    pb->interrupt = &call.stop.hook;
    k = run_batch(exact_kernel, &call, 1, 1.0);
    PyMem_Free(call.work);
    if (k < 0)
        goto fail;
    Py_XDECREF(h);
    {
        const rr_exact_result *r = &call.res;
        res = Py_BuildValue("(i(dddddddiiiiidd)NNNNNN)", call.st, r->fx, r->fy, r->mz, r->fn,
                            r->delta, r->area, r->pmax, r->ncontact, r->nslip,
                            r->normal_products, r->tang_products, r->newton_steps,
                            r->normal_residual, r->tang_residual, arr[0], arr[1], arr[2],
                            arr[3], arr[4], arr[5]);
    }
    return res;
fail:
    Py_XDECREF(h);
    release(arr, 6);
    return NULL;
}

/* ------------------------------------------------------- contact geometry */

/* A 1-D contiguous float64 array of at least 2 elements, or NULL with an
 * exception naming the argument. */
static PyArrayObject *profile_array(PyObject *obj, const char *name)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 1, 1,
                                                          NPY_ARRAY_IN_ARRAY);
    if (!a)
        return NULL;
    if (PyArray_DIM(a, 0) < 2) {
        PyErr_Format(PyExc_ValueError, "wheelset_contact: %s needs at least 2 points", name);
        Py_DECREF(a);
        return NULL;
    }
    return a;
}

#define NGEO 11   /* per side: y z s_wheel s_roller r R delta A B gap two_point */
#define NPROF 12  /* knots, values, second derivatives of four profiles */

/* The four profiles (each its spline: knots, values, second derivatives,
 * the Profile's own, so that Python and C evaluate the same curve) and the
 * eight placement parameters (r0, R0, wheel_y, roller_y per side) as the two
 * wheel-roller pairs; prof[] keeps the arrays alive.  0, or -1 with an
 * exception set. */
static int parse_pairs(PyObject *const *pobj, const double *par, const char *func,
                       PyArrayObject **prof, rr_wheel_roller *pair)
{
    static const char *const pnames[4] = {"wheel_left", "roller_left", "wheel_right",
                                          "roller_right"};
    int k;
    for (k = 0; k < NPROF; k++)
        if (!(prof[k] = profile_array(pobj[k], pnames[k / 3])))
            return -1;
    for (k = 0; k < 4; k++) {
        const npy_intp len = PyArray_DIM(prof[3 * k], 0);
        const double *sv = (const double *)PyArray_DATA(prof[3 * k]);
        rr_wheel_roller *p = &pair[k / 2];
        rr_spline *sp = k % 2 == 0 ? &p->wheel : &p->roller;
        npy_intp j;
        if (PyArray_DIM(prof[3 * k + 1], 0) != len || PyArray_DIM(prof[3 * k + 2], 0) != len) {
            PyErr_Format(PyExc_ValueError, "%s: %s: knots, values and second derivatives "
                         "differ in length", func, pnames[k]);
            return -1;
        }
        for (j = 1; j < len; j++)
            if (!(sv[j] > sv[j - 1])) {
                PyErr_Format(PyExc_ValueError, "%s: %s: knots not strictly increasing", func,
                             pnames[k]);
                return -1;
            }
        sp->n = (int)len;
        sp->s = sv;
        sp->z = (const double *)PyArray_DATA(prof[3 * k + 1]);
        sp->m = (const double *)PyArray_DATA(prof[3 * k + 2]);
    }
    for (k = 0; k < 2; k++) {
        pair[k].r0 = par[4 * k];
        pair[k].R0 = par[4 * k + 1];
        pair[k].wheel_y = par[4 * k + 2];
        pair[k].roller_y = par[4 * k + 3];
        pair[k].side = k == 0 ? 1 : -1;
    }
    return 0;
}

#define PAIR_FORMAT "OOOOOOOOOOOO(dddddddd)"
#define PAIR_ARGS(pobj, par) &pobj[0], &pobj[1], &pobj[2], &pobj[3], &pobj[4], &pobj[5], \
    &pobj[6], &pobj[7], &pobj[8], &pobj[9], &pobj[10], &pobj[11], &par[0], &par[1], &par[2], \
    &par[3], &par[4], &par[5], &par[6], &par[7]

/* One side's geometry into column i of a [NGEO, n] block. */
static void store_geo(double *d, npy_intp n, npy_intp i, const rr_contact_point *q)
{
    const double v[NGEO] = {q->y, q->z, q->s_wheel, q->s_roller, q->r, q->R,
                            q->delta, q->A, q->B, q->gap, (double)q->two_point};
    int k;
    for (k = 0; k < NGEO; k++)
        d[k * n + i] = v[k];
}

/* The search options from Python objects, nsamples range-checked. */
static int parse_search(PyObject *nobj, double tol, double sep, const char *func,
                        rr_search_opts *o)
{
    if (int_arg(nobj, func, "nsamples", 3, RR_SEARCH_MAX_SAMPLES, &o->nsamples) < 0)
        return -1;
    o->two_point_tol = tol;
    o->two_point_sep = sep;
    return 0;
}

/* Work units of one search: about 4 nsamples profile probes. */
static double search_cost(const rr_search_opts *o)
{
    return 4.0 * o->nsamples;
}

typedef struct {
    const rr_wheel_roller *pair;
    const rr_search_opts *o;
    const double *y;
    npy_intp n;
    npy_int8 *status;
    double *z, *roll, *left, *right;
} search_batch;

static int search_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    search_batch *b = ctx;
    npy_intp i;
    for (i = start; i < stop; i++) {
        rr_wheelset_pose pose;
        rr_contact_point c[2];
        b->status[i] = (npy_int8)rr_wheelset_contact(&b->pair[0], &b->pair[1], b->y[i], b->o,
                                                     &pose, &c[0], &c[1]);
        b->z[i] = pose.z;
        b->roll[i] = pose.roll;
        store_geo(b->left, b->n, i, &c[0]);
        store_geo(b->right, b->n, i, &c[1]);
    }
    return 0;
}

/* wheelset_contact(12 profile arrays, params (8 floats), y_ws, nsamples,
 * two_point_tol, two_point_sep) -> (status, z, roll, left[NGEO, n], right[NGEO, n]). */
static PyObject *py_wheelset_contact(PyObject *self, PyObject *args)
{
    PyObject *pobj[NPROF], *yobj, *nobj, *out[5] = {NULL, NULL, NULL, NULL, NULL}, *res;
    PyArrayObject *prof[NPROF], *yarr = NULL;
    double par[8], tol, sep;
    rr_wheel_roller pair[2];
    rr_search_opts o;
    search_batch b;
    npy_intp n, dims[2];
    int k;
    (void)self;

    for (k = 0; k < NPROF; k++)
        prof[k] = NULL;
    if (!PyArg_ParseTuple(args, PAIR_FORMAT "OOdd:wheelset_contact", PAIR_ARGS(pobj, par),
                          &yobj, &nobj, &tol, &sep))
        return NULL;
    if (parse_search(nobj, tol, sep, "wheelset_contact", &o) < 0
        || parse_pairs(pobj, par, "wheelset_contact", prof, pair) < 0)
        goto fail;
    if (!(yarr = (PyArrayObject *)PyArray_FROMANY(yobj, NPY_DOUBLE, 1, 1, NPY_ARRAY_IN_ARRAY)))
        goto fail;
    n = PyArray_DIM(yarr, 0);
    dims[0] = NGEO;
    dims[1] = n;
    out[0] = PyArray_SimpleNew(1, &n, NPY_INT8);
    out[1] = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    out[2] = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    out[3] = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    out[4] = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    for (k = 0; k < 5; k++)
        if (!out[k])
            goto fail;
    b.pair = pair;
    b.o = &o;
    b.y = (const double *)PyArray_DATA(yarr);
    b.n = n;
    b.status = OUT8(out[0]);
    b.z = OUT(out[1]);
    b.roll = OUT(out[2]);
    b.left = OUT(out[3]);
    b.right = OUT(out[4]);
    if (run_batch(search_kernel, &b, n, search_cost(&o)) < 0)
        goto fail;
    release((PyObject **)prof, NPROF);
    Py_DECREF(yarr);
    if ((res = outputs_tuple(out, 5)) != NULL)
        return res;
    release(out, 5);
    return NULL;
fail:
    release((PyObject **)prof, NPROF);
    Py_XDECREF(yarr);
    release(out, 5);
    return NULL;
}

typedef struct {
    const rr_wheel_roller *pair;
    const rr_search_opts *o;
    rr_contact_table *t;
    int st;
    double bad_y;
} table_batch;

/* rows [start, stop) of the table; the first error stops the build */
static int table_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    table_batch *b = ctx;
    b->st = rr_contact_table_build_rows(&b->pair[0], &b->pair[1], b->o, b->t, (int)start,
                                        (int)stop, &b->bad_y);
    return b->st < 0;
}

/* contact_table(12 profile arrays, params, y0, dy, n, nsamples, tol, sep)
 * -> (data, status, bad_y): the C core's table rows, built in chunks of rows
 * with the GIL released, Ctrl-C noticed between them. */
static PyObject *py_contact_table(PyObject *self, PyObject *args)
{
    PyObject *pobj[NPROF], *rows, *nobj, *data = NULL;
    PyArrayObject *prof[NPROF];
    double par[8], tol, sep;
    rr_wheel_roller pair[2];
    rr_search_opts o;
    rr_contact_table t;
    table_batch b;
    npy_intp len;
    int k;
    (void)self;

    for (k = 0; k < NPROF; k++)
        prof[k] = NULL;
    if (!PyArg_ParseTuple(args, PAIR_FORMAT "ddOOdd:contact_table", PAIR_ARGS(pobj, par),
                          &t.y0, &t.dy, &rows, &nobj, &tol, &sep))
        return NULL;
    if (int_arg(rows, "contact_table", "n", 2, 10000000, &t.n) < 0)
        return NULL;
    if (parse_search(nobj, tol, sep, "contact_table", &o) < 0
        || parse_pairs(pobj, par, "contact_table", prof, pair) < 0)
        goto fail;
    len = (npy_intp)rr_contact_table_len(t.n);
    if (!(data = PyArray_SimpleNew(1, &len, NPY_DOUBLE)))
        goto fail;
    t.data = OUT(data);
    b.pair = pair;
    b.o = &o;
    b.t = &t;
    b.st = RR_OK;
    b.bad_y = NAN;
    /* a row is one wheelset solve */
    if (run_batch(table_kernel, &b, t.n, search_cost(&o)) < 0)
        goto fail;
    release((PyObject **)prof, NPROF);
    return Py_BuildValue("Nid", data, b.st, b.bad_y);
fail:
    release((PyObject **)prof, NPROF);
    Py_XDECREF(data);
    return NULL;
}

/* The table from its Python parts: rows as a 1-D float64 array. */
static int parse_table(PyObject *obj, double y0, double dy, const char *func,
                       rr_contact_table *t)
{
    PyArrayObject *a;
    npy_intp rowlen = (npy_intp)rr_contact_table_len(1);
    if (!PyArray_Check(obj) || PyArray_TYPE((PyArrayObject *)obj) != NPY_DOUBLE
        || PyArray_NDIM((PyArrayObject *)obj) != 1
        || !PyArray_IS_C_CONTIGUOUS((PyArrayObject *)obj)) {
        PyErr_Format(PyExc_ValueError, "%s: the table data must be a contiguous 1-D float64 "
                     "array", func);
        return -1;
    }
    a = (PyArrayObject *)obj;
    if (PyArray_DIM(a, 0) % rowlen != 0 || PyArray_DIM(a, 0) < 2 * rowlen
        || PyArray_DIM(a, 0) / rowlen > INT_MAX) {
        PyErr_Format(PyExc_ValueError, "%s: the table data has %zd values, not a whole number "
                     "(>= 2) of %zd-value rows", func, (Py_ssize_t)PyArray_DIM(a, 0),
                     (Py_ssize_t)rowlen);
        return -1;
    }
    if (!(isfinite(y0) && isfinite(dy) && dy > 0.0)) {
        PyErr_Format(PyExc_ValueError, "%s: table y0, dy must be finite with dy > 0, got %g, %g",
                     func, y0, dy);
        return -1;
    }
    t->y0 = y0;
    t->dy = dy;
    t->n = (int)(PyArray_DIM(a, 0) / rowlen);
    t->data = (double *)PyArray_DATA(a);
    return 0;
}

typedef struct {
    const rr_contact_table *t;
    const double *y;
    npy_intp n;
    npy_int8 *status;
    double *z, *roll, *dz, *droll, *left, *right;
} lookup_batch;

static int lookup_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    lookup_batch *b = ctx;
    npy_intp i;
    for (i = start; i < stop; i++) {
        rr_wheelset_pose pose, slope;
        rr_contact_point c[2];
        b->status[i] = (npy_int8)rr_contact_table_lookup(b->t, b->y[i], &pose, &slope, &c[0],
                                                         &c[1]);
        b->z[i] = pose.z;
        b->roll[i] = pose.roll;
        b->dz[i] = slope.z;
        b->droll[i] = slope.roll;
        store_geo(b->left, b->n, i, &c[0]);
        store_geo(b->right, b->n, i, &c[1]);
    }
    return 0;
}

/* table_lookup(data, y0, dy, y) -> (status, z, roll, dz_dy, droll_dy, left, right) */
static PyObject *py_table_lookup(PyObject *self, PyObject *args)
{
    PyObject *dobj, *yobj, *out[7] = {NULL, NULL, NULL, NULL, NULL, NULL, NULL}, *res;
    PyArrayObject *yarr = NULL;
    rr_contact_table t;
    lookup_batch b;
    double y0, dy;
    npy_intp n, dims[2];
    int k;
    (void)self;

    if (!PyArg_ParseTuple(args, "OddO:table_lookup", &dobj, &y0, &dy, &yobj))
        return NULL;
    if (parse_table(dobj, y0, dy, "table_lookup", &t) < 0)
        return NULL;
    if (!(yarr = (PyArrayObject *)PyArray_FROMANY(yobj, NPY_DOUBLE, 1, 1, NPY_ARRAY_IN_ARRAY)))
        return NULL;
    n = PyArray_DIM(yarr, 0);
    dims[0] = NGEO;
    dims[1] = n;
    out[0] = PyArray_SimpleNew(1, &n, NPY_INT8);
    for (k = 1; k < 5; k++)
        out[k] = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    out[5] = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    out[6] = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    for (k = 0; k < 7; k++)
        if (!out[k])
            goto fail;
    b.t = &t;
    b.y = (const double *)PyArray_DATA(yarr);
    b.n = n;
    b.status = OUT8(out[0]);
    b.z = OUT(out[1]);
    b.roll = OUT(out[2]);
    b.dz = OUT(out[3]);
    b.droll = OUT(out[4]);
    b.left = OUT(out[5]);
    b.right = OUT(out[6]);
    /* a lookup costs a few dozen flops */
    if (run_batch(lookup_kernel, &b, n, 1.0) < 0)
        goto fail;
    Py_DECREF(yarr);
    yarr = NULL;
    if ((res = outputs_tuple(out, 7)) != NULL)
        return res;
fail:
    Py_XDECREF(yarr);
    release(out, 7);
    return NULL;
}

/* ---------------------------------------------------- rig contact */

#define NSTATE 10
static const char *const state_names[NSTATE] = {"x", "y", "yaw", "vx", "vy", "yaw_rate",
                                                "spin", "roller_spin", "N_left", "N_right"};
#define NPOSE 11   /* c[3] roll beta v[3] w[3] */
#define NWHEEL RR_WHEEL_NVALUES   /* the fields of rr_wheel_field (RIG_WHEEL_FIELDS) */

static void store_wheel(double *d, npy_intp n, npy_intp i, const rr_wheel_contact *w)
{
    rr_wheel_store(w, d + i, (long)n);
}

typedef struct {
    input in[NSTATE];
    const rr_rig_contact_model *m;
    int kin_only;
    npy_intp n;
    npy_int8 *status, *left_status, *right_status;
    double *pose, *left, *right;
} rig_contact_batch;

static int rig_contact_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    rig_contact_batch *b = ctx;
    npy_intp i;
    int k;
    for (i = start; i < stop; i++) {
        rr_rig_state s;
        rr_rig_pose pose;
        rr_wheel_contact w[2];
        double N[2];
        s.x = IN(b->in[0], i);
        s.y = IN(b->in[1], i);
        s.yaw = IN(b->in[2], i);
        s.vx = IN(b->in[3], i);
        s.vy = IN(b->in[4], i);
        s.yaw_rate = IN(b->in[5], i);
        s.spin = IN(b->in[6], i);
        s.roller_spin = IN(b->in[7], i);
        N[0] = IN(b->in[8], i);
        N[1] = IN(b->in[9], i);
        if (b->kin_only) {
            b->status[i] = (npy_int8)rr_rig_kinematics(b->m, &s, &pose, w);
            for (k = 0; k < 2; k++) {
                w[k].N = w[k].hertz.a = w[k].hertz.b = w[k].hertz.p0 = NAN;
                w[k].f.fx = w[k].f.fy = w[k].f.mz = NAN;
                w[k].force[0] = w[k].force[1] = w[k].force[2] = NAN;
                w[k].moment[0] = w[k].moment[1] = w[k].moment[2] = NAN;
            }
        } else {
            b->status[i] = (npy_int8)rr_rig_contact(b->m, &s, N, &pose, w);
        }
        b->left_status[i] = (npy_int8)w[0].status;
        b->right_status[i] = (npy_int8)w[1].status;
        {
            const double pv[NPOSE] = {pose.c[0], pose.c[1], pose.c[2], pose.roll, pose.beta,
                                      pose.v[0], pose.v[1], pose.v[2], pose.w[0], pose.w[1],
                                      pose.w[2]};
            for (k = 0; k < NPOSE; k++)
                b->pose[k * b->n + i] = pv[k];
        }
        store_wheel(b->left, b->n, i, &w[0]);
        store_wheel(b->right, b->n, i, &w[1]);
    }
    return 0;
}

/* rig_contact(data, y0, dy, (R0, estar, G, nu, mu0, A, B, vmin), 10 state arrays, *,
 *             kinematics_only, <creep options>)
 * -> (status, pose[NPOSE, n], left[NWHEEL, n], right[NWHEEL, n], left_status, right_status) */
static PyObject *py_rig_contact(PyObject *self, PyObject *args, PyObject *kwargs)
{
    PyObject *dobj, *objs[NSTATE], *out[6] = {NULL, NULL, NULL, NULL, NULL, NULL}, *res, *v;
    rig_contact_batch b;
    rr_contact_table t;
    rr_rig_contact_model m;
    double y0, dy;
    npy_intp n, dims[2];
    int k, kin_only = 0;
    (void)self;

    if (!PyArg_ParseTuple(args, "Odd(dddddddd)OOOOOOOOOO:rig_contact", &dobj, &y0, &dy, &m.R0,
                          &m.estar, &m.G, &m.nu, &m.friction.mu0, &m.friction.A,
                          &m.friction.B, &m.vmin, &objs[0], &objs[1], &objs[2], &objs[3],
                          &objs[4], &objs[5], &objs[6], &objs[7], &objs[8], &objs[9]))
        return NULL;
    if (parse_table(dobj, y0, dy, "rig_contact", &t) < 0)
        return NULL;
    m.table = &t;
    if (kwargs && (v = PyDict_GetItemString(kwargs, "kinematics_only")) != NULL) {
        kin_only = PyObject_IsTrue(v);
        if (kin_only < 0)
            return NULL;
    }
    if (parse_opts(kwargs, "rig_contact", "kinematics_only", &m.creep) < 0)
        return NULL;
    {
        int st = rr_rig_contact_check(&m);
        if (st < 0) {
            PyErr_Format(PyExc_ValueError, "rig_contact: invalid model: %s",
                         rr_status_message(st));
            return NULL;
        }
    }
    if (parse_inputs("rig_contact", objs, state_names, NSTATE, &n, b.in) < 0)
        return NULL;
    dims[1] = n;
    out[0] = PyArray_SimpleNew(1, &n, NPY_INT8);
    dims[0] = NPOSE;
    out[1] = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    dims[0] = NWHEEL;
    out[2] = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    out[3] = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    out[4] = PyArray_SimpleNew(1, &n, NPY_INT8);
    out[5] = PyArray_SimpleNew(1, &n, NPY_INT8);
    for (k = 0; k < 6; k++)
        if (!out[k])
            goto fail;
    b.m = &m;
    b.kin_only = kin_only;
    b.n = n;
    b.status = OUT8(out[0]);
    b.pose = OUT(out[1]);
    b.left = OUT(out[2]);
    b.right = OUT(out[3]);
    b.left_status = OUT8(out[4]);
    b.right_status = OUT8(out[5]);
    /* two contacts a case, plus the kinematics (about 8 closed-form cases' work) */
    if (run_batch(rig_contact_kernel, &b, n,
                  kin_only ? 8.0 : 8.0 + 2.0 * rr_creep_cost(&m.creep)) < 0)
        goto fail;
    if ((res = outputs_tuple(out, 6)) != NULL)
        return res;
fail:
    release(out, 6);
    return NULL;
}

/* ------------------------------------------------------------- the rig */

/* A rig in time: rr_rig_params and rr_rig, with the contact table it reads.
 * One user at a time: run() releases the GIL while the C rig steps, so every
 * method (and __init__) refuses while another thread is inside one (busy,
 * set and read under the GIL); a rig whose __init__ never succeeded (or
 * whose last __init__ failed) refuses every method. */
typedef struct {
    PyObject_HEAD
    PyObject *data;            /* the table's rows, kept alive */
    rr_contact_table table;
    rr_rig_params p;
    rr_rig rig;
    int ready;                 /* 1 after a successful __init__ */
    int busy;                  /* 1 while a method works on the rig */
} RigObject;

/* The rig's primary values (rr_rig_config) from a dict {"section.key": value}
 * of rr_rig_params.h's rows (any subset: the rest keep their defaults); a
 * creep row is refused (its value goes through the creep options), and so
 * is an unknown name or a bad value, naming both. */
static int rig_config_from(PyObject *d, rr_rig_config *c)
{
    PyObject *key, *v;
    Py_ssize_t pos = 0;
    rr_rig_config_default(c);
    while (PyDict_Next(d, &pos, &key, &v)) {
        const char *name = PyUnicode_Check(key) ? PyUnicode_AsUTF8(key) : NULL;
        const rr_rig_param *row = name ? rr_rig_param_find(name) : NULL;
        int st;
        if (!row || row->creep) {
            if (!PyErr_Occurred())
                PyErr_Format(PyExc_ValueError, "Rig: %R is not a rig parameter%s", key,
                             row ? " (a creep-force option: give it with the creep options)"
                                 : "");
            return -1;
        }
        if (row->type == RR_RIG_LIST) {
            double vals[RR_RIG_MAX_LIST];
            PyObject *seq = PySequence_Fast(v, "a list");
            Py_ssize_t k, n;
            if (!seq) {
                PyErr_Format(PyExc_ValueError, "Rig: %s must be a list of numbers, got %R",
                             name, v);
                return -1;
            }
            n = PySequence_Fast_GET_SIZE(seq);
            for (k = 0; k < n && k < RR_RIG_MAX_LIST; k++) {
                vals[k] = PyFloat_AsDouble(PySequence_Fast_GET_ITEM(seq, k));
                if (vals[k] == -1.0 && PyErr_Occurred()) {
                    Py_DECREF(seq);
                    return -1;
                }
            }
            Py_DECREF(seq);
            st = n > RR_RIG_MAX_LIST ? RR_ERR_PARAM
                                     : rr_rig_config_set_list(c, name, (int)n, vals);
        } else if (row->type == RR_RIG_CHOICE) {
            const char *text = PyUnicode_Check(v) ? PyUnicode_AsUTF8(v) : NULL;
            if (!text && PyErr_Occurred())
                return -1;
            st = text ? rr_rig_config_set_choice(c, name, text) : RR_ERR_PARAM;
        } else if (row->type != RR_RIG_REAL && !PyLong_Check(v)) {
            st = RR_ERR_PARAM;                  /* ints and flags (bool is an int) */
        } else {
            double x = PyFloat_AsDouble(v);
            if (x == -1.0 && PyErr_Occurred())
                return -1;
            st = rr_rig_config_set(c, name, x);
        }
        if (st != RR_OK) {
            PyErr_Format(PyExc_ValueError, "Rig: %s = %R: %s", name, v, rr_status_message(st));
            return -1;
        }
    }
    return 0;
}

/* Enter a method: 0, or -1 with RuntimeError if the rig is not initialised
 * or another thread is using it.  Under the GIL, so the test-and-set is
 * atomic. */
static int rig_enter(RigObject *self, const char *method)
{
    if (self->busy) {
        PyErr_Format(PyExc_RuntimeError, "Rig.%s: the rig is in use by another thread (one "
                     "Rig, one thread at a time)", method);
        return -1;
    }
    if (!self->ready) {
        PyErr_Format(PyExc_RuntimeError, "Rig.%s: the rig is not initialised (construct it "
                     "with Rig(...), e.g. rollerrig.build_rig(); a failed __init__ leaves it "
                     "so)", method);
        return -1;
    }
    self->busy = 1;
    return 0;
}

static void rig_leave(RigObject *self)
{
    self->busy = 0;
}

static void Rig_dealloc(RigObject *self)
{
    Py_XDECREF(self->data);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

/* Rig(data, y0, dy, params, creep, roller_speed): params {"section.key": value}
 * (rig_config_from), the rig's parameters derived by rr_rig_params_from */
static int Rig_init(RigObject *self, PyObject *args, PyObject *kwargs)
{
    PyObject *dobj, *params, *creep;
    double y0, dy, roller_speed;
    int st;
    (void)kwargs;
    if (self->busy) {
        PyErr_SetString(PyExc_RuntimeError, "Rig.__init__: the rig is in use by another thread");
        return -1;
    }
    /* from here on, until success, the rig is not usable */
    self->ready = 0;
    if (!PyArg_ParseTuple(args, "OddO!O!d:Rig", &dobj, &y0, &dy, &PyDict_Type, &params,
                          &PyDict_Type, &creep, &roller_speed))
        return -1;
    if (parse_table(dobj, y0, dy, "Rig", &self->table) < 0)
        return -1;
    {
        rr_rig_config c;
        const char *bad = NULL;
        if (rig_config_from(params, &c) < 0)
            return -1;
        st = rr_rig_params_from(&c, &self->table, &self->p);
        if (st < 0) {
            rr_rig_config_check(&c, &bad);
            PyErr_Format(PyExc_ValueError, "Rig: %s%s%s", bad ? bad : "", bad ? ": " : "",
                         rr_status_message(st));
            return -1;
        }
    }
    if (parse_opts(creep, "Rig", NULL, &self->p.contact.creep) < 0)
        return -1;
    Py_INCREF(dobj);
    Py_XSETREF(self->data, dobj);
    st = rr_rig_init(&self->p, roller_speed, &self->rig);
    if (st < 0) {
        PyErr_Format(PyExc_ValueError, "Rig: %s", rr_status_message(st));
        return -1;
    }
    self->ready = 1;
    return 0;
}

static PyObject *new_record(double **rec)
{
    npy_intp n = RR_REC_COUNT;
    PyObject *a = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    if (a)
        *rec = OUT(a);
    return a;
}

typedef struct {
    rr_rig *rig;
    const double *roller_ref, *xi_ref;
    double *rec;
    int worst;
} run_batch_ctx;

/* samples [start, stop); the run's status is its error, else its worst warning */
static int run_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    run_batch_ctx *b = ctx;
    int st = RR_OK;
    rr_rig_run(b->rig, (long)(stop - start), b->roller_ref + start, b->xi_ref + start,
               b->rec + start * RR_REC_COUNT, &st);
    if (st < 0 || st > b->worst)
        b->worst = st;
    return st < 0;
}

/* A rig sample costs about 10 us: 256 of them between Ctrl-C checks. */
#define SAMPLE_COST (CHUNK_WORK / 256.0)

/* run(roller_ref, xi_ref[, out]) -> (records[n, RR_REC_COUNT], status):
 * rr_rig_run, one sample per element, in chunks (GIL released, Ctrl-C
 * noticed between them); stops at the first error (its row has the
 * status, the rest NaN).  out: a C-contiguous float64 array of that shape
 * to write the records into (returned), else a new one. */
static PyObject *Rig_run(RigObject *self, PyObject *args)
{
    PyObject *robj, *xobj, *oobj = Py_None, *out = NULL;
    PyArrayObject *r = NULL, *x = NULL;
    npy_intp n, i, dims[2];
    run_batch_ctx b;

    if (!PyArg_ParseTuple(args, "OO|O:run", &robj, &xobj, &oobj))
        return NULL;
    r = (PyArrayObject *)PyArray_FROMANY(robj, NPY_DOUBLE, 1, 1, NPY_ARRAY_IN_ARRAY);
    x = (PyArrayObject *)PyArray_FROMANY(xobj, NPY_DOUBLE, 1, 1, NPY_ARRAY_IN_ARRAY);
    if (!r || !x)
        goto fail;
    n = PyArray_DIM(r, 0);
    if (PyArray_DIM(x, 0) != n) {
        PyErr_Format(PyExc_ValueError, "Rig.run: roller_ref and xi_ref differ in length "
                     "(%zd, %zd)", (Py_ssize_t)n, (Py_ssize_t)PyArray_DIM(x, 0));
        goto fail;
    }
    dims[0] = n;
    dims[1] = RR_REC_COUNT;
    if (oobj != Py_None) {
        PyArrayObject *o = (PyArrayObject *)oobj;
        if (!PyArray_Check(oobj) || PyArray_TYPE(o) != NPY_DOUBLE || PyArray_NDIM(o) != 2
            || PyArray_DIM(o, 0) != n || PyArray_DIM(o, 1) != RR_REC_COUNT
            || !PyArray_IS_C_CONTIGUOUS(o) || !PyArray_ISWRITEABLE(o)) {
            PyErr_Format(PyExc_ValueError, "Rig.run: out must be a writable C-contiguous "
                         "float64 array of shape (%zd, %d)", (Py_ssize_t)n, RR_REC_COUNT);
            goto fail;
        }
        Py_INCREF(oobj);
        out = oobj;
    } else if (!(out = PyArray_SimpleNew(2, dims, NPY_DOUBLE))) {
        goto fail;
    }
    if (rig_enter(self, "run") < 0)
        goto fail;
    b.rig = &self->rig;
    b.roller_ref = (const double *)PyArray_DATA(r);
    b.xi_ref = (const double *)PyArray_DATA(x);
    b.rec = OUT(out);
    b.worst = RR_OK;
    for (i = 0; i < n * RR_REC_COUNT; i++)
        b.rec[i] = NAN;
    if (run_batch(run_kernel, &b, n, SAMPLE_COST) < 0) {
        rig_leave(self);
        goto fail;
    }
    rig_leave(self);
    Py_DECREF(r);
    Py_DECREF(x);
    return Py_BuildValue("Ni", out, b.worst);
fail:
    Py_XDECREF(r);
    Py_XDECREF(x);
    Py_XDECREF(out);
    return NULL;
}

static PyObject *Rig_sample(RigObject *self, PyObject *args)
{
    double roller_ref, xi_ref;
    int st;
    if (!PyArg_ParseTuple(args, "dd:sample", &roller_ref, &xi_ref) || rig_enter(self, "sample") < 0)
        return NULL;
    st = rr_rig_sample(&self->rig, roller_ref, xi_ref);
    rig_leave(self);
    return PyLong_FromLong(st);
}

/* read() -> (signals, status): rr_rig_read; signals the tuple (t, roller_count,
 * wheelset_count, roller_angle, wheelset_angle, roller_speed, wheelset_speed,
 * roller_torque, wheelset_torque, xi_est), NaN on error */
static PyObject *Rig_read(RigObject *self, PyObject *noargs)
{
    rr_rig_signals s;
    int st;
    (void)noargs;
    if (rig_enter(self, "read") < 0)
        return NULL;
    st = rr_rig_read(&self->rig, &s);
    rig_leave(self);
    return Py_BuildValue("(dddddddddd)i", s.t, s.roller_count, s.wheelset_count,
                         s.roller_angle, s.wheelset_angle, s.roller_speed, s.wheelset_speed,
                         s.roller_torque, s.wheelset_torque, s.xi_est, st);
}

/* write(roller_mode, roller_ref, wheelset_mode, wheelset_ref, mu0) -> status: rr_rig_write */
static PyObject *Rig_write(RigObject *self, PyObject *args)
{
    rr_rig_command c;
    int st;
    if (!PyArg_ParseTuple(args, "ididd:write", &c.roller_mode, &c.roller_ref, &c.wheelset_mode,
                          &c.wheelset_ref, &c.mu0) || rig_enter(self, "write") < 0)
        return NULL;
    st = rr_rig_write(&self->rig, &c);
    rig_leave(self);
    return PyLong_FromLong(st);
}

/* A fresh record filled by fn (rr_rig_advance or rr_rig_record), with its status. */
static PyObject *record_call(RigObject *self, int (*fn)(rr_rig *, double *), const char *name)
{
    double *rec;
    PyObject *a;
    int st;
    if (rig_enter(self, name) < 0)
        return NULL;
    if (!(a = new_record(&rec))) {
        rig_leave(self);
        return NULL;
    }
    st = fn(&self->rig, rec);
    rig_leave(self);
    return Py_BuildValue("Ni", a, st);
}

static PyObject *Rig_advance(RigObject *self, PyObject *noargs)
{
    (void)noargs;
    return record_call(self, rr_rig_advance, "advance");
}

static PyObject *Rig_record(RigObject *self, PyObject *noargs)
{
    (void)noargs;
    return record_call(self, rr_rig_record, "record");
}

static int state_vector(PyObject *obj, double *y)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 1, 1,
                                                          NPY_ARRAY_IN_ARRAY);
    int j;
    if (!a)
        return -1;
    if (PyArray_DIM(a, 0) != RR_RIG_NSTATE) {
        PyErr_Format(PyExc_ValueError, "Rig: the state has %d values, got %zd", RR_RIG_NSTATE,
                     (Py_ssize_t)PyArray_DIM(a, 0));
        Py_DECREF(a);
        return -1;
    }
    for (j = 0; j < RR_RIG_NSTATE; j++)
        y[j] = ((const double *)PyArray_DATA(a))[j];
    Py_DECREF(a);
    return 0;
}

/* rhs(t, y) -> (dydt, status); jac(t, y) -> (J, status): the plant with the held references. */
static PyObject *Rig_rhs(RigObject *self, PyObject *args)
{
    PyObject *yobj, *out;
    double t, y[RR_RIG_NSTATE];
    npy_intp n = RR_RIG_NSTATE;
    int st;
    if (!PyArg_ParseTuple(args, "dO:rhs", &t, &yobj) || state_vector(yobj, y) < 0)
        return NULL;
    if (!(out = PyArray_SimpleNew(1, &n, NPY_DOUBLE)))
        return NULL;
    if (rig_enter(self, "rhs") < 0) {
        Py_DECREF(out);
        return NULL;
    }
    st = rr_rig_rhs(&self->rig, t, y, OUT(out));
    rig_leave(self);
    return Py_BuildValue("Ni", out, st);
}

static PyObject *Rig_jac(RigObject *self, PyObject *args)
{
    PyObject *yobj, *out;
    double t, y[RR_RIG_NSTATE];
    npy_intp dims[2] = {RR_RIG_NSTATE, RR_RIG_NSTATE};
    int st;
    if (!PyArg_ParseTuple(args, "dO:jac", &t, &yobj) || state_vector(yobj, y) < 0)
        return NULL;
    if (!(out = PyArray_SimpleNew(2, dims, NPY_DOUBLE)))
        return NULL;
    if (rig_enter(self, "jac") < 0) {
        Py_DECREF(out);
        return NULL;
    }
    st = rr_rig_jac(&self->rig, t, y, OUT(out));
    if (st < 0) {
        int k;
        for (k = 0; k < RR_RIG_NSTATE * RR_RIG_NSTATE; k++)
            OUT(out)[k] = NAN;      /* the C call leaves J unset on error */
    }
    rig_leave(self);
    return Py_BuildValue("Ni", out, st);
}

static PyObject *Rig_set_state(RigObject *self, PyObject *args)
{
    PyObject *yobj;
    double t, y[RR_RIG_NSTATE];
    int st;
    if (!PyArg_ParseTuple(args, "dO:set_state", &t, &yobj) || state_vector(yobj, y) < 0
        || rig_enter(self, "set_state") < 0)
        return NULL;
    st = rr_rig_set_state(&self->rig, t, y);
    rig_leave(self);
    return PyLong_FromLong(st);
}

static PyObject *Rig_get_t(RigObject *self, void *closure)
{
    double t;
    (void)closure;
    if (rig_enter(self, "t") < 0)
        return NULL;
    t = self->rig.t;
    rig_leave(self);
    return PyFloat_FromDouble(t);
}

static PyObject *Rig_get_y(RigObject *self, void *closure)
{
    npy_intp n = RR_RIG_NSTATE;
    PyObject *a;
    (void)closure;
    if (rig_enter(self, "y") < 0)
        return NULL;
    if ((a = PyArray_SimpleNew(1, &n, NPY_DOUBLE)) != NULL)
        memcpy(OUT(a), self->rig.y, sizeof self->rig.y);
    rig_leave(self);
    return a;
}

/* info: what a controller is configured with, from the rig's parameters */
static PyObject *Rig_get_info(RigObject *self, void *closure)
{
    const rr_rig_params *p = &self->p;
    (void)closure;
    if (!self->ready) {
        PyErr_SetString(PyExc_RuntimeError, "Rig.info: the rig is not initialised");
        return NULL;
    }
    return Py_BuildValue("{s:d,s:d,s:d,s:i,s:i,s:i,s:d,s:d,s:d,s:d,s:d,s:d}",
                         "dt", p->T, "wheel_radius", p->creepctl.r_w,
                         "roller_radius", p->creepctl.r_r, "sense", p->creepctl.sense,
                         "roller_counts", p->roller_enc.counts,
                         "wheelset_counts", p->wheelset_enc.counts,
                         "roller_torque_limit", p->roller_pi.Tmax,
                         "wheelset_torque_limit", p->wheelset_pi.Tmax,
                         "alpha", p->creepctl.alpha, "beta", p->creepctl.beta,
                         "min_reference_speed", p->creepctl.vmin,
                         "roller_surface_radius", p->contact.R0);
}

static PyObject *Rig_get_status(RigObject *self, void *closure)
{
    int st;
    (void)closure;
    if (rig_enter(self, "status") < 0)
        return NULL;
    st = self->rig.status;
    rig_leave(self);
    return PyLong_FromLong(st);
}

static PyMethodDef Rig_methods[] = {
    {"run", (PyCFunction)Rig_run, METH_VARARGS,
     "run(roller_ref, xi_ref) -> (records, status): one sample per element"},
    {"sample", (PyCFunction)Rig_sample, METH_VARARGS,
     "sample(roller_ref, xi_ref) -> status: encoders and controllers at this instant"},
    {"read", (PyCFunction)Rig_read, METH_NOARGS,
     "read() -> (signals, status): the encoders and drives at this sample (rr_rig_read)"},
    {"write", (PyCFunction)Rig_write, METH_VARARGS,
     "write(roller_mode, roller_ref, wheelset_mode, wheelset_ref, mu0) -> status: the "
     "references held over the sample (rr_rig_write)"},
    {"advance", (PyCFunction)Rig_advance, METH_NOARGS,
     "advance() -> (record, status): the plant over one sample"},
    {"record", (PyCFunction)Rig_record, METH_NOARGS, "record() -> (record, status)"},
    {"rhs", (PyCFunction)Rig_rhs, METH_VARARGS, "rhs(t, y) -> (dydt, status)"},
    {"jac", (PyCFunction)Rig_jac, METH_VARARGS, "jac(t, y) -> (J, status)"},
    {"set_state", (PyCFunction)Rig_set_state, METH_VARARGS, "set_state(t, y) -> status"},
    {NULL, NULL, 0, NULL}
};

static PyGetSetDef Rig_getset[] = {
    {"t", (getter)Rig_get_t, NULL, "time [s]", NULL},
    {"y", (getter)Rig_get_y, NULL, "plant state (a copy)", NULL},
    {"status", (getter)Rig_get_status, NULL, "status of the last sample", NULL},
    {"info", (getter)Rig_get_info, NULL, "the controllers' settings (a dict)", NULL},
    {NULL, NULL, NULL, NULL, NULL}
};

static PyTypeObject RigType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "rollerrig._core.Rig",
    .tp_basicsize = sizeof(RigObject),
    .tp_dealloc = (destructor)Rig_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "Rig(data, y0, dy, params, creep, roller_speed): the C rig (rr_rig.h)",
    .tp_methods = Rig_methods,
    .tp_getset = Rig_getset,
    .tp_init = (initproc)Rig_init,
    .tp_new = PyType_GenericNew,
};

/* ------------------------------------ profile splines and tables (rr_tables.h) */

/* Profile points as a contiguous 1-D float64 array of RR_SPLINE_MIN_POINTS
 * to RR_SPLINE_MAX_POINTS values, or NULL with a ValueError naming it. */
static PyArrayObject *points_array(PyObject *obj, const char *func, const char *name)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 1, 1,
                                                          NPY_ARRAY_IN_ARRAY);
    if (!a)
        return NULL;
    if (PyArray_DIM(a, 0) < RR_SPLINE_MIN_POINTS || PyArray_DIM(a, 0) > RR_SPLINE_MAX_POINTS) {
        PyErr_Format(PyExc_ValueError, "%s: %s holds %zd points; a profile has from %d to %d",
                     func, name, (Py_ssize_t)PyArray_DIM(a, 0), RR_SPLINE_MIN_POINTS,
                     RR_SPLINE_MAX_POINTS);
        Py_DECREF(a);
        return NULL;
    }
    return a;
}

/* y and z of one profile, of one length; 0, or -1 with an exception. */
static int points_pair(PyObject *yobj, PyObject *zobj, const char *func, const char *yname,
                       const char *zname, PyArrayObject **y, PyArrayObject **z)
{
    if (!(*y = points_array(yobj, func, yname)) || !(*z = points_array(zobj, func, zname)))
        return -1;
    if (PyArray_DIM(*y, 0) != PyArray_DIM(*z, 0)) {
        PyErr_Format(PyExc_ValueError, "%s: %s and %s differ in length (%zd, %zd)", func,
                     yname, zname, (Py_ssize_t)PyArray_DIM(*y, 0),
                     (Py_ssize_t)PyArray_DIM(*z, 0));
        return -1;
    }
    return 0;
}

/* spline_fit(y, z, end) -> (status, slope, c2, c3, d2): rr_spline_fit and
 * the knots' second derivatives, the arrays of rollerrig.profiles.Profile. */
static PyObject *py_spline_fit(PyObject *self, PyObject *args)
{
    PyObject *yobj, *zobj, *endobj, *out[4] = {NULL, NULL, NULL, NULL};
    PyArrayObject *y = NULL, *z = NULL;
    double *work = NULL;
    npy_intp n, n1;
    int end, st, k;
    (void)self;

    if (!PyArg_ParseTuple(args, "OOO:spline_fit", &yobj, &zobj, &endobj))
        return NULL;
    if (int_arg(endobj, "spline_fit", "end", RR_SPLINE_NOT_A_KNOT, RR_SPLINE_NATURAL, &end) < 0
        || points_pair(yobj, zobj, "spline_fit", "y", "z", &y, &z) < 0)
        goto fail;
    n = PyArray_DIM(y, 0);
    n1 = n - 1;
    out[0] = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    out[1] = PyArray_SimpleNew(1, &n1, NPY_DOUBLE);
    out[2] = PyArray_SimpleNew(1, &n1, NPY_DOUBLE);
    out[3] = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    work = PyMem_Malloc((size_t)n * sizeof(double));
    for (k = 0; k < 4; k++)
        if (!out[k])
            goto fail;
    if (!work) {
        PyErr_NoMemory();
        goto fail;
    }
    st = rr_spline_fit((int)n, (const double *)PyArray_DATA(y), (const double *)PyArray_DATA(z),
                       end, OUT(out[0]), OUT(out[1]), OUT(out[2]), work);
    if (st == RR_OK)
        st = rr_spline_knot_d2((int)n, (const double *)PyArray_DATA(y), OUT(out[1]),
                               OUT(out[2]), OUT(out[3]));
    PyMem_Free(work);
    Py_DECREF(y);
    Py_DECREF(z);
    return Py_BuildValue("iNNNN", st, out[0], out[1], out[2], out[3]);
fail:
    PyMem_Free(work);
    Py_XDECREF(y);
    Py_XDECREF(z);
    release(out, 4);
    return NULL;
}

/* analytic_profile(kind, param, y_min, y_max, n) -> (status, y, z):
 * rr_profile_conical (kind 0, param the cone angle) or rr_profile_crowned
 * (kind 1, param the crown radius, 0 for a cylinder). */
static PyObject *py_analytic_profile(PyObject *self, PyObject *args)
{
    PyObject *kobj, *nobj, *y = NULL, *z = NULL;
    double param, y_min, y_max;
    npy_intp len;
    int kind, n, st;
    (void)self;

    if (!PyArg_ParseTuple(args, "OdddO:analytic_profile", &kobj, &param, &y_min, &y_max, &nobj)
        || int_arg(kobj, "analytic_profile", "kind", 0, 1, &kind) < 0
        || int_arg(nobj, "analytic_profile", "n", RR_SPLINE_MIN_POINTS, RR_SPLINE_MAX_POINTS,
                   &n) < 0)
        return NULL;
    len = n;
    if (!(y = PyArray_SimpleNew(1, &len, NPY_DOUBLE)) || !(z = PyArray_SimpleNew(1, &len,
                                                                                 NPY_DOUBLE))) {
        Py_XDECREF(y);
        return NULL;
    }
    st = kind == 0 ? rr_profile_conical(param, y_min, y_max, n, OUT(y), OUT(z))
                   : rr_profile_crowned(param, y_min, y_max, n, OUT(y), OUT(z));
    return Py_BuildValue("iNN", st, y, z);
}

typedef struct {
    const rr_profile_points *wheel, *roller;
    const rr_profile_placement *place;
    const rr_search_opts *o;
    const rr_rig_geometry *g;       /* the rig's table: NULL for two point lists */
    rr_contact_table *t;
    long data_len, work_len;
    double *work, bad_y;
    int st;
} points_table_batch;

/* rows [start, stop) of a table from point lists or of the rig's; the first
 * error stops the build */
static int points_table_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    points_table_batch *b = ctx;
    b->st = b->g ? rr_rig_table_build_rows(b->g, b->t->data, b->data_len, b->work, b->work_len,
                                           (int)start, (int)stop, b->t, &b->bad_y)
                 : rr_profile_table_build_rows(b->wheel, b->roller, b->place, b->o, b->t,
                                               b->data_len, b->work, b->work_len, (int)start,
                                               (int)stop, &b->bad_y);
    return b->st < 0;
}

/* profile_table(wheel_y, wheel_z, wheel_end, roller_y, roller_z, roller_end,
 * (r0, R0, wheel_y, roller_y), y0, dy, n, nsamples, tol, sep)
 * -> (data, status, bad_y): rr_profile_table_build_rows through the batch loop. */
static PyObject *py_profile_table(PyObject *self, PyObject *args)
{
    PyObject *wyo, *wzo, *weo, *ryo, *rzo, *reo, *rows, *nobj, *data = NULL;
    PyArrayObject *arr[4] = {NULL, NULL, NULL, NULL};
    rr_profile_points wheel, roller;
    rr_profile_placement place;
    rr_search_opts o;
    rr_contact_table t;
    points_table_batch b;
    double tol, sep, *work = NULL;
    npy_intp len;
    long work_len;
    (void)self;

    if (!PyArg_ParseTuple(args, "OOOOOO(dddd)ddOOdd:profile_table", &wyo, &wzo, &weo, &ryo,
                          &rzo, &reo, &place.wheel_radius, &place.roller_radius,
                          &place.wheel_y, &place.roller_y, &t.y0, &t.dy, &rows, &nobj, &tol,
                          &sep))
        return NULL;
    if (int_arg(weo, "profile_table", "wheel_end", 0, 1, &wheel.end) < 0
        || int_arg(reo, "profile_table", "roller_end", 0, 1, &roller.end) < 0
        || int_arg(rows, "profile_table", "n", 2, RR_RIG_TABLE_MAX_ROWS, &t.n) < 0
        || parse_search(nobj, tol, sep, "profile_table", &o) < 0
        || points_pair(wyo, wzo, "profile_table", "wheel_y", "wheel_z", &arr[0], &arr[1]) < 0
        || points_pair(ryo, rzo, "profile_table", "roller_y", "roller_z", &arr[2], &arr[3]) < 0)
        goto fail;
    wheel.n = (int)PyArray_DIM(arr[0], 0);
    wheel.y = (const double *)PyArray_DATA(arr[0]);
    wheel.z = (const double *)PyArray_DATA(arr[1]);
    roller.n = (int)PyArray_DIM(arr[2], 0);
    roller.y = (const double *)PyArray_DATA(arr[2]);
    roller.z = (const double *)PyArray_DATA(arr[3]);
    len = (npy_intp)rr_contact_table_len(t.n);
    work_len = rr_profile_table_work_len(wheel.n, roller.n);
    if (!(data = PyArray_SimpleNew(1, &len, NPY_DOUBLE)))
        goto fail;
    if (!(work = PyMem_Malloc((size_t)work_len * sizeof(double)))) {
        PyErr_NoMemory();
        goto fail;
    }
    t.data = OUT(data);
    b.wheel = &wheel;
    b.roller = &roller;
    b.place = &place;
    b.o = &o;
    b.g = NULL;
    b.t = &t;
    b.data_len = (long)len;
    b.work = work;
    b.work_len = work_len;
    b.bad_y = NAN;
    b.st = RR_OK;
    if (run_batch(points_table_kernel, &b, t.n, search_cost(&o)) < 0)
        goto fail;
    PyMem_Free(work);
    release((PyObject **)arr, 4);
    return Py_BuildValue("Nid", data, b.st, b.bad_y);
fail:
    PyMem_Free(work);
    release((PyObject **)arr, 4);
    Py_XDECREF(data);
    return NULL;
}

/* rig_table(r0, R0, half_width, alpha, crown, half_spacing, half_range, rows)
 * -> (data, y0, dy, status, bad_y): rr_rig_table_build_rows through the batch loop. */
static PyObject *py_rig_table(PyObject *self, PyObject *args)
{
    rr_rig_geometry g;
    rr_contact_table t;
    rr_search_opts o;
    points_table_batch b;
    PyObject *rows, *data;
    double *work;
    npy_intp len;
    int st;
    (void)self;

    if (!PyArg_ParseTuple(args, "dddddddO:rig_table", &g.wheel_radius, &g.roller_radius,
                          &g.profile_half_width, &g.cone_angle, &g.crown_radius,
                          &g.contact_half_spacing, &g.table_half_range, &rows)
        || int_arg(rows, "rig_table", "rows", 2, RR_RIG_TABLE_MAX_ROWS, &g.table_rows) < 0)
        return NULL;
    len = (npy_intp)rr_rig_table_data_len(&g);
    if (!(data = PyArray_SimpleNew(1, &len, NPY_DOUBLE)))
        return NULL;
    if (!(work = PyMem_Malloc(RR_RIG_TABLE_WORK_LEN * sizeof(double)))) {
        Py_DECREF(data);
        return PyErr_NoMemory();
    }
    t.y0 = t.dy = NAN;
    t.data = OUT(data);
    rr_search_opts_default(&o);
    b.g = &g;
    b.t = &t;
    b.data_len = (long)len;
    b.work = work;
    b.work_len = RR_RIG_TABLE_WORK_LEN;
    b.bad_y = NAN;
    b.st = RR_OK;
    /* a row is one wheelset solve at the default search's samples */
    st = run_batch(points_table_kernel, &b, len ? g.table_rows : 1, search_cost(&o));
    PyMem_Free(work);
    if (st < 0) {
        Py_DECREF(data);
        return NULL;
    }
    return Py_BuildValue("Nddid", data, t.y0, t.dy, b.st, b.bad_y);
}

/* A list of up to RR_RIG_MAX_LIST finite numbers into l; 0, or -1 with a ValueError. */
static int rig_list(PyObject *obj, const char *name, rr_rig_list *l)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 1, 1,
                                                          NPY_ARRAY_IN_ARRAY);
    npy_intp k;
    if (!a)
        return -1;
    if (PyArray_DIM(a, 0) < 1 || PyArray_DIM(a, 0) > RR_RIG_MAX_LIST) {
        PyErr_Format(PyExc_ValueError, "rig_schedule: %s must have 1 to %d entries, got %zd",
                     name, RR_RIG_MAX_LIST, (Py_ssize_t)PyArray_DIM(a, 0));
        Py_DECREF(a);
        return -1;
    }
    l->n = (int)PyArray_DIM(a, 0);
    for (k = 0; k < l->n; k++)
        l->v[k] = ((const double *)PyArray_DATA(a))[k];
    Py_DECREF(a);
    return 0;
}

/* rig_schedule(roller_speed, roller_radius, targets, target_start, T, first, stop)
 * -> (roller_ref, xi_ref) of samples first <= k < stop: rr_rig_schedule, the
 * rule the C programs follow. */
static PyObject *py_rig_schedule(PyObject *self, PyObject *args)
{
    PyObject *tobj, *sobj, *out[2] = {NULL, NULL};
    rr_rig_config c;
    Py_ssize_t first, stop, k;
    npy_intp n;
    (void)self;
    if (!PyArg_ParseTuple(args, "ddOOdnn:rig_schedule", &c.roller_speed, &c.roller_radius,
                          &tobj, &sobj, &c.T, &first, &stop)
        || rig_list(tobj, "targets", &c.targets) < 0
        || rig_list(sobj, "target_start", &c.target_start) < 0)
        return NULL;
    if (first < 0 || stop < first) {
        PyErr_Format(PyExc_ValueError, "rig_schedule: samples %zd to %zd", first, stop);
        return NULL;
    }
    n = stop - first;
    if (!(out[0] = PyArray_SimpleNew(1, &n, NPY_DOUBLE))
        || !(out[1] = PyArray_SimpleNew(1, &n, NPY_DOUBLE))) {
        release(out, 2);
        return NULL;
    }
    for (k = 0; k < n; k++)
        rr_rig_schedule(&c, (long)(first + k), OUT(out[0]) + k, OUT(out[1]) + k);
    return outputs_tuple(out, 2);
}

/* rig_speed_loops(params) -> ((stable, rho, lo, hi), (...)): the roller's and
 * the wheelset's sampled speed loops of the rig's primary values (a dict as
 * Rig takes): stable at the sample time (rr_speed_loop_check), the largest
 * pole's |z| (rr_speed_loop_radius), the stable sample times within
 * [RR_RIG_MIN_T, RR_RIG_MAX_T] (rr_speed_loop_range; NaN if none). */
static PyObject *py_rig_speed_loops(PyObject *self, PyObject *arg)
{
    rr_rig_config c;
    rr_speed_loop loops[2];
    PyObject *out[2] = {NULL, NULL};
    int k;
    (void)self;
    if (!PyDict_Check(arg)) {
        PyErr_SetString(PyExc_TypeError, "rig_speed_loops: a dict of the rig's parameters");
        return NULL;
    }
    if (rig_config_from(arg, &c) < 0)
        return NULL;
    rr_rig_config_speed_loops(&c, loops);
    for (k = 0; k < 2; k++) {
        double rho, lo, hi;
        const int st = rr_speed_loop_radius(&loops[k], &rho);
        if (st < 0) {
            PyErr_Format(PyExc_ValueError, "rig_speed_loops: %s", rr_status_message(st));
            release(out, 2);
            return NULL;
        }
        rr_speed_loop_range(&loops[k], RR_RIG_MIN_T, RR_RIG_MAX_T, &lo, &hi);
        if (!(out[k] = Py_BuildValue("(Nddd)", PyBool_FromLong(rr_speed_loop_check(&loops[k])
                                                                == RR_OK), rho, lo, hi))) {
            release(out, 2);
            return NULL;
        }
    }
    return outputs_tuple(out, 2);
}

/* ==== issue 23, item 4 (c-decl): rig_config_report ==================== */
/* rig_config_report(params) -> [(key, status, rule, other, entry, value, lo,
 * hi), ...]: every problem of the rig's primary values {"section.key":
 * value} (any subset, the rest at their defaults), as rr_rig_config_report
 * gives them (rr_rig_params.h: rule "range", "count", "increasing",
 * "nondecreasing", "before", "sample", "circumference", "loop" or "sum";
 * other None or a row's name; entry -1 or a list's entry, a loop's drive),
 * in its order: the rows in the declaration's order, then the rules between
 * them.  A value the configuration cannot hold is its row's "range" problem
 * (rr_rig_config_put; value NaN where it is no number): the types are
 * rollerrig.rig's rules' (a real: a numbers.Real but a bool; an int: a
 * numbers.Integral but a bool; a flag: a bool; a choice: one of its names;
 * a list: a list or tuple of reals).  An unknown name or a creep row raises
 * ValueError (as Rig does). */
static const char *const rig_rule_names[] = {
    [RR_RIG_RULE_RANGE] = "range", [RR_RIG_RULE_COUNT] = "count",
    [RR_RIG_RULE_INCREASING] = "increasing", [RR_RIG_RULE_NONDECREASING] = "nondecreasing",
    [RR_RIG_RULE_BEFORE] = "before", [RR_RIG_RULE_SAMPLE] = "sample",
    [RR_RIG_RULE_CIRCUMFERENCE] = "circumference", [RR_RIG_RULE_LOOP] = "loop",
    [RR_RIG_RULE_SUM] = "sum"};

/* A real of the parameter rules as a double: 1, 0 (not one: a bool, no
 * numbers.Real, an int beyond a double), -1 with an exception. */
static int report_real(PyObject *v, PyObject *real, double *x)
{
    int is = PyBool_Check(v) ? 0 : PyObject_IsInstance(v, real);
    if (is <= 0)
        return is;
    *x = PyFloat_AsDouble(v);
    if (*x == -1.0 && PyErr_Occurred()) {
        if (!PyErr_ExceptionMatches(PyExc_OverflowError))
            return -1;
        PyErr_Clear();
        return 0;
    }
    return 1;
}

/* The value of row r stored in c (rr_rig_config_put), or its problem in *p:
 * 0 stored, 1 a problem, -1 an exception. */
static int report_value(const rr_rig_param *r, PyObject *v, PyObject *real, PyObject *integral,
                        rr_rig_config *c, rr_rig_problem *p)
{
    double x = NAN;
    int ok, entry = -1;
    if (r->type == RR_RIG_LIST) {
        double vals[RR_RIG_MAX_LIST];
        Py_ssize_t k, n;
        ok = PyList_Check(v) || PyTuple_Check(v);
        n = ok ? PySequence_Fast_GET_SIZE(v) : 0;
        for (k = 0; ok && k < n && k < RR_RIG_MAX_LIST; k++)
            if ((ok = report_real(PySequence_Fast_GET_ITEM(v, k), real, &vals[k])) < 0)
                return -1;
            else if (!ok)
                entry = (int)k;
        if (ok)
            return rr_rig_config_put_list(c, r->name, n > RR_RIG_MAX_LIST ? RR_RIG_MAX_LIST + 1
                                                                           : (int)n,
                                          vals, p) == RR_OK ? 0 : 1;
    } else if (r->type == RR_RIG_CHOICE) {
        const char *text = PyUnicode_Check(v) ? PyUnicode_AsUTF8(v) : NULL;
        int k;
        if (!text && PyErr_Occurred())
            return -1;
        if (text && (k = rr_rig_param_choice(r, text)) >= 0)
            return rr_rig_config_put(c, r->name, k, p) == RR_OK ? 0 : 1;
        ok = 0;
    } else if (r->type == RR_RIG_FLAG) {
        if ((ok = PyBool_Check(v)) != 0)
            return rr_rig_config_put(c, r->name, v == Py_True, p) == RR_OK ? 0 : 1;
    } else {
        if ((ok = report_real(v, r->type == RR_RIG_INT ? integral : real, &x)) < 0)
            return -1;
        if (ok)
            return rr_rig_config_put(c, r->name, x, p) == RR_OK ? 0 : 1;
        /* a real for an integer: its value in the problem */
        if (r->type != RR_RIG_INT || report_real(v, real, &x) <= 0)
            x = NAN;
        PyErr_Clear();
    }
    /* not a value of the row's kind: the row's range problem, value NaN (a
     * list: entry the first that is no real, -1 where it is no list) */
    p->key = r->name;
    p->other = NULL;
    p->status = RR_ERR_PARAM;
    p->rule = RR_RIG_RULE_RANGE;
    p->entry = entry;
    p->value = x;
    p->lo = r->lo;
    p->hi = r->hi;
    if (r->type == RR_RIG_CHOICE || r->type == RR_RIG_FLAG) {
        int k = 0;
        while (r->choices && r->choices[k])
            k++;
        p->lo = 0.0;
        p->hi = r->type == RR_RIG_FLAG ? 1.0 : k - 1.0;
    }
    return 1;
}

/* report_value, and where a REAL or LIST row cannot hold its value, a NaN
 * in its place: the report then judges no rule with that row (and with an
 * INT, FLAG or CHOICE row the default: no rule reads one). */
static int report_put(const rr_rig_param *r, PyObject *v, PyObject *real, PyObject *integral,
                      rr_rig_config *c, rr_rig_problem *p)
{
    const double nan = NAN;
    const int st = report_value(r, v, real, integral, c, p);
    if (st == 1 && r->type == RR_RIG_REAL)
        rr_rig_config_put(c, r->name, nan, NULL);
    else if (st == 1 && r->type == RR_RIG_LIST)
        rr_rig_config_put_list(c, r->name, 1, &nan, NULL);
    return st;
}

static PyObject *report_tuple(const rr_rig_problem *p)
{
    return Py_BuildValue("(sisziddd)", p->key, p->status, rig_rule_names[p->rule], p->other,
                         p->entry, p->value, p->lo, p->hi);
}

static PyObject *py_rig_config_report(PyObject *self, PyObject *arg)
{
    rr_rig_config c;
    rr_rig_problem found[RR_RIG_MAX_PROBLEMS];
    rr_rig_problem *held = NULL;        /* per row: the value it could not hold */
    char *has = NULL;
    PyObject *numbers = NULL, *real = NULL, *integral = NULL, *key, *v, *out = NULL;
    Py_ssize_t pos = 0;
    const int nrows = rr_rig_param_count();
    int n, i, k;
    (void)self;
    if (!PyDict_Check(arg)) {
        PyErr_SetString(PyExc_TypeError, "rig_config_report: a dict of the rig's parameters");
        return NULL;
    }
    held = PyMem_Calloc((size_t)nrows, sizeof *held);
    has = PyMem_Calloc((size_t)nrows, 1);
    if (!held || !has) {
        PyErr_NoMemory();
        goto done;
    }
    if (!(numbers = PyImport_ImportModule("numbers"))
        || !(real = PyObject_GetAttrString(numbers, "Real"))
        || !(integral = PyObject_GetAttrString(numbers, "Integral")))
        goto done;
    rr_rig_config_default(&c);
    while (PyDict_Next(arg, &pos, &key, &v)) {
        const char *name = PyUnicode_Check(key) ? PyUnicode_AsUTF8(key) : NULL;
        const rr_rig_param *row = name ? rr_rig_param_find(name) : NULL;
        int st;
        if (!row || row->creep) {
            if (!PyErr_Occurred())
                PyErr_Format(PyExc_ValueError, "rig_config_report: %R is not a rig parameter%s",
                             key, row ? " (a creep-force option)" : "");
            goto done;
        }
        i = (int)(row - rr_rig_param_at(0));
        if ((st = report_put(row, v, real, integral, &c, &held[i])) < 0)
            goto done;
        has[i] = (char)st;
    }
    n = rr_rig_config_report(&c, found, RR_RIG_MAX_PROBLEMS);
    if (!(out = PyList_New(0)))
        goto done;
    /* the rows' own problems in the declaration's order, then the rules' */
    for (i = 0; i < nrows; i++) {
        const rr_rig_problem *p = has[i] ? &held[i] : NULL;
        for (k = 0; !p && k < n && k < RR_RIG_MAX_PROBLEMS; k++)
            if (found[k].rule == RR_RIG_RULE_RANGE && found[k].key == rr_rig_param_at(i)->name)
                p = &found[k];
        if (p) {
            PyObject *t = report_tuple(p);
            if (!t || PyList_Append(out, t) < 0) {
                Py_XDECREF(t);
                Py_CLEAR(out);
                goto done;
            }
            Py_DECREF(t);
        }
    }
    for (k = 0; k < n && k < RR_RIG_MAX_PROBLEMS; k++) {
        PyObject *t;
        if (found[k].rule == RR_RIG_RULE_RANGE)
            continue;
        t = report_tuple(&found[k]);
        if (!t || PyList_Append(out, t) < 0) {
            Py_XDECREF(t);
            Py_CLEAR(out);
            goto done;
        }
        Py_DECREF(t);
    }
done:
    PyMem_Free(held);
    PyMem_Free(has);
    Py_XDECREF(numbers);
    Py_XDECREF(real);
    Py_XDECREF(integral);
    return out;
}
/* ==== end of issue 23, item 4 (c-decl) ================================== */

static PyObject *py_status_message(PyObject *self, PyObject *arg)
{
    long code = PyLong_AsLong(arg);
    (void)self;
    if (code == -1 && PyErr_Occurred())
        return NULL;
    if (code < INT_MIN || code > INT_MAX)
        code = INT_MIN;
    return PyUnicode_FromString(rr_status_message((int)code));
}

static PyMethodDef core_methods[] = {
    {"hertz", py_hertz, METH_VARARGS,
     "hertz(A, B, N, E1, nu1, E2, nu2) -> (a, b, p0, delta, status)"},
    {"hertz1", (PyCFunction)(void (*)(void))py_hertz1, METH_FASTCALL,
     "hertz1(A, B, N, E1, nu1, E2, nu2) -> (a, b, p0, delta, status)"},
    {"exact_table_builtin", py_exact_table_builtin, METH_NOARGS,
     "exact_table_builtin() -> (shape, lo, hi, nu, r0, nx, float32 bytes): the built-in table"},
    {"kalker", py_kalker, METH_VARARGS,
     "kalker(a_over_b, nu) -> (c11, c22, c23, c33, status)"},
    {"creep_forces", (PyCFunction)(void (*)(void))py_creep_forces, METH_VARARGS | METH_KEYWORDS,
     "creep_forces(cx, cy, cphi, a, b, N, mu, G, nu, speed, A, B, *, method, <its options>)"
     " -> (fx, fy, mz, status); METHODS lists the methods and their options"},
    {"check_creep_options", py_check_creep_options, METH_VARARGS,
     "check_creep_options(func, {method: ..., <its options>}) -> None, or ValueError"},
    {"creep_forces1", (PyCFunction)(void (*)(void))py_creep_forces1, METH_FASTCALL,
     "creep_forces1(opts, cx, cy, cphi, a, b, N, mu, G, nu, speed, A, B) -> (fx, fy, mz, status)"},
    {"exact_hertz_problem", (PyCFunction)(void (*)(void))py_exact_hertz_problem,
     METH_VARARGS | METH_KEYWORDS,
     "exact_hertz_problem(<as creep_forces, one case>, method='exact', <options>) -> (status, "
     "mx, my, dx, dy, x0, y0, A, B, N, G, nu, mu, cx, cy, cphi, spin_shift, tol, maxit)"},
    {"exact_solve", py_exact_solve, METH_VARARGS,
     "exact_solve(mx, my, dx, dy, x0, y0, h, A, B, N, G, nu, mu, cx, cy, cphi, spin_shift, "
     "tol, maxit) -> (status, results, pn, px, py, sx, sy, state)"},
    {"fastsim_field", (PyCFunction)(void (*)(void))py_fastsim_field,
     METH_VARARGS | METH_KEYWORDS,
     "fastsim_field(<as creep_forces, one case>) -> (fx, fy, mz, status, x, y, pn, px, py, slip, area)"},
    {"wheelset_contact", py_wheelset_contact, METH_VARARGS,
     "wheelset_contact(12 profile arrays (s, z, z'' each), 8 params, y_ws, nsamples, tol, sep)"
     " -> (status, z, roll, left, right)"},
    {"contact_table", py_contact_table, METH_VARARGS,
     "contact_table(12 profile arrays, 8 params, y0, dy, n, nsamples, tol, sep)"
     " -> (data, status, bad_y)"},
    {"table_lookup", py_table_lookup, METH_VARARGS,
     "table_lookup(data, y0, dy, y) -> (status, z, roll, dz_dy, droll_dy, left, right)"},
    {"rig_contact", (PyCFunction)(void (*)(void))py_rig_contact, METH_VARARGS | METH_KEYWORDS,
     "rig_contact(data, y0, dy, (R0, estar, G, nu, mu0, A, B, vmin), x, y, yaw, vx, vy,"
     " yaw_rate, spin, roller_spin, N_left, N_right, *, kinematics_only, <creep options>)"
     " -> (status, pose, left, right, left_status, right_status)"},
    {"spline_fit", py_spline_fit, METH_VARARGS,
     "spline_fit(y, z, end) -> (status, slope, c2, c3, d2)"},
    {"analytic_profile", py_analytic_profile, METH_VARARGS,
     "analytic_profile(kind (0 conical, 1 crowned), alpha or crown radius, y_min, y_max, n)"
     " -> (status, y, z)"},
    {"profile_table", py_profile_table, METH_VARARGS,
     "profile_table(wheel_y, wheel_z, wheel_end, roller_y, roller_z, roller_end,"
     " (r0, R0, wheel_y, roller_y), y0, dy, n, nsamples, tol, sep) -> (data, status, bad_y)"},
    {"rig_schedule", py_rig_schedule, METH_VARARGS,
     "rig_schedule(roller_speed, roller_radius, targets, target_start, T, first, stop)"
     " -> (roller_ref, xi_ref)"},
    {"rig_table", py_rig_table, METH_VARARGS,
     "rig_table(r0, R0, half_width, alpha, crown, half_spacing, half_range, rows)"
     " -> (data, y0, dy, status, bad_y)"},
    {"rig_speed_loops", py_rig_speed_loops, METH_O,
     "rig_speed_loops({\"section.key\": value}) -> ((stable, rho, lo, hi) of the roller's "
     "and the wheelset's sampled speed loops)"},
    /* issue 23, item 4 (c-decl) */
    {"rig_config_report", py_rig_config_report, METH_O,
     "rig_config_report({\"section.key\": value}) -> [(key, status, rule, other, entry, "
     "value, lo, hi), ...]: every problem of the rig's parameters (rr_rig_config_report)"},
    {"status_message", py_status_message, METH_O, "status_message(code) -> str"},
    {NULL, NULL, 0, NULL}
};

static struct PyModuleDef core_module = {
    PyModuleDef_HEAD_INIT, "rollerrig._core",
    "Binding of the rollerrig C core; use the functions of the rollerrig package.", -1,
    core_methods, NULL, NULL, NULL, NULL
};

/* a float constant of the module (PyModule_AddObject steals only on success) */
static int add_double(PyObject *m, const char *name, double v)
{
    PyObject *o = PyFloat_FromDouble(v);
    if (!o || PyModule_AddObject(m, name, o) < 0) {
        Py_XDECREF(o);
        return -1;
    }
    return 0;
}

/* The declarations of rr_rig_params.h as tuples of tuples (module constants):
 * RIG_PARAMETERS rows (name, unit, type, default, lo, hi, lo_open, hi_open,
 * choices, text, creep, origin, option) with type "real", "int", "flag", "choice" or
 * "list" and default a float, int, bool, str or tuple of floats (a creep row:
 * None, its text is the TOML default); RIG_SECTIONS (name, note);
 * RIG_RETIRED (name, reason); RIG_RECORD and RIG_WHEEL_FIELDS (name, width,
 * unit, meaning). */
static PyObject *param_default(const rr_rig_param *r)
{
    Py_ssize_t k;
    PyObject *t;
    if (r->creep)
        Py_RETURN_NONE;
    switch (r->type) {
    case RR_RIG_INT:
        return PyLong_FromDouble(r->value);
    case RR_RIG_FLAG:
        return PyBool_FromLong(r->value != 0.0);
    case RR_RIG_CHOICE:
        return PyUnicode_FromString(r->choices[(int)r->value]);
    case RR_RIG_LIST:
        if (!(t = PyTuple_New(r->nlist)))
            return NULL;
        for (k = 0; k < r->nlist; k++) {
            PyObject *x = PyFloat_FromDouble(r->list[k]);
            if (!x) {
                Py_DECREF(t);
                return NULL;
            }
            PyTuple_SET_ITEM(t, k, x);
        }
        return t;
    default:
        return PyFloat_FromDouble(r->value);
    }
}

/* A NULL-terminated list of names (NULL: none) as a tuple of str. */
static PyObject *names_tuple(const char *const *names)
{
    Py_ssize_t n = 0, k;
    PyObject *t;
    while (names && names[n])
        n++;
    if (!(t = PyTuple_New(n)))
        return NULL;
    for (k = 0; k < n; k++) {
        PyObject *x = PyUnicode_FromString(names[k]);
        if (!x) {
            Py_DECREF(t);
            return NULL;
        }
        PyTuple_SET_ITEM(t, k, x);
    }
    return t;
}

static PyObject *param_tuple(int i)
{
    static const char *const types[] = {"real", "int", "flag", "choice", "list"};
    const rr_rig_param *r = rr_rig_param_at(i);
    PyObject *dflt = param_default(r), *choices = names_tuple(r->choices), *res = NULL;
    if (dflt && choices)
        res = Py_BuildValue("(sssOddOOOzOsz)", r->name, r->unit, types[r->type], dflt, r->lo,
                            r->hi, r->lo_open ? Py_True : Py_False,
                            r->hi_open ? Py_True : Py_False, choices, r->text,
                            r->creep ? Py_True : Py_False, r->origin, r->option);
    Py_XDECREF(dflt);
    Py_XDECREF(choices);
    return res;
}

static PyObject *section_tuple(int i)
{
    const rr_rig_section *s = rr_rig_section_at(i);
    return Py_BuildValue("(ss)", s->name, s->note);
}

static PyObject *retired_tuple(int i)
{
    const rr_rig_retired *s = rr_rig_retired_at(i);
    return Py_BuildValue("(ss)", s->name, s->reason);
}

static PyObject *field_tuple(const rr_rig_field *f)
{
    return Py_BuildValue("(siss)", f->name, f->width, f->unit, f->meaning);
}

static PyObject *record_tuple(int i)
{
    return field_tuple(rr_rig_record_field(i));
}

static PyObject *wheel_tuple(int i)
{
    return field_tuple(rr_wheel_field(i));
}

/* module constant `name`: the tuple of row(i), 0 <= i < n */
static int add_rows(PyObject *m, const char *name, int n, PyObject *(*row)(int))
{
    PyObject *t = PyTuple_New(n);
    int i;
    if (!t)
        return -1;
    for (i = 0; i < n; i++) {
        PyObject *x = row(i);
        if (!x) {
            Py_DECREF(t);
            return -1;
        }
        PyTuple_SET_ITEM(t, i, x);
    }
    if (PyModule_AddObject(m, name, t) < 0) {
        Py_DECREF(t);
        return -1;
    }
    return 0;
}

/* The registry as _core.METHODS: a tuple of (name, doc, options, has_field,
 * saturates, in_loop, coulomb_only, in_rig), in_loop True where the method
 * needs no workspace (a time-loop method: the rig's contact model takes it),
 * in_rig where the rig steps with it (rr_rig_method_check: in_loop and
 * saturates), coulomb_only
 * True where it refuses a falling friction law, options a tuple of (name, type, unit, default, lo, hi,
 * lo_open, hi_open, choices, doc): type "int", "real" or "choice"; an
 * integer's default and range as ints, a choice's default as its name (its
 * range None), choices a tuple of names (empty but for a choice). */
static PyObject *option_tuple(const rr_creep_option *op)
{
    static const char *const types[] = {"int", "real", "choice"};
    PyObject *choices, *def, *lo, *hi;
    if (!(choices = names_tuple(op->type == RR_OPT_CHOICE ? op->choices : NULL)))
        return NULL;
    if (op->type == RR_OPT_CHOICE) {
        def = PyUnicode_FromString(op->choices[(int)op->def]);
        Py_INCREF(Py_None);
        Py_INCREF(Py_None);
        lo = hi = Py_None;
    } else if (op->type == RR_OPT_INT) {
        def = PyLong_FromDouble(op->def);
        lo = PyLong_FromDouble(op->lo);
        hi = PyLong_FromDouble(op->hi);
    } else {
        def = PyFloat_FromDouble(op->def);
        lo = PyFloat_FromDouble(op->lo);
        hi = PyFloat_FromDouble(op->hi);
    }
    return Py_BuildValue("(sssNNNNNNs)", op->name, types[op->type], op->unit, def, lo, hi,
                         PyBool_FromLong(op->lo_open), PyBool_FromLong(op->hi_open), choices,
                         op->doc);
}

static int add_methods(PyObject *m)
{
    PyObject *all = PyTuple_New(rr_method_count());
    int i, k;
    if (!all)
        return -1;
    for (i = 0; i < rr_method_count(); i++) {
        const rr_method_desc *d = rr_method_get(i);
        PyObject *opts = PyTuple_New(d->nopts), *row;
        if (!opts)
            goto fail;
        for (k = 0; k < d->nopts; k++) {
            PyObject *t = option_tuple(&d->opts[k]);
            if (!t) {
                Py_DECREF(opts);
                goto fail;
            }
            PyTuple_SET_ITEM(opts, k, t);
        }
        rr_creep_opts o;
        rr_creep_opts_default(&o, i);
        row = Py_BuildValue("(ssNNNNNN)", d->name, d->doc, opts,
                            PyBool_FromLong(d->field != NULL), PyBool_FromLong(d->saturates),
                            PyBool_FromLong(rr_creep_workspace_len(&o) == 0),
                            PyBool_FromLong(d->coulomb_only),
                            PyBool_FromLong(rr_rig_method_check(&o) == RR_OK));
        if (!row)
            goto fail;
        PyTuple_SET_ITEM(all, i, row);
    }
    if (PyModule_AddObject(m, "METHODS", all) == 0)
        return 0;
fail:
    Py_DECREF(all);
    return -1;
}

PyMODINIT_FUNC PyInit__core(void)
{
    PyObject *m;
    import_array();
    if (PyType_Ready(&RigType) < 0 || PyType_Ready(&CreepOptionsType) < 0)
        return NULL;
    m = PyModule_Create(&core_module);
    if (!m)
        return NULL;
    Py_INCREF(&RigType);
    if (PyModule_AddObject(m, "Rig", (PyObject *)&RigType) < 0) {
        Py_DECREF(&RigType);
        Py_DECREF(m);
        return NULL;
    }
    Py_INCREF(&CreepOptionsType);
    if (PyModule_AddObject(m, "CreepOptions", (PyObject *)&CreepOptionsType) < 0) {
        Py_DECREF(&CreepOptionsType);
        Py_DECREF(m);
        return NULL;
    }
    if (add_methods(m) < 0
        || PyModule_AddIntConstant(m, "TABLE_ROW", (int)rr_contact_table_len(1)) < 0
        || PyModule_AddIntConstant(m, "SEARCH_MAX_SAMPLES", RR_SEARCH_MAX_SAMPLES) < 0
        || PyModule_AddIntConstant(m, "SPLINE_NOT_A_KNOT", RR_SPLINE_NOT_A_KNOT) < 0
        || PyModule_AddIntConstant(m, "SPLINE_NATURAL", RR_SPLINE_NATURAL) < 0
        || PyModule_AddIntConstant(m, "RIG_PROFILE_POINTS", RR_RIG_PROFILE_POINTS) < 0
        || PyModule_AddIntConstant(m, "RIG_NSTATE", RR_RIG_NSTATE) < 0
        || PyModule_AddIntConstant(m, "REC_COUNT", RR_REC_COUNT) < 0
        || PyModule_AddIntConstant(m, "RIG_MAX_LIST", RR_RIG_MAX_LIST) < 0
        || PyModule_AddIntConstant(m, "CMD_BUILTIN", RR_CMD_BUILTIN) < 0
        || PyModule_AddIntConstant(m, "CMD_SPEED", RR_CMD_SPEED) < 0
        || PyModule_AddIntConstant(m, "CMD_TORQUE", RR_CMD_TORQUE) < 0
        || PyModule_AddIntConstant(m, "ERR_CONTROLLER", RR_ERR_CONTROLLER) < 0
        || PyModule_AddIntConstant(m, "EXACT_MAX_GRID", RR_EXACT_MAX_GRID) < 0
        || PyModule_AddIntConstant(m, "EXACT_MARGIN", RR_EXACT_MARGIN) < 0
        || PyModule_AddIntConstant(m, "ERR_FRICTION_LIMIT", RR_ERR_FRICTION_LIMIT) < 0
        || PyModule_AddIntConstant(m, "ERR_UNTRUSTED", RR_ERR_UNTRUSTED) < 0
        || add_rows(m, "RIG_PARAMETERS", rr_rig_param_count(), param_tuple) < 0
        || add_rows(m, "RIG_SECTIONS", rr_rig_section_count(), section_tuple) < 0
        || add_rows(m, "RIG_RETIRED", rr_rig_retired_count(), retired_tuple) < 0
        || add_rows(m, "RIG_RECORD", RR_REC_COUNT, record_tuple) < 0
        || add_rows(m, "RIG_WHEEL_FIELDS", RR_WHEEL_NFIELDS, wheel_tuple) < 0
        || PyModule_AddIntConstant(m, "ODE_ROS2", RR_ODE_ROS2) < 0
        || PyModule_AddIntConstant(m, "ODE_TRBDF2", RR_ODE_TRBDF2) < 0
        || PyModule_AddIntConstant(m, "ODE_LINEULER", RR_ODE_LINEULER) < 0
        || PyModule_AddIntConstant(m, "STATUS_MIN", RR_STATUS_MIN) < 0
        || PyModule_AddIntConstant(m, "STATUS_MAX", RR_STATUS_MAX) < 0
        || add_double(m, "FRICTION_MAX", RR_FRICTION_MAX) < 0) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
