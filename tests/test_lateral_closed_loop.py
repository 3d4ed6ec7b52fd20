"""The rig's full state (checkpoints) and the closed loop's linearisation
(issue 25, item 1's second half)."""
import math

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import _core
from rollerrig import RollerRigError


def _rig():
    return rr.build_rig()[0]


def _refs(rig, n, xi=0.02):
    w = 5.0 / rig.info.roller_radius
    return np.full(n, w), np.full(n, xi)


def test_full_state_names_and_values():
    rig = _rig()
    s = rig.full_state()
    assert list(s)[:3] == ["t", "x", "y"] and len(s) == 35
    # the plant's part is the plant's vector, bit for bit
    plant = [s[n] for n in ("x", "y", "yaw", "chi", "theta_r", "vx", "vy", "yaw_rate", "spin",
                            "roller_spin", "torque_roller", "torque_wheelset")]
    assert np.array_equal(plant, rig.y) and s["t"] == rig.t
    assert s["creep_control"] == 0.0 and math.isnan(s["xi_ref"])


def test_checkpoint_bit_for_bit():
    """get -> 60 samples -> set back -> the same 60 samples, bit for bit,
    with the creepage controller running (its K, the PI integrals and the
    encoders' counts all in play); a changed value changes the run."""
    rig = _rig()
    r, x = _refs(rig, 200)
    rec0, st = rig.run(r[:40], x[:40])
    assert st >= 0
    saved = rig.full_state()
    assert saved["creep_control"] == 1.0 and saved["roller_enc_primed"] == 1.0
    a, st = rig.run(r[:60], x[:60])
    assert st >= 0
    assert rig.set_full_state(saved) >= 0
    b, st = rig.run(r[:60], x[:60])
    assert st >= 0
    assert np.array_equal(a, b)               # the NaN-free record: exact equality
    changed = dict(saved, creepctl_K=saved["creepctl_K"] - 0.01)
    assert rig.set_full_state(changed) >= 0
    c, _ = rig.run(r[:60], x[:60])
    i = [f[0] for f in _core.RIG_RECORD].index("spin")
    assert a[-1, i] != c[-1, i]


def test_set_full_state_refusals():
    rig = _rig()
    s = rig.full_state()
    before = rig.full_state()
    with pytest.raises(RollerRigError, match="must be a dict"):
        rig.set_full_state(list(s.values()))
    with pytest.raises(RollerRigError, match=r"lacks \['t'\]"):
        rig.set_full_state({k: v for k, v in s.items() if k != "t"})
    with pytest.raises(RollerRigError, match="unknown names"):
        rig.set_full_state(dict(s, bogus=1.0))
    with pytest.raises(RollerRigError, match=r"state\['vy'\] must be a real number"):
        rig.set_full_state(dict(s, vy="fast"))
    assert rig.set_full_state(dict(s, vy=math.nan)) == -1            # RR_ERR_NONFINITE
    assert rig.set_full_state(dict(s, creep_control=2.0)) == -9      # RR_ERR_PARAM
    assert rig.set_full_state(dict(s, wheelset_count=0.5)) == -9
    assert rig.set_full_state(dict(s, y=0.02)) == -3                 # the wheel off its roller
    assert rig.full_state() == pytest.approx(before, nan_ok=True)    # nothing changed
    rig.sample(*[v[0] for v in _refs(rig, 1)])
    with pytest.raises(RollerRigError, match="Rig.full_state"):
        rig.full_state()
