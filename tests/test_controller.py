"""A controller of the user's in the rig's loop: simulate(controller=...),
rollerrig.rig.control, and the binding's Rig.read / Rig.write."""
import math
import numbers

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import _core
from rollerrig.rig.control import CreepageController, RigInfo, RigSignals

KW = dict(duration=1.2, targets=[0.04, 0.015], target_times=[0.2, 0.7])


@pytest.fixture(scope="module")
def builtin():
    return rr.simulate(**KW)


def bits(a):
    return np.ascontiguousarray(a).view(np.uint64)


def test_the_paper_controller_in_python_gives_the_builtin_history_bit_for_bit(builtin):
    """CreepageController (eq. 13-16 written as a user's controller: the
    encoders' speeds in, the wheelset's speed reference out) in the loop
    gives the built-in controller's history to the last bit: every record
    field of every sample, over the start of control and a change of
    target; also on the paper's whole 20 s scenario."""
    res = rr.simulate(controller=CreepageController(), **KW)
    assert res.status == builtin.status and len(res) == len(builtin) == 300
    np.testing.assert_array_equal(bits(res.records), bits(builtin.records))
    paper = rr.simulate(controller=CreepageController())
    np.testing.assert_array_equal(bits(paper.records), bits(rr.simulate().records))


def test_a_controller_that_returns_none_leaves_the_rig_its_own(builtin):
    res = rr.simulate(controller=lambda s: None, **KW)
    np.testing.assert_array_equal(bits(res.records), bits(builtin.records))


def test_decimated_records_with_a_controller(builtin):
    res = rr.simulate(controller=CreepageController(), record_every=7, **KW)
    np.testing.assert_array_equal(bits(res.records), bits(builtin.records[6::7]))


def test_the_controller_sees_the_encoders_and_is_started_once():
    """start(info) once, with the rig's settings; then at each sample k the
    time k dt, the quantised angles (whole counts of 2 pi / counts), the
    speed estimates (eq. 12: the counts' difference over dt), the drive
    torques and the scenario's references."""
    seen, infos = [], []

    class Spy:
        def start(self, info):
            infos.append(info)

        def __call__(self, s):
            seen.append(s)

    res = rr.simulate(controller=Spy(), **KW)
    assert len(infos) == 1 and isinstance(infos[0], RigInfo)
    info = infos[0]
    assert info.dt == 0.004 and info.sense == -1 and info.wheelset_counts == 2 ** 23
    assert info.wheelset_torque_limit == 60.0 and 0.09 < info.wheel_radius < 0.093
    assert len(seen) == 300 and all(isinstance(s, RigSignals) for s in seen)
    q = 2 * math.pi / info.wheelset_counts
    for k, s in enumerate(seen):
        assert s.k == k and s.t == pytest.approx(k * 0.004, abs=1e-12)
        assert s.wheelset_angle == s.wheelset_count * q and s.wheelset_count == int(
            s.wheelset_count)
    ws = np.array([s.wheelset_count for s in seen])
    speeds = np.array([s.wheelset_speed for s in seen])
    np.testing.assert_allclose(speeds[1:], np.diff(ws) * q / 0.004, rtol=1e-12)
    torques = np.array([s.wheelset_torque for s in seen])
    np.testing.assert_array_equal(torques[1:], res.torque_wheelset[:-1])
    assert np.isnan(seen[0].xi_ref) and seen[100].xi_ref == 0.04 and seen[200].xi_ref == 0.015
    assert all(s.roller_ref == 5.0 / 0.16 for s in seen)


def test_torque_commands_are_held_and_clipped():
    """A constant braking torque on the wheelset: the torque reference is
    the command (clipped at the drive's limit), the wheelset's speed
    reference is NaN, and past the adhesion limit the wheel locks up."""
    res = rr.simulate(duration=0.6, targets=[0.02], controller=lambda s: {"wheelset_torque": -25.0})
    assert res.status >= 0
    assert np.all(res.torque_ref_wheelset == -25.0) and np.all(np.isnan(res.w_ref))
    big = rr.simulate(duration=0.6, targets=[0.02], controller=lambda s: {"wheelset_torque": -1e9})
    assert np.all(big.torque_ref_wheelset == -60.0)
    # 60 N m against at most 0.4 * 1043 N * 0.092 m = 38 N m of adhesion: the
    # wheel slides and slows
    assert big.wheelset_speed[-1] < 0.5 * big.roller_speed[-1]
    # a roller torque of 0 lets the braked rig slow down
    free = rr.simulate(duration=0.6, targets=[0.02], controller=lambda s: {"roller_torque": 0.0,
                                                           "wheelset_torque": -30.0})
    assert free.roller_speed[-1] < free.roller_speed[0] - 0.05
    assert np.all(free.torque_ref_roller == 0.0)


def test_speed_commands_go_to_the_drives_pi():
    res = rr.simulate(duration=1.0, targets=[0.02], controller=lambda s: {"wheelset_speed": 50.0})
    assert np.all(res.w_ref == 50.0)
    assert res.spin[-1] == pytest.approx(50.0, rel=2e-3)


@pytest.mark.parametrize("returned, says", [
    ({"wheelset_torque": math.nan}, "wheelset_torque.*input is NaN or infinite"),
    ({"wheelset_speed": math.inf}, "input is NaN or infinite"),
    ({"brake": 1.0}, "unknown key 'brake'"),
    ({"wheelset_speed": 1.0, "wheelset_torque": 1.0}, "both 'wheelset_speed' and "
                                                      "'wheelset_torque'"),
    ({"roller_torque": "1"}, "roller_torque = '1', not a real number"),
    (1.5, "returned float 1.5, not a dict"),
])
def test_a_bad_command_stops_the_run_naming_the_sample(returned, says):
    """The controller works for 100 samples, then returns something that is
    not a command: a RollerRigError names the sample and what was wrong;
    its .result keeps the 100 good samples."""
    def ctl(s):
        return None if s.k < 100 else returned
    with pytest.raises(rr.RollerRigError, match=f"sample 100 \\(t = 0.4000 s\\): .*{says}") as e:
        rr.simulate(controller=ctl, **KW)
    res = e.value.result
    assert len(res) == 100 and res.samples_run == 100 and res.status < 0
    ref = rr.simulate(duration=0.4, targets=[0.04], target_times=[0.2])
    np.testing.assert_array_equal(bits(res.records), bits(ref.records))


class _Unreadable(numbers.Real):
    """A number whose float() raises: numbers.Real in name only."""
    def __float__(self):
        raise TypeError("no float for you")

    def __repr__(self):
        raise RuntimeError("no repr either")

    __abs__ = __add__ = __ceil__ = __eq__ = __floor__ = __floordiv__ = __le__ = __lt__ = \
        __mod__ = __mul__ = __neg__ = __pos__ = __pow__ = __radd__ = __rfloordiv__ = \
        __rmod__ = __rmul__ = __round__ = __rpow__ = __rtruediv__ = __truediv__ = \
        __trunc__ = lambda self, *a: NotImplemented
    __hash__ = object.__hash__


class _BrokenItems(dict):
    """A mapping whose items() raises."""
    def items(self):
        raise KeyError("gone")


class _Unhashable(dict):
    """A mapping with a key that cannot be looked up."""
    def items(self):
        return [(["wheelset_torque"], 1.0)]


@pytest.mark.parametrize("returned, says, cause", [
    ({"wheelset_torque": _Unreadable()}, r"wheelset_torque = a _Unreadable whose float\(\) "
                                         r"raised TypeError: no float for you", TypeError),
    (_BrokenItems(), r"a _BrokenItems whose items\(\) raised KeyError: 'gone'", KeyError),
    (_Unhashable(), r"unknown key \['wheelset_torque'\]", None),
])
def test_a_command_that_cannot_be_read_stops_the_run_naming_the_sample(returned, says, cause):
    """Reading what the controller returned raised (its float() or its
    items()): that exception escaped raw; it is a RollerRigError naming the
    sample and why, with the exception as its cause and .result kept, as
    for a controller that raises."""
    def ctl(s):
        return None if s.k < 100 else returned
    with pytest.raises(rr.RollerRigError, match=f"sample 100 \\(t = 0.4000 s\\): .*{says}") \
            as e:
        rr.simulate(controller=ctl, **KW)
    res = e.value.result
    assert len(res) == 100 and res.status == _core.ERR_CONTROLLER
    assert cause is None or isinstance(e.value.__cause__, cause)


def test_a_controller_that_raises_stops_the_run_with_its_exception_as_cause():
    def ctl(s):
        if s.k == 42:
            raise ZeroDivisionError("my bug")
    with pytest.raises(rr.RollerRigError, match=r"sample 42 .*it raised ZeroDivisionError: "
                                                r"my bug") as e:
        rr.simulate(controller=ctl, **KW)
    assert isinstance(e.value.__cause__, ZeroDivisionError)
    assert len(e.value.result) == 42 and e.value.result.status == _core.ERR_CONTROLLER
    assert "controller failed" in rr.status_message(_core.ERR_CONTROLLER)

    class BadStart:
        def start(self, info):
            raise RuntimeError("no config")

        def __call__(self, s):
            return None
    with pytest.raises(rr.RollerRigError, match="start\\(info\\) raised RuntimeError"):
        rr.simulate(controller=BadStart(), **KW)


def test_controller_must_be_callable():
    with pytest.raises(rr.RollerRigError, match="controller must be a callable"):
        rr.simulate(controller=3)


def test_rig_read_write_by_hand():
    """Stepping by hand: read, write, advance; out of order is refused
    (RR_ERR_SEQUENCE, -15) and a bad mode named."""
    rig, P, _ = rr.build_rig()
    vals, st = rig.read()
    assert st == 0 and vals[0] == 0.0 and len(vals) == 10
    assert rig.read()[1] == -15
    with pytest.raises(rr.RollerRigError, match="wheelset_mode must be one of"):
        rig.write(_core.CMD_SPEED, 31.25, 5, 0.0)
    assert rig.write(_core.CMD_SPEED, 31.25, _core.CMD_TORQUE, -10.0) == 0
    assert rig.write(_core.CMD_SPEED, 31.25, _core.CMD_TORQUE, -10.0) == -15
    rec, st = rig.advance()
    assert st >= 0 and rec[rr.rig.RECORD_FIELDS.index("torque_ref_wheelset")] == -10.0
    assert rig.read()[1] == 0 and rig.write(0, 31.25, 0, math.nan, 0.2) == 0
    rec, st = rig.advance()
    assert rec[rr.rig.RECORD_FIELDS.index("mu_left")] == 0.2
    assert rig.info.dt == 0.004
