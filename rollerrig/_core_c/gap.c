/*
 * gap.c - the undeformed distance of one wheel on its roller (rr_gap.h),
 * core.h: the C build with its frame, regions and the numbers of a failed
 * build's message (rollerrig/geometry/patch.py words them).
 */
#include "core.h"

/* (a, b, c) of a 3-vector */
static PyObject *vec3(const double *v)
{
    return Py_BuildValue("(ddd)", v[0], v[1], v[2]);
}

/* ((lo, hi), ...) of n intervals */
static PyObject *intervals(const double (*iv)[2], int n)
{
    PyObject *t = PyTuple_New(n);
    int k;
    if (!t)
        return NULL;
    for (k = 0; k < n; k++) {
        PyObject *e = Py_BuildValue("(dd)", iv[k][0], iv[k][1]);
        if (!e) {
            Py_DECREF(t);
            return NULL;
        }
        PyTuple_SET_ITEM(t, k, e);
    }
    return t;
}

/* The patch's numbers as a dict (names as rr_gap_patch's fields). */
CORE_PRIVATE PyObject *gap_patch_dict(const rr_gap_patch *p)
{
    const struct { const char *name; double v; } num[] = {
        {"dx", p->grid.dx}, {"dy", p->grid.dy}, {"x0", p->grid.x0}, {"y0", p->grid.y0},
        {"delta", p->delta}, {"s_roller", p->s_roller}, {"s_wheel", p->s_wheel},
        {"r", p->r}, {"R", p->R}, {"pen", p->pen}, {"level", p->level}, {"lo", p->lo},
        {"hi", p->hi}, {"plane_lo", p->plane_lo}, {"plane_hi", p->plane_hi},
        {"x_t", p->x_t}, {"half_length", p->half_length}, {"need_mx", p->need_mx},
        {"need_my", p->need_my}, {"step", p->step}, {"off_s", p->off_s},
        {"off_lo", p->off_lo}, {"off_hi", p->off_hi}};
    const struct { const char *name; int v; } ints[] = {
        {"why", p->why}, {"mx", p->grid.mx}, {"my", p->grid.my}, {"off_body", p->off_body}};
    const char *names[] = {"point", "wheel_point", "t1", "t2", "n", "regions", "excluded"};
    PyObject *d = PyDict_New(), *v[7];
    int k, bad = d == NULL;
    for (k = 0; !bad && k < RR_COUNTOF(num); k++) {
        PyObject *x = PyFloat_FromDouble(num[k].v);
        bad = !x || PyDict_SetItemString(d, num[k].name, x) < 0;
        Py_XDECREF(x);
    }
    for (k = 0; !bad && k < RR_COUNTOF(ints); k++) {
        PyObject *x = PyLong_FromLong(ints[k].v);
        bad = !x || PyDict_SetItemString(d, ints[k].name, x) < 0;
        Py_XDECREF(x);
    }
    if (bad) {
        Py_XDECREF(d);
        return NULL;
    }
    v[0] = vec3(p->point);
    v[1] = vec3(p->wheel_point);
    v[2] = vec3(p->t1);
    v[3] = vec3(p->t2);
    v[4] = vec3(p->n);
    v[5] = intervals((const double (*)[2])p->regions, p->nregions);
    v[6] = intervals((const double (*)[2])p->excluded, p->nexcluded);
    for (k = 0; k < 7; k++) {
        if (!v[k] || PyDict_SetItemString(d, names[k], v[k]) < 0)
            bad = 1;
        Py_XDECREF(v[k]);
    }
    if (bad) {
        Py_DECREF(d);
        return NULL;
    }
    return d;
}

/* h of a built grid as a new (my, mx) float64 array. */
CORE_PRIVATE PyObject *gap_h_array(const double *h, int mx, int my)
{
    npy_intp dims[2];
    PyObject *a;
    dims[0] = my;
    dims[1] = mx;
    if (!(a = PyArray_SimpleNew(2, dims, NPY_DOUBLE)))
        return NULL;
    memcpy(OUT(a), h, (size_t)mx * (size_t)my * sizeof(double));
    return a;
}

/* The options of a build from Python numbers: 0, or -1 with a ValueError. */
static int gap_opts(int reference, double ref_s, double ref_delta, double approach,
                    double cover, PyObject *nobj, double dx, double dy, double combine,
                    const char *func, rr_gap_opts *o)
{
    rr_gap_opts_default(o);
    if (int_arg(nobj, func, "n", 4, RR_GAP_MAX_N, &o->n) < 0)
        return -1;
    o->reference = reference;
    o->s_roller = ref_s;
    o->delta = ref_delta;
    o->approach = approach;
    o->cover = cover;
    o->dx = dx;
    o->dy = dy;
    o->combine = combine;
    return 0;
}

/* gap_build(12 profile arrays, 8 params, side (0 left, 1 right), y_ws, z, roll,
 * s_roller, s_wheel, delta, reference, ref_s_roller, ref_delta, approach,
 * cover, n, dx, dy, combine) -> (status, h (my, mx) or None, {patch}) */
PyObject *py_gap_build(PyObject *self, PyObject *args)
{
    PyObject *pobj[NPROF], *nobj, *h_arr = NULL, *info = NULL, *res = NULL;
    PyArrayObject *prof[NPROF];
    double par[8], y_ws, z, roll, s_r, s_w, delta, ref_s, ref_d, approach, cover, dx, dy, comb;
    double *work = NULL, *h = NULL;
    rr_wheel_roller pair[2];
    rr_gap_site site;
    rr_gap_opts o;
    rr_gap_patch patch;
    size_t work_len, h_len = (size_t)RR_EXACT_MAX_GRID * RR_EXACT_MAX_GRID;
    int side, reference, st, k;
    (void)self;

    for (k = 0; k < NPROF; k++)
        prof[k] = NULL;
    if (!PyArg_ParseTuple(args, PAIR_FORMAT "iddddddiddddOddd:gap_build",
                          PAIR_ARGS(pobj, par), &side, &y_ws, &z, &roll, &s_r, &s_w, &delta,
                          &reference, &ref_s, &ref_d, &approach, &cover, &nobj, &dx, &dy,
                          &comb))
        return NULL;
    if (parse_pairs(pobj, par, "undeformed_distance", prof, pair) < 0
        || gap_opts(reference, ref_s, ref_d, approach, cover, nobj, dx, dy, comb,
                    "undeformed_distance", &o) < 0)
        goto done;
    site.pair = &pair[side == 0 ? 0 : 1];
    site.y_ws = y_ws;
    site.z = z;
    site.roll = roll;
    site.s_roller = s_r;
    site.s_wheel = s_w;
    site.delta = delta;
    /* the samples' workspace (up to 13 x 800 003 doubles for elements of
     * 1e-6 m and below) and an h as large as the solver takes, whose pages
     * the system gives only where the grid writes */
    if (!(work_len = rr_gap_workspace_len(&o))) {
        work_len = 1;                        /* the build names the bad option */
    }
    work = PyMem_RawMalloc(work_len * sizeof(double));
    h = PyMem_RawMalloc(h_len * sizeof(double));
    if (!work || !h) {
        PyErr_NoMemory();
        goto done;
    }
    Py_BEGIN_ALLOW_THREADS
    st = rr_gap_build(&site, &o, work, work_len, h, h_len, &patch);
    Py_END_ALLOW_THREADS
    if (st >= 0) {
        h_arr = gap_h_array(h, patch.grid.mx, patch.grid.my);
    } else {
        h_arr = Py_None;
        Py_INCREF(h_arr);
    }
    info = gap_patch_dict(&patch);
    if (h_arr && info)
        res = Py_BuildValue("(iOO)", st, h_arr, info);
done:
    PyMem_RawFree(work);
    PyMem_RawFree(h);
    Py_XDECREF(h_arr);
    Py_XDECREF(info);
    release((PyObject **)prof, NPROF);
    return res;
}

/* ------------------------------------------------------- rr_wheel_exact */

/* One rr_wheel_exact call in the batch loop (the GIL released, Ctrl-C
 * through the hook). */
typedef struct {
    rr_wheel_exact_problem pb;
    double *work, *h;
    size_t work_len, cells;
    rr_exact_field field;
    rr_wheel_exact_result res;
    interrupt_hook stop;
    int st;
} wheel_call;

static int wheel_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    wheel_call *k = ctx;
    (void)start;
    (void)stop;
    k->st = rr_wheel_exact(&k->pb, k->work, k->work_len, k->h, k->cells, &k->field, k->cells,
                           &k->res);
    return 0;
}

static void wheel_free(wheel_call *k)
{
    work_give(WORK_WHEEL, k->work, k->work_len);
    PyMem_RawFree(k->h);
    PyMem_RawFree(k->field.pn);
    PyMem_RawFree(k->field.px);
    PyMem_RawFree(k->field.py);
    PyMem_RawFree(k->field.sx);
    PyMem_RawFree(k->field.sy);
    PyMem_RawFree(k->field.state);
    k->work = k->h = k->field.pn = k->field.px = k->field.py = k->field.sx = k->field.sy = NULL;
    k->field.state = NULL;
}

/* Buffers for grids up to side x side: the workspace zero-filled (the
 * solver's rule), h and the fields.  0, or -1 with MemoryError. */
static int wheel_alloc(wheel_call *k, int side)
{
    wheel_free(k);
    k->cells = (size_t)side * (size_t)side;
    k->work_len = rr_wheel_exact_workspace_len(&k->pb, side, side);
    if (!k->work_len)
        k->work_len = 1;                     /* options rr_wheel_exact names */
    k->work = work_take(WORK_WHEEL, k->work_len, &k->work_len);
    k->h = PyMem_RawMalloc(k->cells * sizeof(double));
    k->field.pn = PyMem_RawMalloc(k->cells * sizeof(double));
    k->field.px = PyMem_RawMalloc(k->cells * sizeof(double));
    k->field.py = PyMem_RawMalloc(k->cells * sizeof(double));
    k->field.sx = PyMem_RawMalloc(k->cells * sizeof(double));
    k->field.sy = PyMem_RawMalloc(k->cells * sizeof(double));
    k->field.state = PyMem_RawMalloc(k->cells);
    if (!k->work || !k->h || !k->field.pn || !k->field.px || !k->field.py || !k->field.sx
        || !k->field.sy || !k->field.state) {
        wheel_free(k);
        PyErr_NoMemory();
        return -1;
    }
    return 0;
}

/* A field of the final grid as a new (my, mx) array. */
static PyObject *field_array(const void *v, int mx, int my, int type)
{
    npy_intp dims[2];
    PyObject *a;
    dims[0] = my;
    dims[1] = mx;
    if (!(a = PyArray_SimpleNew(2, dims, type)))
        return NULL;
    memcpy(PyArray_DATA((PyArrayObject *)a), v,
           (size_t)mx * (size_t)my * (type == NPY_INT8 ? 1 : sizeof(double)));
    return a;
}

/* The result's numbers as a dict. */
static PyObject *wheel_result_dict(const rr_wheel_exact_result *r)
{
    return Py_BuildValue("{s:d,s:d,s:d,s:d,s:d,s:(ddd),s:d,s:d,s:d,s:d,s:d,s:i,s:i,s:i,s:i,"
                         "s:d,s:n}",
                         "cx", r->cx, "cy", r->cy, "cphi", r->cphi, "V", r->V, "N", r->N,
                         "force", r->force[0], r->force[1], r->force[2], "z", r->z,
                         "roll", r->roll, "lowered", r->lowered, "approach", r->approach,
                         "cover", r->cover, "passes", r->passes, "builds", r->builds,
                         "why", r->why,
                         "fail_pass", r->fail_pass, "fail_N", r->fail_N,
                         "need", (Py_ssize_t)r->need);
}

/* wheel_exact(12 profile arrays, 8 params, side, y_ws, (z0, roll0), (s_roller,
 * s_wheel, delta, A, B), (N, Fz, E, nu, mu), (creep_given, cx, cy, cphi),
 * ((c), (v), (w)), roller_spin, vmin, (reference, ref_s_roller, ref_delta,
 * approach, cover, n, dx, dy, combine), (z, roll, loaded, passes), (tol,
 * maxit, spin_shift)) -> (status, (fx, fy, mz, fn, delta, area, pmax,
 * ncontact, nslip, normal_products, tang_products, newton_steps,
 * normal_residual, tang_residual), pn, px, py, sx, sy, state, h, {patch},
 * {result}); the arrays None on error.  Buffers grow until the grids fit. */
PyObject *py_wheel_exact(PyObject *self, PyObject *args)
{
    PyObject *pobj[NPROF], *nobj, *arr[7] = {NULL, NULL, NULL, NULL, NULL, NULL, NULL};
    PyObject *pd = NULL, *rd = NULL, *res = NULL;
    PyArrayObject *prof[NPROF];
    double par[8];
    rr_wheel_roller pair[2];
    wheel_call k;
    rr_wheel_exact_problem *pb = &k.pb;
    rr_contact_point *q = &pb->point;
    rr_motion *m = &pb->wheelset;
    int side, ref, side_len, tries, j;
    double ref_s, ref_d, approach, cover, dx, dy, comb;
    (void)self;

    memset(&k, 0, sizeof k);
    rr_wheel_exact_default(pb);
    for (j = 0; j < NPROF; j++)
        prof[j] = NULL;
    if (!PyArg_ParseTuple(args, PAIR_FORMAT "id(dd)(ddddd)(ddddd)(iddd)((ddd)(ddd)(ddd))dd"
                          "(iddddOddd)(ddii)(did):wheel_exact",
                          PAIR_ARGS(pobj, par), &side, &pb->y_ws, &pb->pose0.z,
                          &pb->pose0.roll, &q->s_roller, &q->s_wheel, &q->delta, &q->A, &q->B,
                          &pb->N, &pb->Fz, &pb->E, &pb->nu, &pb->mu, &pb->creep_given, &pb->cx,
                          &pb->cy, &pb->cphi, &m->c[0], &m->c[1], &m->c[2], &m->v[0], &m->v[1],
                          &m->v[2], &m->w[0], &m->w[1], &m->w[2], &pb->roller_spin, &pb->vmin,
                          &ref, &ref_s, &ref_d, &approach, &cover, &nobj, &dx, &dy, &comb,
                          &pb->z, &pb->roll, &pb->loaded, &pb->passes, &pb->tol, &pb->maxit,
                          &pb->spin_shift))
        return NULL;
    if (parse_pairs(pobj, par, "rig_exact", prof, pair) < 0
        || gap_opts(ref, ref_s, ref_d, approach, cover, nobj, dx, dy, comb, "rig_exact",
                    &pb->gap) < 0)
        goto done;
    pb->pair = &pair[side == 0 ? 0 : 1];
    /* a first guess of the largest grid (n and its growth), then as large
     * as a grid asked for */
    side_len = pb->gap.n + 16 < RR_EXACT_MAX_GRID ? pb->gap.n + 16 : RR_EXACT_MAX_GRID;
    for (tries = 0; tries < 8; tries++) {
        int need;
        if (wheel_alloc(&k, side_len) < 0)
            goto done;
        interrupt_hook_init(&k.stop);
        pb->interrupt = &k.stop.hook;
        if (run_batch(wheel_kernel, &k, 1, 1.0) < 0)
            goto done;
        if (k.st != RR_ERR_WORKSPACE || side_len == RR_EXACT_MAX_GRID
            || !(k.res.patch.grid.mx > 0))
            break;
        need = k.res.patch.grid.mx > k.res.patch.grid.my ? k.res.patch.grid.mx
                                                          : k.res.patch.grid.my;
        need = need + need / 4 + 8;
        side_len = need > side_len ? need : 2 * side_len;
        side_len = side_len < RR_EXACT_MAX_GRID ? side_len : RR_EXACT_MAX_GRID;
    }
    if (k.st >= 0) {
        const int mx = k.res.patch.grid.mx, my = k.res.patch.grid.my;
        const void *src[7] = {k.field.pn, k.field.px, k.field.py, k.field.sx, k.field.sy,
                              k.field.state, k.h};
        for (j = 0; j < 7; j++)
            if (!(arr[j] = field_array(src[j], mx, my, j == 5 ? NPY_INT8 : NPY_DOUBLE)))
                goto done;
    } else {
        for (j = 0; j < 7; j++) {
            arr[j] = Py_None;
            Py_INCREF(Py_None);
        }
    }
    if (!(pd = gap_patch_dict(&k.res.patch)) || !(rd = wheel_result_dict(&k.res)))
        goto done;
    {
        const rr_exact_result *r = &k.res.sol;
        res = Py_BuildValue("(i(dddddddiiiiidd)OOOOOOOOO)", k.st, r->fx, r->fy, r->mz, r->fn,
                            r->delta, r->area, r->pmax, r->ncontact, r->nslip,
                            r->normal_products, r->tang_products, r->newton_steps,
                            r->normal_residual, r->tang_residual, arr[0], arr[1], arr[2],
                            arr[3], arr[4], arr[5], arr[6], pd, rd);
    }
done:
    wheel_free(&k);
    release(arr, 7);
    Py_XDECREF(pd);
    Py_XDECREF(rd);
    release((PyObject **)prof, NPROF);
    return res;
}
