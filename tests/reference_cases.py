"""Reference cases from tests/data, decoded into SI, for the tests and benchmarks.

Every CSV in tests/data starts with a ``#`` line naming its source and units;
CONTACT prints lengths in mm, stresses in N/mm^2 and spin in rad/mm, which
are converted to SI here.

The main entry point is :func:`score_methods`, which runs the 3220 cases of
CONTACT's ``test_table`` (contact_test_table_mx11.csv) through
``rollerrig.creep_forces`` (through ``rollerrig.analysis.reference``, which decodes and
scores the table) and returns the error statistics per method; the
benchmark scripts can import it as well::

    import sys; sys.path.insert(0, "tests")
    from reference_cases import score_methods, format_scores
    print(format_scores(score_methods()))
"""
import csv
import os

import numpy as np

import rollerrig as rr
from rollerrig.analysis import reference

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")

MM = 1e-3          # m per mm
N_PER_MM2 = 1e6    # Pa per N/mm^2


def data_path(name):
    return os.path.join(DATA, name)


def read_csv(name):
    """(comment line without '#', list of row dicts) of a tests/data CSV."""
    with open(data_path(name), newline="") as f:
        comment = f.readline()
        assert comment.startswith("#"), f"{name}: first line should be a # comment"
        rows = list(csv.DictReader(f))
    return comment[1:].strip(), rows


def read_columns(name):
    """{column: array} of a tests/data CSV, every # comment line skipped
    (numbers as float64, other columns as strings)."""
    with open(data_path(name), newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    out = {}
    for k in rows[0]:
        try:
            out[k] = np.array([float(r[k]) for r in rows])
        except ValueError:
            out[k] = np.array([r[k] for r in rows])
    return out


# --------------------------------------------------------------------------
# CONTACT's test_table (contact_test_table_mx11.csv): decoded and scored by
# rollerrig.analysis.reference, which ships a byte-identical copy of the CSV
# --------------------------------------------------------------------------

#: Settings of CONTACT's src/test_table.f90, as given in the CSV header.
TABLE_G = 82000.0 * N_PER_MM2   # Pa
TABLE_FN = 82000.0              # N
TABLE_MU = 0.3
TABLE_NU = 0.28

TABLE_METHODS = ("linear", "fastsim", "fastsim_blended", "modified_fastsim", "polach")

_table_header_params = reference._table_header_params


def load_test_table():
    """The 3220 cases decoded as the CSV header describes, in SI.

    Returns a dict of 1-D arrays: cx, cy [-], cphi [rad/m], a, b [m] and the
    reference Fx, Fy (= FX/(mu FN), FY/(mu FN)), Mz (= MZ/(mu FN cp)), and
    scalars N, mu, G, nu: rollerrig.analysis.reference.exact_cases() (its docstring
    gives the decoding) as a dict.
    """
    t = reference.exact_cases()
    return {k: getattr(t, k) for k in ("cx", "cy", "cphi", "a", "b", "Fx", "Fy", "Mz",
                                       "N", "mu", "G", "nu")}


def _grid(method, **grid):
    """The grid options the method has (the registry refuses the others)."""
    return {k: v for k, v in grid.items() if k in rr.METHODS[method].options}


def table_errors(method, table=None, nx=30, ny=30, grid="rect", bound="parabolic", **opts):
    """Per-case error hypot(dFx, dFy)/(mu N) of one method against the table
    (rollerrig.analysis.reference.score(...).error); table: unused, kept for callers."""
    return reference.score(method, **_grid(method, nx=nx, ny=ny, grid=grid, bound=bound),
                           **opts).error


def score_methods(methods=TABLE_METHODS, nx=30, ny=30, grid="rect", bound="parabolic"):
    """{method: {"median", "p95", "max": float, "n": int}} over the 3220 cases."""
    scores = {}
    for method in methods:
        s = reference.score(method, **_grid(method, nx=nx, ny=ny, grid=grid,
                                            bound=bound)).overall
        scores[method] = {k: s[k] for k in ("median", "p95", "max", "n")}
    return scores


def format_scores(scores):
    """A small text table of score_methods() output."""
    lines = [f"{'method':<18}{'median':>10}{'p95':>10}{'max':>10}{'n':>7}"]
    for method, s in scores.items():
        lines.append(f"{method:<18}{s['median']:>10.4f}{s['p95']:>10.4f}{s['max']:>10.4f}"
                     f"{s['n']:>7d}")
    return "\n".join(lines)


if __name__ == "__main__":
    print(format_scores(score_methods()))
