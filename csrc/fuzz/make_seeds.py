"""Write the seed corpus fuzz/corpus/<target>/ (run from csrc/: python fuzz/make_seeds.py).

The decoder (fuzz.h) reads a selector byte before each double: below 160 a
plausible value, so inputs of such bytes reach the deep paths (a valid case,
a table, a rig that steps); a few mixed inputs start at the edges.  Seeded
random bytes: the corpus is the same on every run.  The regression inputs
(fuzz/regressions/<target>/) are replayed by make fuzz-replay, not copied.
"""
import os
import random

TARGETS = ("fuzz_control", "fuzz_creep", "fuzz_creepage", "fuzz_geometry", "fuzz_hertz",
           "fuzz_kalker", "fuzz_ode", "fuzz_rig", "fuzz_rig_contact", "fuzz_rig_params",
           "fuzz_spline", "fuzz_spline_fit", "fuzz_tables")
HERE = os.path.dirname(os.path.abspath(__file__))


def seeds(rng):
    yield "zeros-64", bytes(64)
    yield "zeros-512", bytes(512)
    for n in (32, 128, 512, 2048):
        for k in range(2):
            yield f"plausible-{n}-{k}", bytes(rng.randrange(160) for _ in range(n))
    for n in (64, 512):
        yield f"mixed-{n}", bytes(rng.randrange(256) for _ in range(n))


def main():
    for t in TARGETS:
        rng = random.Random(t)                # one stream per target: stable names
        d = os.path.join(HERE, "corpus", t)
        os.makedirs(d, exist_ok=True)
        for name, data in seeds(rng):
            with open(os.path.join(d, name), "wb") as f:
                f.write(data)


if __name__ == "__main__":
    main()
