"""The slide-protection example (examples/slide_protection.py): braking
through a patch of mu0 0.1 with a demand worth an adhesion of 0.25."""
import importlib.util
import os

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
PATH = os.path.join(HERE, "..", "examples", "slide_protection.py")


@pytest.fixture(scope="module")
def example():
    spec = importlib.util.spec_from_file_location("slide_protection", PATH)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="module")
def results(example):
    return example.runs()


def test_the_unprotected_wheel_locks_and_stays_locked(example, results):
    """Kalker's creepage divides by the mean rolling speed: a locked wheel
    has cx = 2.  The locked wheel's falling friction (0.17 at 5 m/s of
    slip) is less than the demand (0.25), so it stays locked after the
    patch: the braking force stays below the demand."""
    res = results["no protection"]
    inside = (res.time > example.PATCH[0]) & (res.time < example.PATCH[1])
    assert np.max(res.creepage[inside]) > 1.9
    # the brake fades below 0.5 rad/s (0.046 m/s at the wheel): at rest but for a creep
    assert np.all(res.wheelset_speed[res.time > 3.2] < 0.05)
    after = res.time > example.PATCH[1] + 0.5
    assert np.all(-res.fx[after] < 0.8 * example.DEMAND / 0.092)


def test_slide_protection_keeps_the_creepage_bounded(example, results):
    """Where the unprotected wheel locks, the example's creepage stays below
    0.1 (its slide threshold 0.05 and the dump's lag), it brakes with at
    least 90 % of what the patch allows on average, and after the patch it
    is back on the demand with the creepage of clean rail (< 0.005)."""
    res = results["slide protection (this example)"]
    assert res.status >= 0
    inside = (res.time > example.PATCH[0]) & (res.time < example.PATCH[1])
    assert np.max(res.creepage) < 0.1
    limit = res.mu_left * res.normal_load_left + res.mu_right * res.normal_load_right
    assert np.mean(-res.fx[inside]) > 0.9 * np.mean(limit[inside])
    after = res.time > example.PATCH[1] + 1.0
    assert np.all(res.creepage[after] < 0.005)
    np.testing.assert_allclose(res.torque_ref_wheelset[after], -example.DEMAND, rtol=1e-2)


def test_the_creepage_controller_holds_its_target_through_the_patch(example, results):
    res = results["creepage controller, 0.02"]
    assert np.max(res.creepage[res.time > 1.0]) < 0.035


def test_the_figure(example, results, tmp_path):
    path = example.figure(results, str(tmp_path / "sp.png"))
    assert os.path.getsize(path) > 10_000
