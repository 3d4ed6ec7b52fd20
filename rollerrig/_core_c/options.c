/*
 * options.c - a creep-force method and its options from Python keywords,
 * read from the registry's descriptors (core.h): every message names the
 * call, the method, the option, its range and the value.
 */
#include "core.h"

#include <string.h>

PyObject *quoted_names(const char *const *names, int n)
{
    PyObject *list = PyList_New(0), *sep, *res = NULL;
    int k;
    if (!list)
        return NULL;
    for (k = 0; k < n; k++) {
        PyObject *q = PyUnicode_FromFormat("'%s'", names[k]);
        if (!q || PyList_Append(list, q) < 0) {
            Py_XDECREF(q);
            Py_DECREF(list);
            return NULL;
        }
        Py_DECREF(q);
    }
    if ((sep = PyUnicode_FromString(", ")) != NULL) {
        res = PyUnicode_Join(sep, list);
        Py_DECREF(sep);
    }
    Py_DECREF(list);
    return res;
}

static PyObject *method_names(void)
{
    const char *names[RR_METHOD_COUNT];
    int k;
    for (k = 0; k < rr_method_count(); k++)
        names[k] = rr_method_get(k)->name;
    return quoted_names(names, rr_method_count());
}

static PyObject *option_names(const rr_method_desc *d)
{
    const char *names[RR_CREEP_MAX_OPTS];
    int k;
    for (k = 0; k < d->nopts; k++)
        names[k] = d->opts[k].name;
    return quoted_names(names, d->nopts);
}

static int choice_count(const rr_creep_option *op)
{
    int n = 0;
    while (op->choices[n])
        n++;
    return n;
}

/* A range end as Python writes the number ("1", "0.54", "inf"). */
static PyObject *number_str(double x)
{
    char *t = PyOS_double_to_string(x, 'r', 0, 0, NULL);
    PyObject *r;
    if (!t)
        return NULL;
    r = PyUnicode_FromString(t);
    PyMem_Free(t);
    return r;
}

/* ValueError: "func: name must be <what the option takes>, got value" */
static int option_error(const char *func, const rr_creep_option *op, PyObject *value)
{
    PyObject *lo = NULL, *hi = NULL, *names = NULL;
    if (op->type == RR_OPT_CHOICE) {
        if ((names = quoted_names(op->choices, choice_count(op))) != NULL)
            PyErr_Format(PyExc_ValueError, "%s: %s must be one of %U (or None: the default), "
                         "got %R", func, op->name, names, value);
    } else if ((lo = number_str(op->lo)) != NULL && (hi = number_str(op->hi)) != NULL) {
        PyErr_Format(PyExc_ValueError, "%s: %s must be %s in %s%U, %U%s, got %R", func, op->name,
                     op->type == RR_OPT_INT ? "an integer" : "a real number",
                     op->lo_open ? "(" : "[", lo, hi, op->hi_open ? ")" : "]", value);
    }
    Py_XDECREF(lo);
    Py_XDECREF(hi);
    Py_XDECREF(names);
    return -1;
}

/* One option's value from Python: None (the default), a choice's name, an
 * integer (never wrapped: 2**32 + 1 stays out of range) or a real; 0, or
 * -1 with a ValueError naming the option, its range and the value. */
static int option_value(PyObject *v, const char *func, const rr_creep_option *op, double *out)
{
    double x;
    if (v == Py_None) {
        *out = op->def;
        return 0;
    }
    if (op->type == RR_OPT_CHOICE) {
        int k;
        const char *name = PyUnicode_Check(v) ? PyUnicode_AsUTF8(v) : NULL;
        if (PyUnicode_Check(v) && !name)
            return -1;
        for (k = 0; name && op->choices[k]; k++)
            if (strcmp(name, op->choices[k]) == 0) {
                *out = k;
                return 0;
            }
        return option_error(func, op, v);
    }
    if (PyBool_Check(v) || PyUnicode_Check(v) || PyBytes_Check(v))
        return option_error(func, op, v);
    if (op->type == RR_OPT_INT) {
        PyObject *i;
        long n;
        int overflow = 0;
        if (!PyIndex_Check(v))
            return option_error(func, op, v);
        if (!(i = PyNumber_Index(v)))
            return -1;
        n = PyLong_AsLongAndOverflow(i, &overflow);
        Py_DECREF(i);
        if (n == -1 && PyErr_Occurred())
            return -1;
        if (overflow || n < -(1L << 30) || n > (1L << 30))
            return option_error(func, op, v);
        x = (double)n;
    } else {
        x = PyFloat_AsDouble(v);
        if (x == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();          /* not a number, or an int beyond the doubles */
            return option_error(func, op, v);
        }
    }
    if (rr_method_option_check(op, x) != RR_OK)
        return option_error(func, op, v);
    *out = x;
    return 0;
}

int parse_opts(PyObject *kwargs, const char *func, const char *own, rr_creep_checked *k)
{
    PyObject *v = kwargs ? PyDict_GetItemString(kwargs, "method") : NULL, *key, *names;
    const rr_method_desc *d;
    rr_creep_opts opts, *o = &opts;
    const char *mname = v && PyUnicode_Check(v) ? PyUnicode_AsUTF8(v) : NULL;
    Py_ssize_t pos = 0;
    int method, bad, st;

    if (v && PyUnicode_Check(v) && !mname)
        return -1;
    method = mname ? rr_method_find(mname) : RR_ERR_METHOD;
    if (method < 0) {
        if ((names = method_names()) != NULL) {
            if (v)
                PyErr_Format(PyExc_ValueError, "%s: method must be one of %U, got %R", func,
                             names, v);
            else
                PyErr_Format(PyExc_ValueError, "%s: method is required (one of %U)", func,
                             names);
            Py_DECREF(names);
        }
        return -1;
    }
    d = rr_method_get(method);
    rr_creep_opts_default(o, method);
    while (kwargs && PyDict_Next(kwargs, &pos, &key, &v)) {
        const char *name = PyUnicode_Check(key) ? PyUnicode_AsUTF8(key) : NULL;
        int i;
        if (!name)
            return PyErr_Occurred() ? -1 : (PyErr_SetString(PyExc_TypeError, "keywords must "
                                                            "be strings"), -1);
        if (strcmp(name, "method") == 0 || (own && strcmp(name, own) == 0))
            continue;
        if ((i = rr_method_option(d, name)) < 0) {
            if ((names = option_names(d)) != NULL) {
                if (d->nopts > 0)
                    PyErr_Format(PyExc_ValueError, "%s: method '%s' has no option %s (its "
                                 "options: %U), got %s=%R", func, d->name, name, names, name, v);
                else
                    PyErr_Format(PyExc_ValueError, "%s: method '%s' has no options, got %s=%R",
                                 func, d->name, name, v);
                Py_DECREF(names);
            }
            return -1;
        }
        if (option_value(v, func, &d->opts[i], &o->v[i]) < 0)
            return -1;
    }
    /* the one check of the call: rr_creep_check keeps the checked options */
    st = rr_creep_check(k, o, &bad);
    if (st < 0) {
        /* each option passed its own range: a constraint across options */
        PyObject *got = PyUnicode_FromString(""), *part;
        int j;
        for (j = 0; got && j < d->nopts; j++) {
            PyObject *num = number_str(o->v[j]);
            part = num ? PyUnicode_FromFormat("%s%s = %U", j ? ", " : "", d->opts[j].name, num)
                       : NULL;
            Py_XDECREF(num);
            if (!part) {
                Py_CLEAR(got);
                break;
            }
            PyUnicode_Append(&got, part);
            Py_DECREF(part);
        }
        if (got) {
            PyErr_Format(PyExc_ValueError, "%s: %s must satisfy %s (method '%s'), got %U: %s",
                         func, bad >= 0 ? d->opts[bad].name : "the options",
                         d->check_doc ? d->check_doc : "the method's constraints", d->name, got,
                         rr_status_message(st));
            Py_DECREF(got);
        }
        return -1;
    }
    return 0;
}

int opts_first(PyObject *args)
{
    return PyTuple_GET_SIZE(args) > 0
           && PyObject_TypeCheck(PyTuple_GET_ITEM(args, 0), &CreepOptionsType);
}

int call_opts(PyObject *args, PyObject *kwargs, const char *func, rr_creep_checked *k)
{
    if (opts_first(args)) {
        const CreepOptionsObject *opts = (const CreepOptionsObject *)PyTuple_GET_ITEM(args, 0);
        if (!opts->ready || (kwargs && PyDict_GET_SIZE(kwargs) > 0)) {
            PyErr_Format(PyExc_TypeError, "%s: %s", func, opts->ready
                         ? "options given twice (a CreepOptions and keywords)"
                         : "the CreepOptions is not initialised");
            return -1;
        }
        *k = opts->k;
        return 1;
    }
    return parse_opts(kwargs, func, NULL, k) < 0 ? -1 : 0;
}

/* check_creep_options(func, options) -> CreepOptions: the options (a dict
 * with method=) checked as every call checks them, messages naming func,
 * for the calls that take them (creep_forces, fastsim_field,
 * exact_hertz_problem, creep_forces1); or a ValueError. */
PyObject *py_check_creep_options(PyObject *self, PyObject *args)
{
    const char *func;
    PyObject *d;
    rr_creep_checked k;
    CreepOptionsObject *opts;
    (void)self;
    if (!PyArg_ParseTuple(args, "sO!:check_creep_options", &func, &PyDict_Type, &d))
        return NULL;
    if (parse_opts(d, func, NULL, &k) < 0)
        return NULL;
    opts = (CreepOptionsObject *)CreepOptionsType.tp_alloc(&CreepOptionsType, 0);
    if (opts) {
        opts->k = k;
        opts->ready = 1;
    }
    return (PyObject *)opts;
}

/* CreepOptions(**options): parsed once, for repeated calls (core.h) */
static int CreepOptions_init(CreepOptionsObject *self, PyObject *args, PyObject *kwargs)
{
    self->ready = 0;
    if (PyTuple_GET_SIZE(args) != 0) {
        PyErr_SetString(PyExc_TypeError, "CreepOptions: options are keywords only");
        return -1;
    }
    if (parse_opts(kwargs, "creep_forces", NULL, &self->k) < 0)
        return -1;
    self->ready = 1;
    return 0;
}

PyTypeObject CreepOptionsType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "rollerrig._core.CreepOptions",
    .tp_basicsize = sizeof(CreepOptionsObject),
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "CreepOptions(method=..., <options>): checked options for creep_forces1, "
              "creep_forces, fastsim_field and exact_hertz_problem",
    .tp_init = (initproc)CreepOptions_init,
    .tp_new = PyType_GenericNew,
};
