/*
 * exact.c - Kalker's exact theory (core.h): the problem of a Hertzian case,
 * the solver with its fields on any grid, and the built-in table of the
 * exact_table method.
 */
#include "core.h"

#include <string.h>

/* exact_hertz_problem(<as creep_forces, one case>, method="exact", <options>)
 * -> (status, mx, my, dx, dy, x0, y0, A, B, N, G, nu, mu, cx, cy, cphi,
 * spin_shift, tol, maxit): the problem rr_exact_solve gets for a Hertzian
 * case (rr_exact_hertz_problem), for exact_solve and its field. */
PyObject *py_exact_hertz_problem(PyObject *self, PyObject *args, PyObject *kwargs)
{
    PyObject *objs[NCASE];
    input in[NCASE];
    rr_creep_checked o;
    rr_contact_case c;
    rr_friction fr;
    rr_exact_problem pb;
    npy_intp n;
    const int first = opts_first(args);
    int k, st;
    (void)self;

    if (PyTuple_GET_SIZE(args) != first + NCASE) {
        PyErr_Format(PyExc_TypeError, "exact_hertz_problem: expected %d arrays", NCASE);
        return NULL;
    }
    for (k = 0; k < NCASE; k++)
        objs[k] = PyTuple_GET_ITEM(args, first + k);
    if (call_opts(args, kwargs, "exact_field", &o) < 0)
        return NULL;
    if (o.o.method != RR_METHOD_EXACT) {
        PyErr_Format(PyExc_ValueError, "exact_field: method must be 'exact', got '%s'",
                     o.d->name);
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
    st = rr_exact_hertz_problem(&c, &fr, &o.o, &pb);
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
PyObject *py_exact_solve(PyObject *self, PyObject *args)
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

/* The built-in exact-theory table: (shape, lo, hi, nu, r0, nx, the bytes of
 * its float32 values). */
PyObject *py_exact_table_builtin(PyObject *self, PyObject *unused)
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
