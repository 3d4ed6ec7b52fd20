/*
 * bench_rig.c - time the contact evaluation of the rig's wheelset on its
 * rollers and its parts, in C alone (no Python): the speed figures of
 * issue 3 (direct contact search, table lookup, Hertz, creepage, the whole
 * evaluation with FASTSIM 20x20, and the share of geometry in it).
 *
 * Built and run by benchmarks/bench_rig_contact.py, or by hand:
 *   cc -O3 -std=c99 -Wall -Wextra -pedantic -Werror -I csrc benchmarks/bench_rig.c \
 *      csrc/{util,contact,geometry,rig}/rr_*.c -lm -o bench_rig
 *   ./bench_rig [--states N] [--search-states M] [--solve-states K] [--repeats R]
 *               [--seed S] [--table-rows T] [--table-half-range H] [--only ITEM]
 *               [--dump FILE] [--check-states C]
 *
 * The rig is the default one of rollerrig/data/rig_default.toml, built as
 * rr.simulate() builds it (rr_rig_table_build, csrc/geometry/rr_tables.h):
 * a conical 1:20 wheel (r0 = 0.092 m) on a crowned roller (R0 = 0.16 m,
 * crown radius 0.06 m), both profiles over +-15 mm with
 * RR_RIG_PROFILE_POINTS (121) knots, the profiles' not-a-knot splines
 * (rr_spline_fit), profile origins 0.15 m from the centre line on both
 * sides; a contact table of T rows (161) over y = -H .. +H (8 mm; the
 * TOML's [integration] table_rows, table_half_range_m), the search options
 * of rr_search_opts_default.  The search items use the same splines
 * (rr_profile_surface).  Contact: E = 2.1e11 Pa,
 * nu = 0.28 (E* = rr_estar, G = E / (2 (1 + nu))), Polach's falling friction
 * mu0 = 0.4, A = 0.4, B = 0.6 s/m, vmin = 0.01 m/s; creep forces by FASTSIM
 * 20x20 (rect grid, parabolic bound, falling friction at the local slip
 * speed), FASTSIM 10x10, Polach (kA = 1, kS = 0.4) and linear theory.
 *
 * States (N of them, uniform random, splitmix64 from the seed): x +-1 mm,
 * y +-3 mm, yaw +-2 mrad, vx, vy +-0.02 m/s, yaw rate +-0.1 rad/s, roller
 * surface speed 5 m/s (roller_spin = 5 / R0), wheelset spin 5 / r0 (1 - c)
 * with c 0-5 % (braking), normal loads 400-700 N per wheel.
 *
 * Items (each timed over all N states (100000), or the first M (10000) for
 * the direct search and K (1000) for the direct wheelset solve, which cost
 * far more; best of R passes (5), the items taking turns within each round,
 * clock_gettime(CLOCK_MONOTONIC)):
 *   search          rr_contact_search of each wheel at the table's pose (per wheel)
 *   wheelset        rr_wheelset_contact: the direct pose solve (per wheelset)
 *   build           rr_rig_table_build of the T rows (per table; per row)
 *   lookup          rr_contact_table_lookup with slopes, both wheels (per wheelset)
 *   hertz           rr_hertz on the table's curvature sums (per wheel)
 *   creepage        rr_creepage on the motions and frames rr_rig_kinematics
 *                   gives (per wheel)
 *   kinematics      rr_rig_kinematics (per wheelset)
 *   contact_<m>     rr_rig_contact, the whole evaluation (per wheelset)
 * with <m> one of fastsim20, fastsim10, polach, linear, and fastsim20_rigid
 * (FASTSIM 20x20 with the friction at the rigid slip speed, for comparison).
 *
 * Derived: whole evaluation per wheel = contact_<m> / 2; contact placement
 * = kinematics - lookup - 2 creepage (the pose, the turn and yaw shift of
 * the contact points and their frames, the model check); geometry share =
 * (lookup + placement) / contact_<m>; kinematics share = kinematics /
 * contact_<m> (lookup, placement and both creepages).
 *
 * Prints one line of JSON: parameters, times in us per call ("us"), counts
 * of calls with an error status ("bad"), a checksum of outputs (so that no
 * call is optimised away) and the derived figures.  --only ITEM times that
 * item alone.  --dump FILE writes the states, the table and the FASTSIM
 * 20x20 outputs for the Python side (format in dump()).
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rollerrig.h"

/* ------------------------------------------------ the default rig (TOML) */
#define WHEEL_R0 0.092          /* wheelset.wheel_radius_m */
#define CONICITY 0.05           /* wheelset.conicity (1:20) */
#define WHEEL_HALF 0.015        /* wheelset.profile_half_width_m */
#define ROLLER_R0 0.160         /* roller.radius_m */
#define CROWN 0.060             /* roller.crown_radius_m */
#define HALF_SPACING 0.15       /* wheelset / roller contact_half_spacing_m */
#define YOUNG 2.1e11            /* contact.youngs_modulus_Pa */
#define POISSON 0.28            /* contact.poisson_ratio */
#define MU0 0.4                 /* scenario.mu0 */
#define POLACH_A 0.4            /* contact.polach_A */
#define POLACH_B 0.6            /* contact.polach_B_s_per_m */
#define POLACH_KA 1.0           /* contact.polach_kA */
#define POLACH_KS 0.4           /* contact.polach_kS */
#define VMIN 0.01               /* contact.min_rolling_speed_m_s */
#define FASTSIM_N 20            /* contact.fastsim_nx, fastsim_ny */
#define ROLLER_SPEED 5.0        /* scenario.roller_speed_m_s */

#define NP RR_RIG_PROFILE_POINTS  /* knots of each profile (0.25 mm apart) */
#define TABLE_ROWS 161           /* integration.table_rows */
#define TABLE_HALF 0.008         /* integration.table_half_range_m */

#define NMETHODS 5
static const char *const method_names[NMETHODS] = {"fastsim20", "fastsim10", "polach",
                                                   "linear", "fastsim20_rigid"};

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void die(const char *msg)
{
    fprintf(stderr, "bench_rig: %s\n", msg);
    exit(2);
}

static void *alloc(size_t n, size_t size)
{
    void *p = calloc(n, size);    /* zeroed: no pass pays the page faults */
    if (!p)
        die("out of memory");
    return p;
}

/* splitmix64 */
static uint64_t rng_state;

static double uniform(double lo, double hi)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return lo + (hi - lo) * (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static double wy[NP], wz[NP], wzup[NP], wm[NP], ry[NP], rz[NP], rzup[NP], rm[NP];
static double work[RR_RIG_TABLE_WORK_LEN];

/* the rig's geometry with the table's rows and half range */
static rr_rig_geometry rig_geometry(int rows, double half)
{
    rr_rig_geometry g;
    g.wheel_radius = WHEEL_R0;
    g.roller_radius = ROLLER_R0;
    g.profile_half_width = WHEEL_HALF;
    g.cone_angle = atan(CONICITY);
    g.crown_radius = CROWN;
    g.contact_half_spacing = HALF_SPACING;
    g.table_half_range = half;
    g.table_rows = rows;
    return g;
}

/* The wheel-roller pairs of the search items: the profiles and splines
 * rr_rig_table_build makes. */
static void rig_pair(rr_wheel_roller *left, rr_wheel_roller *right)
{
    rr_profile_points w, r;
    if (rr_profile_conical(atan(CONICITY), -WHEEL_HALF, WHEEL_HALF, NP, wy, wz)
        || rr_profile_crowned(CROWN, -WHEEL_HALF, WHEEL_HALF, NP, ry, rz))
        die("profiles failed");
    w.n = r.n = NP;
    w.y = wy; w.z = wz; r.y = ry; r.z = rz;
    w.end = r.end = RR_SPLINE_NOT_A_KNOT;
    if (rr_profile_surface(&w, wzup, wm, work) || rr_profile_surface(&r, rzup, rm, work))
        die("profile splines failed");
    left->wheel.n = NP; left->wheel.s = wy; left->wheel.z = wzup; left->wheel.m = wm;
    left->roller.n = NP; left->roller.s = ry; left->roller.z = rzup; left->roller.m = rm;
    left->r0 = WHEEL_R0;
    left->R0 = ROLLER_R0;
    left->wheel_y = HALF_SPACING;
    left->roller_y = HALF_SPACING;
    left->side = +1;
    *right = *left;
    right->side = -1;
}

static void method_opts(int k, rr_creep_opts *o)
{
    static const int methods[NMETHODS] = {RR_METHOD_FASTSIM, RR_METHOD_FASTSIM,
                                          RR_METHOD_POLACH, RR_METHOD_LINEAR,
                                          RR_METHOD_FASTSIM};
    rr_creep_opts_default(o, methods[k]);    /* rect grid, parabolic bound, local slip */
    if (methods[k] == RR_METHOD_FASTSIM) {
        o->v[RR_FASTSIM_NX] = o->v[RR_FASTSIM_NY] = k == 1 ? 10 : FASTSIM_N;
        if (k == 4)
            o->v[RR_FASTSIM_SLIP_SPEED] = RR_SLIP_RIGID;   /* one friction value per contact */
    }
    if (methods[k] == RR_METHOD_POLACH) {
        o->v[RR_POLACH_KA] = POLACH_KA;
        o->v[RR_POLACH_KS] = POLACH_KS;
    }
    if (rr_creep_opts_check(o))
        die("invalid creep options");
}

/* ------------------------------------------------------------- the data */
typedef struct {
    long n, nsearch, nsolve;
    rr_wheel_roller left, right;
    rr_search_opts so;
    rr_rig_geometry geometry;
    rr_contact_table table, scratch;     /* scratch: the build item's own rows */
    rr_rig_contact_model model[NMETHODS];
    rr_rig_state *s;
    double (*N)[2];
    double *z, *roll;                    /* the table's pose at each state */
    double *hA, *hB, *hN;                /* per wheel (2 n): Hertz inputs */
    rr_motion *wheel, *roller;           /* per state: creepage inputs */
    rr_contact_frame *frame;             /* per wheel */
    double checksum;
} bench;

static void setup(bench *b, long n, long nsearch, long nsolve, uint64_t seed, int parts,
                  int rows, double half)
{
    const double estar = rr_estar(YOUNG, POISSON, YOUNG, POISSON);
    long i;
    int k, m;

    b->n = n;
    b->nsearch = nsearch;
    b->nsolve = nsolve;
    rig_pair(&b->left, &b->right);
    rr_search_opts_default(&b->so);
    b->geometry = rig_geometry(rows, half);
    b->table.data = alloc((size_t)rr_contact_table_len(rows), sizeof(double));
    if (rr_rig_table_build(&b->geometry, b->table.data, rr_contact_table_len(rows), work,
                           RR_RIG_TABLE_WORK_LEN, &b->table, NULL))
        die("table build failed");
    b->scratch = b->table;
    b->scratch.data = alloc((size_t)rr_contact_table_len(rows), sizeof(double));
    for (m = 0; m < NMETHODS; m++) {
        rr_rig_contact_model *md = &b->model[m];
        md->table = &b->table;
        md->R0 = ROLLER_R0;
        md->estar = estar;
        md->G = YOUNG / (2.0 * (1.0 + POISSON));
        md->nu = POISSON;
        md->friction.mu0 = MU0;
        md->friction.A = POLACH_A;
        md->friction.B = POLACH_B;
        md->vmin = VMIN;
        method_opts(m, &md->creep);
        if (rr_rig_contact_check(md))
            die("invalid model");
    }

    b->s = alloc((size_t)n, sizeof *b->s);
    b->N = alloc((size_t)n, sizeof *b->N);
    rng_state = seed;
    for (i = 0; i < n; i++) {
        rr_rig_state *s = &b->s[i];
        s->x = uniform(-1e-3, 1e-3);
        s->y = uniform(-3e-3, 3e-3);
        s->yaw = uniform(-2e-3, 2e-3);
        s->vx = uniform(-0.02, 0.02);
        s->vy = uniform(-0.02, 0.02);
        s->yaw_rate = uniform(-0.1, 0.1);
        s->roller_spin = ROLLER_SPEED / ROLLER_R0;
        s->spin = ROLLER_SPEED / WHEEL_R0 * (1.0 - uniform(0.0, 0.05));
        b->N[i][0] = uniform(400.0, 700.0);
        b->N[i][1] = uniform(400.0, 700.0);
    }
    b->checksum = 0.0;
    if (!parts)
        return;

    /* the inputs of the part items, as rr_rig_kinematics and rr_rig_contact
     * hand them on */
    b->z = alloc((size_t)n, sizeof *b->z);
    b->roll = alloc((size_t)n, sizeof *b->roll);
    b->hA = alloc((size_t)(2 * n), sizeof *b->hA);
    b->hB = alloc((size_t)(2 * n), sizeof *b->hB);
    b->hN = alloc((size_t)(2 * n), sizeof *b->hN);
    b->wheel = alloc((size_t)n, sizeof *b->wheel);
    b->roller = alloc((size_t)n, sizeof *b->roller);
    b->frame = alloc((size_t)(2 * n), sizeof *b->frame);
    for (i = 0; i < n; i++) {
        rr_rig_pose pose;
        rr_wheel_contact w[2];
        rr_wheelset_pose tp;
        rr_contact_point cl, cr;
        if (rr_rig_kinematics(&b->model[0], &b->s[i], &pose, w) < 0
            || rr_contact_table_lookup(&b->table, b->s[i].y, &tp, NULL, &cl, &cr) < 0)
            die("a state has no contact (should not happen)");
        b->z[i] = tp.z;
        b->roll[i] = tp.roll;
        for (k = 0; k < 2; k++) {
            b->hA[2 * i + k] = w[k].geo.A;
            b->hB[2 * i + k] = w[k].geo.B;
            b->hN[2 * i + k] = b->N[i][k];
            b->frame[2 * i + k] = w[k].frame;
        }
        for (k = 0; k < 3; k++) {
            b->wheel[i].c[k] = pose.c[k];
            b->wheel[i].v[k] = pose.v[k];
            b->wheel[i].w[k] = pose.w[k];
            b->roller[i].c[k] = b->roller[i].v[k] = b->roller[i].w[k] = 0.0;
        }
        b->roller[i].c[2] = -ROLLER_R0;
        b->roller[i].w[1] = -b->s[i].roller_spin;
    }
}

/* ---------------------------------------------------------------- items */
enum {
    IT_SEARCH, IT_WHEELSET, IT_BUILD, IT_LOOKUP, IT_HERTZ, IT_CREEPAGE, IT_KINEMATICS,
    IT_CONTACT, IT_COUNT = IT_CONTACT + NMETHODS
};

static char item_names[IT_COUNT][32];

static void name_items(void)
{
    static const char *const fixed[IT_CONTACT] = {"search", "wheelset", "build", "lookup",
                                                  "hertz", "creepage", "kinematics"};
    int k;
    for (k = 0; k < IT_CONTACT; k++)
        strcpy(item_names[k], fixed[k]);
    for (k = 0; k < NMETHODS; k++)
        sprintf(item_names[IT_CONTACT + k], "contact_%s", method_names[k]);
}

/* Calls per pass of an item (the unit its time is divided by). */
static long item_calls(const bench *b, int it)
{
    switch (it) {
    case IT_SEARCH: return 2 * b->nsearch;                 /* per wheel */
    case IT_WHEELSET: return b->nsolve;                    /* per wheelset */
    case IT_BUILD: return 1;                               /* per table */
    case IT_HERTZ: case IT_CREEPAGE: return 2 * b->n;      /* per wheel */
    default: return b->n;                                  /* per wheelset */
    }
}

/* One pass of item `it`; returns its wall time [s] and counts the calls
 * with an error status into *bad. */
static double run_item(bench *b, int it, long *bad)
{
    const long n = b->n;
    double acc = 0.0, t0, t;
    long i, nbad = 0;

    t0 = now();
    switch (it) {
    case IT_SEARCH:
        for (i = 0; i < b->nsearch; i++) {
            rr_contact_point c;
            nbad += rr_contact_search(&b->left, b->s[i].y, b->z[i], b->roll[i], &b->so, &c) < 0;
            acc += c.r + c.delta;
            nbad += rr_contact_search(&b->right, b->s[i].y, b->z[i], b->roll[i], &b->so, &c) < 0;
            acc += c.r + c.delta;
        }
        break;
    case IT_WHEELSET:
        for (i = 0; i < b->nsolve; i++) {
            rr_wheelset_pose p;
            rr_contact_point cl, cr;
            nbad += rr_wheelset_contact(&b->left, &b->right, b->s[i].y, &b->so, &p, &cl,
                                        &cr) < 0;
            acc += p.z + p.roll + cl.r + cr.r;
        }
        break;
    case IT_BUILD:
        nbad += rr_rig_table_build(&b->geometry, b->scratch.data,
                                   rr_contact_table_len(b->scratch.n), work,
                                   RR_RIG_TABLE_WORK_LEN, &b->scratch, NULL) < 0;
        acc += b->scratch.data[rr_contact_table_len(b->scratch.n) / 2];
        break;
    case IT_LOOKUP:
        for (i = 0; i < n; i++) {
            rr_wheelset_pose p, sl;
            rr_contact_point cl, cr;
            nbad += rr_contact_table_lookup(&b->table, b->s[i].y, &p, &sl, &cl, &cr) < 0;
            acc += p.z + sl.roll + cl.r + cr.A;
        }
        break;
    case IT_HERTZ:
        for (i = 0; i < 2 * n; i++) {
            rr_hertz_result h;
            nbad += rr_hertz(b->hA[i], b->hB[i], b->hN[i], b->model[0].estar, &h) < 0;
            acc += h.a + h.b;
        }
        break;
    case IT_CREEPAGE:
        for (i = 0; i < 2 * n; i++) {
            rr_creepages c;
            nbad += rr_creepage(&b->wheel[i / 2], &b->roller[i / 2], &b->frame[i], VMIN, &c) < 0;
            acc += c.cx + c.cy + c.cphi;
        }
        break;
    case IT_KINEMATICS:
        for (i = 0; i < n; i++) {
            rr_rig_pose p;
            rr_wheel_contact w[2];
            nbad += rr_rig_kinematics(&b->model[0], &b->s[i], &p, w) < 0;
            acc += w[0].creep.cx + w[1].creep.cy + p.v[2];
        }
        break;
    default: {
        const rr_rig_contact_model *md = &b->model[it - IT_CONTACT];
        for (i = 0; i < n; i++) {
            rr_rig_pose p;
            rr_wheel_contact w[2];
            nbad += rr_rig_contact(md, &b->s[i], b->N[i], &p, w) < 0;
            acc += w[0].force[0] + w[1].force[1] + w[0].moment[2];
        }
    }
    }
    t = now() - t0;
    b->checksum += acc;
    *bad = nbad;
    return t;
}

/* ----------------------------------------------------------------- dump */
/*
 * FILE (native byte order): int64 n, int64 ncheck, int64 table rows, then
 * doubles: y0, dy, the table (rr_contact_table_len(rows) doubles), the 10
 * state columns of n (x, y, yaw, vx, vy, yaw_rate, spin, roller_spin,
 * N_left, N_right), then 17 columns of ncheck, the first ncheck states'
 * rr_rig_contact with FASTSIM 20x20: status, and per wheel (left, then
 * right) cx, cy, cphi, a, b, fx, fy, mz.
 */
static void dump(const bench *b, const char *path, long ncheck)
{
    FILE *f = fopen(path, "wb");
    const long n = b->n, len = rr_contact_table_len(b->table.n);
    int64_t head[3];
    double *cols = alloc((size_t)(10 * n + 17 * ncheck), sizeof *cols), *out = cols + 10 * n;
    long i;
    int c, k;

    if (!f)
        die("cannot open the dump file");
    for (i = 0; i < n; i++) {
        const rr_rig_state *s = &b->s[i];
        const double st[10] = {s->x, s->y, s->yaw, s->vx, s->vy, s->yaw_rate, s->spin,
                               s->roller_spin, b->N[i][0], b->N[i][1]};
        for (c = 0; c < 10; c++)
            cols[c * n + i] = st[c];
    }
    for (i = 0; i < ncheck; i++) {
        rr_rig_pose p;
        rr_wheel_contact w[2];
        out[i] = rr_rig_contact(&b->model[0], &b->s[i], b->N[i], &p, w);
        for (k = 0; k < 2; k++) {
            const rr_wheel_contact *q = &w[k];
            const double v[8] = {q->creep.cx, q->creep.cy, q->creep.cphi, q->hertz.a,
                                 q->hertz.b, q->f.fx, q->f.fy, q->f.mz};
            for (c = 0; c < 8; c++)
                out[(1 + 8 * k + c) * ncheck + i] = v[c];
        }
    }
    head[0] = n;
    head[1] = ncheck;
    head[2] = b->table.n;
    fwrite(head, sizeof head[0], 3, f);
    fwrite(&b->table.y0, sizeof(double), 1, f);
    fwrite(&b->table.dy, sizeof(double), 1, f);
    fwrite(b->table.data, sizeof(double), (size_t)len, f);
    fwrite(cols, sizeof *cols, (size_t)(10 * n + 17 * ncheck), f);
    if (fclose(f))
        die("cannot write the dump file");
    free(cols);
}

/* ----------------------------------------------------------------- main */
static long arg_long(const char *s, long lo)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (*end || v < lo)
        die("bad numeric argument");
    return v;
}

int main(int argc, char **argv)
{
    static bench b;
    long n = 100000, nsearch = 10000, nsolve = 1000, ncheck = 2000, bad[IT_COUNT];
    double best[IT_COUNT], us[IT_COUNT];
    double half = TABLE_HALF;
    int repeats = 5, only = -1, rows = TABLE_ROWS, i, r, it;
    uint64_t seed = 20240601;
    const char *dump_path = NULL;

    name_items();
    for (i = 1; i < argc; i++) {
        const char *opt = argv[i];
        if (i + 1 >= argc)
            die("usage: bench_rig [--states N] [--search-states M] [--solve-states K] "
                "[--repeats R] [--seed S] [--table-rows T] [--table-half-range H] [--only ITEM] "
                "[--dump FILE] [--check-states C]");
        if (!strcmp(opt, "--states"))
            n = arg_long(argv[++i], 1);
        else if (!strcmp(opt, "--search-states"))
            nsearch = arg_long(argv[++i], 1);
        else if (!strcmp(opt, "--solve-states"))
            nsolve = arg_long(argv[++i], 1);
        else if (!strcmp(opt, "--check-states"))
            ncheck = arg_long(argv[++i], 0);
        else if (!strcmp(opt, "--table-rows"))
            rows = (int)arg_long(argv[++i], 2);
        else if (!strcmp(opt, "--table-half-range")) {
            char *end;
            half = strtod(argv[++i], &end);
            if (*end || !(half > 0.0 && half < 0.015))
                die("--table-half-range must be in (0, 0.015) m");
        } else if (!strcmp(opt, "--repeats"))
            repeats = (int)arg_long(argv[++i], 1);
        else if (!strcmp(opt, "--seed"))
            seed = (uint64_t)arg_long(argv[++i], 0);
        else if (!strcmp(opt, "--dump"))
            dump_path = argv[++i];
        else if (!strcmp(opt, "--only")) {
            const char *name = argv[++i];
            for (it = 0; it < IT_COUNT; it++)
                if (!strcmp(name, item_names[it]))
                    only = it;
            if (only < 0)
                die("unknown item");
        } else
            die("unknown option");
    }
    if (nsearch > n)
        nsearch = n;
    if (nsolve > n)
        nsolve = n;
    if (ncheck > n)
        ncheck = n;

    setup(&b, n, nsearch, nsolve, seed,
          only < 0 || only == IT_SEARCH || only == IT_HERTZ || only == IT_CREEPAGE, rows, half);
    if (dump_path)
        dump(&b, dump_path, ncheck);

    for (it = 0; it < IT_COUNT; it++) {
        best[it] = INFINITY;
        bad[it] = 0;
    }
    for (r = 0; r < repeats; r++)          /* the items take turns within a round */
        for (it = 0; it < IT_COUNT; it++)
            if (only < 0 || it == only) {
                double t = run_item(&b, it, &bad[it]);
                if (t < best[it])
                    best[it] = t;
            }
    for (it = 0; it < IT_COUNT; it++)
        us[it] = best[it] / (double)item_calls(&b, it) * 1e6;

    printf("{\"states\": %ld, \"search_states\": %ld, \"solve_states\": %ld, \"repeats\": %d, "
           "\"seed\": %llu, ", n, nsearch, nsolve, repeats, (unsigned long long)seed);
    printf("\"params\": {\"r0\": %.17g, \"conicity\": %.17g, \"wheel_half_width\": %.17g, "
           "\"R0\": %.17g, \"crown_radius\": %.17g, \"roller_half_width\": %.17g, "
           "\"half_spacing\": %.17g, \"wheel_knots\": %d, \"roller_knots\": %d, "
           "\"E\": %.17g, \"nu\": %.17g, \"mu0\": %.17g, \"A\": %.17g, \"B\": %.17g, "
           "\"kA\": %.17g, \"kS\": %.17g, \"vmin\": %.17g, \"fastsim_n\": %d, "
           "\"roller_speed\": %.17g, \"nsamples\": %d}, ",
           WHEEL_R0, CONICITY, WHEEL_HALF, ROLLER_R0, CROWN, WHEEL_HALF, HALF_SPACING, NP, NP,
           YOUNG, POISSON, MU0, POLACH_A, POLACH_B, POLACH_KA, POLACH_KS, VMIN, FASTSIM_N,
           ROLLER_SPEED, b.so.nsamples);
    printf("\"table\": {\"rows\": %d, \"y0\": %.17g, \"dy\": %.17g}, ", b.table.n,
           b.table.y0, b.table.dy);
    printf("\"us\": {");
    for (it = 0, i = 0; it < IT_COUNT; it++)
        if (only < 0 || it == only)
            printf("%s\"%s\": %.6g", i++ ? ", " : "", item_names[it], us[it]);
    printf("}, \"bad\": {");
    for (it = 0, i = 0; it < IT_COUNT; it++)
        if (only < 0 || it == only)
            printf("%s\"%s\": %ld", i++ ? ", " : "", item_names[it], bad[it]);
    printf("}, ");
    if (only < 0) {
        const double placement = us[IT_KINEMATICS] - us[IT_LOOKUP] - 2.0 * us[IT_CREEPAGE];
        printf("\"derived\": {\"build_row_us\": %.6g, \"lookup_wheel_us\": %.6g, "
               "\"placement_wheelset_us\": %.6g", us[IT_BUILD] / b.table.n, us[IT_LOOKUP] / 2.0,
               placement);
        for (it = 0; it < NMETHODS; it++) {
            const double whole = us[IT_CONTACT + it];
            printf(", \"%s\": {\"whole_wheel_us\": %.6g, \"geometry_share\": %.6g, "
                   "\"kinematics_share\": %.6g}", method_names[it], whole / 2.0,
                   (us[IT_LOOKUP] + placement) / whole, us[IT_KINEMATICS] / whole);
        }
        printf("}, ");
    }
    printf("\"checksum\": %.17g}\n", b.checksum);
    return 0;
}
