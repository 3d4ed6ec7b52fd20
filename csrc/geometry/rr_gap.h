/*
 * rr_gap.h - the undeformed distance h(x, y) of one wheel on its roller on a
 * grid, for Kalker's exact theory (rr_exact.h): the patch of a contact that
 * need not be an ellipse (near the flange root, two regions close together,
 * a measured profile's uneven curvature), built from the profiles' splines.
 * rollerrig.undeformed_distance is this function; its docstring
 * (rollerrig/geometry/patch.py) is the long form of what follows.
 *
 * Planar contact, as CONTACT's (its D = 2): one tangent plane through a
 * reference point P on the roller's surface with contact angle delta; x
 * along t1 = +X (rolling), y along t2 = n x t1 (lateral in the plane, toward
 * +Y), n = (0, -sigma sin delta, cos delta) into the wheel (sigma = +1
 * left, -1 right).  Both bodies are bodies of revolution (the roller about
 * the rig's roller axis, the wheel about its axle after the roll): at
 * longitudinal position x each cross-section is its profile with every
 * point moved toward the body's axis by R - sqrt(R^2 - x^2) (R that point's
 * radius; the exact circle).  h(x, y) is the distance along n from the
 * roller's cross-section to the wheel's at lateral y of the plane, shifted
 * so that its least value on the grid is 0.  The profiles are sampled
 * RR_GAP_SAMPLE apart (finer where the elements are under ten samples:
 * a tenth of the element, at least RR_GAP_SAMPLE_MIN) over RR_GAP_WINDOW
 * either side of the reference and interpolated linearly in the plane (the
 * cross-section is the run of samples around the reference along which it
 * is a function of y).
 *
 * The reference: CONTACT's weighted one (the centre of the vertical
 * interpenetration at the approach, each lateral strip weighted by the
 * integral over x of its squared interpenetration, pen^2.5 / sqrt(a), and
 * the roller's inclination averaged with the same weights, delta iterated),
 * the rigid contact point's, or one given.
 *
 * The grid: uniform, centres at whole multiples of (dx, dy) from P, about n
 * elements across the longer side of the region where h <= cover x
 * approach (square elements unless dx, dy are given), one exterior element
 * beyond it on every side (grown until the region leaves the border free).
 * Lateral intervals of that region farther than `combine` from the deepest
 * one are a separate patch (CONTACT's D_COMB), listed in `excluded`, not on
 * the grid.
 *
 * Zero yaw and longitudinal shift only.  No allocation: the caller's
 * workspace (rr_gap_workspace_len) and h buffer; every input checked, and
 * every size bounded before a buffer is indexed.
 */
#ifndef RR_GAP_H
#define RR_GAP_H

#include <stddef.h>
#include "geometry/rr_geometry.h"
#include "contact/rr_exact.h"

#define RR_GAP_SAMPLE 2e-5       /* profile samples' spacing [m], at most */
#define RR_GAP_SAMPLE_MIN 1e-7   /* and at least */
#define RR_GAP_SAMPLE_MAX 1e-3   /* rr_gap_opts.sample at most */
#define RR_GAP_WINDOW 0.04       /* the samples' half-window around the reference [m] */
#define RR_GAP_MAX_RUNS 64       /* separate intervals of the region, at most */
#define RR_GAP_MAX_N 1000        /* elements across the region's longer side, at most */
#define RR_GAP_MAX_INDEX 1e8     /* the grid's elements from P along y, at most */

/* The reference of the plane (rr_gap_opts.reference). */
enum rr_gap_reference {
    RR_GAP_WEIGHTED = 0,   /* CONTACT's weighted reference */
    RR_GAP_POINT = 1,      /* the rigid contact point and its angle (rr_contact_search's) */
    RR_GAP_GIVEN = 2       /* s_roller and delta of rr_gap_opts */
};

typedef struct {
    int reference;       /* rr_gap_reference */
    double s_roller;     /* RR_GAP_GIVEN: P's roller profile coordinate [m] */
    double delta;        /* RR_GAP_GIVEN: the plane's angle [rad], |delta| < pi/2 */
    double approach;     /* the expected approach [m], > 0 */
    double cover;        /* the grid covers where h <= cover x approach; >= 1 */
    int n;               /* elements across the region's longer side, 4..RR_GAP_MAX_N */
    double dx, dy;       /* element sizes [m]; 0: from n (square) */
    double combine;      /* intervals farther than this from the deepest are left out [m], >= 0 */
    int keep;            /* 0: the region is the deepest interval and those within combine
                            (CONTACT's); 1: the gap within rig Y [keep_lo, keep_hi] alone
                            (every interval there, cut at the band's ends; the level and
                            the reference's weights from the deepest point there; combine
                            unused): one of several separate patches, rr_nonhertz_table.h */
    double keep_lo, keep_hi;   /* keep = 1: rig Y [m], keep_lo < keep_hi */
    double sample;       /* the profiles' sample spacing [m], RR_GAP_SAMPLE_MIN..RR_GAP_SAMPLE_MAX;
                            0: RR_GAP_SAMPLE, or a tenth of the smallest element given
                            (rr_wheel_exact's coarse pass: coarser, for its approach alone) */
} rr_gap_opts;

/* Weighted reference, cover 1.5, n 40, dx = dy = 0 (from n), combine 4 mm,
 * keep 0, sample 0 (automatic); approach 0 (the caller's to set). */
void rr_gap_opts_default(rr_gap_opts *o);

/* Where the gap is: one side's wheel and roller at a pose of the wheelset,
 * and the rigid contact point there (rr_contact_search's s_roller, s_wheel
 * and delta; the reference starts from it). */
typedef struct {
    const rr_wheel_roller *pair;   /* the side's profiles and placement (pair->side) */
    double y_ws, z, roll;          /* the wheelset's lateral shift [m], axle height [m], roll [rad] */
    double s_roller, s_wheel;      /* the contact point's profile coordinates [m] */
    double delta;                  /* and its contact angle [rad] */
} rr_gap_site;

/* Why a build failed (rr_gap_patch.why); the numbers a message needs are in
 * the patch's fields named with each. */
enum rr_gap_why {
    RR_GAP_OK = 0,
    RR_GAP_OFF_PROFILE = 1,     /* the reference lies off a profile (off_body, off_s, off_lo,
                                   off_hi: the body, 0 roller 1 wheel, its coordinate and
                                   the profile's range) */
    RR_GAP_FOLD = 2,            /* a profile folds at the reference point */
    RR_GAP_APART = 3,           /* the cross-sections do not overlap laterally: no patch */
    RR_GAP_REGION_ENDS = 4,     /* the region reaches the end of the profiles in the plane
                                   (plane_lo, plane_hi) */
    RR_GAP_REGION_LONG = 5,     /* the region is as long as the radii (x_t, r, R) */
    RR_GAP_REGION_BEYOND = 6,   /* its ends along x lie beyond the profiles (x_t) */
    RR_GAP_TOO_MANY = 7,        /* more than RR_EXACT_MAX_GRID elements a side (need_mx,
                                   need_my, half_length, lo, hi, grid.dx, grid.dy) */
    RR_GAP_PATCH_REACHES = 8,   /* the grid reaches where a profile folds or ends
                                   (plane_lo, plane_hi) */
    RR_GAP_PATCH_NONFINITE = 9, /* h not finite on the grid: the same, off the plane x = 0 */
    RR_GAP_RUNS = 10,           /* more than RR_GAP_MAX_RUNS separate intervals */
    RR_GAP_WEIGHTS = 11,        /* the reference's weights vanish (an approach so small that
                                   pen^2.5 underflows) or are not finite */
    RR_GAP_SCAN = 12,           /* the plane's lateral range holds more samples than the
                                   workspace (cross-sections far longer than the window) */
    RR_GAP_H_BUFFER = 13,       /* h_len < need_mx need_my: the grid is in grid */
    RR_GAP_FAR = 14,            /* the grid lies more than RR_GAP_MAX_INDEX elements from P
                                   (elements far smaller than the region's distance from
                                   it: lo, hi, grid.dy) */
    RR_GAP_KEEP = 15            /* keep = 1: no sample of the gap within [keep_lo, keep_hi] */
};

typedef struct {
    rr_grid grid;              /* h's grid: element (i, j) at (x0 + i dx, y0 + j dy) from P */
    double point[3];           /* P in the rig frame (on the roller) [m] */
    double wheel_point[3];     /* P - pen n: the wheel's material point (CONTACT's Q) */
    double t1[3], t2[3], n[3]; /* the plane's frame (rig frame) */
    double delta;              /* the plane's angle [rad] */
    double s_roller, s_wheel;  /* profile coordinates of P and of where its normal meets
                                  the wheel [m] */
    double r, R;               /* wheel and roller radius there [m] */
    double pen;                /* the pose's interpenetration along n: max(0, -least h
                                  before the shift) [m] */
    double level;              /* cover x approach [m] */
    double lo, hi;             /* the region's lateral extent in the plane (kept intervals) */
    double plane_lo, plane_hi; /* where both cross-sections are defined at x = 0 */
    double x_t;                /* the region's half-length estimate from the radii [m] */
    double half_length;        /* the region's half-length along x [m] */
    double need_mx, need_my;   /* elements the grid needs (RR_GAP_TOO_MANY, RR_GAP_H_BUFFER) */
    int nregions, nexcluded;   /* intervals on the grid, and left out */
    double regions[RR_GAP_MAX_RUNS][2];   /* (y_lo, y_hi) in the plane [m], increasing */
    double excluded[RR_GAP_MAX_RUNS][2];
    double step;               /* the profile samples' spacing used [m] */
    int why;                   /* rr_gap_why of a failed build */
    int off_body;              /* RR_GAP_OFF_PROFILE: 0 roller, 1 wheel */
    double off_s, off_lo, off_hi;
} rr_gap_patch;

/* Doubles of workspace rr_gap_build needs for options o (the profile
 * samples, their sections, the plane's lateral scan); 0 if o is NULL or its
 * element sizes are not finite and >= 0. */
size_t rr_gap_workspace_len(const rr_gap_opts *o);

/*
 * rr_gap_build - the undeformed distance of one wheel on its roller.
 *   given:   site: the pair, the pose, the rigid contact point; o the
 *            options; work of work_len >= rr_gap_workspace_len(o) doubles;
 *            h of h_len doubles
 *   returns: h[j mx + i] at (x0 + i dx, y0 + j dy) (least value 0) and
 *            *out (grid, frame, regions; out->why on failure)
 *   status:  0 OK (out->nexcluded > 0: intervals left out);
 *            RR_ERR_NULL (site, its pair, o or out NULL), RR_ERR_WORKSPACE
 *            (work too short; h too short for the grid: why RR_GAP_H_BUFFER
 *            with the grid in out->grid), RR_ERR_NONFINITE, RR_ERR_PARAM (an
 *            option out of range; the pair's radii or side), errors of
 *            rr_spline_check, RR_ERR_GEOMETRY (why OFF_PROFILE, FOLD, APART,
 *            PATCH_REACHES, PATCH_NONFINITE, KEEP), RR_ERR_RANGE (why
 *            REGION_ENDS, REGION_LONG, REGION_BEYOND, RUNS, WEIGHTS, SCAN, FAR:
 *            a load or approach beyond one planar patch on these
 *            profiles), RR_ERR_GRID (why TOO_MANY: elements too small for
 *            the region, refused before h is touched).  On error the
 *            frame's fields reached are kept for the message, h is NaN
 *            where reached.
 */
int rr_gap_build(const rr_gap_site *site, const rr_gap_opts *o, double *work, size_t work_len,
                 double *h, size_t h_len, rr_gap_patch *out);

#endif
