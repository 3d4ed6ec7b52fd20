/*
 * rig.c - the rig in time (core.h): the Rig type over rr_rig (its
 * parameters from a dict, run, the sample's read and write, the plant's
 * right-hand side and Jacobian), and the rig's schedule and speed loops.
 */
#include "core.h"

#include <string.h>

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
    double *work;              /* the rig's workspace (rr_rig_workspace_len), or NULL */
    PyObject *nh_rows[2];      /* the non-Hertzian tables' rows (left, right), kept alive */
    rr_nh_table nh[2];         /* and the tables over them (contact.patch = "nonhertz") */
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
    PyMem_Free(self->work);
    Py_XDECREF(self->nh_rows[0]);
    Py_XDECREF(self->nh_rows[1]);
    Py_XDECREF(self->data);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

/* One side's non-Hertzian table from (rows, (sigma, R0, G, nu, mu_ref)): rows a
 * C-contiguous float64 (n, RR_NH_ROW_LEN) array, kept by *keep (a new
 * reference); the rig checks the table itself (rr_rig_init). */
static int nh_side(PyObject *side, rr_nh_table *t, PyObject **keep)
{
    PyObject *rows, *head;
    PyArrayObject *a;
    if (!PyArg_ParseTuple(side, "OO", &rows, &head))
        return -1;
    a = (PyArrayObject *)rows;
    if (!PyArray_Check(rows) || PyArray_TYPE(a) != NPY_DOUBLE || PyArray_NDIM(a) != 2
        || PyArray_DIM(a, 1) != RR_NH_ROW_LEN || !PyArray_IS_C_CONTIGUOUS(a)
        || PyArray_DIM(a, 0) > 100000000) {
        PyErr_Format(PyExc_ValueError, "Rig: a nonhertz table's rows must be a C-contiguous "
                     "float64 array of shape (n, %d)", RR_NH_ROW_LEN);
        return -1;
    }
    memset(t, 0, sizeof *t);
    t->nrows = (int)PyArray_DIM(a, 0);
    t->rows = PyArray_DATA(a);
    if (!PyArg_ParseTuple(head, "ddddd", &t->sigma, &t->R0, &t->G, &t->nu, &t->mu_ref))
        return -1;
    Py_INCREF(rows);
    Py_XSETREF(*keep, rows);
    return 0;
}

/* Rig(data, y0, dy, params, creep, roller_speed[, nonhertz]): params
 * {"section.key": value} (rig_config_from), the rig's parameters derived by
 * rr_rig_params_from; nonhertz None or ((left rows, head), (right rows,
 * head)): the tables of contact.patch = "nonhertz" */
static int Rig_init(RigObject *self, PyObject *args, PyObject *kwargs)
{
    PyObject *dobj, *params, *creep, *nhobj = Py_None;
    double y0, dy, roller_speed;
    int st;
    (void)kwargs;
    if (self->busy) {
        PyErr_SetString(PyExc_RuntimeError, "Rig.__init__: the rig is in use by another thread");
        return -1;
    }
    /* from here on, until success, the rig is not usable */
    self->ready = 0;
    if (!PyArg_ParseTuple(args, "OddO!O!d|O:Rig", &dobj, &y0, &dy, &PyDict_Type, &params,
                          &PyDict_Type, &creep, &roller_speed, &nhobj))
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
    {
        rr_creep_checked k;
        if (parse_opts(creep, "Rig", NULL, &k) < 0)
            return -1;
        self->p.contact.creep = k.o;
    }
    if (nhobj != Py_None) {
        PyObject *l, *r;
        if (!PyArg_ParseTuple(nhobj, "OO", &l, &r) || nh_side(l, &self->nh[0], &self->nh_rows[0]) < 0
            || nh_side(r, &self->nh[1], &self->nh_rows[1]) < 0)
            return -1;
        rr_rig_params_set_nonhertz(&self->p, &self->nh[0], &self->nh[1]);
    }
    Py_INCREF(dobj);
    Py_XSETREF(self->data, dobj);
    {
        /* the rig's workspace for its creep method, the rig's own: allocated
         * here, never in a step (none for the methods it steps with today) */
        const size_t len = rr_rig_workspace_len(&self->p);
        PyMem_Free(self->work);
        self->work = NULL;
        if (len > 0 && !(self->work = PyMem_Calloc(len, sizeof(double)))) {
            PyErr_NoMemory();
            return -1;
        }
        st = rr_rig_init(&self->p, roller_speed, self->work, len, &self->rig);
    }
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

/* n doubles from a 1-D array-like (`what`: the state, the full state) */
static int vector_n(PyObject *obj, double *y, int n, const char *what)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 1, 1,
                                                          NPY_ARRAY_IN_ARRAY);
    int j;
    if (!a)
        return -1;
    if (PyArray_DIM(a, 0) != n) {
        PyErr_Format(PyExc_ValueError, "Rig: %s has %d values, got %zd", what, n,
                     (Py_ssize_t)PyArray_DIM(a, 0));
        Py_DECREF(a);
        return -1;
    }
    for (j = 0; j < n; j++)
        y[j] = ((const double *)PyArray_DATA(a))[j];
    Py_DECREF(a);
    return 0;
}

static int state_vector(PyObject *obj, double *y)
{
    return vector_n(obj, y, RR_RIG_NSTATE, "the state");
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

/* full_state() -> (names, values, status); set_full_state(values) -> status:
 * the rig's whole state between samples (rr_rig_get_full_state). */
static PyObject *Rig_full_state(RigObject *self, PyObject *noargs)
{
    const char *const *names = rr_rig_full_state_names();
    npy_intp n = RR_FS_COUNT;
    PyObject *out, *tup;
    int j, st;
    (void)noargs;
    if (!(tup = PyTuple_New(RR_FS_COUNT)))
        return NULL;
    for (j = 0; j < RR_FS_COUNT; j++) {
        PyObject *name = PyUnicode_FromString(names[j]);
        if (!name) {
            Py_DECREF(tup);
            return NULL;
        }
        PyTuple_SET_ITEM(tup, j, name);
    }
    if (!(out = PyArray_SimpleNew(1, &n, NPY_DOUBLE)) || rig_enter(self, "full_state") < 0) {
        Py_XDECREF(out);
        Py_DECREF(tup);
        return NULL;
    }
    st = rr_rig_get_full_state(&self->rig, OUT(out));
    rig_leave(self);
    return Py_BuildValue("NNi", tup, out, st);
}

static PyObject *Rig_set_full_state(RigObject *self, PyObject *args)
{
    PyObject *obj;
    double v[RR_FS_COUNT];
    int st;
    if (!PyArg_ParseTuple(args, "O:set_full_state", &obj)
        || vector_n(obj, v, RR_FS_COUNT, "the full state") < 0
        || rig_enter(self, "set_full_state") < 0)
        return NULL;
    st = rr_rig_set_full_state(&self->rig, v);
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
    {"full_state", (PyCFunction)Rig_full_state, METH_NOARGS,
     "full_state() -> (names, values, status): the rig's whole state between samples"},
    {"set_full_state", (PyCFunction)Rig_set_full_state, METH_VARARGS,
     "set_full_state(values) -> status"},
    {NULL, NULL, 0, NULL}
};

static PyGetSetDef Rig_getset[] = {
    {"t", (getter)Rig_get_t, NULL, "time [s]", NULL},
    {"y", (getter)Rig_get_y, NULL, "plant state (a copy)", NULL},
    {"status", (getter)Rig_get_status, NULL, "status of the last sample", NULL},
    {"info", (getter)Rig_get_info, NULL, "the controllers' settings (a dict)", NULL},
    {NULL, NULL, NULL, NULL, NULL}
};

PyTypeObject RigType = {
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

/* ------------------------------------------- the schedule and speed loops */

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
PyObject *py_rig_schedule(PyObject *self, PyObject *args)
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
PyObject *py_rig_speed_loops(PyObject *self, PyObject *arg)
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
