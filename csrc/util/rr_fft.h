/*
 * rr_fft.h - 2-D linear convolutions by FFT, for the influence-coefficient
 * products of the exact contact solver (rr_exact.h).
 *
 * A product u = K * p of a grid of mx x my values with a kernel on the
 * offsets kx in [-(mx-1), mx-1], ky in [-(my-1), my-1] (a two-level Toeplitz
 * matrix) costs O(N^2) directly.  Embedded in an L1 x L2 torus, L1 >= 2 mx -
 * 1 and L2 >= 2 my - 1, it becomes a circular convolution without
 * wrap-around, done by FFT in O(N log N).  The transform is our own:
 * mixed radix 2, 3, 4, 5, self-sorting (Stockham), with each butterfly
 * applied to whole rows at once (contiguous loops that vectorise), split
 * real and imaginary planes.  The zero rows and columns of the padded input
 * and the unused part of the output are never transformed.
 *
 * Real data, complex transforms: a real kernel's product with a real field
 * needs only the real part, so two real fields go through one complex
 * transform (rr_conv2d_apply packs the two halves of one field;
 * rr_conv2d_apply2 packs the x and y components of a traction field and
 * separates their spectra by the symmetry Z(-k) = conj Z(k) of real data).
 *
 * Memory: everything lives in caller workspace (rr_conv2d_workspace_len
 * doubles); the plan (twiddles) is computed by rr_conv2d_init, a kernel's
 * spectrum once by rr_conv2d_spectrum into caller memory, then reused by
 * any number of products.  No allocation, no globals; one rr_conv2d per
 * thread (the products write its scratch planes).
 */
#ifndef RR_FFT_H
#define RR_FFT_H

#include <stddef.h>

/* Largest transform length (torus side). */
#define RR_FFT_MAX_LEN 8192

/* The smallest 2^a 3^b 5^c >= n, or 0 for n < 1 or above RR_FFT_MAX_LEN. */
int rr_fft_good_size(int n);

typedef struct {
    int mx, my;            /* the grid */
    int L1, L2;            /* the torus: L1 along x, L2 along y */
    double *tw1, *tw2;     /* twiddles of the x and y transforms */
    double *re, *im;       /* scratch planes, L1 * L2 each */
    double *re2, *im2;     /* the Stockham passes' other buffer */
} rr_conv2d;

/* Doubles of workspace for an mx x my grid; 0 for sizes outside
 * [1, (RR_FFT_MAX_LEN + 1) / 2]. */
size_t rr_conv2d_workspace_len(int mx, int my);

/* Doubles of one kernel spectrum of an mx x my grid (0 for bad sizes). */
size_t rr_conv2d_spectrum_len(int mx, int my);

/*
 * rr_conv2d_init - the engine for an mx x my grid in work.  Status:
 * RR_OK; RR_ERR_GRID (mx, my outside [1, (RR_FFT_MAX_LEN + 1) / 2]),
 * RR_ERR_WORKSPACE (work_len too small), RR_ERR_NULL.
 */
int rr_conv2d_init(rr_conv2d *cv, int mx, int my, double *work, size_t work_len);

/*
 * rr_conv2d_spectrum - spec (rr_conv2d_spectrum_len doubles) the spectrum
 * of the real kernel kern, given at the offsets as
 * kern[(ky + my - 1) * (2 mx - 1) + (kx + mx - 1)]; the 1/(L1 L2) of the
 * inverse transform is folded in.  Status: RR_OK, RR_ERR_NULL.
 */
int rr_conv2d_spectrum(rr_conv2d *cv, const double *kern, double *spec);

/*
 * rr_conv2d_apply - out(i, j) = sum over (k, l) of K(i - k, j - l) in(k, l)
 * for the grid's mx x my values (element (i, j) at j * mx + i); in and out
 * may be the same array.  Status: RR_OK, RR_ERR_NULL.
 */
int rr_conv2d_apply(rr_conv2d *cv, const double *spec, const double *in, double *out);

/*
 * rr_conv2d_apply2 - the 2 x 2 block product
 *   outx = Kxx * inx + Kxy * iny,   outy = Kyx * inx + Kyy * iny
 * with four real kernels (their spectra; NULL for a zero kernel), one
 * forward and one inverse transform for the pair.  outx, outy may be inx,
 * iny.  Status: RR_OK, RR_ERR_NULL.
 */
int rr_conv2d_apply2(rr_conv2d *cv, const double *sxx, const double *sxy, const double *syx,
                     const double *syy, const double *inx, const double *iny, double *outx,
                     double *outy);

#endif
