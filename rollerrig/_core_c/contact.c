/*
 * contact.c - the contact core's batch calls (core.h): Hertz, Kalker's
 * coefficients, creep forces (the array call and the scalar path) and
 * the traction field of one case.
 */
#include "core.h"

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

PyObject *py_hertz(PyObject *self, PyObject *args)
{
    static const char *const names[] = {"A", "B", "N", "E1", "nu1", "E2", "nu2"};
    elementwise b;
    (void)self;
    return elementwise_call("hertz", args, 0, names, 7, 4, hertz_kernel, &b, 1.0);
}

/* hertz1(A, B, N, E1, nu1, E2, nu2) -> (a, b, p0, delta, status): one case
 * from Python numbers, the scalar path. */
PyObject *py_hertz1(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
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

PyObject *py_kalker(PyObject *self, PyObject *args)
{
    static const char *const names[] = {"a_over_b", "nu"};
    elementwise b;
    (void)self;
    return elementwise_call("kalker_coefficients", args, 0, names, 2, 4, kalker_kernel, &b, 1.0);
}

/* --------------------------------------------------------- creep forces */

const char *const case_names[NCASE] = {"cx", "cy", "cphi", "a", "b", "N",
                                       "mu", "G", "nu", "speed", "A", "B"};

void load_case(const input *in, npy_intp i, rr_contact_problem *c)
{
    c->cx = IN(in[0], i);
    c->cy = IN(in[1], i);
    c->cphi = IN(in[2], i);
    c->a = IN(in[3], i);
    c->b = IN(in[4], i);
    c->N = IN(in[5], i);
    c->friction.mu0 = IN(in[6], i);
    c->G = IN(in[7], i);
    c->nu = IN(in[8], i);
    c->speed = IN(in[9], i);
    c->friction.A = IN(in[10], i);
    c->friction.B = IN(in[11], i);
    c->patch = RR_PATCH_ELLIPSE;
}

/* The problem of one case's NCASE numbers v[] (in case_names' order). */
static void case_of(const double *v, rr_contact_problem *c)
{
    input in[NCASE];
    int k;
    for (k = 0; k < NCASE; k++) {
        in[k].data = (const char *)&v[k];
        in[k].stride = 0;
    }
    load_case(in, 0, c);
}

/* The argument of the case's calls (case_names) holding each member of an
 * ellipse problem, by enum rr_problem_field; NULL: none (the grid's) */
static const char *const case_arg[RR_PF_COUNT] = {
    [RR_PF_A] = "a", [RR_PF_B] = "b", [RR_PF_N] = "N", [RR_PF_G] = "G", [RR_PF_NU] = "nu",
    [RR_PF_CX] = "cx", [RR_PF_CY] = "cy", [RR_PF_CPHI] = "cphi", [RR_PF_SPEED] = "speed",
    [RR_PF_MU0] = "mu", [RR_PF_FRICTION_A] = "friction.A", [RR_PF_FRICTION_B] = "friction.B",
};

const char *case_blame(int field)
{
    return field > RR_PF_NONE && field < RR_PF_COUNT ? case_arg[field] : NULL;
}

static int creep_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    elementwise *b = ctx;
    npy_intp i;
    for (i = start; i < stop; i++) {
        rr_contact_problem c;
        rr_forces f;
        load_case(b->in, i, &c);
        b->st[i] = (npy_int8)rr_creep_forces_checked(&b->creep, &c, b->work, b->work_len,
                                                     &b->stop.hook, &f);
        b->out[0][i] = f.fx;
        b->out[1][i] = f.fy;
        b->out[2][i] = f.mz;
        if (b->stop.stopped)
            return 1;         /* Ctrl-C: the exception is set, the batch ends */
    }
    return 0;
}

/* creep_forces([opts,] cx, ..., B, *, method, <its options>): the options a
 * CreepOptions or keywords, checked once for the batch (call_opts); each
 * case's own numbers checked by the method */
PyObject *py_creep_forces(PyObject *self, PyObject *args, PyObject *kwargs)
{
    elementwise b;
    PyObject *res;
    int first;
    (void)self;
    if ((first = call_opts(args, kwargs, "creep_forces", &b.creep)) < 0)
        return NULL;
    /* one workspace for the whole batch, zero-filled: a method may keep
     * what it can reuse from one case to the next there (the exact
     * solver's kernel spectra); each call, so each thread, has its own */
    b.work_len = b.creep.work_len;
    b.work = NULL;
    if (b.work_len > 0 && !(b.work = PyMem_Calloc(b.work_len, sizeof(double))))
        return PyErr_NoMemory();
    interrupt_hook_init(&b.stop);
    res = elementwise_call("creep_forces", args, first, case_names, NCASE, 3, creep_kernel, &b,
                           b.creep.cost);
    PyMem_Free(b.work);
    return res;
}

/* creep_forces1(opts, cx, cy, cphi, a, b, N, mu, G, nu, speed, A, B)
 * -> (fx, fy, mz, status): one case from Python numbers, the scalar path
 * (no arrays: the GIL is kept, a case takes microseconds at most). */
PyObject *py_creep_forces1(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    double v[NCASE];
    rr_contact_problem c = {0};
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
    case_of(v, &c);
    {
        const rr_creep_checked *o = &((CreepOptionsObject *)args[0])->k;
        const size_t work_len = o->work_len;
        if (work_len == 0) {
            st = rr_creep_forces_checked(o, &c, NULL, 0, NULL, &f);
        } else {
            /* a method with a workspace is a long computation: the GIL is let
             * go, Ctrl-C noticed within the case */
            double *work = PyMem_Calloc(work_len, sizeof(double));
            interrupt_hook stop;
            if (!work)
                return PyErr_NoMemory();
            interrupt_hook_init(&stop);
            Py_BEGIN_ALLOW_THREADS
            st = rr_creep_forces_checked(o, &c, work, work_len, &stop.hook, &f);
            Py_END_ALLOW_THREADS
            PyMem_Free(work);
            if (stop.stopped)
                return NULL;
        }
    }
    return Py_BuildValue("(dddi)", f.fx, f.fy, f.mz, st);
}

typedef struct {
    rr_contact_problem c;
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
    k->st = rr_creep_field(&k->c, k->o, &k->f, &k->field);
    return 0;
}

/* One case with its traction field (methods that have one, as the registry
 * says), arrays of shape (rows, cols) of the method's field_shape. */
PyObject *py_fastsim_field(PyObject *self, PyObject *args, PyObject *kwargs)
{
    PyObject *objs[NCASE], *arr[7] = {NULL, NULL, NULL, NULL, NULL, NULL, NULL};
    input in[NCASE];
    rr_creep_checked o;
    const rr_method_desc *d;
    fastsim_field_call call;
    npy_intp n, dims[2];
    const int first = opts_first(args);
    int k, rows, cols;
    (void)self;

    if (PyTuple_GET_SIZE(args) != first + NCASE) {
        PyErr_Format(PyExc_TypeError, "fastsim_field: expected %d arrays", NCASE);
        return NULL;
    }
    for (k = 0; k < NCASE; k++)
        objs[k] = PyTuple_GET_ITEM(args, first + k);
    if (call_opts(args, kwargs, "fastsim_field", &o) < 0)
        return NULL;
    d = o.d;
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
    d->field_shape(&o.o, NULL, &rows, &cols);
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
    load_case(in, 0, &call.c);
    call.o = &o.o;
    if (run_batch(fastsim_field_kernel, &call, 1, 1.0) < 0)
        goto fail;
    return Py_BuildValue("(dddiNNNNNNN)", call.f.fx, call.f.fy, call.f.mz, call.st, arr[0],
                         arr[1], arr[2], arr[3], arr[4], arr[5], arr[6]);
fail:
    release(arr, 7);
    return NULL;
}

/* creep_blame(opts, cx, cy, cphi, a, b, N, mu, G, nu, speed, A, B, status)
 * -> the name of the argument of one case that the method's status blames
 * (rr_creep_blame mapped to the case's arguments), or None where no one
 * argument is: for the message of a failed element. */
PyObject *py_creep_blame(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    double v[NCASE];
    rr_contact_problem c = {0};
    const char *name;
    int k, st;
    (void)self;
    if (nargs != NCASE + 2 || !PyObject_TypeCheck(args[0], &CreepOptionsType)
        || !((CreepOptionsObject *)args[0])->ready) {
        PyErr_Format(PyExc_TypeError, "creep_blame: expected a CreepOptions, %d numbers and "
                     "a status", NCASE);
        return NULL;
    }
    for (k = 0; k < NCASE; k++) {
        v[k] = PyFloat_AsDouble(args[k + 1]);
        if (v[k] == -1.0 && PyErr_Occurred())
            return NULL;
    }
    st = (int)PyLong_AsLong(args[NCASE + 1]);
    if (st == -1 && PyErr_Occurred())
        return NULL;
    case_of(v, &c);
    name = case_blame(rr_creep_blame(&((CreepOptionsObject *)args[0])->k, &c, st));
    if (!name)
        Py_RETURN_NONE;
    return PyUnicode_FromString(name);
}
