/*
 * geometry.c - wheel-roller geometry (core.h): the contact search of a
 * wheelset, contact tables and their lookup, profile splines, analytic
 * profiles, tables from profile points and the rig's default table.
 */
#include "core.h"

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

/* The four profiles (each its spline: knots, values, second derivatives,
 * the Profile's own, so that Python and C evaluate the same curve) and the
 * eight placement parameters (r0, R0, wheel_y, roller_y per side) as the two
 * wheel-roller pairs; prof[] keeps the arrays alive.  0, or -1 with an
 * exception set. */
int parse_pairs(PyObject *const *pobj, const double *par, const char *func,
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
PyObject *py_wheelset_contact(PyObject *self, PyObject *args)
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
PyObject *py_contact_table(PyObject *self, PyObject *args)
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

int parse_table(PyObject *obj, double y0, double dy, const char *func, rr_contact_table *t)
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
PyObject *py_table_lookup(PyObject *self, PyObject *args)
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
PyObject *py_spline_fit(PyObject *self, PyObject *args)
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
PyObject *py_analytic_profile(PyObject *self, PyObject *args)
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
PyObject *py_profile_table(PyObject *self, PyObject *args)
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
PyObject *py_rig_table(PyObject *self, PyObject *args)
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
