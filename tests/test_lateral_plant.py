"""The plant's lateral physics (issue 25): the spinning wheelset's gyroscopic
terms and track mode (csrc/rig/rr_rig.h, rr_rig_plant.c;
docs/lateral_dynamics.md)."""
import math
import os
import re

import numpy as np
import pytest

import rollerrig as rr
from rollerrig._errors import RollerRigError
from rollerrig.rig.params import TRACK_RADIUS_M

HERE = os.path.dirname(os.path.abspath(__file__))
X, Y, YAW, CHI, THR, VX, VY, YR, SPIN, RSPIN, TR, TW = range(12)
NO_GYRO = {"wheelset": {"gyroscopic": False}}
RUN = {"targets": [0.02], "target_times": [0.0]}


def _state(rig, y=0.0, vy=0.0, yaw_rate=0.0):
    s = np.array(rig.y)
    s[Y], s[VY], s[YR] = y, vy, yaw_rate
    return s


def test_the_switches_are_declared_with_their_defaults():
    P = rr.default_parameters()
    assert P["wheelset"]["gyroscopic"] is True
    assert P["scenario"]["track"] is False
    # the Python twin of the C constant (a C caller builds its track table
    # with RR_RIG_TRACK_RADIUS)
    with open(os.path.join(HERE, "..", "csrc", "rig", "rr_rig.h")) as fh:
        m = re.search(r"#define RR_RIG_TRACK_RADIUS ([0-9.e+]+)", fh.read())
    assert float(m.group(1)) == TRACK_RADIUS_M


def test_gyroscopic_yaw_moment_is_minus_Iw_spin_roll_rate():
    """The only change the switch makes to the yaw row: Izz d(yaw_rate) =
    -I_w spin roll_rate cos(roll) (at zero yaw), I_w the wheelset's own spin
    inertia (not its drive's), roll_rate the constraint's d roll/dy vy from
    the contact table (an independent evaluation: rig_contact)."""
    on, P, table = rr.build_rig()
    off, *_ = rr.build_rig(NO_GYRO)
    s = _state(on, y=1e-3, vy=0.02, yaw_rate=0.0)
    d_on, st1 = on.rhs(0.0, s)
    d_off, st2 = off.rhs(0.0, s)
    assert st1 == st2 == 0
    pose = rr.rig_contact(table, y=s[Y], vy=s[VY], spin=s[SPIN], roller_spin=s[RSPIN],
                          kinematics_only=True).pose
    Iw, Izz = P["wheelset"]["spin_inertia_kg_m2"], P["wheelset"]["yaw_inertia_kg_m2"]
    roll_rate = float(pose.w[0])          # at zero yaw the roll rate is w's X
    want = -Iw * s[SPIN] * roll_rate * math.cos(float(pose.roll)) / Izz
    assert want != 0.0
    # the yaw row changes by exactly the gyroscopic term (rounding: 1e-9);
    # the lateral and longitudinal rows barely (through the loads' roll
    # balance, which yaw_rate = 0 leaves unchanged)
    assert d_on[YR] - d_off[YR] == pytest.approx(want, rel=1e-9)
    assert d_on[VY] == pytest.approx(d_off[VY], rel=1e-12, abs=1e-12)


def _load_difference(params, yaw_rate):
    rig, P, _ = rr.build_rig(params)
    rig.set_state(0.0, _state(rig, yaw_rate=yaw_rate))
    rec = rig.record()[0]
    names = rr.rig.result.RECORD_FIELDS
    return rec[names.index("normal_load_left")] - rec[names.index("normal_load_right")], P, rig


def test_gyroscopic_roll_moment_transfers_load():
    """A yaw rate makes the contacts carry the roll moment -I_w spin
    yaw_rate: N_left - N_right changes by about that over the contacts'
    half-spacing s.  Within 10 %: the yaw rate's creepage (a yaw_rate / V =
    0.015 here) makes creep forces that scale with the loads and add their
    own roll moment (measured 5 %), the contact angle 0.3 %.  Exactly linear
    in I_w: twice the inertia, twice the change (to 1e-6)."""
    w = 0.5
    on, P, rig = _load_difference(None, w)
    off, *_ = _load_difference(NO_GYRO, w)
    Iw, s_c = P["wheelset"]["spin_inertia_kg_m2"], P["wheelset"]["contact_half_spacing_m"]
    spin = rig.y[SPIN]
    want = -Iw * spin * w / s_c
    assert on - off == pytest.approx(want, rel=0.1)
    twice, *_ = _load_difference({"wheelset": {"spin_inertia_kg_m2": 2 * Iw}}, w)
    assert twice - off == pytest.approx(2 * (on - off), rel=1e-6)
    # and odd in the yaw rate
    neg_on, *_ = _load_difference(None, -w)
    neg_off, *_ = _load_difference(NO_GYRO, -w)
    assert neg_on - neg_off == pytest.approx(-(on - off), rel=1e-6)


def test_gyroscopic_terms_leave_the_paper_scenario_alone():
    """The wheelset runs centred in the paper's braking scenario: the terms
    are products of yaw and roll rates that stay at rounding level (1e-19
    rad/s), so the longitudinal history is the same doubles."""
    a = rr.simulate(duration=1.0, targets=[0.04], target_times=[0.0])
    b = rr.simulate(duration=1.0, targets=[0.04], target_times=[0.0], params=NO_GYRO)
    for f in ("creepage", "fx", "normal_load_left", "spin", "roller_speed"):
        assert np.array_equal(getattr(a, f), getattr(b, f)), f
    assert np.max(np.abs(a.yaw_rate - b.yaw_rate)) < 1e-15


def test_track_holds_the_rails_speed_and_uses_the_track_radius():
    rig, P, table = rr.build_rig(track=True)
    assert P["scenario"]["track"] is True and P["roller"]["radius_m"] == TRACK_RADIUS_M
    s = _state(rig, y=1e-3, vy=0.01, yaw_rate=0.1)
    d, st = rig.rhs(0.0, s)
    assert st == 0 and d[RSPIN] == 0.0 and d[YR] != 0.0
    # the roller's speed (the track's) is V / R
    assert s[RSPIN] * TRACK_RADIUS_M == pytest.approx(5.0, rel=1e-15)
    # the rolling radius of the rail is the track radius (the table's R)
    c = rr.rig_contact(table, spin=s[SPIN], roller_spin=s[RSPIN], kinematics_only=True)
    assert float(c.left.R) == pytest.approx(TRACK_RADIUS_M, rel=1e-6)


def test_track_in_simulate_and_in_a_scenario_file(tmp_path):
    res = rr.simulate(duration=0.2, track=True, **RUN)
    assert res.status >= 0
    # the rails' speed never changes (the rig's roller PI moves nothing)
    assert np.all(res.roller_speed == res.roller_speed[0])
    f = tmp_path / "track.toml"
    f.write_text("[scenario]\ntrack = true\n")
    res2 = rr.simulate(duration=0.2, params=str(f), **RUN)
    assert res2.params["scenario"]["track"] is True
    assert np.array_equal(res.creepage, res2.creepage)
    # track=False overrides the file
    res3 = rr.simulate(duration=0.2, params=str(f), track=False, **RUN)
    assert res3.params["roller"]["radius_m"] == 0.16


@pytest.mark.parametrize("bad", [1, "yes", None.__class__])
def test_track_argument_must_be_a_bool(bad):
    with pytest.raises(RollerRigError, match="track must be True or False"):
        rr.simulate(duration=0.1, track=bad, **RUN)
