/* rr_status.c - the one place where status messages live. */
#include "util/rr_common.h"

static const char *const rr_messages[] = {
    /* -19 */ ("too many samples did not converge (their inner iterations ended above the "
               "tolerance): the run cannot be trusted"),   /* parentheses: one string (clang) */
    /* -18 */ "a creep force exceeds mu N: the method broke its friction limit",
    /* -17 */ "interrupted by the caller",
    /* -16 */ "the controller failed (it raised, or gave what is not a command)",
    /* -15 */ "call out of order (a command before the reading, or two readings in a sample)",
    /* -14 */ "outside the exact-theory table (a/b beyond [0.1, 10], or nu not the table's)",
    /* -13 */ "a required pointer is NULL, or the object was never initialised",
    /* -12 */ "inputs too extreme: a result would overflow, underflow or lose its precision",
    /* -11 */ "matrix singular to working precision (e.g. I - gamma h J)",
    /* -10 */ "caller-supplied buffer missing or too small",
    /*  -9 */ "parameter out of range (a method option, a controller or search setting)",
    /*  -8 */ "unknown method or traction bound",
    /*  -7 */ "falling friction needs a positive rolling speed",
    /*  -6 */ "grid size out of range",
    /*  -5 */ "friction coefficient not positive or falling-law A, B invalid",
    /*  -4 */ "modulus not positive or Poisson ratio outside [0, 0.5]",
    /*  -3 */ "curvature or semi-axis not positive, or a wheel off its roller",
    /*  -2 */ "normal load not positive",
    /*  -1 */ "input is NaN or infinite",
    /*   0 */ "ok",
    /*   1 */ "inner iteration did not converge"
};

const char *rr_status_message(int status)
{
    if (status < RR_STATUS_MIN || status > RR_STATUS_MAX)
        return "unknown status";
    return rr_messages[status - RR_STATUS_MIN];
}
