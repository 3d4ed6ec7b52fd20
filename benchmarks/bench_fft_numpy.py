"""numpy.fft on the tori of benchmarks/bench_fft.c, for a side-by-side ratio.

For each grid side m (default 11, 29, 47, 101) the torus is L x L with
L = the smallest 2^a 3^b 5^c >= 2m - 1 (rr_fft_good_size), and the time is
numpy.fft.fft2 + numpy.fft.ifft2 of one complex L x L field (pocketfft;
what an apply2 costs done with numpy, without the pointwise products),
plus, for apply, rfft2 + irfft2 of a real one.  Median over REPEATS
batches of at least 2 ms each, in us per call, one line of JSON per size:

    python benchmarks/bench_fft_numpy.py [--repeats R] [m ...]
"""
import argparse
import json
import time

import numpy as np


def good_size(n):
    best = None
    p5 = 1
    while p5 < 2 * n:
        p35 = p5
        while p35 < 2 * n:
            v = p35
            while v < n:
                v *= 2
            best = v if best is None else min(best, v)
            p35 *= 3
        p5 *= 5
    return best


def median_time(fn, repeats, min_s=2e-3):
    calls = 1
    while True:
        t0 = time.perf_counter()
        for _ in range(calls):
            fn()
        dt = time.perf_counter() - t0
        if dt >= min_s:
            break
        calls = int(calls * 1.2 * min_s / dt) + 1 if dt > 0 else calls * 10
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(calls):
            fn()
        times.append((time.perf_counter() - t0) / calls)
    times.sort()
    return times[len(times) // 2]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=21)
    ap.add_argument("sizes", type=int, nargs="*", default=[11, 29, 47, 101])
    args = ap.parse_args()
    rng = np.random.default_rng(1)
    for m in args.sizes:
        L = good_size(2 * m - 1)
        z = rng.uniform(-1, 1, (L, L)) + 1j * rng.uniform(-1, 1, (L, L))
        r = rng.uniform(-1, 1, (L, L))
        c2 = median_time(lambda: np.fft.ifft2(np.fft.fft2(z)), args.repeats)
        r2 = median_time(lambda: np.fft.irfft2(np.fft.rfft2(r), s=(L, L)), args.repeats)
        print(json.dumps({"mx": m, "my": m, "L1": L, "L2": L, "numpy": np.__version__,
                          "fft2_ifft2_us": round(c2 * 1e6, 3),
                          "rfft2_irfft2_us": round(r2 * 1e6, 3)}), flush=True)


if __name__ == "__main__":
    main()
