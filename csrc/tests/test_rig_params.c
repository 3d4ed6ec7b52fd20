/* test_rig_params.c - the rig's parameter declaration: defaults, setters,
 * checks, derivations, schedule, output names; every error status. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rr_test.h"
#include "rollerrig.h"

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
    return rr_test_summary();
}
