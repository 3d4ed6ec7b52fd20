/* test_rig_params.c - the rig's parameter declaration: defaults, setters,
 * checks, derivations, schedule, output names; every error status. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rr_test.h"
#include "rollerrig.h"

/* The problem i of a report is (key, status, rule). */
static int is(const rr_rig_problem *p, const char *key, int status, int rule)
{
    return p->key && strcmp(p->key, key) == 0 && p->status == status && p->rule == rule;
}

/* rr_rig_config_report (issue 23): every problem with its row, status,
 * rule and bounds, so that a caller names every bad key without restating
 * the rules; rr_rig_config_check is its first. */
static void test_report(void)
{
    rr_rig_config c;
    rr_rig_problem p[RR_RIG_MAX_PROBLEMS], one;
    const char *bad;
    const double two[2] = {0.01, 0.02}, starts3[3] = {0.0, 1.0, 2.0};
    const double times[3] = {0.0, 2.0, 1.0}, mu[2] = {0.3, 0.2}, targets3[3] = {0.01, 0.02, 0.03};
    int n, i;

    rr_rig_config_default(&c);
    CHECK(rr_rig_config_report(&c, p, RR_RIG_MAX_PROBLEMS) == 0, "defaults: no problem");
    CHECK(rr_rig_config_report(&c, NULL, 0) == 0, "count only");
    CHECK_STATUS(rr_rig_config_report(NULL, p, 1), RR_ERR_NULL, "report NULL");
    CHECK_STATUS(rr_rig_config_report(&c, NULL, 1), RR_ERR_NULL, "report out NULL");

    /* put: unchecked where the member can hold the value */
    CHECK_STATUS(rr_rig_config_put(&c, "wheelset.mass_kg", NAN, NULL), RR_OK, "put NaN real");
    CHECK_STATUS(rr_rig_config_put(&c, "roller.radius_m", -0.1, NULL), RR_OK, "put -0.1");
    one.key = NULL;
    CHECK_STATUS(rr_rig_config_put(&c, "integration.table_rows", 2.5, &one), RR_ERR_PARAM,
                 "put 2.5 in an int");
    CHECK(is(&one, "integration.table_rows", RR_ERR_PARAM, RR_RIG_RULE_RANGE)
          && one.value == 2.5 && one.lo == 2 && one.hi == 100000 && one.entry == -1,
          "its problem, with the row's range");
    CHECK_STATUS(rr_rig_config_put(&c, "integration.substeps", NAN, &one), RR_ERR_NONFINITE,
                 "put NaN in an int");
    CHECK_STATUS(rr_rig_config_put(&c, "scenario.drive_mode", 1e300, &one), RR_ERR_PARAM,
                 "put 1e300 in a choice");
    CHECK(one.lo == 0 && one.hi == 1, "a choice's range: its indices");
    CHECK_STATUS(rr_rig_config_put(&c, "wheelset.mass", 1.0, NULL), RR_ERR_PARAM, "put unknown");
    CHECK_STATUS(rr_rig_config_put(&c, "contact.polach_kA", 0.5, NULL), RR_ERR_PARAM,
                 "put a creep row");
    CHECK_STATUS(rr_rig_config_put(&c, "scenario.targets", 0.5, NULL), RR_ERR_PARAM,
                 "put a list as a scalar");
    CHECK_STATUS(rr_rig_config_put_list(&c, "wheelset.mass_kg", 1, two, NULL), RR_ERR_PARAM,
                 "put a scalar as a list");
    CHECK_STATUS(rr_rig_config_put_list(&c, "scenario.targets", RR_RIG_MAX_LIST + 1, two, &one),
                 RR_ERR_PARAM, "put too long a list");
    CHECK(one.value == RR_RIG_MAX_LIST + 1 && one.lo == 1 && one.hi == RR_RIG_MAX_LIST
          && one.entry == -1, "a list's length and its bounds");
    CHECK_STATUS(rr_rig_config_put(NULL, "wheelset.mass_kg", 1.0, NULL), RR_ERR_NULL, "put NULL");
    CHECK_STATUS(rr_rig_config_put_list(&c, "scenario.targets", 2, NULL, NULL), RR_ERR_NULL,
                 "put_list NULL");

    /* every bad row, and the rules whose rows are in range */
    CHECK_STATUS(rr_rig_config_put_list(&c, "scenario.targets", 2, two, NULL), RR_OK, "2 targets");
    CHECK_STATUS(rr_rig_config_put_list(&c, "adhesion.schedule_times_s", 3, times, NULL), RR_OK,
                 "times");
    CHECK_STATUS(rr_rig_config_put_list(&c, "adhesion.schedule_mu0", 2, mu, NULL), RR_OK, "mu0");
    CHECK_STATUS(rr_rig_config_put(&c, "adhesion.patch_length_m", 2.0, NULL), RR_OK, "patch");
    n = rr_rig_config_report(&c, p, RR_RIG_MAX_PROBLEMS);
    CHECK(n == 5, "five problems (table_rows = 2.5 was not stored: put refused it)");
    CHECK(is(&p[0], "scenario.roller_speed_m_s", RR_ERR_PARAM, RR_RIG_RULE_RANGE) == 0
          && is(&p[0], "wheelset.mass_kg", RR_ERR_NONFINITE, RR_RIG_RULE_RANGE)
          && isnan(p[0].value) && p[0].lo == 0.0 && isinf(p[0].hi) && p[0].other == NULL,
          "1: the mass, NaN, with its range");
    CHECK(is(&p[1], "roller.radius_m", RR_ERR_PARAM, RR_RIG_RULE_RANGE) && p[1].value == -0.1,
          "2: the radius");
    CHECK(is(&p[2], "scenario.target_start_s", RR_ERR_PARAM, RR_RIG_RULE_COUNT)
          && strcmp(p[2].other, "scenario.targets") == 0 && p[2].value == 4 && p[2].hi == 2,
          "3: four start times for two targets");
    CHECK(is(&p[3], "adhesion.schedule_mu0", RR_ERR_PARAM, RR_RIG_RULE_COUNT)
          && strcmp(p[3].other, "adhesion.schedule_times_s") == 0 && p[3].value == 2
          && p[3].hi == 3 && isnan(p[3].lo), "4: two mu0 for three times (none would not do)");
    CHECK(is(&p[4], "adhesion.schedule_times_s", RR_ERR_PARAM, RR_RIG_RULE_NONDECREASING)
          && p[4].entry == 2 && p[4].value == 1.0, "5: the times decrease at entry 2");
    /* no sixth: the patch's rule reads the radius, out of range; the loops
     * do not read the mass */
    CHECK_STATUS(rr_rig_config_check(&c, &bad), RR_ERR_NONFINITE, "check: the first");
    CHECK(bad && strcmp(bad, "wheelset.mass_kg") == 0, "check: its key");
    /* the cap: all counted, the first cap kept, nothing written beyond */
    p[2].key = "untouched";
    CHECK(rr_rig_config_report(&c, p, 2) == n && strcmp(p[2].key, "untouched") == 0, "cap");
    CHECK(rr_rig_config_report(&c, p, -1) == n, "a negative cap: count only");

    /* a rule is judged only where its rows are in range: a bad target is
     * not also a count */
    rr_rig_config_default(&c);
    rr_rig_config_put_list(&c, "scenario.targets", 2, two, NULL);
    c.targets.v[1] = 2.0;
    n = rr_rig_config_report(&c, p, RR_RIG_MAX_PROBLEMS);
    CHECK(n == 1 && is(&p[0], "scenario.targets", RR_ERR_PARAM, RR_RIG_RULE_RANGE)
          && p[0].entry == 1 && p[0].value == 2.0 && p[0].lo == 0.0 && p[0].hi == 1.0,
          "a bad target: its entry, no count");
    /* start times: increasing, then before the duration; the duration a sample */
    rr_rig_config_default(&c);
    rr_rig_config_put_list(&c, "scenario.targets", 3, targets3, NULL);
    rr_rig_config_put_list(&c, "scenario.target_start_s", 3, starts3, NULL);
    c.target_start.v[2] = 0.5;
    n = rr_rig_config_report(&c, p, RR_RIG_MAX_PROBLEMS);
    CHECK(n == 1 && is(&p[0], "scenario.target_start_s", RR_ERR_PARAM, RR_RIG_RULE_INCREASING)
          && p[0].entry == 2 && p[0].value == 0.5, "start times that do not increase");
    c.target_start.v[2] = 2.0;
    rr_rig_config_put(&c, "scenario.duration_s", 2.0, NULL);
    n = rr_rig_config_report(&c, p, RR_RIG_MAX_PROBLEMS);
    CHECK(n == 1 && is(&p[0], "scenario.target_start_s", RR_ERR_PARAM, RR_RIG_RULE_BEFORE)
          && strcmp(p[0].other, "scenario.duration_s") == 0 && p[0].value == 2.0
          && p[0].hi == 2.0 && p[0].entry == 2, "the last start at the duration");
    rr_rig_config_put(&c, "scenario.duration_s", 0.001, NULL);
    n = rr_rig_config_report(&c, p, RR_RIG_MAX_PROBLEMS);
    CHECK(n == 2 && is(&p[1], "scenario.duration_s", RR_ERR_PARAM, RR_RIG_RULE_SAMPLE)
          && strcmp(p[1].other, "scenario.control_sample_time_s") == 0 && p[1].lo == c.T,
          "a duration shorter than a sample, and the starts beyond it");
    /* the patch on the roller; A and B: one per time or none */
    rr_rig_config_default(&c);
    rr_rig_config_put(&c, "adhesion.patch_length_m", 1.01, NULL);
    rr_rig_config_put_list(&c, "adhesion.schedule_times_s", 2, two, NULL);
    rr_rig_config_put_list(&c, "adhesion.schedule_mu0", 2, mu, NULL);
    rr_rig_config_put_list(&c, "adhesion.schedule_polach_B_s_per_m", 1, mu, NULL);
    n = rr_rig_config_report(&c, p, RR_RIG_MAX_PROBLEMS);
    CHECK(n == 2 && is(&p[0], "adhesion.schedule_polach_B_s_per_m", RR_ERR_PARAM,
                       RR_RIG_RULE_COUNT) && p[0].value == 1 && p[0].hi == 2 && p[0].lo == 0.0,
          "one B for two times (none for A is fine, and would be for B: lo 0)");
    CHECK(is(&p[1], "adhesion.patch_length_m", RR_ERR_PARAM, RR_RIG_RULE_CIRCUMFERENCE)
          && strcmp(p[1].other, "roller.radius_m") == 0 && p[1].hi == 2.0 * RR_PI * c.roller_radius,
          "a patch longer than the roller's circumference");
    /* the speed loops: the sample time at which one rings, with the times it does not */
    rr_rig_config_default(&c);
    rr_rig_config_put(&c, "scenario.control_sample_time_s", 0.02, NULL);
    n = rr_rig_config_report(&c, p, RR_RIG_MAX_PROBLEMS);
    CHECK(n >= 1 && is(&p[0], "scenario.control_sample_time_s", RR_ERR_PARAM, RR_RIG_RULE_LOOP)
          && (p[0].entry == 0 || p[0].entry == 1) && p[0].value > 1.0 && p[0].lo < 0.004
          && p[0].hi > 0.004 && p[0].hi < 0.02, "an unstable loop, its pole and stable times");
    CHECK(rr_rig_config_report(&c, NULL, 0) == n, "the count without the scans");
    for (i = 0; i < n; i++)
        CHECK(p[i].rule == RR_RIG_RULE_LOOP, "only loops");
    CHECK_STATUS(rr_rig_config_check(&c, &bad), RR_ERR_PARAM, "check: the loop");
    CHECK(bad && strcmp(bad, "scenario.control_sample_time_s") == 0, "check: the sample time");
    /* a choice out of range is its row's problem, and the loops read of such a
     * config do not index by it (UBSan found the report's loops reading
     * drive_senses[5]: fuzz/regressions/fuzz_rig_params) */
    rr_rig_config_default(&c);
    c.drive_mode = 5;
    n = rr_rig_config_report(&c, p, RR_RIG_MAX_PROBLEMS);
    CHECK(n == 1 && is(&p[0], "scenario.drive_mode", RR_ERR_PARAM, RR_RIG_RULE_RANGE)
          && p[0].value == 5 && p[0].lo == 0 && p[0].hi == 1, "a drive mode out of range");
    {
        rr_speed_loop loops[2];
        CHECK_STATUS(rr_rig_config_speed_loops(&c, loops), RR_OK, "its loops");
        CHECK(loops[1].J == c.spin_inertia + c.drive_inertia, "the wheelset's inertia");
    }
    /* the inertias' sum */
    rr_rig_config_default(&c);
    rr_rig_config_put(&c, "wheelset.spin_inertia_kg_m2", 1.5e308, NULL);
    rr_rig_config_put(&c, "wheelset_drive.drive_inertia_kg_m2", 1.5e308, NULL);
    n = rr_rig_config_report(&c, p, RR_RIG_MAX_PROBLEMS);
    CHECK(n == 1 && is(&p[0], "wheelset.spin_inertia_kg_m2", RR_ERR_RANGE, RR_RIG_RULE_SUM)
          && strcmp(p[0].other, "wheelset_drive.drive_inertia_kg_m2") == 0 && isinf(p[0].value),
          "Iyy overflows: both inertias named");
}

int main(void)
{
    rr_rig_config c, d;
    rr_rig_params p;
    const char *bad;
    double r, xi, v[2] = {0.01, 0.02};
    int i;

    CHECK_STATUS(rr_rig_config_default(NULL), RR_ERR_NULL, "default NULL");
    CHECK_STATUS(rr_rig_params_default(NULL), RR_ERR_NULL, "params default NULL");
    CHECK_STATUS(rr_rig_config_default(&c), RR_OK, "default");
    CHECK_STATUS(rr_rig_config_check(&c, &bad), RR_OK, "defaults pass");
    CHECK(bad == NULL, "no culprit");
    /* every row: its text is its value, its default within its range */
    for (i = 0; i < rr_rig_param_count(); i++) {
        const rr_rig_param *row = rr_rig_param_at(i);
        CHECK(row && row->origin && row->origin[0], "origin");
        CHECK(rr_rig_param_find(row->name) == row, "find");
        if (!row->creep && (row->type == RR_RIG_REAL || row->type == RR_RIG_INT))
            CHECK(strtod(row->text, NULL) == row->value, row->name);
    }
    CHECK(rr_rig_param_at(-1) == NULL && rr_rig_param_at(rr_rig_param_count()) == NULL, "at");
    /* the creep rows' option column (issue 23: declared, not parsed from the
     * name): every creep row but the method's names an option some method
     * of the registry has; no other row names one */
    {
        int nopt = 0;
        for (i = 0; i < rr_rig_param_count(); i++) {
            const rr_rig_param *row = rr_rig_param_at(i);
            int m, found = 0;
            if (!row->creep || strcmp(row->name, "contact.creep_method") == 0) {
                CHECK(row->option == NULL, row->name);
                continue;
            }
            CHECK(row->option != NULL, row->name);
            for (m = 0; row->option && m < rr_method_count(); m++)
                found |= rr_method_option(rr_method_get(m), row->option) >= 0;
            CHECK(found, row->name);
            nopt++;
        }
        CHECK(nopt == 5, "five creep rows set options");
        CHECK(nopt + 1 <= RR_FMU_MAX_CREEP, "the creep rows fit the FMU's slots");
        CHECK(strcmp(rr_rig_param_find("contact.fastsim_slip_speed")->option, "slip_speed") == 0
              && strcmp(rr_rig_param_find("contact.polach_kS")->option, "kS") == 0,
              "fastsim_slip_speed sets slip_speed (not the name after its first _), polach_kS kS");
    }
    CHECK(rr_rig_param_find("wheelset.mass") == NULL && rr_rig_param_find(NULL) == NULL,
          "unknown");
    CHECK(rr_rig_record_field(RR_REC_STATUS) && !rr_rig_record_field(RR_REC_COUNT), "records");
    CHECK(strcmp(rr_rig_record_field(RR_REC_FX)->name, "fx") == 0, "record name");
    {
        int n = 0;
        for (i = 0; i < RR_WHEEL_NFIELDS; i++)
            n += rr_wheel_field(i)->width;
        CHECK(n == RR_WHEEL_NVALUES && !rr_wheel_field(RR_WHEEL_NFIELDS), "wheel block");
    }
    /* setters: unknown, creep row, NaN, range, integer, choice, list */
    d = c;
    CHECK_STATUS(rr_rig_config_set(NULL, "wheelset.mass_kg", 1.0), RR_ERR_NULL, "set NULL");
    CHECK_STATUS(rr_rig_config_set(&c, NULL, 1.0), RR_ERR_NULL, "set NULL name");
    CHECK_STATUS(rr_rig_config_set(&c, "wheelset.mass", 1.0), RR_ERR_PARAM, "set unknown");
    CHECK_STATUS(rr_rig_config_set(&c, "contact.fastsim_nx", 10), RR_ERR_PARAM, "set creep");
    CHECK_STATUS(rr_rig_config_set(&c, "wheelset.mass_kg", NAN), RR_ERR_NONFINITE, "NaN");
    CHECK_STATUS(rr_rig_config_set(&c, "wheelset.mass_kg", 0.0), RR_ERR_PARAM, "open end");
    CHECK_STATUS(rr_rig_config_set(&c, "contact.poisson_ratio", 0.5), RR_OK, "closed end");
    CHECK_STATUS(rr_rig_config_set(&c, "integration.table_rows", 2.5), RR_ERR_PARAM, "int");
    CHECK_STATUS(rr_rig_config_set(&c, "integration.linear_first_stage", 2), RR_ERR_PARAM,
                 "flag");
    CHECK_STATUS(rr_rig_config_set(&c, "scenario.drive_mode", 2), RR_ERR_PARAM, "choice index");
    CHECK_STATUS(rr_rig_config_set_choice(&c, "scenario.drive_mode", "coasting"), RR_ERR_PARAM,
                 "choice name");
    CHECK_STATUS(rr_rig_config_set_choice(&c, "scenario.drive_mode", NULL), RR_ERR_NULL,
                 "choice NULL");
    CHECK_STATUS(rr_rig_config_set_choice(&c, "scenario.drive_mode", "traction"), RR_OK,
                 "traction");
    CHECK_STATUS(rr_rig_config_set_list(&c, "scenario.targets", 0, v), RR_ERR_PARAM, "empty");
    CHECK_STATUS(rr_rig_config_set_list(&c, "scenario.targets", 2, NULL), RR_ERR_NULL, "list NULL");
    CHECK_STATUS(rr_rig_config_set_list(&c, "scenario.targets", RR_RIG_MAX_LIST + 1, v),
                 RR_ERR_PARAM, "too long");
    CHECK_STATUS(rr_rig_config_set_list(&c, "wheelset.mass_kg", 2, v), RR_ERR_PARAM, "not a list");
    CHECK_STATUS(rr_rig_config_set_list(&c, "scenario.targets", 2, v), RR_OK, "targets");
    /* the scenario: one start time per target */
    CHECK_STATUS(rr_rig_config_check(&c, &bad), RR_ERR_PARAM, "starts and targets differ");
    CHECK(bad && strcmp(bad, "scenario.target_start_s") == 0, "named");
    CHECK_STATUS(rr_rig_params_from(&c, NULL, &p), RR_ERR_PARAM, "from a bad config");
    CHECK_STATUS(rr_rig_params_from(NULL, NULL, &p), RR_ERR_NULL, "from NULL");
    CHECK(rr_rig_samples(NULL) == 0, "samples NULL");
    /* derivations */
    CHECK_STATUS(rr_rig_params_default(&p), RR_OK, "params default");
    CHECK(p.Iyy == d.spin_inertia + d.drive_inertia, "Iyy");
    CHECK(p.contact.G == d.E / (2.0 * (1.0 + d.nu)), "G");
    CHECK(p.creepctl.sense == RR_CREEPCTL_BRAKING && p.contact.table == NULL, "sense, table");
    CHECK(p.roller_pi.T == p.T && p.wheelset_enc.T == p.T && p.T == d.T, "sample time");
    CHECK_STATUS(rr_rig_params_set_table(&p, NULL), RR_ERR_NULL, "set table NULL");
    /* the schedule: NaN before the first start, then each target */
    CHECK(rr_rig_samples(&d) == 5000, "samples");
    CHECK_STATUS(rr_rig_schedule(&d, -1, &r, &xi), RR_ERR_PARAM, "k < 0");
    CHECK_STATUS(rr_rig_schedule(NULL, 0, &r, &xi), RR_ERR_NULL, "schedule NULL");
    CHECK_STATUS(rr_rig_schedule(&d, 0, &r, &xi), RR_OK, "k = 0");
    CHECK(r == d.roller_speed / d.roller_radius && xi == 0.04, "first target at t = 0");
    CHECK_STATUS(rr_rig_schedule(&d, 1250, &r, &xi), RR_OK, "k = 1250");
    CHECK(xi == 0.015, "second target at 5 s");
    d.target_start.v[0] = 1.0;
    CHECK_STATUS(rr_rig_schedule(&d, 0, &r, &xi), RR_OK, "before the first");
    CHECK(isnan(xi), "NaN before the first start");
    /* fuzz_rig_params: values each in range whose derived values overflow */
    rr_rig_config_default(&c);
    CHECK_STATUS(rr_rig_config_set(&c, "roller.radius_m", 1e-322), RR_OK, "tiny radius in range");
    CHECK_STATUS(rr_rig_schedule(&c, 0, &r, &xi), RR_ERR_RANGE, "schedule: speed/radius overflows");
    CHECK(isnan(r) && isnan(xi), "schedule: overflow -> NaN");
    rr_rig_config_default(&c);
    CHECK_STATUS(rr_rig_config_set(&c, "wheelset.spin_inertia_kg_m2", 1.5e308), RR_OK, "Iyy 1");
    CHECK_STATUS(rr_rig_config_set(&c, "wheelset_drive.drive_inertia_kg_m2", 1.5e308), RR_OK,
                 "Iyy 2");
    CHECK_STATUS(rr_rig_params_from(&c, NULL, &p), RR_ERR_RANGE, "from: Iyy overflows");
    CHECK(p.mass == 0.0 && p.Iyy == 0.0, "from: overflow -> p zeroed");
    CHECK_STATUS(rr_rig_config_check(&c, &bad), RR_ERR_RANGE, "check: Iyy overflows");
    CHECK(bad && strcmp(bad, "wheelset.spin_inertia_kg_m2") == 0, "check names the sum");
    test_report();
    return rr_test_summary();
}
