/* rr_fmu.c - the roller rig as a co-simulation unit (rr_fmu.h). */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_creep.h"
#include "rig/rr_rig_params.h"
#include "fmu/rr_fmu.h"

/* what a variable is (rr_fmu_var.kind) */
enum { K_TIME = 0, K_PARAM, K_LIST, K_CREEP, K_CONTROL, K_INPUT, K_RECORD, K_ENCODER, K_WHEEL };

/* ------------------------------------------------------------------ tables */

static const char *const roller_modes[] = {"scenario", "speed", "torque", NULL};
static const char *const wheelset_modes[] = {"scenario", "creepage", "speed", "torque", "free",
                                              NULL};
static const char *const mu_sources[] = {"adhesion", "input", NULL};
static const char *const start_states[] = {"rolling", "rest", NULL};

typedef struct {
    const char *name;
    const char *const *choices;
    int variability;
    const char *description;
} control_decl;

/* each at its enum rr_fmu_control index; the sizes checked below */
static const control_decl controls[] = {
    [RR_FMU_ROLLER_MODE] = {"control.roller_mode", roller_modes, RR_FMU_TUNABLE,
     "how the roller drive is commanded at each sample: scenario (its PI to the scenario's "
     "speed, scenario.roller_speed_m_s over roller.radius_m), speed (its PI to the input "
     "roller_speed_ref), torque (the input roller_torque_ref to the drive)"},
    [RR_FMU_WHEELSET_MODE] = {"control.wheelset_mode", wheelset_modes, RR_FMU_TUNABLE,
     "how the wheelset drive is commanded at each sample: scenario (the creepage controller, "
     "eq. 13-16, to the scenario's targets, scenario.targets from scenario.target_start_s), "
     "creepage (the creepage controller to the input creepage_ref), speed (its PI to the "
     "input wheelset_speed_ref), torque (the input wheelset_torque_ref to the drive), free (no "
     "creepage control: its PI to free rolling at the roller's measured speed)"},
    [RR_FMU_MU_SOURCE] = {"control.mu_source", mu_sources, RR_FMU_TUNABLE,
     "the static friction coefficient mu0 at each sample: adhesion (the [adhesion] schedule "
     "and patch; scenario.mu0 without a schedule) or input (the input mu; a patch still "
     "applies)"},
    [RR_FMU_START] = {"control.start", start_states, RR_FMU_FIXED,
     "the initial state: rolling (the wheelset rolling freely on the rollers at "
     "scenario.roller_speed_m_s) or rest (everything at standstill; the roller drive spins "
     "the rig up), as rollerrig.simulate's start"},
};

typedef struct {
    const char *name;
    const char *unit;
    double lo, hi;
    int lo_open, hi_open;
    const char *description;
} input_decl;

static const input_decl inputs[] = {
    [RR_FMU_IN_ROLLER_SPEED] = {"roller_speed_ref", "rad/s", -HUGE_VAL, HUGE_VAL, 0, 0,
     "roller speed reference of the roller's PI (eq. 10-11) with control.roller_mode = "
     "speed; start: scenario.roller_speed_m_s / roller.radius_m"},
    [RR_FMU_IN_ROLLER_TORQUE] = {"roller_torque_ref", "N m", -HUGE_VAL, HUGE_VAL, 0, 0,
     "roller drive torque reference with control.roller_mode = torque (clipped to "
     "roller_drive.torque_limit_N_m)"},
    [RR_FMU_IN_CREEPAGE] = {"creepage_ref", "-", 0.0, 1.0, 0, 1,
     "creepage target of the creepage controller (eq. 13-16) with control.wheelset_mode = "
     "creepage, in the drive's sense (> 0; control.wheelset_mode = free: none, free "
     "rolling); start: the first of scenario.targets"},
    [RR_FMU_IN_WHEELSET_SPEED] = {"wheelset_speed_ref", "rad/s", -HUGE_VAL, HUGE_VAL, 0, 0,
     "wheelset speed reference of the wheelset's PI with control.wheelset_mode = speed; "
     "start: scenario.roller_speed_m_s / wheelset.wheel_radius_m"},
    [RR_FMU_IN_WHEELSET_TORQUE] = {"wheelset_torque_ref", "N m", -HUGE_VAL, HUGE_VAL, 0, 0,
     "wheelset drive torque reference with control.wheelset_mode = torque (clipped to "
     "wheelset_drive.torque_limit_N_m)"},
    [RR_FMU_IN_MU] = {"mu", "-", 0.0, RR_FRICTION_MAX, 1, 0,
     "static friction coefficient mu0 over the sample with control.mu_source = input (the "
     "falling law's A and B stay the contact section's); start: scenario.mu0"},
};

#define ENC(name, member, unit, meaning) \
    {name, 1, (long)offsetof(rr_rig_signals, member), unit, meaning}
static const rr_rig_field encoders[] = {
    [RR_FMU_ENC_ROLLER_COUNT] = ENC("encoder.roller_count", roller_count, "-",
        "roller encoder's counter at the present time (whole counts, cumulative)"),
    [RR_FMU_ENC_WHEELSET_COUNT] = ENC("encoder.wheelset_count", wheelset_count, "-",
        "wheelset encoder's counter at the present time (whole counts, cumulative)"),
    [RR_FMU_ENC_ROLLER_ANGLE] = ENC("encoder.roller_angle", roller_angle, "rad",
        "roller angle the encoder reads (quantised: count 2 pi / counts per revolution)"),
    [RR_FMU_ENC_WHEELSET_ANGLE] = ENC("encoder.wheelset_angle", wheelset_angle, "rad",
        "wheelset angle the encoder reads (quantised)"),
    [RR_FMU_ENC_ROLLER_SPEED] = ENC("encoder.roller_speed", roller_speed, "rad/s",
        "roller speed estimate from the encoder's last two readings (eq. 12)"),
    [RR_FMU_ENC_WHEELSET_SPEED] = ENC("encoder.wheelset_speed", wheelset_speed, "rad/s",
        "wheelset speed estimate from the encoder's last two readings (eq. 12)"),
    [RR_FMU_ENC_XI_EST] = ENC("encoder.xi_est", xi_est, "-",
        "creepage estimate from the encoders' speeds at the present time (eq. 16, in the "
        "creepage controller's sense); the record's xi_est is the one the controller used "
        "at the last sample"),
};

/* The rows the rig reads afresh at every sample: tunable. */
static const char *const tunable_rows[] = {
    "scenario.roller_speed_m_s", "scenario.targets", "scenario.target_start_s", "scenario.mu0",
    "contact.polach_A", "contact.polach_B_s_per_m",
    "roller_drive.kp_N_m_s_per_rad", "roller_drive.ki_N_m_s_per_rad",
    "wheelset_drive.kp_N_m_s_per_rad", "wheelset_drive.ki_N_m_s_per_rad",
    "creepage_controller.alpha", "creepage_controller.beta",
    "creepage_controller.min_reference_speed_m_s",
    "adhesion.schedule_times_s", "adhesion.schedule_mu0", "adhesion.schedule_polach_A",
    "adhesion.schedule_polach_B_s_per_m", "adhesion.patch_length_m", "adhesion.patch_start_m",
    "adhesion.patch_mu0", "adhesion.patch_polach_A", "adhesion.patch_polach_B_s_per_m",
    "adhesion.patch_edge_m",
};

static const char *const default_type_names[] = {
    [RR_FMU_REAL] = "Real", [RR_FMU_INTEGER] = "Integer", [RR_FMU_BOOLEAN] = "Boolean",
    [RR_FMU_ENUMERATION] = "Enumeration"};
static const char *const causality_names[] = {
    [RR_FMU_INDEPENDENT] = "independent", [RR_FMU_PARAMETER] = "parameter",
    [RR_FMU_INPUT] = "input", [RR_FMU_OUTPUT] = "output"};
static const char *const mode_names[] = {
    [RR_FMU_INSTANTIATED] = "instantiated", [RR_FMU_INITIALIZATION] = "initialization mode",
    [RR_FMU_STEPPING] = "stepping", [RR_FMU_TERMINATED] = "terminated",
    [RR_FMU_FAILED] = "failed"};

#define COUNT(a) RR_COUNTOF(a)

RR_STATIC_ASSERT(COUNT(controls) == RR_FMU_NCONTROL, one_control_each);
RR_STATIC_ASSERT(COUNT(inputs) == RR_FMU_NINPUT, one_input_each);
RR_STATIC_ASSERT(COUNT(encoders) == RR_FMU_NENCODER, one_encoder_each);
RR_STATIC_ASSERT(COUNT(default_type_names) == RR_FMU_ENUMERATION + 1, one_type_name_each);
RR_STATIC_ASSERT(COUNT(causality_names) == RR_FMU_OUTPUT + 1, one_causality_name_each);
RR_STATIC_ASSERT(COUNT(mode_names) == RR_FMU_FAILED + 1, one_mode_name_each);

/* ------------------------------------------------------------------ helpers */

void rr_fmu_format_number(double x, char *buf, size_t len)
{
    int p;
    if (!buf || len == 0)
        return;
    if (isnan(x)) {
        snprintf(buf, len, "nan");
        return;
    }
    if (isinf(x)) {
        snprintf(buf, len, x > 0 ? "inf" : "-inf");
        return;
    }
    /* the shortest of 15, 16, 17 digits that reads back as x */
    for (p = 15; p <= 17; p++) {
        snprintf(buf, len, "%.*g", p, x);
        if (strtod(buf, NULL) == x)
            return;
    }
}

static int fail(rr_fmu *m, int st, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(m->msg, sizeof m->msg, fmt, ap);
    va_end(ap);
    return st;
}

static int nchoices(const char *const *c)
{
    int n = 0;
    while (c && c[n])
        n++;
    return n;
}

static int is_tunable(const char *name)
{
    int i;
    for (i = 0; i < COUNT(tunable_rows); i++)
        if (strcmp(tunable_rows[i], name) == 0)
            return 1;
    return 0;
}

/* The option a creep row sets (its declared option): the first method's
 * of that name (rollerrig.rig's _option_rule); NULL for
 * contact.creep_method. */
static const rr_creep_option *creep_option(const rr_rig_param *row)
{
    int i, k;
    if (!row->option)
        return NULL;
    for (i = 0; i < rr_method_count(); i++) {
        const rr_method_desc *d = rr_method_get(i);
        if (d && (k = rr_method_option(d, row->option)) >= 0)
            return &d->opts[k];
    }
    return NULL;
}

/* The creep row's slot in rr_fmu_config.creep, or -1. */
static int creep_slot(const rr_rig_param *row)
{
    int i, n = 0;
    for (i = 0; i < rr_rig_param_count(); i++) {
        const rr_rig_param *r = rr_rig_param_at(i);
        if (r == row)
            return row->creep && n < RR_FMU_MAX_CREEP ? n : -1;
        n += r->creep;
    }
    return -1;
}

/* A method the rig can step with (rr_rig_method_check: no workspace, |F| <= mu N). */
static int method_usable(int method)
{
    rr_creep_opts o;
    if (rr_creep_opts_default(&o, method) != RR_OK)
        return 0;
    return rr_rig_method_check(&o) == RR_OK;
}

/* A creep row's default as text (its TOML text without the quotes). */
static void row_text(const rr_rig_param *row, char *buf, size_t len)
{
    size_t n = 0;
    const char *t = row->text ? row->text : "";
    for (; *t && n + 1 < len; t++)
        if (*t != '"')
            buf[n++] = *t;
    buf[n] = '\0';
}

static const rr_rig_list *list_of(const rr_rig_config *c, const rr_rig_param *row)
{
    return (const rr_rig_list *)(const void *)((const char *)c + row->offset);
}

static double row_load(const rr_rig_config *c, const rr_rig_param *row)
{
    const char *at = (const char *)c + row->offset;
    return row->type == RR_RIG_REAL ? *(const double *)(const void *)at
                                    : (double)*(const int *)(const void *)at;
}

/* ------------------------------------------------------------------ configuration */

int rr_fmu_config_default(rr_fmu_config *f)
{
    int i;
    if (!f)
        return RR_ERR_NULL;
    memset(f, 0, sizeof *f);
    rr_rig_config_default(&f->c);
    for (i = 0; i < rr_rig_param_count(); i++) {
        const rr_rig_param *row = rr_rig_param_at(i);
        const rr_creep_option *op;
        char text[64];
        int slot = row->creep ? creep_slot(row) : -1;
        if (slot < 0)
            continue;
        row_text(row, text, sizeof text);
        op = creep_option(row);
        if (!op) {
            f->creep[slot] = rr_method_find(text);
        } else if (op->type == RR_OPT_CHOICE) {
            int k;
            for (k = 0; op->choices[k] && strcmp(op->choices[k], text) != 0; k++)
                ;
            f->creep[slot] = k;
        } else {
            f->creep[slot] = row->value;
        }
    }
    return RR_OK;
}

static int control_index(const char *name)
{
    int i;
    for (i = 0; i < RR_FMU_NCONTROL; i++)
        if (strcmp(controls[i].name, name) == 0)
            return i;
    return -1;
}

/* 0 if v may be stored in the creep row (its option's range; a method the
 * rig can step with). */
static int creep_value_ok(const rr_rig_param *row, double v)
{
    const rr_creep_option *op = creep_option(row);
    if (!isfinite(v))
        return RR_ERR_NONFINITE;
    if (!op)
        return v == floor(v) && v >= 0 && v < rr_method_count() && method_usable((int)v)
             ? RR_OK : RR_ERR_PARAM;
    return rr_method_option_check(op, v) == RR_OK ? RR_OK : RR_ERR_PARAM;
}

int rr_fmu_config_set(rr_fmu_config *f, const char *name, double v)
{
    const rr_rig_param *row;
    int k, st;
    if (!f || !name)
        return RR_ERR_NULL;
    if ((k = control_index(name)) >= 0) {
        if (!isfinite(v))
            return RR_ERR_NONFINITE;
        if (v != floor(v) || v < 0 || v >= nchoices(controls[k].choices))
            return RR_ERR_PARAM;
        f->control[k] = (int)v;
        return RR_OK;
    }
    row = rr_rig_param_find(name);
    if (row && row->creep) {
        if ((st = creep_value_ok(row, v)) != RR_OK)
            return st;
        f->creep[creep_slot(row)] = v;
        return RR_OK;
    }
    return rr_rig_config_set(&f->c, name, v);
}

int rr_fmu_config_set_choice(rr_fmu_config *f, const char *name, const char *choice)
{
    const rr_rig_param *row;
    int k, i;
    if (!f || !name || !choice)
        return RR_ERR_NULL;
    if ((k = control_index(name)) >= 0) {
        for (i = 0; controls[k].choices[i]; i++)
            if (strcmp(controls[k].choices[i], choice) == 0)
                return rr_fmu_config_set(f, name, i);
        return RR_ERR_PARAM;
    }
    row = rr_rig_param_find(name);
    if (row && row->creep) {
        const rr_creep_option *op = creep_option(row);
        if (!op)
            return rr_method_find(choice) >= 0
                 ? rr_fmu_config_set(f, name, rr_method_find(choice)) : RR_ERR_PARAM;
        if (op->type != RR_OPT_CHOICE)
            return RR_ERR_PARAM;
        for (i = 0; op->choices[i]; i++)
            if (strcmp(op->choices[i], choice) == 0)
                return rr_fmu_config_set(f, name, i);
        return RR_ERR_PARAM;
    }
    return rr_rig_config_set_choice(&f->c, name, choice);
}

int rr_fmu_config_set_list(rr_fmu_config *f, const char *name, int n, const double *v)
{
    if (!f || !name)
        return RR_ERR_NULL;
    return rr_rig_config_set_list(&f->c, name, n, v);
}

int rr_fmu_creep_opts(const rr_fmu_config *f, rr_creep_opts *o, const char **bad)
{
    const rr_rig_param *method_row = rr_rig_param_find("contact.creep_method");
    const rr_method_desc *d;
    int i, st, at;
    if (bad)
        *bad = NULL;
    if (!f || !o)
        return RR_ERR_NULL;
    st = rr_creep_opts_default(o, (int)f->creep[creep_slot(method_row)]);
    if (st == RR_OK && !method_usable(o->method))
        st = RR_ERR_METHOD;
    if (st != RR_OK) {
        if (bad)
            *bad = method_row->name;
        return st;
    }
    d = rr_method_get(o->method);
    for (i = 0; i < rr_rig_param_count(); i++) {
        const rr_rig_param *row = rr_rig_param_at(i);
        if (!row->option || rr_method_option(d, row->option) < 0)
            continue;
        if ((st = rr_creep_opts_set(o, row->option, f->creep[creep_slot(row)])) != RR_OK) {
            if (bad)
                *bad = row->name;
            return st;
        }
    }
    st = rr_creep_opts_check_at(o, &at);
    if (st != RR_OK && bad) {
        /* the row of the option at fault, if one sets it */
        *bad = method_row->name;
        for (i = 0; at >= 0 && i < rr_rig_param_count(); i++) {
            const rr_rig_param *row = rr_rig_param_at(i);
            if (row->option && strcmp(row->option, d->opts[at].name) == 0)
                *bad = row->name;
        }
    }
    return st;
}

/* ------------------------------------------------------------------ variables */

static int list_len(const rr_fmu_config *start, const rr_rig_param *row)
{
    return list_of(&start->c, row)->n;
}

/* The wheel block's field and component of value index j. */
static const rr_rig_field *wheel_value(int j, int *comp)
{
    int i;
    for (i = 0; i < RR_WHEEL_NFIELDS; i++) {
        const rr_rig_field *f = rr_wheel_field(i);
        if (j < f->width) {
            *comp = f->width > 1 ? j : -1;
            return f;
        }
        j -= f->width;
    }
    return NULL;
}

static void var_clear(rr_fmu_var *v, unsigned vr, int kind, int index)
{
    memset(v, 0, sizeof *v);
    v->vr = vr;
    v->prefix = "";
    v->entry = -1;
    v->unit = "";
    v->description = "";
    v->lo = -HUGE_VAL;
    v->hi = HUGE_VAL;
    v->kind = kind;
    v->index = index;
}

/* The variable of parameter row `row` (index r), entry e of a LIST. */
static void param_var(const rr_rig_param *row, int r, int e, rr_fmu_var *v)
{
    const rr_creep_option *op;
    if (row->type == RR_RIG_LIST) {
        var_clear(v, RR_FMU_VR_LIST + RR_FMU_VR_LIST_ROW * (unsigned)r + (unsigned)e, K_LIST, r);
        v->entry = e;
    } else {
        var_clear(v, RR_FMU_VR_PARAM + (unsigned)r, row->creep ? K_CREEP : K_PARAM, r);
    }
    v->row = row;
    v->base = row->name;
    v->unit = row->unit;
    v->description = row->origin;
    v->causality = RR_FMU_PARAMETER;
    v->variability = is_tunable(row->name) ? RR_FMU_TUNABLE : RR_FMU_FIXED;
    switch (row->type) {
    case RR_RIG_INT:
        v->type = RR_FMU_INTEGER;
        break;
    case RR_RIG_FLAG:
        v->type = RR_FMU_BOOLEAN;
        break;
    case RR_RIG_CHOICE:
        v->type = RR_FMU_ENUMERATION;
        break;
    default:
        v->type = RR_FMU_REAL;
    }
    if (row->creep) {
        if ((op = creep_option(row)) != NULL) {
            v->lo = op->lo;
            v->hi = op->hi;
            v->lo_open = op->lo_open;
            v->hi_open = op->hi_open;
            if (op->type == RR_OPT_INT) {
                /* an integer range's open ends, closed (rollerrig.rig does so) */
                v->lo = op->lo + op->lo_open;
                v->hi = op->hi - op->hi_open;
                v->lo_open = v->hi_open = 0;
            }
        }
    } else if (row->type == RR_RIG_REAL || row->type == RR_RIG_INT || row->type == RR_RIG_LIST) {
        v->lo = row->lo;
        v->hi = row->hi;
        v->lo_open = row->lo_open;
        v->hi_open = row->hi_open;
    }
}

static int n_params(const rr_fmu_config *start)
{
    int i, n = 0;
    for (i = 0; i < rr_rig_param_count(); i++) {
        const rr_rig_param *row = rr_rig_param_at(i);
        n += row->type == RR_RIG_LIST ? list_len(start, row) : 1;
    }
    return n;
}

#define N_RECORD_OUT (RR_REC_COUNT - 1)     /* all but the time */

int rr_fmu_var_count(const rr_fmu_config *start)
{
    if (!start)
        return 0;
    return 1 + n_params(start) + RR_FMU_NCONTROL + RR_FMU_NINPUT + N_RECORD_OUT
         + RR_FMU_NENCODER + 2 * RR_WHEEL_NVALUES;
}

static void control_var(int i, rr_fmu_var *v)
{
    var_clear(v, RR_FMU_VR_CONTROL + (unsigned)i, K_CONTROL, i);
    v->base = controls[i].name;
    v->description = controls[i].description;
    v->type = RR_FMU_ENUMERATION;
    v->causality = RR_FMU_PARAMETER;
    v->variability = controls[i].variability;
}

static void input_var(int i, rr_fmu_var *v)
{
    var_clear(v, RR_FMU_VR_INPUT + (unsigned)i, K_INPUT, i);
    v->base = inputs[i].name;
    v->unit = inputs[i].unit;
    v->description = inputs[i].description;
    v->type = RR_FMU_REAL;
    v->causality = RR_FMU_INPUT;
    /* sampled by the rig's controllers at each sample and held over it */
    v->variability = RR_FMU_DISCRETE;
    v->lo = inputs[i].lo;
    v->hi = inputs[i].hi;
    v->lo_open = inputs[i].lo_open;
    v->hi_open = inputs[i].hi_open;
}

static void output_var(unsigned vr, int kind, int index, const rr_rig_field *f, rr_fmu_var *v)
{
    var_clear(v, vr, kind, index);
    v->base = f->name;
    v->unit = f->unit;
    v->description = f->meaning;
    v->type = RR_FMU_REAL;
    v->causality = RR_FMU_OUTPUT;
    v->variability = RR_FMU_CONTINUOUS;
}

static void record_var(int i, rr_fmu_var *v)
{
    output_var(RR_FMU_VR_RECORD + (unsigned)i, K_RECORD, i, rr_rig_record_field(i), v);
    if (i == RR_REC_STATUS) {
        v->type = RR_FMU_INTEGER;
        v->variability = RR_FMU_DISCRETE;
    }
}

static void wheel_var(int side, int j, rr_fmu_var *v)
{
    int comp;
    const rr_rig_field *f = wheel_value(j, &comp);
    output_var(RR_FMU_VR_WHEEL + RR_FMU_VR_WHEEL_SIDE * (unsigned)side + (unsigned)j, K_WHEEL,
               side * RR_WHEEL_NVALUES + j, f, v);
    v->prefix = side ? "right." : "left.";
    v->entry = comp;
}

static void time_var(rr_fmu_var *v)
{
    var_clear(v, RR_FMU_VR_TIME, K_TIME, 0);
    v->base = "time";
    v->unit = "s";
    v->description = "time (the rig's clock runs from the start time, where the scenario "
                     "begins)";
    v->type = RR_FMU_REAL;
    v->causality = RR_FMU_INDEPENDENT;
    v->variability = RR_FMU_CONTINUOUS;
}

int rr_fmu_var_at(const rr_fmu_config *start, int i, rr_fmu_var *v)
{
    int r;
    if (!start || !v)
        return RR_ERR_NULL;
    if (i < 0)
        return RR_ERR_PARAM;
    if (i == 0) {
        time_var(v);
        return RR_OK;
    }
    i -= 1;
    for (r = 0; r < rr_rig_param_count(); r++) {
        const rr_rig_param *row = rr_rig_param_at(r);
        const int n = row->type == RR_RIG_LIST ? list_len(start, row) : 1;
        if (i < n) {
            param_var(row, r, row->type == RR_RIG_LIST ? i : 0, v);
            return RR_OK;
        }
        i -= n;
    }
    if (i < RR_FMU_NCONTROL) {
        control_var(i, v);
        return RR_OK;
    }
    i -= RR_FMU_NCONTROL;
    if (i < RR_FMU_NINPUT) {
        input_var(i, v);
        return RR_OK;
    }
    i -= RR_FMU_NINPUT;
    if (i < N_RECORD_OUT) {
        record_var(i + 1, v);
        return RR_OK;
    }
    i -= N_RECORD_OUT;
    if (i < RR_FMU_NENCODER) {
        output_var(RR_FMU_VR_ENCODER + (unsigned)i, K_ENCODER, i, &encoders[i], v);
        return RR_OK;
    }
    i -= RR_FMU_NENCODER;
    if (i < 2 * RR_WHEEL_NVALUES) {
        wheel_var(i / RR_WHEEL_NVALUES, i % RR_WHEEL_NVALUES, v);
        return RR_OK;
    }
    return RR_ERR_PARAM;
}

int rr_fmu_var_find(const rr_fmu_config *start, unsigned vr, rr_fmu_var *v)
{
    if (!start || !v)
        return RR_ERR_NULL;
    if (vr == RR_FMU_VR_TIME) {
        time_var(v);
        return RR_OK;
    }
    if (vr >= RR_FMU_VR_CONTROL && vr < RR_FMU_VR_CONTROL + RR_FMU_NCONTROL) {
        control_var((int)(vr - RR_FMU_VR_CONTROL), v);
        return RR_OK;
    }
    if (vr >= RR_FMU_VR_INPUT && vr < RR_FMU_VR_INPUT + RR_FMU_NINPUT) {
        input_var((int)(vr - RR_FMU_VR_INPUT), v);
        return RR_OK;
    }
    if (vr > RR_FMU_VR_RECORD && vr < RR_FMU_VR_RECORD + RR_REC_COUNT) {
        record_var((int)(vr - RR_FMU_VR_RECORD), v);
        return RR_OK;
    }
    if (vr >= RR_FMU_VR_ENCODER && vr < RR_FMU_VR_ENCODER + RR_FMU_NENCODER) {
        const int i = (int)(vr - RR_FMU_VR_ENCODER);
        output_var(vr, K_ENCODER, i, &encoders[i], v);
        return RR_OK;
    }
    if (vr >= RR_FMU_VR_WHEEL && vr < RR_FMU_VR_WHEEL + 2 * RR_FMU_VR_WHEEL_SIDE) {
        const unsigned side = (vr - RR_FMU_VR_WHEEL) / RR_FMU_VR_WHEEL_SIDE;
        const unsigned j = (vr - RR_FMU_VR_WHEEL) % RR_FMU_VR_WHEEL_SIDE;
        if (j < RR_WHEEL_NVALUES) {
            wheel_var((int)side, (int)j, v);
            return RR_OK;
        }
        return RR_ERR_PARAM;
    }
    if (vr >= RR_FMU_VR_PARAM && vr < RR_FMU_VR_PARAM + (unsigned)rr_rig_param_count()) {
        const int r = (int)(vr - RR_FMU_VR_PARAM);
        const rr_rig_param *row = rr_rig_param_at(r);
        if (row->type == RR_RIG_LIST)
            return RR_ERR_PARAM;
        param_var(row, r, 0, v);
        return RR_OK;
    }
    if (vr >= RR_FMU_VR_LIST) {
        const unsigned r = (vr - RR_FMU_VR_LIST) / RR_FMU_VR_LIST_ROW;
        const unsigned e = (vr - RR_FMU_VR_LIST) % RR_FMU_VR_LIST_ROW;
        const rr_rig_param *row = r < (unsigned)rr_rig_param_count()
                                ? rr_rig_param_at((int)r) : NULL;
        if (row && row->type == RR_RIG_LIST && e < (unsigned)list_len(start, row)) {
            param_var(row, (int)r, (int)e, v);
            return RR_OK;
        }
    }
    return RR_ERR_PARAM;
}

int rr_fmu_var_name(const rr_fmu_var *v, char *buf, size_t len)
{
    if (!v || !buf || len == 0)
        return RR_ERR_NULL;
    if (v->entry >= 0)
        return snprintf(buf, len, "%s%s[%d]", v->prefix, v->base, v->entry + 1);
    return snprintf(buf, len, "%s%s", v->prefix, v->base);
}

int rr_fmu_var_item(const rr_fmu_var *v, int i, const char **name, int *value)
{
    const char *const *choices = NULL;
    const rr_creep_option *op;
    int k, n = -1;
    if (!v || !name || !value || v->type != RR_FMU_ENUMERATION || i < 0)
        return 0;
    if (v->kind == K_CONTROL) {
        choices = controls[v->index].choices;
    } else if (v->kind == K_PARAM) {
        choices = v->row->choices;
    } else if (v->kind == K_CREEP) {
        if ((op = creep_option(v->row)) != NULL) {
            choices = op->choices;
        } else {
            /* the registry's methods the rig can step with, by their numbers */
            for (k = 0; k < rr_method_count(); k++)
                if (method_usable(k) && ++n == i) {
                    *name = rr_method_get(k)->name;
                    *value = k;
                    return 1;
                }
            return 0;
        }
    }
    if (!choices || i >= nchoices(choices))
        return 0;
    *name = choices[i];
    *value = i;
    return 1;
}

/* The present value of a parameter or input variable from cfg and in. */
static double param_value(const rr_fmu_config *f, const double *in, const rr_fmu_var *v)
{
    switch (v->kind) {
    case K_PARAM:
        return row_load(&f->c, v->row);
    case K_LIST:
        return list_of(&f->c, v->row)->v[v->entry];
    case K_CREEP:
        return f->creep[creep_slot(v->row)];
    case K_CONTROL:
        return f->control[v->index];
    case K_INPUT:
        return in ? in[v->index] : NAN;
    default:
        return NAN;
    }
}

/* The inputs' start values of a start configuration. */
static void input_starts(const rr_fmu_config *f, double *in)
{
    const rr_rig_config *c = &f->c;
    in[RR_FMU_IN_ROLLER_SPEED] = c->roller_speed / c->roller_radius;
    in[RR_FMU_IN_ROLLER_TORQUE] = 0.0;
    in[RR_FMU_IN_CREEPAGE] = c->targets.n > 0 ? c->targets.v[0] : NAN;
    in[RR_FMU_IN_WHEELSET_SPEED] = c->roller_speed / c->wheel_radius;
    in[RR_FMU_IN_WHEELSET_TORQUE] = 0.0;
    in[RR_FMU_IN_MU] = c->mu0;
}

int rr_fmu_var_start(const rr_fmu_config *start, const rr_fmu_var *v, double *x)
{
    double in[RR_FMU_NINPUT];
    if (!start || !v || !x)
        return RR_ERR_NULL;
    if (v->causality != RR_FMU_PARAMETER && v->causality != RR_FMU_INPUT) {
        *x = NAN;
        return RR_ERR_PARAM;
    }
    input_starts(start, in);
    *x = param_value(start, in, v);
    return RR_OK;
}

/* ------------------------------------------------------------------ checks with messages */

static void range_text(const rr_fmu_var *v, char *buf, size_t len)
{
    char lo[32], hi[32];
    rr_fmu_format_number(v->lo, lo, sizeof lo);
    rr_fmu_format_number(v->hi, hi, sizeof hi);
    snprintf(buf, len, "%s%s, %s%s", v->lo_open || isinf(v->lo) ? "(" : "[", lo, hi,
             v->hi_open || isinf(v->hi) ? ")" : "]");
}

/* 0 if x is a value of v, else the status with the message. */
static int check_value(rr_fmu *m, const rr_fmu_var *v, double x)
{
    char name[RR_FMU_NAME_LEN], num[32], range[80];
    const char *item;
    int i, value, in_range;
    rr_fmu_var_name(v, name, sizeof name);
    rr_fmu_format_number(x, num, sizeof num);
    switch (v->type) {
    case RR_FMU_BOOLEAN:
        return RR_OK;
    case RR_FMU_ENUMERATION:
        for (i = 0; rr_fmu_var_item(v, i, &item, &value); i++)
            if (x == value)
                return RR_OK;
        {
            char items[256];
            size_t n = 0;
            items[0] = '\0';
            for (i = 0; rr_fmu_var_item(v, i, &item, &value) && n < sizeof items; i++)
                n += (size_t)snprintf(items + n, sizeof items - n, "%s%d (%s)", i ? ", " : "",
                                      value, item);
            return fail(m, RR_ERR_PARAM, "%s = %s is not one of its values: %s", name, num,
                        items);
        }
    default:
        break;
    }
    if (!isfinite(x))
        return fail(m, RR_ERR_NONFINITE, "%s = %s: the value must be a finite number", name,
                    num);
    in_range = (v->lo_open ? x > v->lo : x >= v->lo) && (v->hi_open ? x < v->hi : x <= v->hi);
    if (v->type == RR_FMU_INTEGER && x != floor(x))
        in_range = 0;
    if (!in_range) {
        range_text(v, range, sizeof range);
        return fail(m, RR_ERR_PARAM, "%s = %s is out of range: it must be %s in %s%s%s", name,
                    num, v->type == RR_FMU_INTEGER ? "an integer" : "a number", range,
                    v->unit[0] && strcmp(v->unit, "-") != 0 ? " " : "",
                    strcmp(v->unit, "-") != 0 ? v->unit : "");
    }
    return RR_OK;
}

/* ------------------------------------------------------------------ the unit */

int rr_fmu_init(rr_fmu *m, const rr_fmu_config *start, rr_fmu_alloc alloc, rr_fmu_free release,
                void *ctx, const char *const *type_names)
{
    if (!m || !start || !alloc || !release)
        return RR_ERR_NULL;
    memset(m, 0, sizeof *m);
    m->start = *start;
    m->alloc = alloc;
    m->release = release;
    m->mem_ctx = ctx;
    m->type_names = type_names ? type_names : default_type_names;
    return rr_fmu_reset(m);
}

void rr_fmu_release(rr_fmu *m)
{
    if (!m)
        return;
    if (m->table_data)
        m->release(m->mem_ctx, m->table_data);
    m->table_data = NULL;
    m->table_cap = 0;
    m->table_ok = 0;
    m->s.ready = 0;
}

const char *rr_fmu_message(const rr_fmu *m)
{
    return m ? m->msg : "";
}

int rr_fmu_reset(rr_fmu *m)
{
    rr_fmu_state *s;
    if (!m)
        return RR_ERR_NULL;
    s = &m->s;
    memset(s, 0, sizeof *s);
    s->cfg = m->start;
    input_starts(&m->start, s->in);
    s->mode = RR_FMU_INSTANTIATED;
    m->msg[0] = '\0';
    return RR_OK;
}

static const char *mode_name(int mode)
{
    return mode >= 0 && mode <= RR_FMU_FAILED ? mode_names[mode] : "unknown";
}

static int wrong_mode(rr_fmu *m, const char *what, const char *need)
{
    if (m->s.mode == RR_FMU_FAILED)
        return fail(m, RR_ERR_SEQUENCE, "%s: the unit failed (%s) and cannot go on: reset "
                    "it, or set an FMU state saved before", what,
                    rr_status_message(m->s.failed_status));
    return fail(m, RR_ERR_SEQUENCE, "%s: not allowed when the unit is %s (it must be %s)", what,
                mode_name(m->s.mode), need);
}

/* The contact table of the configuration's geometry, built if it is not
 * the one held (allocating its rows). */
static int table_for(rr_fmu *m, const rr_rig_config *c)
{
    rr_rig_geometry g;
    long len;
    double bad_y = NAN;
    int st;
    rr_rig_geometry_from(c, &g);
    if (m->table_ok && memcmp(&g, &m->g, sizeof g) == 0)
        return RR_OK;
    m->table_ok = 0;
    len = rr_rig_table_data_len(&g);
    if (len <= 0)
        return fail(m, RR_ERR_PARAM, "the contact table: integration.table_rows = %d is out "
                    "of range", g.table_rows);
    if (len > m->table_cap) {
        double *data = m->alloc(m->mem_ctx, (size_t)len * sizeof *data);
        if (!data)
            return fail(m, RR_ERR_WORKSPACE, "the contact table: out of memory (%ld doubles)",
                        len);
        if (m->table_data)
            m->release(m->mem_ctx, m->table_data);
        m->table_data = data;
        m->table_cap = len;
    }
    st = rr_rig_table_build(&g, m->table_data, m->table_cap, m->table_work,
                            RR_RIG_TABLE_WORK_LEN, &m->table, &bad_y);
    if (st < 0) {
        char y[32];
        rr_fmu_format_number(bad_y, y, sizeof y);
        return fail(m, st, "the rig's geometry (wheelset.wheel_radius_m, roller.radius_m, "
                    "wheelset.profile_half_width_m, wheelset.conicity, roller.crown_radius_m, "
                    "wheelset.contact_half_spacing_m, integration.table_half_range_m, "
                    "integration.table_rows) gives no contact table%s%s: %s",
                    isnan(bad_y) ? "" : " at y_ws = ", isnan(bad_y) ? "" : y,
                    rr_status_message(st));
    }
    m->g = g;
    m->table_ok = 1;
    return RR_OK;
}

/* The refusal of a sample time at which a drive's speed loop is unstable:
 * which drive, and the sample times at which it is stable. */
static int loop_fail(rr_fmu *m, const rr_rig_config *c, int st)
{
    static const char *const drive[2] = {"roller", "wheelset"};
    rr_speed_loop loops[2];
    double lo, hi;
    char T[32];
    int k = 0;
    rr_rig_config_speed_loops(c, loops);
    while (k < 1 && rr_speed_loop_check(&loops[k]) != RR_ERR_PARAM)
        k++;
    rr_fmu_format_number(c->T, T, sizeof T);
    if (rr_speed_loop_range(&loops[k], RR_RIG_MIN_T, RR_RIG_MAX_T, &lo, &hi) != RR_OK)
        return fail(m, st, "scenario.control_sample_time_s = %s s: the %s drive's sampled speed "
                    "loop (its PI gains on its inertia through its lag) is stable at no sample "
                    "time from %g to %g s", T, drive[k], RR_RIG_MIN_T, RR_RIG_MAX_T);
    return fail(m, st, "scenario.control_sample_time_s = %s s: the %s drive's sampled speed "
                "loop (its PI gains on its inertia through its lag) is unstable at this "
                "sample time; it is stable from %.3g to %.3g s", T, drive[k], lo, hi);
}

/* The rig's parameters of the configuration, into *p (its table m's). */
static int derive(rr_fmu *m, const rr_fmu_config *f, rr_rig_params *p)
{
    const char *bad = NULL;
    rr_creep_opts o;
    int st;
    if ((st = rr_rig_config_check(&f->c, &bad)) < 0) {
        if (st == RR_ERR_PARAM && bad && strcmp(bad, "scenario.control_sample_time_s") == 0)
            return loop_fail(m, &f->c, st);
        return fail(m, st, "the parameters do not hold together: %s: %s", bad ? bad : "?",
                    rr_status_message(st));
    }
    if ((st = rr_fmu_creep_opts(f, &o, &bad)) < 0)
        return fail(m, st, "the creep-force method: %s: %s", bad ? bad : "?",
                    rr_status_message(st));
    if (rr_method_get(o.method)->coulomb_only
        && strcmp(rr_rig_param_find("contact.friction_law")->choices[f->c.friction_law],
                  "coulomb") != 0)
        return fail(m, RR_ERR_FRICTION, "contact.creep_method = %s is built for Coulomb "
                    "friction; the parameters' contact.friction_law is %s (set it to "
                    "coulomb)", rr_method_get(o.method)->name,
                    rr_rig_param_find("contact.friction_law")->choices[f->c.friction_law]);
    if ((st = table_for(m, &f->c)) < 0)
        return st;
    if ((st = rr_rig_params_from(&f->c, &m->table, p)) < 0)
        return fail(m, st, "the rig's parameters: %s", rr_status_message(st));
    p->contact.creep = o;
    if ((st = rr_rig_check(p)) < 0)
        return fail(m, st, "the rig's parameters: %s", rr_status_message(st));
    return RR_OK;
}

/* The rig built from the parameters, at the start: its record and the
 * encoders' first reading. */
static int build(rr_fmu *m)
{
    rr_fmu_state *s = &m->s;
    const rr_rig_config *c = &s->cfg.c;
    int st;
    if (s->ready)
        return RR_OK;
    if ((st = derive(m, &s->cfg, &s->p)) < 0)
        return st;
    st = rr_rig_init(&s->p, s->cfg.control[RR_FMU_START] == RR_FMU_START_REST
                                ? 0.0 : c->roller_speed / c->roller_radius, &s->rig);
    if (st < 0)
        return fail(m, st, "the rig cannot start: %s", rr_status_message(st));
    s->k = 0;
    s->retune = 0;
    st = rr_rig_record(&s->rig, s->rec);
    if (st >= 0)
        st = rr_rig_read(&s->rig, &s->sig);
    if (st < 0)
        return fail(m, st, "the rig cannot start: %s", rr_status_message(st));
    s->ready = 1;
    return RR_OK;
}

int rr_fmu_enter_init(rr_fmu *m, double t0)
{
    char num[32];
    if (!m)
        return RR_ERR_NULL;
    m->msg[0] = '\0';
    if (m->s.mode != RR_FMU_INSTANTIATED)
        return wrong_mode(m, "entering initialization mode", "instantiated");
    if (!isfinite(t0)) {
        rr_fmu_format_number(t0, num, sizeof num);
        return fail(m, RR_ERR_NONFINITE, "the start time must be finite, got %s", num);
    }
    m->s.t0 = t0;
    m->s.mode = RR_FMU_INITIALIZATION;
    return RR_OK;
}

int rr_fmu_exit_init(rr_fmu *m)
{
    int st;
    if (!m)
        return RR_ERR_NULL;
    m->msg[0] = '\0';
    if (m->s.mode != RR_FMU_INITIALIZATION)
        return wrong_mode(m, "exiting initialization mode", "in initialization mode");
    if ((st = build(m)) < 0)
        return st;
    m->s.mode = RR_FMU_STEPPING;
    return RR_OK;
}

int rr_fmu_terminate(rr_fmu *m)
{
    if (!m)
        return RR_ERR_NULL;
    m->msg[0] = '\0';
    if (m->s.mode != RR_FMU_STEPPING && m->s.mode != RR_FMU_INITIALIZATION
        && m->s.mode != RR_FMU_FAILED)
        return wrong_mode(m, "terminating", "initialised");
    m->s.mode = RR_FMU_TERMINATED;
    return RR_OK;
}

double rr_fmu_time(const rr_fmu *m)
{
    if (!m)
        return NAN;
    return m->s.t0 + (m->s.ready ? m->s.rig.t : 0.0);
}

/* The tunable parameters changed: the rig's parameters derived again. */
static int retune(rr_fmu *m)
{
    rr_rig_params p;
    int st;
    if ((st = derive(m, &m->s.cfg, &p)) < 0)
        return st;
    /* tried on the copy first: on error the unit keeps its parameters */
    if ((st = rr_rig_rebind(&m->s.rig, &p)) < 0)
        return st;
    m->s.p = p;
    st = rr_rig_rebind(&m->s.rig, &m->s.p);
    m->s.retune = 0;
    return st;
}

/* The command of sample k from the control modes and the inputs; *which
 * names the input a refused command came from. */
static void command(const rr_fmu_state *s, rr_rig_command *cmd, const char **which)
{
    double roller_ref = NAN, xi_ref = NAN;
    if (s->cfg.control[RR_FMU_ROLLER_MODE] == RR_FMU_ROLLER_SCENARIO
        || s->cfg.control[RR_FMU_WHEELSET_MODE] == RR_FMU_WHEELSET_SCENARIO)
        rr_rig_schedule(&s->cfg.c, s->k, &roller_ref, &xi_ref);
    switch (s->cfg.control[RR_FMU_ROLLER_MODE]) {
    case RR_FMU_ROLLER_SPEED:
        cmd->roller_mode = RR_CMD_SPEED;
        cmd->roller_ref = s->in[RR_FMU_IN_ROLLER_SPEED];
        which[0] = inputs[RR_FMU_IN_ROLLER_SPEED].name;
        break;
    case RR_FMU_ROLLER_TORQUE:
        cmd->roller_mode = RR_CMD_TORQUE;
        cmd->roller_ref = s->in[RR_FMU_IN_ROLLER_TORQUE];
        which[0] = inputs[RR_FMU_IN_ROLLER_TORQUE].name;
        break;
    default:
        cmd->roller_mode = RR_CMD_BUILTIN;
        cmd->roller_ref = roller_ref;
        which[0] = "the scenario's roller speed";
    }
    switch (s->cfg.control[RR_FMU_WHEELSET_MODE]) {
    case RR_FMU_WHEELSET_CREEPAGE:
        cmd->wheelset_mode = RR_CMD_BUILTIN;
        cmd->wheelset_ref = s->in[RR_FMU_IN_CREEPAGE];
        which[1] = inputs[RR_FMU_IN_CREEPAGE].name;
        break;
    case RR_FMU_WHEELSET_SPEED:
        cmd->wheelset_mode = RR_CMD_SPEED;
        cmd->wheelset_ref = s->in[RR_FMU_IN_WHEELSET_SPEED];
        which[1] = inputs[RR_FMU_IN_WHEELSET_SPEED].name;
        break;
    case RR_FMU_WHEELSET_TORQUE:
        cmd->wheelset_mode = RR_CMD_TORQUE;
        cmd->wheelset_ref = s->in[RR_FMU_IN_WHEELSET_TORQUE];
        which[1] = inputs[RR_FMU_IN_WHEELSET_TORQUE].name;
        break;
    case RR_FMU_WHEELSET_FREE:
        cmd->wheelset_mode = RR_CMD_BUILTIN;
        cmd->wheelset_ref = NAN;            /* rr_rig_write's "no target" */
        which[1] = "free rolling";
        break;
    default:
        cmd->wheelset_mode = RR_CMD_BUILTIN;
        cmd->wheelset_ref = xi_ref;
        which[1] = "the scenario's creepage target";
    }
    if (s->cfg.control[RR_FMU_MU_SOURCE] == RR_FMU_MU_INPUT) {
        cmd->mu0 = s->in[RR_FMU_IN_MU];
        which[2] = inputs[RR_FMU_IN_MU].name;
    } else {
        cmd->mu0 = NAN;
        which[2] = "the adhesion";
    }
}

int rr_fmu_do_step(rr_fmu *m, double t, double h)
{
    rr_fmu_state *s;
    double T, n_real, now;
    long n, i;
    int st, worst = RR_OK, warned = 0;
    char a[32], b[32];

    if (!m)
        return RR_ERR_NULL;
    s = &m->s;
    m->msg[0] = '\0';
    if (s->mode != RR_FMU_STEPPING)
        return wrong_mode(m, "doStep", "stepping (after the initialization)");
    T = s->p.T;
    n_real = floor(h / T + 0.5);
    now = s->t0 + (double)s->k * T;
    /* the step: a whole number of samples, but for the rounding of a
     * master's difference of two times */
    if (!(h > 0.0) || !isfinite(h) || n_real < 1.0 || n_real > 1e15
        || fabs(h - n_real * T) > 1e-6 * T + 4.0 * DBL_EPSILON * (fabs(now) + h)) {
        rr_fmu_format_number(h, a, sizeof a);
        rr_fmu_format_number(T, b, sizeof b);
        return fail(m, RR_ERR_PARAM, "the communication step %s s is not a whole "
                    "multiple of the control sample time %s s "
                    "(scenario.control_sample_time_s): the rig steps by whole samples", a, b);
    }
    /* the time: the unit's, within a thousandth of a sample (a master that
     * adds up its steps drifts from k T by rounding; a skipped or repeated
     * step is a whole sample off) */
    if (!(fabs(t - now) <= 1e-3 * T)) {
        rr_fmu_format_number(t, a, sizeof a);
        rr_fmu_format_number(now, b, sizeof b);
        return fail(m, RR_ERR_PARAM, "currentCommunicationPoint %s s is not the "
                    "unit's time %s s (the start time plus %ld samples)", a, b, s->k);
    }
    if (s->retune && (st = retune(m)) < 0)
        return st;
    n = (long)n_real;
    for (i = 0; i < n; i++) {
        rr_rig_command cmd;
        const char *which[3];
        command(s, &cmd, which);
        if ((st = rr_rig_write(&s->rig, &cmd)) < 0) {
            char r0[32], r1[32], mu[32];
            rr_fmu_format_number(cmd.roller_ref, r0, sizeof r0);
            rr_fmu_format_number(cmd.wheelset_ref, r1, sizeof r1);
            rr_fmu_format_number(cmd.mu0, mu, sizeof mu);
            rr_fmu_format_number(s->rig.t + s->t0, a, sizeof a);
            fail(m, st, "sample %ld (t = %s s): the rig refused the command (roller: "
                 "%s = %s; wheelset: %s = %s; mu0: %s = %s): %s", s->k, a, which[0], r0,
                 which[1], r1, which[2], mu, rr_status_message(st));
            if (i > 0) {
                s->mode = RR_FMU_FAILED;
                s->failed_status = st;
            }
            return st;
        }
        st = rr_rig_advance(&s->rig, s->rec);
        if (st >= 0) {
            s->k++;
            if (st > 0) {
                warned++;
                if (st > worst)
                    worst = st;
            }
            st = rr_rig_read(&s->rig, &s->sig);
        }
        if (st < 0) {
            rr_fmu_format_number(s->rig.t + s->t0, a, sizeof a);
            s->mode = RR_FMU_FAILED;
            s->failed_status = st;
            return fail(m, st, "sample %ld (t = %s s) failed: %s; the unit stops "
                        "there (its outputs are that sample's start)", s->k, a,
                        rr_status_message(st));
        }
    }
    if (worst > 0)
        return fail(m, worst, "%d of %ld samples warned: %s", warned, n,
                    rr_status_message(worst));
    return RR_OK;
}

/* ------------------------------------------------------------------ get and set */

static int lookup(rr_fmu *m, int type, unsigned vr, rr_fmu_var *v)
{
    char name[RR_FMU_NAME_LEN];
    if (rr_fmu_var_find(&m->start, vr, v) != RR_OK)
        return fail(m, RR_ERR_PARAM, "unknown value reference %u (no variable has it)", vr);
    if (v->type != type) {
        rr_fmu_var_name(v, name, sizeof name);
        return fail(m, RR_ERR_PARAM, "%s (value reference %u) is of type %s, not %s: use "
                    "the %s functions", name, vr, m->type_names[v->type],
                    m->type_names[type < 0 || type > 3 ? 0 : type], m->type_names[v->type]);
    }
    return RR_OK;
}

int rr_fmu_get(rr_fmu *m, int type, unsigned vr, double *x)
{
    rr_fmu_state *s;
    rr_fmu_var v;
    int st;
    if (!m || !x)
        return RR_ERR_NULL;
    s = &m->s;
    /* the record's real outputs, read at every step by a master: straight */
    if (type == RR_FMU_REAL && vr > RR_FMU_VR_RECORD && vr < RR_FMU_VR_RECORD + RR_REC_STATUS
        && s->ready && s->mode != RR_FMU_INSTANTIATED) {
        *x = s->rec[vr - RR_FMU_VR_RECORD];
        return RR_OK;
    }
    *x = NAN;
    if ((st = lookup(m, type, vr, &v)) < 0)
        return st;
    if (v.causality == RR_FMU_PARAMETER || v.causality == RR_FMU_INPUT) {
        *x = param_value(&s->cfg, s->in, &v);
        return RR_OK;
    }
    if (s->mode == RR_FMU_INSTANTIATED) {
        char name[RR_FMU_NAME_LEN];
        rr_fmu_var_name(&v, name, sizeof name);
        return fail(m, RR_ERR_SEQUENCE, "%s: the %s is known from the initialization mode on",
                    name, v.causality == RR_FMU_OUTPUT ? "output" : "time");
    }
    if (!s->ready && (st = build(m)) < 0)
        return st;
    switch (v.kind) {
    case K_TIME:
        *x = s->t0 + s->rig.t;
        break;
    case K_RECORD:
        *x = s->rec[v.index];
        break;
    case K_ENCODER:
        *x = *(const double *)(const void *)((const char *)&s->sig + encoders[v.index].offset);
        break;
    case K_WHEEL: {
        int comp;
        const rr_rig_field *f = wheel_value(v.index % RR_WHEEL_NVALUES, &comp);
        const rr_wheel_contact *w = &s->rig.w[v.index / RR_WHEEL_NVALUES];
        *x = ((const double *)(const void *)((const char *)w + f->offset))[comp < 0 ? 0 : comp];
        break;
    }
    default:
        break;
    }
    return RR_OK;
}

int rr_fmu_set(rr_fmu *m, int type, unsigned vr, double x)
{
    rr_fmu_state *s;
    rr_fmu_var v;
    char name[RR_FMU_NAME_LEN];
    int st;
    if (!m)
        return RR_ERR_NULL;
    s = &m->s;
    if ((st = lookup(m, type, vr, &v)) < 0)
        return st;
    rr_fmu_var_name(&v, name, sizeof name);
    if (v.causality != RR_FMU_PARAMETER && v.causality != RR_FMU_INPUT)
        return fail(m, RR_ERR_PARAM, "%s (value reference %u) is an %s: it cannot be set",
                    name, vr, causality_names[v.causality]);
    if (s->mode == RR_FMU_TERMINATED || s->mode == RR_FMU_FAILED)
        return wrong_mode(m, name, "instantiated, initialised or stepping");
    if (s->mode == RR_FMU_STEPPING && v.causality == RR_FMU_PARAMETER
        && v.variability == RR_FMU_FIXED)
        return fail(m, RR_ERR_SEQUENCE, "%s is a fixed parameter: set it before the "
                    "initialization ends (or after a reset)", name);
    if ((st = check_value(m, &v, x)) < 0)
        return st;
    switch (v.kind) {
    case K_PARAM:
        st = rr_rig_config_set(&s->cfg.c, v.row->name, x);
        break;
    case K_LIST: {
        rr_rig_list l = *list_of(&s->cfg.c, v.row);
        l.v[v.entry] = x;
        st = rr_rig_config_set_list(&s->cfg.c, v.row->name, l.n, l.v);
        break;
    }
    case K_CREEP:
        if ((st = creep_value_ok(v.row, x)) == RR_OK)
            s->cfg.creep[creep_slot(v.row)] = x;
        break;
    case K_CONTROL:
        s->cfg.control[v.index] = (int)x;
        break;
    case K_INPUT:
        s->in[v.index] = x;
        return RR_OK;
    default:
        break;
    }
    if (st < 0) {
        char num[32];
        rr_fmu_format_number(x, num, sizeof num);
        return fail(m, st, "%s = %s: %s", name, num, rr_status_message(st));
    }
    if (v.kind == K_CONTROL && v.index != RR_FMU_START)
        return RR_OK;               /* read at each sample */
    if (s->mode == RR_FMU_STEPPING)
        s->retune = 1;
    else
        s->ready = 0;
    return RR_OK;
}

/* ------------------------------------------------------------------ FMU states */

int rr_fmu_save(const rr_fmu *m, rr_fmu_state *st)
{
    if (!m || !st)
        return RR_ERR_NULL;
    *st = m->s;
    return RR_OK;
}

int rr_fmu_restore(rr_fmu *m, const rr_fmu_state *st)
{
    int status;
    if (!m || !st)
        return RR_ERR_NULL;
    m->msg[0] = '\0';
    if (st->mode < RR_FMU_INSTANTIATED || st->mode > RR_FMU_FAILED)
        return fail(m, RR_ERR_PARAM, "set FMU state: not a state of this unit");
    if (st->ready) {
        /* the pointers of the copy are remade: the rig's parameters, their
         * table (this unit's, of the state's geometry) and the
         * integrator's model function (this process's) */
        if ((status = table_for(m, &st->cfg.c)) < 0)
            return status;
    }
    m->s = *st;
    if (m->s.ready) {
        m->s.p.contact.table = &m->table;
        if ((status = rr_rig_rebind(&m->s.rig, &m->s.p)) < 0)
            return fail(m, status, "set FMU state: the state's rig cannot go on: %s",
                        rr_status_message(status));
    } else {
        m->s.p.contact.table = NULL;
        m->s.rig.p = NULL;
        m->s.rig.ode.model = NULL;
    }
    return RR_OK;
}
