/* rr_fft_avx2.c - rr_fft_conv.c's convolutions built for AVX2 (x86-64, GCC or
 * clang; see there); elsewhere this unit is empty. */
#define RR_FFT_ISA_COPY
#include "util/rr_fft_conv.c"

typedef int rr_fft_avx2_unit;   /* ISO C wants a declaration in every unit */
