/* rr_exact.c - Kalker's exact theory of steady rolling: the normal and the
 * tangential problem on a grid, with FFT products (see rr_exact.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "util/rr_common.h"
#include "util/rr_fft.h"
#include "contact/rr_influence.h"
#include "contact/rr_hertz.h"
#include "contact/rr_kalker.h"
#include "contact/rr_exact.h"

/* Krylov vectors kept by GMRES before it restarts. */
#define GMRES_M 30
/* The workspace's header: a tag, then the key of the cached spectra. */
#define HDR_LEN 8
/* the stencils of the inverse operators (inverse_stencils), kept with the spectra */
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

/* Doubles of one kernel spectrum of rr_conv2d for an mx x my grid: the
 * torus L1 x (L2/2 + 1) of complex values (rr_fft.h); checked against
 * rr_conv2d_spectrum_len once the engine exists. */
static size_t spectrum_len(int mx, int my)
{
    const int L1 = rr_conv2d_torus_len(2 * mx - 1), L2 = rr_conv2d_torus_len(2 * my - 1);
    return 2 * (size_t)L1 * (size_t)(L2 / 2 + 1);
}

/* The workspace's carving; lengths in doubles.  With base NULL only the
 * total is computed. */
static size_t carve(layout *L, int mx, int my, double *base)
{
    const size_t n = (size_t)mx * (size_t)my, n2 = 2 * n;
    const size_t conv_len = rr_conv2d_workspace_len(mx, my);
    size_t spec_len, tab_len, torus_len, kern_len, off = 0;

#define TAKE(ptr, len) do { (ptr) = base ? base + off : NULL; off += (len); } while (0)
    memset(L, 0, sizeof *L);
    if (conv_len == 0)
        return 0;
    spec_len = spectrum_len(mx, my);
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

size_t rr_exact_workspace_len(int mx, int my)
{
    layout L;
    if (mx < 1 || my < 1 || mx > RR_EXACT_MAX_GRID || my > RR_EXACT_MAX_GRID)
        return 0;
    return carve(&L, mx, my, NULL);
}

int rr_exact_hertz_grid(double a, double b, int nx, int ny, rr_exact_grid *g)
{
    if (!g)
        return RR_ERR_NULL;
    memset(g, 0, sizeof *g);
    if (!isfinite(a) || !isfinite(b))
        return RR_ERR_NONFINITE;
    if (!(a > 0.0) || !(b > 0.0))
        return RR_ERR_GEOMETRY;
    if (nx < 1 || ny < 1 || nx > RR_EXACT_MAX_GRID - 2 * RR_EXACT_MARGIN
        || ny > RR_EXACT_MAX_GRID - 2 * RR_EXACT_MARGIN)
        return RR_ERR_GRID;
    g->mx = nx + 2 * RR_EXACT_MARGIN;
    g->my = ny + 2 * RR_EXACT_MARGIN;
    g->dx = 2.0 * a / nx;
    g->dy = 2.0 * b / ny;
    if (!isnormal(g->dx) || !isnormal(g->dy))
        return RR_ERR_GEOMETRY;
    g->x0 = -0.5 * (g->mx - 1) * g->dx;
    g->y0 = -0.5 * (g->my - 1) * g->dy;
    return RR_OK;
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

/* The 3 x 3 stencils nearest the inverses of the half-space's operators,
 * for the preconditioners: the inverse symbols on the torus, transformed
 * back at the offsets -1 .. 1.  The half-space's symbol grows as 1/|w| at
 * low frequencies, so the inverse decays fast and these few values carry
 * most of it; it must be the symbol of the kernel on the whole torus
 * (the grid's offsets alone, zero beyond, leave it negative somewhere).
 * Given the symbols (scaled as rr_conv2d's spectra) of A_nn in snn and of
 * the symmetric tangential block in sp2 (xx), sp3 (yy), spinv (xy) (the
 * three overwritten); stn[0..3] Snn (centre, (1, 0), (0, 1), (1, 1)),
 * stn[4] = 1 where usable; stn[8..11] Sxx, stn[12..15] Syy, stn[16] Sxy at
 * (1, 1) (odd in x and in y), stn[17] = 1 where usable.  Not usable: grids
 * under 3 x 3, a symbol with a zero, or a stencil whose symbol is not
 * positive (definite). */
static void inverse_stencils(layout *L, const rr_conv2d *cv)
{
    const int L1 = cv->L1, L2 = cv->L2, nh = cv->nh;
    const size_t half = (size_t)L1 * nh;
    const double sc = 2.0 * L1 * L2;
    double *stn = L->stn, *cx = L->kern, *sx = cx + L1, *wy = sx + L1, *cy = wy + nh;
    double *sy = cy + nh, *nr = L->kern2, *ni = nr + half, t[4];
    const double ks = 1.0 / ((double)L1 * L2);
    size_t i;
    int a, usable_n = 1, usable_t = 1;

    memset(stn, 0, STN_LEN * sizeof *stn);
    if (L->mx < 3 || L->my < 3)
        return;
    for (a = 0; a < L1; a++) {
        cx[a] = cos(2.0 * RR_PI * a / L1);
        sx[a] = sin(2.0 * RR_PI * a / L1);
    }
    for (a = 0; a < nh; a++) {
        wy[a] = a == 0 || 2 * a == L2 ? 1.0 : 2.0;
        cy[a] = wy[a] * cos(2.0 * RR_PI * a / L2);
        sy[a] = wy[a] * sin(2.0 * RR_PI * a / L2);
    }
    for (i = 0; i < half; i++) {
        /* 1 / nn; [[a, b], [b, d]]^-1 = [[d, -b], [-b, a]] / (a d - b b) */
        const double re = L->snn[i] * sc, im = L->snn[half + i] * sc, m = re * re + im * im;
        const double ar = L->sp2[i] * sc, ai = L->sp2[half + i] * sc;
        const double dr = L->sp3[i] * sc, di = L->sp3[half + i] * sc;
        const double br = L->spinv[i] * sc, bi = L->spinv[half + i] * sc;
        const double er = ar * dr - ai * di - (br * br - bi * bi);
        const double ei = ar * di + ai * dr - 2.0 * br * bi, me = er * er + ei * ei;
        const double fr = er / me, fi = -ei / me;
        usable_n &= m > 0.0 && isfinite(m);
        usable_t &= me > 0.0 && isfinite(me);
        nr[i] = re / m;
        ni[i] = -im / m;
        L->sp2[i] = dr * fr - di * fi;
        L->sp2[half + i] = dr * fi + di * fr;
        L->sp3[i] = ar * fr - ai * fi;
        L->sp3[half + i] = ar * fi + ai * fr;
        L->spinv[i] = -(br * fr - bi * fi);
        L->spinv[half + i] = -(br * fi + bi * fr);
    }
    if (usable_n) {
        kernel_near_origin(L1, nh, ks, nr, ni, cx, sx, wy, cy, sy, stn);
        stn[4] = stencil_positive(stn) && rr_all_finite(stn, 4);
    }
    if (usable_t) {
        kernel_near_origin(L1, nh, ks, L->sp2, L->sp2 + half, cx, sx, wy, cy, sy, stn + 8);
        kernel_near_origin(L1, nh, ks, L->sp3, L->sp3 + half, cx, sx, wy, cy, sy, stn + 12);
        kernel_near_origin(L1, nh, ks, L->spinv, L->spinv + half, cx, sx, wy, cy, sy, t);
        stn[16] = t[3];
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
}

/* The kernels' spectra for the grid shape (mx, my, dy/dx) and nu: the
 * normal A_nn/dx and the steady tangential (A(k) - A(k + e_x))/dx, and
 * the preconditioners' stencils (inverse_stencils); kept in the workspace
 * and rebuilt only when the key changes.  Three transforms: the
 * primitives' boxes ta, tb, tr on the whole torus, of which every kernel is
 * a sum (rr_influence.h); the steady kernel's symbol is the symmetric one's
 * times 1 - e^(i wx) (the shift by one element, exact where the torus
 * holds offset mx: L1 >= 2 mx; else its kernel is transformed itself). */
static int build_spectra(layout *L, rr_conv2d *cv, double aspect, double nu,
                         const rr_interrupt *stop)
{
    const int mx = L->mx, my = L->my, L1 = cv->L1, L2 = cv->L2, nh = cv->nh;
    const int nkx = mx + 1 > L1 / 2 + 1 ? mx + 1 : L1 / 2 + 1;
    const int nky = my > L2 / 2 + 1 ? my : L2 / 2 + 1;
    const size_t half = (size_t)L1 * nh;
    const double c = 1.0 / RR_PI;
    double fr = 0.0, fi = 0.0;
    int st, kx, ky, q;
    size_t i;

    if (L->hdr[0] == HDR_TAG && L->hdr[1] == mx && L->hdr[2] == my && L->hdr[3] == aspect
        && L->hdr[4] == nu)
        return RR_OK;
    L->hdr[0] = 0.0;
    st = rr_influence_boxes(nkx, nky, 1.0, aspect, L->ta, L->tb, L->tr);
    if (st < 0)
        return st;
#define QA(i, j) (L->ta[(j) * nkx + (i)])
#define QB(i, j) (L->tb[(j) * nkx + (i)])
#define QR(i, j) (L->tr[(j) * nkx + (i)])
    /* ta, tb, tr on the whole torus (tr odd in x and y, 0 on the axes):
     * offsets 0 .. L/2, then -(L - L/2 - 1) .. -1 (the offset L/2 of an
     * even L taken as +L/2: it lies beyond the grid's offsets, where only
     * the symbol's shape needs it) */
    for (q = 0; q < 3; q++) {
        double *spec = q == 0 ? L->sp2 : q == 1 ? L->sp3 : L->spinv;
        const double *tab = q == 0 ? L->ta : q == 1 ? L->tb : L->tr;
        for (ky = 0; ky < L2; ky++) {
            const int j = ky <= L2 / 2 ? ky : L2 - ky;
            const double sy = q == 2 && ky > L2 / 2 ? -1.0 : 1.0;
            const double *row = tab + (size_t)j * nkx;
            double *o = L->kern + (size_t)ky * L1;
            for (kx = 0; kx <= L1 / 2; kx++)
                o[kx] = sy * row[kx];
            for (kx = L1 / 2 + 1; kx < L1; kx++)
                o[kx] = (q < 2 ? sy : -sy) * row[L1 - kx];
        }
        if (rr_interrupted(stop))
            return RR_ERR_INTERRUPTED;
        if ((st = rr_conv2d_spectrum_torus(cv, L->kern, spec)) < 0)
            return st;
    }
    /* every kernel a sum of the three, the steady ones shifted */
    for (i = 0; i < half; i++) {
        const double ar = L->sp2[i], ai = L->sp2[half + i], br = L->sp3[i], bi = L->sp3[half + i];
        const double rr = L->spinv[i], ri = L->spinv[half + i];
        const double xr = c * ((1.0 - nu) * ar + br), xi = c * ((1.0 - nu) * ai + bi);
        const double yr = c * (ar + (1.0 - nu) * br), yi = c * (ai + (1.0 - nu) * bi);
        const double zr = -nu * c * rr, zi = -nu * c * ri;
        if (i % nh == 0) {
            /* 1 - e^(i wx), for the line kx = i / nh */
            const double wx = 2.0 * RR_PI * (double)(i / nh) / L1;
            fr = 1.0 - cos(wx);
            fi = -sin(wx);
        }
        L->snn[i] = (1.0 - nu) * c * (ar + br);
        L->snn[half + i] = (1.0 - nu) * c * (ai + bi);
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
    if (!finite4(L->snn, 2 * half) || !finite4(L->sxx, 2 * half) || !finite4(L->syy, 2 * half)
        || !finite4(L->sxy, 2 * half))
        return RR_ERR_RANGE;
    if (rr_interrupted(stop))
        return RR_ERR_INTERRUPTED;
    inverse_stencils(L, cv);
    L->hdr[1] = mx;
    L->hdr[2] = my;
    L->hdr[3] = aspect;
    L->hdr[4] = nu;
    L->hdr[0] = HDR_TAG;
    return RR_OK;
}

/* The diagonal of the steady operator (per 1/G): (A(0) - A(e_x))/dx, mean of xx and yy. */
static double steady_diagonal(double aspect, double nu)
{
    double a0[4], a1[4];
    rr_influence_at(0, 0, 1.0, aspect, nu, a0);
    rr_influence_at(1, 0, 1.0, aspect, nu, a1);
    return 0.5 * ((a0[1] - a1[1]) + (a0[2] - a1[2]));
}

/* ---- the stencils' products ------------------------------------------------- */

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

/* in (n values, a component) into rows j0 .. j1 of the halo plane h (the
 * grid's rows, clamped to it; their border elements 0), times mask (1 or
 * 0 an element); the halo's first and last rows 0 */
static void to_halo(const layout *L, const double *in, const double *mask, int j0, int j1,
                    double *h)
{
    const int mx = L->mx, my = L->my, w = mx + 2;
    int i, j;
    memset(h, 0, (size_t)w * sizeof *h);
    memset(h + (size_t)(my + 1) * w, 0, (size_t)w * sizeof *h);
    for (j = j0 > 0 ? j0 : 0; j <= j1 && j < my; j++) {
        const double *a = in + j * mx, *m = mask + j * mx;
        double *o = h + (size_t)(j + 1) * w;
        o[0] = o[mx + 1] = 0.0;
        for (i = 0; i < mx; i++)
            o[i + 1] = a[i] * m[i];
    }
}

/* NormCG's residual and its preconditioned form: r = delta - g on the
 * contact set (0 elsewhere) and z = S r there, S the normal operator's
 * inverse stencil; returns the mean of z on the set, *count its elements */
static double normal_residual_stencil(const layout *L, double delta, const double *g,
                                      double *r, double *z, int *count)
{
    const int mx = L->mx, my = L->my, w = mx + 2;
    const double s0 = L->stn[0], s1 = L->stn[1], s2 = L->stn[2], s3 = L->stn[3];
    const signed char *in = L->state;
    double *h = L->halo, sum = 0.0;
    int i, j, c = 0;
    memset(h, 0, (size_t)w * sizeof *h);
    memset(h + (size_t)(my + 1) * w, 0, (size_t)w * sizeof *h);
    for (j = 0; j < my; j++) {
        double *o = h + (size_t)(j + 1) * w;
        o[0] = o[mx + 1] = 0.0;
        for (i = 0; i < mx; i++) {
            const int k = j * mx + i;
            r[k] = in[k] != OUTSIDE ? delta - g[k] : 0.0;
            o[i + 1] = r[k];
        }
    }
    for (j = 0; j < my; j++)
        for (i = 0; i < mx; i++) {
            const int k = j * mx + i, q = (j + 1) * w + i + 1;
            if (in[k] != OUTSIDE) {
                z[k] = STENCIL3(s0, s1, s2, s3, h, q, w);
                sum += z[k];
                c++;
            } else {
                z[k] = 0.0;
            }
        }
    *count = c;
    return c ? sum / c : 0.0;
}

/* ---- the normal problem ---------------------------------------------------- */

typedef struct {
    const rr_exact_problem *pb;
    layout *L;
    rr_conv2d *cv;
    int products;
} solver;

/* u = (dx/G) A_nn * p; the caller's interrupt hook is polled before every
 * product, the unit of the solver's work (RR_ERR_INTERRUPTED) */
static int normal_product(solver *S, const double *p, double *u)
{
    const double sc = S->pb->grid.dx / S->pb->G;
    int k, st;
    if (rr_interrupted(S->pb->interrupt))
        return RR_ERR_INTERRUPTED;
    st = rr_conv2d_apply(S->cv, S->L->snn, p, u);
    for (k = 0; k < S->L->n; k++)
        u[k] *= sc;
    S->products++;
    /* the inputs were checked: a product that fails has overflowed */
    return st < 0 ? RR_ERR_RANGE : st;
}

/* g = h + u(p): the gap before the approach, from a fresh product */
static int gap_of(solver *S, const double *p, double *g)
{
    int k, st = normal_product(S, p, g);
    for (k = 0; k < S->L->n; k++)
        g[k] += S->L->h[k];
    return st;
}

static double mean_on(const double *v, const signed char *in, int n, int *count)
{
    double sum = 0.0;
    int k, c = 0;
    for (k = 0; k < n; k++)
        if (in[k] != OUTSIDE) {
            sum += v[k];
            c++;
        }
    *count = c;
    return c ? sum / c : 0.0;
}

/* A start from q (in p on entry): the pressure sqrt(q) where q > 0 (those
 * elements make the first contact set), scaled to the load N.  Returns the
 * elements in contact, 0 where none or not finite. */
static int start_from_q(const rr_exact_problem *pb, layout *L, double *p)
{
    const int n = L->n;
    double psum = 0.0;
    int k, cnt = 0;
    for (k = 0; k < n; k++) {
        const double q = p[k];
        L->state[k] = q > 0.0 ? ADHESION : OUTSIDE;
        p[k] = q > 0.0 ? sqrt(q) : 0.0;
        psum += p[k];
        cnt += q > 0.0;
    }
    if (cnt == 0 || !(psum > 0.0))
        return 0;
    for (k = 0; k < n; k++)
        p[k] *= pb->N / (pb->grid.dx * pb->grid.dy * psum);
    return rr_all_finite(p, n) ? cnt : 0;
}

/* A start for any h: Hertz's pressure of the curvatures of h at its
 * lowest element (second differences), laid over the level sets of h:
 * p = sqrt(1 - h/h_c) with h_c the gap at the Hertzian ellipse's rim.  A
 * patch that is not elliptic gets the right shape roughly, which saves CG
 * steps against a uniform start.  Returns the elements in contact, 0 where
 * h has no usable curvature there (the caller starts otherwise). */
static int start_from_h(const rr_exact_problem *pb, layout *L, const double *h, double *p)
{
    const int mx = L->mx, my = L->my, n = L->n;
    const double dx = pb->grid.dx, dy = pb->grid.dy;
    int k, i, j, km = 0;
    double A, B, hc;
    rr_hertz_result hz;

    for (k = 1; k < n; k++)
        if (h[k] < h[km])
            km = k;
    i = km % mx;
    j = km / mx;
    if (i < 1 || i > mx - 2 || j < 1 || j > my - 2)
        return 0;
    A = (h[km + 1] - 2.0 * h[km] + h[km - 1]) / (2.0 * dx * dx);
    B = (h[km + mx] - 2.0 * h[km] + h[km - mx]) / (2.0 * dy * dy);
    if (!(A > 0.0) || !(B > 0.0)
        || rr_hertz(A, B, pb->N, pb->G / (1.0 - pb->nu), &hz) != RR_OK)
        return 0;
    hc = 0.5 * (A * hz.a * hz.a + B * hz.b * hz.b);
    if (!(hc > 0.0) || !isfinite(hc))
        return 0;
    for (k = 0; k < n; k++)
        p[k] = 1.0 - (h[k] - h[km]) / hc;
    return start_from_q(pb, L, p);
}

/* NormCG: min 1/2 p.Ap + h.p over p >= 0 with dA sum p = N; the approach is
 * the multiplier, eliminated by keeping every search direction mean-free on
 * the contact set C.  Preconditioned, as Vollebregt's NormCG, by an
 * approximate inverse of A restricted to C and made mean-free there: here
 * the 3 x 3 stencil of the inverse (inverse_stencils), which costs a
 * stencil instead of a product and took the products on the 300 random
 * cases from 18.4 to 10.0 at 27 across, 20.7 to 10.8 at 45.  Returns the
 * status; res gets delta, the products and the residual. */
static int solve_normal(solver *S, rr_exact_result *res)
{
    const rr_exact_problem *pb = S->pb;
    layout *L = S->L;
    const int n = L->n;
    const double dA = pb->grid.dx * pb->grid.dy;
    double *h = L->h, *p = L->pn, *g = L->gap, *r = L->r, *rold = L->rold, *d = L->d,
           *v = L->v, *z = L->stn[4] != 0.0 ? L->z : L->r;
    signed char *in = L->state;
    double hmin = HUGE_VAL, hmax = -HUGE_VAL, delta = 0.0, rz_old = 0.0, step_rms = HUGE_VAL;
    double h0;
    rr_hertz_result hz;
    int k, cnt, restart = 1, st, converged = 0, have_delta = 0;

    for (k = 0; k < n; k++) {
        if (h[k] < hmin) hmin = h[k];
        if (h[k] > hmax) hmax = h[k];
    }
    /* h from its lowest value: a large offset would drown the gap's
     * variation in round-off (the approach absorbs any constant) */
    for (k = 0; k < n; k++)
        h[k] -= hmin;
    hmax -= hmin;
    h0 = hmin;
    hmin = 0.0;
    /* start: Hertz's pressure where h is Hertzian (the discrete solution
     * differs by about 1 % rms: a few CG steps), else the lowest tenth of h
     * under a uniform pressure */
    cnt = 0;
    if (!pb->h && rr_hertz(pb->A, pb->B, pb->N, pb->G / (1.0 - pb->nu), &hz) == RR_OK) {
        for (k = 0; k < n; k++) {
            const double x = (pb->grid.x0 + (k % L->mx) * pb->grid.dx) / hz.a;
            const double y = (pb->grid.y0 + (k / L->mx) * pb->grid.dy) / hz.b;
            p[k] = 1.0 - x * x - y * y;
        }
        cnt = start_from_q(pb, L, p);
    }
    if (cnt == 0)
        cnt = start_from_h(pb, L, h, p);
    if (cnt == 0) {
        for (k = 0; k < n; k++) {
            in[k] = (h[k] <= hmin + 0.1 * (hmax - hmin)) ? ADHESION : OUTSIDE;
            cnt += in[k] != OUTSIDE;
        }
        for (k = 0; k < n; k++)
            p[k] = in[k] != OUTSIDE ? pb->N / (dA * cnt) : 0.0;
    }
    if ((st = gap_of(S, p, g)) < 0)
        return st;

    /* the passes over the grid fused where one can follow another: r with
     * its halo copy, the stencil with z's sum, z's projection with the dot
     * products, d with its sum, d's projection with r.d, the update with
     * the checks and the next approach */
    while (S->products < pb->maxit) {
        double rz = 0.0, rzold = 0.0, rd = 0.0, dv = 0.0, alpha, beta, psum = 0.0, p2 = 0.0,
               s2 = 0.0, dsum = 0.0, gsum = 0.0, dm;
        int changed = 0, nc;

        if (!have_delta)
            delta = mean_on(g, in, n, &nc);
        /* z: the preconditioned residual (z = r without a stencil) */
        if (L->stn[4] != 0.0) {
            const double zm = normal_residual_stencil(L, delta, g, r, z, &nc);
            for (k = 0; k < n; k++)
                if (in[k] != OUTSIDE) {
                    z[k] -= zm;
                    rz += r[k] * z[k];
                    if (!restart)
                        rzold += z[k] * rold[k];
                }
        } else {
            nc = 0;
            for (k = 0; k < n; k++) {
                r[k] = in[k] != OUTSIDE ? delta - g[k] : 0.0;
                nc += in[k] != OUTSIDE;
                rz += r[k] * r[k];
                if (!restart)
                    rzold += r[k] * rold[k];
            }
        }
        if (rz == 0.0) {
            converged = 1;
            break;
        }
        /* Polak-Ribiere, reset to steepest descent after a change of C; a
         * restart never reads d (what the workspace holds from another
         * case, a NaN of a failed one, would survive 0 d) */
        beta = restart ? 0.0 : fmax(0.0, (rz - rzold) / rz_old);
        for (k = 0; k < n; k++) {
            d[k] = in[k] == OUTSIDE ? 0.0 : restart ? z[k] : z[k] + beta * d[k];
            rold[k] = r[k];
            dsum += d[k];
        }
        /* mean-free on C to round-off, so that the load stays N */
        dm = nc ? dsum / nc : 0.0;
        for (k = 0; k < n; k++)
            if (in[k] != OUTSIDE) {
                d[k] -= dm;
                rd += r[k] * d[k];
            }
        rz_old = rz;
        restart = 0;
        if ((st = normal_product(S, d, v)) < 0)
            return st;
        for (k = 0; k < n; k++)
            dv += d[k] * v[k];
        if (!(dv > 0.0))
            return RR_ERR_RANGE;
        alpha = rd / dv;
        /* the gap changes everywhere, the pressure only on C; elements
         * pulled below zero leave C (the load is then restored by scaling) */
        for (k = 0; k < n; k++) {
            g[k] += alpha * v[k];
            if (in[k] != OUTSIDE) {
                p[k] += alpha * d[k];
                s2 += (alpha * d[k]) * (alpha * d[k]);
                if (p[k] < 0.0) {
                    p[k] = 0.0;
                    in[k] = OUTSIDE;
                    changed = 1;
                } else {
                    p2 += p[k] * p[k];
                    gsum += g[k];
                }
            }
        }
        if (changed) {
            for (k = 0; k < n; k++)
                psum += p[k];
            if (!(psum > 0.0))
                return RR_ERR_GEOMETRY;
            for (k = 0; k < n; k++)
                p[k] *= pb->N / (dA * psum);
            if ((st = gap_of(S, p, g)) < 0)
                return st;
            restart = 1;
            have_delta = 0;
            continue;
        }
        /* exterior elements that the surfaces would penetrate join C */
        delta = nc ? gsum / nc : 0.0;
        for (k = 0; k < n; k++)
            if (in[k] == OUTSIDE && g[k] < delta) {
                in[k] = ADHESION;
                changed = 1;
            }
        step_rms = sqrt(s2 / (p2 > 0.0 ? p2 : 1.0));
        if (changed) {
            restart = 1;
            have_delta = 0;
            continue;
        }
        have_delta = 1;
        if (step_rms <= pb->tol) {
            converged = 1;
            break;
        }
    }
    res->delta = mean_on(g, in, n, &cnt) + h0;
    res->normal_products = S->products;
    res->normal_residual = step_rms;
    return converged ? RR_OK : RR_WARN_NOT_CONVERGED;
}

/* ---- the tangential problem -------------------------------------------------- */

/* |(x, y)|: the square root of the sum of squares where that can neither
 * overflow nor lose digits to underflow (tractions and slips are far from
 * both), else hypot, which costs several times more */
static double norm2(double x, double y)
{
    const double s = x * x + y * y;
    if (s > 1e-290 && s < 1e290)
        return sqrt(s);
    return hypot(x, y);
}

/* out = G M p (the product not divided by G: the callers fold 1/G into
 * their own passes) for p = (px, py) packed as p[0..n) and p[n..2n) */
static int tang_product_g(solver *S, const double *p, double *out)
{
    layout *L = S->L;
    const int n = L->n;
    int st;
    if (rr_interrupted(S->pb->interrupt))
        return RR_ERR_INTERRUPTED;
    st = rr_conv2d_apply2(S->cv, L->sxx, L->sxy, L->sxy, L->syy, p, p + n, out, out + n);
    S->products++;
    return st < 0 ? RR_ERR_RANGE : st;
}

/* The preconditioner's first part: out = P in, the inverse of the upwind difference
 * along each row from the leading edge (+x) down, which turns the steady
 * operator into the symmetric half-space one where elements adhere; a
 * slipping element takes its upstream neighbour's value only along the
 * traction bound's tangent and by the fraction g/|z| (its Jacobian's own
 * weight there).  This cut the tangential products by about 30 % against
 * restarting the sum at every slipping element. */
static void precondition(const layout *L, const double *in, double *out)
{
    const int mx = L->mx, my = L->my, n = L->n;
    int i, j, r;
    /* one recurrence for all states (newton_coeffs): o = a + f (u - n (n.u))
     * with u the upstream value, f = 0 without an upstream neighbour in
     * contact, n = 0 in adhesion.  Four rows at a time: the recurrence is a
     * chain of dependent operations along a row, and four independent
     * chains keep the processor busy (2.5 times faster than row by row). */
    for (j = 0; j + 4 <= my; j += 4) {
        double ux[4] = {0.0, 0.0, 0.0, 0.0}, uy[4] = {0.0, 0.0, 0.0, 0.0};
        for (i = mx - 1; i >= 0; i--)
            for (r = 0; r < 4; r++) {
                const int k = (j + r) * mx + i;
                const double nx = L->jn[k], ny = L->jn[k + n], f = L->pcf[k];
                const double d = nx * ux[r] + ny * uy[r];
                ux[r] = in[k] + f * (ux[r] - nx * d);
                uy[r] = in[k + n] + f * (uy[r] - ny * d);
                out[k] = ux[r];
                out[k + n] = uy[r];
            }
    }
    for (; j < my; j++) {
        double ux = 0.0, uy = 0.0;
        for (i = mx - 1; i >= 0; i--) {
            const int k = j * mx + i;
            const double nx = L->jn[k], ny = L->jn[k + n], f = L->pcf[k];
            const double d = nx * ux + ny * uy;
            ux = in[k] + f * (ux - nx * d);
            uy = in[k + n] + f * (uy - ny * d);
            out[k] = ux;
            out[k + n] = uy;
        }
    }
}

/* One row of tang_stencil: the rows j - 1, j, j + 1 of the halo planes
 * from their element 0 (xs, xc, xn; ys, yc, yn), st the two stencils and
 * the coupling (times c) */
static void tang_stencil_row(int mx, const double *st, const double *restrict xs,
                             const double *restrict xc, const double *restrict xn,
                             const double *restrict ys, const double *restrict yc,
                             const double *restrict yn, const double *restrict a,
                             const double *restrict ix, const double *restrict iy,
                             double *restrict ox, double *restrict oy)
{
    const double x0 = st[0], x1 = st[1], x2 = st[2], x3 = st[3];
    const double y0 = st[4], y1 = st[5], y2 = st[6], y3 = st[7], xy = st[8];
    int i;
    for (i = 0; i < mx; i++) {
        const double dx = (xn[i - 1] + xn[i + 1]) + (xs[i - 1] + xs[i + 1]);
        const double dy = (yn[i - 1] + yn[i + 1]) + (ys[i - 1] + ys[i + 1]);
        /* the odd-odd coupling: S(o) = s sign(ox) sign(oy), out(i) = sum S(o) in(i - o) */
        const double cx = (xn[i + 1] - xn[i - 1]) - (xs[i + 1] - xs[i - 1]);
        const double cy = (yn[i + 1] - yn[i - 1]) - (ys[i + 1] - ys[i - 1]);
        const double sx = x0 * xc[i] + x1 * (xc[i - 1] + xc[i + 1]) + x2 * (xs[i] + xn[i])
                          + x3 * dx + xy * cy;
        const double sy = y0 * yc[i] + y1 * (yc[i - 1] + yc[i + 1]) + y2 * (ys[i] + yn[i])
                          + y3 * dy + xy * cx;
        /* a s + (1 - a) in with a 1 or 0: exactly one of them */
        ox[i] = a[i] * sx + (1.0 - a[i]) * ix[i];
        oy[i] = a[i] * sy + (1.0 - a[i]) * iy[i];
    }
}

/* The tangential preconditioner's second part: out = c S in on the
 * adhering elements, S the symmetric tangential operator's inverse
 * stencil, on the values of adhering elements alone; out = in elsewhere.
 * After the inverse upwind difference (precondition) the steady operator
 * acts on adhering elements as the symmetric one, and S undoes most of
 * that (GMRES took 27 % fewer products on the 300 random cases at 27
 * across, 30 % at 45).  c: 0.8 G / rho, the fewest products of 0.5 to
 * 4 times G / rho. */
static void tang_stencil(const layout *L, double c, const double *in, double *out)
{
    const int mx = L->mx, my = L->my, n = L->n, w = mx + 2;
    const size_t hn = (size_t)w * (my + 2);
    const int i0 = L->ai0, nb = L->ai1 - L->ai0 + 1;
    double *hx = L->halo, *hy = L->halo + hn, st[9];
    int j;
    /* out = in, then S on the adhering elements' bounding box, the halo
     * rows around it filled (each masked to the adhering elements) */
    memcpy(out, in, (size_t)(2 * n) * sizeof *out);
    if (L->stn[17] == 0.0 || L->ai1 < 0)
        return;
    for (j = 0; j < 9; j++)
        st[j] = c * L->stn[8 + j];
    to_halo(L, in, L->madh, L->aj0 - 1, L->aj1 + 1, hx);
    to_halo(L, in + n, L->madh, L->aj0 - 1, L->aj1 + 1, hy);
    for (j = L->aj0; j <= L->aj1; j++) {
        const int k = j * mx + i0;
        const double *xs = hx + (size_t)j * w + 1 + i0, *ys = hy + (size_t)j * w + 1 + i0;
        tang_stencil_row(nb, st, xs, xs + w, xs + 2 * w, ys, ys + w, ys + 2 * w, L->madh + k,
                         in + k, in + n + k, out + k, out + n + k);
    }
}

/* The Jacobian's coefficients for the states of the last residual, which
 * hold through a GMRES solve: J v = v - f (e - n (n.e)), e = v - rho M v,
 * with (f, n) = (1, 0) in adhesion (J v = rho M v), (g/|z|, z/|z|) in slip,
 * (0, 0) outside (v is 0 there); pcf: f where the upstream neighbour is in
 * contact, else 0 (precondition); madh: 1 in adhesion, else 0. */
static void newton_coeffs(layout *L)
{
    const int n = L->n, mx = L->mx;
    int k;
    for (k = 0; k < n; k++) {
        const int st = L->state[k];
        L->jf[k] = st == ADHESION ? 1.0 : st == SLIP ? L->fac[k] : 0.0;
        L->jn[k] = st == SLIP ? L->nz[k] : 0.0;
        L->jn[k + n] = st == SLIP ? L->nz[k + n] : 0.0;
        L->madh[k] = st == ADHESION;
    }
    L->ai0 = mx;
    L->ai1 = -1;
    L->aj0 = L->my;
    L->aj1 = -1;
    for (k = 0; k < n; k++) {
        const int i = k % mx, j = k / mx;
        L->pcf[k] = i + 1 < mx && L->state[k + 1] != OUTSIDE ? L->jf[k] : 0.0;
        if (L->state[k] == ADHESION) {
            L->ai0 = i < L->ai0 ? i : L->ai0;
            L->ai1 = i > L->ai1 ? i : L->ai1;
            L->aj0 = j < L->aj0 ? j : L->aj0;
            L->aj1 = j > L->aj1 ? j : L->aj1;
        }
    }
}

/* out = J v, J = I - D (I - rho M) on C, given Mv = G M v (a product
 * not yet divided by G) and rg = rho / G */
static void jacobian(const layout *L, double rg, const double *restrict v,
                     const double *restrict Mv, double *restrict out)
{
    const int n = L->n;
    const double *restrict jf = L->jf, *restrict jnx = L->jn, *restrict jny = L->jn + n;
    int k;
    for (k = 0; k < n; k++) {
        const double ex = v[k] - rg * Mv[k], ey = v[k + n] - rg * Mv[k + n];
        const double nx = jnx[k], ny = jny[k], dot = nx * ex + ny * ey;
        out[k] = v[k] - jf[k] * (ex - nx * dot);
        out[k + n] = v[k + n] - jf[k] * (ey - ny * dot);
    }
}

/* a.b with four partial sums (independent chains: the loop pipelines and
 * vectorises without reassociating a single sum) */
static double dot2(const double *a, const double *b, int n2)
{
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    int k;
    for (k = 0; k + 4 <= n2; k += 4) {
        s0 += a[k] * b[k];
        s1 += a[k + 1] * b[k + 1];
        s2 += a[k + 2] * b[k + 2];
        s3 += a[k + 3] * b[k + 3];
    }
    for (; k < n2; k++)
        s0 += a[k] * b[k];
    return (s0 + s1) + (s2 + s3);
}

/* w += a x, then w . y, or w . w where y is NULL (four partial sums, as
 * dot2) */
static double axpy_dot(double *restrict w, double a, const double *restrict x,
                       const double *restrict y, int n2)
{
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    int k;
    if (y) {
        for (k = 0; k + 4 <= n2; k += 4) {
            const double w0 = w[k] + a * x[k], w1 = w[k + 1] + a * x[k + 1];
            const double w2 = w[k + 2] + a * x[k + 2], w3 = w[k + 3] + a * x[k + 3];
            w[k] = w0;
            w[k + 1] = w1;
            w[k + 2] = w2;
            w[k + 3] = w3;
            s0 += w0 * y[k];
            s1 += w1 * y[k + 1];
            s2 += w2 * y[k + 2];
            s3 += w3 * y[k + 3];
        }
    } else {
        for (k = 0; k + 4 <= n2; k += 4) {
            const double w0 = w[k] + a * x[k], w1 = w[k + 1] + a * x[k + 1];
            const double w2 = w[k + 2] + a * x[k + 2], w3 = w[k + 3] + a * x[k + 3];
            w[k] = w0;
            w[k + 1] = w1;
            w[k + 2] = w2;
            w[k + 3] = w3;
            s0 += w0 * w0;
            s1 += w1 * w1;
            s2 += w2 * w2;
            s3 += w3 * w3;
        }
    }
    for (; k < n2; k++) {
        w[k] += a * x[k];
        s0 += w[k] * (y ? y[k] : w[k]);
    }
    return (s0 + s1) + (s2 + s3);
}

static void scale_by(double *v, double a, int n2)
{
    int k;
    for (k = 0; k < n2; k++)
        v[k] *= a;
}

/* F = p - Proj_g(p - rho s) on C; also the states and the projection's
 * derivative data (unit z and g/|z| of slipping elements).  Returns ||F||. */
static double residual(layout *L, double rho, const double *p, const double *s, double *F)
{
    const int n = L->n;
    double f2 = 0.0;
    int k;
    for (k = 0; k < n; k++) {
        double zx, zy, z, g;
        if (L->state[k] == OUTSIDE) {
            F[k] = F[k + n] = 0.0;
            continue;
        }
        g = L->fac[k + n];               /* the traction bound, kept in fac's upper half */
        zx = p[k] - rho * s[k];
        zy = p[k + n] - rho * s[k + n];
        z = norm2(zx, zy);
        if (z <= g) {
            L->state[k] = ADHESION;
            F[k] = p[k] - zx;
            F[k + n] = p[k + n] - zy;
        } else {
            const double f = g / z;
            L->state[k] = SLIP;
            L->nz[k] = zx / z;
            L->nz[k + n] = zy / z;
            L->fac[k] = f;
            F[k] = p[k] - f * zx;
            F[k + n] = p[k + n] - f * zy;
        }
        f2 += F[k] * F[k] + F[k + n] * F[k + n];
    }
    return sqrt(f2);
}

/* GMRES(m) on J P u = -F (the Newton step), right-preconditioned by P =
 * the inverse upwind difference (precondition), then the stencil on the
 * adhering elements (tang_stencil); on return dlt = P u and mdl = M dlt
 * (kept from the products, no extra one).  Stops at ||F + J P u|| <= eta
 * ||F|| or when the product budget is spent. */
static int gmres(solver *S, double rho, const double *F, double eta, double *dlt, double *mdl)
{
    layout *L = S->L;
    const int n2 = 2 * L->n, m = GMRES_M;
    const double bnorm = sqrt(dot2(F, F, n2)), rg = rho / S->pb->G, ig = 1.0 / S->pb->G;
    double *V = L->V, *MV = L->MV, *H = L->H, *gv = L->gv, *cs = L->cs, *sn = L->sn,
           *y = L->y, *t = L->t1, *q = L->t2;
    const double cst = 0.8 * S->pb->G / rho;
    double beta = bnorm;
    int k, j, i, st;

    memset(dlt, 0, (size_t)n2 * sizeof *dlt);
    memset(mdl, 0, (size_t)n2 * sizeof *mdl);
    if (bnorm == 0.0)
        return RR_OK;
    newton_coeffs(L);
    for (k = 0; k < n2; k++)
        V[k] = -F[k];
    while (S->products < S->pb->maxit) {
        int jm = 0;
        /* V[0] = r / |r| */
        scale_by(V, 1.0 / beta, n2);
        memset(gv, 0, (GMRES_M + 1) * sizeof *gv);
        gv[0] = beta;
        for (j = 0; j < m && S->products < S->pb->maxit; j++) {
            double *w = V + (size_t)(j + 1) * n2, *mvj = MV + (size_t)j * n2, h, hn;
            precondition(L, V + (size_t)j * n2, q);
            tang_stencil(L, cst, q, t);
            /* the products kept times G, divided once at the end */
            if ((st = tang_product_g(S, t, mvj)) < 0)
                return st;
            /* modified Gram-Schmidt, each pass subtracting one basis vector
             * and taking the dot product with the next (the last: |w|^2) */
            jacobian(L, rg, t, mvj, w);
            h = dot2(w, V, n2);
            for (i = 0; i <= j; i++) {
                H[i * m + j] = h;
                h = axpy_dot(w, -h, V + (size_t)i * n2, i < j ? V + (size_t)(i + 1) * n2 : NULL,
                             n2);
            }
            hn = sqrt(h);
            H[(j + 1) * m + j] = hn;
            if (hn > 0.0)
                scale_by(w, 1.0 / hn, n2);
            /* Givens rotations keep H upper triangular and give the residual */
            for (i = 0; i < j; i++) {
                const double a = H[i * m + j], c = H[(i + 1) * m + j];
                H[i * m + j] = cs[i] * a + sn[i] * c;
                H[(i + 1) * m + j] = -sn[i] * a + cs[i] * c;
            }
            {
                const double a = H[j * m + j], c = H[(j + 1) * m + j], rr = hypot(a, c);
                cs[j] = rr > 0.0 ? a / rr : 1.0;
                sn[j] = rr > 0.0 ? c / rr : 0.0;
                H[j * m + j] = rr;
                H[(j + 1) * m + j] = 0.0;
                gv[j + 1] = -sn[j] * gv[j];
                gv[j] = cs[j] * gv[j];
            }
            jm = j + 1;
            if (fabs(gv[j + 1]) <= eta * bnorm || hn == 0.0)
                break;
        }
        /* y = H^-1 g, then dlt += P V y and mdl += (M P V) y (times G) */
        for (i = jm - 1; i >= 0; i--) {
            double sum = gv[i];
            for (k = i + 1; k < jm; k++)
                sum -= H[i * m + k] * y[k];
            y[i] = H[i * m + i] != 0.0 ? sum / H[i * m + i] : 0.0;
        }
        memset(q, 0, (size_t)n2 * sizeof *q);
        for (i = 0; i < jm; i++) {
            const double *vi = V + (size_t)i * n2, *mvi = MV + (size_t)i * n2, yi = y[i];
            for (k = 0; k < n2; k++) {
                q[k] += yi * vi[k];
                mdl[k] += yi * mvi[k];
            }
        }
        precondition(L, q, t);
        tang_stencil(L, cst, t, q);
        for (k = 0; k < n2; k++)
            dlt[k] += q[k];
        beta = fabs(gv[jm]);
        if (jm == 0 || beta <= eta * bnorm)
            break;
        /* restart from the true residual -F - J dlt */
        jacobian(L, rg, dlt, mdl, V);
        for (k = 0; k < n2; k++)
            V[k] = -F[k] - V[k];
        beta = sqrt(dot2(V, V, n2));
        if (beta <= eta * bnorm)
            break;
    }
    scale_by(mdl, ig, n2);
    return RR_OK;
}

/* A start for Newton: FASTSIM's traction on the solver's own grid and
 * bound (Kalker's simplified theory marched from the leading edge, each
 * element clipped to mu pn), with the flexibilities of the ellipse that the
 * contact set spans.  It puts the slip area about right, which saves
 * Newton steps; RR_OK, or RR_ERR_RANGE (no usable ellipse: start from 0). */
static int start_fastsim(const rr_exact_problem *pb, layout *L, const double *w)
{
    const int mx = L->mx, my = L->my, n = L->n;
    const double dx = pb->grid.dx, dy = pb->grid.dy;
    int i, j, imin = mx, imax = -1, jmin = my, jmax = -1;
    double a, b, fl[3];
    rr_kalker_coeffs kc;

    for (j = 0; j < my; j++)
        for (i = 0; i < mx; i++)
            if (L->state[j * mx + i] != OUTSIDE) {
                imin = i < imin ? i : imin;
                imax = i > imax ? i : imax;
                jmin = j < jmin ? j : jmin;
                jmax = j > jmax ? j : jmax;
            }
    if (imax < 0)
        return RR_ERR_RANGE;
    a = 0.5 * (imax - imin + 1) * dx;
    b = 0.5 * (jmax - jmin + 1) * dy;
    if (rr_kalker(a / b, pb->nu, &kc) != RR_OK)
        return RR_ERR_RANGE;
    rr_kalker_flexibilities(a, b, pb->G, &kc, fl);
    for (j = 0; j < my; j++) {
        double qx = 0.0, qy = 0.0;
        for (i = mx - 1; i >= 0; i--) {
            const int k = j * mx + i;
            double g, t;
            if (L->state[k] == OUTSIDE) {
                qx = qy = 0.0;
                L->p[k] = L->p[k + n] = 0.0;
                continue;
            }
            /* the rigid slip split into its creepage and spin parts */
            {
                const double spx = w[k] - pb->cx, spy = w[k + n] - pb->cy;
                qx -= dx * (pb->cx / fl[0] + spx / fl[2]);
                qy -= dx * (pb->cy / fl[1] + spy / fl[2]);
            }
            g = L->fac[k + n];
            t = norm2(qx, qy);
            if (t > g) {
                qx *= g / t;
                qy *= g / t;
            }
            L->p[k] = qx;
            L->p[k + n] = qy;
        }
    }
    if (!rr_all_finite(L->p, 2 * n))
        return RR_ERR_RANGE;
    for (i = 0; i < 2 * n; i++)
        if (L->p[i] != 0.0)
            return RR_OK;
    return RR_ERR_RANGE;      /* no traction (no creepage): the zero start needs no product */
}

static int solve_tangential(solver *S, rr_exact_result *res)
{
    const rr_exact_problem *pb = S->pb;
    layout *L = S->L;
    const int n = L->n, mx = L->mx, n2 = 2 * n;
    /* rho: half the inverse diagonal of the steady operator (of the values
     * tried, 0.2 to 30 times it, the fewest products: 0.5) */
    const double rho = 0.5 * pb->G / steady_diagonal(pb->grid.dy / pb->grid.dx, pb->nu);
    double *p = L->p, *s = L->s, *w = L->w, *F = L->f, *dl = L->dlt, *md = L->mdl, *pt = L->t1,
           *stt = L->t2;
    double g2 = 0.0, nF, nFold = 0.0, eta = 0.3, goal = 0.0;
    int k, st = RR_OK, newton = 0, converged = 0;
    S->products = 0;
    for (k = 0; k < n; k++) {
        const double x = pb->grid.x0 + (k % mx) * pb->grid.dx;
        const double y = pb->grid.y0 + (k / mx) * pb->grid.dy;
        const double xs = x + pb->spin_shift * pb->grid.dx;
        L->state[k] = L->pn[k] > 0.0 ? ADHESION : OUTSIDE;
        L->fac[k + n] = pb->mu * L->pn[k];     /* traction bound */
        g2 += L->fac[k + n] * L->fac[k + n];
        w[k] = L->state[k] != OUTSIDE ? pb->cx - pb->cphi * y : 0.0;
        w[k + n] = L->state[k] != OUTSIDE ? pb->cy + pb->cphi * xs : 0.0;
        p[k] = p[k + n] = 0.0;
        s[k] = w[k];
        s[k + n] = w[k + n];
    }
    g2 = sqrt(g2);
    if (start_fastsim(pb, L, w) == RR_OK) {
        if ((st = tang_product_g(S, p, s)) < 0)
            return st;
        for (k = 0; k < n2; k++)
            s[k] = s[k] / pb->G + w[k];
    } else {
        memset(p, 0, (size_t)n2 * sizeof *p);       /* from zero traction: s = w */
    }
    nF = residual(L, rho, p, s, F);
    while (1) {
        double t = 1.0, nFt = 0.0;
        int ls;
        if (!isfinite(nF))
            return RR_ERR_RANGE;
        /* the tolerance is relative to the traction found, not to the
         * bound: at small creepage p is orders of magnitude below mu pn */
        goal = fmax(pb->tol * sqrt(dot2(p, p, n2)), 1e-15 * g2);
        if (nF <= goal) {
            converged = 1;
            break;
        }
        if (S->products >= pb->maxit)
            break;
        /* Eisenstat-Walker forcing, safeguarded, never finer than the goal */
        if (newton > 0) {
            double e = 0.9 * (nF / nFold) * (nF / nFold);
            if (0.9 * eta * eta > 0.1)
                e = fmax(e, 0.9 * eta * eta);
            eta = fmin(0.3, fmax(e, 1e-3));
        }
        eta = fmax(eta, 0.5 * goal / nF);
        if ((st = gmres(S, rho, F, eta, dl, md)) < 0)
            return st;
        newton++;
        nFold = nF;
        /* backtracking on ||F||: s(p + t dl) = s + t M dl, no product needed */
        for (ls = 0; ls < 30; ls++) {
            for (k = 0; k < n2; k++) {
                pt[k] = p[k] + t * dl[k];
                stt[k] = s[k] + t * md[k];
            }
            nFt = residual(L, rho, pt, stt, F);
            if (nFt <= (1.0 - 1e-4 * t) * nF)
                break;
            t *= 0.5;
        }
        memcpy(p, pt, (size_t)n2 * sizeof *p);
        memcpy(s, stt, (size_t)n2 * sizeof *s);
        if (ls == 30) {
            nF = nFt;
            break;               /* no descent: stalled */
        }
        nF = nFt;
    }
    /* the last iterate onto the traction bound (a change of the order of
     * the tolerance): |p| <= mu pn holds in every element, so |F| <= mu N
     * whatever the status */
    for (k = 0; k < n; k++) {
        const double g = L->fac[k + n], t = norm2(p[k], p[k + n]);
        if (t > g) {
            p[k] *= g / t;
            p[k + n] *= g / t;
        }
    }
    res->tang_products = S->products;
    res->newton_steps = newton;
    {
        const double pnorm = sqrt(dot2(p, p, n2));
        res->tang_residual = pnorm > 0.0 ? nF / pnorm : 0.0;
    }
    return converged ? RR_OK : RR_WARN_NOT_CONVERGED;
}

/* ---- the normal solution of the previous case ------------------------------- */

/* The numbers that decide the normal problem, in key order. */
static void normal_key(const rr_exact_problem *pb, double *k)
{
    k[0] = pb->grid.mx;
    k[1] = pb->grid.my;
    k[2] = pb->grid.dx;
    k[3] = pb->grid.dy;
    k[4] = pb->grid.x0;
    k[5] = pb->grid.y0;
    k[6] = pb->N;
    k[7] = pb->G;
    k[8] = pb->nu;
    k[9] = pb->tol;
    k[10] = pb->maxit;
    k[11] = pb->h ? 1.0 : 0.0;
    k[12] = pb->h ? 0.0 : pb->A;     /* the Hertzian start depends on them */
    k[13] = pb->h ? 0.0 : pb->B;
}
#define NKEY_USED 14

/* A sweep over creepages (a creep curve, a table) repeats the normal
 * problem: where every number of it and every value of h equal the last
 * one's bit for bit, its solution is the one a fresh solve would give
 * (the same operations on the same doubles), so it is reused.  Returns the
 * cached status (pressure in L->pn), or 2 where there is none. */
static int normal_cached(const rr_exact_problem *pb, layout *L, rr_exact_result *res)
{
    double k[NKEY_USED];
    normal_key(pb, k);
    if (L->nkey[0] != NKEY_TAG || memcmp(L->nkey + 1, k, sizeof k) != 0
        || memcmp(L->h_cache, L->h, (size_t)L->n * sizeof(double)) != 0)
        return 2;
    memcpy(L->pn, L->pn_cache, (size_t)L->n * sizeof(double));
    res->delta = L->nkey[1 + NKEY_USED + 1];
    res->normal_residual = L->nkey[1 + NKEY_USED + 2];
    res->normal_products = 0;
    return (int)L->nkey[1 + NKEY_USED];
}

static void normal_keep(const rr_exact_problem *pb, layout *L, const rr_exact_result *res,
                        int st)
{
    normal_key(pb, L->nkey + 1);
    L->nkey[1 + NKEY_USED] = st;
    L->nkey[1 + NKEY_USED + 1] = res->delta;
    L->nkey[1 + NKEY_USED + 2] = res->normal_residual;
    memcpy(L->pn_cache, L->pn, (size_t)L->n * sizeof(double));
    L->nkey[0] = NKEY_TAG;        /* h_cache was kept before the solve */
}

/* ---- the driver ------------------------------------------------------------ */

static void result_nan(rr_exact_result *res)
{
    res->fx = res->fy = res->mz = res->fn = res->delta = res->area = res->pmax = NAN;
    res->normal_residual = res->tang_residual = NAN;
    res->ncontact = res->nslip = 0;
    res->normal_products = res->tang_products = res->newton_steps = 0;
}

static void field_nan(const rr_exact_problem *pb, rr_exact_field *f)
{
    size_t k, n;
    if (!f || !pb || pb->grid.mx < 1 || pb->grid.my < 1 || pb->grid.mx > RR_EXACT_MAX_GRID
        || pb->grid.my > RR_EXACT_MAX_GRID)
        return;
    n = (size_t)pb->grid.mx * (size_t)pb->grid.my;
    for (k = 0; k < n; k++) {
        if (f->pn) f->pn[k] = NAN;
        if (f->px) f->px[k] = NAN;
        if (f->py) f->py[k] = NAN;
        if (f->sx) f->sx[k] = NAN;
        if (f->sy) f->sy[k] = NAN;
        if (f->state) f->state[k] = OUTSIDE;
    }
}

static int check_problem(const rr_exact_problem *pb, size_t work_len)
{
    const rr_exact_grid *g = &pb->grid;
    const double reals[] = {g->dx, g->dy, g->x0, g->y0, pb->N, pb->G, pb->nu, pb->mu,
                            pb->cx, pb->cy, pb->cphi, pb->spin_shift, pb->tol};
    size_t need;

    if (g->mx < 1 || g->my < 1 || g->mx > RR_EXACT_MAX_GRID || g->my > RR_EXACT_MAX_GRID)
        return RR_ERR_GRID;
    if (!rr_all_finite(reals, (int)(sizeof reals / sizeof reals[0])))
        return RR_ERR_NONFINITE;
    if (pb->h) {
        if (!rr_all_finite(pb->h, g->mx * g->my))
            return RR_ERR_NONFINITE;
    } else if (!isfinite(pb->A) || !isfinite(pb->B)) {
        return RR_ERR_NONFINITE;
    }
    if (!(g->dx > 0.0) || !(g->dy > 0.0) || !isnormal(g->dx) || !isnormal(g->dy)
        || !isnormal(g->dx * g->dy) || g->dx / g->dy > 1e6 || g->dy / g->dx > 1e6)
        return RR_ERR_GEOMETRY;
    if (!pb->h && (!(pb->A > 0.0) || !(pb->B > 0.0)))
        return RR_ERR_GEOMETRY;
    if (!(pb->N > 0.0))
        return RR_ERR_LOAD;
    if (!(pb->G > 0.0) || !isnormal(pb->G) || !(pb->nu >= 0.0 && pb->nu <= 0.5))
        return RR_ERR_MATERIAL;
    if (!(pb->mu > 0.0))
        return RR_ERR_FRICTION;
    if (!(pb->tol >= 1e-14 && pb->tol <= 0.1) || pb->maxit < 1
        || !(pb->spin_shift >= -1.0 && pb->spin_shift <= 1.0))
        return RR_ERR_PARAM;
    need = rr_exact_workspace_len(g->mx, g->my);
    if (work_len < need)
        return RR_ERR_WORKSPACE;
    /* the mean pressure and the tractions must be finite doubles */
    {
        const double pmean = pb->N / (g->dx * g->dy) / ((double)g->mx * g->my);
        if (!isnormal(pmean) || !isfinite(pmean * pb->mu * 1e3) || !isfinite(pmean / pb->G)
            || !isnormal(pb->mu * pb->N) || !isnormal(pb->mu * pmean))
            return RR_ERR_RANGE;      /* forces or bounds without a double's digits */
    }
    return RR_OK;
}

int rr_exact_solve(const rr_exact_problem *pb, double *work, size_t work_len,
                   rr_exact_result *res, rr_exact_field *field)
{
    layout L;
    rr_conv2d cv;
    solver S;
    int st, st2, k, n, mx;
    double fx = 0.0, fy = 0.0, mz = 0.0, fn = 0.0, pmax = 0.0, dA;

    if (!res)
        return RR_ERR_NULL;
    if (!pb || !work) {
        result_nan(res);
        field_nan(pb, field);
        return RR_ERR_NULL;
    }
    st = check_problem(pb, work_len);
    if (st < 0) {
        result_nan(res);
        field_nan(pb, field);
        return st;
    }
    result_nan(res);
    mx = pb->grid.mx;
    n = mx * pb->grid.my;
    carve(&L, mx, pb->grid.my, work);
    st = rr_conv2d_init(&cv, mx, pb->grid.my, L.conv, L.conv_len);
    if (st == RR_OK && rr_conv2d_spectrum_len(&cv) > spectrum_len(mx, pb->grid.my))
        st = RR_ERR_WORKSPACE;
    if (st == RR_OK)
        st = build_spectra(&L, &cv, pb->grid.dy / pb->grid.dx, pb->nu, pb->interrupt);
    if (st < 0) {
        field_nan(pb, field);
        return st;
    }
    for (k = 0; k < n; k++) {
        if (pb->h) {
            L.h[k] = pb->h[k];
        } else {
            const double x = pb->grid.x0 + (k % mx) * pb->grid.dx;
            const double y = pb->grid.y0 + (k / mx) * pb->grid.dy;
            L.h[k] = pb->A * x * x + pb->B * y * y;
        }
    }
    if (!rr_all_finite(L.h, n)) {
        result_nan(res);
        field_nan(pb, field);
        return RR_ERR_RANGE;
    }
    S.pb = pb;
    S.L = &L;
    S.cv = &cv;
    S.products = 0;
    st = normal_cached(pb, &L, res);
    if (st == 2) {
        /* a new normal problem: solved, and kept for the next case */
        L.nkey[0] = 0.0;
        memcpy(L.h_cache, L.h, (size_t)n * sizeof(double));
        st = solve_normal(&S, res);
        if (st >= 0)
            normal_keep(pb, &L, res, st);
    }
    if (st >= 0)
        st2 = solve_tangential(&S, res);
    else
        st2 = st;
    if (st < 0 || st2 < 0) {
        result_nan(res);
        field_nan(pb, field);
        return st < 0 ? st : st2;
    }
    dA = pb->grid.dx * pb->grid.dy;
    res->ncontact = res->nslip = 0;
    for (k = 0; k < n; k++) {
        const double x = pb->grid.x0 + (k % mx) * pb->grid.dx;
        const double y = pb->grid.y0 + (k / mx) * pb->grid.dy;
        const double px = L.p[k], py = L.p[k + n];
        int state = L.pn[k] > 0.0 ? L.state[k] : OUTSIDE;
        fx += px;
        fy += py;
        mz += x * py - y * px;
        fn += L.pn[k];
        if (L.pn[k] > pmax)
            pmax = L.pn[k];
        res->ncontact += state != OUTSIDE;
        res->nslip += state == SLIP;
        if (field) {
            if (field->pn) field->pn[k] = L.pn[k];
            if (field->px) field->px[k] = px;
            if (field->py) field->py[k] = py;
            if (field->sx) field->sx[k] = state == SLIP ? L.s[k] : 0.0;
            if (field->sy) field->sy[k] = state == SLIP ? L.s[k + n] : 0.0;
            if (field->state) field->state[k] = (signed char)state;
        }
    }
    res->fx = fx * dA;
    res->fy = fy * dA;
    res->mz = mz * dA;
    res->fn = fn * dA;
    res->pmax = pmax;
    res->area = res->ncontact * dA;
    {
        const double out[] = {res->fx, res->fy, res->mz, res->fn, res->delta, res->area};
        /* the pressure must carry the load: a normal problem whose elastic
         * displacements lie below the rounding of its gap (a load of 1e-300 N
         * on a gap of micrometres: the fuzzer's find) loses it */
        if (!rr_all_finite(out, 6) || res->ncontact < 1
            || !(fabs(res->fn - pb->N) <= 1e-6 * pb->N)) {
            result_nan(res);
            field_nan(pb, field);
            return RR_ERR_RANGE;
        }
    }
    return st != RR_OK ? st : st2;
}
