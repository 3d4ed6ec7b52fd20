/*
 * rr_fft.h - our own mixed-radix FFT (no outside library), for the 2-D
 * linear convolutions of the exact contact solver (Kalker's theory): the
 * influence-coefficient products u = A * p on an mx x my grid of elements.
 *
 * Why: A is a (block-)Toeplitz operator, so A p is a discrete convolution.
 * The direct sum costs (mx my)^2 per product, by FFT it is
 * O(mx my log(mx my)), and an iterative solver takes 50-200 products per
 * contact case.
 *
 * How.  A field of mx x my values is convolved on an L1 x L2 torus,
 * L1 = rr_conv2d_torus_len(2 mx - 1), L2 = rr_conv2d_torus_len(2 my - 1):
 * large enough that the circular convolution with the kernel wrapped onto
 * the torus is the linear one on the grid.  A 2-D transform is a pass along y
 * and one along x (the inverse: x, then y), each a batch of 1-D Stockham
 * (self-sorting) transforms in which a butterfly combines whole lines of
 * values: the inner loops run over contiguous memory with one set of
 * twiddles (vectorisable), on split real and imaginary planes, with a
 * transpose between the passes.  Radices 2, 3, 4, 5, and 6, 8, 9 so that
 * the lengths of interest take 3 sweeps (60 = 4 5 3, 96 = 4 4 6,
 * 216 = 4 6 9).  Only what is needed is transformed: the y passes take
 * only the grid's mx columns, the forward x pass only its mx nonzero
 * lines, the inverse x pass gives only mx; the first stage of a forward
 * transform skips the zero half of its input, the last stage of an
 * inverse one the unneeded half of its output (both radix 4 when the
 * length allows).  The spectra are kept for ky in [0, L2/2] only (real
 * kernels: S(-k) = conj S(k)), the normalisation folded in: a product
 * does no scaling pass.
 *
 *   rr_conv2d_apply: one real kernel, on half-length transforms: the two
 *     halves of the grid's columns (ix < ceil(mx/2), and the rest) packed
 *     as real and imaginary part of one complex field, transformed along
 *     y, untangled into the y spectra of the real columns (ky <= L2/2
 *     only), then along x; the inverse packs them again.  (Packing the
 *     columns, not the rows, because the y pass comes first.)  Half the
 *     lanes of apply2 in the y passes, half the spectrum in the x passes.
 *   rr_conv2d_apply2: a 2x2 block of real kernels (not necessarily even:
 *     the steady-rolling B(k) = A(k) - A(k + e_x) is not) on the pair
 *     (x, y): z = inx + i iny forward, then in one step the untangling
 *     Px = (Z(k) + conj Z(-k))/2, Py = (Z(k) - conj Z(-k))/(2i) and the
 *     four products: W(k) = C(k) Z(k) + D(k) conj Z(-k) with
 *     C = (Sxx + Syy + i (Syx - Sxy))/2, D = (Sxx - Syy + i (Syx + Sxy))/2;
 *     one inverse: Re = outx, Im = outy.
 *
 * Accuracy: the twiddles are cos/sin of 2 pi j / n reduced to the first
 * octant, each computed directly (no recurrence); a product's error is a
 * few 1e-16 of max |out| (tests: <= 1e-13 against the direct sum).  It
 * is relative to the norms of the operands: apply2 transforms inx and iny
 * as one complex field, so each output carries the rounding of both (a
 * field 1e10 times larger than the other swamps the other's products to
 * about 1e-6 relative).
 * Values beyond about 1e300 / (L1 L2) overflow (RR_ERR_RANGE).
 *
 * Memory: none allocated.  rr_conv2d_init keeps pointers into the caller's
 * workspace (twiddle tables and scratch planes): it must stay alive and
 * untouched while the rr_conv2d is used, and an rr_conv2d with its
 * workspace serves one thread at a time (the products write its scratch).
 * Spectra are caller memory, read-only for the products: one spectrum may
 * serve several rr_conv2d of the same grid size (e.g. one per thread).
 */
#ifndef RR_FFT_H
#define RR_FFT_H

#include <stddef.h>

/* Longest transform rr_fft_good_size gives (and most stages of one). */
#define RR_FFT_MAX_LEN (1 << 20)
#define RR_FFT_MAX_STAGES 24

/* Largest grid side of rr_conv2d (as RR_FASTSIM_MAX_GRID): L <= 8192, so
 * every index fits an int and every workspace length a 32-bit size_t. */
#define RR_CONV2D_MAX_GRID 4096

/*
 * rr_fft_good_size - the smallest n' >= n of the form 2^a 3^b 5^c (the
 * lengths the transforms take); 0 for n < 1 or n > RR_FFT_MAX_LEN.
 */
int rr_fft_good_size(int n);

/*
 * rr_conv2d_torus_len - the torus side rr_conv2d takes for n offsets:
 * the least multiple of 4 of the form 2^a 3^b 5^c that is >= n, or
 * rr_fft_good_size(n) where that is at most 9/10 of it.  Lengths with a
 * factor 4 start and end with the pruned radix-4 stages; 2 x odd and odd
 * ones took 1.2 to 1.5 times as long per point (apply2 at a 45 x 45 grid:
 * 37 us on 96 against 44 on 90; at 63 x 63: 77 on 128 against 109 on
 * 125).  0 for n < 1 or n > RR_FFT_MAX_LEN / 2.
 */
int rr_conv2d_torus_len(int n);

/* One 1-D transform length: the radix of each stage, in order, and the
 * stages' twiddles w_p^k = exp(-2 pi i p k / n_t) (p < n_t / r_t,
 * k = 1 .. r_t - 1, as (re, im) pairs; n_t the length left at stage t). */
typedef struct {
    int n;
    int nstage;
    int radix[RR_FFT_MAX_STAGES];
    int stride[RR_FFT_MAX_STAGES];   /* product of the radices before stage t */
    const double *tw[RR_FFT_MAX_STAGES];
} rr_fft_plan;

/*
 * A 2-D convolution engine for mx x my grids.  Set by rr_conv2d_init; the
 * fields are private (read mx, my, L1, L2 if useful).
 *
 * Fields are row-major with x contiguous: element (ix, iy) at
 * iy * mx + ix.  Products: out(ix, iy) = sum_{jx, jy} K(ix - jx, iy - jy)
 * in(jx, jy), ix < mx, iy < my (linear, not circular, convolution).
 */
typedef struct {
    int mx, my;          /* grid */
    int L1, L2;          /* torus: rr_conv2d_torus_len(2 mx - 1), (2 my - 1) */
    int nh;              /* L2 / 2 + 1: the spectrum's ky in [0, nh) */
    int vmax;            /* longest line of any pass: max(L1, L2) */
    /* forward plans start with radix 4 (or 2) for the input pruning,
     * backward ones end with it for the output pruning, when the length
     * allows */
    rr_fft_plan xf, xb, yf, yb;
    size_t cap;          /* doubles of one component of a plane (>= L1 L2) */
    double *plane[2];    /* two scratch planes: re [0, cap), im [cap, 2 cap) */
    const double *zero;  /* vmax zeros */
    double *tmp;         /* RR_CONV2D_TMP_LINES lines of vmax: partial butterflies */
    unsigned ready;      /* RR_CONV2D_READY once initialised */
} rr_conv2d;

#define RR_CONV2D_READY 0x52524654u
/* scratch lines of the partial butterflies: r in and r out, real and
 * imaginary, for the largest radix (9) */
#define RR_CONV2D_TMP_LINES 36

/*
 * rr_conv2d_workspace_len - doubles of workspace rr_conv2d_init needs for
 * an mx x my grid (twiddles, a zero line, scratch lines, two planes of
 * 2 L1 L2 doubles, alignment slack): about 4 L1 L2.  0 if mx or my is
 * outside [1, RR_CONV2D_MAX_GRID].
 */
size_t rr_conv2d_workspace_len(int mx, int my);

/*
 * rr_conv2d_init - plan the transforms of an mx x my grid.
 *   given:   mx, my in [1, RR_CONV2D_MAX_GRID]; work, work_len doubles
 *            (>= rr_conv2d_workspace_len(mx, my)), kept by pointer
 *   returns: *cv, usable by the functions below
 *   status:  0 OK; RR_ERR_NULL (cv NULL), RR_ERR_GRID (mx or my out of
 *            range), RR_ERR_WORKSPACE (work NULL or too short).  On error
 *            *cv (if not NULL) is marked not initialised.
 */
int rr_conv2d_init(rr_conv2d *cv, int mx, int my, double *work, size_t work_len);

/*
 * rr_conv2d_spectrum_len - doubles of one kernel spectrum: 2 L1 nh
 * (re plane, then im plane, of L1 x nh values); 0 if cv is NULL or not
 * initialised.
 */
size_t rr_conv2d_spectrum_len(const rr_conv2d *cv);

/*
 * rr_conv2d_spectrum - the spectrum of a real kernel, for the products.
 *   given:   kern[(ky + my - 1) * (2 mx - 1) + (kx + mx - 1)], the kernel
 *            at the offsets kx in [-(mx - 1), mx - 1], ky in
 *            [-(my - 1), my - 1]: (2 mx - 1) (2 my - 1) values
 *   returns: spec, rr_conv2d_spectrum_len(cv) doubles of caller memory:
 *            the transform of the kernel wrapped onto the torus, times
 *            1 / (2 L1 L2) (the products' normalisation), ky <= L2 / 2
 *   status:  0 OK; RR_ERR_NULL (cv, kern or spec NULL, cv not
 *            initialised), RR_ERR_NONFINITE (a kernel value NaN or
 *            infinite), RR_ERR_RANGE (the spectrum overflows: values near
 *            DBL_MAX).  On error spec (if not NULL, cv initialised) is NaN.
 *   Costs about one product.  Uses cv's scratch.
 */
int rr_conv2d_spectrum(rr_conv2d *cv, const double *kern, double *spec);

/*
 * rr_conv2d_spectrum_torus - the same from a kernel given on the whole
 * torus: kern[ky L1 + kx], kx in [0, L1), ky in [0, L2), the offset
 * kx (ky) or kx - L1 (ky - L2).  The products read only the offsets of
 * the grid, so either spectrum serves them; this one also holds the
 * kernel's values at the other offsets, where the symbol itself matters
 * (an approximate inverse of the kernel from 1 / spectrum).
 *   given:   kern, L1 L2 values; returns, status and cost as
 *            rr_conv2d_spectrum.
 */
int rr_conv2d_spectrum_torus(rr_conv2d *cv, const double *kern, double *spec);

/*
 * rr_conv2d_apply - out = K * in for one real kernel K (its spectrum spec).
 *   given:   in, out: mx my values each.  in and out may be the same
 *            array (or overlap in any way): in is read in full before out
 *            is written.  Neither may overlap the workspace or spec.
 *   status:  0 OK; RR_ERR_NULL (cv, spec, in or out NULL; cv not
 *            initialised), RR_ERR_NONFINITE (an input NaN or infinite),
 *            RR_ERR_RANGE (a result not finite: inputs, kernel too large,
 *            or spec not a spectrum).  On error out (if not NULL, cv
 *            initialised) is NaN.
 */
int rr_conv2d_apply(rr_conv2d *cv, const double *spec, const double *in, double *out);

/*
 * rr_conv2d_apply2 - a 2x2 block of real kernels on a vector field:
 *     outx = Kxx * inx + Kxy * iny,   outy = Kyx * inx + Kyy * iny.
 *   given:   the four spectra (rr_conv2d_spectrum); any of them may be NULL,
 *            meaning a zero kernel (sxy == syx == NULL takes a cheaper
 *            path; sxy == syx, one array, is fine); inx, iny, outx, outy:
 *            mx my values each.  The inputs are read in full before the
 *            outputs are written: outx, outy may be inx, iny (or overlap
 *            them in any way), but outx and outy must not overlap each
 *            other, nor any of them the workspace or a spectrum.
 *   status:  as rr_conv2d_apply (RR_ERR_NULL: cv or an input or output
 *            NULL).  On error outx and outy (those not NULL) are NaN.
 *   Cost: one forward and one inverse complex transform of the torus (with
 *   the pruning above), about twice rr_conv2d_apply.
 */
int rr_conv2d_apply2(rr_conv2d *cv, const double *sxx, const double *sxy,
                     const double *syx, const double *syy, const double *inx,
                     const double *iny, double *outx, double *outy);

/* Not API: the two builds of the spectra and convolutions on x86-64 with GCC or
 * clang (rr_fft.c says why), the baseline and AVX2, for rr_fft.c's
 * dispatch and for the test that they give the same doubles. */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(RR_PORTABLE)
#define RR_FFT_DISPATCH 1

int rr_conv2d_spectrum_baseline(rr_conv2d *cv, const double *kern, double *spec);
int rr_conv2d_spectrum_torus_baseline(rr_conv2d *cv, const double *kern, double *spec);
int rr_conv2d_apply_baseline(rr_conv2d *cv, const double *spec, const double *in, double *out);
int rr_conv2d_apply2_baseline(rr_conv2d *cv, const double *sxx, const double *sxy,
                              const double *syx, const double *syy, const double *inx,
                              const double *iny, double *outx, double *outy);
int rr_conv2d_spectrum_avx2(rr_conv2d *cv, const double *kern, double *spec);
int rr_conv2d_spectrum_torus_avx2(rr_conv2d *cv, const double *kern, double *spec);
int rr_conv2d_apply_avx2(rr_conv2d *cv, const double *spec, const double *in, double *out);
int rr_conv2d_apply2_avx2(rr_conv2d *cv, const double *sxx, const double *sxy,
                          const double *syx, const double *syy, const double *inx,
                          const double *iny, double *outx, double *outy);
#else
#define RR_FFT_DISPATCH 0
#endif

#endif
