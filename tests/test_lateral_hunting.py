"""rollerrig.hunting: the limit cycle against speed by a ramp down (issue 25,
docs/lateral_dynamics.md), against fresh runs and the linear analysis."""
import numpy as np
import pytest

import rollerrig as rr
from rollerrig._errors import RollerRigError
from rollerrig.analysis.hunting import SUBSTEPS
from rollerrig.rig.result import RECORD_FIELDS

SOFT = {"suspension": {"kx_N_per_m": 2e4, "ky_N_per_m": 2e4}}
SPEEDS = np.arange(106.0, 66.0, -4.0)
IY, IT = RECORD_FIELDS.index("y"), RECORD_FIELDS.index("time")


@pytest.fixture(scope="module")
def ramp():
    return rr.hunting(SPEEDS, SOFT, track=True)


def _run(V, shift, seconds, substeps=SUBSTEPS):
    """The rig on track at speed V from a lateral shift, stepped by hand:
    its records."""
    rig, P, _ = rr.build_rig(SOFT, track=True, roller_speed=V, substeps=substeps)
    y = np.array(rig.y)
    y[1] += shift
    rig.set_state(0.0, y)
    n = round(seconds / P["scenario"]["control_sample_time_s"])
    rec, st = rig.run(np.full(n, V / P["roller"]["radius_m"]), np.full(n, np.nan))
    assert st >= 0
    return rec


def _decay_rate(rec, after=1.0):
    """The slope of log(peaks of y) after `after` s [1/s]."""
    yy, tt = rec[:, IY], rec[:, IT]
    k = np.flatnonzero((yy[1:-1] > yy[:-2]) & (yy[1:-1] >= yy[2:])) + 1
    m = tt[k] > after
    return np.polyfit(tt[k][m], np.log(yy[k][m]), 1)[0]


def test_the_rigs_time_step_gives_the_linear_decay_rate():
    """The rig's integrator, whose Jacobian carries the conicity's
    longitudinal creepage (without it the explicit coupling grew the
    hunting mode at +1.3/s here), against the linearisation at 60 m/s on
    track (-1.26/s): within 10 % at one substep a 4 ms sample (measured
    7.7 %, the approximate Jacobian's first-order error), 5 % at SUBSTEPS
    (3 %)."""
    lin = rr.linearize(SOFT, roller_speed=60.0, track=True).least_damped.eigenvalue.real
    assert _decay_rate(_run(60.0, 1e-6, 4.0, substeps=1)) == pytest.approx(lin, rel=0.1)
    assert _decay_rate(_run(60.0, 1e-6, 4.0)) == pytest.approx(lin, rel=0.05)


def test_the_cycle_above_the_linear_critical_speed_is_the_ramps(ramp):
    """At 90 m/s (above the linear 78.3 m/s) runs of their own from a 0.5 mm
    and a 3 mm shift grow and shrink into the cycle the ramp found there:
    the same amplitude within 2 % after 10 s (the ramp's 3 s a speed leave
    it within 1 %: measured)."""
    i = int(np.flatnonzero(ramp.speeds == 90.0)[0])
    assert ramp.sustained[i]
    for shift in (5e-4, 3e-3):
        rec = _run(90.0, shift, 10.0)
        assert np.max(np.abs(rec[-250:, IY])) == pytest.approx(ramp.amplitude[i], rel=0.02)


def test_hunting_is_supercritical_on_the_cone(ramp):
    """The cycle's amplitude falls toward zero as the speed comes down to
    the linear critical speed, and no cycle survives below it: the
    nonlinear critical speed is the first grid speed above the linear one
    (a supercritical bifurcation: FASTSIM's creep forces damp more as the
    amplitude grows).  A 3 mm shift at 0.95 of the linear critical speed
    dies out."""
    vc = rr.stability([60.0, 100.0], SOFT, track=True).critical_speed
    vnl = ramp.nonlinear_critical_speed
    assert vc < vnl <= vc + 4.0
    a = ramp.amplitude[ramp.sustained]
    assert np.all(np.diff(a) < 0) and a[-1] < 0.5 * a[0]
    rec = _run(0.95 * vc, 3e-3, 6.0)
    assert np.max(np.abs(rec[-250:, IY])) < 0.2 * 3e-3
    assert np.all((ramp.frequency_hz[ramp.sustained] > 5)
                  & (ramp.frequency_hz[ramp.sustained] < 12))


def test_hunting_on_real_profiles():
    """S1002 on UIC60-headed rollers (the rig at 1/5, soft axle boxes): the
    same supercritical picture as on the cone, at the real profiles' far
    higher conicity (linear critical speed 9.83 m/s): no cycle below it, the
    first within one grid step above (10.5 m/s), the amplitude growing with
    speed (0.58 mm at 30 m/s, the flanges untouched), and the smallest
    cycle sways near the linear mode's frequency: 9.74 against 10.24 Hz at
    10.5 m/s (4.9 %; 8 % allowed: S1002's conicity changes within 0.065 mm,
    so even the smallest cycle is not quite linear)."""
    real = {**SOFT, "wheelset": {"profile": "s1002"}, "roller": {"profile": "uic60"}}
    vc = rr.stability(np.linspace(5.0, 30.0, 26), real).critical_speed
    h = rr.hunting(np.arange(30.0, 3.0, -1.5), real)
    assert vc < h.nonlinear_critical_speed <= vc + 1.5
    a = h.amplitude[h.sustained]
    assert np.all(np.diff(a) < 0) and 3e-4 < a[0] < 2e-3
    low = h.speeds[h.sustained][-1]
    f_lin = rr.linearize(real, roller_speed=float(low)).least_damped.frequency_hz
    assert h.frequency_hz[h.sustained][-1] == pytest.approx(f_lin, rel=0.08)


@pytest.mark.parametrize("kw,match", [
    ({"speeds": [50.0, 60.0]}, "decreasing"), ({"speeds": [50.0, -1.0]}, "finite speeds > 0"),
    ({"speeds": []}, "non-empty"), ({"speeds": [60.0, float("nan")]}, "finite"),
    ({"speeds": [60.0, 50.0], "settle": 0.0}, "settle must be"),
    ({"speeds": [60.0, 50.0], "shift": float("nan")}, "shift must be")])
def test_hunting_refuses_bad_input(kw, match):
    with pytest.raises(RollerRigError, match=f"hunting: .*{match}"):
        rr.hunting(**kw)
