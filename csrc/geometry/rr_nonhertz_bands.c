/*
 * rr_nonhertz_bands.c - the patches of a non-Hertzian table row
 * (rr_nonhertz_table.h): the gap's separate regions told apart at the
 * nominal load, a band of rig Y per patch, its gap g at the zero-gap pose,
 * and the grids clipped to their band.
 */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "util/rr_spline.h"
#include "geometry/rr_gap.h"
#include "geometry/rr_wheel_exact.h"
#include "geometry/rr_nonhertz_table.h"
#include "geometry/rr_nonhertz_row.h"

/* Rows of a grid outside the patch's band (rr_gap's exterior element
 * beyond the band's edge can reach into the next patch's interpenetration)
 * lifted out of reach, then h shifted back to least 0 and pen with it: the
 * patch holds its band's gap alone. */
void rr_nh_clip_band(const rr_nh_band *bd, rr_gap_patch *g, double *h)
{
    const size_t mx = (size_t)g->grid.mx, my = (size_t)g->grid.my;
    double top = -INFINITY, m = INFINITY;
    size_t i, j;
    for (i = 0; i < mx * my; i++)
        top = h[i] > top ? h[i] : top;
    top += 10.0 * g->level;
    for (j = 0; j < my; j++) {
        const double Y = g->point[1] + (g->grid.y0 + (double)j * g->grid.dy) * g->t2[1];
        for (i = 0; i < mx; i++) {
            if (!(Y >= bd->lo && Y <= bd->hi))
                h[j * mx + i] = top;
            m = h[j * mx + i] < m ? h[j * mx + i] : m;
        }
    }
    if (!(m > 0.0))
        return;
    for (i = 0; i < mx * my; i++)
        h[i] -= m;
    g->pen = g->pen > m ? g->pen - m : 0.0;
    for (i = 0; i < 3; i++)
        g->wheel_point[i] = g->point[i] - g->pen * g->n[i];
}

/* ---- the row's patches ------------------------------------------------ */

#define MAX_IV (2 * RR_GAP_MAX_RUNS)

/* The gap's interpenetration at lowering L from the zero-gap pose (cover
 * 1: where h is below the approach), the plane at its own approach: in
 * band bd's keep (bd NULL: CONTACT's grouping round the rigid contact
 * point's region, every interval listed) into *q, h in the node buffer. */
static int probe(rr_nh_call *c, double L, const rr_nh_band *bd, rr_gap_patch *q)
{
    const rr_nh_row_problem *pb = c->pb;
    rr_gap_site site;
    rr_gap_opts o;
    double a;
    int it, st;
    site.pair = pb->pair;
    site.y_ws = pb->y_ws;
    site.z = pb->pose0.z - L;
    site.roll = pb->pose0.roll;
    site.s_roller = bd ? bd->s_roller : pb->point.s_roller;
    site.s_wheel = bd ? bd->s_wheel : pb->point.s_wheel;
    site.delta = bd ? bd->delta : pb->point.delta;
    rr_gap_opts_default(&o);
    o.n = pb->n;
    o.cover = 1.0;
    o.combine = pb->combine;
    if (bd) {
        o.keep = 1;
        o.keep_lo = bd->lo;
        o.keep_hi = bd->hi;
    }
    a = (L - (bd ? bd->g : 0.0)) * cos(site.delta);
    for (it = 0; it < 4; it++) {
        o.approach = a > 1e-3 * L ? a : 1e-3 * L;
        if ((st = rr_gap_build(&site, &o, c->b.gap, c->b.gap_len, c->b.h, c->b.cells, q)) < 0)
            return rr_nh_grid_failed(c, st, q, 1);
        if (bd)
            rr_nh_clip_band(bd, q, c->b.h);
        if (!(q->pen > 0.0) || fabs(q->pen / o.approach - 1.0) < 1e-3)
            break;
        a = q->pen;
    }
    return RR_OK;
}

/* The intervals of a probe in rig Y (the plane's y from P along t2),
 * increasing; their count. */
static int intervals(const rr_gap_patch *q, double (*iv)[2])
{
    int n = 0, k, m;
    for (k = 0; k < q->nregions + q->nexcluded; k++) {
        const double *r = k < q->nregions ? q->regions[k] : q->excluded[k - q->nregions];
        const double lo = q->point[1] + r[0] * q->t2[1], hi = q->point[1] + r[1] * q->t2[1];
        for (m = n; m > 0 && iv[m - 1][0] > lo; m--) {
            iv[m][0] = iv[m - 1][0];
            iv[m][1] = iv[m - 1][1];
        }
        iv[m][0] = lo;
        iv[m][1] = hi;
        n++;
    }
    return n;
}

/*
 * The row's patches: the gap's separate regions (intervals farther apart
 * than combine, CONTACT's D_COMB) at the lowering of the regions' load
 * Fz_regions (the table's nominal one), at most RR_NH_MAX_PATCHES of them
 * (the rigid contact point's and the widest other; a third lies in a
 * neighbour's band: info->merged); the bands part the lateral axis half-way
 * between them and reach combine / 2 beyond the interpenetration at the
 * largest lowering (intervals touching there farther out: info->excluded).
 * Each band's gap g: 0 for the rigid contact point's; the others' from their
 * interpenetration pen at two lowerings L, g = L - pen / cos(delta).
 */
int rr_nh_find_bands(rr_nh_call *c, double e_max, rr_nh_band *bd, int *nb)
{
    const rr_nh_row_problem *pb = c->pb;
    const rr_wheel_roller *pr = pb->pair;
    const double Ypt = pr->side * (pr->roller_y + pb->point.s_roller), cb = pb->combine;
    double iv[MAX_IV][2], grp[MAX_IV][2], lo, hi, best = -1.0, dist = INFINITY;
    rr_gap_patch q;
    int n, ng = 0, ng0, k, j, st, home = 0, other = -1;
    double Lg = e_max;
    if (pb->Fz_regions > 0.0 && pb->Fz_regions < pb->Fz_max)
        Lg = e_max * pow(pb->Fz_regions / pb->Fz_max, 2.0 / 3.0);
    if ((st = probe(c, Lg, NULL, &q)) < 0)
        return st;
    n = intervals(&q, iv);
    for (k = 0; k < n; k++) {
        if (ng > 0 && iv[k][0] - grp[ng - 1][1] <= cb) {
            grp[ng - 1][1] = fmax(grp[ng - 1][1], iv[k][1]);
            continue;
        }
        grp[ng][0] = iv[k][0];
        grp[ng++][1] = iv[k][1];
    }
    if (ng == 0) {
        c->info->why = RR_NH_ROW_GRID;
        return RR_ERR_GEOMETRY;
    }
    for (k = 0; k < ng; k++) {
        const double d = Ypt < grp[k][0] ? grp[k][0] - Ypt : Ypt > grp[k][1] ? Ypt - grp[k][1] : 0;
        if (d < dist)
            dist = d, home = k;
    }
    ng0 = ng;
    /* what touches at the largest lowering: within combine of a group its
     * extent; farther out a region of its own (touching above the nominal
     * load only) */
    lo = grp[home][0];
    hi = grp[home][1];
    for (k = 0; k < ng; k++)
        lo = fmin(lo, grp[k][0]), hi = fmax(hi, grp[k][1]);
    if ((st = probe(c, e_max, NULL, &q)) < 0)
        return st;
    n = intervals(&q, iv);
    for (k = 0; k < n; k++) {
        int m, near = 0;
        for (m = 0; m < ng0 && !near; m++)
            near = iv[k][0] - grp[m][1] <= cb && grp[m][0] - iv[k][1] <= cb;
        if (near) {
            lo = fmin(lo, iv[k][0]);
            hi = fmax(hi, iv[k][1]);
        } else if (ng > ng0 && iv[k][0] - grp[ng - 1][1] <= cb) {
            grp[ng - 1][1] = fmax(grp[ng - 1][1], iv[k][1]);
        } else if (ng < MAX_IV) {
            grp[ng][0] = iv[k][0];
            grp[ng++][1] = iv[k][1];
        }
    }
    /* the other patch: the widest region of the nominal load's, else of
     * the largest load's */
    for (k = 0; k < ng0; k++)
        if (k != home && grp[k][1] - grp[k][0] > best)
            best = grp[k][1] - grp[k][0], other = k;
    for (k = ng0; other < 0 && k < ng; k++)
        if (grp[k][1] - grp[k][0] > best)
            best = grp[k][1] - grp[k][0], other = k;
    if (other >= 0) {
        lo = fmin(lo, grp[other][0]);
        hi = fmax(hi, grp[other][1]);
    }
    for (k = 0; k < ng; k++)
        if (k != home && k != other) {
            if (grp[k][1] < lo - 0.5 * cb || grp[k][0] > hi + 0.5 * cb)
                c->info->excluded++;         /* beyond the bands */
            else
                c->info->merged++;           /* in a neighbour's rr_nh_band */
        }
    /* the bands, increasing in Y */
    *nb = other >= 0 ? 2 : 1;
    if (other >= 0 && grp[other][0] < grp[home][0]) {
        k = home;
        home = other;
        other = k;
        j = 1;                          /* the rigid contact point's rr_nh_band */
    } else
        j = 0;
    bd[0].lo = lo - 0.5 * cb;
    bd[*nb - 1].hi = hi + 0.5 * cb;
    if (*nb == 2)
        bd[0].hi = bd[1].lo = 0.5 * (grp[home][1] + grp[other][0]);
    bd[j].g = 0.0;
    bd[j].s_roller = pb->point.s_roller;
    bd[j].s_wheel = pb->point.s_wheel;
    bd[j].delta = pb->point.delta;
    for (k = 0; k < *nb; k++) {
        rr_nh_band *b = &bd[k];
        if (k == j)
            continue;
        {
            /* the region's middle, its roller's slope, the wheel above it */
            const double *gk = grp[k == 0 ? home : other];
            double z, dz, L = e_max;
            int it;
            b->s_roller = pr->side * 0.5 * (gk[0] + gk[1]) - pr->roller_y;
            b->s_wheel = pb->point.s_wheel + (b->s_roller - pb->point.s_roller);
            if ((st = rr_spline_eval(&pr->roller, b->s_roller, &z, &dz, NULL)) < 0)
                return st;
            b->delta = atan(dz);
            b->g = 0.0;
            for (it = 0; it < 3; it++) {
                st = probe(c, L, b, &q);
                if (st == RR_ERR_GEOMETRY || st == RR_ERR_RANGE || (st >= 0 && !(q.pen > 0.0))) {
                    /* a region whose patch cannot be built on these profiles
                     * (off them, beyond one planar patch): left out, counted
                     * (the table's one-patch rows, warned), not the row lost */
                    c->info->why = c->info->gap_why = 0;
                    c->info->excluded++;
                    bd[0] = bd[j];
                    *nb = 1;
                    return RR_OK;
                }
                if (st < 0)
                    return st;
                b->g = fmax(0.0, L - q.pen / cos(q.delta));
                b->delta = q.delta;
                b->s_roller = q.s_roller;
                b->s_wheel = q.s_wheel;
                L = b->g + 0.5 * (e_max - b->g);
            }
        }
    }
    /* a region that touches only at the top of the loads: the neighbour's */
    for (k = 0; k < *nb; k++)
        if (bd[k].g > 0.9 * e_max) {
            const rr_nh_band keep = bd[1 - k];
            bd[0] = keep;
            bd[0].lo = lo - 0.5 * cb;
            bd[0].hi = hi + 0.5 * cb;
            *nb = 1;
            break;
        }
    return RR_OK;
}

