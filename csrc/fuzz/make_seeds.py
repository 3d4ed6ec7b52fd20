"""Write the seed corpus fuzz/corpus/<target>/ (run from csrc/: python fuzz/make_seeds.py).

The decoder (fuzz.h) reads a selector byte before each double: below 160 a
plausible value, so inputs of such bytes reach the deep paths (a valid case,
a table, a rig that steps); a few mixed inputs start at the edges.  Seeded
random bytes: the corpus is the same on every run.  The regression inputs
(fuzz/regressions/<target>/) are replayed by make fuzz-replay, not copied.
"""
import os
import random

TARGETS = ("fuzz_control", "fuzz_creep", "fuzz_creepage", "fuzz_exact", "fuzz_exact_table",
           "fuzz_fft", "fuzz_fmu", "fuzz_gap", "fuzz_geometry", "fuzz_nonhertz", "fuzz_nonhertz_row", "fuzz_hertz", "fuzz_kalker", "fuzz_ode", "fuzz_rig", "fuzz_rig_contact",
           "fuzz_rig_params", "fuzz_spline", "fuzz_spline_fit", "fuzz_tables")
HERE = os.path.dirname(os.path.abspath(__file__))


def seeds(rng):
    yield "zeros-64", bytes(64)
    yield "zeros-512", bytes(512)
    for n in (32, 128, 512, 2048):
        for k in range(2):
            yield f"plausible-{n}-{k}", bytes(rng.randrange(160) for _ in range(n))
    for n in (64, 512):
        yield f"mixed-{n}", bytes(rng.randrange(256) for _ in range(n))


#: fuzz_fft: grids (mx, my) whose tori take the stages random sides seldom reach:
#: radix 8 (32 = 4 8, 64 = 4 8 2), 9 (27 = 9 3, 36 = 4 9, 45 = 9 5), 6 (72 = 4 6 3),
#: single stages (3, 5, 9), a lone row or column, the largest side
FFT_GRIDS = ((16, 5), (32, 2), (14, 23), (18, 3), (23, 18), (36, 4), (2, 3), (5, 40),
             (1, 33), (40, 1), (40, 40))


def fft_grid_seeds(rng):
    """fuzz_fft's decoder: big (one byte, 0 = sides up to 40), mx and my (a
    selector below 224, then four little-endian bytes: side - 1), the
    workspace (2: exact), no misuse (1); then plausible bytes."""
    for mx, my in FFT_GRIDS:
        head = bytes([0, 0]) + (mx - 1).to_bytes(4, "little") + bytes([0]) \
            + (my - 1).to_bytes(4, "little") + bytes([2, 1])
        yield f"grid-{mx}x{my}", head + bytes(rng.randrange(160) for _ in range(1024))


def main():
    for t in TARGETS:
        rng = random.Random(t)                # one stream per target: stable names
        d = os.path.join(HERE, "corpus", t)
        os.makedirs(d, exist_ok=True)
        extra = fft_grid_seeds(random.Random(t + "-grids")) if t == "fuzz_fft" else ()
        for name, data in list(seeds(rng)) + list(extra):
            with open(os.path.join(d, name), "wb") as f:
                f.write(data)


if __name__ == "__main__":
    main()
