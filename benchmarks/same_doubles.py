"""Whether two builds give the same doubles: a refactor's check.

    python benchmarks/same_doubles.py dump OUT.npz      # with one build installed
    python benchmarks/same_doubles.py compare A.npz B.npz

`dump` saves rr.simulate()'s whole history for every method the rig runs
(the paper's 20 s scenario for the default method, 4 s for the others;
fastrip with Coulomb friction, which it needs) and rr.creep_forces' fx, fy,
mz for every method on 2000 seeded cases (100 for "exact", on a 9 x 9
grid), bad elements' NaN included.  `compare` says, per array, whether the
two files hold the same bits; it exits 1 if any differ.
"""
import sys
import warnings

import numpy as np


def dump(path):
    import rollerrig as rr
    out = {}
    for m, info in rr.METHODS.items():
        if not getattr(info, "in_rig", False):
            continue
        params = {"contact": {"friction_law": "coulomb"}} if m == "fastrip" else None
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")      # the 4 s runs' target times scaled
            r = rr.simulate(method=m, duration=20.0 if m == "fastsim" else 4.0,
                            params=params)
        out[f"simulate_{m}"] = r.to_dataframe().to_numpy(dtype=float)
    rng = np.random.default_rng(1)
    n = 2000
    cx, cy = rng.uniform(-5e-3, 5e-3, n), rng.uniform(-5e-3, 5e-3, n)
    cphi = rng.uniform(-1.0, 1.0, n)
    a, b = rng.uniform(2e-3, 1e-2, n), rng.uniform(2e-3, 1e-2, n)
    N = rng.uniform(1e3, 1e5, n)
    for m in rr.METHODS:
        k = slice(0, 100) if m == "exact" else slice(None)
        kw = dict(nx=9, ny=9) if m == "exact" else {}
        f = rr.creep_forces(cx[k], cy[k], cphi[k], a=a[k], b=b[k], N=N[k], mu=0.3,
                            method=m, errors="ignore", **kw)
        out[f"creep_{m}"] = np.stack([np.asarray(getattr(f, q), float)
                                      for q in ("fx", "fy", "mz")])
    np.savez(path, **out)
    print(f"{path}: {len(out)} arrays")


def compare(path_a, path_b):
    a, b = np.load(path_a), np.load(path_b)
    differ = sorted(set(a) ^ set(b))
    for name in differ:
        print(f"{name}: in one file only")
    for name in sorted(set(a) & set(b)):
        x, y = a[name], b[name]
        same = x.shape == y.shape and np.array_equal(x.view(np.uint64), y.view(np.uint64))
        print(f"{name} {x.shape}: {'the same bits' if same else 'DIFFERENT'}")
        differ += [] if same else [name]
    return 1 if differ else 0


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "dump":
        dump(sys.argv[2])
    elif len(sys.argv) == 4 and sys.argv[1] == "compare":
        sys.exit(compare(sys.argv[2], sys.argv[3]))
    else:
        sys.exit(__doc__)
