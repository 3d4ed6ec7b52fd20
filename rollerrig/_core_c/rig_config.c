/*
 * rig_config.c - every problem of the rig's parameters at once (core.h):
 * rig_config_report, the binding of rr_rig_config_report, which
 * rollerrig.rig reads instead of restating the C rules.
 */
#include "core.h"

#include <math.h>
#include <string.h>

/* rig_config_report(params) -> [(key, status, rule, other, entry, value, lo,
 * hi), ...]: every problem of the rig's primary values {"section.key":
 * value} (any subset, the rest at their defaults), as rr_rig_config_report
 * gives them (rr_rig_params.h: rule "range", "count", "increasing",
 * "nondecreasing", "before", "sample", "circumference", "loop" or "sum";
 * other None or a row's name; entry -1 or a list's entry, a loop's drive),
 * in its order: the rows in the declaration's order, then the rules between
 * them.  A value the configuration cannot hold is its row's "range" problem
 * (rr_rig_config_put; value NaN where it is no number): the types are
 * rollerrig.rig's rules' (a real: a numbers.Real but a bool; an int: a
 * numbers.Integral but a bool; a flag: a bool; a choice: one of its names;
 * a list: a list or tuple of reals).  An unknown name or a creep row raises
 * ValueError (as Rig does). */
static const char *const rig_rule_names[] = {
    [RR_RIG_RULE_RANGE] = "range", [RR_RIG_RULE_COUNT] = "count",
    [RR_RIG_RULE_INCREASING] = "increasing", [RR_RIG_RULE_NONDECREASING] = "nondecreasing",
    [RR_RIG_RULE_BEFORE] = "before", [RR_RIG_RULE_SAMPLE] = "sample",
    [RR_RIG_RULE_CIRCUMFERENCE] = "circumference", [RR_RIG_RULE_LOOP] = "loop",
    [RR_RIG_RULE_SUM] = "sum"};

/* A real of the parameter rules as a double: 1, 0 (not one: a bool, no
 * numbers.Real, an int beyond a double), -1 with an exception. */
static int report_real(PyObject *v, PyObject *real, double *x)
{
    int is = PyBool_Check(v) ? 0 : PyObject_IsInstance(v, real);
    if (is <= 0)
        return is;
    *x = PyFloat_AsDouble(v);
    if (*x == -1.0 && PyErr_Occurred()) {
        if (!PyErr_ExceptionMatches(PyExc_OverflowError))
            return -1;
        PyErr_Clear();
        return 0;
    }
    return 1;
}

/* The value of row r stored in c (rr_rig_config_put), or its problem in *p:
 * 0 stored, 1 a problem, -1 an exception. */
static int report_value(const rr_rig_param *r, PyObject *v, PyObject *real, PyObject *integral,
                        rr_rig_config *c, rr_rig_problem *p)
{
    double x = NAN;
    int ok, entry = -1;
    if (r->type == RR_RIG_LIST) {
        double vals[RR_RIG_MAX_LIST];
        Py_ssize_t k, n;
        ok = PyList_Check(v) || PyTuple_Check(v);
        n = ok ? PySequence_Fast_GET_SIZE(v) : 0;
        for (k = 0; ok && k < n && k < RR_RIG_MAX_LIST; k++)
            if ((ok = report_real(PySequence_Fast_GET_ITEM(v, k), real, &vals[k])) < 0)
                return -1;
            else if (!ok)
                entry = (int)k;
        if (ok)
            return rr_rig_config_put_list(c, r->name, n > RR_RIG_MAX_LIST ? RR_RIG_MAX_LIST + 1
                                                                           : (int)n,
                                          vals, p) == RR_OK ? 0 : 1;
    } else if (r->type == RR_RIG_CHOICE) {
        Py_ssize_t len = 0;
        const char *text = PyUnicode_Check(v) ? PyUnicode_AsUTF8AndSize(v, &len) : NULL;
        int k;
        if (!text && PyErr_Occurred()) {
            /* a str UTF-8 cannot hold (a lone surrogate) is no name */
            if (!PyErr_ExceptionMatches(PyExc_UnicodeEncodeError))
                return -1;
            PyErr_Clear();
        }
        /* a name with a NUL inside is none of the names, not its head */
        if (text && strlen(text) == (size_t)len && (k = rr_rig_param_choice(r, text)) >= 0)
            return rr_rig_config_put(c, r->name, k, p) == RR_OK ? 0 : 1;
        ok = 0;
    } else if (r->type == RR_RIG_FLAG) {
        if ((ok = PyBool_Check(v)) != 0)
            return rr_rig_config_put(c, r->name, v == Py_True, p) == RR_OK ? 0 : 1;
    } else {
        if ((ok = report_real(v, r->type == RR_RIG_INT ? integral : real, &x)) < 0)
            return -1;
        if (ok)
            return rr_rig_config_put(c, r->name, x, p) == RR_OK ? 0 : 1;
        /* a real for an integer: its value in the problem */
        if (r->type != RR_RIG_INT || report_real(v, real, &x) <= 0)
            x = NAN;
        PyErr_Clear();
    }
    /* not a value of the row's kind: the row's range problem, value NaN (a
     * list: entry the first that is no real, -1 where it is no list) */
    p->key = r->name;
    p->other = NULL;
    p->status = RR_ERR_PARAM;
    p->rule = RR_RIG_RULE_RANGE;
    p->entry = entry;
    p->value = x;
    p->lo = r->lo;
    p->hi = r->hi;
    if (r->type == RR_RIG_CHOICE || r->type == RR_RIG_FLAG) {
        int k = 0;
        while (r->choices && r->choices[k])
            k++;
        p->lo = 0.0;
        p->hi = r->type == RR_RIG_FLAG ? 1.0 : k - 1.0;
    }
    return 1;
}

/* report_value, and where a REAL or LIST row cannot hold its value, a NaN
 * in its place: the report then judges no rule with that row (and with an
 * INT, FLAG or CHOICE row the default: no rule reads one). */
static int report_put(const rr_rig_param *r, PyObject *v, PyObject *real, PyObject *integral,
                      rr_rig_config *c, rr_rig_problem *p)
{
    const double nan = NAN;
    const int st = report_value(r, v, real, integral, c, p);
    if (st == 1 && r->type == RR_RIG_REAL)
        rr_rig_config_put(c, r->name, nan, NULL);
    else if (st == 1 && r->type == RR_RIG_LIST)
        rr_rig_config_put_list(c, r->name, 1, &nan, NULL);
    return st;
}

static PyObject *report_tuple(const rr_rig_problem *p)
{
    return Py_BuildValue("(sisziddd)", p->key, p->status, rig_rule_names[p->rule], p->other,
                         p->entry, p->value, p->lo, p->hi);
}

PyObject *py_rig_config_report(PyObject *self, PyObject *arg)
{
    rr_rig_config c;
    rr_rig_problem found[RR_RIG_MAX_PROBLEMS];
    rr_rig_problem *held = NULL;        /* per row: the value it could not hold */
    char *has = NULL;
    PyObject *numbers = NULL, *real = NULL, *integral = NULL, *key, *v, *out = NULL;
    Py_ssize_t pos = 0;
    const int nrows = rr_rig_param_count();
    int n, i, k;
    (void)self;
    if (!PyDict_Check(arg)) {
        PyErr_SetString(PyExc_TypeError, "rig_config_report: a dict of the rig's parameters");
        return NULL;
    }
    held = PyMem_Calloc((size_t)nrows, sizeof *held);
    has = PyMem_Calloc((size_t)nrows, 1);
    if (!held || !has) {
        PyErr_NoMemory();
        goto done;
    }
    if (!(numbers = PyImport_ImportModule("numbers"))
        || !(real = PyObject_GetAttrString(numbers, "Real"))
        || !(integral = PyObject_GetAttrString(numbers, "Integral")))
        goto done;
    rr_rig_config_default(&c);
    while (PyDict_Next(arg, &pos, &key, &v)) {
        Py_ssize_t len = 0;
        const char *name = PyUnicode_Check(key) ? PyUnicode_AsUTF8AndSize(key, &len) : NULL;
        const rr_rig_param *row = name && strlen(name) == (size_t)len ? rr_rig_param_find(name)
                                                                      : NULL;
        int st;
        if (!row || row->creep) {
            if (!PyErr_Occurred())
                PyErr_Format(PyExc_ValueError, "rig_config_report: %R is not a rig parameter%s",
                             key, row ? " (a creep-force option)" : "");
            goto done;
        }
        i = (int)(row - rr_rig_param_at(0));
        if ((st = report_put(row, v, real, integral, &c, &held[i])) < 0)
            goto done;
        has[i] = (char)st;
    }
    n = rr_rig_config_report(&c, found, RR_RIG_MAX_PROBLEMS);
    if (!(out = PyList_New(0)))
        goto done;
    /* the rows' own problems in the declaration's order, then the rules' */
    for (i = 0; i < nrows; i++) {
        const rr_rig_problem *p = has[i] ? &held[i] : NULL;
        for (k = 0; !p && k < n && k < RR_RIG_MAX_PROBLEMS; k++)
            if (found[k].rule == RR_RIG_RULE_RANGE && found[k].key == rr_rig_param_at(i)->name)
                p = &found[k];
        if (p) {
            PyObject *t = report_tuple(p);
            if (!t || PyList_Append(out, t) < 0) {
                Py_XDECREF(t);
                Py_CLEAR(out);
                goto done;
            }
            Py_DECREF(t);
        }
    }
    for (k = 0; k < n && k < RR_RIG_MAX_PROBLEMS; k++) {
        PyObject *t;
        if (found[k].rule == RR_RIG_RULE_RANGE)
            continue;
        t = report_tuple(&found[k]);
        if (!t || PyList_Append(out, t) < 0) {
            Py_XDECREF(t);
            Py_CLEAR(out);
            goto done;
        }
        Py_DECREF(t);
    }
done:
    PyMem_Free(held);
    PyMem_Free(has);
    Py_XDECREF(numbers);
    Py_XDECREF(real);
    Py_XDECREF(integral);
    return out;
}
/* ==== end of issue 23, item 4 (c-decl) ================================== */
