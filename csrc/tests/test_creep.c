/*
 * test_creep.c - creep-force methods: Kalker's linear theory (rr_linear),
 * Polach's method (rr_polach), FASTSIM and its blended and modified variants
 * (rr_fastsim), FaStrip (rr_fastrip), the dispatcher (rr_creep_forces) and the option checks.
 *
 * Conventions (rr_contact.h): forces on the wheel, fx = -G a b C11 cx for
 * small creepage; rigid slip (cx - cphi y, cy + cphi x).
 *
 * Over 800 lines on purpose: the methods share the helpers above and the
 * dispatcher's checks (test_dispatch, test_extremes, test_bad_options) run
 * every method through the same cases; each check is a function of its own,
 * listed by main and read by its name, so the file is held a check at a
 * time.  A method's checks move to a program of its own when they outgrow
 * the shared helpers (as test_exact.c and test_exact_table.c did).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_kalker.h"
#include "contact/rr_friction.h"
#include "contact/rr_contact.h"
#include "contact/rr_creep.h"
#include "contact/rr_linear.h"
#include "contact/rr_polach.h"
#include "contact/rr_fastsim.h"
#include "contact/rr_fastrip.h"
#include "rr_test.h"

/* problem c with the friction law fr (the tests vary the two apart): c's
 * law set to *fr, c returned (NULL stays NULL) */
static const rr_contact_problem *with_law(rr_contact_problem *c, const rr_friction *fr)
{
    if (c && fr)
        c->friction = *fr;
    return c;
}

/* ---- helpers ------------------------------------------------------------- */

#define MAXEL (80 * 80)   /* largest grid whose traction field is requested */

static double fld_x[MAXEL], fld_y[MAXEL], fld_pn[MAXEL], fld_px[MAXEL], fld_py[MAXEL];
static signed char fld_slip[MAXEL];

/* A locomotive-like wheel: a/b = 1.5, N = 80 kN, steel. */
static rr_contact_problem base_case(void)
{
    rr_contact_problem c = {0};    /* an ellipse problem */
    c.a = 6e-3;
    c.b = 4e-3;
    c.N = 8e4;
    c.G = 8.2e10;
    c.nu = 0.28;
    c.cx = c.cy = c.cphi = 0.0;
    c.speed = 10.0;
    c.friction.mu0 = 0.3;
    c.friction.A = 1.0;
    c.friction.B = 0.0;
    return c;
}

static rr_friction coulomb(double mu)
{
    rr_friction f;
    f.mu0 = mu;
    f.A = 1.0;
    f.B = 0.0;
    return f;
}

static rr_friction falling(double mu0, double A, double B)
{
    rr_friction f;
    f.mu0 = mu0;
    f.A = A;
    f.B = B;
    return f;
}

static rr_creep_opts opts(int method, int nx, int ny, int bound, int grid)
{
    rr_creep_opts o;
    rr_creep_opts_default(&o, method);
    o.v[RR_FASTSIM_NX] = nx;
    o.v[RR_FASTSIM_NY] = ny;
    o.v[RR_FASTSIM_BOUND] = bound;
    o.v[RR_FASTSIM_GRID] = grid;
    return o;
}

static int forces_nan(const rr_forces *f)
{
    return isnan(f->fx) && isnan(f->fy) && isnan(f->mz);
}

static rr_kalker_coeffs coeffs(const rr_contact_problem *c)
{
    rr_kalker_coeffs k;
    rr_kalker(c->a / c->b, c->nu, &k);
    return k;
}

/* deterministic LCG (Knuth's MMIX constants), uniform in [0, 1) */
static unsigned long long lcg_state = 12345ULL;
static double lcg(void)
{
    lcg_state = lcg_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(lcg_state >> 11) * (1.0 / 9007199254740992.0);
}
static double lcg_range(double lo, double hi)
{
    return lo + (hi - lo) * lcg();
}
/* signed creepage of random magnitude spread over several decades */
static double lcg_creep(double maxabs)
{
    double m = maxabs * pow(10.0, -4.0 * lcg());
    return lcg() < 0.5 ? -m : m;
}

static const char *const grid_name[2] = {"rect", "strips"};
static const char *const bound_name[2] = {"parabolic", "elliptic"};

/* ---- linear theory ------------------------------------------------------- */

static void test_linear(void)
{
    rr_contact_problem c = base_case();
    rr_kalker_coeffs k = coeffs(&c);
    rr_forces f, fd, f1, f2, f3, fn;
    rr_creep_opts o = opts(RR_METHOD_LINEAR, 30, 30, RR_BOUND_PARABOLIC, RR_GRID_RECT);
    rr_friction fr = coulomb(0.3);
    double ab = c.a * c.b, c3 = ab * sqrt(ab);
    int st;

    c.cx = 1e-3;
    c.cy = -2e-3;
    c.cphi = 0.7;
    st = rr_linear(&c, &f);
    CHECK_STATUS(st, RR_OK, "rr_linear status");
    /* the documented formulas with the same coefficients: a few roundings */
    CHECK_CLOSE(f.fx, -c.G * ab * k.c11 * c.cx, 0.0, 1e-14, "linear fx = -G c^2 C11 cx");
    CHECK_CLOSE(f.fy, -c.G * ab * k.c22 * c.cy - c.G * c3 * k.c23 * c.cphi, 0.0, 1e-14,
                "linear fy = -G c^2 C22 cy - G c^3 C23 cphi");
    CHECK_CLOSE(f.mz, c.G * c3 * k.c23 * c.cy - c.G * ab * ab * k.c33 * c.cphi, 0.0, 1e-14,
                "linear mz = G c^3 C23 cy - G c^4 C33 cphi");
    {
        /* pure spin at table nodes against Kalker's C33 typed from Table E.3
         * (kalker_c33.csv): a/b = 0.5 and 2, nu = 0.25 */
        static const struct { double a, b, c33; } node[] = {
            {3e-3, 6e-3, 1.93}, {6e-3, 3e-3, 0.819}
        };
        unsigned i;
        for (i = 0; i < sizeof node / sizeof node[0]; i++) {
            rr_contact_problem s = c;
            rr_forces fs;
            double sab = node[i].a * node[i].b;
            s.a = node[i].a;
            s.b = node[i].b;
            s.nu = 0.25;
            s.cx = s.cy = 0.0;
            s.cphi = 0.7;
            CHECK_STATUS(rr_linear(&s, &fs), RR_OK, "rr_linear pure spin at a node: status");
            /* a node of the table: C33 exact, then three roundings: 1e-14 */
            CHECK_CLOSE(fs.mz, -s.G * sab * sab * node[i].c33 * s.cphi, 0.0, 1e-14,
                        "linear pure-spin mz = -G c^4 C33 cphi with Table E.3's C33");
        }
    }

    /* the dispatcher gives the same, and ignores friction */
    st = rr_creep_forces(with_law(&c, &fr), &o, &fd);
    CHECK_STATUS(st, RR_OK, "dispatcher, linear: status");
    CHECK(fd.fx == f.fx && fd.fy == f.fy && fd.mz == f.mz, "dispatcher = rr_linear");

    /* superposition of the three creepages */
    {
        rr_contact_problem c1 = c, c2 = c, c3c = c;
        c1.cy = c1.cphi = 0.0;
        c2.cx = c2.cphi = 0.0;
        c3c.cx = c3c.cy = 0.0;
        rr_linear(&c1, &f1);
        rr_linear(&c2, &f2);
        rr_linear(&c3c, &f3);
        /* linear in each creepage: rounding of a sum of two terms */
        CHECK_CLOSE(f1.fx + f2.fx + f3.fx, f.fx, 0.0, 1e-14, "linear superposition fx");
        CHECK_CLOSE(f1.fy + f2.fy + f3.fy, f.fy, 0.0, 1e-14, "linear superposition fy");
        CHECK_CLOSE(f1.mz + f2.mz + f3.mz, f.mz, 0.0, 1e-14, "linear superposition mz");
    }
    /* odd symmetry: negation is exact */
    c.cx = -c.cx;
    c.cy = -c.cy;
    c.cphi = -c.cphi;
    rr_linear(&c, &fn);
    CHECK(fn.fx == -f.fx && fn.fy == -f.fy && fn.mz == -f.mz, "linear odd symmetry");

    /* bad contact cases */
    {
        static const struct {
            int field;
            double value;
            int status;
            const char *what;
        } t[] = {
            {0, 0.0, RR_ERR_GEOMETRY, "linear: a = 0"},
            {1, -1e-3, RR_ERR_GEOMETRY, "linear: b < 0"},
            {2, 0.0, RR_ERR_LOAD, "linear: N = 0"},
            {3, -1.0, RR_ERR_MATERIAL, "linear: G < 0"},
            {4, 0.5000000000000001, RR_ERR_MATERIAL, "linear: nu just above 0.5"},
            {4, -0.1, RR_ERR_MATERIAL, "linear: nu < 0"},
            {5, NAN, RR_ERR_NONFINITE, "linear: cx NaN"},
            {6, INFINITY, RR_ERR_NONFINITE, "linear: cphi inf"},
            {7, -1.0, RR_ERR_SPEED, "linear: speed < 0"},
            {7, NAN, RR_ERR_NONFINITE, "linear: speed NaN"}
        };
        unsigned i;
        for (i = 0; i < sizeof t / sizeof t[0]; i++) {
            rr_contact_problem b = base_case();
            double *fieldp[8];
            fieldp[0] = &b.a;
            fieldp[1] = &b.b;
            fieldp[2] = &b.N;
            fieldp[3] = &b.G;
            fieldp[4] = &b.nu;
            fieldp[5] = &b.cx;
            fieldp[6] = &b.cphi;
            fieldp[7] = &b.speed;
            *fieldp[t[i].field] = t[i].value;
            CHECK_STATUS(rr_contact_problem_check(&b, NULL), t[i].status, t[i].what);
            st = rr_linear(&b, &f);
            CHECK_STATUS(st, t[i].status, t[i].what);
            CHECK(forces_nan(&f), t[i].what);
        }
    }
}

/* ---- Polach ---------------------------------------------------------------- */

static void test_polach(void)
{
    rr_contact_problem c = base_case();
    rr_kalker_coeffs k = coeffs(&c);
    rr_friction fr = coulomb(0.3);
    rr_forces f, fl;
    double ab = c.a * c.b, c3 = ab * sqrt(ab), muN = fr.mu0 * c.N;
    int st;

    /* small creepage: Kalker's linear theory (kA = kS = 1) */
    c.cx = 1e-9;
    st = rr_polach(with_law(&c, &fr), 1.0, 1.0, &f);
    CHECK_STATUS(st, RR_OK, "Polach status");
    rr_linear(&c, &fl);
    /* Polach's series deviates by O(eps^2) ~ 1e-12 at creepage 1e-9: 1e-6 */
    CHECK_CLOSE(f.fx, fl.fx, 0.0, 1e-6, "Polach small cx = linear fx");
    CHECK_CLOSE(f.fx, -c.G * ab * k.c11 * c.cx, 0.0, 1e-6, "Polach small cx: -G c^2 C11 cx");
    CHECK(f.fy == 0.0 && f.mz == 0.0, "Polach pure cx: fy = mz = 0");

    c.cx = 0.0;
    c.cy = -1e-9;
    rr_polach(with_law(&c, &fr), 1.0, 1.0, &f);
    rr_linear(&c, &fl);
    /* as above */
    CHECK_CLOSE(f.fy, fl.fy, 0.0, 1e-6, "Polach small cy = linear fy");
    CHECK_CLOSE(f.fy, -c.G * ab * k.c22 * c.cy, 0.0, 1e-6, "Polach small cy: -G c^2 C22 cy");
    CHECK(f.fx == 0.0, "Polach pure cy: fx = 0");

    /* spin only: fy = -G c^3 C23 cphi */
    c.cy = 0.0;
    c.cphi = 1e-7;
    rr_polach(with_law(&c, &fr), 1.0, 1.0, &f);
    /* K_M = -(2/3) eps_M + O(eps_M^3): eps_M ~ 1e-9 here: 1e-6 */
    CHECK_CLOSE(f.fy, -c.G * c3 * k.c23 * c.cphi, 0.0, 1e-6, "Polach spin only: -G c^3 C23 cphi");
    CHECK(f.fx == 0.0 && f.mz == 0.0, "Polach spin only: fx = mz = 0");
    c.cphi = -1e-7;
    rr_polach(with_law(&c, &fr), 1.0, 1.0, &f);
    CHECK_CLOSE(f.fy, -c.G * c3 * k.c23 * c.cphi, 0.0, 1e-6, "Polach negative spin only");

    /* reduction factors: small-creepage slope times (kA + kS)/2 */
    c.cphi = 0.0;
    c.cx = 1e-9;
    c.cy = 0.0;
    rr_polach(with_law(&c, &fr), 0.8, 0.3, &f);
    rr_linear(&c, &fl);
    /* as above */
    CHECK_CLOSE(f.fx, 0.55 * fl.fx, 0.0, 1e-6, "Polach kA = 0.8, kS = 0.3: fx = 0.55 linear");
    c.cx = 0.0;
    c.cy = 1e-9;
    rr_polach(with_law(&c, &fr), 0.8, 0.3, &f);
    rr_linear(&c, &fl);
    CHECK_CLOSE(f.fy, 0.55 * fl.fy, 0.0, 1e-6, "Polach kA = 0.8, kS = 0.3: fy = 0.55 linear");

    /* combined cx, cy: Polach's force is along the creepage (cx, cy), with
     * the magnitude of the linear theory's |(C11 cx, C22 cy)| G c^2; the
     * linear force itself points elsewhere when C11 != C22 */
    c.cx = 1e-9;
    c.cy = 2e-9;
    rr_polach(with_law(&c, &fr), 1.0, 1.0, &f);
    rr_linear(&c, &fl);
    /* as above */
    CHECK_CLOSE(hypot(f.fx, f.fy), hypot(fl.fx, fl.fy), 0.0, 1e-6,
                "Polach combined small creepage: |F| = |F linear|");
    /* direction from the same two numbers: rounding only */
    CHECK_CLOSE(f.fy / f.fx, c.cy / c.cx, 0.0, 1e-14, "Polach: F parallel to (cx, cy)");

    /* zero creepage: zero force */
    c.cx = c.cy = c.cphi = 0.0;
    st = rr_polach(with_law(&c, &fr), 1.0, 1.0, &f);
    CHECK(st == RR_OK && f.fx == 0.0 && f.fy == 0.0 && f.mz == 0.0, "Polach zero creepage");

    /* saturation: |F| grows monotonically toward mu N, never beyond */
    {
        double prev = 0.0, F = 0.0, cx;
        int mono = 1, below = 1;
        for (cx = 1e-6; cx <= 1.0; cx *= 1.5) {
            c.cx = cx;
            c.cy = 0.3 * cx;
            rr_polach(with_law(&c, &fr), 1.0, 1.0, &f);
            F = hypot(f.fx, f.fy);
            if (!(F > prev))
                mono = 0;
            if (!(F <= muN))
                below = 0;
            prev = F;
        }
        CHECK(mono, "Polach |F| increasing with creepage (Coulomb)");
        CHECK(below, "Polach |F| <= mu N");
        /* at creepage ~1 eps ~ 300: 1 - F/(mu N) ~ (4/3pi) eps^-3 ~ 1e-8: 1e-6 */
        CHECK_CLOSE(F, muN, 0.0, 1e-6, "Polach |F| -> mu N at large creepage");
    }
    /* falling friction: saturates at mu(speed s_C) N */
    {
        rr_friction ff = falling(0.3, 0.4, 0.6);
        c.cx = 5.0;
        c.cy = 0.0;
        st = rr_polach(with_law(&c, &ff), 1.0, 1.0, &f);
        CHECK_STATUS(st, RR_OK, "Polach falling friction status");
        /* eps ~ 4000: the 1/eps^3 term is ~1e-11: 1e-9 */
        CHECK_CLOSE(-f.fx, rr_friction_mu(&ff, c.speed * c.cx) * c.N, 0.0, 1e-9,
                    "Polach falling friction: |F| -> mu(speed cx) N");
        c.speed = 0.0;
        st = rr_polach(with_law(&c, &ff), 1.0, 1.0, &f);
        CHECK_STATUS(st, RR_ERR_SPEED, "Polach falling friction at speed 0");
        CHECK(forces_nan(&f), "Polach falling friction at speed 0: NaN");
        st = rr_polach(with_law(&c, &fr), 1.0, 1.0, &f);
        CHECK_STATUS(st, RR_OK, "Polach Coulomb friction at speed 0 is fine");
        c.speed = 10.0;
    }
    /* odd symmetry, with spin */
    {
        rr_forces fn;
        c.cx = 2e-3;
        c.cy = -1e-3;
        c.cphi = 0.8;
        rr_polach(with_law(&c, &fr), 0.9, 0.7, &f);
        c.cx = -c.cx;
        c.cy = -c.cy;
        c.cphi = -c.cphi;
        rr_polach(with_law(&c, &fr), 0.9, 0.7, &fn);
        CHECK(fn.fx == -f.fx && fn.fy == -f.fy && fn.mz == -f.mz, "Polach odd symmetry");
    }
    /* moderate spin, beyond the linear range: Polach (1999) transcribed here
     * from the paper's formulas (independently of rr_creep.c):
     *   s_yC = cy + cphi a if |cy + cphi a| > |cy|, else cy;  s_C = |(cx, s_yC)|
     *   k_s = 1 + 6.3 (1 - exp(-a/b))
     *   eps_M = (8/3) G b sqrt(ab) C23 |s_yC| / (N mu k_s)
     *   delta = (eps_M^2 - 1)/(eps_M^2 + 1)
     *   K_M = |eps_M| (delta^3/3 - delta^2/2 + 1/6) - sqrt((1 - delta^2)^3)/3
     *   F_yS = (9/16) a N mu K_M k_s cphi / s_C  (added to fy) */
    {
        static const double cr[4][3] = {
            {0.0, 0.0, 2.0}, {0.0, 0.0, -20.0}, {1e-3, 2e-4, 3.0}, {-5e-4, -1e-3, 1.0}};
        int i;
        for (i = 0; i < 4; i++) {
            double syc, sc, s, cjj, eps, F, ks, epsm, d, km, fys;
            char buf[120];
            c = base_case();
            c.cx = cr[i][0];
            c.cy = cr[i][1];
            c.cphi = cr[i][2];
            syc = fabs(c.cy + c.cphi * c.a) > fabs(c.cy) ? c.cy + c.cphi * c.a : c.cy;
            sc = sqrt(c.cx * c.cx + syc * syc);
            s = sqrt(c.cx * c.cx + c.cy * c.cy);
            cjj = s > 0.0 ? sqrt(pow(k.c11 * c.cx / s, 2.0) + pow(k.c22 * c.cy / s, 2.0)) : 0.0;
            eps = RR_PI * c.G * c.a * c.b * cjj * sc / (4.0 * c.N * fr.mu0);
            F = 2.0 * c.N * fr.mu0 / RR_PI * (eps / (1.0 + eps * eps) + atan(eps));
            ks = 1.0 + 6.3 * (1.0 - exp(-c.a / c.b));
            epsm = 8.0 / 3.0 * c.G * c.b * sqrt(c.a * c.b) / (c.N * fr.mu0) * k.c23 * fabs(syc) / ks;
            d = (epsm * epsm - 1.0) / (epsm * epsm + 1.0);
            km = fabs(epsm) * (d * d * d / 3.0 - d * d / 2.0 + 1.0 / 6.0)
               - sqrt(pow(1.0 - d * d, 3.0)) / 3.0;
            fys = 9.0 / 16.0 * c.a * c.N * fr.mu0 * km * ks * c.cphi / sc;
            st = rr_polach(with_law(&c, &fr), 1.0, 1.0, &f);
            snprintf(buf, sizeof buf, "Polach (1999) with spin, case %d: fx", i);
            /* the same closed forms evaluated in another order: ~1e-15; K_M
             * cancels mildly near eps_M ~ 1: 1e-12 on the scale mu N */
            CHECK_CLOSE(f.fx, -F * c.cx / sc, 1e-12 * muN, 1e-12, buf);
            snprintf(buf, sizeof buf, "Polach (1999) with spin, case %d: fy", i);
            CHECK_CLOSE(f.fy, -F * c.cy / sc + fys, 1e-12 * muN, 1e-12, buf);
            snprintf(buf, sizeof buf, "Polach (1999) with spin, case %d: |F| <= mu N", i);
            CHECK(st == RR_OK && hypot(f.fx, f.fy) <= muN, buf);
        }
    }
    /* bad parameters */
    {
        c = base_case();
        c.cx = 1e-3;
        st = rr_polach(with_law(&c, &fr), 2.0, 1.0, &f);
        CHECK_STATUS(st, RR_ERR_PARAM, "Polach kA = 2");
        CHECK(forces_nan(&f), "Polach kA = 2: NaN");
        st = rr_polach(with_law(&c, &fr), 0.0, 1.0, &f);
        CHECK_STATUS(st, RR_ERR_PARAM, "Polach kA = 0");
        st = rr_polach(with_law(&c, &fr), 1.0, 1.5, &f);
        CHECK_STATUS(st, RR_ERR_PARAM, "Polach kS = 1.5");
        st = rr_polach(with_law(&c, &fr), 0.5, 0.6, &f);
        CHECK_STATUS(st, RR_ERR_PARAM, "Polach kS > kA (Polach 2005: kS <= kA)");
        st = rr_polach(with_law(&c, &fr), NAN, 1.0, &f);
        CHECK_STATUS(st, RR_ERR_NONFINITE, "Polach kA NaN");
        CHECK(forces_nan(&f), "Polach kA NaN: NaN");
        fr.mu0 = 0.0;
        st = rr_polach(with_law(&c, &fr), 1.0, 1.0, &f);
        CHECK_STATUS(st, RR_ERR_FRICTION, "Polach mu0 = 0");
        CHECK(forces_nan(&f), "Polach mu0 = 0: NaN");
    }
}

/* ---- FASTSIM ----------------------------------------------------------------- */

/* |F| <= mu N for random cases: every element's traction is bounded by
 * mu pn and the pressure sums to N. */
static void test_fastsim_bound(void)
{
    static const int methods[3] = {RR_METHOD_FASTSIM, RR_METHOD_FASTSIM_BLENDED,
                                   RR_METHOD_MODIFIED_FASTSIM};
    int n, bad_bound = 0, bad_status = 0, bad_finite = 0, ncase = 0;
    char buf[200];

    for (n = 0; n < 150; n++) {
        rr_contact_problem c = {0};    /* an ellipse problem */
        rr_friction fr;
        int im, bound, grid;
        c.a = lcg_range(2e-3, 1e-2);
        c.b = lcg_range(2e-3, 1e-2);
        c.N = lcg_range(1e3, 1.2e5);
        c.G = lcg_range(2e10, 8.2e10);
        c.nu = lcg_range(0.0, 0.49);
        c.cx = lcg_creep(0.02);
        c.cy = lcg_creep(0.02);
        c.cphi = lcg() < 0.3 ? 0.0 : lcg_creep(5.0);
        c.speed = lcg_range(0.1, 30.0);
        if (n % 3 == 0)
            fr = coulomb(lcg_range(0.05, 0.6));
        else
            fr = falling(lcg_range(0.05, 0.6), lcg_range(0.0, 1.0), lcg_range(0.0, 2.0));
        for (im = 0; im < 3; im++)
            for (bound = 0; bound < 2; bound++)
                for (grid = 0; grid < 2; grid++) {
                    rr_creep_opts o = opts(methods[im], 8 + n % 23, 7 + n % 19, bound, grid);
                    rr_forces f;
                    int st;
                    o.v[RR_FASTSIM_SLIP_SPEED] = n % 2 == 0 ? RR_SLIP_LOCAL : RR_SLIP_RIGID;
                    st = rr_fastsim(with_law(&c, &fr), &o, &f, 0);
                    ncase++;
                    if (st != RR_OK) {
                        bad_status++;
                        if (bad_status <= 3) {
                            snprintf(buf, sizeof buf, "random case %d method %d: status %d",
                                     n, methods[im], st);
                            CHECK(0, buf);
                        }
                    }
                    if (!(isfinite(f.fx) && isfinite(f.fy) && isfinite(f.mz)))
                        bad_finite++;
                    /* |F| <= mu0 N: each term bounded, pressure sums to N; the
                     * sums round at ~1e-15 relative: allow 1e-12 */
                    if (!(hypot(f.fx, f.fy) <= fr.mu0 * c.N * (1.0 + 1e-12))) {
                        bad_bound++;
                        if (bad_bound <= 3) {
                            snprintf(buf, sizeof buf,
                                     "random case %d method %d bound %d grid %d: "
                                     "|F| = %.17g > mu N = %.17g",
                                     n, methods[im], bound, grid, hypot(f.fx, f.fy),
                                     fr.mu0 * c.N);
                            CHECK(0, buf);
                        }
                    }
                }
    }
    snprintf(buf, sizeof buf, "FASTSIM random cases: %d of %d with |F| > mu N", bad_bound, ncase);
    CHECK(bad_bound == 0, buf);
    snprintf(buf, sizeof buf, "FASTSIM random cases: %d of %d with status != 0", bad_status, ncase);
    CHECK(bad_status == 0, buf);
    snprintf(buf, sizeof buf, "FASTSIM random cases: %d of %d not finite", bad_finite, ncase);
    CHECK(bad_finite == 0, buf);
}

/* Full sliding without spin: every element at mu pn in one direction. */
static void test_full_sliding(void)
{
    static const double dirs[3][2] = {{1.0, 0.0}, {-0.6, 0.8}, {0.0, -1.0}};
    int bound, grid, d;
    char buf[160];

    for (grid = 0; grid < 2; grid++)
        for (bound = 0; bound < 2; bound++)
            for (d = 0; d < 3; d++) {
                rr_contact_problem c = base_case();
                rr_friction fr = coulomb(0.3);
                rr_creep_opts o = opts(RR_METHOD_FASTSIM, 31, 24, bound, grid);
                rr_fastsim_field fld = {0, 0, 0, 0, 0, 0, 0, 0};
                rr_forces f;
                int st, i, ninside = 0;
                fld.pn = fld_pn;
                c.cx = 2.0 * dirs[d][0];
                c.cy = 2.0 * dirs[d][1];
                st = rr_fastsim(with_law(&c, &fr), &o, &f, &fld);
                snprintf(buf, sizeof buf, "full sliding %s %s dir (%g, %g)", grid_name[grid],
                         bound_name[bound], dirs[d][0], dirs[d][1]);
                CHECK_STATUS(st, RR_OK, buf);
                /* the pressure sums to N on the grid by construction; the
                 * traction sums round at ~1e-15: 1e-12 per the brief */
                CHECK_CLOSE(hypot(f.fx, f.fy), fr.mu0 * c.N, 0.0, 1e-12, buf);
                /* the force opposes the creepage */
                CHECK(f.fx * c.cx <= 0.0 && f.fy * c.cy <= 0.0, buf);
                if (c.cy == 0.0)
                    CHECK(f.fy == 0.0, "full sliding with cy = 0: fy exactly 0");
                if (c.cx == 0.0)
                    CHECK(f.fx == 0.0, "full sliding with cx = 0: fx exactly 0");
                for (i = 0; i < o.v[RR_FASTSIM_NX] * o.v[RR_FASTSIM_NY]; i++)
                    if (fld_pn[i] > 0.0)
                        ninside++;
                CHECK(fld.nslip == ninside, "full sliding: every loaded element slips");
            }
}

/* F(-cx, -cy, -cphi) = -F: the march is mirrored bit for bit. */
static void test_odd_symmetry(void)
{
    static const int methods[3] = {RR_METHOD_FASTSIM, RR_METHOD_FASTSIM_BLENDED,
                                   RR_METHOD_MODIFIED_FASTSIM};
    static const double cr[4][3] = {
        {1e-3, 0.0, 0.0}, {2e-3, -1.5e-3, 0.5}, {-4e-4, 3e-3, -2.0}, {0.0, 0.0, 3.0}};
    int im, bound, grid, ic, sm;
    int ok = 1, n = 0;

    for (im = 0; im < 3; im++)
        for (bound = 0; bound < 2; bound++)
            for (grid = 0; grid < 2; grid++)
                for (sm = 0; sm < 2; sm++)
                    for (ic = 0; ic < 4; ic++) {
                        rr_contact_problem c = base_case();
                        rr_friction fr = sm == 0 ? coulomb(0.3) : falling(0.3, 0.4, 0.6);
                        rr_creep_opts o = opts(methods[im], 20, 16, bound, grid);
                        rr_forces f, g;
                        c.cx = cr[ic][0];
                        c.cy = cr[ic][1];
                        c.cphi = cr[ic][2];
                        rr_fastsim(with_law(&c, &fr), &o, &f, 0);
                        c.cx = -c.cx;
                        c.cy = -c.cy;
                        c.cphi = -c.cphi;
                        rr_fastsim(with_law(&c, &fr), &o, &g, 0);
                        n++;
                        /* negation is exact in IEEE arithmetic and every
                         * magnitude (|p*|, |(cx, cy)|) is sign-blind: exact */
                        if (!(g.fx == -f.fx && g.fy == -f.fy && g.mz == -f.mz)) {
                            ok = 0;
                            printf("  odd symmetry: method %d bound %d grid %d friction %d "
                                   "case %d: (%.17g %.17g %.17g) vs (%.17g %.17g %.17g)\n",
                                   methods[im], bound, grid, sm, ic, f.fx, f.fy, f.mz,
                                   g.fx, g.fy, g.mz);
                        }
                    }
    CHECK(ok && n == 96, "FASTSIM odd symmetry F(-c) = -F in all variants");
}

/* Initial slope against Kalker's linear theory, and its grid convergence. */
static void test_slope(void)
{
    static const int ns[] = {5, 10, 20, 40, 80, 160};
    rr_contact_problem c = base_case();
    rr_kalker_coeffs k = coeffs(&c);
    rr_friction fr = coulomb(0.3);
    double lin = c.G * c.a * c.b * k.c11, linphi = c.G * pow(c.a * c.b, 1.5) * k.c23;
    double prev_err[2] = {1.0, 1.0}, prev_phi = 1.0;
    unsigned i;
    int grid, bound;
    char buf[200];

    for (i = 0; i < sizeof ns / sizeof ns[0]; i++)
        for (grid = 0; grid < 2; grid++) {
            const int n = ns[i];
            const double allowed = 1.0 / n + 2.0 / ((double)n * n);
            double errs[2];
            for (bound = 0; bound < 2; bound++) {
                rr_creep_opts o = opts(RR_METHOD_FASTSIM, n, n, bound, grid);
                rr_forces f;
                double err;
                c.cx = 1e-9;
                c.cy = c.cphi = 0.0;
                rr_fastsim(with_law(&c, &fr), &o, &f, 0);
                err = f.fx / (-lin * c.cx) - 1.0;
                errs[bound] = err;
                snprintf(buf, sizeof buf, "slope %s %s n = %d: error %.3e > 0", grid_name[grid],
                         bound_name[bound], n, err);
                /* Kalker's explicit scheme overshoots the slope */
                CHECK(err > 0.0, buf);
                if (grid == RR_GRID_STRIPS) {
                    /* strip j: sum_i (i+1) h^2 = 2 a_j^2 (1 + 1/nx); midpoint rule in y
                     * on 1 - y^2/b^2: 1 + 1/(2 ny^2): exact up to rounding, 1e-12 */
                    CHECK_CLOSE(1.0 + err, (1.0 + 1.0 / n) * (1.0 + 0.5 / ((double)n * n)), 0.0,
                                1e-12, buf);
                    CHECK(err <= allowed, buf);
                } else {
                    /* rectangular grid: rows keep the box's element length
                     * 2a/nx, so a row of chord 2a_j has only ~nx a_j/a
                     * elements and overshoots by ~1/(nx sqrt(1 - y_j^2/b^2));
                     * weighted by a_j^2 that is (3 pi/8)/nx = 1.18/nx, plus the
                     * ragged cut of the ellipse, which makes it erratic in n:
                     * measured 1.08 - 1.49 times 1/nx + 2/ny^2 for the n used
                     * here (0.56 - 2.06 over all n = 5 ... 320, worst n = 9):
                     * allow twice (see the report) */
                    CHECK(err <= 2.0 * allowed, buf);
                }
            }
            /* the initial slope does not depend on the traction bound */
            snprintf(buf, sizeof buf, "slope %s n = %d: same for both bounds", grid_name[grid], n);
            CHECK(errs[0] == errs[1], buf);
            snprintf(buf, sizeof buf, "slope %s n = %d: error shrinks with refinement (%.3e -> %.3e)",
                     grid_name[grid], n, prev_err[grid], errs[0]);
            CHECK(errs[0] < prev_err[grid], buf);
            if (i > 0 && grid == RR_GRID_STRIPS) {
                /* first order: halving h halves the error (within 15 %) */
                CHECK(errs[0] < 0.6 * prev_err[grid] && errs[0] > 0.4 * prev_err[grid], buf);
            }
            prev_err[grid] = errs[0];

            /* lateral creepage: the same factor with C22 */
            {
                rr_creep_opts o = opts(RR_METHOD_FASTSIM, n, n, RR_BOUND_PARABOLIC, grid);
                rr_forces f;
                c.cx = 0.0;
                c.cy = 1e-9;
                rr_fastsim(with_law(&c, &fr), &o, &f, 0);
                snprintf(buf, sizeof buf, "slope in cy %s n = %d equals the slope in cx",
                         grid_name[grid], n);
                /* same discretisation factor: rounding only */
                CHECK_CLOSE(f.fy / (-c.G * c.a * c.b * k.c22 * c.cy), 1.0 + errs[0], 0.0, 1e-12, buf);
                c.cy = 0.0;
            }
            /* spin on strips: Fy -> -G c^3 C23 cphi, second order in the grid */
            if (grid == RR_GRID_STRIPS) {
                rr_creep_opts o = opts(RR_METHOD_FASTSIM, n, n, RR_BOUND_PARABOLIC, grid);
                rr_forces f;
                double e;
                c.cphi = 1e-7;
                rr_fastsim(with_law(&c, &fr), &o, &f, 0);
                e = fabs(f.fy / (-linphi * c.cphi) - 1.0);
                snprintf(buf, sizeof buf, "spin slope strips n = %d: error %.3e", n, e);
                /* measured 3.1e-2 at n = 5 falling 4x per doubling: (1/n)^2 bounds it */
                CHECK(e <= 1.0 / ((double)n * n), buf);
                CHECK(e < prev_phi, buf);
                prev_phi = e;
                c.cphi = 0.0;
            }
        }
}

/* Falling friction: the force peaks and falls toward A mu0 N. */
static void test_falling(void)
{
    rr_contact_problem c = base_case();
    rr_friction ff = falling(0.3, 0.4, 0.6);
    double muN0 = ff.mu0 * c.N;
    int sm;
    char buf[200];

    for (sm = 0; sm < 2; sm++) {
        rr_creep_opts o = opts(RR_METHOD_FASTSIM, 30, 30, RR_BOUND_PARABOLIC, RR_GRID_RECT);
        double F[24], cxs[24], cx = 1e-5, peak = 0.0;
        int i, ipeak = 0, up = 1, down = 1, st, allok = 1;
        o.v[RR_FASTSIM_SLIP_SPEED] = sm;
        for (i = 0; i < 24; i++, cx *= 2.0) {
            rr_forces f;
            c.cx = cx;
            st = rr_fastsim(with_law(&c, &ff), &o, &f, 0);
            if (st != RR_OK)
                allok = 0;
            cxs[i] = cx;
            F[i] = -f.fx;
            if (F[i] > peak) {
                peak = F[i];
                ipeak = i;
            }
        }
        snprintf(buf, sizeof buf, "falling %s: status 0 along the curve",
                 sm == RR_SLIP_LOCAL ? "local" : "rigid");
        CHECK(allok, buf);
        for (i = 1; i <= ipeak; i++)
            if (!(F[i] > F[i - 1]))
                up = 0;
        for (i = ipeak + 1; i < 24; i++)
            if (!(F[i] <= F[i - 1]))
                down = 0;
        snprintf(buf, sizeof buf, "falling %s: interior peak (at cx = %g, %.4f mu0 N)",
                 sm == RR_SLIP_LOCAL ? "local" : "rigid", cxs[ipeak], peak / muN0);
        CHECK(ipeak > 0 && ipeak < 23, buf);
        /* the peak lies near the static limit: above 0.9 mu0 N (measured 0.965) */
        CHECK(peak > 0.9 * muN0 && peak < muN0, buf);
        snprintf(buf, sizeof buf, "falling %s: rises to the peak, then falls",
                 sm == RR_SLIP_LOCAL ? "local" : "rigid");
        CHECK(up && down, buf);
        snprintf(buf, sizeof buf, "falling %s: |F| -> A mu0 N at cx = %g",
                 sm == RR_SLIP_LOCAL ? "local" : "rigid", cxs[23]);
        /* cx ~ 84, speed 10: exp(-0.6 * 840) underflows, mu = A mu0 to the last
         * bit; every element slides at about the rigid slip speed: 1e-9 */
        CHECK_CLOSE(F[23], ff.A * muN0, 0.0, 1e-9, buf);
        if (sm == RR_SLIP_RIGID) {
            /* full sliding at the rigid slip speed: exactly mu(speed cx) N; sums of
             * ~700 terms round at ~1e-15: 1e-9 per the brief */
            for (i = 0; i < 24; i++)
                if (cxs[i] >= 0.1) {
                    snprintf(buf, sizeof buf, "falling rigid: |F| = mu(speed cx) N at cx = %g",
                             cxs[i]);
                    CHECK_CLOSE(F[i], rr_friction_mu(&ff, c.speed * cxs[i]) * c.N, 0.0, 1e-9, buf);
                }
        } else {
            /* local slip speed: close to the rigid one once the whole patch
             * slides (measured 1.5e-4 above it at cx = 0.33, 2e-5 at 0.66,
             * 4e-7 at 1.3): 1e-3 */
            for (i = 0; i < 24; i++)
                if (cxs[i] >= 0.3) {
                    snprintf(buf, sizeof buf, "falling local: |F| ~ mu(speed cx) N at cx = %g",
                             cxs[i]);
                    CHECK_CLOSE(F[i], rr_friction_mu(&ff, c.speed * cxs[i]) * c.N, 0.0, 1e-3, buf);
                }
        }
    }
    /* lateral and diagonal creepage: the local slip speed uses the
     * flexibility of each direction (L2 for y); at full sliding it again
     * approaches the rigid slip speed */
    {
        static const double dirs[2][2] = {{0.0, 1.0}, {0.6, -0.8}};
        static const double mags[3] = {0.33, 0.66, 1.3};
        int d, i;
        for (d = 0; d < 2; d++)
            for (i = 0; i < 3; i++) {
                rr_creep_opts o = opts(RR_METHOD_FASTSIM, 30, 30, RR_BOUND_PARABOLIC, RR_GRID_RECT);
                rr_forces f;
                int st;
                c = base_case();
                c.cx = mags[i] * dirs[d][0];
                c.cy = mags[i] * dirs[d][1];
                st = rr_fastsim(with_law(&c, &ff), &o, &f, 0);
                snprintf(buf, sizeof buf, "falling local, creepage (%g, %g): |F| ~ mu(speed |c|) N",
                         c.cx, c.cy);
                CHECK_STATUS(st, RR_OK, buf);
                /* as for pure cx above: 1e-3 */
                CHECK_CLOSE(hypot(f.fx, f.fy), rr_friction_mu(&ff, c.speed * mags[i]) * c.N, 0.0,
                            1e-3, buf);
            }
    }
    /* speed 0 with falling friction: RR_ERR_SPEED and NaN, all FASTSIM variants
     * and the dispatcher; Coulomb friction at speed 0 is fine */
    {
        static const int methods[3] = {RR_METHOD_FASTSIM, RR_METHOD_FASTSIM_BLENDED,
                                       RR_METHOD_MODIFIED_FASTSIM};
        int im;
        for (im = 0; im < 3; im++) {
            rr_creep_opts o = opts(methods[im], 10, 10, RR_BOUND_PARABOLIC, RR_GRID_RECT);
            rr_friction fr = coulomb(0.3);
            rr_forces f;
            int st;
            c = base_case();
            c.cx = 1e-3;
            c.speed = 0.0;
            st = rr_fastsim(with_law(&c, &ff), &o, &f, 0);
            snprintf(buf, sizeof buf, "falling friction at speed 0, method %d", methods[im]);
            CHECK_STATUS(st, RR_ERR_SPEED, buf);
            CHECK(forces_nan(&f), buf);
            st = rr_creep_forces(with_law(&c, &ff), &o, &f);
            CHECK_STATUS(st, RR_ERR_SPEED, buf);
            CHECK(forces_nan(&f), buf);
            st = rr_fastsim(with_law(&c, &fr), &o, &f, 0);
            snprintf(buf, sizeof buf, "Coulomb friction at speed 0, method %d", methods[im]);
            CHECK_STATUS(st, RR_OK, buf);
            CHECK(isfinite(f.fx) && f.fx < 0.0, buf);
        }
    }
}

/* Bad options, friction and cases: documented status and NaN forces. */
static void test_bad_options(void)
{
    rr_contact_problem c = base_case();
    rr_friction fr = coulomb(0.3);
    rr_forces f;
    rr_creep_opts o;
    int st;

    c.cx = 1e-3;
#define BAD_OPT(method_, stmt, want, what)                                   \
    do {                                                                     \
        rr_creep_opts_default(&o, (method_));                                \
        stmt;                                                                \
        CHECK_STATUS(rr_creep_opts_check(&o), (want), what " (opts_check)"); \
        f.fx = f.fy = f.mz = 0.0;                                            \
        st = rr_creep_forces(with_law(&c, &fr), &o, &f);                               \
        CHECK_STATUS(st, (want), what " (rr_creep_forces)");                 \
        CHECK(forces_nan(&f), what " (rr_creep_forces NaN)");                \
    } while (0)

    BAD_OPT(RR_METHOD_FASTSIM, o.v[RR_FASTSIM_NX] = 0, RR_ERR_GRID, "nx = 0");
    BAD_OPT(RR_METHOD_FASTSIM, o.v[RR_FASTSIM_NY] = 0, RR_ERR_GRID, "ny = 0");
    BAD_OPT(RR_METHOD_FASTSIM, o.v[RR_FASTSIM_NX] = -3, RR_ERR_GRID, "nx < 0");
    BAD_OPT(RR_METHOD_FASTSIM, o.v[RR_FASTSIM_NX] = RR_FASTSIM_MAX_GRID + 1, RR_ERR_GRID, "nx > max");
    BAD_OPT(RR_METHOD_FASTSIM_BLENDED, o.v[RR_FASTSIM_NY] = RR_FASTSIM_MAX_GRID + 1, RR_ERR_GRID, "ny > max");
    BAD_OPT(RR_METHOD_FASTSIM, o.v[RR_FASTSIM_BOUND] = 7, RR_ERR_METHOD, "bound = 7");
    BAD_OPT(RR_METHOD_FASTSIM, o.v[RR_FASTSIM_BOUND] = -1, RR_ERR_METHOD, "bound = -1");
    BAD_OPT(RR_METHOD_FASTSIM, o.v[RR_FASTSIM_GRID] = 5, RR_ERR_METHOD, "grid = 5");
    BAD_OPT(RR_METHOD_FASTSIM, o.v[RR_FASTSIM_SLIP_SPEED] = 2, RR_ERR_METHOD, "slip_speed = 2");
    BAD_OPT(RR_METHOD_MODIFIED_FASTSIM, o.v[RR_FASTSIM_K0] = 0.0, RR_ERR_PARAM, "k0 = 0");
    BAD_OPT(RR_METHOD_MODIFIED_FASTSIM, o.v[RR_FASTSIM_K0] = 1.5, RR_ERR_PARAM, "k0 = 1.5");
    BAD_OPT(RR_METHOD_MODIFIED_FASTSIM, o.v[RR_FASTSIM_ALPHA_INF] = -0.1, RR_ERR_PARAM, "alpha_inf < 0");
    BAD_OPT(RR_METHOD_MODIFIED_FASTSIM, o.v[RR_FASTSIM_ALPHA_INF] = 1.1, RR_ERR_PARAM, "alpha_inf > 1");
    BAD_OPT(RR_METHOD_MODIFIED_FASTSIM, o.v[RR_FASTSIM_BETA] = -1.0, RR_ERR_PARAM, "beta < 0");
    BAD_OPT(RR_METHOD_MODIFIED_FASTSIM, o.v[RR_FASTSIM_K0] = NAN, RR_ERR_NONFINITE, "k0 NaN");
    BAD_OPT(RR_METHOD_POLACH, o.v[RR_POLACH_KA] = 2.0, RR_ERR_PARAM, "kA = 2");
    BAD_OPT(RR_METHOD_POLACH, o.v[RR_POLACH_KS] = 0.0, RR_ERR_PARAM, "kS = 0");
    BAD_OPT(RR_METHOD_POLACH, o.v[RR_POLACH_KS] = INFINITY, RR_ERR_NONFINITE, "kS inf");
    BAD_OPT(RR_METHOD_FASTSIM, o.method = 99, RR_ERR_METHOD, "method = 99");
    BAD_OPT(RR_METHOD_FASTSIM, o.method = -1, RR_ERR_METHOD, "method = -1");
#undef BAD_OPT

    /* only the values of a method's own options are checked (each method
     * has its own indices: values past its options are not looked at) */
    rr_creep_opts_default(&o, RR_METHOD_LINEAR);
    o.v[0] = 0;
    o.v[1] = 2.0;
    o.v[RR_FASTSIM_K0] = 0.0;
    CHECK_STATUS(rr_creep_opts_check(&o), RR_OK, "linear (no options) ignores every value");
    rr_creep_opts_default(&o, RR_METHOD_FASTSIM);
    o.v[RR_FASTSIM_K0] = 0.0;
    o.v[RR_FASTSIM_BETA] = -1.0;
    CHECK_STATUS(rr_creep_opts_check(&o), RR_OK, "FASTSIM ignores modified FASTSIM's k0, beta");
    rr_creep_opts_default(&o, RR_METHOD_POLACH);
    o.v[RR_FASTSIM_BOUND] = 7;
    CHECK_STATUS(rr_creep_opts_check(&o), RR_OK, "Polach ignores the values past kA, kS");
    /* the largest grid is accepted (one strip keeps it cheap) */
    o = opts(RR_METHOD_FASTSIM, RR_FASTSIM_MAX_GRID, 1, RR_BOUND_PARABOLIC, RR_GRID_STRIPS);
    st = rr_fastsim(with_law(&c, &fr), &o, &f, 0);
    CHECK_STATUS(st, RR_OK, "nx = RR_FASTSIM_MAX_GRID accepted");
    CHECK(isfinite(f.fx), "nx = RR_FASTSIM_MAX_GRID: finite");
    /* the smallest grid: one element */
    o = opts(RR_METHOD_FASTSIM, 1, 1, RR_BOUND_PARABOLIC, RR_GRID_RECT);
    st = rr_fastsim(with_law(&c, &fr), &o, &f, 0);
    CHECK_STATUS(st, RR_OK, "1 x 1 grid accepted");
    /* one element, pressure N/area: full sliding or not, |F| <= mu N */
    CHECK(isfinite(f.fx) && fabs(f.fx) <= 0.3 * c.N * (1.0 + 1e-12), "1 x 1 grid: finite, bounded");

    /* rr_fastsim with a method that is not FASTSIM */
    o = opts(RR_METHOD_POLACH, 10, 10, RR_BOUND_PARABOLIC, RR_GRID_RECT);
    st = rr_fastsim(with_law(&c, &fr), &o, &f, 0);
    CHECK_STATUS(st, RR_ERR_METHOD, "rr_fastsim with method Polach");
    CHECK(forces_nan(&f), "rr_fastsim with method Polach: NaN");
    o.method = RR_METHOD_LINEAR;
    st = rr_fastsim(with_law(&c, &fr), &o, &f, 0);
    CHECK_STATUS(st, RR_ERR_METHOD, "rr_fastsim with method linear");
    o = opts(RR_METHOD_FASTSIM, 10, 10, 7, RR_GRID_RECT);
    st = rr_fastsim(with_law(&c, &fr), &o, &f, 0);
    CHECK_STATUS(st, RR_ERR_METHOD, "rr_fastsim with bound = 7");
    CHECK(forces_nan(&f), "rr_fastsim with bound = 7: NaN");

    /* bad friction laws */
    {
        static const struct {
            double mu0, A, B;
            int status;
            const char *what;
        } t[] = {
            {0.0, 1.0, 0.0, RR_ERR_FRICTION, "mu0 = 0"},
            {-0.3, 1.0, 0.0, RR_ERR_FRICTION, "mu0 < 0"},
            {0.3, 1.5, 0.5, RR_ERR_FRICTION, "A > 1"},
            {0.3, -0.1, 0.5, RR_ERR_FRICTION, "A < 0"},
            {0.3, 0.4, -0.5, RR_ERR_FRICTION, "B < 0"},
            {NAN, 1.0, 0.0, RR_ERR_NONFINITE, "mu0 NaN"},
            {0.3, 0.4, INFINITY, RR_ERR_NONFINITE, "B inf"}
        };
        unsigned i;
        o = opts(RR_METHOD_FASTSIM, 10, 10, RR_BOUND_PARABOLIC, RR_GRID_RECT);
        for (i = 0; i < sizeof t / sizeof t[0]; i++) {
            rr_friction b = falling(t[i].mu0, t[i].A, t[i].B);
            CHECK_STATUS(rr_friction_check(&b), t[i].status, t[i].what);
            st = rr_fastsim(with_law(&c, &b), &o, &f, 0);
            CHECK_STATUS(st, t[i].status, t[i].what);
            CHECK(forces_nan(&f), t[i].what);
        }
    }
    /* bad contact case through FASTSIM */
    {
        rr_contact_problem b = base_case();
        o = opts(RR_METHOD_FASTSIM, 10, 10, RR_BOUND_PARABOLIC, RR_GRID_RECT);
        b.N = -1.0;
        st = rr_fastsim(with_law(&b, &fr), &o, &f, 0);
        CHECK_STATUS(st, RR_ERR_LOAD, "FASTSIM N < 0");
        CHECK(forces_nan(&f), "FASTSIM N < 0: NaN");
        b = base_case();
        b.cy = NAN;
        st = rr_fastsim(with_law(&b, &fr), &o, &f, 0);
        CHECK_STATUS(st, RR_ERR_NONFINITE, "FASTSIM cy NaN");
        b = base_case();
        b.b = 0.0;
        st = rr_fastsim(with_law(&b, &fr), &o, &f, 0);
        CHECK_STATUS(st, RR_ERR_GEOMETRY, "FASTSIM b = 0");
    }
}

/* Blended FASTSIM = plain FASTSIM for pure longitudinal creepage. */
static void test_blended(void)
{
    static const double cxs[] = {1e-7, 1e-5, 1e-4, 5e-4, 1e-3, 3e-3, 1e-2, 0.1, 1.0};
    unsigned i;
    int grid, sm;
    char buf[160];

    for (grid = 0; grid < 2; grid++)
        for (sm = 0; sm < 2; sm++)
            for (i = 0; i < sizeof cxs / sizeof cxs[0]; i++) {
                rr_contact_problem c = base_case();
                rr_friction fr = sm == 0 ? coulomb(0.3) : falling(0.3, 0.4, 0.6);
                rr_creep_opts op = opts(RR_METHOD_FASTSIM, 30, 30, RR_BOUND_PARABOLIC, grid);
                rr_creep_opts ob = opts(RR_METHOD_FASTSIM_BLENDED, 30, 30, RR_BOUND_PARABOLIC, grid);
                rr_forces fp, fb;
                double scale = fr.mu0 * c.N;
                c.cx = cxs[i] * (i % 2 ? -1.0 : 1.0);
                rr_fastsim(with_law(&c, &fr), &op, &fp, 0);
                rr_fastsim(with_law(&c, &fr), &ob, &fb, 0);
                snprintf(buf, sizeof buf, "blended = plain, pure cx = %g, %s, %s", c.cx,
                         grid_name[grid], sm ? "falling" : "Coulomb");
                /* the single flexibility is cx^2/(cx^2/L1) = L1 up to an ulp, and L2,
                 * L3 multiply zero creepages: 1e-12 relative */
                CHECK_CLOSE(fb.fx, fp.fx, 0.0, 1e-12, buf);
                CHECK(fb.fy == 0.0 && fp.fy == 0.0, buf);
                /* mz of a pure cx is a sum of +-y px that cancels to rounding:
                 * compare on the scale mu N b */
                CHECK_CLOSE(fb.mz, fp.mz, 1e-12 * scale * c.b, 0.0, buf);
            }
    /* The documented blend, checked where no element slips: the tractions
     * are then linear in c_i / L_i, so the blended forces are the plain
     * forces of each creepage alone times L_i / L_i' (exact superposition).
     * Both rules (cases 1 and 2 have spin: it enters rule "spin"'s weight
     * and not CONTACT's). */
    {
        static const double cr[3][3] = {{1e-6, 2e-6, 0.0}, {-1e-6, 5e-7, 2e-4}, {0.0, 1e-6, -1e-3}};
        int ic, rule;
        for (rule = 0; rule < 2; rule++)
        for (ic = 0; ic < 3; ic++) {
            rr_contact_problem c = base_case(), c1, c2, c3;
            rr_kalker_coeffs k = coeffs(&c);
            rr_friction fr = coulomb(0.3);
            rr_creep_opts op = opts(RR_METHOD_FASTSIM, 24, 20, RR_BOUND_PARABOLIC, RR_GRID_RECT);
            rr_creep_opts ob = opts(RR_METHOD_FASTSIM_BLENDED, 24, 20, RR_BOUND_PARABOLIC, RR_GRID_RECT);
            rr_fastsim_field fld = {0, 0, 0, 0, 0, 0, 0, 0};
            rr_forces fb, f1, f2, f3;
            double ab = c.a * c.b, cc = sqrt(ab), sat, fxn, fyn, fpn, w, pe, L, L1, L2, L3;
            double r1, r2, r3, ex, ey, em, scale;
            c.cx = cr[ic][0];
            c.cy = cr[ic][1];
            c.cphi = cr[ic][2];
            /* the header's formulas (Kalker 1982; Vollebregt and Voltr 2023) */
            L1 = 8.0 * c.a / (3.0 * k.c11 * c.G);
            L2 = 8.0 * c.a / (3.0 * k.c22 * c.G);
            L3 = RR_PI * c.a * sqrt(c.a / c.b) / (4.0 * k.c23 * c.G);
            sat = fr.mu0 * c.N;
            fxn = c.cx / (sat / (c.G * ab * k.c11));
            fyn = c.cy / (sat / (c.G * ab * k.c22));
            fpn = c.cphi / (sat / (c.G * ab * cc * k.c23));
            ob.v[RR_FASTSIM_BLEND_RULE] = rule;
            if (rule == RR_BLEND_CONTACT) {
                /* CONTACT's simpflex: |(cx, cy)| / |(ch_x, ch_y)| / 3, no spin */
                const double chx = sat / (c.G * ab * k.c11), chy = sat / (c.G * ab * k.c22);
                w = sqrt((c.cx * c.cx + c.cy * c.cy) / (chx * chx + chy * chy)) / 3.0;
            } else {
                w = sqrt(fxn * fxn + fyn * fyn + fpn * fpn) / 3.0;
            }
            if (w > 1.0)
                w = 1.0;
            pe = 3.0 * RR_PI * c.a * c.cphi / 32.0;
            L = (c.cx * c.cx + c.cy * c.cy + pe * pe)
              / (c.cx * c.cx / L1 + c.cy * c.cy / L2 + pe * pe / L3);
            r1 = L1 / ((1.0 - w) * L1 + w * L);
            r2 = L2 / ((1.0 - w) * L2 + w * L);
            r3 = L3 / ((1.0 - w) * L3 + w * L);
            c1 = c2 = c3 = c;
            c1.cy = c1.cphi = 0.0;
            c2.cx = c2.cphi = 0.0;
            c3.cx = c3.cy = 0.0;
            rr_fastsim(with_law(&c1, &fr), &op, &f1, 0);
            rr_fastsim(with_law(&c2, &fr), &op, &f2, 0);
            rr_fastsim(with_law(&c3, &fr), &op, &f3, 0);
            fld.slip = fld_slip;
            rr_fastsim(with_law(&c, &fr), &ob, &fb, &fld);
            snprintf(buf, sizeof buf, "blended flexibilities as documented, rule %d, case %d "
                     "(w = %.2e)", rule, ic, w);
            CHECK(fld.nslip == 0 && w > 1e-5, buf);
            ex = f1.fx * r1 + f2.fx * r2 + f3.fx * r3;
            ey = f1.fy * r1 + f2.fy * r2 + f3.fy * r3;
            em = f1.mz * r1 + f2.mz * r2 + f3.mz * r3;
            scale = hypot(f1.fx, f1.fy) + hypot(f2.fx, f2.fy) + hypot(f3.fx, f3.fy);
            /* superposition of three adhesion-only marches: rounding ~1e-15 of
             * the force scale; the blend itself moves the forces by ~w ~ 1e-4:
             * 1e-12 resolves it to 1e-8 */
            CHECK_CLOSE(fb.fx, ex, 1e-12 * scale, 0.0, buf);
            CHECK_CLOSE(fb.fy, ey, 1e-12 * scale, 0.0, buf);
            CHECK_CLOSE(fb.mz, em, 1e-12 * scale * c.a, 0.0, buf);
        }
    }
    /* with lateral creepage and spin the blend does change the result at
     * large creepage (sanity: the option is not a no-op) */
    {
        rr_contact_problem c = base_case();
        rr_friction fr = coulomb(0.3);
        rr_creep_opts op = opts(RR_METHOD_FASTSIM, 30, 30, RR_BOUND_PARABOLIC, RR_GRID_RECT);
        rr_creep_opts ob = opts(RR_METHOD_FASTSIM_BLENDED, 30, 30, RR_BOUND_PARABOLIC, RR_GRID_RECT);
        rr_forces fp, fb;
        c.cx = 2e-3;
        c.cy = 2e-3;
        c.cphi = 1.0;
        rr_fastsim(with_law(&c, &fr), &op, &fp, 0);
        rr_fastsim(with_law(&c, &fr), &ob, &fb, 0);
        CHECK(fb.fy != fp.fy, "blended differs from plain with cy and spin");
    }
}

/* Modified FASTSIM with k0 = 1, alpha_inf = 1 is plain FASTSIM; with the
 * defaults its initial slope is k0 times plain FASTSIM's. */
static void test_modified(void)
{
    static const double cr[5][3] = {
        {1e-6, 0.0, 0.0}, {1e-3, 0.0, 0.0}, {2e-3, -1.5e-3, 0.5}, {-4e-4, 3e-3, -2.0},
        {0.0, 1e-2, 4.0}};
    int grid, sm, ic;
    char buf[160];

    for (grid = 0; grid < 2; grid++)
        for (sm = 0; sm < 3; sm++)
            for (ic = 0; ic < 5; ic++) {
                rr_contact_problem c = base_case();
                rr_friction fr = sm == 0 ? coulomb(0.3) : falling(0.3, 0.4, 0.6);
                rr_creep_opts op = opts(RR_METHOD_FASTSIM, 25, 20, RR_BOUND_ELLIPTIC, grid);
                rr_creep_opts om = opts(RR_METHOD_MODIFIED_FASTSIM, 25, 20, RR_BOUND_ELLIPTIC, grid);
                rr_forces fp, fm;
                double scale = fr.mu0 * c.N;
                om.v[RR_FASTSIM_K0] = 1.0;
                om.v[RR_FASTSIM_ALPHA_INF] = 1.0;
                om.v[RR_FASTSIM_BETA] = 0.62;
                op.v[RR_FASTSIM_SLIP_SPEED] = om.v[RR_FASTSIM_SLIP_SPEED] = sm == 2 ? RR_SLIP_RIGID : RR_SLIP_LOCAL;
                c.cx = cr[ic][0];
                c.cy = cr[ic][1];
                c.cphi = cr[ic][2];
                rr_fastsim(with_law(&c, &fr), &op, &fp, 0);
                rr_fastsim(with_law(&c, &fr), &om, &fm, 0);
                snprintf(buf, sizeof buf, "modified(k0 = 1, alpha_inf = 1) = plain, %s, case %d, "
                         "friction %d", grid_name[grid], ic, sm);
                /* k = 1 (1 + 0/(1 + beta eps)) = 1 exactly, L/1 = L: 1e-12 on the
                 * force scale mu N (and mu N a for the moment) */
                CHECK_CLOSE(fm.fx, fp.fx, 1e-12 * scale, 1e-12, buf);
                CHECK_CLOSE(fm.fy, fp.fy, 1e-12 * scale, 1e-12, buf);
                CHECK_CLOSE(fm.mz, fp.mz, 1e-12 * scale * c.a, 1e-12, buf);
            }
    {
        rr_contact_problem c = base_case();
        rr_friction fr = coulomb(0.3);
        rr_creep_opts op = opts(RR_METHOD_FASTSIM, 30, 30, RR_BOUND_PARABOLIC, RR_GRID_RECT);
        rr_creep_opts om = opts(RR_METHOD_MODIFIED_FASTSIM, 30, 30, RR_BOUND_PARABOLIC, RR_GRID_RECT);
        rr_forces fp, fm;
        c.cx = 1e-10;
        rr_fastsim(with_law(&c, &fr), &op, &fp, 0);
        rr_fastsim(with_law(&c, &fr), &om, &fm, 0);
        /* eps ~ 1e-7 at this creepage: k = k0 (1 - (1 - alpha_inf) beta eps): 1e-6 */
        CHECK_CLOSE(fm.fx, om.v[RR_FASTSIM_K0] * fp.fx, 0.0, 1e-6, "modified FASTSIM: initial slope k0 x plain");
    }
    /* The documented slope reduction where no element slips: all L_i are
     * divided by k, so every traction, and the forces, are k times plain's.
     *   k = k0 (alpha_inf + (1 - alpha_inf)/(1 + beta eps)),
     *   eps = pi G a b k0 C11 |(cx, cy + a cphi)| / (4 mu N), the spin term
     *   only where it grows |cy|, mu at the rigid slip speed |(cx, cy)| speed */
    {
        static const double cr[4][3] = {
            {1e-6, 0.0, 0.0}, {1e-6, 2e-6, 0.0}, {-1e-6, 5e-7, 2e-4}, {5e-7, 1e-6, -1e-3}};
        int ic, sm;
        char buf[160];
        for (sm = 0; sm < 2; sm++)
            for (ic = 0; ic < 4; ic++) {
                rr_contact_problem c = base_case();
                rr_kalker_coeffs k = coeffs(&c);
                rr_friction fr = sm == 0 ? coulomb(0.3) : falling(0.3, 0.4, 0.6);
                rr_creep_opts op = opts(RR_METHOD_FASTSIM, 24, 20, RR_BOUND_PARABOLIC, RR_GRID_RECT);
                rr_creep_opts om = opts(RR_METHOD_MODIFIED_FASTSIM, 24, 20, RR_BOUND_PARABOLIC,
                                        RR_GRID_RECT);
                rr_fastsim_field fld = {0, 0, 0, 0, 0, 0, 0, 0};
                rr_forces fp, fm;
                double nphi, mu, eps, kf, scale;
                c.cx = cr[ic][0];
                c.cy = cr[ic][1];
                c.cphi = cr[ic][2];
                nphi = fabs(c.cy + c.a * c.cphi) > fabs(c.cy) ? c.cy + c.a * c.cphi : c.cy;
                mu = rr_friction_mu(&fr, c.speed * hypot(c.cx, c.cy));
                eps = RR_PI * c.G * c.a * c.b * om.v[RR_FASTSIM_K0] * k.c11 * hypot(c.cx, nphi) / (4.0 * mu * c.N);
                kf = om.v[RR_FASTSIM_K0] * (om.v[RR_FASTSIM_ALPHA_INF] + (1.0 - om.v[RR_FASTSIM_ALPHA_INF]) / (1.0 + om.v[RR_FASTSIM_BETA] * eps));
                rr_fastsim(with_law(&c, &fr), &op, &fp, 0);
                fld.slip = fld_slip;
                rr_fastsim(with_law(&c, &fr), &om, &fm, &fld);
                snprintf(buf, sizeof buf, "modified FASTSIM k as documented, case %d friction %d "
                         "(k/k0 - 1 = %.2e)", ic, sm, kf / om.v[RR_FASTSIM_K0] - 1.0);
                CHECK(fld.nslip == 0, buf);
                scale = hypot(fp.fx, fp.fy);
                /* one common factor on every traction: rounding only; the
                 * reduction beyond k0 is ~1e-4 here, resolved to 1e-8 */
                CHECK_CLOSE(fm.fx, kf * fp.fx, 1e-12 * scale, 0.0, buf);
                CHECK_CLOSE(fm.fy, kf * fp.fy, 1e-12 * scale, 0.0, buf);
                CHECK_CLOSE(fm.mz, kf * fp.mz, 1e-12 * scale * c.a, 0.0, buf);
            }
    }
}

/* The traction field sums back to the returned forces. */
static void test_field(void)
{
    static const double cr[3][3] = {{1e-3, 0.0, 0.0}, {2e-3, -1.5e-3, 0.5}, {-4e-4, 3e-3, -2.0}};
    static const int methods[2] = {RR_METHOD_FASTSIM, RR_METHOD_MODIFIED_FASTSIM};
    int grid, bound, ic, im, sm;
    char buf[200];

    for (grid = 0; grid < 2; grid++)
        for (bound = 0; bound < 2; bound++)
            for (ic = 0; ic < 3; ic++)
                for (im = 0; im < 2; im++)
                    for (sm = 0; sm < 2; sm++) {
                        const int nx = 27, ny = 22;
                        rr_contact_problem c = base_case();
                        rr_friction fr = sm == 0 ? coulomb(0.3) : falling(0.3, 0.4, 0.6);
                        rr_creep_opts o = opts(methods[im], nx, ny, bound, grid);
                        rr_fastsim_field fld;
                        rr_forces f, f0;
                        double dy = 2.0 * c.b / ny, sx = 0.0, sy = 0.0, sm_ = 0.0, sn = 0.0;
                        double muN = fr.mu0 * c.N;
                        int i, j, st, nsl = 0, okpos = 1, okbound = 1, okout = 1, okslip = 1;
                        c.cx = cr[ic][0];
                        c.cy = cr[ic][1];
                        c.cphi = cr[ic][2];
                        fld.x = fld_x;
                        fld.y = fld_y;
                        fld.pn = fld_pn;
                        fld.px = fld_px;
                        fld.py = fld_py;
                        fld.slip = fld_slip;
                        fld.nslip = -1;
                        fld.area = NULL;   /* not wanted here */
                        st = rr_fastsim(with_law(&c, &fr), &o, &f, &fld);
                        rr_fastsim(with_law(&c, &fr), &o, &f0, 0);
                        snprintf(buf, sizeof buf, "field %s %s case %d method %d friction %d",
                                 grid_name[grid], bound_name[bound], ic, methods[im], sm);
                        CHECK_STATUS(st, RR_OK, buf);
                        CHECK(f.fx == f0.fx && f.fy == f0.fy && f.mz == f0.mz, buf);
                        for (j = 0; j < ny; j++) {
                            const double yj = -c.b + (j + 0.5) * dy;
                            const double aj = grid == RR_GRID_STRIPS
                                ? c.a * sqrt(1.0 - yj * yj / (c.b * c.b)) : c.a;
                            /* element area: (2 a_j/nx)(2b/ny) on strips, (2a/nx)(2b/ny)
                             * on the rectangular grid */
                            const double area = 2.0 * aj / nx * dy;
                            for (i = 0; i < nx; i++) {
                                const int id = j * nx + i;
                                const double xi = -aj + (i + 0.5) * 2.0 * aj / nx;
                                /* positions: same formula, different rounding: 1e-12 of a */
                                if (fabs(fld_x[id] - xi) > 1e-12 * c.a
                                    || fabs(fld_y[id] - yj) > 1e-12 * c.b)
                                    okpos = 0;
                                if (i > 0 && !(fld_x[id] > fld_x[id - 1]))
                                    okpos = 0;
                                sx += fld_px[id] * area;
                                sy += fld_py[id] * area;
                                sm_ += (fld_x[id] * fld_py[id] - fld_y[id] * fld_px[id]) * area;
                                sn += fld_pn[id] * area;
                                nsl += fld_slip[id];
                                /* |p| <= mu0 pn, rounding 1e-12 */
                                if (!(hypot(fld_px[id], fld_py[id])
                                      <= fr.mu0 * fld_pn[id] * (1.0 + 1e-12)))
                                    okbound = 0;
                                if (fld_slip[id] != 0 && fld_slip[id] != 1)
                                    okslip = 0;
                                /* outside the ellipse: nothing */
                                if (fld_x[id] * fld_x[id] / (c.a * c.a)
                                        + fld_y[id] * fld_y[id] / (c.b * c.b) >= 1.0
                                    && (fld_pn[id] != 0.0 || fld_px[id] != 0.0
                                        || fld_py[id] != 0.0 || fld_slip[id] != 0))
                                    okout = 0;
                            }
                        }
                        CHECK(okpos, "field: element centres at the documented positions");
                        CHECK(okbound, "field: |p| <= mu pn in every element");
                        CHECK(okslip, "field: slip flags are 0 or 1");
                        CHECK(okout, "field: empty outside the ellipse");
                        CHECK(nsl == fld.nslip, "field: nslip = number of slip flags");
                        /* the same sums in another order: 1e-12 of the force scale mu N */
                        CHECK_CLOSE(sx, f.fx, 1e-12 * muN, 0.0, "field: sum px dA = fx");
                        CHECK_CLOSE(sy, f.fy, 1e-12 * muN, 0.0, "field: sum py dA = fy");
                        CHECK_CLOSE(sm_, f.mz, 1e-12 * muN * c.a, 0.0,
                                    "field: sum (x py - y px) dA = mz");
                        /* the pressure is scaled to sum to N on the grid: 1e-12 */
                        CHECK_CLOSE(sn, c.N, 0.0, 1e-12, "field: sum pn dA = N");
                    }

    /* partial field: only some outputs wanted; the rest stay untouched */
    {
        rr_contact_problem c = base_case();
        rr_friction fr = coulomb(0.3);
        rr_creep_opts o = opts(RR_METHOD_FASTSIM, 12, 10, RR_BOUND_PARABOLIC, RR_GRID_RECT);
        rr_fastsim_field fld = {0, 0, 0, 0, 0, 0, 0, 0};
        rr_forces f, f0;
        int st, i, ok = 1;
        for (i = 0; i < 120; i++)
            fld_x[i] = -7.0;
        fld.py = fld_py;
        c.cx = 1e-3;
        c.cy = 1e-3;
        st = rr_fastsim(with_law(&c, &fr), &o, &f, &fld);
        rr_fastsim(with_law(&c, &fr), &o, &f0, 0);
        CHECK_STATUS(st, RR_OK, "partial field: status");
        CHECK(f.fx == f0.fx && f.fy == f0.fy && f.mz == f0.mz, "partial field: same forces");
        for (i = 0; i < 120; i++)
            if (fld_x[i] != -7.0)
                ok = 0;
        CHECK(ok, "partial field: unrequested arrays untouched");
        CHECK(fld.nslip >= 0 && fld.nslip <= 120, "partial field: nslip set");
    }
}

static int same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* With one friction coefficient over the patch and no field, FASTSIM runs
 * its vector kernel (4 rows per AVX vector where the processor has AVX,
 * else 2); with a field, the scalar march.  Both must give the same bits
 * for any number of rows: groups of any width, idle lanes, groups past the
 * ones set up once (more than 80 rows with 2 lanes, 160 with 4). */
static void test_vector_kernel(void)
{
    static const int methods[3] = {RR_METHOD_FASTSIM, RR_METHOD_FASTSIM_BLENDED,
                                   RR_METHOD_MODIFIED_FASTSIM};
    static const int many_rows[4] = {81, 99, 161, 170};
    int t, rep, ok = 1, st_ok = 1, n = 0;
    char buf[160];

    /* 1 .. 40 rows, then a few more (the field of 170 x 37 fits MAXEL) */
    for (t = 0; t < 44; t++)
        for (rep = 0; rep < 8; rep++) {
            const int ny = t < 40 ? t + 1 : many_rows[t - 40];
            const int nx = 1 + (int)((ny <= 40 ? 40 : 37) * lcg());
            const int grid = rep & 1 ? RR_GRID_STRIPS : RR_GRID_RECT;
            const int bound = rep & 2 ? RR_BOUND_ELLIPTIC : RR_BOUND_PARABOLIC;
            rr_contact_problem c = base_case();
            rr_friction fr = rep & 4 ? falling(lcg_range(0.1, 0.6), lcg_range(0.2, 0.9),
                                               lcg_range(0.1, 2.0))
                                     : coulomb(lcg_range(0.1, 0.6));
            rr_creep_opts o = opts(methods[(int)(3 * lcg())], nx, ny, bound, grid);
            rr_fastsim_field fld = {0, 0, 0, 0, 0, 0, 0, 0};
            rr_forces f, f0;
            int st, st0;
            o.v[RR_FASTSIM_SLIP_SPEED] = RR_SLIP_RIGID;
            c.a = lcg_range(1e-3, 8e-3);
            c.b = c.a * lcg_range(0.2, 5.0);
            c.N = lcg_range(1e2, 1e5);
            c.cx = lcg_creep(5e-2);
            c.cy = lcg() < 0.2 ? 0.0 : lcg_creep(5e-3);
            c.cphi = lcg() < 0.2 ? 0.0 : lcg_creep(2.0);
            c.speed = lcg_range(0.5, 30.0);
            fld.px = fld_px;
            st = rr_fastsim(with_law(&c, &fr), &o, &f, 0);
            st0 = rr_fastsim(with_law(&c, &fr), &o, &f0, &fld);
            if (st != RR_OK || st0 != RR_OK)
                st_ok = 0;
            if (!same_bits(f.fx, f0.fx) || !same_bits(f.fy, f0.fy) || !same_bits(f.mz, f0.mz)) {
                if (ok) {
                    snprintf(buf, sizeof buf, "vector kernel = scalar march, first at %dx%d %s %s",
                             nx, ny, grid_name[grid], bound_name[bound]);
                    CHECK(0, buf);
                }
                ok = 0;
            }
            n++;
        }
    snprintf(buf, sizeof buf, "vector kernel = scalar march, bit for bit, on %d cases", n);
    CHECK(ok, buf);
    CHECK(st_ok, "vector kernel cases: status OK");
}

/* The dispatcher calls the chosen method. */
static void test_dispatch(void)
{
    static const int methods[3] = {RR_METHOD_FASTSIM, RR_METHOD_FASTSIM_BLENDED,
                                   RR_METHOD_MODIFIED_FASTSIM};
    rr_contact_problem c = base_case();
    rr_friction fr = falling(0.3, 0.4, 0.6);
    rr_forces f, g;
    int im, st;

    c.cx = 3e-3;
    c.cy = -1e-3;
    c.cphi = 0.4;
    for (im = 0; im < 3; im++) {
        rr_creep_opts o;
        rr_creep_opts_default(&o, methods[im]);
        st = rr_creep_forces(with_law(&c, &fr), &o, &f);
        rr_fastsim(with_law(&c, &fr), &o, &g, 0);
        CHECK(st == RR_OK && f.fx == g.fx && f.fy == g.fy && f.mz == g.mz,
              "dispatcher = rr_fastsim");
    }
    {
        rr_creep_opts o;
        rr_creep_opts_default(&o, RR_METHOD_POLACH);
        o.v[RR_POLACH_KA] = 0.9;
        o.v[RR_POLACH_KS] = 0.6;
        st = rr_creep_forces(with_law(&c, &fr), &o, &f);
        rr_polach(with_law(&c, &fr), 0.9, 0.6, &g);
        CHECK(st == RR_OK && f.fx == g.fx && f.fy == g.fy && f.mz == g.mz,
              "dispatcher = rr_polach with the options' kA, kS");
    }
    {
        /* documented defaults */
        rr_creep_opts o;
        rr_creep_opts_default(&o, RR_METHOD_MODIFIED_FASTSIM);
        CHECK(o.v[RR_FASTSIM_NX] == 30 && o.v[RR_FASTSIM_NY] == 30 && o.v[RR_FASTSIM_BOUND] == RR_BOUND_PARABOLIC && o.v[RR_FASTSIM_GRID] == RR_GRID_RECT
              && o.v[RR_FASTSIM_SLIP_SPEED] == RR_SLIP_RIGID && o.v[RR_FASTSIM_K0] == 0.54 && o.v[RR_FASTSIM_ALPHA_INF] == 0.02
              && o.v[RR_FASTSIM_BETA] == 0.62, "modified FASTSIM defaults");
        rr_creep_opts_default(&o, RR_METHOD_FASTSIM);
        CHECK(o.v[RR_FASTSIM_SLIP_SPEED] == RR_SLIP_LOCAL && isnan(o.v[RR_FASTSIM_K0]),
              "FASTSIM defaults (no k0: not its option)");
        rr_creep_opts_default(&o, RR_METHOD_POLACH);
        CHECK(o.v[RR_POLACH_KA] == 1.0 && o.v[RR_POLACH_KS] == 1.0, "Polach defaults");
    }
}

/* Extreme but finite inputs (issue 11's reproducers): a finite answer or
 * RR_ERR_RANGE with NaN, never NaN or inf with a success status; and
 * Polach's total force on the friction limit. */
static void test_extremes(void)
{
    rr_contact_problem c = {0};    /* an ellipse problem */
    rr_friction fr = {0.3, 1.0, 0.0};
    rr_creep_opts o;
    rr_forces f;
    int st, i, j, over = 0;
    double worst = 0.0;

    c.a = 2.2e-308; c.b = 0.0068; c.N = 1e4; c.G = 8.2e10; c.nu = 0.28;
    c.cx = 0.0068; c.cy = 0.001; c.cphi = 0.094; c.speed = 0.0;
    rr_creep_opts_default(&o, RR_METHOD_FASTSIM);
    st = rr_creep_forces(with_law(&c, &fr), &o, &f);
    CHECK_STATUS(st, RR_ERR_RANGE, "FASTSIM a = 2.2e-308 (was NaN with status 0)");
    CHECK(isnan(f.fx) && isnan(f.fy) && isnan(f.mz), "RANGE: NaN forces");

    c.a = 1e12; c.cx = 1e300; c.cy = 0.0; c.cphi = 0.0;
    rr_creep_opts_default(&o, RR_METHOD_LINEAR);
    st = rr_creep_forces(with_law(&c, &fr), &o, &f);
    CHECK_STATUS(st, RR_ERR_RANGE, "linear cx = 1e300, a = 1e12 (was -inf)");
    CHECK(isnan(f.fx), "RANGE: NaN");

    /* huge creepage on an ordinary patch: full sliding, |F| = mu N */
    c.a = c.b = 0.006; c.cx = 1e3;
    rr_creep_opts_default(&o, RR_METHOD_FASTSIM);
    st = rr_creep_forces(with_law(&c, &fr), &o, &f);
    CHECK_STATUS(st, RR_OK, "FASTSIM cx = 1e3");
    CHECK_CLOSE(f.fx, -0.3e4, 0.0, 1e-12, "FASTSIM cx = 1e3: full sliding");
    c.cx = 1e40;         /* 1e43 times the saturation creepage: still full sliding */
    CHECK_STATUS(rr_creep_forces(with_law(&c, &fr), &o, &f), RR_OK, "FASTSIM cx = 1e40");
    CHECK_CLOSE(f.fx, -0.3e4, 0.0, 1e-12, "FASTSIM cx = 1e40: full sliding");
    c.cx = 1e160;        /* increments beyond 1e150 Pa: their squares would overflow */
    CHECK_STATUS(rr_creep_forces(with_law(&c, &fr), &o, &f), RR_ERR_RANGE, "FASTSIM cx = 1e160");

    /* Polach with spin: 401 x 401 grid of cy, cphi at kS = 0.4, the rig's
     * default; the reproducer was cy = -0.0019, cphi = 0.38: |F| = 1.012 mu N */
    c.a = 0.01; c.b = 0.001; c.N = 1e4; c.cx = 0.0;
    fr.mu0 = 0.5;
    for (i = 0; i <= 400; i++)
        for (j = 0; j <= 400; j++) {
            c.cy = -0.01 + 0.02 * i / 400.0;
            c.cphi = -1.0 + 2.0 * j / 400.0;
            st = rr_polach(with_law(&c, &fr), 1.0, 0.4, &f);
            if (st != RR_OK || !(hypot(f.fx, f.fy) <= 0.5e4 * (1.0 + 1e-14)))
                over++;
            if (hypot(f.fx, f.fy) / 0.5e4 > worst)
                worst = hypot(f.fx, f.fy) / 0.5e4;
        }
    CHECK(over == 0, "Polach with spin: |F| <= mu N on the whole grid");
    c.cy = -0.0019; c.cphi = 0.38;
    CHECK_STATUS(rr_polach(with_law(&c, &fr), 1.0, 0.4, &f), RR_OK, "Polach reproducer");
    CHECK_CLOSE(hypot(f.fx, f.fy), 0.5e4, 0.0, 1e-14, "Polach reproducer: on the limit");
    CHECK(worst > 0.99, "the grid reaches the limit (the check is not vacuous)");

    /* NULL pointers */
    CHECK_STATUS(rr_creep_forces(NULL, &o, &f), RR_ERR_NULL, "problem NULL");
    CHECK(isnan(f.fx), "problem NULL: NaN");
    CHECK_STATUS(rr_creep_forces(with_law(&c, &fr), NULL, &f), RR_ERR_NULL, "options NULL");
    CHECK_STATUS(rr_creep_forces(with_law(&c, &fr), &o, NULL), RR_ERR_NULL, "out NULL");
    CHECK_STATUS(rr_fastsim(with_law(&c, &fr), NULL, &f, NULL), RR_ERR_NULL, "fastsim options NULL");
    /* the friction law at an infinite slip speed: Coulomb stays mu0 */
    fr.mu0 = 0.3; fr.A = 1.0; fr.B = 0.0;
    CHECK(rr_friction_mu(&fr, INFINITY) == 0.3, "Coulomb mu at w = inf");
    fr.A = 0.4; fr.B = 0.6;
    CHECK_CLOSE(rr_friction_mu(&fr, INFINITY), 0.12, 0.0, 1e-15, "falling mu at w = inf");
    CHECK(isnan(rr_friction_mu(NULL, 1.0)), "mu of a NULL law: NaN");
}

/* ---- FaStrip ------------------------------------------------------------- */

static void test_fastrip(void)
{
    rr_contact_problem c = base_case();
    rr_friction fr = coulomb(0.3), ff = falling(0.3, 0.4, 0.5);
    rr_kalker_coeffs k;
    rr_creep_opts o;
    rr_forces f, g;
    const double ab = c.a * c.b, cc = sqrt(ab);
    rr_kalker(c.a / c.b, c.nu, &k);
    rr_creep_opts_default(&o, RR_METHOD_FASTRIP);
    o.v[RR_FASTRIP_NX] = o.v[RR_FASTRIP_NY] = 90.0;

    CHECK_STATUS(rr_fastrip(with_law(&c, &fr), &o, &f), RR_OK, "fastrip zero creepage");
    CHECK(f.fx == 0.0 && f.fy == 0.0 && f.mz == 0.0, "zero creepage, zero force");

    /* linear limit: the strip theory's is Kalker's in the continuum; on 90 x
     * 90 the trailing edge's square-root traction costs about 1 % */
    c.cx = 1e-7;
    CHECK_STATUS(rr_fastrip(with_law(&c, &fr), &o, &f), RR_OK, "fastrip small cx");
    CHECK_CLOSE(f.fx, -c.G * ab * k.c11 * c.cx, 0.0, 0.02, "fastrip -> C11");
    CHECK(fabs(f.fy) <= 1e-12 * fabs(f.fx), "no lateral force from cx");
    c.cx = 0.0;
    c.cy = 1e-7;
    rr_fastrip(with_law(&c, &fr), &o, &f);
    CHECK_CLOSE(f.fy, -c.G * ab * k.c22 * c.cy, 0.0, 0.02, "fastrip -> C22");
    c.cy = 0.0;
    c.cphi = 1e-5;
    rr_fastrip(with_law(&c, &fr), &o, &f);
    CHECK_CLOSE(f.fy, -c.G * ab * cc * k.c23 * c.cphi, 0.0, 0.03, "fastrip -> C23");

    /* full sliding: |F| -> mu N on the pressure that sums to N */
    c.cphi = 0.0;
    c.cx = 0.3;
    c.cy = -0.4;
    rr_fastrip(with_law(&c, &fr), &o, &f);
    CHECK_CLOSE(hypot(f.fx, f.fy), 0.3 * c.N, 0.0, 1e-3, "fastrip full sliding");
    CHECK(hypot(f.fx, f.fy) <= 0.3 * c.N * (1.0 + 1e-12), "fastrip within mu N");

    /* symmetry: xi odd in fx; (eta, phi) odd in (fy, mz) */
    c.cx = 2e-4;
    c.cy = 3e-4;
    c.cphi = 0.3;
    rr_fastrip(with_law(&c, &fr), &o, &f);
    c.cx = -c.cx;
    rr_fastrip(with_law(&c, &fr), &o, &g);
    CHECK_CLOSE(g.fx, -f.fx, 1e-9 * c.N, 0.0, "fx odd in xi");
    CHECK_CLOSE(g.fy, f.fy, 1e-9 * c.N, 0.0, "fy even in xi");
    c.cy = -c.cy;
    c.cphi = -c.cphi;
    rr_fastrip(with_law(&c, &fr), &o, &g);
    CHECK_CLOSE(g.fx, -f.fx, 1e-9 * c.N, 0.0, "all signs: fx odd");
    CHECK_CLOSE(g.fy, -f.fy, 1e-9 * c.N, 0.0, "all signs: fy odd");
    CHECK_CLOSE(g.mz, -f.mz, 1e-9 * c.N * c.a, 0.0, "all signs: mz odd");

    /* refusals */
    CHECK_STATUS(rr_fastrip(with_law(&c, &ff), &o, &f), RR_ERR_FRICTION, "falling friction refused");
    CHECK(isnan(f.fx), "NaN on error");
    CHECK_STATUS(rr_fastrip(NULL, &o, &f), RR_ERR_NULL, "NULL problem");
    o.v[RR_FASTRIP_NX] = 0.0;
    CHECK_STATUS(rr_fastrip(with_law(&c, &fr), &o, &f), RR_ERR_GRID, "nx = 0");
    o.v[RR_FASTRIP_NX] = 30.0;
    o.v[RR_FASTRIP_K0] = 0.0;
    CHECK_STATUS(rr_fastrip(with_law(&c, &fr), &o, &f), RR_ERR_PARAM, "k0 = 0");
    o.v[RR_FASTRIP_K0] = 1.0;
    o.v[RR_FASTRIP_GEOMETRY] = 2.0;
    CHECK_STATUS(rr_fastrip(with_law(&c, &fr), &o, &f), RR_ERR_METHOD, "no geometry 2");
    o.v[RR_FASTRIP_GEOMETRY] = RR_FASTRIP_CONTACT;
    CHECK_STATUS(rr_creep_forces(with_law(&c, &fr), &o, &g), RR_OK, "dispatcher");
    CHECK_STATUS(rr_fastrip(with_law(&c, &fr), &o, &f), RR_OK, "contact geometry");
    CHECK(f.fx == g.fx && f.fy == g.fy && f.mz == g.mz, "dispatcher gives rr_fastrip's");
}

int main(void)
{
    test_linear();
    test_polach();
    test_fastsim_bound();
    test_full_sliding();
    test_odd_symmetry();
    test_slope();
    test_falling();
    test_bad_options();
    test_blended();
    test_modified();
    test_field();
    test_vector_kernel();
    test_dispatch();
    test_extremes();
    test_fastrip();
    return rr_test_summary();
}
