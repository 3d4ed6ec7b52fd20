/*
 * rr_rig_config.c - a configuration of the rig's primary values
 * (rr_rig_config, rr_rig_params.h): its defaults, setting a row checked,
 * storing one unchecked, and the report of every problem with the check
 * that is its first.  The rows themselves, and the rig's parameters derived
 * from a checked configuration, are rr_rig_params.c's.
 */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "rig/rr_rig_params.h"

static int nchoices(const rr_rig_param *row)
{
    int n = 0;
    while (row->choices[n])
        n++;
    return n;
}

/* 0 if v is within the row's range (REAL, INT, LIST entries), else the status. */
static int in_range(const rr_rig_param *row, double v)
{
    if (!isfinite(v))
        return RR_ERR_NONFINITE;
    if ((row->lo_open ? !(v > row->lo) : !(v >= row->lo))
        || (row->hi_open ? !(v < row->hi) : !(v <= row->hi)))
        return RR_ERR_PARAM;
    return RR_OK;
}

/* 0 if v may be stored in a (non-LIST) row. */
static int value_ok(const rr_rig_param *row, double v)
{
    int st;
    switch (row->type) {
    case RR_RIG_REAL:
        return in_range(row, v);
    case RR_RIG_INT:
        if ((st = in_range(row, v)) != RR_OK)
            return st;
        return v == floor(v) ? RR_OK : RR_ERR_PARAM;
    case RR_RIG_FLAG:
        if (!isfinite(v))
            return RR_ERR_NONFINITE;
        return v == 0.0 || v == 1.0 ? RR_OK : RR_ERR_PARAM;
    case RR_RIG_CHOICE:
        if (!isfinite(v))
            return RR_ERR_NONFINITE;
        return v >= 0.0 && v < nchoices(row) && v == floor(v) ? RR_OK : RR_ERR_PARAM;
    default:
        return RR_ERR_PARAM;
    }
}

static void store(rr_rig_config *c, const rr_rig_param *row, double v)
{
    char *at = (char *)c + row->offset;
    if (row->type == RR_RIG_REAL)
        *(double *)at = v;
    else
        *(int *)at = (int)v;
}

static double load(const rr_rig_config *c, const rr_rig_param *row)
{
    const char *at = (const char *)c + row->offset;
    return row->type == RR_RIG_REAL ? *(const double *)at : (double)*(const int *)at;
}

/* the row `name` if the config may hold it: not NULL, not a creep row */
static const rr_rig_param *settable(const char *name, int *st)
{
    const rr_rig_param *row = rr_rig_param_find(name);
    *st = !name ? RR_ERR_NULL : !row || row->creep ? RR_ERR_PARAM : RR_OK;
    return *st == RR_OK ? row : NULL;
}

int rr_rig_config_default(rr_rig_config *c)
{
    int i;
    if (!c)
        return RR_ERR_NULL;
    memset(c, 0, sizeof *c);
    for (i = 0; i < rr_rig_param_count(); i++) {
        const rr_rig_param *row = rr_rig_param_at(i);
        if (row->creep)
            continue;
        if (row->type == RR_RIG_LIST) {
            rr_rig_list *l = (rr_rig_list *)(void *)((char *)c + row->offset);
            l->n = row->nlist;
            if (row->nlist > 0)
                memcpy(l->v, row->list, (size_t)row->nlist * sizeof l->v[0]);
        } else {
            store(c, row, row->value);
        }
    }
    return RR_OK;
}

int rr_rig_config_set(rr_rig_config *c, const char *name, double v)
{
    int st;
    const rr_rig_param *row = settable(name, &st);
    if (!c)
        return RR_ERR_NULL;
    if (!row)
        return st;
    if ((st = value_ok(row, v)) != RR_OK)
        return st;
    store(c, row, v);
    return RR_OK;
}

int rr_rig_config_set_choice(rr_rig_config *c, const char *name, const char *choice)
{
    int st, k;
    const rr_rig_param *row = settable(name, &st);
    if (!c || !choice)
        return RR_ERR_NULL;
    if (!row)
        return st;
    if ((k = rr_rig_param_choice(row, choice)) < 0)
        return RR_ERR_PARAM;
    store(c, row, k);
    return RR_OK;
}

int rr_rig_config_set_list(rr_rig_config *c, const char *name, int n, const double *v)
{
    int st, i;
    const rr_rig_param *row = settable(name, &st);
    rr_rig_list *l;
    if (!c || (!v && n > 0))
        return RR_ERR_NULL;
    if (!row)
        return st;
    if (row->type != RR_RIG_LIST || n < (row->nlist > 0) || n > RR_RIG_MAX_LIST)
        return RR_ERR_PARAM;
    for (i = 0; i < n; i++)
        if ((st = in_range(row, v[i])) != RR_OK)
            return st;
    l = (rr_rig_list *)(void *)((char *)c + row->offset);
    l->n = n;
    if (n > 0)
        memcpy(l->v, v, (size_t)n * sizeof v[0]);
    return RR_OK;
}

/* ------------------------------------------------------------------ the report */

/* The problems found so far: the first cap kept, all counted. */
typedef struct {
    rr_rig_problem *out;
    int cap, n;
} sink;

static void add(sink *s, const char *key, const char *other, int status, int rule, int entry,
                double value, double lo, double hi)
{
    if (s->n < s->cap) {
        rr_rig_problem *p = &s->out[s->n];
        p->key = key;
        p->other = other;
        p->status = status;
        p->rule = rule;
        p->entry = entry;
        p->value = value;
        p->lo = lo;
        p->hi = hi;
    }
    s->n++;
}

static const rr_rig_list *list_at(const rr_rig_config *c, const rr_rig_param *row)
{
    return (const rr_rig_list *)(const void *)((const char *)c + row->offset);
}

/* 0 if scalar v may be stored in the row, else the status and its RANGE
 * problem (to s: one problem at most). */
static int scalar_problem(const rr_rig_param *row, double v, sink *s)
{
    const int st = value_ok(row, v);
    if (st != RR_OK) {
        const int choice = row->type == RR_RIG_CHOICE;
        add(s, row->name, NULL, st, RR_RIG_RULE_RANGE, -1, v, choice ? 0.0 : row->lo,
            choice ? nchoices(row) - 1.0 : row->hi);
    }
    return st;
}

/* 0 if the list v[0..n-1] may be stored in the row, else as scalar_problem:
 * its length, or its first entry out of range. */
static int list_problem(const rr_rig_param *row, int n, const double *v, sink *s)
{
    const int least = row->nlist > 0;
    int k, st;
    if (n < least || n > RR_RIG_MAX_LIST) {
        add(s, row->name, NULL, RR_ERR_PARAM, RR_RIG_RULE_RANGE, -1, n, least, RR_RIG_MAX_LIST);
        return RR_ERR_PARAM;
    }
    for (k = 0; k < n; k++)
        if ((st = in_range(row, v[k])) != RR_OK) {
            add(s, row->name, NULL, st, RR_RIG_RULE_RANGE, k, v[k], row->lo, row->hi);
            return st;
        }
    return RR_OK;
}

/* 0 if the row's member of c is in its range (problems to s, if any). */
static int row_problem(const rr_rig_config *c, const rr_rig_param *row, sink *s)
{
    if (row->type == RR_RIG_LIST) {
        const rr_rig_list *l = list_at(c, row);
        return list_problem(row, l->n, l->v, s);
    }
    return scalar_problem(row, load(c, row), s);
}

/* 1 if every row named (a NULL-terminated list) is in its range in c. */
static int rows_ok(const rr_rig_config *c, const char *const *names)
{
    sink none = {NULL, 0, 0};
    for (; *names; names++)
        if (row_problem(c, rr_rig_param_find(*names), &none) != RR_OK)
            return 0;
    return 1;
}

#define STARTS "scenario.target_start_s"
#define TARGETS "scenario.targets"
#define DURATION "scenario.duration_s"
#define SAMPLE_TIME "scenario.control_sample_time_s"
#define TIMES "adhesion.schedule_times_s"
#define SPIN_INERTIA "wheelset.spin_inertia_kg_m2"
#define DRIVE_INERTIA "wheelset_drive.drive_inertia_kg_m2"

/* the rows each rule reads */
static const char *const scenario_rows[] = {TARGETS, STARTS, NULL};
static const char *const duration_rows[] = {DURATION, NULL};
static const char *const sample_rows[] = {DURATION, SAMPLE_TIME, NULL};
static const char *const schedule_rows[] = {TIMES, "adhesion.schedule_mu0",
                                            "adhesion.schedule_polach_A",
                                            "adhesion.schedule_polach_B_s_per_m", NULL};
static const char *const lateral_rows[] = {"disturbance.lateral_force_times_s",
                                           "disturbance.lateral_force_N", NULL};
static const char *const patch_rows[] = {"adhesion.patch_length_m", "roller.radius_m", NULL};
static const char *const inertia_rows[] = {SPIN_INERTIA, DRIVE_INERTIA, NULL};
/* drives_from's rows that rr_rig_speed_loops reads (the PI's Tmax too: its check) */
static const char *const loop_rows[] = {
    SAMPLE_TIME, "roller.inertia_kg_m2", SPIN_INERTIA, DRIVE_INERTIA,
    "roller_drive.kp_N_m_s_per_rad", "roller_drive.ki_N_m_s_per_rad",
    "roller_drive.torque_limit_N_m", "roller_drive.lag_time_constant_s",
    "wheelset_drive.kp_N_m_s_per_rad", "wheelset_drive.ki_N_m_s_per_rad",
    "wheelset_drive.torque_limit_N_m", "wheelset_drive.lag_time_constant_s",
    "creepage_controller.alpha", NULL};

/* A schedule list of as many entries as the times, or (may_be_empty) none:
 * lo 0 says that none would do too. */
static void schedule_count(const rr_rig_config *c, const char *key, const rr_rig_list *l,
                           int may_be_empty, sink *s)
{
    if (l->n != c->schedule_t.n && !(may_be_empty && l->n == 0))
        add(s, key, TIMES, RR_ERR_PARAM, RR_RIG_RULE_COUNT, -1, l->n, may_be_empty ? 0.0 : NAN,
            c->schedule_t.n);
}

/* rr_rig_config_report; scans 0: a loop's pole and stable sample times
 * left NaN (rr_rig_config_check reads none of them) */
static int report(const rr_rig_config *c, rr_rig_problem *out, int cap, int scans)
{
    sink s;
    int i, k;
    if (!c || (!out && cap > 0))
        return RR_ERR_NULL;
    s.out = out;
    s.cap = cap > 0 ? cap : 0;
    s.n = 0;
    for (i = 0; i < rr_rig_param_count(); i++)
        if (!rr_rig_param_at(i)->creep)
            row_problem(c, rr_rig_param_at(i), &s);
    /* the scenario: one start time per target, increasing, inside the duration */
    if (rows_ok(c, scenario_rows)) {
        const rr_rig_list *t = &c->target_start;
        if (t->n != c->targets.n) {
            add(&s, STARTS, TARGETS, RR_ERR_PARAM, RR_RIG_RULE_COUNT, -1, t->n, NAN,
                c->targets.n);
        } else {
            for (k = 1; k < t->n && t->v[k] > t->v[k - 1]; k++)
                ;
            if (k < t->n)
                add(&s, STARTS, NULL, RR_ERR_PARAM, RR_RIG_RULE_INCREASING, k, t->v[k], NAN, NAN);
            else if (rows_ok(c, duration_rows) && !(t->v[t->n - 1] < c->duration))
                add(&s, STARTS, DURATION, RR_ERR_PARAM, RR_RIG_RULE_BEFORE, t->n - 1,
                    t->v[t->n - 1], NAN, c->duration);
        }
    }
    if (rows_ok(c, sample_rows) && !(c->duration >= c->T * (1.0 - 1e-9)))
        add(&s, DURATION, SAMPLE_TIME, RR_ERR_PARAM, RR_RIG_RULE_SAMPLE, -1, c->duration, c->T,
            NAN);
    /* the adhesion: one mu0 (and A, B, or none) per time, in order; the patch on the roller */
    if (rows_ok(c, schedule_rows)) {
        schedule_count(c, "adhesion.schedule_mu0", &c->schedule_mu0, 0, &s);
        schedule_count(c, "adhesion.schedule_polach_A", &c->schedule_A, 1, &s);
        schedule_count(c, "adhesion.schedule_polach_B_s_per_m", &c->schedule_B, 1, &s);
        for (k = 1; k < c->schedule_t.n && c->schedule_t.v[k] >= c->schedule_t.v[k - 1]; k++)
            ;
        if (k < c->schedule_t.n)
            add(&s, TIMES, NULL, RR_ERR_PARAM, RR_RIG_RULE_NONDECREASING, k, c->schedule_t.v[k],
                NAN, NAN);
    }
    /* the lateral force: one per time, the times in order */
    if (rows_ok(c, lateral_rows)) {
        if (c->lateral_f.n != c->lateral_t.n)
            add(&s, "disturbance.lateral_force_N", "disturbance.lateral_force_times_s",
                RR_ERR_PARAM, RR_RIG_RULE_COUNT, -1, c->lateral_f.n, NAN, c->lateral_t.n);
        for (k = 1; k < c->lateral_t.n && c->lateral_t.v[k] >= c->lateral_t.v[k - 1]; k++)
            ;
        if (k < c->lateral_t.n)
            add(&s, "disturbance.lateral_force_times_s", NULL, RR_ERR_PARAM,
                RR_RIG_RULE_NONDECREASING, k, c->lateral_t.v[k], NAN, NAN);
    }
    if (rows_ok(c, patch_rows) && !(c->patch_length <= 2.0 * RR_PI * c->roller_radius))
        add(&s, "adhesion.patch_length_m", "roller.radius_m", RR_ERR_PARAM,
            RR_RIG_RULE_CIRCUMFERENCE, -1, c->patch_length, NAN, 2.0 * RR_PI * c->roller_radius);
    /* the drives' sampled loops stable at the sample time (rr_rig_check's
     * rule; a loop of an inertia sum that overflows is the rule below's) */
    if (rows_ok(c, loop_rows)) {
        rr_speed_loop loops[2];
        rr_rig_config_speed_loops(c, loops);
        for (k = 0; k < 2; k++)
            if (rr_speed_loop_check(&loops[k]) == RR_ERR_PARAM) {
                double rho = NAN, lo = NAN, hi = NAN;
                if (scans && s.n < s.cap) {     /* the costly scan: a problem kept */
                    rr_speed_loop_radius(&loops[k], &rho);
                    rr_speed_loop_range(&loops[k], RR_RIG_MIN_T, RR_RIG_MAX_T, &lo, &hi);
                }
                add(&s, SAMPLE_TIME, NULL, RR_ERR_PARAM, RR_RIG_RULE_LOOP, k, rho, lo, hi);
            }
    }
    /* the wheelset's inertia with its drive's (rr_rig_params_from's Iyy) */
    if (rows_ok(c, inertia_rows) && !isfinite(c->spin_inertia + c->drive_inertia))
        add(&s, SPIN_INERTIA, DRIVE_INERTIA, RR_ERR_RANGE, RR_RIG_RULE_SUM, -1,
            c->spin_inertia + c->drive_inertia, NAN, NAN);
    return s.n;
}

int rr_rig_config_report(const rr_rig_config *c, rr_rig_problem *out, int cap)
{
    return report(c, out, cap, 1);
}

int rr_rig_config_check(const rr_rig_config *c, const char **bad)
{
    rr_rig_problem first;
    const int n = report(c, &first, 1, 0);
    if (bad)
        *bad = n > 0 ? first.key : NULL;
    return n < 0 ? n : n > 0 ? first.status : RR_OK;
}

/* the row `name` of the kind asked (a LIST or not), if the config holds it */
static const rr_rig_param *puttable(const char *name, int list, int *st)
{
    const rr_rig_param *row = settable(name, st);
    if (row && (row->type == RR_RIG_LIST) != list) {
        *st = RR_ERR_PARAM;
        return NULL;
    }
    return row;
}

int rr_rig_config_put(rr_rig_config *c, const char *name, double v, rr_rig_problem *p)
{
    int st;
    const rr_rig_param *row = puttable(name, 0, &st);
    if (!c)
        return RR_ERR_NULL;
    if (!row)
        return st;
    /* an INT, FLAG or CHOICE member holds whole numbers in int's range */
    if (row->type != RR_RIG_REAL && !(v == floor(v) && fabs(v) <= 2147483647.0)) {
        sink s;
        s.out = p;
        s.cap = p ? 1 : 0;
        s.n = 0;
        st = scalar_problem(row, v, &s);
        return st != RR_OK ? st : RR_ERR_PARAM;     /* (every such value is out of range) */
    }
    store(c, row, v);
    return RR_OK;
}

int rr_rig_config_put_list(rr_rig_config *c, const char *name, int n, const double *v,
                           rr_rig_problem *p)
{
    int st;
    const rr_rig_param *row = puttable(name, 1, &st);
    rr_rig_list *l;
    if (!c || (!v && n > 0))
        return RR_ERR_NULL;
    if (!row)
        return st;
    if (n < 0 || n > RR_RIG_MAX_LIST) {
        sink s;
        s.out = p;
        s.cap = p ? 1 : 0;
        s.n = 0;
        add(&s, row->name, NULL, RR_ERR_PARAM, RR_RIG_RULE_RANGE, -1, n, row->nlist > 0,
            RR_RIG_MAX_LIST);
        return RR_ERR_PARAM;
    }
    l = (rr_rig_list *)(void *)((char *)c + row->offset);
    l->n = n;
    if (n > 0)
        memcpy(l->v, v, (size_t)n * sizeof v[0]);
    return RR_OK;
}
