/*
 * test_fft.c - the FFT convolutions (rr_fft.h) against the direct sums they
 * replace, on grids whose tori need every radix (2, 3, 4, 5), with
 * non-symmetric kernels; bad input.  Tolerance: 1e-13 of the largest
 * output, round-off of a few dozen operations per value.
 */
#include <stdlib.h>
#include <string.h>
#include "tests/rr_test.h"
#include "util/rr_fft.h"

static double urand(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return ((*s >> 8) & 0xffff) / 32768.0 - 1.0;
}

static void direct(int mx, int my, const double *K, const double *in, double *out)
{
    const int kw = 2 * mx - 1;
    int i, j, a, b;
    for (j = 0; j < my; j++)
        for (i = 0; i < mx; i++) {
            double s = 0.0;
            for (b = 0; b < my; b++)
                for (a = 0; a < mx; a++)
                    s += K[(j - b + my - 1) * kw + (i - a + mx - 1)] * in[b * mx + a];
            out[j * mx + i] = s;
        }
}

static double maxabs(const double *v, int n)
{
    double m = 0.0;
    int k;
    for (k = 0; k < n; k++)
        if (fabs(v[k]) > m)
            m = fabs(v[k]);
    return m;
}

static void test_grid(int mx, int my, unsigned seed)
{
    const int nk = (2 * mx - 1) * (2 * my - 1), n = mx * my;
    const size_t wl = rr_conv2d_workspace_len(mx, my), sl = rr_conv2d_spectrum_len(mx, my);
    double *work = malloc(wl * sizeof *work), *spec = malloc(4 * sl * sizeof *spec);
    double *K = malloc(4 * (size_t)nk * sizeof *K), *in = malloc(2 * (size_t)n * sizeof *in);
    double *out = malloc(2 * (size_t)n * sizeof *out), *ref = malloc(2 * (size_t)n * sizeof *ref);
    double *tmp = malloc((size_t)n * sizeof *tmp);
    rr_conv2d cv;
    int k, c;
    unsigned s = seed;
    for (k = 0; k < 4 * nk; k++)
        K[k] = urand(&s);
    for (k = 0; k < 2 * n; k++)
        in[k] = urand(&s);
    CHECK_STATUS(rr_conv2d_init(&cv, mx, my, work, wl), RR_OK, "init");
    for (c = 0; c < 4; c++)
        CHECK_STATUS(rr_conv2d_spectrum(&cv, K + (size_t)c * nk, spec + (size_t)c * sl), RR_OK,
                     "spectrum");
    /* scalar */
    CHECK_STATUS(rr_conv2d_apply(&cv, spec, in, out), RR_OK, "apply");
    direct(mx, my, K, in, ref);
    for (k = 0; k < n; k++)
        CHECK_CLOSE(out[k], ref[k], 1e-13 * maxabs(ref, n), 0.0, "apply against direct sum");
    /* in place */
    memcpy(tmp, in, (size_t)n * sizeof *tmp);
    rr_conv2d_apply(&cv, spec, tmp, tmp);
    for (k = 0; k < n; k++)
        CHECK_CLOSE(tmp[k], ref[k], 1e-13 * maxabs(ref, n), 0.0, "apply in place");
    /* 2 x 2 block: xx, xy, yx, yy all different */
    CHECK_STATUS(rr_conv2d_apply2(&cv, spec, spec + sl, spec + 2 * sl, spec + 3 * sl, in,
                                  in + n, out, out + n), RR_OK, "apply2");
    direct(mx, my, K, in, ref);
    direct(mx, my, K + nk, in + n, tmp);
    for (k = 0; k < n; k++)
        ref[k] += tmp[k];
    direct(mx, my, K + 2 * (size_t)nk, in, ref + n);
    direct(mx, my, K + 3 * (size_t)nk, in + n, tmp);
    for (k = 0; k < n; k++)
        ref[n + k] += tmp[k];
    for (k = 0; k < 2 * n; k++)
        CHECK_CLOSE(out[k], ref[k], 1e-13 * maxabs(ref, 2 * n), 0.0, "apply2 against direct");
    /* NULL spectra are zero kernels */
    rr_conv2d_apply2(&cv, spec, NULL, NULL, spec + 3 * sl, in, in + n, out, out + n);
    direct(mx, my, K, in, ref);
    direct(mx, my, K + 3 * (size_t)nk, in + n, ref + n);
    for (k = 0; k < 2 * n; k++)
        CHECK_CLOSE(out[k], ref[k], 1e-13 * maxabs(ref, 2 * n), 0.0, "apply2 diagonal");
    free(work); free(spec); free(K); free(in); free(out); free(ref); free(tmp);
}

static void test_bad(void)
{
    double w[64];
    rr_conv2d cv;
    CHECK(rr_fft_good_size(1) == 1 && rr_fft_good_size(7) == 8 && rr_fft_good_size(11) == 12
          && rr_fft_good_size(61) == 64 && rr_fft_good_size(97) == 100
          && rr_fft_good_size(0) == 0 && rr_fft_good_size(RR_FFT_MAX_LEN + 1) == 0,
          "good sizes");
    CHECK(rr_conv2d_workspace_len(0, 3) == 0 && rr_conv2d_workspace_len(3, 100000) == 0,
          "bad sizes have no workspace");
    CHECK_STATUS(rr_conv2d_init(&cv, 0, 3, w, 64), RR_ERR_GRID, "mx 0");
    CHECK_STATUS(rr_conv2d_init(&cv, 3, 3, w, 10), RR_ERR_WORKSPACE, "small workspace");
    CHECK_STATUS(rr_conv2d_init(&cv, 3, 3, NULL, 64), RR_ERR_NULL, "NULL work");
    CHECK_STATUS(rr_conv2d_init(NULL, 3, 3, w, 64), RR_ERR_NULL, "NULL cv");
    CHECK_STATUS(rr_conv2d_apply(&cv, NULL, w, w), RR_ERR_NULL, "NULL spectrum");
}

int main(void)
{
    const int grids[][2] = {{1, 1}, {1, 6}, {5, 1}, {2, 2}, {7, 5}, {13, 29}, {30, 30},
                            {31, 31}, {23, 8}};
    size_t t;
    for (t = 0; t < sizeof grids / sizeof grids[0]; t++)
        test_grid(grids[t][0], grids[t][1], 17u + (unsigned)t);
    test_bad();
    return rr_test_summary();
}
