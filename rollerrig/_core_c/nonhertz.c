/*
 * nonhertz.c - the non-Hertzian contact's table rows (rr_nonhertz_table.h,
 * the GIL released while a row is built: Python threads build rows side by
 * side) and one wheel's contact from a table (rr_nonhertz.h).
 * rollerrig/geometry/nonhertz.py words the errors.
 */
#include "core.h"

#include <string.h>

/* The row's build in the batch loop (no GIL; Ctrl-C through the hook). */
typedef struct {
    rr_nh_row_problem pb;
    double *work;
    size_t work_len;
    int side;
    double row[RR_NH_ROW_LEN];
    rr_nh_row_info info;
    interrupt_hook stop;
    int st;
} row_call;

static int row_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    row_call *k = ctx;
    (void)start;
    (void)stop;
    k->st = rr_nonhertz_row(&k->pb, k->work, k->work_len, k->side, k->row, &k->info);
    return 0;
}

/* nonhertz_row(12 profile arrays, 8 params, side, y_ws, (z0, roll0), (s_roller,
 * s_wheel, delta, A, B), (Fz_max, Fz_regions, E, nu, mu), ((c), (v), (w)), roller_spin,
 * vmin, (n, n_corr, richardson, combine), (tol, maxit)) -> (status, row
 * (RR_NH_ROW_LEN,), {info}).  The workspace grows until the grids fit. */
PyObject *py_nonhertz_row(PyObject *self, PyObject *args)
{
    PyObject *pobj[NPROF], *res = NULL, *arr = NULL;
    PyArrayObject *prof[NPROF];
    double par[8];
    rr_wheel_roller pair[2];
    row_call *k;
    rr_nh_row_problem *pb;
    rr_contact_point *q;
    rr_motion *m;
    int side, tries, j;
    npy_intp dim = RR_NH_ROW_LEN;
    (void)self;

    for (j = 0; j < NPROF; j++)
        prof[j] = NULL;
    if (!(k = PyMem_RawCalloc(1, sizeof *k)))
        return PyErr_NoMemory();
    pb = &k->pb;
    q = &pb->point;
    m = &pb->wheelset;
    rr_nonhertz_row_default(pb);
    if (!PyArg_ParseTuple(args, PAIR_FORMAT "id(dd)(ddddd)(ddddd)((ddd)(ddd)(ddd))dd(iiid)(di)"
                          ":nonhertz_row",
                          PAIR_ARGS(pobj, par), &side, &pb->y_ws, &pb->pose0.z,
                          &pb->pose0.roll, &q->s_roller, &q->s_wheel, &q->delta, &q->A, &q->B,
                          &pb->Fz_max, &pb->Fz_regions, &pb->E, &pb->nu, &pb->mu, &m->c[0], &m->c[1], &m->c[2],
                          &m->v[0], &m->v[1], &m->v[2], &m->w[0], &m->w[1], &m->w[2],
                          &pb->roller_spin, &pb->vmin, &pb->n, &pb->n_corr, &pb->richardson,
                          &pb->combine, &pb->tol, &pb->maxit))
        goto done;
    if (parse_pairs(pobj, par, "nonhertz_table", prof, pair) < 0)
        goto done;
    pb->pair = &pair[side == 0 ? 0 : 1];
    k->side = pb->n + 16;
    for (tries = 0; tries < 6; tries++) {
        int need;
        k->side = k->side < RR_EXACT_MAX_GRID / 2 ? k->side : RR_EXACT_MAX_GRID / 2;
        PyMem_RawFree(k->work);
        k->work_len = rr_nonhertz_row_workspace_len(pb, k->side);
        if (!k->work_len)
            k->work_len = 1;               /* options rr_nonhertz_row names */
        if (!(k->work = PyMem_RawCalloc(k->work_len, sizeof(double)))) {
            PyErr_NoMemory();
            goto done;
        }
        interrupt_hook_init(&k->stop);
        pb->interrupt = &k->stop.hook;
        if (run_batch(row_kernel, k, 1, 1.0) < 0)
            goto done;
        if (k->st != RR_ERR_WORKSPACE || k->side == RR_EXACT_MAX_GRID / 2 || !k->info.need)
            break;
        need = (int)k->info.need;
        need = need + need / 4 + 8;
        k->side = need > k->side ? need : 2 * k->side;
    }
    if (!(arr = PyArray_SimpleNew(1, &dim, NPY_DOUBLE)))
        goto done;
    memcpy(PyArray_DATA((PyArrayObject *)arr), k->row, sizeof k->row);
    res = Py_BuildValue("(iO{s:i,s:i,s:i,s:i,s:i,s:n,s:i,s:i,s:i,s:i,s:i})", k->st, arr,
                        "why", k->info.why, "patch", k->info.patch, "node", k->info.node,
                        "wheel_why", k->info.wheel_why, "gap_why", k->info.gap_why, "need",
                        (Py_ssize_t)k->info.need, "solves", k->info.solves, "patches",
                        k->info.patches, "excluded", k->info.excluded, "merged",
                        k->info.merged, "side", k->side);
done:
    Py_XDECREF(arr);
    PyMem_RawFree(k->work);
    PyMem_RawFree(k);
    release((PyObject **)prof, NPROF);
    return res;
}

/* The table of rows (a C-contiguous (nrows, RR_NH_ROW_LEN) float64 array)
 * and its header (sigma, R0, G, nu, mu_ref). */
static int parse_nh_table(PyObject *rows, PyObject *head, rr_nh_table *t)
{
    PyArrayObject *a;
    if (!PyArray_Check(rows)) {
        PyErr_SetString(PyExc_TypeError, "nonhertz: rows must be a numpy array");
        return -1;
    }
    a = (PyArrayObject *)rows;
    if (PyArray_TYPE(a) != NPY_DOUBLE || PyArray_NDIM(a) != 2
        || PyArray_DIM(a, 1) != RR_NH_ROW_LEN || !PyArray_IS_C_CONTIGUOUS(a)
        || PyArray_DIM(a, 0) > 100000000) {
        PyErr_Format(PyExc_ValueError, "nonhertz: rows must be a C-contiguous float64 array "
                     "of shape (n, %d)", RR_NH_ROW_LEN);
        return -1;
    }
    memset(t, 0, sizeof *t);
    t->nrows = (int)PyArray_DIM(a, 0);
    t->rows = PyArray_DATA(a);
    return PyArg_ParseTuple(head, "ddddd", &t->sigma, &t->R0, &t->G, &t->nu, &t->mu_ref) ? 0
                                                                                         : -1;
}

/* nonhertz_check(rows, (sigma, R0, G, nu, mu_ref)) -> (status, bad_row) */
PyObject *py_nonhertz_check(PyObject *self, PyObject *args)
{
    PyObject *rows, *head;
    rr_nh_table t;
    int bad = -1, st;
    (void)self;
    if (!PyArg_ParseTuple(args, "OO:nonhertz_check", &rows, &head)
        || parse_nh_table(rows, head, &t) < 0)
        return NULL;
    st = rr_nonhertz_table_check(&t, &bad);
    return Py_BuildValue("(ii)", st, bad);
}

static PyObject *patch_tuple(const rr_nh_patch *p)
{
    return Py_BuildValue("{s:d,s:d,s:d,s:d,s:(ddd),s:(ddd),s:(ddd),s:(ddd),s:(ddd),s:d,s:d,s:d,"
                         "s:d,s:d,s:d}", "N", p->N, "fx", p->fx, "fy", p->fy, "mz", p->mz,
                         "force", p->force[0], p->force[1], p->force[2], "point", p->point[0],
                         p->point[1], p->point[2], "t1", p->t1[0], p->t1[1], p->t1[2], "t2",
                         p->t2[0], p->t2[1], p->t2[2], "n", p->n[0], p->n[1], p->n[2], "delta",
                         p->delta, "cx", p->cx, "cy", p->cy, "cphi", p->cphi, "area", p->area,
                         "pmax", p->pmax);
}

/* nonhertz_wheel(rows, (sigma, R0, G, nu, mu_ref), (y, Fz, mu, roller_spin,
 * vmin), ((c0)(v0)(w0)), ((c1)(v1)(w1))) -> (status, {result}, (patch, ...))
 * (the table checked first: status RR_ERR_TABLE, bad_row in the result);
 * nonhertz_locate(rows, head, y) -> (status, row, w). */
PyObject *py_nonhertz_wheel(PyObject *self, PyObject *args)
{
    PyObject *rows, *head, *pt = NULL, *res = NULL;
    rr_nh_table t;
    rr_nh_state s;
    rr_nh_result r;
    int st, bad = -1, j;
    (void)self;
    memset(&s, 0, sizeof s);
    memset(&r, 0, sizeof r);
    if (!PyArg_ParseTuple(args, "OO(ddddddd)((ddd)(ddd)(ddd))((ddd)(ddd)(ddd)):nonhertz_wheel",
                          &rows, &head, &s.y, &s.Fz, &s.mu, &s.roller_spin, &s.vmin, &s.x,
                          &s.yaw,
                          &s.motion[0].c[0], &s.motion[0].c[1], &s.motion[0].c[2],
                          &s.motion[0].v[0], &s.motion[0].v[1], &s.motion[0].v[2],
                          &s.motion[0].w[0], &s.motion[0].w[1], &s.motion[0].w[2],
                          &s.motion[1].c[0], &s.motion[1].c[1], &s.motion[1].c[2],
                          &s.motion[1].v[0], &s.motion[1].v[1], &s.motion[1].v[2],
                          &s.motion[1].w[0], &s.motion[1].w[1], &s.motion[1].w[2])
        || parse_nh_table(rows, head, &t) < 0)
        return NULL;
    st = rr_nonhertz_table_check(&t, &bad);
    if (st == RR_OK)
        st = rr_nonhertz_wheel(&t, &s, &r);
    if (!(pt = PyTuple_New(st == RR_OK ? r.npatch : 0)))
        return NULL;
    for (j = 0; st == RR_OK && j < r.npatch; j++) {
        PyObject *p = patch_tuple(&r.patch[j]);
        if (!p) {
            Py_DECREF(pt);
            return NULL;
        }
        PyTuple_SET_ITEM(pt, j, p);
    }
    res = Py_BuildValue("(i{s:(ddd),s:(ddd),s:d,s:d,s:d,s:(ddd),s:(dd),s:i,s:d,s:i,s:i}O)", st,
                        "force", r.force[0], r.force[1], r.force[2], "moment", r.moment[0],
                        r.moment[1], r.moment[2], "N", r.N, "area", r.area, "pmax", r.pmax,
                        "centre", r.centre[0], r.centre[1], r.centre[2], "dz", r.dz[0],
                        r.dz[1], "row", r.row, "w", r.w, "table_calls", r.table_calls,
                        "bad_row", bad, pt);
    Py_DECREF(pt);
    return res;
}

PyObject *py_nonhertz_locate(PyObject *self, PyObject *args)
{
    PyObject *rows, *head;
    rr_nh_table t;
    double y, w = 0.0;
    int row = -1, st;
    (void)self;
    if (!PyArg_ParseTuple(args, "OOd:nonhertz_locate", &rows, &head, &y)
        || parse_nh_table(rows, head, &t) < 0)
        return NULL;
    st = rr_nonhertz_locate(&t, y, &row, &w);
    return Py_BuildValue("(iid)", st, row, w);
}

int add_nonhertz(PyObject *m)
{
    const struct { const char *name; int value; } c[] = {
        {"NH_ROW_LEN", RR_NH_ROW_LEN}, {"NH_ROW_HEAD", RR_NH_ROW_HEAD},
        {"NH_PATCH_LEN", RR_NH_PATCH_LEN}, {"NH_NODES", RR_NH_NODES},
        {"NH_NQ", RR_NH_NQ}, {"NH_MAX_PATCHES", RR_NH_MAX_PATCHES},
        {"NH_CORR", RR_NH_CORR}, {"NH_CORR_LEN", RR_NH_CORR_LEN},
        {"NH_ROW_NODE", RR_NH_ROW_NODE}, {"NH_ROW_GRID", RR_NH_ROW_GRID},
        {"NH_ROW_SOLVE", RR_NH_ROW_SOLVE}, {"NH_ROW_COEFF", RR_NH_ROW_COEFF}};
    int k;
    for (k = 0; k < RR_COUNTOF(c); k++)
        if (PyModule_AddIntConstant(m, c[k].name, c[k].value) < 0)
            return -1;
    return 0;
}
