/*
 * rig_contact.c - the rig's contact model over arrays of states (core.h):
 * the pose, both wheels' contact and their statuses, per state.
 */
#include "core.h"

#define NSTATE 10
static const char *const state_names[NSTATE] = {"x", "y", "yaw", "vx", "vy", "yaw_rate",
                                                "spin", "roller_spin", "N_left", "N_right"};
#define NPOSE 11   /* c[3] roll beta v[3] w[3] */
#define NWHEEL RR_WHEEL_NVALUES   /* the fields of rr_wheel_field (RIG_WHEEL_FIELDS) */

static void store_wheel(double *d, npy_intp n, npy_intp i, const rr_wheel_contact *w)
{
    rr_wheel_store(w, d + i, (long)n);
}

/* State i of the inputs in[0..8) (x, y, yaw, vx, vy, yaw_rate, spin, roller_spin). */
static void read_state(const input *in, npy_intp i, rr_rig_state *s)
{
    s->x = IN(in[0], i);
    s->y = IN(in[1], i);
    s->yaw = IN(in[2], i);
    s->vx = IN(in[3], i);
    s->vy = IN(in[4], i);
    s->yaw_rate = IN(in[5], i);
    s->spin = IN(in[6], i);
    s->roller_spin = IN(in[7], i);
}

/* The pose's NPOSE numbers into column i of d (NPOSE rows of n). */
static void store_pose(double *d, npy_intp n, npy_intp i, const rr_rig_pose *p)
{
    const double pv[NPOSE] = {p->c[0], p->c[1], p->c[2], p->roll, p->beta, p->v[0], p->v[1],
                              p->v[2], p->w[0], p->w[1], p->w[2]};
    int k;
    for (k = 0; k < NPOSE; k++)
        d[k * n + i] = pv[k];
}

typedef struct {
    input in[NSTATE];
    const rr_rig_contact_checked *m;     /* checked once for the batch */
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
        read_state(b->in, i, &s);
        N[0] = IN(b->in[8], i);
        N[1] = IN(b->in[9], i);
        memset(w, 0, sizeof w);                /* each state on its own: no seed */
        if (b->kin_only) {
            b->status[i] = (npy_int8)rr_rig_kinematics_checked(b->m, &s, &pose, w);
            for (k = 0; k < 2; k++) {
                w[k].N = w[k].hertz.a = w[k].hertz.b = w[k].hertz.p0 = NAN;
                w[k].f.fx = w[k].f.fy = w[k].f.mz = NAN;
                w[k].force[0] = w[k].force[1] = w[k].force[2] = NAN;
                w[k].moment[0] = w[k].moment[1] = w[k].moment[2] = NAN;
            }
        } else {
            b->status[i] = (npy_int8)rr_rig_contact_eval_checked(b->m, &s, N, &pose, w);
        }
        b->left_status[i] = (npy_int8)w[0].status;
        b->right_status[i] = (npy_int8)w[1].status;
        store_pose(b->pose, b->n, i, &pose);
        store_wheel(b->left, b->n, i, &w[0]);
        store_wheel(b->right, b->n, i, &w[1]);
    }
    return 0;
}

/* rig_contact(data, y0, dy, (R0, estar, G, nu, mu0, A, B, vmin), 10 state arrays, *,
 *             kinematics_only, <creep options>)
 * -> (status, pose[NPOSE, n], left[NWHEEL, n], right[NWHEEL, n], left_status, right_status) */
PyObject *py_rig_contact(PyObject *self, PyObject *args, PyObject *kwargs)
{
    PyObject *dobj, *objs[NSTATE], *out[6] = {NULL, NULL, NULL, NULL, NULL, NULL}, *res, *v;
    rig_contact_batch b;
    rr_contact_table t;
    rr_rig_contact_model m;
    rr_rig_contact_checked checked;
    rr_creep_checked creep;
    double y0, dy, *work = NULL;
    npy_intp n, dims[2];
    int k, kin_only = 0;
    (void)self;

    memset(&m, 0, sizeof m);               /* Hertz: the patch's rows zero */
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
    if (parse_opts(kwargs, "rig_contact", "kinematics_only", &creep) < 0)
        return NULL;
    m.creep = creep.o;
    {
        /* the creep method's workspace, the call's own (none for the time-loop
         * methods of today) */
        const size_t len = rr_rig_contact_workspace_len(&m);
        int st;
        if (len > 0 && !(work = PyMem_Calloc(len, sizeof(double))))
            return PyErr_NoMemory();
        st = rr_rig_contact_bind(&checked, &m, work, len);
        if (st < 0) {
            PyErr_Format(PyExc_ValueError, "rig_contact: invalid model: %s",
                         rr_status_message(st));
            PyMem_Free(work);
            return NULL;
        }
    }
    if (parse_inputs("rig_contact", objs, state_names, NSTATE, &n, b.in) < 0) {
        PyMem_Free(work);
        return NULL;
    }
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
    b.m = &checked;
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
                  kin_only ? 8.0 : 8.0 + 2.0 * creep.cost) < 0)
        goto fail;
    if ((res = outputs_tuple(out, 6)) != NULL) {
        PyMem_Free(work);
        return res;
    }
fail:
    PyMem_Free(work);
    release(out, 6);
    return NULL;
}

/* ------------------------------------------------ the rows' kinematics */

#define NROW 9     /* the state's eight numbers and y_rates */
static const char *const row_names[NROW] = {"x", "y", "yaw", "vx", "vy", "yaw_rate", "spin",
                                            "roller_spin", "y_rates"};

typedef struct {
    input in[NROW];
    const rr_rig_contact_checked *m;
    npy_intp n;
    npy_int8 *status;
    double *pose;
} row_batch;

static int row_kernel(void *ctx, npy_intp start, npy_intp stop)
{
    row_batch *b = ctx;
    npy_intp i;
    for (i = start; i < stop; i++) {
        rr_rig_state s;
        rr_rig_pose pose;
        rr_wheel_contact w[2];
        read_state(b->in, i, &s);
        memset(w, 0, sizeof w);
        b->status[i] = (npy_int8)rr_rig_kinematics_rates_at(b->m, &s, IN(b->in[8], i), &pose, w);
        store_pose(b->pose, b->n, i, &pose);
    }
    return 0;
}

/* rig_row_kinematics(data, y0, dy, (R0, vmin), x, y, yaw, vx, vy, yaw_rate,
 * spin, roller_spin, y_rates) -> (status, pose[NPOSE, n]): the wheelset's
 * pose at y with the rates of y_rates (rr_rig_kinematics_rates_at; the
 * rows of the non-Hertzian contact's table, y_rates the state's own). */
PyObject *py_rig_row_kinematics(PyObject *self, PyObject *args)
{
    PyObject *dobj, *objs[NROW], *out[2] = {NULL, NULL}, *res;
    row_batch b;
    rr_contact_table t;
    rr_rig_contact_model m;
    rr_rig_contact_checked checked;
    double y0, dy;
    npy_intp n, dims[2];
    int st;
    (void)self;

    memset(&m, 0, sizeof m);
    if (!PyArg_ParseTuple(args, "Odd(dd)OOOOOOOOO:rig_row_kinematics", &dobj, &y0, &dy, &m.R0,
                          &m.vmin, &objs[0], &objs[1], &objs[2], &objs[3], &objs[4], &objs[5],
                          &objs[6], &objs[7], &objs[8]))
        return NULL;
    if (parse_table(dobj, y0, dy, "rig_row_kinematics", &t) < 0)
        return NULL;
    m.table = &t;
    /* the kinematics use no material, friction or creep method: valid ones */
    m.estar = 1.0;
    m.G = 1.0;
    m.nu = 0.25;
    m.friction.mu0 = 1.0;
    m.friction.A = 1.0;
    rr_creep_opts_default(&m.creep, RR_METHOD_FASTSIM);
    st = rr_rig_contact_bind(&checked, &m, NULL, 0);
    if (st < 0) {
        PyErr_Format(PyExc_ValueError, "rig_row_kinematics: invalid model: %s",
                     rr_status_message(st));
        return NULL;
    }
    if (parse_inputs("rig_row_kinematics", objs, row_names, NROW, &n, b.in) < 0)
        return NULL;
    dims[0] = NPOSE;
    dims[1] = n;
    out[0] = PyArray_SimpleNew(1, &n, NPY_INT8);
    out[1] = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (!out[0] || !out[1])
        goto fail;
    b.m = &checked;
    b.n = n;
    b.status = OUT8(out[0]);
    b.pose = OUT(out[1]);
    if (run_batch(row_kernel, &b, n, 8.0) < 0)
        goto fail;
    if ((res = outputs_tuple(out, 2)) != NULL)
        return res;
fail:
    release(out, 2);
    return NULL;
}
