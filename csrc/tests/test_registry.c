/* test_registry.c - the creep-force methods' registry: lookup, defaults,
 * options set by name, checks driven by the descriptors and each method's
 * range edges, the dispatcher's and the field's refusals. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_creep.h"
#include "contact/rr_fastsim.h"
#include "contact/rr_polach.h"
#include "contact/rr_exact.h"
#include "rr_test.h"

/* problem c with the friction law fr (the tests vary the two apart): c's
 * law set to *fr, c returned (NULL stays NULL) */
static const rr_contact_problem *with_law(rr_contact_problem *c, const rr_friction *fr)
{
    if (c && fr)
        c->friction = *fr;
    return c;
}

static rr_contact_problem base_case(void)
{
    rr_contact_problem c = {0};    /* an ellipse problem */
    c.a = 0.006; c.b = 0.004; c.N = 1e4; c.G = 8.2e10; c.nu = 0.28;
    c.cx = 1e-3; c.cy = 0.0; c.cphi = 0.0; c.speed = 5.0;
    c.friction.mu0 = 0.3; c.friction.A = 1.0; c.friction.B = 0.0;
    return c;
}

static void test_lookup(void)
{
    static const char *const names[] = {"linear", "fastsim", "fastsim_blended",
                                        "modified_fastsim", "polach", "exact", "fastrip",
                                        "exact_table"};
    int i;
    CHECK(rr_method_count() == RR_METHOD_COUNT
          && RR_METHOD_COUNT == (int)(sizeof names / sizeof names[0]), "every method named");
    for (i = 0; i < RR_METHOD_COUNT; i++) {
        const rr_method_desc *d = rr_method_get(i);
        CHECK(d && strcmp(d->name, names[i]) == 0, "method names in rr_methods.def's order");
        CHECK(rr_method_find(names[i]) == i, "rr_method_find");
        CHECK(d && d->nopts <= RR_CREEP_MAX_OPTS && d->forces && d->cost && d->slope_scale
              && d->workspace_len && d->doc && d->doc[0], "descriptor complete");
        CHECK(d && (d->field == NULL) == (d->field_shape == NULL), "field and its shape paired");
    }
    CHECK(rr_method_get(-1) == NULL && rr_method_get(RR_METHOD_COUNT) == NULL,
          "rr_method_get out of range");
    CHECK_STATUS(rr_method_find("kalker"), RR_ERR_METHOD, "unknown name");
    CHECK_STATUS(rr_method_find(NULL), RR_ERR_NULL, "NULL name");
    CHECK(rr_method_get(RR_METHOD_LINEAR)->saturates == 0, "linear does not saturate");
    CHECK(rr_method_get(RR_METHOD_POLACH)->saturates == 1, "Polach saturates");
    CHECK(rr_method_get(RR_METHOD_FASTSIM)->field != NULL
          && rr_method_get(RR_METHOD_FASTSIM_BLENDED)->field != NULL
          && rr_method_get(RR_METHOD_MODIFIED_FASTSIM)->field != NULL
          && rr_method_get(RR_METHOD_LINEAR)->field == NULL
          && rr_method_get(RR_METHOD_POLACH)->field == NULL, "the FASTSIM variants have fields");
    CHECK(rr_method_option(rr_method_get(RR_METHOD_MODIFIED_FASTSIM), "beta") == RR_FASTSIM_BETA,
          "rr_method_option");
    CHECK(rr_method_option(rr_method_get(RR_METHOD_FASTSIM), "beta") == -1, "no beta in FASTSIM");
    CHECK(rr_method_option(NULL, "nx") == -1 && rr_method_option(rr_method_get(1), NULL) == -1,
          "rr_method_option NULL");
}

static void test_defaults_and_costs(void)
{
    rr_creep_opts o;
    int m;
    for (m = 0; m < RR_METHOD_COUNT; m++) {
        CHECK_STATUS(rr_creep_opts_default(&o, m), RR_OK, "defaults");
        CHECK_STATUS(rr_creep_opts_check(&o), RR_OK, "defaults are valid");
        /* only the exact solver needs workspace (its grid and FFT planes) */
        CHECK((rr_creep_workspace_len(&o, NULL) > 0) == (m == RR_METHOD_EXACT),
              "workspace only for the exact solver");
    }
    CHECK_STATUS(rr_creep_opts_default(&o, RR_METHOD_COUNT), RR_ERR_METHOD,
                 "default of a method past the table");
    CHECK(o.method == RR_METHOD_COUNT && isnan(o.v[0]), "that method: set, values NaN");
    CHECK_STATUS(rr_creep_opts_default(NULL, 0), RR_ERR_NULL, "default NULL");
    rr_creep_opts_default(&o, RR_METHOD_FASTSIM);
    CHECK(rr_creep_cost(&o) == 900.0, "FASTSIM 30 x 30 costs 900");
    CHECK(rr_creep_slope_scale(&o) == 1.0 && rr_creep_saturates(&o), "FASTSIM slope 1");
    rr_creep_opts_default(&o, RR_METHOD_LINEAR);
    CHECK(rr_creep_cost(&o) == 1.0 && !rr_creep_saturates(&o) && rr_creep_slope_scale(&o) == 1.0,
          "linear: cost 1, no saturation");
    rr_creep_opts_default(&o, RR_METHOD_POLACH);
    o.v[RR_POLACH_KA] = 0.7;
    o.v[RR_POLACH_KS] = 0.4;
    CHECK(rr_creep_slope_scale(&o) == 0.5 * (0.7 + 0.4), "Polach: (kA + kS)/2");
    rr_creep_opts_default(&o, RR_METHOD_MODIFIED_FASTSIM);
    CHECK(rr_creep_slope_scale(&o) == 0.54, "modified FASTSIM: k0");
    CHECK(o.v[RR_FASTSIM_SLIP_SPEED] == RR_SLIP_RIGID, "modified FASTSIM: rigid slip speed");
    o.v[RR_FASTSIM_K0] = 2.0;
    CHECK(rr_creep_cost(&o) == 0.0 && isnan(rr_creep_slope_scale(&o)) && !rr_creep_saturates(&o),
          "invalid options: cost 0, slope NaN");
    CHECK(rr_creep_cost(NULL) == 0.0 && isnan(rr_creep_slope_scale(NULL)), "NULL options");
}

static void test_set(void)
{
    rr_creep_opts o;
    rr_creep_opts_default(&o, RR_METHOD_FASTSIM);
    CHECK_STATUS(rr_creep_opts_set(&o, "nx", 20.0), RR_OK, "set nx");
    CHECK(o.v[RR_FASTSIM_NX] == 20.0, "nx set");
    CHECK_STATUS(rr_creep_opts_set(&o, "nx", 20.5), RR_ERR_GRID, "nx not an integer");
    CHECK_STATUS(rr_creep_opts_set(&o, "nx", NAN), RR_ERR_GRID, "nx NaN");
    CHECK_STATUS(rr_creep_opts_set(&o, "nx", 0.0), RR_ERR_GRID, "nx = 0");
    CHECK_STATUS(rr_creep_opts_set(&o, "nx", 4097.0), RR_ERR_GRID, "nx = 4097");
    CHECK_STATUS(rr_creep_opts_set(&o, "nx", 4294967297.0), RR_ERR_GRID, "nx = 2^32 + 1");
    CHECK(o.v[RR_FASTSIM_NX] == 20.0, "a refused value leaves the option");
    CHECK_STATUS(rr_creep_opts_set(&o, "bound", 1.0), RR_OK, "bound elliptic");
    CHECK_STATUS(rr_creep_opts_set(&o, "bound", 2.0), RR_ERR_METHOD, "bound 2");
    CHECK_STATUS(rr_creep_opts_set(&o, "grid", 0.5), RR_ERR_METHOD, "grid 0.5");
    CHECK_STATUS(rr_creep_opts_set(&o, "k0", 0.5), RR_ERR_PARAM, "FASTSIM has no k0");
    CHECK_STATUS(rr_creep_opts_set(&o, NULL, 0.5), RR_ERR_NULL, "NULL name");
    CHECK_STATUS(rr_creep_opts_set(NULL, "nx", 5.0), RR_ERR_NULL, "NULL options");
    o.method = 42;
    CHECK_STATUS(rr_creep_opts_set(&o, "nx", 5.0), RR_ERR_METHOD, "unknown method");
    rr_creep_opts_default(&o, RR_METHOD_MODIFIED_FASTSIM);
    CHECK_STATUS(rr_creep_opts_set(&o, "beta", INFINITY), RR_ERR_NONFINITE, "beta inf");
    CHECK_STATUS(rr_creep_opts_set(&o, "k0", NAN), RR_ERR_NONFINITE, "k0 NaN");
    CHECK_STATUS(rr_creep_opts_set(&o, "beta", 1e300), RR_OK, "beta 1e300");
    /* a constraint across options waits for the check */
    rr_creep_opts_default(&o, RR_METHOD_POLACH);
    CHECK_STATUS(rr_creep_opts_set(&o, "kA", 0.3), RR_OK, "kA 0.3 below kS = 1: set");
    CHECK_STATUS(rr_creep_opts_check(&o), RR_ERR_PARAM, "then kS > kA refused");
    {
        int bad = 99;
        CHECK_STATUS(rr_creep_opts_check_at(&o, &bad), RR_ERR_PARAM, "check_at");
        CHECK(bad == RR_POLACH_KS, "kS named");
        o.method = -3;
        CHECK_STATUS(rr_creep_opts_check_at(&o, &bad), RR_ERR_METHOD, "check_at method");
        CHECK(bad == -1, "no option to blame");
        CHECK_STATUS(rr_creep_opts_check_at(NULL, &bad), RR_ERR_NULL, "check_at NULL");
    }
}

/* Each option's range edges, open or closed, from its descriptor. */
static void test_edges(void)
{
    int m, i;
    for (m = 0; m < RR_METHOD_COUNT; m++) {
        const rr_method_desc *d = rr_method_get(m);
        for (i = 0; i < d->nopts; i++) {
            const rr_creep_option *op = &d->opts[i];
            rr_creep_opts o;
            int bad, st;
            char what[96];
            rr_creep_opts_default(&o, m);
            if (isfinite(op->lo)) {
                o.v[i] = op->lo;
                st = rr_creep_opts_check_at(&o, &bad);
                snprintf(what, sizeof what, "%s.%s at its lower end", d->name, op->name);
                /* Polach's kS = kA: at kS's lower end kA is 1, so kS <= kA holds */
                CHECK(op->lo_open ? st == op->status && bad == i : st == RR_OK, what);
                o.v[i] = op->lo - (op->type == RR_OPT_REAL ? 1e-9 : 1.0);
                snprintf(what, sizeof what, "%s.%s below its range", d->name, op->name);
                CHECK(rr_creep_opts_check_at(&o, &bad) == op->status && bad == i, what);
            }
            rr_creep_opts_default(&o, m);
            if (isfinite(op->hi)) {
                o.v[i] = op->hi;
                st = rr_creep_opts_check_at(&o, &bad);
                snprintf(what, sizeof what, "%s.%s at its upper end", d->name, op->name);
                CHECK(op->hi_open ? st == op->status && bad == i : st == RR_OK, what);
                o.v[i] = op->hi + (op->type == RR_OPT_REAL ? 1e-9 : 1.0);
                snprintf(what, sizeof what, "%s.%s above its range", d->name, op->name);
                CHECK(rr_creep_opts_check_at(&o, &bad) == op->status && bad == i, what);
            }
            rr_creep_opts_default(&o, m);
            o.v[i] = NAN;
            snprintf(what, sizeof what, "%s.%s NaN", d->name, op->name);
            CHECK(rr_creep_opts_check(&o)
                      == (op->type == RR_OPT_REAL ? RR_ERR_NONFINITE : op->status), what);
            if (op->type == RR_OPT_CHOICE) {
                int n = 0;
                while (op->choices[n])
                    n++;
                snprintf(what, sizeof what, "%s.%s: one name per value", d->name, op->name);
                CHECK(op->lo == 0.0 && op->hi == n - 1, what);
            }
        }
    }
}

static void test_dispatch(void)
{
    rr_contact_problem c = base_case();
    rr_friction fr = {0.3, 1.0, 0.0};
    rr_creep_opts o;
    rr_forces f;
    rr_fastsim_field fl;
    double x[4];
    memset(&fl, 0, sizeof fl);
    fl.x = x;
    rr_creep_opts_default(&o, RR_METHOD_POLACH);
    CHECK_STATUS(rr_creep_field(with_law(&c, &fr), &o, &f, &fl), RR_ERR_METHOD, "Polach has no field");
    CHECK(isnan(f.fx), "no field: NaN forces");
    rr_creep_opts_default(&o, RR_METHOD_FASTSIM);
    o.v[RR_FASTSIM_NX] = 2;
    o.v[RR_FASTSIM_NY] = 2;
    CHECK_STATUS(rr_creep_field(with_law(&c, &fr), &o, &f, &fl), RR_OK, "FASTSIM field 2 x 2");
    CHECK(isfinite(f.fx) && isfinite(x[0]), "FASTSIM field: finite");
    CHECK_STATUS(rr_creep_forces(with_law(&c, &fr), NULL, &f), RR_ERR_NULL, "NULL options");
    CHECK_STATUS(rr_creep_forces(with_law(&c, &fr), &o, NULL), RR_ERR_NULL, "NULL output");
    CHECK_STATUS(rr_creep_forces_work(with_law(&c, &fr), &o, NULL, 0, &f), RR_OK, "no workspace needed");
    o.v[RR_FASTSIM_NX] = 2.5;
    CHECK_STATUS(rr_creep_forces(with_law(&c, &fr), &o, &f), RR_ERR_GRID, "nx = 2.5 refused");
    CHECK(isnan(f.fx), "refused: NaN");
    CHECK_STATUS(rr_fastsim(with_law(&c, &fr), &o, &f, NULL), RR_ERR_GRID, "rr_fastsim nx = 2.5 refused");
}

static int same_forces(const rr_forces *a, const rr_forces *b)
{
    return memcmp(a, b, sizeof *a) == 0;
}

/* Options checked once (rr_creep_check), then many cases without checking
 * them again (rr_creep_forces_checked): the dispatcher's doubles and
 * statuses for every method, good and bad cases, Coulomb and falling
 * friction; what a C caller can get wrong refused. */
static void test_checked(void)
{
    static double work[1 << 18];
    rr_contact_problem cases[6];
    rr_friction laws[3] = {{0.3, 1.0, 0.0}, {0.3, 0.4, 0.6}, {NAN, 1.0, 0.0}};
    rr_creep_checked k;
    rr_creep_opts o;
    rr_forces f, g;
    int m, i, j, bad;
    char what[96];

    for (i = 0; i < 6; i++)
        cases[i] = base_case();
    cases[1].cy = 2e-3; cases[1].cphi = 0.5;    /* towards full sliding, with spin */
    cases[2].cx = -4e-2;
    cases[3].N = -1.0;                          /* refused by every method */
    cases[4].a = NAN;
    cases[5].speed = 0.0;                       /* refused with falling friction */
    for (m = 0; m < rr_method_count(); m++) {
        rr_creep_opts_default(&o, m);
        if (m == RR_METHOD_EXACT)
            o.v[RR_EXACT_NX] = o.v[RR_EXACT_NY] = 8;   /* a small grid: a quick test */
        snprintf(what, sizeof what, "%s: checked", rr_method_get(m)->name);
        CHECK_STATUS(rr_creep_check(&k, &o, &bad), RR_OK, what);
        CHECK(bad == -1 && k.d == rr_method_get(m) && k.work_len == rr_creep_workspace_len(&o, NULL)
              && k.cost == rr_creep_cost(&o), "the checked record: method, workspace, cost");
        CHECK(k.work_len <= sizeof work / sizeof work[0], "the test's workspace suffices");
        for (i = 0; i < 6; i++)
            for (j = 0; j < 3; j++) {
                const int st = rr_creep_forces_work(with_law(&cases[i], &laws[j]), &o, work, k.work_len,
                                                    &f);
                snprintf(what, sizeof what, "%s: case %d, law %d: as the dispatcher",
                         rr_method_get(m)->name, i, j);
                CHECK_STATUS(rr_creep_forces_checked(&k, with_law(&cases[i], &laws[j]), work, k.work_len,
                                                     NULL, &g), st, what);
                CHECK(same_forces(&f, &g), what);
            }
        CHECK_STATUS(rr_creep_forces_checked(&k, NULL, work, k.work_len, NULL, &g),
                     RR_ERR_NULL, "NULL problem");
        CHECK(isnan(g.fx), "NULL: NaN");
        if (k.work_len > 0) {
            CHECK_STATUS(rr_creep_forces_checked(&k, with_law(&cases[0], &laws[0]), NULL, 0, NULL, &g),
                         RR_ERR_WORKSPACE, "no workspace");
            CHECK_STATUS(rr_creep_forces_checked(&k, with_law(&cases[0], &laws[0]), work, k.work_len - 1,
                                                 NULL, &g), RR_ERR_WORKSPACE, "one double short");
            CHECK(isnan(g.fx), "refused: NaN");
        }
    }
    /* refused options leave no record the forces take */
    rr_creep_opts_default(&o, RR_METHOD_POLACH);
    o.v[RR_POLACH_KS] = 0.9;
    o.v[RR_POLACH_KA] = 0.5;
    CHECK_STATUS(rr_creep_check(&k, &o, &bad), RR_ERR_PARAM, "kS > kA refused");
    CHECK(bad == RR_POLACH_KS, "naming kS");
    CHECK_STATUS(rr_creep_forces_checked(&k, with_law(&cases[0], &laws[0]), NULL, 0, NULL, &g),
                 RR_ERR_NULL, "a refused record is not used");
    CHECK(isnan(g.fx) && isnan(g.fy) && isnan(g.mz), "refused: NaN forces");
    memset(&k, 0, sizeof k);
    CHECK_STATUS(rr_creep_forces_checked(&k, with_law(&cases[0], &laws[0]), NULL, 0, NULL, &g),
                 RR_ERR_NULL, "a zeroed record is not one");
    rr_creep_opts_default(&o, RR_METHOD_FASTSIM);
    CHECK_STATUS(rr_creep_check(&k, &o, NULL), RR_OK, "FASTSIM checked");
    k.o.method = RR_METHOD_COUNT;
    CHECK_STATUS(rr_creep_forces_checked(&k, with_law(&cases[0], &laws[0]), NULL, 0, NULL, &g),
                 RR_ERR_NULL, "a method that is not the record's");
    k.o.method = RR_METHOD_POLACH;
    CHECK_STATUS(rr_creep_forces_checked(&k, with_law(&cases[0], &laws[0]), NULL, 0, NULL, &g),
                 RR_ERR_NULL, "nor another method's");
    CHECK_STATUS(rr_creep_forces_checked(NULL, with_law(&cases[0], &laws[0]), NULL, 0, NULL, &g),
                 RR_ERR_NULL, "NULL record");
    CHECK_STATUS(rr_creep_check(&k, &o, NULL), RR_OK, "FASTSIM checked again");
    CHECK_STATUS(rr_creep_forces_checked(&k, with_law(&cases[0], &laws[0]), NULL, 0, NULL, NULL),
                 RR_ERR_NULL, "NULL output");
    CHECK_STATUS(rr_creep_check(NULL, &o, &bad), RR_ERR_NULL, "NULL record to fill");
    CHECK_STATUS(rr_creep_check(&k, NULL, &bad), RR_ERR_NULL, "NULL options");
    CHECK(bad == -1, "none to blame");
}

int main(void)
{
    test_lookup();
    test_defaults_and_costs();
    test_set();
    test_edges();
    test_dispatch();
    test_checked();
    return rr_test_summary();
}
