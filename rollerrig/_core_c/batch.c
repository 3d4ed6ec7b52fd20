/*
 * batch.c - the binding's one batch loop and the inputs and outputs of its
 * batch calls (core.h): 1-D float64 arrays of length n or 1, outputs
 * allocated here, the GIL released around chunks of cases, Ctrl-C checked
 * between chunks and, through the core's interrupt hook, within a case;
 * and the exact solver's workspaces, kept from call to call.
 */
#include "core.h"

#include <stddef.h>
#include <string.h>
#include <time.h>

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

int parse_inputs(const char *func, PyObject *const *objs, const char *const *names,
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

int new_outputs(npy_intp n, int ndouble, PyObject **out)
{
    int k;
    for (k = 0; k <= ndouble; k++) {
        out[k] = PyArray_SimpleNew(1, &n, k < ndouble ? NPY_DOUBLE : NPY_INT8);
        if (!out[k])
            return -1;
    }
    return 0;
}

PyObject *outputs_tuple(PyObject **out, int count)
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

void release(PyObject **out, int count)
{
    int k;
    for (k = 0; k < count; k++)
        Py_XDECREF(out[k]);
}

int run_batch(batch_kernel kernel, void *ctx, npy_intp n, double cost)
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

void interrupt_hook_init(interrupt_hook *h)
{
    h->hook.poll = poll_signals;
    h->hook.ctx = h;
    h->stopped = 0;
    h->next = seconds_now() + INTERRUPT_PERIOD;
}

int int_arg(PyObject *v, const char *func, const char *name, long lo, long hi, int *out)
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

PyObject *elementwise_call(const char *func, PyObject *args, int first,
                           const char *const *names, int nin, int nout, batch_kernel kernel,
                           elementwise *b, double cost)
{
    PyObject *objs[MAX_IN], *out[MAX_OUT + 1] = {NULL, NULL, NULL, NULL, NULL}, *res;
    npy_intp n;
    int k;
    if (!PyTuple_Check(args) || PyTuple_GET_SIZE(args) != first + nin) {
        PyErr_Format(PyExc_TypeError, "%s: expected %d arrays (%s, ...)", func, nin, names[0]);
        return NULL;
    }
    for (k = 0; k < nin; k++)
        objs[k] = PyTuple_GET_ITEM(args, first + k);
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

/* ---- the exact solver's workspaces, kept from call to call ----------------- */

/* The solver's rule is a workspace zero-filled before its first use, after
 * which it keeps the kernel spectra of its grids there (rr_exact.h: a case
 * gives the doubles it gives on a fresh workspace).  A fresh one
 * zero-filled each call cost rig_exact's call a ninth of its instructions
 * (a workspace for grids of n + 16 elements a side, most of it never
 * touched), and threw the spectra away.  Taken and given back with the GIL
 * held, so a call has its workspace to itself while it runs without it.
 * A pool per kind of call: exact_solve's layout and rig_exact's carving of
 * the same memory differ, and one's scratch can fall on the other's kept
 * spectra and not on their keys (rr_wheel_exact.c marks its own carving;
 * the bare solver's could not tell). */
#define POOL_SIZE 2
static double *pool_work[WORK_KINDS][POOL_SIZE];
static size_t pool_len[WORK_KINDS][POOL_SIZE];

/* A workspace of kind for at least len doubles: the smallest kept one that
 * is long enough, else a new one zero-filled; *got its length.  NULL: no
 * memory. */
double *work_take(int kind, size_t len, size_t *got)
{
    double **pw = pool_work[kind];
    size_t *pl = pool_len[kind];
    int j, best = -1;
    double *w;
    for (j = 0; j < POOL_SIZE; j++)
        if (pw[j] && pl[j] >= len && (best < 0 || pl[j] < pl[best]))
            best = j;
    if (best >= 0) {
        w = pw[best];
        *got = pl[best];
        pw[best] = NULL;
        return w;
    }
    *got = len;
    return PyMem_RawCalloc(len, sizeof(double));
}

/* w (of len doubles) kept for the next call of its kind: in an empty place,
 * else in place of the smallest kept one where that is shorter (which is
 * freed), else freed. */
void work_give(int kind, double *w, size_t len)
{
    double **pw = pool_work[kind];
    size_t *pl = pool_len[kind];
    int j, slot = 0;
    if (!w)
        return;
    for (j = 0; j < POOL_SIZE; j++) {
        if (!pw[j]) {
            slot = j;
            break;
        }
        if (pl[j] < pl[slot])
            slot = j;
    }
    if (pw[slot] && pl[slot] >= len) {
        PyMem_RawFree(w);
        return;
    }
    PyMem_RawFree(pw[slot]);
    pw[slot] = w;
    pl[slot] = len;
}
