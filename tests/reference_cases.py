"""Reference cases from tests/data, decoded into SI, for the tests and benchmarks.

Every CSV in tests/data starts with a ``#`` line naming its source and units;
CONTACT prints lengths in mm, stresses in N/mm^2 and spin in rad/mm, which
are converted to SI here.

The main entry point is :func:`score_methods`, which runs the 3220 cases of
CONTACT's ``test_table`` (contact_test_table_mx11.csv) through
``rollerrig.creep_forces`` and returns the error statistics per method; the
benchmark scripts can import it as well::

    import sys; sys.path.insert(0, "tests")
    from reference_cases import score_methods, format_scores
    print(format_scores(score_methods()))
"""
import csv
import os
import re

import numpy as np

import rollerrig as rr

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


# --------------------------------------------------------------------------
# CONTACT's test_table (contact_test_table_mx11.csv)
# --------------------------------------------------------------------------

#: Settings of CONTACT's src/test_table.f90, as given in the CSV header.
TABLE_G = 82000.0 * N_PER_MM2   # Pa
TABLE_FN = 82000.0              # N
TABLE_MU = 0.3
TABLE_NU = 0.28

TABLE_METHODS = ("linear", "fastsim", "fastsim_blended", "modified_fastsim", "polach")


def _table_header_params(comment):
    """{a/b: (rho [mm], cp [mm])} from the header line of the test table."""
    found = re.findall(r"a/b=\s*([0-9.]+):\s*rho=\s*([0-9.]+)\s*,\s*cp=\s*([0-9.]+)", comment)
    params = {float(aob): (float(rho), float(cp)) for aob, rho, cp in found}
    assert len(params) == 5, f"could not read rho, cp per a/b from the header: {found}"
    return params


def load_test_table():
    """The 3220 cases decoded as the CSV header describes, in SI.

    Returns a dict of 1-D arrays: cx, cy [-], cphi [rad/m], a, b [m] and the
    reference Fx, Fy (= FX/(mu FN), FY/(mu FN)), Mz (= MZ/(mu FN cp)), and
    scalars N, mu, G, nu.
    cksi = mgn mu cos(ang) cp/rho, ceta = mgn mu sin(ang) cp/rho (cp/rho
    dimensionless), cphi = mu spin/rho per mm (times 1000 per m).
    """
    comment, rows = read_csv("contact_test_table_mx11.csv")
    params = _table_header_params(comment)
    col = {k: np.array([float(r[k]) for r in rows])
           for k in ("a_over_b", "aa_mm", "spin_norm", "creep_angle_rad", "creep_mgn",
                     "Fx", "Fy", "Mz")}
    aob = col["a_over_b"]
    rho = np.array([params[v][0] for v in aob])       # mm
    cp = np.array([params[v][1] for v in aob])        # mm
    mu = TABLE_MU
    mgn, ang = col["creep_mgn"], col["creep_angle_rad"]
    return dict(
        cx=mgn * mu * np.cos(ang) * cp / rho,
        cy=mgn * mu * np.sin(ang) * cp / rho,
        cphi=mu * col["spin_norm"] / rho / MM,           # rad/mm -> rad/m
        a=col["aa_mm"] * MM,
        b=col["aa_mm"] / aob * MM,
        Fx=col["Fx"], Fy=col["Fy"], Mz=col["Mz"],
        N=TABLE_FN, mu=mu, G=TABLE_G, nu=TABLE_NU,
    )


def table_errors(method, table=None, nx=30, ny=30, grid="rect", bound="parabolic", **opts):
    """Per-case error hypot(dFx, dFy)/(mu N) of one method against the table."""
    t = load_test_table() if table is None else table
    f = rr.creep_forces(t["cx"], t["cy"], t["cphi"], a=t["a"], b=t["b"], N=t["N"], mu=t["mu"],
                        G=t["G"], nu=t["nu"], method=method, nx=nx, ny=ny, grid=grid,
                        bound=bound, errors="raise", **opts)
    scale = t["mu"] * t["N"]
    return np.hypot(f.fx / scale - t["Fx"], f.fy / scale - t["Fy"])


def score_methods(methods=TABLE_METHODS, nx=30, ny=30, grid="rect", bound="parabolic"):
    """{method: {"median", "p95", "max": float, "n": int}} over the 3220 cases."""
    table = load_test_table()
    scores = {}
    for method in methods:
        err = table_errors(method, table, nx=nx, ny=ny, grid=grid, bound=bound)
        scores[method] = dict(median=float(np.median(err)), p95=float(np.percentile(err, 95)),
                              max=float(np.max(err)), n=int(err.size))
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
