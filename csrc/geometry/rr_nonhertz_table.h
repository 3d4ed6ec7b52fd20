/*
 * rr_nonhertz_table.h - one row of the non-Hertzian contact's table
 * (rr_nonhertz.h's layout) built by the exact theory: the wheel at lateral
 * shift y_ws lowered from its zero-gap pose by RR_NH_NODES lowerings e_k =
 * f_k e_max, f = (0.03, 0.1, 0.2, 0.33, 0.46, 0.6, 0.75, 0.88, 1), e_max
 * the lowering rr_wheel_exact finds for the vertical load Fz_max; at each
 * the patch on CONTACT's weighted plane at the pose's own interpenetration
 * and the exact normal solution whose approach is that interpenetration
 * (the load the pose carries: N(e) by definition, monotone where one plane
 * holds the patch, NONHERTZ_STUDY.md's construction); per node the
 * pressure's centroid and moments, area and peak, and the exact linear
 * creep coefficients about the centroid (three tiny creepages, Richardson
 * from elements half as large where asked); at nodes RR_NH_CORR_NODE0, 1
 * the exact forces (Richardson, n_corr elements across) less the
 * calibrated ellipse's at RR_NH_U x RR_NH_TH normalised creepages and at
 * zero, all at the row's free-rolling spin (the wheelset's motion given).
 *
 * A patch per separate region of the gap (rr_nonhertz_bands.c): the
 * regions are the gap's interpenetrating intervals at the lowering of
 * Fz_regions (the table's nominal load), grouped as CONTACT's D_COMB does
 * (intervals within `combine`, 4 mm, are one region, one plane); a region
 * that touches only above it, farther than combine from those, is one too.
 * Up to RR_NH_MAX_PATCHES of them, the rigid contact point's and the
 * widest other (a third lies in a neighbour's band: info->merged).  Each
 * patch holds a band of rig Y (the bands part the lateral axis half-way
 * between the regions and reach combine / 2 beyond what interpenetrates
 * at the largest lowering; farther out: info->excluded), its gap g at the
 * zero-gap pose (0 for the rigid contact point's; the others' from their
 * interpenetration at two lowerings), its nodes at lowerings f_k (e_max -
 * g) beyond g on its own plane (CONTACT's weighted one within its band,
 * rr_gap's keep), its coefficients and correction.  At run time the
 * patches share the wheel's lowering and the load splits by their own N(e
 * - g_j) (rr_nonhertz.h).  Within one region the grouping is the
 * nominal load's at every node: two intervals that part at small loads
 * stay one patch (one plane), and two regions that meet above it stay
 * two (each cut at the band's edge).  No allocation: the
 * caller's workspace (rr_nonhertz_row_workspace_len for grids up to side x
 * side, zero-filled before its first use).  One workspace per thread: rows
 * are independent.
 */
#ifndef RR_NONHERTZ_TABLE_H
#define RR_NONHERTZ_TABLE_H

#include <stddef.h>
#include "geometry/rr_geometry.h"
#include "geometry/rr_creepage.h"
#include "geometry/rr_nonhertz.h"

typedef struct {
    const rr_wheel_roller *pair;   /* the side's profiles and placement */
    double y_ws;                   /* the row's lateral shift [m] */
    rr_wheelset_pose pose0;        /* rr_wheelset_contact's zero-gap pose there */
    rr_contact_point point;        /* and this side's contact point */
    double Fz_max;                 /* the largest vertical load of the nodes [N], > 0 */
    double Fz_regions;             /* the load whose lowering tells the gap's separate
                                      regions apart (the table's nominal load), in
                                      [0, Fz_max]; 0: Fz_max */
    double E, nu;                  /* both bodies [Pa], [-] */
    double mu;                     /* the correction's friction (the table's mu_ref) */
    rr_motion wheelset;            /* the wheelset's motion at free rolling there (the
                                      correction's spin) */
    double roller_spin, vmin;      /* [rad/s], [m/s] > 0 */
    int n;                         /* elements across the nodes' grids' longer side (at
                                      least n / 2 across the shorter: a flange patch, a/b
                                      over 10, resolved across), 8..RR_GAP_MAX_N/2 */
    int n_corr;                    /* and across the correction's, 8..n */
    int richardson;                /* 1: coefficients and correction extrapolated from
                                      elements half as large; 0: the grids' own */
    double combine;                /* intervals farther apart are separate regions [m], >= 0 */
    double tol;                    /* the solver's tolerance and iterations */
    int maxit;
    const rr_interrupt *interrupt;
} rr_nh_row_problem;

/* n 40, n_corr 30, Richardson, E 2.1e11, nu 0.28, mu 0.52, vmin 1e-3,
 * combine 4 mm, tol 1e-6, maxit 5000; the rest zero (the caller's). */
void rr_nonhertz_row_default(rr_nh_row_problem *pb);

/* Where a build failed (rr_nh_row_info.why). */
enum rr_nh_row_why {
    RR_NH_ROW_OK = 0,
    RR_NH_ROW_NODE = 1,      /* the largest load's rr_wheel_exact (wheel_why says why), or
                                a node's contact keeps reaching its grid's edge */
    RR_NH_ROW_GRID = 2,      /* a node's, a fine, a correction or a region's rr_gap_build
                                (gap_why), or a region that does not touch */
    RR_NH_ROW_SOLVE = 3,     /* a solve of the coefficients or the correction */
    RR_NH_ROW_COEFF = 4      /* a linear coefficient not positive: the patch too coarse */
};

typedef struct {
    int why;                 /* rr_nh_row_why */
    int patch, node;         /* the patch and node at fault (-1: none) */
    int wheel_why, gap_why;  /* rr_wheel_exact_why, rr_gap_why */
    size_t need;             /* RR_ERR_WORKSPACE: the grid side the row needs */
    int solves;              /* exact solves spent */
    int patches;             /* patches of the row */
    int excluded;            /* intervals interpenetrating at the largest lowering beyond
                                combine of every band, or a region whose own patch
                                could not be built (off the profiles, beyond one
                                planar patch): not tabulated */
    int merged;              /* separate regions beyond RR_NH_MAX_PATCHES, held in a
                                neighbour's band (its plane) */
} rr_nh_row_info;

/* Doubles of workspace for grids up to side x side (the fine ones twice
 * that); 0 if pb is NULL or side outside [8, RR_EXACT_MAX_GRID / 2]. */
size_t rr_nonhertz_row_workspace_len(const rr_nh_row_problem *pb, int side);

/*
 * rr_nonhertz_row - one row of the table (RR_NH_ROW_LEN doubles; its
 * patches as above, increasing in rig Y; an unused patch's place zero).
 *   status: 0 OK, RR_WARN_NOT_CONVERGED (a solve hit maxit); errors (row
 *   NaN; info says where): RR_ERR_NULL, RR_ERR_NONFINITE, RR_ERR_LOAD
 *   (Fz_max, Fz_regions), RR_ERR_PARAM (n, n_corr, richardson, combine), RR_ERR_WORKSPACE
 *   (a grid beyond side: info->need the side it needs), the statuses of
 *   rr_wheel_exact, rr_gap_build, rr_exact_solve, rr_kalker and
 *   rr_exact_table_forces, RR_ERR_GEOMETRY (why COEFF).
 */
int rr_nonhertz_row(const rr_nh_row_problem *pb, double *work, size_t work_len, int side,
                    double *row, rr_nh_row_info *info);

#endif
