"""A flange excursion on the measured pair (issue 24 item 2): a lateral
force on the wheelset (disturbance.lateral_force_*, csrc/rig/rr_rig.h
rr_rig_lateral) pushes it to flange contact and back
(rollerrig/data/rig_flange_excursion.toml, examples/flange_excursion.py)."""
import importlib.util
import os
import warnings

import numpy as np
import pytest

import rollerrig as rr

DATA = os.path.join(os.path.dirname(rr.__file__), "data")
EXAMPLES = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "examples")


def _example():
    spec = importlib.util.spec_from_file_location(
        "flange_excursion", os.path.join(EXAMPLES, "flange_excursion.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="module")
def excursion():
    return _example().run()


def test_the_lateral_force_reaches_flange_contact_and_leaves_it(excursion):
    res, geo = excursion
    assert res.status == 0
    P = res.params
    scale = P["wheelset"]["profile_scale"]
    ky2 = 2 * P["suspension"]["ky_N_per_m"]
    F = _example().lateral_force(res)
    hold = (res.time > 3.2) & (res.time < 4.0)
    before, after = res.time < 1.0, res.time > 5.5
    # on the tread before and after: small contact angles, the contact point
    # within 10 mm of the taping line (full size), both wheels loaded alike
    for sel in (before, after):
        assert np.degrees(geo.left.delta[sel]).max() < 5
        assert np.all(np.abs(geo.left.s_wheel[sel] / scale) < 0.010)
    # held at 3250 N: the left wheel on its flange root (contact angle past
    # 20 degrees, the contact point over 25 mm toward the flange), the right
    # on its tread, unloaded by the roll the flange makes
    assert np.degrees(geo.left.delta[hold]).min() > 20
    assert np.all(geo.left.s_wheel[hold] / scale < -0.025)
    assert np.degrees(geo.right.delta[hold]).max() < 5
    assert res.normal_load_right[hold].max() < 0.9 * res.normal_load_left[hold].min()
    # the loads still carry the preload and the weight (900.85 + 14.504 g)
    total = res.normal_load_left + res.normal_load_right
    assert np.allclose(total[before], 900.85 + 14.504 * 9.81, rtol=2e-3)
    # on the tread the lateral springs take the force (the tread's gravitational
    # stiffness and the lateral creep force are small: within 5 %, measured 1 %);
    # on the flange its contact takes part of it: the shift is less than F / 2 ky
    ramp = (res.time > 1.5) & (res.time < 2.4)
    assert np.allclose(res.y[ramp], F[ramp] / ky2, rtol=0.05)
    assert np.all(res.y[hold] < F[hold] / ky2)
    # the creepage controller holds its estimate (eq. 16, from the encoders with the
    # radii of the centred wheelset) through it; each contact's creepage is then
    # the estimate seen through that contact's own radii, 1 - (1 - xi_est)
    # (r / r_w) (R_w / R): on the flange root the left wheel's radius is 1.3 %
    # larger and its creepage falls to about 0.0025 (independent of the contact
    # model: kinematics; tolerance 3e-4, the creepage's rolling speed being the
    # mean of the two surfaces' and the yaw's share)
    assert np.mean(res.xi_est[hold]) == pytest.approx(0.02, rel=0.05)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)
        rig = rr.build_rig(P)[0]
    r_w, R_w = rig.info.wheel_radius, rig.info.roller_radius
    for side, cx in (("left", res.creepage_left), ("right", res.creepage_right)):
        g = getattr(geo, side)
        predicted = 1 - (1 - res.xi_est) * (g.r / r_w) * (R_w / g.R)
        assert np.mean(cx[hold]) == pytest.approx(np.mean(predicted[hold]), abs=3e-4)
    assert np.mean(res.creepage_left[hold]) < 0.005


def test_a_larger_force_climbs_the_flange_and_stops_the_run():
    """Beyond about 3.3 kN the right wheel unloads to nothing (the wheelset
    climbs): the run stops with a negative status at that sample, never a
    crash or a clamp."""
    P = rr.load_parameters(os.path.join(DATA, "rig_flange_excursion.toml"))
    P["disturbance"]["lateral_force_N"] = [0.0, 4000.0, 4000.0, 0.0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)
        res = rr.simulate(params=P)
    assert res.status < 0
    assert "stopped at t =" in res.message or "not to be trusted" in res.message


def test_no_lateral_force_is_the_rig_without_one():
    """An empty disturbance and a zero force leave the run bit for bit (the
    force is added only where points are given; a zero adds +0.0)."""
    a = rr.simulate(duration=0.4, targets=[0.02])
    b = rr.simulate(duration=0.4, targets=[0.02],
                    params={"disturbance": {"lateral_force_times_s": [0.0],
                                            "lateral_force_N": [0.0]}})
    assert np.array_equal(a.records, b.records, equal_nan=True)


def test_bad_lateral_force():
    for D, msg in (({"lateral_force_times_s": [0.0, 1.0], "lateral_force_N": [1.0]},
                    r"disturbance.lateral_force_N has 1 entries but "
                    r"disturbance.lateral_force_times_s has 2"),
                   ({"lateral_force_times_s": [1.0, 0.5], "lateral_force_N": [1.0, 2.0]},
                    r"disturbance.lateral_force_times_s must not decrease"),
                   ({"lateral_force_times_s": [0.0], "lateral_force_N": [float("nan")]},
                    r"disturbance.lateral_force_N must be a list"),
                   ({"lateral_force_times_s": [-1.0], "lateral_force_N": [1.0]},
                    r"disturbance.lateral_force_times_s must be a list")):
        with pytest.raises(rr.RollerRigError, match=msg):
            rr.simulate(duration=0.1, targets=[0.02], params={"disturbance": D})
