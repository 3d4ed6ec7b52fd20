/*
 * rr_exact_solver.h - what the exact solver's files share (the driver
 * rr_exact.c, the operators rr_exact_ops.c, the normal problem
 * rr_exact_normal.c, the tangential problem rr_exact_tangential.c): the
 * workspace's carving, the solver's state, the 3 x 3 stencils and the
 * functions each half offers the others.  Not a header of its own (so that
 * rr_exact.c may include it without an include circle): include it after
 * util/rr_fft.h and contact/rr_exact.h.
 */
#ifndef RR_EXACT_SOLVER_H
#define RR_EXACT_SOLVER_H

#include <stddef.h>

/* Krylov vectors kept by GMRES before it restarts. */
#define GMRES_M 30
/* The workspace's header: a tag, then the key of the cached spectra
 * (mx, my, dy/dx, nu), 1 where their tangential phase is built too, and
 * (the grid's header alone) where the last call had its box's layout. */
#define HDR_LEN 8
#define BOX_AT 6
/* the stencils of the inverse operators (normal_stencil, tangential_stencil),
 * kept with the spectra */
#define STN_LEN 24
#define HDR_TAG 20261204.5
/* The key of the cached normal solution: a tag, the problem's numbers, then
 * its status, approach and residual. */
#define NKEY_LEN 20
#define NKEY_TAG 20261202.25

enum { OUTSIDE = -1, ADHESION = 0, SLIP = 1 };

/* Pointers into the caller's workspace (rr_exact_workspace_len). */
typedef struct {
    int mx, my, n;
    int ai0, ai1, aj0, aj1;                /* the adhering elements' bounding box */
    double *hdr, *stn;
    double *nkey, *pn_cache, *h_cache;     /* the last normal problem and its solution */
    double *conv;
    size_t conv_len;
    double *snn, *sxx, *syy, *sxy;        /* kernel spectra */
    double *ta, *tb, *tr, *kern, *kern2;  /* coefficient tables (while building) */
    double *spinv, *sp2, *sp3;            /* inverse spectra (while building) */
    double *h, *pn, *gap, *r, *rold, *d, *v, *z;      /* normal problem */
    double *p, *s, *w, *f, *nz, *fac, *dlt, *mdl, *t1, *t2;   /* tangential, 2n each */
    double *halo;                                      /* two planes with a border */
    double *jf, *pcf, *madh, *jn;                      /* Jacobian's coefficients (jn: 2n) */
    double *V, *MV, *H, *gv, *cs, *sn, *y;            /* GMRES */
    signed char *state;
} layout;

/* The solver of one case: the problem, the workspace, the FFT engine, the
 * products so far. */
typedef struct {
    const rr_exact_problem *pb;
    const rr_exact_start *start;   /* NULL: the solver's own starts */
    layout *L;
    rr_conv2d *cv;
    int products;
} solver;

/* The 3 x 3 stencil (s0, s1, s2, s3) (even: centre, (1, 0), (0, 1),
 * (1, 1)) applied to the field in the halo plane h (the grid with a border
 * of zeros, rows of w = mx + 2) at its element q. */
#define STENCIL3(s0, s1, s2, s3, h, q, w)                                              \
    ((s0) * (h)[q] + (s1) * ((h)[(q) - 1] + (h)[(q) + 1])                             \
     + (s2) * ((h)[(q) - (w)] + (h)[(q) + (w)])                                        \
     + (s3) * ((h)[(q) - (w) - 1] + (h)[(q) - (w) + 1] + (h)[(q) + (w) - 1] + (h)[(q) + (w) + 1]))
/* the odd-odd one at (1, 1): S(o) = s sign(ox) sign(oy), out(i) = sum S(o) in(i - o) */
#define STENCIL3_XY(s, h, q, w)                                                        \
    ((s) * ((h)[(q) + (w) + 1] - (h)[(q) + (w) - 1] - (h)[(q) - (w) + 1] + (h)[(q) - (w) - 1]))

/* Not API: the doubles of one kernel spectrum of an mx x my grid; the
 * workspace carved (base NULL: its length only); the kernel spectra and
 * inverse stencils of a grid's aspect dy/dx and nu, the normal ones and,
 * where tangential is set, the tangential ones too (polling the interrupt
 * hook); the steady operator's diagonal; the normal problem of a case, the
 * normal displacements u of a pressure p on its grid (one product,
 * counted), and its tangential problem (rr_exact_normal.c,
 * rr_exact_tangential.c). */
size_t rr_exact_spectrum_len(int mx, int my);
size_t rr_exact_carve(layout *L, int mx, int my, double *base);
int rr_exact_build_spectra(layout *L, rr_conv2d *cv, double aspect, double nu, int tangential,
                           const rr_interrupt *stop);
double rr_exact_steady_diagonal(double aspect, double nu);
int rr_exact_solve_normal(solver *S, rr_exact_result *res);
int rr_exact_normal_displacement(solver *S, const double *p, double *u);
int rr_exact_solve_tangential(solver *S, rr_exact_result *res);

#endif
