"""Method "exact_table" against the exact theory, on the layout of CONTACT's
3220 test cases (5 ellipticities x 4 spin levels x creepage directions and
magnitudes up to 12 times the characteristic creepage).

The reference is the library's own exact theory extrapolated to the
continuum (rr.exact_richardson, 27 and 54 elements across: what the table
holds at its nodes), so the map shows the table's interpolation error; the
scores against CONTACT's own 11 x 11 solutions are printed too (those carry
CONTACT's coarse grid's few per cent).  With an output folder it writes
exact_table_error_map.png: blended FASTSIM (30 x 30, top) and the table
(bottom), |dF|/(mu N) per cell, worst of the five ellipticities.

    pip install . && python examples/exact_table.py [output folder]   # about 2 minutes
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import rollerrig as rr  # noqa: E402
from rollerrig import plot as rp  # noqa: E402
from rollerrig.analysis import reference as ref  # noqa: E402

METHODS = [("exact_table", {}), ("fastsim_blended", dict(nx=30, ny=30)),
           ("fastsim", dict(nx=30, ny=30)), ("polach", {})]


def continuum_cases():
    """CONTACT's 3220 cases with the exact theory at the continuum as the answer."""
    t = ref.exact_cases()
    est, _ = rr.exact_richardson(t.cx, t.cy, t.cphi, a=t.a, b=t.b, N=t.N, mu=t.mu, G=t.G,
                                 nu=t.nu, nx=27)
    muN = t.mu * t.N
    return t._replace(Fx=est.fx / muN, Fy=est.fy / muN, Mz=est.mz / (muN * t.cp),
                      source="CONTACT's 3220 cases; the answers: rollerrig's exact theory, "
                             "Richardson 27/54 across")


def main(outdir=None):
    own = continuum_cases()
    results = {m: ref.score(m, cases=own, **o) for m, o in METHODS}
    print("against the exact theory at the continuum (3220 cases of CONTACT's layout)")
    print(ref.table(list(results.values())))
    print("\nagainst CONTACT's own 11 x 11 solutions")
    print(ref.table([ref.score(m, **o) for m, o in METHODS]))
    if outdir is None:
        return
    os.makedirs(outdir, exist_ok=True)
    pair = [results["fastsim_blended"], results["exact_table"]]
    levels = sorted(set(own.spin.tolist()))
    fig, axes = plt.subplots(2, len(levels), figsize=(11, 8.2), sharex=True, sharey=True,
                             constrained_layout=True)
    for row, r in zip(axes, pair):
        rp.error_map(r, ax=row, colorbar=False)
        row[0].set_ylabel(f"{r.method}\ncreepage magnitude (normalised)")
        fig.colorbar(row[0].collections[0], ax=row, shrink=0.9,
                     label=f"{r.method}: |dF| / (mu N)")
    for axi in axes[0]:
        axi.set_xlabel("")
    fig.suptitle("Blended FASTSIM 30 x 30 (top) and the exact-theory table (bottom) against "
                 "the exact theory at the continuum:\nCONTACT's 3220-case layout, one panel "
                 "per spin level, worst of the 5 ellipticities (note the two colour scales)",
                 fontsize=10)
    path = os.path.join(outdir, "exact_table_error_map.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print("wrote", path)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else None)
