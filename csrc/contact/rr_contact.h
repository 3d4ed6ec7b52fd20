/*
 * rr_contact.h - the contact problem every creep-force method takes, and
 * the forces every method returns.
 *
 * A problem is the patch's geometry - Hertz's ellipse (semi-axes a, b) or
 * the undeformed distance h on a grid - with the normal load, the material,
 * the friction law and the creepages.  The ellipse is the grid's special
 * case whose gap is Hertz's A x^2 + B y^2: the ellipse methods need only
 * its semi-axes.
 *
 * Conventions (Kalker's, as CONTACT's): x rolling direction, y lateral, z
 * the normal into the wheel; material enters the patch at x = +a (the
 * grid's last column).  The creepages are the slip of the wheel relative
 * to the roller (or rail) divided by the rolling speed; with spin the
 * rigid slip at (x, y) is (cx - cphi y, cy + cphi x) about the reference
 * point: the ellipse's centre, or the grid problem's origin.  Forces act ON
 * THE WHEEL: for small creepage fx = -G a b C11 cx.  mz = sum of
 * (x py - y px) dA about the reference point.
 */
#ifndef RR_CONTACT_H
#define RR_CONTACT_H

#include "contact/rr_friction.h"

/* The patch of a problem: which of its two geometries holds. */
enum rr_patch {
    RR_PATCH_ELLIPSE = 0,   /* Hertz's ellipse: a, b (a zeroed problem's) */
    RR_PATCH_GRID = 1       /* the undeformed distance h on grid */
};

/* Largest mx, my of a problem's grid (the exact solver's). */
#define RR_CONTACT_MAX_GRID 1024

/* A rectangular grid of mx x my elements of dx x dy: element (i, j) of a
 * field on it is stored at j * mx + i, its centre at (x0 + i dx, y0 + j dy)
 * from the reference point; rows j along y, i along increasing x. */
typedef struct {
    int mx, my;          /* elements along x (rolling) and y */
    double dx, dy;       /* element size [m] */
    double x0, y0;       /* centre of element (0, 0) from the reference point [m] */
} rr_grid;

typedef struct {
    double a, b;         /* RR_PATCH_ELLIPSE: semi-axes [m], a along the rolling
                            direction, b lateral */
    double N;            /* normal load [N] */
    double G;            /* combined shear modulus [Pa] */
    double nu;           /* combined Poisson ratio, 0 <= nu <= 0.5 */
    double cx, cy;       /* longitudinal and lateral creepage xi, eta [-] */
    double cphi;         /* spin creepage phi [rad/m] */
    double speed;        /* rolling speed [m/s] >= 0; needed (> 0) by falling friction */
    rr_friction friction; /* the friction law (rr_friction.h) */
    int patch;           /* enum rr_patch */
    rr_grid grid;        /* RR_PATCH_GRID: the grid of h */
    const double *h;     /* RR_PATCH_GRID: the undeformed distance at the element
                            centres [m], grid.mx * grid.my values (any constant
                            offset: the approach is solved for) */
} rr_contact_problem;

typedef struct {
    double fx, fy;  /* tangential forces on the wheel [N] */
    double mz;      /* spin moment on the wheel about the reference point [N m] */
} rr_forces;

/*
 * The members of a problem, for reports: the one a check blames
 * (rr_contact_problem_check, rr_creep_blame).  One list, so that the names
 * cannot drift from the numbers: RR_PF_NONE (0: no one member), RR_PF_A,
 * ..., RR_PF_COUNT.
 */
#define RR_PROBLEM_FIELDS(X)                                                              \
    X(NONE, "") X(A, "a") X(B, "b") X(N, "N") X(G, "G") X(NU, "nu") X(CX, "cx")          \
    X(CY, "cy") X(CPHI, "cphi") X(SPEED, "speed") X(MU0, "friction.mu0")                 \
    X(FRICTION_A, "friction.A") X(FRICTION_B, "friction.B") X(PATCH, "patch")            \
    X(MX, "grid.mx") X(MY, "grid.my") X(DX, "grid.dx") X(DY, "grid.dy") X(X0, "grid.x0") \
    X(Y0, "grid.y0") X(H, "h")

enum rr_problem_field {
#define RR_PF_ENUM(tag, name) RR_PF_##tag,
    RR_PROBLEM_FIELDS(RR_PF_ENUM)
#undef RR_PF_ENUM
    RR_PF_COUNT
};

/* The member's name ("a", "friction.mu0", "grid.dx", "h"; "" for
 * RR_PF_NONE), or NULL for a number that is no member. */
const char *rr_problem_field_name(int field);

/*
 * rr_contact_problem_check - 0 if the problem is valid, else its status
 * with *field (may be NULL) the member at fault (RR_PF_NONE with RR_OK, or
 * for a NULL p):
 *   the ellipse, in this order: RR_ERR_NONFINITE (the first of a, b, N, G,
 *   nu, cx, cy, cphi, speed not finite), RR_ERR_GEOMETRY (a, b <= 0),
 *   RR_ERR_LOAD (N <= 0), RR_ERR_MATERIAL (G <= 0, nu outside [0, 0.5]),
 *   RR_ERR_SPEED (speed < 0), RR_ERR_RANGE (a, b, N or G subnormal: too few
 *   digits for a force); then the friction law as rr_friction_check
 *   (RR_ERR_NONFINITE, RR_ERR_FRICTION, RR_ERR_RANGE: mu0, A or B);
 *   a grid: RR_ERR_GRID (mx, my outside [1, RR_CONTACT_MAX_GRID]), then as
 *   the ellipse with dx, dy, x0, y0 for a, b (RR_ERR_GEOMETRY: dx, dy <= 0;
 *   RR_ERR_RANGE: dx, dy subnormal), RR_ERR_NULL (h NULL), RR_ERR_NONFINITE
 *   (a value of h), then the friction law;
 *   RR_ERR_PATCH (patch neither); RR_ERR_NULL (p NULL).
 * The methods' own demands on a valid problem (falling friction at rest,
 * Coulomb friction only, a table's range) are theirs (rr_creep_blame).
 */
int rr_contact_problem_check(const rr_contact_problem *p, int *field);

/* Set all outputs to NaN (error path; f may be NULL). */
void rr_forces_nan(rr_forces *f);

/* st, or RR_ERR_RANGE with NaN forces where a success status would carry a
 * non-finite force (a result beyond the floating-point range). */
int rr_forces_checked(int st, rr_forces *f);

#endif
