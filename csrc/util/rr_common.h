/*
 * rr_common.h - status codes, constants and small helpers shared by every
 * module of the rollerrig C core.
 *
 * Conventions (whole core): SI units (m, s, N, Pa, rad); x is the rolling
 * direction, y lateral, z normal; semi-axis a lies along x, b along y.
 * Every public function returns an int status: 0 OK, > 0 warning (outputs
 * valid), < 0 error (outputs set to NaN).  No function prints, aborts,
 * allocates or touches errno.  Every entry point checks what a C caller can
 * get wrong: a NULL pointer gives RR_ERR_NULL (the outputs it can reach set
 * to NaN), and finite inputs so extreme that a result would not be a finite
 * double give RR_ERR_RANGE: a success status never comes with a NaN or an
 * infinity.
 */
#ifndef RR_COMMON_H
#define RR_COMMON_H

#define RR_VERSION_MAJOR 0
#define RR_VERSION_MINOR 1
#define RR_VERSION_PATCH 0

enum rr_status {
    RR_OK = 0,
    /* warnings: results are usable but less certain */
    RR_WARN_NOT_CONVERGED = 1,  /* an inner iteration hit its cap */
    /* errors: outputs are NaN */
    RR_ERR_NONFINITE = -1,      /* an input is NaN or infinite */
    RR_ERR_LOAD = -2,           /* normal load not positive */
    RR_ERR_GEOMETRY = -3,       /* curvature or semi-axis not positive; wheel off its roller */
    RR_ERR_MATERIAL = -4,       /* modulus not positive or nu outside [0, 0.5] */
    RR_ERR_FRICTION = -5,       /* mu not positive, or A, B of the falling law invalid */
    RR_ERR_GRID = -6,           /* grid size outside [1, RR_FASTSIM_MAX_GRID] */
    RR_ERR_SPEED = -7,          /* falling friction needs a positive rolling speed */
    RR_ERR_METHOD = -8,         /* unknown method or traction bound */
    RR_ERR_PARAM = -9,          /* parameter out of range: method option (k0, alpha_inf, beta,
                                   kA, kS), search option, controller setting */
    RR_ERR_WORKSPACE = -10,     /* caller-supplied buffer missing or too small */
    RR_ERR_SINGULAR = -11,      /* a linear system (e.g. I - gamma h J) is singular */
    RR_ERR_RANGE = -12,         /* finite inputs so extreme that a result would overflow,
                                   underflow to zero or lose its precision */
    RR_ERR_NULL = -13,          /* a required pointer is NULL, or an object was never
                                   initialised */
    RR_ERR_TABLE = -14,         /* outside a table: a/b beyond its range, nu not its own */
    RR_ERR_SEQUENCE = -15,      /* a call out of its order (the rig's command before its
                                   reading, or a second reading in one sample) */
    RR_ERR_CONTROLLER = -16,    /* a controller of the caller's failed (it raised, or gave
                                   what is not a command): set by the loop that calls it */
    RR_ERR_INTERRUPTED = -17,   /* stopped by the caller's interrupt hook (rr_interrupt) */
    RR_ERR_FRICTION_LIMIT = -18, /* a creep force exceeds mu N: the method broke its limit */
    RR_ERR_UNTRUSTED = -19,     /* a run's samples did not converge too often to be trusted:
                                   set by the loop that judges the run */
    RR_ERR_PATCH = -20          /* a contact patch the method does not take (an undeformed
                                   distance on a grid, for a method of the ellipse only) */
};

#define RR_STATUS_MIN (-20)
#define RR_STATUS_MAX 1

/* Message of a status code; a fixed string, never NULL. */
const char *rr_status_message(int status);

#define RR_PI 3.14159265358979323846

/* Tables that cannot drift (the core's own, not for callers): the entries
 * of an array counted by its size, and a condition the compiler checks
 * (C99 has no _Static_assert: an array of size -1 stops the build). */
#define RR_COUNTOF(a) ((int)(sizeof(a) / sizeof((a)[0])))
#define RR_STATIC_ASSERT(cond, name) typedef char rr_static_assert_##name[(cond) ? 1 : -1]

/* The caller's interrupt hook of a computation that may take seconds (the
 * exact theory's solve): poll(ctx) is called between its steps, and a
 * nonzero return stops it with RR_ERR_INTERRUPTED (outputs NaN).  poll must
 * not touch the computation's own arguments; a NULL hook or poll: never. */
typedef struct {
    int (*poll)(void *ctx);
    void *ctx;
} rr_interrupt;

/* 1 where the hook i asks to stop. */
static inline int rr_interrupted(const rr_interrupt *i)
{
    return i && i->poll && i->poll(i->ctx) != 0;
}

/* 1 if v[0..n-1] are all finite.  0 * x is NaN exactly when x is NaN or
 * infinite, and a NaN survives any sum: one test at the end instead of a
 * branch per value, for the checks on a time step's hot path. */
static inline int rr_all_finite(const double *v, int n)
{
    double acc = 0.0;
    int i;
    for (i = 0; i < n; i++)
        acc += 0.0 * v[i];
    return acc == 0.0;
}

/* a . b of 3-vectors */
static inline double rr_dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* out = a x b of 3-vectors (out not a or b) */
static inline void rr_cross3(const double *a, const double *b, double *out)
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

#endif
