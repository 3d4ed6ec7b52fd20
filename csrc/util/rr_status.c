/* rr_status.c - the one place where status messages live. */
#include "util/rr_common.h"

/* each message at its code (designated: a row cannot land on another code) */
#define AT(code) [(code) - RR_STATUS_MIN]
static const char *const rr_messages[] = {
    AT(RR_ERR_PATCH) = "the method does not take this contact patch (it is defined on the Hertz "
        "ellipse only, not on an undeformed distance on a grid)",
    AT(RR_ERR_UNTRUSTED) = "too many samples did not converge (their inner iterations ended above "
        "the tolerance): the run cannot be trusted",
    AT(RR_ERR_FRICTION_LIMIT) = "a creep force exceeds mu N: the method broke its friction limit",
    AT(RR_ERR_INTERRUPTED) = "interrupted by the caller",
    AT(RR_ERR_CONTROLLER) = "the controller failed (it raised, or gave what is not a command)",
    AT(RR_ERR_SEQUENCE) = "call out of order (a command before the reading, or two readings in a "
        "sample)",
    AT(RR_ERR_TABLE) = "outside the exact-theory table (a/b beyond [0.1, 10], or nu not the "
        "table's)",
    AT(RR_ERR_NULL) = "a required pointer is NULL, or the object was never initialised",
    AT(RR_ERR_RANGE) = "inputs too extreme: a result would overflow, underflow or lose its "
        "precision",
    AT(RR_ERR_SINGULAR) = "matrix singular to working precision (e.g. I - gamma h J)",
    AT(RR_ERR_WORKSPACE) = "caller-supplied buffer missing or too small",
    AT(RR_ERR_PARAM) = "parameter out of range (a method option, a controller or search setting)",
    AT(RR_ERR_METHOD) = "unknown method or traction bound",
    AT(RR_ERR_SPEED) = "falling friction needs a positive rolling speed",
    AT(RR_ERR_GRID) = "grid size out of range",
    AT(RR_ERR_FRICTION) = "friction coefficient not positive or falling-law A, B invalid",
    AT(RR_ERR_MATERIAL) = "modulus not positive or Poisson ratio outside [0, 0.5]",
    AT(RR_ERR_GEOMETRY) = "curvature or semi-axis not positive, or a wheel off its roller",
    AT(RR_ERR_LOAD) = "normal load not positive",
    AT(RR_ERR_NONFINITE) = "input is NaN or infinite",
    AT(RR_OK) = "ok",
    AT(RR_WARN_NOT_CONVERGED) = "inner iteration did not converge",
};
#undef AT
RR_STATIC_ASSERT(RR_COUNTOF(rr_messages) == RR_STATUS_MAX - RR_STATUS_MIN + 1, one_per_code);

const char *rr_status_message(int status)
{
    if (status < RR_STATUS_MIN || status > RR_STATUS_MAX)
        return "unknown status";
    return rr_messages[status - RR_STATUS_MIN];
}
