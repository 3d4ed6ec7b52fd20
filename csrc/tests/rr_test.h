/*
 * rr_test.h - a tiny header-only check helper for the C unit tests.
 *
 *   CHECK(cond, msg)                      condition must hold
 *   CHECK_CLOSE(got, want, abstol, reltol, what)
 *                                         |got - want| <= abstol + reltol |want|
 *                                         (NaN never passes; equal infinities do)
 *   CHECK_STATUS(got, want, what)         two status codes (enum rr_status) equal
 *   rr_test_summary()                     prints "N checks, M failed" and returns
 *                                         the exit code of the program (0 = pass)
 *
 * Each failure prints file:line and the values.  Every test program is a
 * single translation unit, so the counters are file-scope statics.
 */
#ifndef RR_TEST_H
#define RR_TEST_H

#include <math.h>
#include <stdio.h>
#include "util/rr_common.h"

static int rr_test_nchecks = 0;
static int rr_test_nfailed = 0;

static inline int rr_test_check(int ok, const char *file, int line, const char *msg)
{
    rr_test_nchecks++;
    if (!ok) {
        rr_test_nfailed++;
        printf("%s:%d: FAILED: %s\n", file, line, msg);
    }
    return ok;
}

static inline int rr_test_close(double got, double want, double abstol, double reltol,
                                const char *file, int line, const char *what)
{
    int ok;

    rr_test_nchecks++;
    if (isnan(got) || isnan(want))
        ok = 0;
    else if (isinf(got) || isinf(want))
        ok = got == want;
    else
        ok = fabs(got - want) <= abstol + reltol * fabs(want);
    if (!ok) {
        rr_test_nfailed++;
        printf("%s:%d: FAILED: %s\n    got  %.17g\n    want %.17g\n"
               "    diff %.3e (rel %.3e), allowed abs %.3e + rel %.3e\n",
               file, line, what, got, want, got - want,
               want != 0.0 ? fabs(got - want) / fabs(want) : fabs(got - want),
               abstol, reltol);
    }
    return ok;
}

static inline int rr_test_status(int got, int want, const char *file, int line,
                                 const char *what)
{
    rr_test_nchecks++;
    if (got != want) {
        rr_test_nfailed++;
        printf("%s:%d: FAILED: %s\n    status %d (%s), want %d (%s)\n", file, line, what,
               got, rr_status_message(got), want, rr_status_message(want));
        return 0;
    }
    return 1;
}

static inline int rr_test_summary(void)
{
    printf("%d checks, %d failed\n", rr_test_nchecks, rr_test_nfailed);
    return rr_test_nfailed == 0 ? 0 : 1;
}

#define CHECK(cond, msg) rr_test_check((cond) ? 1 : 0, __FILE__, __LINE__, (msg))
#define CHECK_CLOSE(got, want, abstol, reltol, what) \
    rr_test_close((got), (want), (abstol), (reltol), __FILE__, __LINE__, (what))
#define CHECK_STATUS(got, want, what) rr_test_status((got), (want), __FILE__, __LINE__, (what))

#endif
