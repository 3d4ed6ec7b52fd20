/*
 * fuzz.h - what every fuzz target shares: a cursor that decodes the fuzzer's
 * bytes into choices, integers and doubles, and the oracles that turn a
 * broken promise of the core into an abort() with one line on stderr.
 *
 * Decoding.  Every value is read from the front of the input; once the
 * input runs out every read returns zero bytes, so a short input is a
 * valid input and all-zero bytes decode to the plainest case (the first
 * choice, the low end of each plausible range, the default parameters).
 * A double is one selector byte and then its payload:
 *   selector   0..159  a plausible value, linear or logarithmic in a range
 *            160..199  a plausible value scaled by 2^e, e in [-1100, 1100]
 *                      (finite but extreme: the overflow and underflow paths)
 *            200..231  an edge value from a table (0, -0, subnormals,
 *                      DBL_MAX, inf, NaN, 0.5 - ulp, ...)
 *            232..255  8 raw bytes: any IEEE double
 * With cursor->edges == 0 every selector counts as plausible (the targets
 * switch edges off for long point lists, which one edge value would
 * nearly always make invalid).
 *
 * Oracles (beyond ASan and UBSan): a status outside the documented range,
 * a success status (>= 0) with a non-finite output, a frictional force
 * above mu0 N, an output written that should not be, a result the header
 * promises and the call does not give.
 *
 * Known defects: a target may skip an input class the core is known to
 * get wrong, so that fuzzing reaches past it, but only when compiled with
 * -DFUZZ_SKIP_KNOWN (make fuzz FUZZ_SKIP_KNOWN=1); the default build and
 * fuzz-ci do not skip anything.
 */
#ifndef RR_FUZZ_H
#define RR_FUZZ_H

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rollerrig.h"

#ifdef FUZZ_SKIP_KNOWN
#define FZ_SKIP_KNOWN 1
#else
#define FZ_SKIP_KNOWN 0
#endif

/* 1 if the input is in the known-defect class `name` (cond) and the build
 * skips known defects, unless FUZZ_KEEP names the class: minimising one
 * defect's reproducer (make fuzz FUZZ_SKIP_KNOWN=1, then FUZZ_KEEP=name
 * ... -minimize_crash=1) must not wander off into another. */
static inline int fz_known(const char *name, int cond)
{
    const char *keep;
    if (!FZ_SKIP_KNOWN || !cond)
        return 0;
    keep = getenv("FUZZ_KEEP");
    return !(keep && strcmp(keep, name) == 0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

typedef struct {
    const uint8_t *p;
    size_t n;
    int edges;   /* 1: doubles may take extreme and edge values */
} fz_in;

/* What the current input decoded to, noted by the target (fz_note) and
 * printed with any oracle's failure: the reproducer in numbers. */
static char fz_context[4096];
static size_t fz_context_len;

static inline fz_in fz_start(const uint8_t *data, size_t size)
{
    fz_in in;
    in.p = data;
    in.n = size;
    in.edges = 1;
    fz_context[0] = '\0';
    fz_context_len = 0;
    return in;
}

static void fz_note(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

static void fz_note(const char *fmt, ...)
{
    va_list ap;
    int k;
    if (fz_context_len + 2 >= sizeof fz_context)
        return;
    va_start(ap, fmt);
    k = vsnprintf(fz_context + fz_context_len, sizeof fz_context - fz_context_len, fmt, ap);
    va_end(ap);
    if (k > 0)
        fz_context_len += (size_t)k;
    if (fz_context_len >= sizeof fz_context)
        fz_context_len = sizeof fz_context - 1;
}

static inline unsigned fz_u8(fz_in *in)
{
    unsigned v = 0;
    if (in->n > 0) {
        v = in->p[0];
        in->p++;
        in->n--;
    }
    return v;
}

/* nbytes little-endian bytes (missing ones zero). */
static inline uint64_t fz_bits(fz_in *in, int nbytes)
{
    uint64_t v = 0;
    int i;
    for (i = 0; i < nbytes; i++)
        v |= (uint64_t)fz_u8(in) << (8 * i);
    return v;
}

/* 0 .. n-1 from one byte. */
static inline int fz_choice(fz_in *in, int n)
{
    return (int)(fz_u8(in) % (unsigned)n);
}

/* lo .. hi from four bytes (lo if hi < lo). */
static inline int fz_range(fz_in *in, int lo, int hi)
{
    const uint64_t b = fz_bits(in, 4);
    if (hi <= lo)
        return lo;
    return (int)((int64_t)lo + (int64_t)(b % ((uint64_t)((int64_t)hi - (int64_t)lo) + 1)));
}

/* An int that is usually in [lo, hi] and sometimes an edge (0, +-1,
 * INT_MIN, INT_MAX, the range's neighbours): one selector byte, four bytes. */
static inline int fz_int(fz_in *in, int lo, int hi)
{
    const unsigned sel = fz_u8(in);
    const int v = fz_range(in, lo, hi);
    if (sel < 224)
        return v;
    switch ((sel - 224) % 7) {
    case 0: return 0;
    case 1: return -1;
    case 2: return 1;
    case 3: return INT_MIN;
    case 4: return INT_MAX;
    case 5: return lo > INT_MIN ? lo - 1 : lo;
    default: return hi < INT_MAX ? hi + 1 : hi;
    }
}

/* [0, 1] from four bytes. */
static inline double fz_unit(fz_in *in)
{
    return (double)fz_bits(in, 4) / 4294967295.0;
}

static inline double fz_edge_value(unsigned k)
{
    static const double edge[] = {
        0.0, -0.0, 1.0, -1.0, 0.5, 0.49999999999999994, 2.0, -2.0,
        DBL_MIN, -DBL_MIN, 4.9406564584124654e-324, -4.9406564584124654e-324,
        DBL_MAX, -DBL_MAX, HUGE_VAL, -HUGE_VAL,
        1e-300, 1e300, -1e300, 1e-150, 1e150, DBL_EPSILON, 1e-9, 1e9,
        0.1, 1e-3, 1e3, 1e6, 1e12, 1e250, 0x1p-1022, 0x1.fffffffffffffp-1023
    };
    const unsigned n = sizeof edge / sizeof edge[0];
    if (k % (n + 2) == n)
        return NAN;
    if (k % (n + 2) == n + 1)
        return -NAN;
    return edge[k % (n + 2)];
}

/* v itself, or the extreme or edge value the selector asks for. */
static inline double fz_extreme(fz_in *in, unsigned sel, double v)
{
    if (sel < 160 || !in->edges)
        return v;
    if (sel < 200)
        return ldexp(v, fz_range(in, -1100, 1100));
    if (sel < 232)
        return fz_edge_value(fz_u8(in));
    {
        uint64_t b = fz_bits(in, 8);
        double d;
        memcpy(&d, &b, sizeof d);
        return d;
    }
}

/* A double, plausibly uniform in [lo, hi]. */
static inline double fz_lin(fz_in *in, double lo, double hi)
{
    const unsigned sel = fz_u8(in);
    const double v = lo + fz_unit(in) * (hi - lo);
    return fz_extreme(in, sel, v);
}

/* A double, plausibly log-uniform in [lo, hi], 0 < lo < hi. */
static inline double fz_log(fz_in *in, double lo, double hi)
{
    const unsigned sel = fz_u8(in);
    const double v = lo * pow(hi / lo, fz_unit(in));
    return fz_extreme(in, sel, v);
}

/* A double of either sign, plausibly log-uniform in magnitude in [lo, hi]
 * (and exactly 0 for one payload in 64). */
static inline double fz_slog(fz_in *in, double lo, double hi)
{
    const unsigned sel = fz_u8(in);
    const uint64_t b = fz_bits(in, 4);
    const double u = (double)(b >> 7) / 33554431.0;
    double v = (b & 63) == 0 ? 0.0 : lo * pow(hi / lo, u);
    if (b & 64)
        v = -v;
    return fz_extreme(in, sel, v);
}

/* A plausible value or, with one selector in four, the default d times a
 * log-uniform factor in [1/f, f]; edges as above.  For perturbing a valid
 * parameter set: all-zero bytes give d itself. */
static inline double fz_near(fz_in *in, double d, double f)
{
    const unsigned sel = fz_u8(in);
    const double u = fz_unit(in);
    const double v = sel < 120 ? d : (sel < 160 ? d * pow(f, 2.0 * u - 1.0) : d);
    return fz_extreme(in, sel, v);
}

/* ---- oracles ------------------------------------------------------------------ */

static void fz_fail(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((noreturn, format(printf, 1, 2)))
#endif
    ;

static void fz_fail(const char *fmt, ...)
{
    va_list ap;
    fputs("fuzz oracle: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    if (fz_context_len > 0)
        fprintf(stderr, "fuzz input: %s\n", fz_context);
    fflush(stderr);
    abort();
}

/* A status must be one of the documented codes. */
static inline void fz_status(const char *fn, int st)
{
    if (st < RR_STATUS_MIN || st > RR_STATUS_MAX)
        fz_fail("%s: status %d outside [%d, %d]", fn, st, RR_STATUS_MIN, RR_STATUS_MAX);
}

/* A success status (>= 0) promises a finite output. */
static inline void fz_finite(const char *fn, int st, const char *what, double v)
{
    if (st >= 0 && !isfinite(v))
        fz_fail("%s: status %d (%s) with non-finite %s = %g", fn, st, rr_status_message(st),
                what, v);
}

#define FZ_FINITE(fn, st, x) fz_finite((fn), (st), #x, (x))

static inline void fz_finite_n(const char *fn, int st, const char *what, const double *v,
                               int n)
{
    int i;
    if (st < 0)
        return;
    for (i = 0; i < n; i++)
        if (!isfinite(v[i]))
            fz_fail("%s: status %d (%s) with non-finite %s[%d] = %g", fn, st,
                    rr_status_message(st), what, i, v[i]);
}

/* An invalid input must give an error. */
static inline void fz_error(const char *fn, int st, int invalid, const char *why)
{
    if (invalid && st >= 0)
        fz_fail("%s: status %d (%s) although %s", fn, st, rr_status_message(st), why);
}

/* Coulomb's bound: |(fx, fy)| <= mu0 N for every frictional method. */
static inline void fz_bound(const char *fn, int st, double fx, double fy, double mu0, double N)
{
    if (st >= 0 && !(hypot(fx, fy) <= mu0 * N * (1.0 + 1e-9)))
        fz_fail("%s: status %d with |(fx, fy)| = |(%.17g, %.17g)| = %.17g above mu0 N = "
                "%.17g * %.17g = %.17g", fn, st, fx, fy, hypot(fx, fy), mu0, N, mu0 * N);
}

/* Bytes that must not change. */
static inline void fz_same(const char *fn, const void *before, const void *after, size_t n,
                           const char *what)
{
    if (memcmp(before, after, n) != 0)
        fz_fail("%s: changed %s, which it must leave alone", fn, what);
}

/* Exactly the bytes asked for, on the heap, so that ASan sees one past the
 * end; zero-filled (a count of 0 still gives a valid pointer). */
static inline void *fz_alloc(size_t n)
{
    void *p = calloc(n > 0 ? n : 1, 1);
    if (!p)
        abort();
    return p;
}

/* Guarded caller buffers: nbytes for the call between FZ_GUARD bytes of a
 * canary on either side, the inside filled with the canary too (so that
 * "left alone" can be checked against it), on the heap.  fz_guard_ok fails
 * the oracle if a canary byte changed: a write beyond the documented
 * length that lands inside the allocation, which ASan cannot see. */
#define FZ_GUARD 64
#define FZ_CANARY 0xA5

static inline void *fz_guarded(size_t nbytes)
{
    unsigned char *p = fz_alloc(nbytes + 2 * FZ_GUARD);
    memset(p, FZ_CANARY, nbytes + 2 * FZ_GUARD);
    return p + FZ_GUARD;
}

static inline void fz_guard_ok(const char *fn, const void *buf, size_t nbytes, const char *what)
{
    const unsigned char *p = buf;
    size_t i;
    if (!p)
        return;
    for (i = 0; i < FZ_GUARD; i++)
        if (p[-(ptrdiff_t)FZ_GUARD + (ptrdiff_t)i] != FZ_CANARY || p[nbytes + i] != FZ_CANARY)
            fz_fail("%s: wrote outside %s (%zu bytes): guard byte %s%zu changed", fn, what,
                    nbytes, p[nbytes + i] != FZ_CANARY ? "+" : "-",
                    p[nbytes + i] != FZ_CANARY ? i : FZ_GUARD - i);
}

/* 1 if the nbytes inside the guards are all still the canary. */
static inline int fz_untouched(const void *buf, size_t nbytes)
{
    const unsigned char *p = buf;
    size_t i;
    for (i = 0; i < nbytes; i++)
        if (p[i] != FZ_CANARY)
            return 0;
    return 1;
}

static inline void fz_guard_free(void *buf)
{
    if (buf)
        free((unsigned char *)buf - FZ_GUARD);
}

/* 1 where member `field` of contact problem p (either patch) is at fault as
 * status st says, judged member by member from rr_contact_problem_check's
 * documentation (the one oracle of fuzz_creep and fuzz_exact). */
static inline int fz_member_at_fault(const rr_contact_problem *p, int field, int st)
{
    const rr_grid *q = &p->grid;
    const int grid = p->patch == RR_PATCH_GRID;
    double v;
    long i, bad = 0;
    switch (field) {
    case RR_PF_PATCH: return st == RR_ERR_PATCH && !grid && p->patch != RR_PATCH_ELLIPSE;
    case RR_PF_MX:
        return grid && st == RR_ERR_GRID && !(q->mx >= 1 && q->mx <= RR_CONTACT_MAX_GRID);
    case RR_PF_MY:
        return grid && st == RR_ERR_GRID && !(q->my >= 1 && q->my <= RR_CONTACT_MAX_GRID);
    case RR_PF_H:
        if (!grid || st == RR_ERR_NULL)
            return grid && !p->h;
        for (i = 0; p->h && i < (long)q->mx * q->my; i++)
            bad |= !isfinite(p->h[i]);
        return st == RR_ERR_NONFINITE && bad;
    case RR_PF_A: if (grid) return 0; v = p->a; break;
    case RR_PF_B: if (grid) return 0; v = p->b; break;
    case RR_PF_DX: if (!grid) return 0; v = q->dx; break;
    case RR_PF_DY: if (!grid) return 0; v = q->dy; break;
    case RR_PF_X0: if (!grid) return 0; v = q->x0; break;
    case RR_PF_Y0: if (!grid) return 0; v = q->y0; break;
    case RR_PF_N: v = p->N; break;
    case RR_PF_G: v = p->G; break;
    case RR_PF_NU: v = p->nu; break;
    case RR_PF_CX: v = p->cx; break;
    case RR_PF_CY: v = p->cy; break;
    case RR_PF_CPHI: v = p->cphi; break;
    case RR_PF_SPEED: v = p->speed; break;
    case RR_PF_MU0: v = p->friction.mu0; break;
    case RR_PF_FRICTION_A: v = p->friction.A; break;
    case RR_PF_FRICTION_B: v = p->friction.B; break;
    default: return 0;
    }
    switch (st) {
    case RR_ERR_NONFINITE: return !isfinite(v);
    case RR_ERR_GEOMETRY: return (field == RR_PF_A || field == RR_PF_B || field == RR_PF_DX
                                  || field == RR_PF_DY) && !(v > 0.0);
    case RR_ERR_LOAD: return field == RR_PF_N && !(v > 0.0);
    case RR_ERR_MATERIAL: return (field == RR_PF_G && !(v > 0.0))
                                 || (field == RR_PF_NU && !(v >= 0.0 && v <= 0.5));
    case RR_ERR_SPEED: return field == RR_PF_SPEED && !(v >= 0.0);
    case RR_ERR_FRICTION: return (field == RR_PF_MU0 && !(v > 0.0))
                                 || (field == RR_PF_FRICTION_A && !(v > 0.0 && v <= 1.0))
                                 || (field == RR_PF_FRICTION_B && !(v >= 0.0));
    case RR_ERR_RANGE: return ((field == RR_PF_MU0 || field == RR_PF_FRICTION_B)
                               && v > RR_FRICTION_MAX) || !isnormal(v);
    default: return 0;
    }
}

/* 1 if v[0..n-1] are all NaN. */
static inline int fz_all_nan(const double *v, long n)
{
    long i;
    for (i = 0; i < n; i++)
        if (!isnan(v[i]))
            return 0;
    return 1;
}

#endif
