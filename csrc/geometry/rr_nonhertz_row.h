/*
 * rr_nonhertz_row.h - what rr_nonhertz_table.c and rr_nonhertz_bands.c
 * share: a row build's call state and its patches' bands
 * (rr_nonhertz_table.h says what a row holds; rr_nonhertz_bands.c how its
 * patches are found).  Not a header of its own (so that
 * rr_nonhertz_table.c may include it without an include circle): include
 * it after geometry/rr_nonhertz_table.h.
 */
#ifndef RR_NONHERTZ_ROW_H
#define RR_NONHERTZ_ROW_H

#include <stddef.h>

/* The buffers carved from the caller's workspace. */
typedef struct {
    double *wex, *fine_ex, *gap;        /* rr_wheel_exact's (the coarse solver's at its
                                           start), the fine grids' solver, rr_gap_build's */
    size_t wex_len, coarse_len, fine_len, gap_len;
    double *h, *pn, *hf, *hc, *hcf;     /* side^2, side^2, 4 side^2, side^2, 4 side^2 */
    signed char *state;                 /* side^2 bytes */
    size_t cells;
    int side;                           /* the coarse grids' solver's side (the fine's: 2 side) */
} rr_nh_bufs;

/* A patch of the row: the band of rig Y whose gap it holds (rr_gap's keep:
 * the bands part the lateral axis between the separate regions), its
 * vertical gap at the zero-gap pose and where its plane's search starts. */
typedef struct {
    double lo, hi, g, s_roller, s_wheel, delta;
} rr_nh_band;

/* The row's call state. */
typedef struct {
    const rr_nh_row_problem *pb;
    rr_nh_bufs b;
    rr_nh_row_info *info;
    double G;
    rr_wheel_exact_result scratch;      /* the largest load's solution */
    const rr_nh_band *bd;                     /* the patch being built */
} rr_nh_call;

/* Not API.  A gap build's failure st (its patch p, for a solver of scale x
 * side elements a side: 1 the coarse grids, 2 the fine) into the row's
 * info: why GRID, the gap's reason and, where h or the side was short, the
 * row's side it needs (rr_nonhertz_table.c).  Returns st. */
int rr_nh_grid_failed(rr_nh_call *c, int st, const rr_gap_patch *p, int scale);

/* Not API.  Rows of grid g outside band bd lifted out of reach, h and g->pen shifted
 * back to least 0 (rr_nonhertz_bands.c). */
void rr_nh_clip_band(const rr_nh_band *bd, rr_gap_patch *g, double *h);

/* Not API.  The row's patches' bands (at most RR_NH_MAX_PATCHES, increasing in Y)
 * from the largest lowering e_max: rr_nonhertz_bands.c.  Status 0 or a
 * build's (c->info says where). */
int rr_nh_find_bands(rr_nh_call *c, double e_max, rr_nh_band *bd, int *nb);

#endif
