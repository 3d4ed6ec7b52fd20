/*
 * rr_exact.h - Kalker's exact ("complete") theory of steady rolling contact
 * between two quasi-identical elastic half-spaces with Coulomb friction.
 *
 * The potential contact area is a rectangular grid of mx x my elements of
 * dx x dy with piecewise-constant tractions; the displacements are
 * collocated at the element centres through the half-space's influence
 * coefficients (rr_influence.h), and every product with them is a 2-D
 * convolution done by FFT (rr_fft.h), O(N log N) instead of O(N^2).
 *   Normal problem: given the undeformed distance h and the load N, find
 *   the pressure pn >= 0 and the approach: a bound-constrained quadratic
 *   programme, solved by conjugate gradients on the active set with the
 *   load kept by deflation (Vollebregt's NormCG, J. Comput. Phys. 257,
 *   2014), preconditioned by the 3 x 3 stencil nearest the inverse of the
 *   half-space's operator (from its symbol on the FFT's torus).
 *   Tangential problem: given the creepages, the slip s = w + (u(x) -
 *   u(x + dx))/dx (steady rolling: the material derivative as the upwind
 *   difference over one element, CONTACT's discretisation), with w the
 *   rigid slip, find p with s = 0, |p| <= mu pn in adhesion and p = -mu pn
 *   s/|s| in slip.  Solved as p = Proj(p - rho s) by a semismooth Newton
 *   method whose linear systems go to GMRES, preconditioned by the
 *   inverse of the upwind difference along each run of adhering elements
 *   (which turns the steady operator into the symmetric half-space one),
 *   then by the 3 x 3 stencil nearest the symmetric operator's inverse on
 *   the adhering elements.
 * Conventions as rr_contact.h (CONTACT's): x rolling, material entering at
 * +x, tractions and forces on body 1 (the wheel), rigid slip (cx - cphi y,
 * cy + cphi x) about the reference point.  Element (i, j) of every field
 * is stored at j * mx + i, its centre at (x0 + i dx, y0 + j dy) (rr_grid).
 *
 * The tangential problem lives on the elements in contact, so it is
 * solved on the grid's box around them where that box's torus is at most
 * 4/5 of the grid's (a wheel's patch covers where h reaches the approach,
 * about twice the contact's area): the same equations, the products'
 * rounding aside.  So is the normal problem of a warm start
 * (rr_exact_solve_from), on the box around the start's contact, where one
 * product on the grid shows that no element outside the box is
 * penetrated (else the grid's own solve follows).
 *
 * Memory: caller workspace only (rr_exact_workspace_len doubles for the
 * largest grid used: the grid's layout, and from its middle room for its
 * box's), zero-filled before its first use: the solver keeps the kernel
 * spectra of the last grid shape and Poisson ratio there, and those of its
 * last box, and reuses them for the next case of the same shape (a batch
 * of cases with the same a/b and grid builds them once).  Nothing else a case leaves
 * there (its iterates, a failed case's NaN) reaches the next: a case gives
 * the doubles it gives on a fresh workspace.  One workspace per thread.
 */
#ifndef RR_EXACT_H
#define RR_EXACT_H

#include <stddef.h>
#include "util/rr_common.h"
#include "contact/rr_creep_opts.h"

/* Largest mx, my accepted: a contact problem's (rr_contact.h). */
#define RR_EXACT_MAX_GRID RR_CONTACT_MAX_GRID
/* Elements the Hertzian grid adds on each side of the ellipse (as CONTACT's
 * potential contact area with SCALE = mx / (mx - 4)). */
#define RR_EXACT_MARGIN 2

/* The solver's problem: a contact problem's grid and gap (or Hertz's, from
 * its curvatures) with the solver's settings; rr_exact_problem_from makes
 * it from a contact problem and the options of the method "exact". */
typedef struct {
    rr_grid grid;        /* the grid (rr_contact.h) */
    const double *h;     /* undeformed distance at the element centres [m], mx * my
                            (any constant offset: the approach is solved for);
                            NULL: the Hertzian h = A x^2 + B y^2 */
    double A, B;         /* curvature sums [1/m] where h is NULL */
    double N;            /* normal load [N], > 0 */
    double G, nu;        /* combined shear modulus [Pa], Poisson ratio in [0, 0.5] */
    double mu;           /* Coulomb friction coefficient, > 0 */
    double cx, cy, cphi; /* creepages [-], [-], [1/m] */
    double spin_shift;   /* the spin's rigid slip taken at x + spin_shift dx: CONTACT
                            uses 1/6 (closer on coarse grids); 0 keeps the discrete
                            reciprocity C23 = C32; in [-1, 1] */
    double tol;          /* relative tolerance, in [1e-14, 0.1] */
    int maxit;           /* cap on FFT products of each problem, >= 1 */
    const rr_interrupt *interrupt;  /* NULL, or the caller's hook, polled before every
                            FFT product and kernel transform (rr_common.h) */
} rr_exact_problem;

typedef struct {
    double fx, fy, mz;   /* forces on body 1 [N], spin moment about the reference point [N m] */
    double fn;           /* normal force found (N to the tolerance) [N] */
    double delta;        /* approach: the constant subtracted from h [m] */
    double area;         /* contact area: elements in contact times dx dy [m^2] */
    double pmax;         /* peak pressure [Pa] */
    int ncontact, nslip; /* elements in contact, of them slipping */
    int normal_products, tang_products;  /* FFT products used */
    int newton_steps;
    double normal_residual, tang_residual;  /* final relative residuals (the normal
                            one the last step over the pressure, 1 before any step) */
} rr_exact_result;

/* Fields of a solution, each NULL (not wanted) or mx * my values. */
typedef struct {
    double *pn;          /* pressure [Pa] */
    double *px, *py;     /* tangential traction on body 1 [Pa] */
    double *sx, *sy;     /* slip velocity over the rolling speed [-] (0 in adhesion) */
    signed char *state;  /* -1 outside the contact, 0 adhesion, 1 slip */
} rr_exact_field;

/* A warm start for rr_exact_solve_from: the solution of a nearby problem
 * (another load, creepages or gap; e.g. the field rr_exact_solve gave) on
 * a grid of the same size, which starts the iterations within a few
 * products of the answer where they would start from Hertz and FASTSIM.
 * The arrays are read before anything is written to the field, so they
 * may be the field's own (not the workspace). */
typedef struct {
    int mx, my;          /* the start's grid size: must be the problem's */
    const double *pn;    /* pressure [Pa], mx * my values, finite and >= 0, some > 0:
                            its positive elements are the first contact set, its
                            shape the first pressure (scaled to the load N) */
    const double *px, *py;  /* tangential traction on body 1 [Pa], mx * my finite values
                            each (clipped to the new bound mu pn), or both NULL: the
                            solver's own start (FASTSIM's) */
} rr_exact_start;

/* The options of the registry's method "exact" (rr_exact_method.c), by index. */
enum {
    RR_EXACT_NX = 0,          /* elements across 2a */
    RR_EXACT_NY = 1,          /* elements across 2b */
    RR_EXACT_TOL = 2,
    RR_EXACT_MAXIT = 3,
    RR_EXACT_SPIN_SHIFT = 4
};

/* Doubles of workspace for grids up to mx x my; 0 for sizes outside
 * [1, RR_EXACT_MAX_GRID]. */
size_t rr_exact_workspace_len(int mx, int my);

/* What a workspace keeps for the next case (the spectra of its last grid
 * and box, its last normal solution) forgotten: the next solve on work
 * builds them anew, as on a fresh workspace, whatever the memory holds.
 * For a caller that carves a workspace of its own differently from call
 * to call (rr_wheel_exact), where one carving's scratch may fall on
 * another's kept numbers and not on their keys.  Nothing for work NULL or
 * shorter than the header. */
void rr_exact_workspace_forget(double *work, size_t work_len);

/*
 * rr_exact_solve - the normal, then the tangential problem of pb.
 *   status: RR_OK; RR_WARN_NOT_CONVERGED (a problem hit maxit: results
 *   are the last iterate, residuals say how far); errors (outputs NaN):
 *   RR_ERR_NONFINITE, RR_ERR_GRID (mx, my outside [1, RR_EXACT_MAX_GRID]),
 *   RR_ERR_GEOMETRY (dx, dy not positive or too elongated, A or B not
 *   positive, or no element where h is lowest can carry load), RR_ERR_LOAD,
 *   RR_ERR_MATERIAL, RR_ERR_FRICTION, RR_ERR_PARAM (tol, maxit,
 *   spin_shift), RR_ERR_RANGE (mu N or mu times the mean pressure not a
 *   normal double, the mean pressure or mu times it outside [1e-140,
 *   1e140] Pa, where the solvers' sums of squares fail, sizes so extreme that a result is not finite, or a
 *   load whose displacements drown in the rounding of the gap, so that the
 *   pressure would not carry it to 1e-6), RR_ERR_WORKSPACE, RR_ERR_NULL,
 *   RR_ERR_INTERRUPTED (pb->interrupt asked to stop).  field may be NULL.
 */
int rr_exact_solve(const rr_exact_problem *pb, double *work, size_t work_len,
                   rr_exact_result *res, rr_exact_field *field);

/*
 * rr_exact_solve_from - rr_exact_solve from the caller's start (NULL:
 * rr_exact_solve itself, the same doubles).  The solution is the problem's
 * to the tolerance whatever the start (the converged iterates of a cold and
 * a warm start differ by the tolerance's order, not bit for bit); the
 * workspace's cached normal solution is neither used nor replaced by a
 * warm solve, so that a cold solve after it gives a fresh solve's doubles.
 *   status: rr_exact_solve's; a bad start is refused before any work, as
 *   rr_exact_solve's errors (outputs NaN): RR_ERR_GRID (start->mx, my not
 *   the problem's), RR_ERR_NULL (start->pn NULL, or one of px, py),
 *   RR_ERR_NONFINITE (a value NaN or infinite), RR_ERR_PARAM (a pressure
 *   negative, or none positive).
 */
int rr_exact_solve_from(const rr_exact_problem *pb, const rr_exact_start *start, double *work,
                        size_t work_len, rr_exact_result *res, rr_exact_field *field);

/*
 * rr_exact_at_edge - 1 where a solution's contact (state >= 0, the field's
 * element states, my rows of mx) reaches the border of its grid, so that
 * the grid cut the contact area off; else 0 (also for state NULL or an
 * empty grid).
 */
int rr_exact_at_edge(const signed char *state, int mx, int my);

/*
 * rr_exact_hertz_grid - the grid of a Hertzian ellipse with semi-axes a
 * (along x) and b: nx x ny elements across 2a x 2b, RR_EXACT_MARGIN more
 * on each side, centred on the ellipse (whose edges on the axes are
 * element edges).  Status: RR_OK, RR_ERR_NONFINITE, RR_ERR_GEOMETRY,
 * RR_ERR_GRID, RR_ERR_NULL.
 */
int rr_exact_hertz_grid(double a, double b, int nx, int ny, rr_grid *g);

/*
 * rr_exact_problem_from - *pb for contact problem p with the settings of o,
 * options of the method "exact": an ellipse problem on the ellipse's grid
 * (rr_exact_hertz_grid of o's nx, ny) with Hertz's gap (the curvatures
 * from rr_hertz_curvatures, h NULL); a grid problem on its grid with its h
 * (nx, ny unused).  Coulomb friction only: a falling law is
 * RR_ERR_FRICTION; no interrupt hook (pb->interrupt NULL).  Status as
 * rr_contact_problem_check, RR_ERR_FRICTION, rr_exact_hertz_grid,
 * rr_hertz_curvatures; RR_ERR_NULL.
 */
int rr_exact_problem_from(const rr_contact_problem *p, const rr_creep_opts *o,
                          rr_exact_problem *pb);

#endif
