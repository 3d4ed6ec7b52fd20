"""The fast non-Hertzian contact over the whole lateral range of both pairs
(issue 24's sweep check): the table a user builds (rr.nonhertz_table from
-8 to +8 mm, rows 0.2 mm apart and 0.05 mm near the rigid contact point's
jumps, Fz 61.2 kN), both wheels at -7.9 to +7.9 mm every 0.2 mm (half-way
between two rows: the rows' blend at its worst), against the library's
exact solver rr.rig_exact on each state.

The states.  The rig's rolling speed (rollers 5.587 rad/s), Fz 61.163 kN,
mu 0.52; the wheelset's spin set for a longitudinal creepage of 0.05, 0.2,
0.6 and 2 % at the rigid contact point (the last saturates: |F| = mu N
within 1e-3 on the treads), and one with 0.1 % and 1 cm/s of lateral slip.
Spin creepage comes with the contact angle (up to 1.2 rad on the flanges).

The reference and its tolerance, as tests/test_nonhertz_fast.py: rig_exact
on 80 elements across (its default 40 is itself 0.01 to 0.02 mu N from the
continuum the table aims at).  The goal of issue 24 is the tolerance:
|dF| / (mu N) of the wheel's total force (normal force included) p95 <=
0.02, max <= 0.05.  Measured (2026-12-06, 800 states a pair): the measured
pair 0.0091 / 0.0162, S1002 on UIC60 0.0146 / 0.0471 (-5.3 mm, right wheel,
with lateral slip); the single Hertz ellipse at the rigid contact point
0.11 / 0.16 and 0.22 / 0.63 on the same states.  Until the rows took the
wheelset's rates at its own shift (rr_rig_kinematics_rates_at), S1002's
wheel opposite a flank in contact (+-6.25 to +-6.35 mm, where the other
wheel's contact jumps between two rows) was 0.2 to 0.37 mu N off with
lateral slip.
"""
import functools

import numpy as np
import pytest

import rollerrig as rr

pytestmark = pytest.mark.slow

FZ, MU, ROLLER_SPIN = 61163.0, 0.52, 5.587302
STATES = ((5e-4, 0.0), (2e-3, 0.0), (6e-3, 0.0), (2e-2, 0.0), (1e-3, 0.01))  # (cx, vy)
N_REF = 80
SHIFTS = 80           # -7.9 to +7.9 mm, 0.2 mm apart


@functools.lru_cache(maxsize=None)
def pair(name):
    """(geometry, contact table, nonhertz table) of a pair."""
    g = (rr.RigGeometry.measured_pair() if name == "miniprof"
         else rr.RigGeometry.standard(roller_radius=0.8001))
    ct = rr.contact_table(g, -0.0085, 0.0085, 341)
    nh = rr.nonhertz_table(g, -8e-3, 8e-3, Fz=FZ, mu_ref=MU, workers=2)
    return g, ct, nh


@functools.lru_cache(maxsize=None)
def sweep(name):
    """Per state (y, left, cx target, vy): |dF| / (mu N) of nonhertz and of
    Hertz (FASTSIM), and N's and the contact area's relative differences,
    against rig_exact; NaN in the nonhertz columns where it failed.  The
    states rig_exact does not solve apart: the fast method's status there."""
    g, ct, nh = pair(name)
    rows, unsolved = [], []
    for y in np.linspace(-7.9e-3, 7.9e-3, SHIFTS):
        w = rr.wheelset_contact(g, y)
        for side in ("left", "right"):
            p = getattr(w, side)
            for target, vy in STATES:
                spin = ROLLER_SPIN * float(p.R[0]) / float(p.r[0]) * (1 - target)
                kw = dict(y=y, vy=vy, spin=spin, roller_spin=ROLLER_SPIN, mu=MU, Fz_left=FZ,
                          Fz_right=FZ)
                f = getattr(rr.rig_contact(ct, patch="nonhertz", nonhertz=nh,
                                           errors="ignore", **kw), side)
                try:
                    ref = rr.rig_exact(g, y, side=side, Fz=FZ, mu=MU, spin=spin,
                                       roller_spin=ROLLER_SPIN, vy=vy, table=ct, n=N_REF)
                except rr.RollerRigError:
                    unsolved.append(int(f.status))
                    continue
                hz = getattr(rr.rig_contact(ct, **kw), side)
                muN = MU * ref.N
                ok = f.status >= 0
                rows.append((y, side == "left", target, vy,
                             np.linalg.norm(f.force - ref.force) / muN if ok else np.nan,
                             np.linalg.norm(hz.force - ref.force) / muN,
                             abs(f.N / ref.N - 1) if ok else np.nan,
                             abs(f.area / ref.solution.contact_area - 1) if ok else np.nan))
    return np.array(rows), unsolved


@pytest.mark.parametrize("name", ["miniprof", "s1002_uic60"])
def test_the_sweep_against_the_exact_solver(name):
    a, unsolved = sweep(name)
    assert len(a) + len(unsolved) == SHIFTS * 2 * len(STATES)
    # one state has no vertical balance: S1002's left flank at +6.3 mm with
    # 1 cm/s of lateral slip (the creep forces pull the wheel down the
    # flange harder than the load presses it: the flange climbs); the fast
    # method refuses it too, and solves every state the exact one does
    assert len(unsolved) <= 1 and all(st < 0 for st in unsolved)
    assert not np.isnan(a[:, 4]).any()
    err, hertz = a[:, 4], a[:, 5]
    # issue 24's goal (measured above)
    assert np.percentile(err, 95) <= 0.02 and err.max() <= 0.05
    # the measure tells the methods apart: one Hertz ellipse is off by
    # 0.22 / 0.63 (p95 / max, S1002; 0.11 / 0.16 on the measured pair)
    assert np.percentile(hertz, 95) > 0.1 and hertz.max() > 0.12
    # saturated (cx 2 %) the forces are mu N along the slip on both: the
    # measured largest 0.0004 / 0.0088
    sat = a[:, 2] == 2e-2
    assert err[sat].max() < 0.02
    # the normal solution: N within 1 % (p95; measured 0.016 % / 0.32 %),
    # the area within 8 % (p95; measured 2.5 % / 5.1 %: the nodes on their
    # own 40-element grid, rig_exact's on 80)
    assert np.percentile(a[:, 6], 95) < 1e-2
    assert np.percentile(a[:, 7], 95) < 0.08
