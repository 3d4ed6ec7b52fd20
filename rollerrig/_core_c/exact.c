/*
 * exact.c - Kalker's exact theory (core.h): the problem of a Hertzian case,
 * the solver with its fields on any grid, and the built-in table of the
 * exact_table method.
 */
#include "core.h"

#include <string.h>

/* The method "exact" and its options, from a call's CreepOptions (its first
 * argument) or keywords; 0, or -1 with an exception naming func */
static int exact_opts(PyObject *args, PyObject *kwargs, const char *func, rr_creep_checked *o)
{
    if (call_opts(args, kwargs, func, o) < 0)
        return -1;
    if (o->o.method != RR_METHOD_EXACT) {
        PyErr_Format(PyExc_ValueError, "%s: method must be 'exact', got '%s'", func, o->d->name);
        return -1;
    }
    return 0;
}

/* The one case of a call's NCASE arrays (from args[first:]) as an ellipse
 * problem; 0, or -1 with an exception naming func */
static int one_case(PyObject *args, int first, const char *func, rr_contact_problem *c)
{
    PyObject *objs[NCASE];
    input in[NCASE];
    npy_intp n;
    int k;
    if (PyTuple_GET_SIZE(args) != first + NCASE) {
        PyErr_Format(PyExc_TypeError, "%s: expected %d arrays", func, NCASE);
        return -1;
    }
    for (k = 0; k < NCASE; k++)
        objs[k] = PyTuple_GET_ITEM(args, first + k);
    if (parse_inputs(func, objs, case_names, NCASE, &n, in) < 0)
        return -1;
    if (n != 1) {
        PyErr_Format(PyExc_ValueError, "%s: one case expected, got %zd", func, (Py_ssize_t)n);
        return -1;
    }
    load_case(in, 0, c);
    return 0;
}

/* exact_hertz_problem(<as creep_forces, one case>, method="exact", <options>)
 * -> (status, mx, my, dx, dy, x0, y0, A, B, N, G, nu, mu, cx, cy, cphi,
 * spin_shift, tol, maxit): the solver's problem of an ellipse problem
 * (rr_exact_problem_from). */
PyObject *py_exact_hertz_problem(PyObject *self, PyObject *args, PyObject *kwargs)
{
    rr_creep_checked o;
    rr_contact_problem c = {0};
    rr_exact_problem pb;
    int st;
    (void)self;

    if (exact_opts(args, kwargs, "exact_field", &o) < 0
        || one_case(args, opts_first(args), "exact_field", &c) < 0)
        return NULL;
    st = rr_exact_problem_from(&c, &o.o, &pb);
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

/* Problem p solved by the exact theory with the options of o, with its
 * fields: (status, blamed, (mx, my, dx, dy, x0, y0), (fx, fy, mz, fn, delta,
 * area, pmax, ncontact, nslip, normal_products, tang_products,
 * newton_steps, normal_residual, tang_residual), pn, px, py, sx, sy,
 * state), the fields of shape (my, mx), blamed the argument (blame(member
 * of rr_creep_blame)) of a failed problem, or None; NULL with an exception. */
static PyObject *solve_fields(const rr_contact_problem *p, const rr_creep_checked *o,
                              const char *(*blame)(int))
{
    exact_call call;
    rr_exact_problem *pb = &call.pb;
    PyObject *arr[6] = {NULL, NULL, NULL, NULL, NULL, NULL}, *named;
    const char *name;
    npy_intp dims[2];
    int k;

    memset(&call, 0, sizeof call);
    call.st = rr_exact_problem_from(p, &o->o, pb);
    /* a refused problem keeps its own grid's shape where it has one */
    dims[0] = pb->grid.my >= 1 && pb->grid.my <= RR_EXACT_MAX_GRID ? pb->grid.my : 0;
    dims[1] = pb->grid.mx >= 1 && pb->grid.mx <= RR_EXACT_MAX_GRID ? pb->grid.mx : 0;
    for (k = 0; k < 6; k++)
        if (!(arr[k] = PyArray_SimpleNew(2, dims, k < 5 ? NPY_DOUBLE : NPY_INT8)))
            goto fail;
    call.field.pn = OUT(arr[0]);
    call.field.px = OUT(arr[1]);
    call.field.py = OUT(arr[2]);
    call.field.sx = OUT(arr[3]);
    call.field.sy = OUT(arr[4]);
    call.field.state = (signed char *)PyArray_DATA((PyArrayObject *)arr[5]);
    if (call.st == RR_OK) {
        call.work_len = rr_exact_workspace_len(pb->grid.mx, pb->grid.my);
        if (!(call.work = work_take(WORK_EXACT, call.work_len, &call.work_len))) {
            PyErr_NoMemory();
            goto fail;
        }
        interrupt_hook_init(&call.stop);
        pb->interrupt = &call.stop.hook;
        k = run_batch(exact_kernel, &call, 1, 1.0);
        work_give(WORK_EXACT, call.work, call.work_len);
        if (k < 0)
            goto fail;
    } else {
        const npy_intp n = dims[0] * dims[1];
        npy_intp i;
        for (i = 0; i < n; i++) {
            call.field.pn[i] = call.field.px[i] = call.field.py[i] = NAN;
            call.field.sx[i] = call.field.sy[i] = NAN;
            call.field.state[i] = -1;
        }
        call.res.fx = call.res.fy = call.res.mz = call.res.fn = call.res.delta = NAN;
        call.res.area = call.res.pmax = call.res.normal_residual = NAN;
        call.res.tang_residual = NAN;
    }
    name = call.st < 0 ? blame(rr_creep_blame(o, p, call.st)) : NULL;
    if (name) {
        named = PyUnicode_FromString(name);
    } else {
        named = Py_None;
        Py_INCREF(named);
    }
    {
        const rr_exact_result *r = &call.res;
        const rr_grid *g = &pb->grid;
        return Py_BuildValue("(iN(iidddd)(dddddddiiiiidd)NNNNNN)", call.st, named, g->mx, g->my,
                             g->dx, g->dy, g->x0, g->y0, r->fx, r->fy, r->mz, r->fn, r->delta,
                             r->area, r->pmax, r->ncontact, r->nslip, r->normal_products,
                             r->tang_products, r->newton_steps, r->normal_residual,
                             r->tang_residual, arr[0], arr[1], arr[2], arr[3], arr[4], arr[5]);
    }
fail:
    release(arr, 6);
    return NULL;
}

/* exact_field([opts,] <as creep_forces, one case>, *, method="exact",
 * <options>): the ellipse problem of one case, as solve_fields */
PyObject *py_exact_field(PyObject *self, PyObject *args, PyObject *kwargs)
{
    rr_creep_checked o;
    rr_contact_problem c = {0};
    (void)self;
    if (exact_opts(args, kwargs, "exact_field", &o) < 0
        || one_case(args, opts_first(args), "exact_field", &c) < 0)
        return NULL;
    return solve_fields(&c, &o, case_blame);
}

/* exact_solve's argument holding each member of its grid problem (NULL:
 * none, the falling law's: the call takes Coulomb friction only) */
static const char *const grid_arg[RR_PF_COUNT] = {
    [RR_PF_N] = "N", [RR_PF_G] = "G", [RR_PF_NU] = "nu", [RR_PF_CX] = "cx", [RR_PF_CY] = "cy",
    [RR_PF_CPHI] = "cphi", [RR_PF_MU0] = "mu", [RR_PF_MX] = "h", [RR_PF_MY] = "h",
    [RR_PF_DX] = "dx", [RR_PF_DY] = "dy", [RR_PF_X0] = "x0", [RR_PF_Y0] = "y0", [RR_PF_H] = "h",
};

static const char *grid_blame(int field)
{
    return field > RR_PF_NONE && field < RR_PF_COUNT ? grid_arg[field] : NULL;
}

/* exact_solve(opts, h, dx, dy, x0, y0, N, mu, G, nu, cx, cy, cphi): the grid
 * problem of the undeformed distance h (an array (my, mx)), as
 * solve_fields; opts a CreepOptions of the method "exact" (tol, maxit,
 * spin_shift; nx, ny unused). */
PyObject *py_exact_solve(PyObject *self, PyObject *args)
{
    rr_contact_problem p = {0};
    PyObject *opts, *hobj, *res;
    PyArrayObject *h;
    (void)self;

    if (!PyArg_ParseTuple(args, "O!Oddddddddddd:exact_solve", &CreepOptionsType, &opts, &hobj,
                          &p.grid.dx, &p.grid.dy, &p.grid.x0, &p.grid.y0, &p.N,
                          &p.friction.mu0, &p.G, &p.nu, &p.cx, &p.cy, &p.cphi))
        return NULL;
    if (!((CreepOptionsObject *)opts)->ready
        || ((CreepOptionsObject *)opts)->k.o.method != RR_METHOD_EXACT) {
        PyErr_SetString(PyExc_TypeError, "exact_solve: expected a CreepOptions of method 'exact'");
        return NULL;
    }
    h = (PyArrayObject *)PyArray_FROMANY(hobj, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!h)
        return NULL;
    if (PyArray_DIM(h, 0) > RR_EXACT_MAX_GRID || PyArray_DIM(h, 1) > RR_EXACT_MAX_GRID) {
        PyErr_Format(PyExc_ValueError, "exact_solve: h must have 1 to %d elements a side, got "
                     "shape (%zd, %zd)", RR_EXACT_MAX_GRID, (Py_ssize_t)PyArray_DIM(h, 0),
                     (Py_ssize_t)PyArray_DIM(h, 1));
        Py_DECREF(h);
        return NULL;
    }
    p.patch = RR_PATCH_GRID;
    p.grid.my = (int)PyArray_DIM(h, 0);
    p.grid.mx = (int)PyArray_DIM(h, 1);
    p.h = (const double *)PyArray_DATA(h);
    p.friction.A = 1.0;            /* Coulomb friction */
    p.friction.B = 0.0;
    res = solve_fields(&p, &((CreepOptionsObject *)opts)->k, grid_blame);
    Py_DECREF(h);
    return res;
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
