"""rig_exact's warm starts (issue 24, item 4): every solve after the first
starts from the last solution (csrc/contact/rr_exact.h rr_exact_solve_from;
csrc/geometry/rr_wheel_exact.c maps it onto a rebuilt grid), so the
solution handed back is the one a cold exact_solve gives on the patch
handed back, with the load and creepages reported, to the solver's
tolerance rather than bit for bit.

The tolerance, and why: tol = 1e-6 (rig_exact's default) bounds the normal
step and the tangential residual relative to the pressure and traction
found, so a warm and a cold solve each stop within a few tol of the
discrete solution: forces to 1e-6 mu N (measured up to 4.3e-7 on these
cases), the pressure to 1e-5 of its peak and the tractions to 1e-5 of
mu pmax (measured 1.3e-6 and 2.7e-6), the contact and slip areas the same
elements.  The C tests (csrc/tests/test_exact.c, run by test_c_core.py)
hold rr_exact_solve_from itself to the cold solve at tol 1e-9, its bad
starts refused.
"""
import functools
import os
import random
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import rollerrig as rr

E, NU = 2.1e11, 0.28


@functools.lru_cache(maxsize=None)
def geometry(pair):
    if pair == "miniprof":
        return rr.RigGeometry.measured_pair()
    return rr.RigGeometry.standard(roller_radius=0.8001)


CASES = [  # pair, y_ws [m], mu, grid: the tread, a two-point zone, the flange root
    ("s1002_uic60", -0.002, 0.3, dict(n=40)),
    ("s1002_uic60", 0.0045, 0.4, dict(n=24)),
    ("s1002_uic60", 0.0055, 0.3, dict(dx=4e-4, dy=4e-4)),
    ("miniprof", 0.0035, 0.5, dict(n=40)),
    ("miniprof", -0.0025, 0.3, dict(dx=4e-4, dy=4e-4)),
]


@pytest.mark.parametrize("pair, y_ws, mu, grid", CASES)
def test_rig_exact_is_a_cold_solve_on_its_patch_to_the_tolerance(pair, y_ws, mu, grid):
    e = rr.rig_exact(geometry(pair), y_ws, Fz=6e4, mu=mu, spin=12.4, roller_spin=5.587,
                     **grid)
    # coarse, loaded, the load's steps (the rebuild only where the approach
    # found moved by over 1 %)
    assert e.passes >= 3
    p, q = e.patch, e.solution
    s = rr.exact_solve(p.h, dx=p.dx, dy=p.dy, x0=p.x0, y0=p.y0, N=e.N, mu=mu,
                       G=E / (2 * (1 + NU)), nu=NU, cx=e.cx, cy=e.cy, cphi=e.cphi)
    muN = mu * e.N
    assert np.hypot(s.fx - q.fx, s.fy - q.fy) < 1e-6 * muN
    assert abs(s.mz - q.mz) < 1e-6 * muN * p.dx
    assert abs(s.fn / q.fn - 1) < 1e-12 and abs(s.delta / q.delta - 1) < 1e-7
    assert np.abs(s.pn - q.pn).max() < 1e-5 * s.pmax
    assert max(np.abs(s.px - q.px).max(), np.abs(s.py - q.py).max()) < 1e-5 * mu * s.pmax
    assert np.array_equal(s.contact, q.contact) and np.array_equal(s.slip, q.slip)
    # and the load it was solved for balances the vertical one (the secant's
    # tolerance: the solver's, 1e-6)
    assert abs(e.force[2] - 6e4) <= 1e-6 * 6e4


def test_kept_workspaces_give_a_fresh_ones_doubles_on_any_thread():
    # the binding keeps rr_wheel_exact's workspaces from call to call
    # (rollerrig/_core_c/batch.c, with the spectra of their last grids):
    # each call takes one to itself, and a case gives the doubles it gives on
    # a fresh workspace whatever ran there before: three threads at once,
    # each after other cases, give the doubles of the serial calls
    runs = [(pair, y_ws, mu, grid) for pair, y_ws, mu, grid in CASES]

    def run(case):
        pair, y_ws, mu, grid = case
        e = rr.rig_exact(geometry(pair), y_ws, Fz=6e4, mu=mu, spin=12.4, roller_spin=5.587,
                         **grid)
        return np.array([e.solution.fx, e.solution.fy, e.solution.mz, e.N])

    first = [run(c) for c in runs]
    # shuffled, so that each workspace meets cases of other grids and of
    # h of other lengths (which carve it otherwise: S1002's flange at 0.4 mm
    # before its tread at n = 24 left the tread's coarse spectra half written
    # over, their key kept, until stop 37)
    order = list(range(len(runs))) * 6
    random.Random(3).shuffle(order)
    with ThreadPoolExecutor(3) as pool:
        again = list(pool.map(run, [runs[k] for k in order]))
    for k, got in zip(order, again):
        np.testing.assert_array_equal(got, first[k])


def test_exact_solve_between_leaves_rig_exact_its_doubles():
    # exact_solve and rig_exact keep their workspaces in pools of their own
    # (their layouts differ: one's scratch could fall on the other's kept
    # spectra and not on their keys)
    pair, y_ws, mu, grid = CASES[1]

    def run():
        e = rr.rig_exact(geometry(pair), y_ws, Fz=6e4, mu=mu, spin=12.4, roller_spin=5.587,
                         **grid)
        return np.array([e.solution.fx, e.solution.fy, e.solution.mz, e.N])

    first = run()
    for m in (48, 72):
        x = (np.arange(m) - (m - 1) / 2) * 5e-4
        h = 0.5 * (x[None, :] ** 2 / 0.46 + x[:, None] ** 2 / 0.3)   # an elliptic gap
        rr.exact_solve(h, dx=5e-4, dy=5e-4, N=6e4, mu=0.3, G=E / (2 * (1 + NU)), nu=NU,
                       cx=1e-3)
        np.testing.assert_array_equal(run(), first)


def test_a_workspace_carved_otherwise_between_leaves_a_case_its_doubles(tmp_path):
    # in a fresh process (no workspace kept yet) every call of this sequence
    # takes the first call's workspace, the largest: the flange on 0.4 mm
    # elements, the tread and the two-point zone (n = 24: h of another
    # length, which carves the workspace otherwise), the flange, the
    # two-point zone again.  Until stop 37 the last call found its coarse
    # spectra written over by the flange's scratch, their key kept: the
    # solve did not converge
    code = (
        "import sys, warnings\n"
        f"sys.path.insert(0, {os.path.dirname(os.path.abspath(__file__))!r})\n"
        "import rollerrig as rr\n"
        "from test_exact_warm import CASES, geometry\n"
        "warnings.simplefilter('error', rr.RollerRigWarning)\n"
        "for i in (2, 0, 1, 2, 1):\n"
        "    pair, y_ws, mu, grid = CASES[i]\n"
        "    e = rr.rig_exact(geometry(pair), y_ws, Fz=6e4, mu=mu, spin=12.4, "
        "roller_spin=5.587, **grid)\n"
        "    print(' '.join(float(v).hex() for v in (e.solution.fx, e.solution.fy, "
        "e.solution.mz, e.N)))\n")
    # (run elsewhere than the checkout: its rollerrig/ has no built core)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=600, cwd=tmp_path)
    assert out.returncode == 0, out.stderr[-2000:]
    runs = out.stdout.split("\n")
    assert runs[4] == runs[2] and runs[3] == runs[0]

