/*
 * module.c - the module rollerrig._core: its functions (from the binding's
 * other files, core.h), its types, and the C core's declarations as module
 * constants: the creep-force methods' registry (METHODS), the rig's
 * parameters, sections, record and per-wheel block, and the core's limits.
 */
#define CORE_IMPORT_ARRAY       /* the one file that imports NumPy's C API */
#include "core.h"

static PyObject *py_status_message(PyObject *self, PyObject *arg)
{
    long code = PyLong_AsLong(arg);
    (void)self;
    if (code == -1 && PyErr_Occurred())
        return NULL;
    if (code < INT_MIN || code > INT_MAX)
        code = INT_MIN;
    return PyUnicode_FromString(rr_status_message((int)code));
}

/* The undeformed distance's references and the reasons of a failed build
 * (rr_gap.h), as GAP_<NAME> constants, and those of rr_wheel_exact
 * (WHEEL_EXACT_<NAME>). */
static int add_gap(PyObject *m)
{
    static const struct { const char *name; int value; } c[] = {
        {"GAP_WEIGHTED", RR_GAP_WEIGHTED}, {"GAP_POINT", RR_GAP_POINT},
        {"GAP_GIVEN", RR_GAP_GIVEN}, {"GAP_MAX_N", RR_GAP_MAX_N},
        {"GAP_MAX_RUNS", RR_GAP_MAX_RUNS},
        {"GAP_OFF_PROFILE", RR_GAP_OFF_PROFILE}, {"GAP_FOLD", RR_GAP_FOLD},
        {"GAP_APART", RR_GAP_APART}, {"GAP_REGION_ENDS", RR_GAP_REGION_ENDS},
        {"GAP_REGION_LONG", RR_GAP_REGION_LONG}, {"GAP_REGION_BEYOND", RR_GAP_REGION_BEYOND},
        {"GAP_TOO_MANY", RR_GAP_TOO_MANY}, {"GAP_PATCH_REACHES", RR_GAP_PATCH_REACHES},
        {"GAP_PATCH_NONFINITE", RR_GAP_PATCH_NONFINITE}, {"GAP_RUNS", RR_GAP_RUNS},
        {"GAP_WEIGHTS", RR_GAP_WEIGHTS}, {"GAP_SCAN", RR_GAP_SCAN},
        {"GAP_H_BUFFER", RR_GAP_H_BUFFER}, {"GAP_FAR", RR_GAP_FAR},
        {"WHEEL_EXACT_GAP", RR_WHEEL_EXACT_GAP}, {"WHEEL_EXACT_HERTZ", RR_WHEEL_EXACT_HERTZ},
        {"WHEEL_EXACT_SOLVE", RR_WHEEL_EXACT_SOLVE}, {"WHEEL_EXACT_EDGE", RR_WHEEL_EXACT_EDGE},
        {"WHEEL_EXACT_SETTLE", RR_WHEEL_EXACT_SETTLE},
        {"WHEEL_EXACT_CREEP", RR_WHEEL_EXACT_CREEP}};
    int k;
    for (k = 0; k < RR_COUNTOF(c); k++)
        if (PyModule_AddIntConstant(m, c[k].name, c[k].value) < 0)
            return -1;
    return 0;
}

static PyMethodDef core_methods[] = {
    {"hertz", py_hertz, METH_VARARGS,
     "hertz(A, B, N, E1, nu1, E2, nu2) -> (a, b, p0, delta, status)"},
    {"hertz1", (PyCFunction)(void (*)(void))py_hertz1, METH_FASTCALL,
     "hertz1(A, B, N, E1, nu1, E2, nu2) -> (a, b, p0, delta, status)"},
    {"exact_table_builtin", py_exact_table_builtin, METH_NOARGS,
     "exact_table_builtin() -> (shape, lo, hi, nu, r0, nx, float32 bytes): the built-in table"},
    {"kalker", py_kalker, METH_VARARGS,
     "kalker(a_over_b, nu) -> (c11, c22, c23, c33, status)"},
    {"creep_forces", (PyCFunction)(void (*)(void))py_creep_forces, METH_VARARGS | METH_KEYWORDS,
     "creep_forces(cx, cy, cphi, a, b, N, mu, G, nu, speed, A, B, *, method, <its options>)"
     " -> (fx, fy, mz, status); METHODS lists the methods and their options"},
    {"check_creep_options", py_check_creep_options, METH_VARARGS,
     "check_creep_options(func, {method: ..., <its options>}) -> CreepOptions, or ValueError"},
    {"creep_forces1", (PyCFunction)(void (*)(void))py_creep_forces1, METH_FASTCALL,
     "creep_forces1(opts, cx, cy, cphi, a, b, N, mu, G, nu, speed, A, B) -> (fx, fy, mz, status)"},
    {"creep_blame", (PyCFunction)(void (*)(void))py_creep_blame, METH_FASTCALL,
     "creep_blame(opts, cx, cy, cphi, a, b, N, mu, G, nu, speed, A, B, status) -> the argument "
     "the method's status blames, or None"},
    {"exact_hertz_problem", (PyCFunction)(void (*)(void))py_exact_hertz_problem,
     METH_VARARGS | METH_KEYWORDS,
     "exact_hertz_problem(<as creep_forces, one case>, method='exact', <options>) -> (status, "
     "mx, my, dx, dy, x0, y0, A, B, N, G, nu, mu, cx, cy, cphi, spin_shift, tol, maxit)"},
    {"exact_field", (PyCFunction)(void (*)(void))py_exact_field, METH_VARARGS | METH_KEYWORDS,
     "exact_field([opts,] <as creep_forces, one case>, method='exact', <options>) -> (status, "
     "blamed, grid, results, pn, px, py, sx, sy, state)"},
    {"exact_solve", py_exact_solve, METH_VARARGS,
     "exact_solve(opts, h, dx, dy, x0, y0, N, mu, G, nu, cx, cy, cphi) -> (status, blamed, "
     "grid, results, pn, px, py, sx, sy, state)"},
    {"fastsim_field", (PyCFunction)(void (*)(void))py_fastsim_field,
     METH_VARARGS | METH_KEYWORDS,
     "fastsim_field(<as creep_forces, one case>) -> (fx, fy, mz, status, x, y, pn, px, py, slip, area)"},
    {"wheelset_contact", py_wheelset_contact, METH_VARARGS,
     "wheelset_contact(12 profile arrays (s, z, z'' each), 8 params, y_ws, nsamples, tol, sep)"
     " -> (status, z, roll, left, right)"},
    {"gap_build", py_gap_build, METH_VARARGS,
     "gap_build(12 profile arrays, 8 params, side, y_ws, z, roll, s_roller, s_wheel, delta, "
     "reference, ref_s_roller, ref_delta, approach, cover, n, dx, dy, combine) -> (status, h, "
     "{patch}): rr_gap_build"},
    {"wheel_exact", py_wheel_exact, METH_VARARGS,
     "wheel_exact(12 profile arrays, 8 params, side, y_ws, (z0, roll0), (s_roller, s_wheel, "
     "delta, A, B), (N, Fz, E, nu, mu), (creep_given, cx, cy, cphi), ((c), (v), (w)), "
     "roller_spin, vmin, (reference, ref_s_roller, ref_delta, approach, cover, n, dx, dy, "
     "combine), (z, roll, loaded, passes), (tol, maxit, spin_shift)) -> (status, results, pn, "
     "px, py, sx, sy, state, h, {patch}, {result}): rr_wheel_exact"},
    {"contact_table", py_contact_table, METH_VARARGS,
     "contact_table(12 profile arrays, 8 params, y0, dy, n, nsamples, tol, sep)"
     " -> (data, status, bad_y)"},
    {"table_lookup", py_table_lookup, METH_VARARGS,
     "table_lookup(data, y0, dy, y) -> (status, z, roll, dz_dy, droll_dy, left, right)"},
    {"rig_contact", (PyCFunction)(void (*)(void))py_rig_contact, METH_VARARGS | METH_KEYWORDS,
     "rig_contact(data, y0, dy, (R0, estar, G, nu, mu0, A, B, vmin), x, y, yaw, vx, vy,"
     " yaw_rate, spin, roller_spin, N_left, N_right, *, kinematics_only, <creep options>)"
     " -> (status, pose, left, right, left_status, right_status)"},
    {"rig_row_kinematics", py_rig_row_kinematics, METH_VARARGS,
     "rig_row_kinematics(data, y0, dy, (R0, vmin), x, y, yaw, vx, vy, yaw_rate, spin,"
     " roller_spin, y_rates) -> (status, pose): the pose at y, the rates of y_rates"},
    {"spline_fit", py_spline_fit, METH_VARARGS,
     "spline_fit(y, z, end) -> (status, slope, c2, c3, d2)"},
    {"analytic_profile", py_analytic_profile, METH_VARARGS,
     "analytic_profile(kind (0 conical, 1 crowned), alpha or crown radius, y_min, y_max, n)"
     " -> (status, y, z)"},
    {"profile_table", py_profile_table, METH_VARARGS,
     "profile_table(wheel_y, wheel_z, wheel_end, roller_y, roller_z, roller_end,"
     " (r0, R0, wheel_y, roller_y), y0, dy, n, nsamples, tol, sep) -> (data, status, bad_y)"},
    {"rig_schedule", py_rig_schedule, METH_VARARGS,
     "rig_schedule(roller_speed, roller_radius, targets, target_start, T, first, stop)"
     " -> (roller_ref, xi_ref)"},
    {"rig_table", py_rig_table, METH_VARARGS,
     "rig_table(r0, R0, half_width, alpha, crown, half_spacing, half_range, rows)"
     " -> (data, y0, dy, status, bad_y)"},
    {"rig_profile_table", py_rig_profile_table, METH_VARARGS, "rig_profile_table(geometry, (wheel_scale, roller_scale, gauge), profiles) -> (data, y0, dy, status, bad_y, which, point)"},
    {"rig_speed_loops", py_rig_speed_loops, METH_O,
     "rig_speed_loops({\"section.key\": value}) -> ((stable, rho, lo, hi) of the roller's "
     "and the wheelset's sampled speed loops)"},
    {"rig_config_report", py_rig_config_report, METH_O,
     "rig_config_report({\"section.key\": value}) -> [(key, status, rule, other, entry, "
     "value, lo, hi), ...]: every problem of the rig's parameters (rr_rig_config_report)"},
    {"nonhertz_row", py_nonhertz_row, METH_VARARGS,
     "nonhertz_row(pair, side, y_ws, (z0, roll0), point, (Fz_max, Fz_regions, E, nu, mu), motion, "
     "roller_spin, vmin, (n, n_corr, richardson, combine), (tol, maxit)) -> (status, row, "
     "{info}): rr_nonhertz_row"},
    {"nonhertz_check", py_nonhertz_check, METH_VARARGS,
     "nonhertz_check(rows, head) -> (status, bad_row): rr_nonhertz_table_check"},
    {"nonhertz_wheel", py_nonhertz_wheel, METH_VARARGS,
     "nonhertz_wheel(rows, head, (y, Fz, mu, roller_spin, vmin), motion0, motion1) -> "
     "(status, {result}, patches): rr_nonhertz_wheel"},
    {"nonhertz_locate", py_nonhertz_locate, METH_VARARGS,
     "nonhertz_locate(rows, head, y) -> (status, row, w): rr_nonhertz_locate"},
    {"status_message", py_status_message, METH_O, "status_message(code) -> str"},
    {NULL, NULL, 0, NULL}
};

static struct PyModuleDef core_module = {
    PyModuleDef_HEAD_INIT, "rollerrig._core",
    "Binding of the rollerrig C core; use the functions of the rollerrig package.", -1,
    core_methods, NULL, NULL, NULL, NULL
};

/* a float constant of the module (PyModule_AddObject steals only on success) */
static int add_double(PyObject *m, const char *name, double v)
{
    PyObject *o = PyFloat_FromDouble(v);
    if (!o || PyModule_AddObject(m, name, o) < 0) {
        Py_XDECREF(o);
        return -1;
    }
    return 0;
}

/* The declarations of rr_rig_params.h as tuples of tuples (module constants):
 * RIG_PARAMETERS rows (name, unit, type, default, lo, hi, lo_open, hi_open,
 * choices, text, creep, origin, option) with type "real", "int", "flag", "choice" or
 * "list" and default a float, int, bool, str or tuple of floats (a creep row:
 * None, its text is the TOML default); RIG_SECTIONS (name, note);
 * RIG_RETIRED (name, reason); RIG_RECORD and RIG_WHEEL_FIELDS (name, width,
 * unit, meaning). */
static PyObject *param_default(const rr_rig_param *r)
{
    Py_ssize_t k;
    PyObject *t;
    if (r->creep)
        Py_RETURN_NONE;
    switch (r->type) {
    case RR_RIG_INT:
        return PyLong_FromDouble(r->value);
    case RR_RIG_FLAG:
        return PyBool_FromLong(r->value != 0.0);
    case RR_RIG_CHOICE:
        return PyUnicode_FromString(r->choices[(int)r->value]);
    case RR_RIG_LIST:
        if (!(t = PyTuple_New(r->nlist)))
            return NULL;
        for (k = 0; k < r->nlist; k++) {
            PyObject *x = PyFloat_FromDouble(r->list[k]);
            if (!x) {
                Py_DECREF(t);
                return NULL;
            }
            PyTuple_SET_ITEM(t, k, x);
        }
        return t;
    default:
        return PyFloat_FromDouble(r->value);
    }
}

/* A NULL-terminated list of names (NULL: none) as a tuple of str. */
static PyObject *names_tuple(const char *const *names)
{
    Py_ssize_t n = 0, k;
    PyObject *t;
    while (names && names[n])
        n++;
    if (!(t = PyTuple_New(n)))
        return NULL;
    for (k = 0; k < n; k++) {
        PyObject *x = PyUnicode_FromString(names[k]);
        if (!x) {
            Py_DECREF(t);
            return NULL;
        }
        PyTuple_SET_ITEM(t, k, x);
    }
    return t;
}

static PyObject *param_tuple(int i)
{
    static const char *const types[] = {"real", "int", "flag", "choice", "list"};
    const rr_rig_param *r = rr_rig_param_at(i);
    PyObject *dflt = param_default(r), *choices = names_tuple(r->choices), *res = NULL;
    if (dflt && choices)
        res = Py_BuildValue("(sssOddOOOzOsz)", r->name, r->unit, types[r->type], dflt, r->lo,
                            r->hi, r->lo_open ? Py_True : Py_False,
                            r->hi_open ? Py_True : Py_False, choices, r->text,
                            r->creep ? Py_True : Py_False, r->origin, r->option);
    Py_XDECREF(dflt);
    Py_XDECREF(choices);
    return res;
}

static PyObject *section_tuple(int i)
{
    const rr_rig_section *s = rr_rig_section_at(i);
    return Py_BuildValue("(ss)", s->name, s->note);
}

static PyObject *retired_tuple(int i)
{
    const rr_rig_retired *s = rr_rig_retired_at(i);
    return Py_BuildValue("(ss)", s->name, s->reason);
}

static PyObject *field_tuple(const rr_rig_field *f)
{
    return Py_BuildValue("(siss)", f->name, f->width, f->unit, f->meaning);
}

static PyObject *record_tuple(int i)
{
    return field_tuple(rr_rig_record_field(i));
}

static PyObject *wheel_tuple(int i)
{
    return field_tuple(rr_wheel_field(i));
}

/* module constant `name`: the tuple of row(i), 0 <= i < n */
static int add_rows(PyObject *m, const char *name, int n, PyObject *(*row)(int))
{
    PyObject *t = PyTuple_New(n);
    int i;
    if (!t)
        return -1;
    for (i = 0; i < n; i++) {
        PyObject *x = row(i);
        if (!x) {
            Py_DECREF(t);
            return -1;
        }
        PyTuple_SET_ITEM(t, i, x);
    }
    if (PyModule_AddObject(m, name, t) < 0) {
        Py_DECREF(t);
        return -1;
    }
    return 0;
}

/* The registry as _core.METHODS: a tuple of (name, doc, options, has_field,
 * saturates, in_loop, coulomb_only, in_rig, takes_grid), in_loop True where
 * a case has bounded work (not iterative: a time-loop method, the rig's
 * contact model takes it), in_rig where the rig steps with it
 * (rr_rig_method_check: in_loop and saturates), coulomb_only True where it
 * refuses a falling friction law, takes_grid where it takes a contact
 * problem on a grid (the exact theory), options a tuple of (name, type, unit, default, lo, hi,
 * lo_open, hi_open, choices, doc): type "int", "real" or "choice"; an
 * integer's default and range as ints, a choice's default as its name (its
 * range None), choices a tuple of names (empty but for a choice). */
static PyObject *option_tuple(const rr_creep_option *op)
{
    static const char *const types[] = {"int", "real", "choice"};
    PyObject *choices, *def, *lo, *hi;
    if (!(choices = names_tuple(op->type == RR_OPT_CHOICE ? op->choices : NULL)))
        return NULL;
    if (op->type == RR_OPT_CHOICE) {
        def = PyUnicode_FromString(op->choices[(int)op->def]);
        Py_INCREF(Py_None);
        Py_INCREF(Py_None);
        lo = hi = Py_None;
    } else if (op->type == RR_OPT_INT) {
        def = PyLong_FromDouble(op->def);
        lo = PyLong_FromDouble(op->lo);
        hi = PyLong_FromDouble(op->hi);
    } else {
        def = PyFloat_FromDouble(op->def);
        lo = PyFloat_FromDouble(op->lo);
        hi = PyFloat_FromDouble(op->hi);
    }
    return Py_BuildValue("(sssNNNNNNs)", op->name, types[op->type], op->unit, def, lo, hi,
                         PyBool_FromLong(op->lo_open), PyBool_FromLong(op->hi_open), choices,
                         op->doc);
}

static int add_methods(PyObject *m)
{
    PyObject *all = PyTuple_New(rr_method_count());
    int i, k;
    if (!all)
        return -1;
    for (i = 0; i < rr_method_count(); i++) {
        const rr_method_desc *d = rr_method_get(i);
        PyObject *opts = PyTuple_New(d->nopts), *row;
        if (!opts)
            goto fail;
        for (k = 0; k < d->nopts; k++) {
            PyObject *t = option_tuple(&d->opts[k]);
            if (!t) {
                Py_DECREF(opts);
                goto fail;
            }
            PyTuple_SET_ITEM(opts, k, t);
        }
        rr_creep_opts o;
        rr_creep_opts_default(&o, i);
        row = Py_BuildValue("(ssNNNNNNN)", d->name, d->doc, opts,
                            PyBool_FromLong(d->field != NULL), PyBool_FromLong(d->saturates),
                            PyBool_FromLong(!rr_creep_iterative(&o)),
                            PyBool_FromLong(d->coulomb_only),
                            PyBool_FromLong(rr_rig_method_check(&o) == RR_OK),
                            PyBool_FromLong(d->takes_grid));
        if (!row)
            goto fail;
        PyTuple_SET_ITEM(all, i, row);
    }
    if (PyModule_AddObject(m, "METHODS", all) == 0)
        return 0;
fail:
    Py_DECREF(all);
    return -1;
}

PyMODINIT_FUNC PyInit__core(void)
{
    PyObject *m;
    import_array();
    if (PyType_Ready(&RigType) < 0 || PyType_Ready(&CreepOptionsType) < 0)
        return NULL;
    m = PyModule_Create(&core_module);
    if (!m)
        return NULL;
    Py_INCREF(&RigType);
    if (PyModule_AddObject(m, "Rig", (PyObject *)&RigType) < 0) {
        Py_DECREF(&RigType);
        Py_DECREF(m);
        return NULL;
    }
    Py_INCREF(&CreepOptionsType);
    if (PyModule_AddObject(m, "CreepOptions", (PyObject *)&CreepOptionsType) < 0) {
        Py_DECREF(&CreepOptionsType);
        Py_DECREF(m);
        return NULL;
    }
    if (add_methods(m) < 0
        || PyModule_AddIntConstant(m, "TABLE_ROW", (int)rr_contact_table_len(1)) < 0
        || PyModule_AddIntConstant(m, "SEARCH_MAX_SAMPLES", RR_SEARCH_MAX_SAMPLES) < 0
        || PyModule_AddIntConstant(m, "SPLINE_NOT_A_KNOT", RR_SPLINE_NOT_A_KNOT) < 0
        || PyModule_AddIntConstant(m, "SPLINE_NATURAL", RR_SPLINE_NATURAL) < 0
        || PyModule_AddIntConstant(m, "RIG_PROFILE_POINTS", RR_RIG_PROFILE_POINTS) < 0
        || PyModule_AddIntConstant(m, "RIG_NSTATE", RR_RIG_NSTATE) < 0
        || PyModule_AddIntConstant(m, "REC_COUNT", RR_REC_COUNT) < 0
        || PyModule_AddIntConstant(m, "RIG_MAX_LIST", RR_RIG_MAX_LIST) < 0
        || PyModule_AddIntConstant(m, "CMD_BUILTIN", RR_CMD_BUILTIN) < 0
        || PyModule_AddIntConstant(m, "CMD_SPEED", RR_CMD_SPEED) < 0
        || PyModule_AddIntConstant(m, "CMD_TORQUE", RR_CMD_TORQUE) < 0
        || PyModule_AddIntConstant(m, "ERR_CONTROLLER", RR_ERR_CONTROLLER) < 0
        || PyModule_AddIntConstant(m, "EXACT_MAX_GRID", RR_EXACT_MAX_GRID) < 0
        || PyModule_AddIntConstant(m, "EXACT_MARGIN", RR_EXACT_MARGIN) < 0
        || add_gap(m) < 0
        || add_nonhertz(m) < 0
        || PyModule_AddIntConstant(m, "ERR_FRICTION_LIMIT", RR_ERR_FRICTION_LIMIT) < 0
        || PyModule_AddIntConstant(m, "ERR_UNTRUSTED", RR_ERR_UNTRUSTED) < 0
        || add_rows(m, "RIG_PARAMETERS", rr_rig_param_count(), param_tuple) < 0
        || add_rows(m, "RIG_SECTIONS", rr_rig_section_count(), section_tuple) < 0
        || add_rows(m, "RIG_RETIRED", rr_rig_retired_count(), retired_tuple) < 0
        || add_rows(m, "RIG_RECORD", RR_REC_COUNT, record_tuple) < 0
        || add_rows(m, "RIG_WHEEL_FIELDS", RR_WHEEL_NFIELDS, wheel_tuple) < 0
        || PyModule_AddIntConstant(m, "ODE_ROS2", RR_ODE_ROS2) < 0
        || PyModule_AddIntConstant(m, "ODE_TRBDF2", RR_ODE_TRBDF2) < 0
        || PyModule_AddIntConstant(m, "ODE_LINEULER", RR_ODE_LINEULER) < 0
        || PyModule_AddIntConstant(m, "STATUS_MIN", RR_STATUS_MIN) < 0
        || PyModule_AddIntConstant(m, "STATUS_MAX", RR_STATUS_MAX) < 0
        || add_double(m, "FRICTION_MAX", RR_FRICTION_MAX) < 0) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
