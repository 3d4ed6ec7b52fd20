/*
 * rr_exact_ops.c - the exact solver's operators (rr_exact.h): the
 * workspace's carving, and the influence coefficients' kernel spectra with
 * the inverse stencils that precondition both problems, built once per grid
 * shape and kept in the workspace.  The problems themselves are
 * rr_exact_normal.c and rr_exact_tangential.c, the driver rr_exact.c.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "util/rr_common.h"
#include "util/rr_fft.h"
#include "contact/rr_influence.h"
#include "contact/rr_exact.h"
#include "contact/rr_exact_solver.h"

/* Doubles of one kernel spectrum of rr_conv2d for an mx x my grid: the
 * torus L1 x (L2/2 + 1) of complex values (rr_fft.h); checked against
 * rr_conv2d_spectrum_len once the engine exists. */
size_t rr_exact_spectrum_len(int mx, int my)
{
    const int L1 = rr_conv2d_torus_len(2 * mx - 1), L2 = rr_conv2d_torus_len(2 * my - 1);
    return 2 * (size_t)L1 * (size_t)(L2 / 2 + 1);
}

/* The workspace's carving; lengths in doubles.  With base NULL only the
 * total is computed. */
size_t rr_exact_carve(layout *L, int mx, int my, double *base)
{
    const size_t n = (size_t)mx * (size_t)my, n2 = 2 * n;
    const size_t conv_len = rr_conv2d_workspace_len(mx, my);
    size_t spec_len, tab_len, torus_len, kern_len, off = 0;

#define TAKE(ptr, len) do { (ptr) = base ? base + off : NULL; off += (len); } while (0)
    memset(L, 0, sizeof *L);
    if (conv_len == 0)
        return 0;
    spec_len = rr_exact_spectrum_len(mx, my);
    {
        /* the boxes' table reaches the torus's far offsets L / 2 (build_spectra) */
        const size_t L1 = (size_t)rr_conv2d_torus_len(2 * mx - 1);
        const size_t L2 = (size_t)rr_conv2d_torus_len(2 * my - 1);
        const size_t nkx = (size_t)mx + 1 > L1 / 2 + 1 ? (size_t)mx + 1 : L1 / 2 + 1;
        const size_t nky = (size_t)my > L2 / 2 + 1 ? (size_t)my : L2 / 2 + 1;
        tab_len = nkx * nky;
        torus_len = L1 * L2;
        kern_len = (size_t)(2 * mx - 1) * (size_t)(2 * my - 1);
    }
    L->mx = mx;
    L->my = my;
    L->n = (int)n;
    TAKE(L->hdr, HDR_LEN);
    TAKE(L->stn, STN_LEN);
    TAKE(L->nkey, NKEY_LEN);
    TAKE(L->pn_cache, n);
    TAKE(L->h_cache, n);
    TAKE(L->conv, conv_len);
    L->conv_len = conv_len;
    TAKE(L->snn, spec_len);
    TAKE(L->sxx, spec_len);
    TAKE(L->syy, spec_len);
    TAKE(L->sxy, spec_len);
    TAKE(L->ta, tab_len);
    TAKE(L->tb, tab_len);
    TAKE(L->tr, tab_len);
    TAKE(L->kern, kern_len > torus_len ? kern_len : torus_len);
    TAKE(L->kern2, kern_len > spec_len ? kern_len : spec_len);
    TAKE(L->spinv, spec_len);
    TAKE(L->sp2, spec_len);
    TAKE(L->sp3, spec_len);
    TAKE(L->h, n);
    TAKE(L->pn, n);
    TAKE(L->gap, n);
    TAKE(L->r, n);
    TAKE(L->rold, n);
    TAKE(L->d, n);
    TAKE(L->v, n);
    TAKE(L->z, n);
    TAKE(L->p, n2);
    TAKE(L->s, n2);
    TAKE(L->w, n2);
    TAKE(L->f, n2);
    TAKE(L->nz, n2);
    TAKE(L->fac, n2);
    TAKE(L->dlt, n2);
    TAKE(L->mdl, n2);
    TAKE(L->t1, n2);
    TAKE(L->t2, n2);
    TAKE(L->halo, 2 * (size_t)(mx + 2) * (size_t)(my + 2));
    TAKE(L->jf, n);
    TAKE(L->pcf, n);
    TAKE(L->madh, n);
    TAKE(L->jn, n2);
    TAKE(L->V, (GMRES_M + 1) * n2);
    TAKE(L->MV, GMRES_M * n2);
    TAKE(L->H, (GMRES_M + 1) * GMRES_M);
    TAKE(L->gv, GMRES_M + 1);
    TAKE(L->cs, GMRES_M);
    TAKE(L->sn, GMRES_M);
    TAKE(L->y, GMRES_M);
    {
        double *st;
        TAKE(st, n / sizeof(double) + 1);
        L->state = (signed char *)st;
    }
#undef TAKE
    return off;
}

/* ---- kernels -------------------------------------------------------------- */

/* 1 if v[0..n-1] are all finite: rr_all_finite's test (0 x is 0 exactly
 * for finite x) with four sums, which do not wait for each other */
static int finite4(const double *v, size_t n)
{
    double a0 = 0.0, a1 = 0.0, a2 = 0.0, a3 = 0.0;
    size_t i;
    for (i = 0; i + 4 <= n; i += 4) {
        a0 += 0.0 * v[i];
        a1 += 0.0 * v[i + 1];
        a2 += 0.0 * v[i + 2];
        a3 += 0.0 * v[i + 3];
    }
    for (; i < n; i++)
        a0 += 0.0 * v[i];
    return (a0 + a1) + (a2 + a3) == 0.0;
}

/* The values at offsets (0, 0), (1, 0), (0, 1), (1, 1) of the real kernel
 * whose symbol (not scaled: the transform of the kernel) is (re, im) over
 * the half torus (index kx nh + ky, ky < nh, as rr_conv2d's spectra):
 * K(o) = 1/(L1 L2) sum over the torus of S e^(i w.o), the lines ky and
 * L2 - ky summed as one (twice the real part).  cx, sx: cos and sin of
 * 2 pi kx / L1; wy, cy, sy: the weight (1 or 2) of line ky and it times
 * cos and sin of 2 pi ky / L2. */
static void kernel_near_origin(int L1, int nh, double scale, const double *re, const double *im,
                               const double *cx, const double *sx, const double *wy,
                               const double *cy, const double *sy, double out[4])
{
    double k00 = 0.0, k10 = 0.0, k01 = 0.0, k11 = 0.0;
    int a, b;
    for (a = 0; a < L1; a++) {
        const double *r = re + (size_t)a * nh, *i = im + (size_t)a * nh;
        double p0r = 0.0, p0i = 0.0, p1r = 0.0, p1i = 0.0;
        for (b = 0; b < nh; b++) {
            p0r += wy[b] * r[b];
            p0i += wy[b] * i[b];
            p1r += r[b] * cy[b] - i[b] * sy[b];
            p1i += r[b] * sy[b] + i[b] * cy[b];
        }
        k00 += p0r;
        k01 += p1r;
        k10 += p0r * cx[a] - p0i * sx[a];
        k11 += p1r * cx[a] - p1i * sx[a];
    }
    out[0] = k00 * scale;
    out[1] = k10 * scale;
    out[2] = k01 * scale;
    out[3] = k11 * scale;
}

/* 1 if the symbol of the even stencil s (centre, (1, 0), (0, 1), (1, 1)),
 * s0 + 2 s1 cos wx + 2 s2 cos wy + 4 s3 cos wx cos wy, is positive: it is
 * bilinear in the cosines, so least at a corner. */
static int stencil_positive(const double *s)
{
    return s[0] + 2.0 * s[1] + 2.0 * s[2] + 4.0 * s[3] > 0.0
           && s[0] - 2.0 * s[1] + 2.0 * s[2] - 4.0 * s[3] > 0.0
           && s[0] + 2.0 * s[1] - 2.0 * s[2] - 4.0 * s[3] > 0.0
           && s[0] - 2.0 * s[1] - 2.0 * s[2] + 4.0 * s[3] > 0.0;
}

/* The cosines and sines the stencils' sums take (in L->kern, which the
 * tangential phase's table overwrites in between, so each stencil sets
 * them; a few hundred values against the transforms' tens of thousands):
 * cx, sx of 2 pi kx / L1 and wy, cy, sy: the weight (1 or 2) of line ky
 * and it times cos and sin of 2 pi ky / L2. */
typedef struct {
    double *cx, *sx, *wy, *cy, *sy;
} torus_trig;

static torus_trig trig_of(layout *L, const rr_conv2d *cv)
{
    const int L1 = cv->L1, L2 = cv->L2, nh = cv->nh;
    torus_trig t;
    int a;
    t.cx = L->kern;
    t.sx = t.cx + L1;
    t.wy = t.sx + L1;
    t.cy = t.wy + nh;
    t.sy = t.cy + nh;
    for (a = 0; a < L1; a++) {
        t.cx[a] = cos(2.0 * RR_PI * a / L1);
        t.sx[a] = sin(2.0 * RR_PI * a / L1);
    }
    for (a = 0; a < nh; a++) {
        t.wy[a] = a == 0 || 2 * a == L2 ? 1.0 : 2.0;
        t.cy[a] = t.wy[a] * cos(2.0 * RR_PI * a / L2);
        t.sy[a] = t.wy[a] * sin(2.0 * RR_PI * a / L2);
    }
    return t;
}

/* The 3 x 3 stencils nearest the inverses of the half-space's operators,
 * for the preconditioners: the inverse symbols on the torus, transformed
 * back at the offsets -1 .. 1.  The half-space's symbol grows as 1/|w| at
 * low frequencies, so the inverse decays fast and these few values carry
 * most of it; it must be the symbol of the kernel on the whole torus
 * (the grid's offsets alone, zero beyond, leave it negative somewhere).
 * The normal one, from the symbol (scaled as rr_conv2d's spectra) of A_nn
 * in snn: stn[0..3] Snn (centre, (1, 0), (0, 1), (1, 1)), stn[4] = 1 where
 * usable.  Not usable: grids under 3 x 3, a symbol with a zero, or a
 * stencil whose symbol is not positive (definite). */
static void normal_stencil(layout *L, const rr_conv2d *cv)
{
    const int L1 = cv->L1, L2 = cv->L2, nh = cv->nh;
    const size_t half = (size_t)L1 * nh;
    const double sc = 2.0 * L1 * L2, ks = 1.0 / ((double)L1 * L2);
    double *stn = L->stn, *nr = L->kern2, *ni = nr + half;
    torus_trig t;
    size_t i;
    int usable = 1;

    memset(stn, 0, 8 * sizeof *stn);
    if (L->mx < 3 || L->my < 3)
        return;
    t = trig_of(L, cv);
    for (i = 0; i < half; i++) {
        const double re = L->snn[i] * sc, im = L->snn[half + i] * sc, m = re * re + im * im;
        usable &= m > 0.0 && isfinite(m);
        nr[i] = re / m;
        ni[i] = -im / m;
    }
    if (usable) {
        kernel_near_origin(L1, nh, ks, nr, ni, t.cx, t.sx, t.wy, t.cy, t.sy, stn);
        stn[4] = stencil_positive(stn) && rr_all_finite(stn, 4);
    }
}

/* The tangential one, from the symmetric tangential block's symbols in sp2
 * (xx), sp3 (yy), spinv (xy) (the three overwritten): stn[8..11] Sxx,
 * stn[12..15] Syy, stn[16] Sxy at (1, 1) (odd in x and in y), stn[17] = 1
 * where usable (as above, positive definite where sampled). */
static void tangential_stencil(layout *L, const rr_conv2d *cv)
{
    const int L1 = cv->L1, L2 = cv->L2, nh = cv->nh;
    const size_t half = (size_t)L1 * nh;
    const double sc = 2.0 * L1 * L2, ks = 1.0 / ((double)L1 * L2);
    double *stn = L->stn, t4[4];
    torus_trig t;
    size_t i;
    int usable = 1;

    memset(stn + 8, 0, (STN_LEN - 8) * sizeof *stn);
    if (L->mx < 3 || L->my < 3)
        return;
    t = trig_of(L, cv);
    for (i = 0; i < half; i++) {
        /* [[a, b], [b, d]]^-1 = [[d, -b], [-b, a]] / (a d - b b) */
        const double ar = L->sp2[i] * sc, ai = L->sp2[half + i] * sc;
        const double dr = L->sp3[i] * sc, di = L->sp3[half + i] * sc;
        const double br = L->spinv[i] * sc, bi = L->spinv[half + i] * sc;
        const double er = ar * dr - ai * di - (br * br - bi * bi);
        const double ei = ar * di + ai * dr - 2.0 * br * bi, me = er * er + ei * ei;
        const double fr = er / me, fi = -ei / me;
        usable &= me > 0.0 && isfinite(me);
        L->sp2[i] = dr * fr - di * fi;
        L->sp2[half + i] = dr * fi + di * fr;
        L->sp3[i] = ar * fr - ai * fi;
        L->sp3[half + i] = ar * fi + ai * fr;
        L->spinv[i] = -(br * fr - bi * fi);
        L->spinv[half + i] = -(br * fi + bi * fr);
    }
    if (!usable)
        return;
    kernel_near_origin(L1, nh, ks, L->sp2, L->sp2 + half, t.cx, t.sx, t.wy, t.cy, t.sy, stn + 8);
    kernel_near_origin(L1, nh, ks, L->sp3, L->sp3 + half, t.cx, t.sx, t.wy, t.cy, t.sy, stn + 12);
    kernel_near_origin(L1, nh, ks, L->spinv, L->spinv + half, t.cx, t.sx, t.wy, t.cy, t.sy, t4);
    stn[16] = t4[3];
    /* positive definite where sampled: diagonals positive, and their
     * product above the square of the coupling -4 Sxy sin wx sin wy
     * (at most 16 Sxy^2) */
    stn[17] = stencil_positive(stn + 8) && stencil_positive(stn + 12)
              && rr_all_finite(stn + 8, 9);
    if (stn[17] != 0.0) {
        int p, q;
        for (p = 0; p <= 8 && stn[17] != 0.0; p++)
            for (q = 0; q <= 8; q++) {
                const double wx = RR_PI * p / 8.0, wy = RR_PI * q / 8.0;
                const double c1 = cos(wx), c2 = cos(wy);
                const double xx = stn[8] + 2.0 * stn[9] * c1 + 2.0 * stn[10] * c2
                                  + 4.0 * stn[11] * c1 * c2;
                const double yy = stn[12] + 2.0 * stn[13] * c1 + 2.0 * stn[14] * c2
                                  + 4.0 * stn[15] * c1 * c2;
                const double xy = -4.0 * stn[16] * sin(wx) * sin(wy);
                if (!(xx * yy > xy * xy)) {
                    stn[17] = 0.0;
                    break;
                }
            }
    }
}

/* The primitives' box table tab (ta, tb: even; tr: odd in x and y, 0 on
 * the axes) on the whole torus, into L->kern: offsets 0 .. L/2, then
 * -(L - L/2 - 1) .. -1 (the offset L/2 of an even L taken as +L/2: it lies
 * beyond the grid's offsets, where only the symbol's shape needs it). */
static void torus_table(layout *L, const rr_conv2d *cv, int nkx, const double *tab, int odd)
{
    const int L1 = cv->L1, L2 = cv->L2;
    int kx, ky;
    for (ky = 0; ky < L2; ky++) {
        const int j = ky <= L2 / 2 ? ky : L2 - ky;
        const double sy = odd && ky > L2 / 2 ? -1.0 : 1.0;
        const double *row = tab + (size_t)j * nkx;
        double *o = L->kern + (size_t)ky * L1;
        for (kx = 0; kx <= L1 / 2; kx++)
            o[kx] = sy * row[kx];
        for (kx = L1 / 2 + 1; kx < L1; kx++)
            o[kx] = (odd ? -sy : sy) * row[L1 - kx];
    }
}

/* The first phase of rr_exact_build_spectra: the primitives' tables, the
 * transforms of ta (into sp2) and tb (sp3), snn and the normal stencil. */
static int spectra_normal(layout *L, rr_conv2d *cv, double aspect, double nu,
                          const rr_interrupt *stop)
{
    const int L1 = cv->L1, L2 = cv->L2, nh = cv->nh;
    const int nkx = L->mx + 1 > L1 / 2 + 1 ? L->mx + 1 : L1 / 2 + 1;
    const int nky = L->my > L2 / 2 + 1 ? L->my : L2 / 2 + 1;
    const size_t half = (size_t)L1 * nh;
    const double c = 1.0 / RR_PI;
    int st, q;
    size_t i;

    if ((st = rr_influence_boxes(nkx, nky, 1.0, aspect, L->ta, L->tb, L->tr)) < 0)
        return st;
    for (q = 0; q < 2; q++) {
        torus_table(L, cv, nkx, q == 0 ? L->ta : L->tb, 0);
        if (rr_interrupted(stop))
            return RR_ERR_INTERRUPTED;
        if ((st = rr_conv2d_spectrum_torus(cv, L->kern, q == 0 ? L->sp2 : L->sp3)) < 0)
            return st;
    }
    for (i = 0; i < half; i++) {
        L->snn[i] = (1.0 - nu) * c * (L->sp2[i] + L->sp3[i]);
        L->snn[half + i] = (1.0 - nu) * c * (L->sp2[half + i] + L->sp3[half + i]);
    }
    if (!finite4(L->snn, 2 * half))
        return RR_ERR_RANGE;
    if (rr_interrupted(stop))
        return RR_ERR_INTERRUPTED;
    normal_stencil(L, cv);
    return RR_OK;
}

/* The second: the transform of tr, the steady tangential spectra and the
 * tangential stencil, from the first's tables and transforms. */
static int spectra_tangential(layout *L, rr_conv2d *cv, double nu, const rr_interrupt *stop)
{
    const int mx = L->mx, my = L->my, L1 = cv->L1, nh = cv->nh;
    const int nkx = mx + 1 > L1 / 2 + 1 ? mx + 1 : L1 / 2 + 1;
    const size_t half = (size_t)L1 * nh;
    const double c = 1.0 / RR_PI;
    int st, kx, ky, a, b;

    torus_table(L, cv, nkx, L->tr, 1);
    if (rr_interrupted(stop))
        return RR_ERR_INTERRUPTED;
    if ((st = rr_conv2d_spectrum_torus(cv, L->kern, L->spinv)) < 0)
        return st;
    /* every kernel a sum of the three, the steady ones shifted by one
     * element: times 1 - e^(i wx) on the line kx = a */
    for (a = 0; a < L1; a++) {
        const double wx = 2.0 * RR_PI * (double)a / L1, fr = 1.0 - cos(wx), fi = -sin(wx);
        for (b = 0; b < nh; b++) {
            const size_t i = (size_t)a * nh + (size_t)b;
            const double ar = L->sp2[i], ai = L->sp2[half + i], br = L->sp3[i];
            const double bi = L->sp3[half + i], rr = L->spinv[i], ri = L->spinv[half + i];
            const double xr = c * ((1.0 - nu) * ar + br), xi = c * ((1.0 - nu) * ai + bi);
            const double yr = c * (ar + (1.0 - nu) * br), yi = c * (ai + (1.0 - nu) * bi);
            const double zr = -nu * c * rr, zi = -nu * c * ri;
            L->sxx[i] = xr * fr - xi * fi;
            L->sxx[half + i] = xr * fi + xi * fr;
            L->syy[i] = yr * fr - yi * fi;
            L->syy[half + i] = yr * fi + yi * fr;
            L->sxy[i] = zr * fr - zi * fi;
            L->sxy[half + i] = zr * fi + zi * fr;
            L->sp2[i] = xr;
            L->sp2[half + i] = xi;
            L->sp3[i] = yr;
            L->sp3[half + i] = yi;
            L->spinv[i] = zr;
            L->spinv[half + i] = zi;
        }
    }
#define QA(i, j) (L->ta[(j) * nkx + (i)])
#define QB(i, j) (L->tb[(j) * nkx + (i)])
#define QR(i, j) (L->tr[(j) * nkx + (i)])
    if (L1 < 2 * mx) {
        /* the steady kernels themselves, on the grid's offsets */
        const int kw = 2 * mx - 1;
        if (rr_interrupted(stop))
            return RR_ERR_INTERRUPTED;
        for (ky = -(my - 1); ky < my; ky++)
            for (kx = -(mx - 1); kx < mx; kx++) {
                const int i0 = abs(kx), i1 = abs(kx + 1), j = abs(ky);
                const double da = QA(i0, j) - QA(i1, j), db = QB(i0, j) - QB(i1, j);
                const size_t k = (size_t)(ky + my - 1) * kw + (kx + mx - 1);
                L->kern[k] = ((1.0 - nu) * da + db) / RR_PI;
                L->kern2[k] = (da + (1.0 - nu) * db) / RR_PI;
            }
        if ((st = rr_conv2d_spectrum(cv, L->kern, L->sxx)) < 0
            || (st = rr_conv2d_spectrum(cv, L->kern2, L->syy)) < 0)
            return st;
        for (ky = -(my - 1); ky < my; ky++)
            for (kx = -(mx - 1); kx < mx; kx++) {
                /* A_xy is odd in kx and ky: sign(k) [[r]](|k|), 0 on the axes */
                const int i0 = abs(kx), i1 = abs(kx + 1), j = abs(ky);
                const double sy = (ky > 0) - (ky < 0);
                const double s0 = (kx > 0) - (kx < 0), s1 = (kx + 1 > 0) - (kx + 1 < 0);
                const size_t k = (size_t)(ky + my - 1) * kw + (kx + mx - 1);
                L->kern[k] = -nu / RR_PI * sy * (s0 * QR(i0, j) - s1 * QR(i1, j));
            }
        if ((st = rr_conv2d_spectrum(cv, L->kern, L->sxy)) < 0)
            return st;
    }
#undef QA
#undef QB
#undef QR
    if (!finite4(L->sxx, 2 * half) || !finite4(L->syy, 2 * half) || !finite4(L->sxy, 2 * half))
        return RR_ERR_RANGE;
    if (rr_interrupted(stop))
        return RR_ERR_INTERRUPTED;
    tangential_stencil(L, cv);
    return RR_OK;
}

/* The kernels' spectra for the grid shape (mx, my, dy/dx) and nu: the
 * normal A_nn/dx and, where tangential is set, the steady tangential
 * (A(k) - A(k + e_x))/dx, with the preconditioners' stencils; kept in the
 * workspace, keyed (hdr[1..4]; hdr[5] = 1 once the tangential ones are
 * there too), and built only where missing: a grid whose tangential
 * problem is solved on its box (rr_exact.c) never needs its own.  Three
 * transforms in all: the primitives' boxes ta, tb, tr on the whole torus,
 * of which every kernel is a sum (rr_influence.h); the steady kernel's
 * symbol is the symmetric one's times 1 - e^(i wx) (the shift by one
 * element, exact where the torus holds offset mx: L1 >= 2 mx; else its
 * kernel is transformed itself).  The tangential phase takes the normal
 * one's tables and transforms of ta and tb (sp2, sp3), which nothing else
 * writes while the key holds. */
int rr_exact_build_spectra(layout *L, rr_conv2d *cv, double aspect, double nu, int tangential,
                           const rr_interrupt *stop)
{
    const int mx = L->mx, my = L->my;
    int st;

    if (!(L->hdr[0] == HDR_TAG && L->hdr[1] == mx && L->hdr[2] == my && L->hdr[3] == aspect
          && L->hdr[4] == nu)) {
        L->hdr[0] = 0.0;
        if ((st = spectra_normal(L, cv, aspect, nu, stop)) < 0)
            return st;
        L->hdr[1] = mx;
        L->hdr[2] = my;
        L->hdr[3] = aspect;
        L->hdr[4] = nu;
        L->hdr[5] = 0.0;
        L->hdr[0] = HDR_TAG;
    }
    if (tangential && L->hdr[5] != 1.0) {
        if ((st = spectra_tangential(L, cv, nu, stop)) < 0) {
            L->hdr[0] = 0.0;         /* sp2, sp3 may be half overwritten */
            return st;
        }
        L->hdr[5] = 1.0;
    }
    return RR_OK;
}

/* The diagonal of the steady operator (per 1/G): (A(0) - A(e_x))/dx, mean of xx and yy. */
double rr_exact_steady_diagonal(double aspect, double nu)
{
    double a0[4], a1[4];
    rr_influence_at(0, 0, 1.0, aspect, nu, a0);
    rr_influence_at(1, 0, 1.0, aspect, nu, a1);
    return 0.5 * ((a0[1] - a1[1]) + (a0[2] - a1[2]));
}
