/*
 * rr_fmu.c - the roller rig as a co-simulation unit (rr_fmu.h), its first
 * half: the variables and the configuration.  The tables of the control
 * parameters, inputs and encoder outputs; the configuration (defaults,
 * setting a parameter by name, the creep-force method of the creep rows);
 * the variables in their order and by value reference, with their names,
 * items and start values; and what the unit reads and writes through them
 * (rr_fmu.h's "Not API" block).  The unit itself, its life, steps, get and
 * set and states, is rr_fmu_unit.c.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_creep.h"
#include "rig/rr_rig_params.h"
#include "fmu/rr_fmu.h"

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

#define COUNT(a) RR_COUNTOF(a)

RR_STATIC_ASSERT(COUNT(controls) == RR_FMU_NCONTROL, one_control_each);
RR_STATIC_ASSERT(COUNT(inputs) == RR_FMU_NINPUT, one_input_each);
RR_STATIC_ASSERT(COUNT(encoders) == RR_FMU_NENCODER, one_encoder_each);

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
        var_clear(v, RR_FMU_VR_LIST + RR_FMU_VR_LIST_ROW * (unsigned)r + (unsigned)e,
                  RR_FMU_K_LIST, r);
        v->entry = e;
    } else {
        var_clear(v, RR_FMU_VR_PARAM + (unsigned)r,
                  row->creep ? RR_FMU_K_CREEP : RR_FMU_K_PARAM, r);
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
    var_clear(v, RR_FMU_VR_CONTROL + (unsigned)i, RR_FMU_K_CONTROL, i);
    v->base = controls[i].name;
    v->description = controls[i].description;
    v->type = RR_FMU_ENUMERATION;
    v->causality = RR_FMU_PARAMETER;
    v->variability = controls[i].variability;
}

static void input_var(int i, rr_fmu_var *v)
{
    var_clear(v, RR_FMU_VR_INPUT + (unsigned)i, RR_FMU_K_INPUT, i);
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
    output_var(RR_FMU_VR_RECORD + (unsigned)i, RR_FMU_K_RECORD, i, rr_rig_record_field(i), v);
    if (i == RR_REC_STATUS) {
        v->type = RR_FMU_INTEGER;
        v->variability = RR_FMU_DISCRETE;
    }
}

static void wheel_var(int side, int j, rr_fmu_var *v)
{
    int comp;
    const rr_rig_field *f = wheel_value(j, &comp);
    output_var(RR_FMU_VR_WHEEL + RR_FMU_VR_WHEEL_SIDE * (unsigned)side + (unsigned)j,
               RR_FMU_K_WHEEL, side * RR_WHEEL_NVALUES + j, f, v);
    v->prefix = side ? "right." : "left.";
    v->entry = comp;
}

static void time_var(rr_fmu_var *v)
{
    var_clear(v, RR_FMU_VR_TIME, RR_FMU_K_TIME, 0);
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
        output_var(RR_FMU_VR_ENCODER + (unsigned)i, RR_FMU_K_ENCODER, i, &encoders[i], v);
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
        output_var(vr, RR_FMU_K_ENCODER, i, &encoders[i], v);
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
    if (v->kind == RR_FMU_K_CONTROL) {
        choices = controls[v->index].choices;
    } else if (v->kind == RR_FMU_K_PARAM) {
        choices = v->row->choices;
    } else if (v->kind == RR_FMU_K_CREEP) {
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

double rr_fmu_value(const rr_fmu_config *f, const double *in, const rr_fmu_var *v)
{
    switch (v->kind) {
    case RR_FMU_K_PARAM:
        return row_load(&f->c, v->row);
    case RR_FMU_K_LIST:
        return list_of(&f->c, v->row)->v[v->entry];
    case RR_FMU_K_CREEP:
        return f->creep[creep_slot(v->row)];
    case RR_FMU_K_CONTROL:
        return f->control[v->index];
    case RR_FMU_K_INPUT:
        return in ? in[v->index] : NAN;
    default:
        return NAN;
    }
}

void rr_fmu_input_starts(const rr_fmu_config *f, double *in)
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
    rr_fmu_input_starts(start, in);
    *x = rr_fmu_value(start, in, v);
    return RR_OK;
}

/* ------------------------------------------------------------------ for the unit */

const char *rr_fmu_input_name(int i)
{
    return i >= 0 && i < RR_FMU_NINPUT ? inputs[i].name : "";
}

double rr_fmu_output(const rr_fmu_state *s, const rr_fmu_var *v)
{
    switch (v->kind) {
    case RR_FMU_K_TIME:
        return s->t0 + s->rig.t;
    case RR_FMU_K_RECORD:
        return s->rec[v->index];
    case RR_FMU_K_ENCODER:
        return *(const double *)(const void *)((const char *)&s->sig
                                               + encoders[v->index].offset);
    case RR_FMU_K_WHEEL: {
        int comp;
        const rr_rig_field *f = wheel_value(v->index % RR_WHEEL_NVALUES, &comp);
        const rr_wheel_contact *w = &s->rig.w[v->index / RR_WHEEL_NVALUES];
        return ((const double *)(const void *)((const char *)w + f->offset))[comp < 0 ? 0
                                                                                    : comp];
    }
    default:
        return NAN;
    }
}

int rr_fmu_store(rr_fmu_config *f, double *in, const rr_fmu_var *v, double x)
{
    int st = RR_OK;
    switch (v->kind) {
    case RR_FMU_K_PARAM:
        st = rr_rig_config_set(&f->c, v->row->name, x);
        break;
    case RR_FMU_K_LIST: {
        rr_rig_list l = *list_of(&f->c, v->row);
        l.v[v->entry] = x;
        st = rr_rig_config_set_list(&f->c, v->row->name, l.n, l.v);
        break;
    }
    case RR_FMU_K_CREEP:
        if ((st = creep_value_ok(v->row, x)) == RR_OK)
            f->creep[creep_slot(v->row)] = x;
        break;
    case RR_FMU_K_CONTROL:
        f->control[v->index] = (int)x;
        break;
    case RR_FMU_K_INPUT:
        in[v->index] = x;
        break;
    default:
        break;
    }
    return st;
}
