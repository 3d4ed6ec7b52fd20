/* test_problem.c - the contact problem every method takes (rr_contact.h):
 * its check and the member it names, each method with each patch, the grid
 * problem through the registry against the exact solver itself, the
 * workspace a descriptor asks for a grid, and rr_creep_blame. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_creep.h"
#include "contact/rr_exact.h"
#include "contact/rr_exact_table.h"
#include "contact/rr_fastrip.h"
#include "contact/rr_fastsim.h"
#include "contact/rr_linear.h"
#include "contact/rr_polach.h"
#include "rr_test.h"

/* a/b = 1.5, 10 kN, steel, Coulomb 0.3: a zeroed problem is an ellipse one */
static rr_contact_problem ellipse(void)
{
    rr_contact_problem p = {0};
    p.a = 6e-3;
    p.b = 4e-3;
    p.N = 1e4;
    p.G = 8.2e10;
    p.nu = 0.28;
    p.cx = 1e-3;
    p.cy = 2e-4;
    p.cphi = 0.3;
    p.speed = 5.0;
    p.friction.mu0 = 0.3;
    p.friction.A = 1.0;
    p.friction.B = 0.0;
    return p;
}

#define MX 24
#define MY 20
static double gap[MX * MY];

/* a grid problem on a bowl (not Hertz's: a quartic term), its contact well
 * inside the grid */
static rr_contact_problem bowl(void)
{
    rr_contact_problem p = ellipse();
    int i, j;
    p.a = p.b = 0.0;                  /* not the grid's: unused */
    p.patch = RR_PATCH_GRID;
    p.grid.mx = MX;
    p.grid.my = MY;
    p.grid.dx = 6e-4;
    p.grid.dy = 5e-4;
    p.grid.x0 = -0.5 * (MX - 1) * p.grid.dx;
    p.grid.y0 = -0.5 * (MY - 1) * p.grid.dy;
    for (j = 0; j < MY; j++)
        for (i = 0; i < MX; i++) {
            const double x = p.grid.x0 + i * p.grid.dx, y = p.grid.y0 + j * p.grid.dy;
            gap[j * MX + i] = 2.0 * x * x + 3.0 * y * y + 4e4 * x * x * x * x;
        }
    p.h = gap;
    return p;
}

/* one member spoilt, the status and member the check must give */
typedef struct {
    const char *what;
    int member, status;
    double value;
} spoilt;

static void set_member(rr_contact_problem *p, int m, double v)
{
    switch (m) {
    case RR_PF_A: p->a = v; break;
    case RR_PF_B: p->b = v; break;
    case RR_PF_N: p->N = v; break;
    case RR_PF_G: p->G = v; break;
    case RR_PF_NU: p->nu = v; break;
    case RR_PF_CX: p->cx = v; break;
    case RR_PF_CY: p->cy = v; break;
    case RR_PF_CPHI: p->cphi = v; break;
    case RR_PF_SPEED: p->speed = v; break;
    case RR_PF_MU0: p->friction.mu0 = v; break;
    case RR_PF_FRICTION_A: p->friction.A = v; break;
    case RR_PF_FRICTION_B: p->friction.B = v; break;
    case RR_PF_MX: p->grid.mx = (int)v; break;
    case RR_PF_MY: p->grid.my = (int)v; break;
    case RR_PF_DX: p->grid.dx = v; break;
    case RR_PF_DY: p->grid.dy = v; break;
    case RR_PF_X0: p->grid.x0 = v; break;
    case RR_PF_Y0: p->grid.y0 = v; break;
    case RR_PF_PATCH: p->patch = (int)v; break;
    default: break;
    }
}

static void test_check(void)
{
    static const spoilt ell[] = {
        {"a NaN", RR_PF_A, RR_ERR_NONFINITE, NAN}, {"b inf", RR_PF_B, RR_ERR_NONFINITE, INFINITY},
        {"N NaN", RR_PF_N, RR_ERR_NONFINITE, NAN}, {"cphi inf", RR_PF_CPHI, RR_ERR_NONFINITE,
                                                    -INFINITY},
        {"speed NaN", RR_PF_SPEED, RR_ERR_NONFINITE, NAN},
        {"a = 0", RR_PF_A, RR_ERR_GEOMETRY, 0.0}, {"b < 0", RR_PF_B, RR_ERR_GEOMETRY, -1e-3},
        {"N = 0", RR_PF_N, RR_ERR_LOAD, 0.0}, {"G < 0", RR_PF_G, RR_ERR_MATERIAL, -1.0},
        {"nu > 0.5", RR_PF_NU, RR_ERR_MATERIAL, 0.5000000000000001},
        {"speed < 0", RR_PF_SPEED, RR_ERR_SPEED, -1.0},
        {"a subnormal", RR_PF_A, RR_ERR_RANGE, 1e-310}, {"N subnormal", RR_PF_N, RR_ERR_RANGE,
                                                         4e-320},
        {"G subnormal", RR_PF_G, RR_ERR_RANGE, 1e-315},
        {"mu0 NaN", RR_PF_MU0, RR_ERR_NONFINITE, NAN},
        {"mu0 = 0", RR_PF_MU0, RR_ERR_FRICTION, 0.0},
        {"A = 1.5", RR_PF_FRICTION_A, RR_ERR_FRICTION, 1.5},
        {"B < 0", RR_PF_FRICTION_B, RR_ERR_FRICTION, -0.1},
        {"mu0 1e101", RR_PF_MU0, RR_ERR_RANGE, 1e101},
        {"B 1e101", RR_PF_FRICTION_B, RR_ERR_RANGE, 1e101},
        {"patch 2", RR_PF_PATCH, RR_ERR_PATCH, 2.0},
    };
    static const spoilt grid[] = {
        {"mx = 0", RR_PF_MX, RR_ERR_GRID, 0.0}, {"my too many", RR_PF_MY, RR_ERR_GRID,
                                                 RR_CONTACT_MAX_GRID + 1.0},
        {"dx NaN", RR_PF_DX, RR_ERR_NONFINITE, NAN}, {"y0 inf", RR_PF_Y0, RR_ERR_NONFINITE,
                                                      INFINITY},
        {"dx = 0", RR_PF_DX, RR_ERR_GEOMETRY, 0.0}, {"dy < 0", RR_PF_DY, RR_ERR_GEOMETRY, -1.0},
        {"dy subnormal", RR_PF_DY, RR_ERR_RANGE, 1e-320}, {"N = 0", RR_PF_N, RR_ERR_LOAD, 0.0},
        {"mu0 < 0", RR_PF_MU0, RR_ERR_FRICTION, -0.3},
    };
    char what[120];
    rr_contact_problem p;
    int k, field;

    p = ellipse();
    field = -7;
    CHECK_STATUS(rr_contact_problem_check(&p, &field), RR_OK, "the ellipse is valid");
    CHECK(field == RR_PF_NONE, "a valid problem blames no member");
    CHECK_STATUS(rr_contact_problem_check(&p, NULL), RR_OK, "without the report");
    for (k = 0; k < RR_COUNTOF(ell); k++) {
        p = ellipse();
        set_member(&p, ell[k].member, ell[k].value);
        field = -7;
        snprintf(what, sizeof what, "ellipse, %s", ell[k].what);
        CHECK_STATUS(rr_contact_problem_check(&p, &field), ell[k].status, what);
        CHECK(field == ell[k].member, what);
        CHECK_STATUS(rr_contact_problem_check(&p, NULL), ell[k].status, what);
    }
    /* the order is that of the former rr_contact_check, then rr_friction_check */
    p = ellipse();
    p.N = -1.0;
    p.friction.mu0 = NAN;
    CHECK_STATUS(rr_contact_problem_check(&p, &field), RR_ERR_LOAD, "the case before the law");
    CHECK(field == RR_PF_N, "the case before the law: N");
    p = ellipse();
    p.G = 0.0;
    p.cx = NAN;
    CHECK_STATUS(rr_contact_problem_check(&p, &field), RR_ERR_NONFINITE,
                 "every number finite first");
    CHECK(field == RR_PF_CX, "every number finite first: cx");

    p = bowl();
    CHECK_STATUS(rr_contact_problem_check(&p, &field), RR_OK, "the bowl is valid");
    CHECK(field == RR_PF_NONE, "the bowl: no member");
    for (k = 0; k < RR_COUNTOF(grid); k++) {
        p = bowl();
        set_member(&p, grid[k].member, grid[k].value);
        field = -7;
        snprintf(what, sizeof what, "grid, %s", grid[k].what);
        CHECK_STATUS(rr_contact_problem_check(&p, &field), grid[k].status, what);
        CHECK(field == grid[k].member, what);
    }
    p = bowl();
    p.h = NULL;
    CHECK_STATUS(rr_contact_problem_check(&p, &field), RR_ERR_NULL, "grid, h NULL");
    CHECK(field == RR_PF_H, "grid, h NULL: h");
    p = bowl();
    gap[MX * MY - 1] = NAN;
    CHECK_STATUS(rr_contact_problem_check(&p, &field), RR_ERR_NONFINITE, "grid, h NaN");
    CHECK(field == RR_PF_H, "grid, h NaN: h");
    bowl();
    field = -7;
    CHECK_STATUS(rr_contact_problem_check(NULL, &field), RR_ERR_NULL, "NULL problem");
    CHECK(field == RR_PF_NONE, "NULL problem: no member");

    /* the names, one a member */
    CHECK(strcmp(rr_problem_field_name(RR_PF_MU0), "friction.mu0") == 0, "name of mu0");
    CHECK(strcmp(rr_problem_field_name(RR_PF_DX), "grid.dx") == 0, "name of dx");
    CHECK(strcmp(rr_problem_field_name(RR_PF_H), "h") == 0, "name of h");
    CHECK(strcmp(rr_problem_field_name(RR_PF_NONE), "") == 0, "name of none");
    CHECK(!rr_problem_field_name(-1) && !rr_problem_field_name(RR_PF_COUNT), "no such member");
    for (k = 1; k < RR_PF_COUNT; k++)
        CHECK(rr_problem_field_name(k) && rr_problem_field_name(k)[0], "every member named");
}

static int all_nan(const rr_forces *f)
{
    return isnan(f->fx) && isnan(f->fy) && isnan(f->mz);
}

/* the methods of the ellipse refuse a grid problem, through the dispatcher
 * and their own functions; exact takes it, on the workspace it asks for */
static void test_patches(void)
{
    const rr_contact_problem g = bowl();
    rr_contact_problem e = ellipse();
    rr_creep_opts o;
    rr_creep_checked k;
    rr_forces f;
    rr_traction_field fl;
    char what[120];
    int m;

    memset(&fl, 0, sizeof fl);
    for (m = 0; m < rr_method_count(); m++) {
        const rr_method_desc *d = rr_method_get(m);
        rr_creep_opts_default(&o, m);
        rr_creep_check(&k, &o, NULL);
        snprintf(what, sizeof what, "%s: the ellipse", d->name);
        {
            const size_t wl = rr_creep_workspace_len(&o, NULL);
            double *work = wl ? calloc(wl, sizeof *work) : NULL;
            CHECK(rr_creep_forces_work(&e, &o, work, wl, &f) >= 0 && !all_nan(&f), what);
            free(work);
        }
        if (d->takes_grid)
            continue;
        snprintf(what, sizeof what, "%s: a grid problem refused", d->name);
        CHECK(rr_creep_workspace_len(&o, &g.grid) == 0, what);
        CHECK_STATUS(rr_creep_forces(&g, &o, &f), RR_ERR_PATCH, what);
        CHECK(all_nan(&f), what);
        CHECK_STATUS(rr_creep_forces_checked(&k, &g, NULL, 0, NULL, &f), RR_ERR_PATCH, what);
        CHECK(rr_creep_blame(&k, &g, RR_ERR_PATCH) == RR_PF_PATCH, what);
        if (d->field)
            CHECK_STATUS(rr_creep_field(&g, &o, &f, &fl), RR_ERR_PATCH, what);
    }
    /* the methods' own functions */
    rr_creep_opts_default(&o, RR_METHOD_FASTSIM);
    CHECK_STATUS(rr_fastsim(&g, &o, &f, NULL), RR_ERR_PATCH, "rr_fastsim: grid");
    CHECK_STATUS(rr_linear(&g, &f), RR_ERR_PATCH, "rr_linear: grid");
    CHECK(all_nan(&f), "rr_linear: grid: NaN");
    CHECK_STATUS(rr_polach(&g, 1.0, 1.0, &f), RR_ERR_PATCH, "rr_polach: grid");
    rr_creep_opts_default(&o, RR_METHOD_FASTRIP);
    CHECK_STATUS(rr_fastrip(&g, &o, &f), RR_ERR_PATCH, "rr_fastrip: grid");
    CHECK_STATUS(rr_exact_table_forces(&rr_exact_table_builtin, &g, &f), RR_ERR_PATCH,
                 "rr_exact_table_forces: grid");
    CHECK(all_nan(&f), "rr_exact_table_forces: grid: NaN");
    e.patch = 3;
    CHECK_STATUS(rr_linear(&e, &f), RR_ERR_PATCH, "rr_linear: no such patch");
}

/* The method "exact" on a grid problem: rr_exact_solve of the same h, bit
 * for bit, on the workspace rr_creep_workspace_len asks for the grid (one
 * double short refused); nx, ny unused.  On the ellipse: its own grid. */
static void test_exact_grid(void)
{
    rr_contact_problem g = bowl();
    rr_creep_opts o;
    rr_exact_problem pb;
    rr_exact_result r;
    rr_forces f, f2;
    size_t wl;
    double *work, *w2;
    int st, st2;

    rr_creep_opts_default(&o, RR_METHOD_EXACT);
    o.v[RR_EXACT_NX] = 5;              /* an ellipse's grid: not the problem's */
    wl = rr_creep_workspace_len(&o, &g.grid);
    CHECK(wl == rr_exact_workspace_len(MX, MY) && wl > 0, "exact: the grid's workspace");
    CHECK(rr_creep_workspace_len(&o, NULL) == rr_exact_workspace_len(5 + 2 * RR_EXACT_MARGIN,
                                                                      27 + 2 * RR_EXACT_MARGIN),
          "exact: the ellipse's workspace");
    work = calloc(wl, sizeof *work);
    w2 = calloc(wl, sizeof *w2);
    st = rr_creep_forces_work(&g, &o, work, wl, &f);
    CHECK_STATUS(st, RR_OK, "exact: the grid problem");
    CHECK_STATUS(rr_exact_problem_from(&g, &o, &pb), RR_OK, "exact: its solver's problem");
    CHECK(pb.h == g.h && pb.grid.mx == MX && pb.grid.dx == g.grid.dx, "the problem's grid and h");
    st2 = rr_exact_solve(&pb, w2, wl, &r, NULL);
    CHECK(st2 == st && r.fx == f.fx && r.fy == f.fy && r.mz == f.mz,
          "exact through the registry: rr_exact_solve's doubles");
    CHECK(f.fx < 0.0 && fabs(f.fx) < 0.3 * 1e4, "the bowl's forces: against cx, below mu N");
    CHECK_STATUS(rr_creep_forces_work(&g, &o, work, wl - 1, &f2), RR_ERR_WORKSPACE,
                 "exact: one double short");
    CHECK_STATUS(rr_creep_forces(&g, &o, &f2), RR_ERR_WORKSPACE, "exact: no workspace");
    CHECK(all_nan(&f2), "exact: no workspace: NaN");
    /* falling friction is refused on a grid too, and blamed on the law */
    {
        rr_creep_checked k;
        g.friction.A = 0.4;
        g.friction.B = 0.6;
        rr_creep_check(&k, &o, NULL);
        st = rr_creep_forces_work(&g, &o, work, wl, &f2);
        CHECK_STATUS(st, RR_ERR_FRICTION, "exact: a falling law on a grid");
        CHECK(rr_creep_blame(&k, &g, st) == RR_PF_FRICTION_A, "exact: the law blamed");
        g = bowl();
        g.N = -1.0;
        st = rr_creep_forces_work(&g, &o, work, wl, &f2);
        CHECK_STATUS(st, RR_ERR_LOAD, "exact: a grid problem's load");
        CHECK(rr_creep_blame(&k, &g, st) == RR_PF_N, "exact: N blamed");
    }
    free(work);
    free(w2);
}

/* rr_creep_blame: the member for what a method asks of a valid problem */
static void test_blame(void)
{
    rr_contact_problem p = ellipse();
    rr_creep_opts o;
    rr_creep_checked k;
    rr_forces f;
    int st;

    rr_creep_opts_default(&o, RR_METHOD_FASTSIM);
    rr_creep_check(&k, &o, NULL);
    p.friction.A = 0.4;
    p.friction.B = 0.6;
    p.speed = 0.0;
    st = rr_creep_forces_checked(&k, &p, NULL, 0, NULL, &f);
    CHECK_STATUS(st, RR_ERR_SPEED, "fastsim: falling friction at rest");
    CHECK(rr_creep_blame(&k, &p, st) == RR_PF_SPEED, "fastsim: the speed blamed");
    rr_creep_opts_default(&o, RR_METHOD_FASTRIP);
    rr_creep_check(&k, &o, NULL);
    p.speed = 5.0;
    st = rr_creep_forces_checked(&k, &p, NULL, 0, NULL, &f);
    CHECK_STATUS(st, RR_ERR_FRICTION, "fastrip: a falling law");
    CHECK(rr_creep_blame(&k, &p, st) == RR_PF_FRICTION_A, "fastrip: the law blamed");
    rr_creep_opts_default(&o, RR_METHOD_EXACT_TABLE);
    rr_creep_check(&k, &o, NULL);
    p = ellipse();
    p.nu = 0.3;
    st = rr_creep_forces_checked(&k, &p, NULL, 0, NULL, &f);
    CHECK_STATUS(st, RR_ERR_TABLE, "exact_table: nu not its own");
    CHECK(rr_creep_blame(&k, &p, st) == RR_PF_NU, "exact_table: nu blamed");
    p = ellipse();
    p.a = 0.06;
    p.b = 0.004;
    st = rr_creep_forces_checked(&k, &p, NULL, 0, NULL, &f);
    CHECK_STATUS(st, RR_ERR_TABLE, "exact_table: a/b = 15");
    CHECK(rr_creep_blame(&k, &p, st) == RR_PF_A, "exact_table: a/b blamed on a");
    p = ellipse();
    p.G = -1.0;
    st = rr_creep_forces_checked(&k, &p, NULL, 0, NULL, &f);
    CHECK(rr_creep_blame(&k, &p, st) == RR_PF_G, "exact_table: the check's member");
    /* a result out of range: no one member (the linear theory's overflow) */
    rr_creep_opts_default(&o, RR_METHOD_LINEAR);
    rr_creep_check(&k, &o, NULL);
    p = ellipse();
    p.cx = 1e300;
    p.a = 1e12;
    st = rr_creep_forces_checked(&k, &p, NULL, 0, NULL, &f);
    CHECK_STATUS(st, RR_ERR_RANGE, "linear: overflow");
    CHECK(rr_creep_blame(&k, &p, st) == RR_PF_NONE, "linear: overflow blames no member");
    CHECK(rr_creep_blame(&k, &p, RR_OK) == RR_PF_NONE, "success blames none");
    CHECK(rr_creep_blame(NULL, &p, RR_ERR_LOAD) == RR_PF_NONE, "NULL record");
    CHECK(rr_creep_blame(&k, NULL, RR_ERR_LOAD) == RR_PF_NONE, "NULL problem");
    k.ready = 0;
    CHECK(rr_creep_blame(&k, &p, RR_ERR_LOAD) == RR_PF_NONE, "an unready record");
}

int main(void)
{
    test_check();
    test_patches();
    test_exact_grid();
    test_blame();
    return rr_test_summary();
}
