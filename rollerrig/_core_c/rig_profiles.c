/*
 * rig_profiles.c - the rig's contact table on real profiles (core.h):
 * rig_profile_table, rr_rig_table_build_profiles_rows over the rows in
 * threads, each profile's points checked and kept alive for the call.
 */
#include "core.h"

typedef struct {
    const rr_rig_geometry *g;
    const rr_rig_profiles *pr;
    rr_contact_table *t;
    long data_len, work_len;
    double *work, bad_y;
    int st;
} profile_table_batch;

static int profile_table_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    profile_table_batch *b = ctx;
    b->st = rr_rig_table_build_profiles_rows(b->g, b->pr, b->t->data, b->data_len, b->work,
                                             b->work_len, (int)start, (int)stop, b->t,
                                             &b->bad_y);
    return b->st < 0;
}

/* A slot of rig_profile_table: None (n = 0) or (y, z, end), the arrays 1-D
 * float64 of one length, kept alive in keep[0..1]. */
static int profile_slot(PyObject *o, int k, rr_profile_points *p, PyArrayObject **keep)
{
    PyObject *yo, *zo;
    int end;
    p->n = 0;
    p->y = p->z = NULL;
    p->end = RR_SPLINE_NOT_A_KNOT;
    if (o == Py_None)
        return 0;
    if (!PyArg_ParseTuple(o, "OOi:rig_profile_table", &yo, &zo, &end))
        return -1;
    keep[0] = (PyArrayObject *)PyArray_FROM_OTF(yo, NPY_DOUBLE, NPY_ARRAY_IN_ARRAY);
    keep[1] = keep[0] ? (PyArrayObject *)PyArray_FROM_OTF(zo, NPY_DOUBLE, NPY_ARRAY_IN_ARRAY)
                      : NULL;
    if (!keep[1])
        return -1;
    if (PyArray_NDIM(keep[0]) != 1 || PyArray_NDIM(keep[1]) != 1
        || PyArray_DIM(keep[0], 0) != PyArray_DIM(keep[1], 0)
        || PyArray_DIM(keep[0], 0) > RR_SPLINE_MAX_POINTS) {
        PyErr_Format(PyExc_ValueError, "rig_profile_table: profile %d: y and z must be 1-D "
                     "of one length up to %d", k, RR_SPLINE_MAX_POINTS);
        return -1;
    }
    p->n = (int)PyArray_DIM(keep[0], 0);
    p->y = (const double *)PyArray_DATA(keep[0]);
    p->z = (const double *)PyArray_DATA(keep[1]);
    p->end = end;
    return 0;
}

/* rig_profile_table((r0, R0, half_width, alpha, crown, half_spacing, half_range, rows),
 * (wheel_scale, roller_scale, gauge), (wheel, roller, wheel_right, roller_right))
 * -> (data, y0, dy, status, bad_y, which, point): rr_rig_table_build_profiles_rows
 * through the batch loop; a profile None (rr_rig_profiles' n = 0) or (y, z, end). */
PyObject *py_rig_profile_table(PyObject *self, PyObject *args)
{
    rr_rig_geometry g;
    rr_rig_profiles pr;
    rr_contact_table t;
    profile_table_batch b;
    PyObject *rows, *slots[4], *data = NULL;
    PyArrayObject *keep[8] = {NULL};
    double *work = NULL;
    npy_intp len;
    long work_len;
    int which = -1, point = -1, st;
    (void)self;

    if (!PyArg_ParseTuple(args, "(dddddddO)(ddd)(OOOO):rig_profile_table", &g.wheel_radius,
                          &g.roller_radius, &g.profile_half_width, &g.cone_angle,
                          &g.crown_radius, &g.contact_half_spacing, &g.table_half_range,
                          &rows, &pr.wheel_scale, &pr.roller_scale, &pr.gauge, &slots[0],
                          &slots[1], &slots[2], &slots[3])
        || int_arg(rows, "rig_profile_table", "rows", 2, RR_RIG_TABLE_MAX_ROWS,
                   &g.table_rows) < 0
        || profile_slot(slots[0], 0, &pr.wheel, &keep[0]) < 0
        || profile_slot(slots[1], 1, &pr.roller, &keep[2]) < 0
        || profile_slot(slots[2], 2, &pr.wheel_right, &keep[4]) < 0
        || profile_slot(slots[3], 3, &pr.roller_right, &keep[6]) < 0)
        goto fail;
    t.y0 = t.dy = NAN;
    if ((st = rr_rig_profiles_check(&pr, &which, &point)) != RR_OK) {
        release((PyObject **)keep, 8);
        return Py_BuildValue("Oddidii", Py_None, t.y0, t.dy, st, NAN, which, point);
    }
    len = (npy_intp)rr_rig_table_data_len(&g);
    work_len = rr_rig_profiles_work_len(&pr);
    if (!(data = PyArray_SimpleNew(1, &len, NPY_DOUBLE)))
        goto fail;
    if (!(work = PyMem_Malloc((size_t)(work_len > 0 ? work_len : 1) * sizeof(double)))) {
        PyErr_NoMemory();
        goto fail;
    }
    t.data = OUT(data);
    b.g = &g;
    b.pr = &pr;
    b.t = &t;
    b.data_len = (long)len;
    b.work = work;
    b.work_len = work_len;
    b.bad_y = NAN;
    b.st = RR_OK;
    if (run_batch(profile_table_kernel, &b, len ? g.table_rows : 1, 1600.0) < 0)
        goto fail;
    PyMem_Free(work);
    release((PyObject **)keep, 8);
    return Py_BuildValue("Nddidii", data, t.y0, t.dy, b.st, b.bad_y, -1, -1);
fail:
    PyMem_Free(work);
    release((PyObject **)keep, 8);
    Py_XDECREF(data);
    return NULL;
}
