/* test_fmu.c - the rig's co-simulation unit without FMI (csrc/fmu/rr_fmu.h,
 * rr_fmu_xml.h): its variables from the rig's declarations, get and set with
 * range checks and messages, its life, a default run bitwise as the rig's own
 * step (rig_paper.c's run), steps over several samples, the inputs and
 * control modes, FMU states, two instances, the XML. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rr_test.h"
#include "rollerrig.h"
#include "fmu/rr_fmu.h"
#include "fmu/rr_fmu_xml.h"

static int allocations = 0;

static void *test_alloc(void *ctx, size_t n)
{
    (void)ctx;
    allocations++;
    return malloc(n);
}

static void test_free(void *ctx, void *p)
{
    (void)ctx;
    allocations--;
    free(p);
}

static int same_bits(const double *a, const double *b, int n)
{
    return memcmp(a, b, (size_t)n * sizeof *a) == 0;
}

static int contains(const char *text, const char *part)
{
    return text && part && strstr(text, part) != NULL;
}

/* a unit at the defaults, initialised */
static int start_unit(rr_fmu *m, const rr_fmu_config *f)
{
    int st = rr_fmu_init(m, f, test_alloc, test_free, NULL, NULL);
    if (st == RR_OK)
        st = rr_fmu_enter_init(m, 0.0);
    if (st == RR_OK)
        st = rr_fmu_exit_init(m);
    return st;
}

/* the record of the unit's present time, RR_REC_COUNT doubles (time from the rig) */
static void unit_record(rr_fmu *m, double *rec)
{
    int i;
    rec[0] = m->s.rig.t;
    for (i = 1; i < RR_REC_COUNT; i++)
        rr_fmu_get(m, i == RR_REC_STATUS ? RR_FMU_INTEGER : RR_FMU_REAL,
                   RR_FMU_VR_RECORD + (unsigned)i, &rec[i]);
}

static unsigned vr_of(const rr_fmu_config *f, const char *name)
{
    int i, n = rr_fmu_var_count(f);
    for (i = 0; i < n; i++) {
        rr_fmu_var v;
        char buf[RR_FMU_NAME_LEN];
        rr_fmu_var_at(f, i, &v);
        rr_fmu_var_name(&v, buf, sizeof buf);
        if (strcmp(buf, name) == 0)
            return v.vr;
    }
    return 999999u;
}

static void test_variables(const rr_fmu_config *f)
{
    rr_rig_config c;
    int i, j, n = rr_fmu_var_count(f), nparam = 0, nout = 0;
    static char names[1000][RR_FMU_NAME_LEN];
    static unsigned vrs[1000];

    rr_rig_config_default(&c);
    CHECK(memcmp(&c, &f->c, sizeof c) == 0, "the rig's defaults");
    CHECK(f->creep[0] == rr_method_find("fastsim"), "creep method fastsim");
    CHECK(n > 150 && n < 1000, "variable count");
    for (i = 0; i < n; i++) {
        rr_fmu_var v, w;
        double x;
        CHECK_STATUS(rr_fmu_var_at(f, i, &v), RR_OK, "var_at");
        rr_fmu_var_name(&v, names[i], sizeof names[i]);
        vrs[i] = v.vr;
        CHECK_STATUS(rr_fmu_var_find(f, v.vr, &w), RR_OK, names[i]);
        CHECK(w.kind == v.kind && w.entry == v.entry && strcmp(w.base, v.base) == 0
              && w.type == v.type && w.variability == v.variability, names[i]);
        for (j = 0; j < i; j++) {
            if (strcmp(names[i], names[j]) == 0 || vrs[i] == vrs[j]) {
                CHECK(0, names[i]);
                break;
            }
        }
        nparam += v.causality == RR_FMU_PARAMETER;
        nout += v.causality == RR_FMU_OUTPUT;
        if (v.causality == RR_FMU_PARAMETER || v.causality == RR_FMU_INPUT) {
            CHECK_STATUS(rr_fmu_var_start(f, &v, &x), RR_OK, names[i]);
            CHECK(v.type != RR_FMU_REAL || isfinite(x), names[i]);
        } else {
            CHECK_STATUS(rr_fmu_var_start(f, &v, &x), RR_ERR_PARAM, names[i]);
        }
    }
    CHECK_STATUS(rr_fmu_var_at(f, n, &(rr_fmu_var){0}), RR_ERR_PARAM, "past the end");
    CHECK_STATUS(rr_fmu_var_find(f, 999999u, &(rr_fmu_var){0}), RR_ERR_PARAM, "unknown vr");
    CHECK_STATUS(rr_fmu_var_find(f, RR_FMU_VR_RECORD, &(rr_fmu_var){0}), RR_ERR_PARAM,
                 "the record's time is the time");
    /* every rig row: a parameter of its name (a list: one per entry) */
    for (i = 0; i < rr_rig_param_count(); i++) {
        const rr_rig_param *row = rr_rig_param_at(i);
        char name[RR_FMU_NAME_LEN];
        if (row->type == RR_RIG_LIST) {
            const rr_rig_list *l = (const rr_rig_list *)(const void *)((const char *)&f->c
                                                                       + row->offset);
            for (j = 0; j < l->n; j++) {
                snprintf(name, sizeof name, "%s[%d]", row->name, j + 1);
                CHECK(vr_of(f, name) == RR_FMU_VR_LIST + RR_FMU_VR_LIST_ROW * (unsigned)i
                                        + (unsigned)j, name);
            }
            snprintf(name, sizeof name, "%s[%d]", row->name, l->n + 1);
            CHECK(vr_of(f, name) == 999999u, name);
        } else {
            CHECK(vr_of(f, row->name) == RR_FMU_VR_PARAM + (unsigned)i, row->name);
        }
    }
    for (i = 1; i < RR_REC_COUNT; i++)
        CHECK(vr_of(f, rr_rig_record_field(i)->name) == RR_FMU_VR_RECORD + (unsigned)i,
              rr_rig_record_field(i)->name);
    CHECK(vr_of(f, "time") == RR_FMU_VR_TIME, "time");
    CHECK(vr_of(f, "left.p[1]") == RR_FMU_VR_WHEEL, "left.p[1]");
    CHECK(vr_of(f, "right.N") != 999999u, "right.N");
    CHECK(vr_of(f, "encoder.wheelset_speed") == RR_FMU_VR_ENCODER + RR_FMU_ENC_WHEELSET_SPEED,
          "encoder");
    CHECK(nout == RR_REC_COUNT - 1 + RR_FMU_NENCODER + 2 * RR_WHEEL_NVALUES, "outputs");
    {
        /* tunable and fixed; enumeration items */
        rr_fmu_var v;
        const char *item;
        int value, k;
        rr_fmu_var_find(f, vr_of(f, "scenario.mu0"), &v);
        CHECK(v.variability == RR_FMU_TUNABLE, "mu0 tunable");
        rr_fmu_var_find(f, vr_of(f, "wheelset.mass_kg"), &v);
        CHECK(v.variability == RR_FMU_FIXED && v.lo == 0.0 && v.lo_open, "mass fixed, > 0");
        rr_fmu_var_find(f, vr_of(f, "contact.creep_method"), &v);
        CHECK(v.type == RR_FMU_ENUMERATION, "method enumeration");
        for (k = 0; rr_fmu_var_item(&v, k, &item, &value); k++)
            CHECK(strcmp(item, "exact") != 0 && rr_method_find(item) == value, item);
        CHECK(k >= 5, "methods");
        rr_fmu_var_find(f, vr_of(f, "contact.fastsim_slip_speed"), &v);
        CHECK(rr_fmu_var_item(&v, 0, &item, &value) && value == 0, "slip speed items");
        rr_fmu_var_find(f, vr_of(f, "control.wheelset_mode"), &v);
        CHECK(rr_fmu_var_item(&v, 3, &item, &value) && strcmp(item, "torque") == 0
              && value == RR_FMU_WHEELSET_TORQUE && rr_fmu_var_item(&v, 4, &item, &value)
              && strcmp(item, "free") == 0 && value == RR_FMU_WHEELSET_FREE
              && !rr_fmu_var_item(&v, 5, &item, &value), "wheelset modes");
        rr_fmu_var_find(f, vr_of(f, "contact.fastsim_nx"), &v);
        CHECK(v.type == RR_FMU_INTEGER && v.lo == 1.0 && !v.lo_open, "nx range");
    }
    {
        char buf[16];
        double x = 0.1;
        rr_fmu_format_number(x, buf, sizeof buf);
        CHECK(strcmp(buf, "0.1") == 0, "shortest number");
        rr_fmu_format_number(0.004, buf, sizeof buf);
        CHECK(strcmp(buf, "0.004") == 0, "shortest number 0.004");
    }
}

static void test_config(void)
{
    rr_fmu_config f;
    double v[3] = {0.0, 1.0, 1.0};
    CHECK_STATUS(rr_fmu_config_default(NULL), RR_ERR_NULL, "default NULL");
    rr_fmu_config_default(&f);
    CHECK_STATUS(rr_fmu_config_set(&f, "control.wheelset_mode", 3), RR_OK, "control");
    CHECK_STATUS(rr_fmu_config_set(&f, "control.wheelset_mode", 4), RR_OK, "control 4: free");
    CHECK_STATUS(rr_fmu_config_set(&f, "control.wheelset_mode", 5), RR_ERR_PARAM, "control 5");
    /* a start configuration holds values only: no NaN, no infinity */
    CHECK(rr_fmu_config_set(&f, "control.wheelset_mode", NAN) < 0, "control NaN");
    CHECK(rr_fmu_config_set(&f, "scenario.mu0", NAN) < 0, "mu0 NaN");
    CHECK(rr_fmu_config_set(&f, "scenario.mu0", HUGE_VAL) < 0, "mu0 inf");
    CHECK(rr_fmu_config_set(&f, "contact.fastsim_nx", NAN) < 0, "creep option NaN");
    CHECK(rr_fmu_config_set(&f, "contact.polach_kA", -HUGE_VAL) < 0, "creep option -inf");
    v[1] = NAN;
    CHECK(rr_fmu_config_set_list(&f, "adhesion.schedule_times_s", 3, v) < 0, "list NaN");
    v[1] = 1.0;
    CHECK_STATUS(rr_fmu_config_set_choice(&f, "control.mu_source", "input"), RR_OK, "choice");
    CHECK(f.control[RR_FMU_MU_SOURCE] == RR_FMU_MU_INPUT, "mu source");
    CHECK_STATUS(rr_fmu_config_set_choice(&f, "contact.creep_method", "polach"), RR_OK, "m");
    CHECK(f.creep[0] == rr_method_find("polach"), "polach");
    CHECK_STATUS(rr_fmu_config_set_choice(&f, "contact.creep_method", "exact"), RR_ERR_PARAM,
                 "exact is not a time-step method");
    CHECK_STATUS(rr_fmu_config_set(&f, "contact.fastsim_nx", 0), RR_ERR_PARAM, "nx 0");
    CHECK_STATUS(rr_fmu_config_set(&f, "contact.fastsim_nx", 12), RR_OK, "nx 12");
    CHECK_STATUS(rr_fmu_config_set_choice(&f, "contact.fastsim_slip_speed", "local"), RR_OK,
                 "slip speed");
    CHECK_STATUS(rr_fmu_config_set(&f, "wheelset.mass_kg", -1.0), RR_ERR_PARAM, "mass");
    CHECK_STATUS(rr_fmu_config_set(&f, "nothing", 1.0), RR_ERR_PARAM, "unknown");
    CHECK_STATUS(rr_fmu_config_set_list(&f, "adhesion.schedule_times_s", 3, v), RR_OK, "list");
    CHECK(f.c.schedule_t.n == 3, "list set");
    {
        rr_creep_opts o;
        const char *bad;
        rr_fmu_config_default(&f);
        CHECK_STATUS(rr_fmu_creep_opts(&f, &o, &bad), RR_OK, "creep opts");
        CHECK(o.method == rr_method_find("fastsim") && o.v[0] == 20, "fastsim 20");
        rr_fmu_config_set_choice(&f, "contact.creep_method", "polach");
        rr_fmu_config_set(&f, "contact.polach_kS", 1.0);
        rr_fmu_config_set(&f, "contact.polach_kA", 0.5);
        CHECK_STATUS(rr_fmu_creep_opts(&f, &o, &bad), RR_ERR_PARAM, "kS > kA");
        CHECK(bad && strncmp(bad, "contact.polach_k", 16) == 0, "kS or kA blamed");
    }
}

/* The rig_paper.c run: rr_rig_step with rr_rig_schedule's references (with
 * no creepage target if free_rolling). */
static int paper_run(long n, int free_rolling, double *recs)
{
    static double work[RR_RIG_TABLE_WORK_LEN];
    static rr_rig rig;
    rr_rig_config c;
    rr_rig_geometry g;
    rr_contact_table t;
    rr_rig_params p;
    double *data, roller_ref, xi_ref;
    long k, len;
    int st;
    rr_rig_config_default(&c);
    rr_rig_geometry_from(&c, &g);
    len = rr_rig_table_data_len(&g);
    data = malloc((size_t)len * sizeof *data);
    st = rr_rig_table_build(&g, data, len, work, RR_RIG_TABLE_WORK_LEN, &t, NULL);
    if (st >= 0)
        st = rr_rig_params_from(&c, &t, &p);
    if (st >= 0)
        st = rr_rig_init(&p, c.roller_speed / c.roller_radius, NULL, 0, &rig);
    for (k = 0; st >= 0 && k < n; k++) {
        rr_rig_schedule(&c, k, &roller_ref, &xi_ref);
        if (free_rolling)
            xi_ref = NAN;
        st = rr_rig_step(&rig, roller_ref, xi_ref, recs + k * RR_REC_COUNT);
    }
    free(data);
    return st;
}

#define NRUN 600
#define T 0.004

static void test_default_run(const rr_fmu_config *f)
{
    static double want[NRUN * RR_REC_COUNT], got[NRUN * RR_REC_COUNT];
    static rr_fmu m;
    double rec[RR_REC_COUNT], x;
    long k;
    int st, ok = 1;

    CHECK_STATUS(paper_run(NRUN, 0, want), RR_OK, "the paper's run");
    CHECK_STATUS(start_unit(&m, f), RR_OK, "the unit starts");
    CHECK(allocations == 1, "one allocation: the table");
    rr_fmu_get(&m, RR_FMU_REAL, RR_FMU_VR_TIME, &x);
    CHECK(x == 0.0, "time 0");
    for (k = 0; k < NRUN; k++) {
        st = rr_fmu_do_step(&m, k * T, T);
        if (st != RR_OK) {
            CHECK_STATUS(st, RR_OK, rr_fmu_message(&m));
            break;
        }
        unit_record(&m, got + k * RR_REC_COUNT);
    }
    /* bit for bit; xi_ref is NaN nowhere here (the first target at t = 0) */
    for (k = 0; k < NRUN && ok; k++)
        ok = same_bits(got + k * RR_REC_COUNT, want + k * RR_REC_COUNT, RR_REC_COUNT);
    CHECK(ok, "the unit's records are rr_rig_step's, bit for bit");
    rr_fmu_get(&m, RR_FMU_REAL, RR_FMU_VR_TIME, &x);
    CHECK(x == want[(NRUN - 1) * RR_REC_COUNT], "the time is the rig's");

    /* the same run in steps of 5 samples, the time of the master's own sum */
    CHECK_STATUS(rr_fmu_reset(&m), RR_OK, "reset");
    CHECK_STATUS(rr_fmu_enter_init(&m, 0.0), RR_OK, "enter");
    CHECK_STATUS(rr_fmu_exit_init(&m), RR_OK, "exit");
    CHECK(allocations == 1, "the table kept over a reset");
    ok = 1;
    for (k = 0; k < NRUN / 5; k++) {
        st = rr_fmu_do_step(&m, k * 5 * T, (k + 1) * 5 * T - k * 5 * T);
        if (st != RR_OK) {
            CHECK_STATUS(st, RR_OK, rr_fmu_message(&m));
            break;
        }
        unit_record(&m, rec);
        ok = ok && same_bits(rec, want + (5 * k + 4) * RR_REC_COUNT, RR_REC_COUNT);
    }
    CHECK(ok, "steps of 5 samples: the same records");
    rr_fmu_release(&m);
    CHECK(allocations == 0, "released");
}

static void test_checks(const rr_fmu_config *f)
{
    static rr_fmu m;
    double x;
    unsigned mass = vr_of(f, "wheelset.mass_kg");

    rr_fmu_init(&m, f, test_alloc, test_free, NULL, NULL);
    CHECK_STATUS(rr_fmu_do_step(&m, 0.0, T), RR_ERR_SEQUENCE, "step before init");
    CHECK(contains(rr_fmu_message(&m), "instantiated"), rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_get(&m, RR_FMU_REAL, RR_FMU_VR_RECORD + RR_REC_FX, &x),
                 RR_ERR_SEQUENCE, "output before init");
    CHECK(isnan(x), "NaN");
    CHECK_STATUS(rr_fmu_get(&m, RR_FMU_REAL, mass, &x), RR_OK, "parameter before init");
    CHECK(x == 14.504, "mass");
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, 999999u, 1.0), RR_ERR_PARAM, "unknown vr");
    CHECK(contains(rr_fmu_message(&m), "unknown value reference 999999"), rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, mass, -1.0), RR_ERR_PARAM, "mass -1");
    CHECK(contains(rr_fmu_message(&m), "wheelset.mass_kg = -1 is out of range")
          && contains(rr_fmu_message(&m), "(0, inf) kg"), rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, mass, NAN), RR_ERR_NONFINITE, "mass NaN");
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_INTEGER, mass, 2.0), RR_ERR_PARAM, "mass as integer");
    CHECK(contains(rr_fmu_message(&m), "is of type Real, not Integer"), rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_INTEGER, vr_of(f, "integration.table_rows"), 2.5),
                 RR_ERR_PARAM, "rows 2.5");
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_ENUMERATION, vr_of(f, "control.wheelset_mode"), 7),
                 RR_ERR_PARAM, "mode 7");
    CHECK(contains(rr_fmu_message(&m), "3 (torque)"), rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, RR_FMU_VR_RECORD + RR_REC_FX, 1.0), RR_ERR_PARAM,
                 "set an output");
    CHECK(contains(rr_fmu_message(&m), "fx (value reference 206) is an output"),
          rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, RR_FMU_VR_INPUT + RR_FMU_IN_MU, 0.0),
                 RR_ERR_PARAM, "mu 0");
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, RR_FMU_VR_INPUT + RR_FMU_IN_CREEPAGE, NAN),
                 RR_ERR_NONFINITE, "creepage NaN refused (no control: wheelset_mode free)");
    CHECK(contains(rr_fmu_message(&m), "creepage_ref = nan: the value must be a finite number"),
          rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, vr_of(f, "scenario.targets[2]"), 1.0),
                 RR_ERR_PARAM, "target 1");
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, vr_of(f, "scenario.targets[2]"), 0.01), RR_OK,
                 "target 0.01");
    /* a whole that does not hold: start times out of order, refused at the exit */
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, vr_of(f, "scenario.target_start_s[2]"), 12.0),
                 RR_OK, "start 12");
    CHECK_STATUS(rr_fmu_enter_init(&m, 0.0), RR_OK, "enter");
    CHECK_STATUS(rr_fmu_enter_init(&m, 0.0), RR_ERR_SEQUENCE, "enter twice");
    CHECK_STATUS(rr_fmu_exit_init(&m), RR_ERR_PARAM, "starts out of order");
    CHECK(contains(rr_fmu_message(&m), "scenario.target_start_s"), rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, vr_of(f, "scenario.target_start_s[2]"), 5.0),
                 RR_OK, "start 5");
    /* a sample time at which the roller's loop is unstable: refused, named
     * with the drive and the range at which it is stable (issue 22) */
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, vr_of(f, "scenario.control_sample_time_s"), 0.01),
                 RR_OK, "T 10 ms");
    CHECK_STATUS(rr_fmu_exit_init(&m), RR_ERR_PARAM, "10 ms refused");
    CHECK(contains(rr_fmu_message(&m), "scenario.control_sample_time_s = 0.01 s: the roller "
                   "drive's sampled speed loop") && contains(rr_fmu_message(&m), "it is stable "
                   "from 6.7e-06 to 0.00833 s"), rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, vr_of(f, "scenario.control_sample_time_s"), T),
                 RR_OK, "T back");
    CHECK_STATUS(rr_fmu_get(&m, RR_FMU_REAL, RR_FMU_VR_RECORD + RR_REC_N_LEFT, &x), RR_OK,
                 "an output in initialization mode");
    CHECK(x > 500.0 && x < 550.0, "the static load");
    CHECK_STATUS(rr_fmu_exit_init(&m), RR_OK, "exit");
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, mass, 15.0), RR_ERR_SEQUENCE, "fixed, stepping");
    CHECK(contains(rr_fmu_message(&m), "wheelset.mass_kg is a fixed parameter"),
          rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_do_step(&m, 0.0, 0.005), RR_ERR_PARAM, "not a multiple");
    CHECK(contains(rr_fmu_message(&m), "0.005 s is not a whole multiple of the control sample "
                   "time 0.004 s"), rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_do_step(&m, 0.0, 0.0), RR_ERR_PARAM, "zero step");
    CHECK_STATUS(rr_fmu_do_step(&m, 0.0, NAN), RR_ERR_PARAM, "NaN step");
    CHECK_STATUS(rr_fmu_do_step(&m, 0.0, 1e300), RR_ERR_PARAM, "huge step");
    CHECK_STATUS(rr_fmu_do_step(&m, 0.008, T), RR_ERR_PARAM, "wrong time");
    CHECK(contains(rr_fmu_message(&m), "currentCommunicationPoint 0.008 s is not the unit's "
                   "time 0 s"), rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_do_step(&m, 0.0, 2 * T), RR_OK, "two samples");
    CHECK_STATUS(rr_fmu_do_step(&m, 2 * T + 1e-3 * T, T), RR_ERR_PARAM, "a thousandth off");
    CHECK_STATUS(rr_fmu_do_step(&m, 2 * T + 1e-7, 0.0), RR_ERR_PARAM, "still no zero step");
    CHECK(m.s.k == 2, "the time a master's sum drifted to: accepted below");
    /* a torque command without a number: refused, nothing changes */
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_ENUMERATION, vr_of(f, "control.wheelset_mode"),
                            RR_FMU_WHEELSET_TORQUE), RR_OK, "torque mode");
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, RR_FMU_VR_INPUT + RR_FMU_IN_WHEELSET_TORQUE, NAN),
                 RR_ERR_NONFINITE, "torque NaN");
    m.s.in[RR_FMU_IN_WHEELSET_TORQUE] = NAN;        /* as if set behind the checks */
    CHECK_STATUS(rr_fmu_do_step(&m, 2 * T, T), RR_ERR_NONFINITE, "refused command");
    CHECK(contains(rr_fmu_message(&m), "wheelset_torque_ref = nan"), rr_fmu_message(&m));
    CHECK(m.s.mode == RR_FMU_STEPPING && m.s.k == 2, "nothing changed");
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, RR_FMU_VR_INPUT + RR_FMU_IN_WHEELSET_TORQUE, -20.0),
                 RR_OK, "torque -20");
    CHECK_STATUS(rr_fmu_do_step(&m, 2 * T, 10 * T), RR_OK, "torque mode steps");
    rr_fmu_get(&m, RR_FMU_REAL, RR_FMU_VR_RECORD + RR_REC_TREF_WHEELSET, &x);
    CHECK(x == -20.0, "the torque reference held");
    rr_fmu_get(&m, RR_FMU_REAL, RR_FMU_VR_RECORD + RR_REC_W_REF, &x);
    CHECK(isnan(x), "no speed reference under torque");
    /* a sample the rig cannot do: the wheel off its roller */
    m.s.rig.y[RR_RIG_Y] = 0.5;
    m.s.rig.cache_ok = m.s.rig.lin_ok = 0;
    CHECK(rr_fmu_do_step(&m, 12 * T, T) < 0, "a failed sample");
    CHECK(m.s.mode == RR_FMU_FAILED && contains(rr_fmu_message(&m), "sample 12"),
          rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_do_step(&m, 12 * T, T), RR_ERR_SEQUENCE, "no step after failing");
    CHECK(contains(rr_fmu_message(&m), "reset it"), rr_fmu_message(&m));
    CHECK_STATUS(rr_fmu_terminate(&m), RR_OK, "terminate");
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_REAL, RR_FMU_VR_INPUT + RR_FMU_IN_MU, 0.3),
                 RR_ERR_SEQUENCE, "set after terminate");
    CHECK_STATUS(rr_fmu_reset(&m), RR_OK, "reset");
    CHECK_STATUS(rr_fmu_get(&m, RR_FMU_REAL, vr_of(f, "scenario.targets[2]"), &x), RR_OK, "g");
    CHECK(x == 0.015, "reset to the start values");
    /* control.start changed after the outputs were asked: the rig built again */
    CHECK_STATUS(rr_fmu_enter_init(&m, 0.0), RR_OK, "enter");
    rr_fmu_get(&m, RR_FMU_REAL, RR_FMU_VR_RECORD + RR_REC_ROLLER_SPIN, &x);
    CHECK(x == 31.25, "rolling");
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_ENUMERATION, vr_of(f, "control.start"),
                            RR_FMU_START_REST), RR_OK, "rest");
    rr_fmu_get(&m, RR_FMU_REAL, RR_FMU_VR_RECORD + RR_REC_ROLLER_SPIN, &x);
    CHECK(x == 0.0, "at rest");
    CHECK_STATUS(rr_fmu_exit_init(&m), RR_OK, "exit");
    {
        /* a master adding up 0.004 drifts from k T: its times are taken */
        double t = 0.0;
        int k, st = RR_OK;
        for (k = 0; k < 2000 && st == RR_OK; k++) {
            st = rr_fmu_do_step(&m, t, T);
            t += T;
        }
        CHECK_STATUS(st, RR_OK, "a drifting master's times");
        CHECK(t != 2000 * T, "(it did drift)");
    }
    rr_fmu_release(&m);
    CHECK(allocations == 0, "released");
}

/* NaN and infinities are no value of any variable: every parameter and
 * input refuses them with a message naming it, before the initialisation
 * (a start value), in it and while stepping, and keeps its value; the
 * unit then initialises and steps as if they were never offered (issue 22:
 * creepage_ref = NaN set before the initialisation was taken). */
static void test_nonfinite(const rr_fmu_config *f)
{
    static rr_fmu m;
    static const double bad[3] = {NAN, HUGE_VAL, -HUGE_VAL};
    int phase, i, k, n = rr_fmu_var_count(f), taken = 0, silent = 0, moved = 0, tried = 0;
    double x;

    CHECK_STATUS(rr_fmu_init(&m, f, test_alloc, test_free, NULL, NULL), RR_OK, "init");
    for (phase = 0; phase < 3; phase++) {
        if (phase == 1)
            CHECK_STATUS(rr_fmu_enter_init(&m, 0.0), RR_OK, "enter");
        if (phase == 2)
            CHECK_STATUS(rr_fmu_exit_init(&m), RR_OK, "exit: no bad value was taken");
        for (i = 0; i < n; i++) {
            rr_fmu_var v;
            char name[RR_FMU_NAME_LEN];
            double before, after;
            int st;
            rr_fmu_var_at(f, i, &v);
            if (v.causality != RR_FMU_PARAMETER && v.causality != RR_FMU_INPUT)
                continue;
            rr_fmu_var_name(&v, name, sizeof name);
            for (k = 0; k < 3; k++) {
                tried++;
                rr_fmu_get(&m, v.type, v.vr, &before);
                st = rr_fmu_set(&m, v.type, v.vr, bad[k]);
                rr_fmu_get(&m, v.type, v.vr, &after);
                if (st >= 0) {
                    taken++;
                    printf("    phase %d: %s = %g taken\n", phase, name, bad[k]);
                } else if (!contains(rr_fmu_message(&m), name)) {
                    silent++;
                    printf("    phase %d: %s = %g: \"%s\"\n", phase, name, bad[k],
                           rr_fmu_message(&m));
                }
                if (memcmp(&before, &after, sizeof before) != 0)
                    moved++;
            }
        }
    }
    CHECK(tried > 3 * 150, "every parameter and input tried");
    CHECK(taken == 0, "no parameter or input takes NaN or an infinity");
    CHECK(silent == 0, "each refusal names the variable");
    CHECK(moved == 0, "a refused value changes nothing");
    CHECK_STATUS(rr_fmu_do_step(&m, 0.0, 10 * T), RR_OK, "the unit steps on");
    CHECK_STATUS(rr_fmu_get(&m, RR_FMU_REAL, RR_FMU_VR_RECORD + RR_REC_XI_REF, &x), RR_OK,
                 "xi_ref");
    CHECK(x == f->c.targets.v[0], "the scenario's target, untouched");
    rr_fmu_release(&m);
}

/* control.wheelset_mode = free: no creepage control, the wheelset's PI to
 * free rolling, as rr_rig_step with a NaN target, bit for bit (what
 * creepage_ref = NaN gave before NaN was refused). */
static void test_free_mode(const rr_fmu_config *f)
{
    static double want[100 * RR_REC_COUNT];
    static rr_fmu m;
    double rec[RR_REC_COUNT];
    long k;
    int ok = 1;
    CHECK_STATUS(paper_run(100, 1, want), RR_OK, "free rolling run");
    CHECK_STATUS(rr_fmu_init(&m, f, test_alloc, test_free, NULL, NULL), RR_OK, "init");
    CHECK_STATUS(rr_fmu_set(&m, RR_FMU_ENUMERATION, vr_of(f, "control.wheelset_mode"),
                            RR_FMU_WHEELSET_FREE), RR_OK, "free mode");
    CHECK_STATUS(rr_fmu_enter_init(&m, 0.0), RR_OK, "enter");
    CHECK_STATUS(rr_fmu_exit_init(&m), RR_OK, "exit");
    for (k = 0; k < 100 && ok; k++) {
        CHECK_STATUS(rr_fmu_do_step(&m, k * T, T), RR_OK, "free step");
        unit_record(&m, rec);
        ok = same_bits(rec, want + k * RR_REC_COUNT, RR_REC_COUNT);
    }
    CHECK(ok, "free mode: rr_rig_step with a NaN target, bit for bit");
    CHECK(isnan(rec[RR_REC_XI_REF]) && fabs(rec[RR_REC_CREEPAGE]) < 1e-3,
          "no target, about free rolling");
    rr_fmu_release(&m);
}

/* the unit's records of samples [k0, k1) into recs */
static int run_unit(rr_fmu *m, long k0, long k1, double *recs)
{
    long k;
    int st = RR_OK;
    for (k = k0; k < k1 && st >= 0; k++) {
        st = rr_fmu_do_step(m, k * T, T);
        unit_record(m, recs + (k - k0) * RR_REC_COUNT);
    }
    return st;
}

static void test_states(const rr_fmu_config *f)
{
    static rr_fmu a, b;
    static rr_fmu_state saved;
    static unsigned char bytes[sizeof(rr_fmu_state)];
    static double r1[200 * RR_REC_COUNT], r2[200 * RR_REC_COUNT], r3[200 * RR_REC_COUNT];

    CHECK_STATUS(start_unit(&a, f), RR_OK, "a");
    CHECK_STATUS(run_unit(&a, 0, 100, r1), RR_OK, "a 100");
    CHECK_STATUS(rr_fmu_save(&a, &saved), RR_OK, "save");
    memcpy(bytes, &saved, sizeof saved);
    CHECK_STATUS(run_unit(&a, 100, 300, r1), RR_OK, "a 200 more");
    CHECK_STATUS(rr_fmu_restore(&a, &saved), RR_OK, "restore");
    CHECK_STATUS(run_unit(&a, 100, 300, r2), RR_OK, "a again");
    CHECK(same_bits(r1, r2, 200 * RR_REC_COUNT), "restored: the same continuation");

    /* the state as bytes in another unit, never initialised, its pointers garbled */
    {
        rr_fmu_state *s = (rr_fmu_state *)(void *)bytes;
        s->rig.p = (const rr_rig_params *)(void *)bytes;
        s->p.contact.table = NULL;
        s->rig.ode.model = NULL;
        rr_fmu_init(&b, f, test_alloc, test_free, NULL, NULL);
        CHECK_STATUS(rr_fmu_restore(&b, s), RR_OK, "restore bytes");
        CHECK(b.s.rig.p == &b.s.p && b.s.p.contact.table == &b.table, "pointers remade");
        CHECK_STATUS(run_unit(&b, 100, 300, r3), RR_OK, "b");
        CHECK(same_bits(r1, r3, 200 * RR_REC_COUNT), "restored elsewhere: the same");
    }
    CHECK_STATUS(rr_fmu_restore(&b, NULL), RR_ERR_NULL, "restore NULL");
    saved.mode = 99;
    CHECK_STATUS(rr_fmu_restore(&b, &saved), RR_ERR_PARAM, "not a state");
    rr_fmu_release(&a);
    rr_fmu_release(&b);
}

/* Two units at once, different inputs: each is its run alone. */
static void test_two_units(const rr_fmu_config *f0)
{
    static rr_fmu a, b;
    static double ra[150 * RR_REC_COUNT], rb[150 * RR_REC_COUNT], alone[150 * RR_REC_COUNT];
    rr_fmu_config f = *f0;
    long k;
    int st = RR_OK;
    f.control[RR_FMU_MU_SOURCE] = RR_FMU_MU_INPUT;
    start_unit(&a, &f);
    start_unit(&b, &f);
    rr_fmu_set(&b, RR_FMU_REAL, RR_FMU_VR_INPUT + RR_FMU_IN_MU, 0.2);
    for (k = 0; k < 150 && st >= 0; k++) {
        st = rr_fmu_do_step(&a, k * T, T);
        if (st >= 0)
            st = rr_fmu_do_step(&b, k * T, T);
        unit_record(&a, ra + k * RR_REC_COUNT);
        unit_record(&b, rb + k * RR_REC_COUNT);
    }
    CHECK_STATUS(st, RR_OK, "two units step");
    CHECK(ra[RR_REC_MU_LEFT] == 0.4 && rb[RR_REC_MU_LEFT] == 0.2, "each its mu");
    rr_fmu_reset(&b);
    rr_fmu_enter_init(&b, 0.0);
    rr_fmu_exit_init(&b);
    rr_fmu_set(&b, RR_FMU_REAL, RR_FMU_VR_INPUT + RR_FMU_IN_MU, 0.2);
    CHECK_STATUS(run_unit(&b, 0, 150, alone), RR_OK, "b alone");
    CHECK(same_bits(rb, alone, 150 * RR_REC_COUNT), "b beside a is b alone");
    rr_fmu_release(&a);
    rr_fmu_release(&b);
}

/* The input mu stepping at sample K is the adhesion schedule stepping at
 * the rig's clock there. */
static void test_mu_input(const rr_fmu_config *f0)
{
    static rr_fmu a, b;
    static double ra[300 * RR_REC_COUNT], rb[300 * RR_REC_COUNT];
    rr_fmu_config fa = *f0, fb = *f0;
    double times[4], mu0[4] = {0.4, 0.4, 0.15, 0.15}, t = 0.0;
    long k;
    int st;
    fa.control[RR_FMU_MU_SOURCE] = RR_FMU_MU_INPUT;
    for (k = 0; k < 100; k++)
        t += T;                          /* the rig's clock at sample 100 */
    times[0] = 0.0;
    times[1] = times[2] = t;
    times[3] = 10.0;
    CHECK_STATUS(rr_fmu_config_set_list(&fb, "adhesion.schedule_times_s", 4, times), RR_OK,
                 "schedule times");
    CHECK_STATUS(rr_fmu_config_set_list(&fb, "adhesion.schedule_mu0", 4, mu0), RR_OK,
                 "schedule mu0");
    start_unit(&a, &fa);
    start_unit(&b, &fb);
    st = run_unit(&a, 0, 100, ra);
    rr_fmu_set(&a, RR_FMU_REAL, RR_FMU_VR_INPUT + RR_FMU_IN_MU, 0.15);
    if (st >= 0)
        st = run_unit(&a, 100, 300, ra + 100 * RR_REC_COUNT);
    CHECK_STATUS(st, RR_OK, "mu input run");
    CHECK_STATUS(run_unit(&b, 0, 300, rb), RR_OK, "schedule run");
    CHECK(ra[99 * RR_REC_COUNT + RR_REC_MU_LEFT] == 0.4
          && ra[100 * RR_REC_COUNT + RR_REC_MU_RIGHT] == 0.15, "the step");
    CHECK(same_bits(ra, rb, 300 * RR_REC_COUNT), "input mu = the adhesion schedule, bitwise");
    /* a tunable parameter in the run: scenario.mu0 from the next step */
    rr_fmu_release(&b);
    start_unit(&b, f0);
    CHECK_STATUS(run_unit(&b, 0, 2, rb), RR_OK, "before");
    CHECK_STATUS(rr_fmu_set(&b, RR_FMU_REAL, vr_of(f0, "scenario.mu0"), 0.3), RR_OK, "mu0");
    CHECK(b.s.retune == 1, "retune pending");
    CHECK_STATUS(run_unit(&b, 2, 4, rb + 2 * RR_REC_COUNT), RR_OK, "retuned");
    CHECK(rb[RR_REC_MU_LEFT] == 0.4 && rb[2 * RR_REC_COUNT + RR_REC_MU_LEFT] == 0.3,
          "mu0 tuned from the next step");
    rr_fmu_release(&a);
    rr_fmu_release(&b);
}

static void test_xml(const rr_fmu_config *f)
{
    static const char *const sources[] = {"rig/rr_rig.c", "fmi2_cs.c"};
    rr_fmu_xml_info info = {2, "rollerrig", "rollerrig", "the rig", "test", "{token}",
                            sources, 2};
    long n, n3;
    char *buf;
    int e[4];
    CHECK(rr_fmu_unit_base("N m s/rad", e) && e[0] == 1 && e[1] == 2 && e[2] == -1
          && e[3] == -1, "N m s/rad");
    CHECK(rr_fmu_unit_base("m/s^2", e) && e[1] == 1 && e[2] == -2 && e[0] == 0, "m/s^2");
    CHECK(rr_fmu_unit_base("kg m^2", e) && e[0] == 1 && e[1] == 2, "kg m^2");
    CHECK(rr_fmu_unit_base("Pa", e) && e[0] == 1 && e[1] == -1 && e[2] == -2, "Pa");
    CHECK(!rr_fmu_unit_base("furlong", e) && !rr_fmu_unit_base("m/s/s", e), "unknown unit");
    CHECK(rr_fmu_unit_base("1", e) && !e[0] && !e[1] && !e[2] && !e[3], "dimensionless");
    CHECK(!rr_fmu_unit_base("-", e), "the C tables' dash is not a unit");
    CHECK(rr_fmu_xml(NULL, f, NULL, 0) == RR_ERR_NULL, "NULL info");
    n = rr_fmu_xml(&info, f, NULL, 0);
    CHECK(n > 10000, "length");
    buf = malloc((size_t)n + 1);
    CHECK(rr_fmu_xml(&info, f, buf, n + 1) == n && (long)strlen(buf) == n, "written");
    CHECK(contains(buf, "fmiVersion=\"2.0\"") && contains(buf, "guid=\"{token}\""), "header");
    CHECK(contains(buf, "<File name=\"fmi2_cs.c\"/>"), "sources");
    CHECK(contains(buf, "name=\"scenario.targets[4]\" valueReference=\"101003\""), "list");
    CHECK(contains(buf, "<Unit name=\"N m s/rad\">\n      <BaseUnit kg=\"1\" m=\"2\" s=\"-1\" "
                   "rad=\"-1\"/>"), "unit");
    CHECK(contains(buf, "<Real unit=\"kg\" min=\"0\" start=\"14.504\"/>"), "mass");
    /* dimensionless: CF's "1" (rollerrig/_units.py), defined; never the tables' "-" */
    CHECK(contains(buf, "<Unit name=\"1\">\n      <BaseUnit/>\n    </Unit>")
          && contains(buf, "name=\"scenario.mu0\"") && contains(buf, "<Real unit=\"1\"")
          && !contains(buf, "unit=\"-\"") && !contains(buf, "<Integer unit="), "unit 1");
    CHECK(contains(buf, "<DefaultExperiment startTime=\"0\" stopTime=\"20\" stepSize=\"0.004\""),
          "experiment");
    CHECK(contains(buf, "&quot;braking&quot;") || contains(buf, "&quot;"), "escaped quotes");
    CHECK(!contains(buf, "\"inf\"") && !contains(buf, "nan"), "no inf or nan");
    buf[0] = 'x';
    CHECK(rr_fmu_xml(&info, f, buf, 5) == n && strlen(buf) == 4, "truncated");
    info.fmi_version = 3;
    n3 = rr_fmu_xml(&info, f, NULL, 0);
    free(buf);
    buf = malloc((size_t)n3 + 1);
    rr_fmu_xml(&info, f, buf, n3 + 1);
    CHECK(contains(buf, "fmiVersion=\"3.0\"") && contains(buf, "instantiationToken"), "fmi 3");
    CHECK(contains(buf, "<Float64 name=\"time\" valueReference=\"0\"") && contains(buf,
          "<EnumerationType name=\"control.mu_source\">"), "fmi 3 variables");
    CHECK(contains(buf, "<Output valueReference=\"228\"/>"), "fmi 3 outputs");
    CHECK(!contains(buf, "SourceFiles"), "no FMI 2 sources in FMI 3");
    info.fmi_version = 1;
    CHECK(rr_fmu_xml(&info, f, NULL, 0) == RR_ERR_PARAM, "version 1");
    free(buf);
}

int main(void)
{
    rr_fmu_config f;
    CHECK_STATUS(rr_fmu_config_default(&f), RR_OK, "default");
    test_variables(&f);
    test_config();
    test_default_run(&f);
    test_checks(&f);
    test_nonfinite(&f);
    test_free_mode(&f);
    test_states(&f);
    test_two_units(&f);
    test_mu_input(&f);
    test_xml(&f);
    CHECK(allocations == 0, "every allocation freed");
    return rr_test_summary();
}
