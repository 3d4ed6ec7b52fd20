"""Adhesion that changes: the [adhesion] section's schedule in time and
contaminated patch on the roller circumference (csrc/rig/rr_rig.h,
rr_rig_adhesion)."""
import math

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import plot as rp

KW = dict(duration=2.0, targets=[0.02], target_times=[0.0])
R0 = 0.16
C = 2 * math.pi * R0                    # the roller's circumference [m]


def schedule(times, mu0, **more):
    return {"adhesion": {"schedule_times_s": times, "schedule_mu0": mu0, **more}}


def test_a_schedule_equal_to_the_constant_law_changes_nothing():
    base = rr.simulate(**KW)
    same = rr.simulate(params=schedule([0.0, 1.0], [0.4, 0.4]), **KW)
    np.testing.assert_array_equal(same.records, base.records)
    assert np.all(base.mu_left == 0.4) and np.all(base.mu_right == 0.4)


def test_the_schedule_is_taken_at_each_samples_start_and_held():
    """mu0 linear between the points, held outside, a step at a repeated
    time; each record (at a sample's end) shows the law of its sample,
    taken at the sample's start t - dt (within rounding of the time sum)."""
    times, mu = [0.5, 1.0, 1.0, 1.5], [0.4, 0.2, 0.1, 0.3]
    res = rr.simulate(params=schedule(times, mu), **KW)
    start = res.time - res.dt
    want = np.interp(start, times[:2], mu[:2])
    late = start >= 1.0
    want[late] = np.interp(start[late], times[2:], mu[2:])
    np.testing.assert_allclose(res.mu_left, want, rtol=1e-12, atol=1e-12)
    np.testing.assert_array_equal(res.mu_right, res.mu_left)
    # the force follows mu0 down and up: never above it (Coulomb's bound, the
    # falling law below mu0), and within a few per cent of it once saturated
    assert np.all(res.adhesion <= res.mu_left * (1 + 1e-9))
    low = (start > 1.05) & (start < 1.5)
    assert np.all(res.adhesion[low] > 0.85 * res.mu_left[low])
    assert np.all(res.adhesion[start < 0.5][-10:] > 0.3)


def test_falling_law_parameters_follow_the_schedule():
    """A and B of the schedule act: a steeper fall (B = 5 s/m) lowers the
    adhesion held at the same mu0 and creepage."""
    flat = rr.simulate(params=schedule([0.0], [0.4]), **KW)
    steep = rr.simulate(params=schedule([0.0], [0.4], schedule_polach_B_s_per_m=[5.0]), **KW)
    assert np.mean(steep.adhesion[-100:]) < np.mean(flat.adhesion[-100:]) - 0.02


@pytest.fixture(scope="module")
def patched():
    """A 0.2 m patch of mu0 0.1 on the left roller alone, its start 0.5 m
    from the mark: it reaches the left contact at 0.1 s and each turn after."""
    params = {"adhesion": {"patch_length_m": 0.2, "patch_start_m": 0.5,
                           "patch_rollers": "left"}}
    return rr.simulate(params=params, **KW)


def test_a_patch_passes_under_the_wheel_once_a_revolution(patched):
    """The left contact's mu0 drops to the patch's 0.1 once per turn of the
    roller, for the patch's length over the surface speed; the right roller
    stays clean; the patch's edges ramp over patch_edge_m (2 mm: under one
    sample at 5 m/s, so only a few samples show a value in between)."""
    res = patched
    assert res.status >= 0
    assert np.all(res.mu_right == 0.4)
    inside = res.mu_left == 0.1
    assert np.all((res.mu_left == 0.1) | (res.mu_left == 0.4)
                  | (np.diff(np.r_[0.0, inside.astype(int)]) != 0)
                  | (np.diff(np.r_[inside.astype(int), 0]) != 0))
    # entries into the patch: once per revolution of the roller's surface
    travel = np.cumsum(res.roller_speed) * res.dt                # surface travel [m]
    enters = np.flatnonzero(np.diff(inside.astype(int)) == 1) + 1
    assert len(enters) >= 9
    np.testing.assert_allclose(np.diff(travel[enters]), C, atol=6 * 0.02)
    # each visit lasts about the patch's length over the speed: 0.2 m / 5 m/s = 40 ms
    runs = np.diff(np.flatnonzero(np.diff(np.r_[0, inside.astype(int), 0]) != 0))[::2]
    assert np.all(np.abs(runs * res.dt - 0.2 / 5.0) <= 2 * res.dt)
    # the first at 0.5 m of travel: 0.1 s
    assert res.time[enters[0]] == pytest.approx(0.1, abs=2 * res.dt)


def test_the_patch_moves_the_force_and_yaws_the_wheelset(patched):
    """Inside the patch the left wheel's share of the force is bounded by
    0.1 N; the wheelset, braked harder on the right, yaws."""
    res = patched
    clean = rr.simulate(**KW)
    inside = res.mu_left == 0.1
    assert np.max(np.abs(res.yaw)) > 10 * max(np.max(np.abs(clean.yaw)), 1e-12)
    limit = 0.1 * res.normal_load_left + 0.4 * res.normal_load_right
    assert np.all(np.abs(res.fx[inside]) <= limit[inside] * (1 + 1e-9))


def test_the_figure_and_csv_show_mu(patched, tmp_path):
    ax = rp.rig_force(patched)
    assert [l.get_label() for l in ax.mu_axis.get_lines()] == ["mu0 at the left contact",
                                                               "mu0 at the right contact"]
    np.testing.assert_array_equal(ax.mu_axis.get_lines()[0].get_ydata(), patched.mu_left)
    np.testing.assert_array_equal(ax.get_lines()[1].get_ydata(),
                                  patched.mu_left * patched.normal_load_left
                                  + patched.mu_right * patched.normal_load_right)
    assert "each wheel's mu0 in time" in ax.get_lines()[1].get_label()
    import csv
    path = patched.to_csv(tmp_path / "h.csv")
    with open(path) as fh:
        rows = list(csv.DictReader(line for line in fh if not line.startswith("#")))
    assert float(rows[30]["mu_left"]) == patched.mu_left[30]
    assert {"mu_left", "mu_right"} <= set(rows[0])


def test_a_schedule_in_a_toml_file(tmp_path):
    path = tmp_path / "wet.toml"
    path.write_text("[adhesion]\nschedule_times_s = [0.5, 0.5]\nschedule_mu0 = [0.4, 0.15]\n")
    res = rr.simulate(params=str(path), **KW)
    assert res.mu_left[int(0.5 / 0.004)] == 0.15 and res.mu_left[0] == 0.4


@pytest.mark.parametrize("adhesion, says", [
    ({"schedule_times_s": [0, 1], "schedule_mu0": [0.4]}, "schedule_mu0 has 1 entries"),
    ({"schedule_times_s": [0, 1], "schedule_mu0": [0.4, 0.2], "schedule_polach_A": [0.5]},
     "schedule_polach_A has 1 entries"),
    ({"schedule_times_s": [1, 0], "schedule_mu0": [0.4, 0.2]}, "must not decrease"),
    ({"schedule_times_s": [0], "schedule_mu0": [0.0]}, "schedule_mu0 must be a list"),
    ({"schedule_times_s": [-1.0], "schedule_mu0": [0.3]}, "schedule_times_s must be a list"),
    ({"patch_length_m": 2.0}, "at most the roller's circumference"),
    ({"patch_mu0": math.nan}, "patch_mu0 must be a finite number"),
    ({"patch_edge_m": 0.0}, "patch_edge_m must be a finite number > 0"),
    ({"patch_rollers": "middle"}, "patch_rollers must be 'both' or 'left' or 'right'"),
    ({"schedule_mu0": "0.4"}, "schedule_mu0 must be a list"),
])
def test_bad_adhesion_is_named(adhesion, says):
    with pytest.raises(rr.RollerRigError, match=says):
        rr.simulate(duration=0.1, params={"adhesion": adhesion})


def test_replay_refuses_a_run_whose_adhesion_changed(patched):
    with pytest.raises(rr.RollerRigError, match="replay: the run's adhesion changed"):
        rr.replay(patched)
