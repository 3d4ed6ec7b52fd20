"""The scalar path of creep_forces and hertz (plain numbers straight to C,
rollerrig.contact.creep._scalar_creep) against the general array path: the same
kernel on the same doubles, so the results must be bitwise equal, and every
call the scalar path cannot answer cleanly must behave as before."""
import math

import numpy as np
import pytest

import rollerrig as rr
from rollerrig.contact import creep as contact

from _options import own

RNG = np.random.default_rng(12)


def _cases(n):
    for _ in range(n):
        a = float(RNG.uniform(0.002, 0.01))
        yield dict(cx=float(RNG.uniform(-0.02, 0.02)), cy=float(RNG.uniform(-0.02, 0.02)),
                   cphi=float(RNG.uniform(-2.0, 2.0)), a=a, b=float(a * RNG.uniform(0.3, 3.0)),
                   N=float(RNG.uniform(100.0, 1e5)), mu=float(RNG.uniform(0.1, 0.6)),
                   speed=float(RNG.uniform(0.5, 30.0)))


def _same(x, y):
    """Bitwise equal floats (a signed zero and NaN's bits included)."""
    return np.float64(x).tobytes() == np.float64(y).tobytes()


@pytest.mark.parametrize("method", sorted(rr.METHODS))
@pytest.mark.parametrize("friction", [None, rr.FallingFriction(0.4, 0.6)])
def test_scalar_equals_array_bitwise(method, friction):
    if rr.METHODS[method].coulomb_only and friction is not None:
        pytest.skip(f"{method} is for Coulomb friction (the refusal: test_exact.py, "
                    "test_fastrip.py)")
    opts = own(method, nx=12, ny=9, slip_speed="rigid", kA=0.8, kS=0.5)
    del opts["method"]
    for case in _cases(40):
        cx, cy, cphi = case.pop("cx"), case.pop("cy"), case.pop("cphi")
        s = rr.creep_forces(cx, cy, cphi, method=method, friction=friction, **case, **opts)
        v = rr.creep_forces(np.array([cx]), np.array([cy]), np.array([cphi]), method=method,
                            friction=friction, **case, **opts)
        assert type(s.fx) is float and type(s.status) is int
        for name in ("fx", "fy", "mz"):
            assert _same(getattr(s, name), getattr(v, name)[0]), (method, name, case)
        assert s.status == int(v.status[0])


def test_scalar_path_is_taken_and_its_results_are_the_general_ones():
    case = (0.001, 0.0002, 0.1, 0.004, 0.003, 900.0, 0.35, 8.2e10, 0.28, 5.0)
    fast = contact._scalar_creep("fastsim", {}, None, case)
    assert fast is not None and isinstance(fast, rr.CreepForces)
    cx, cy, cphi, a, b, N, mu, G, nu, speed = case
    slow = rr.creep_forces(np.array(cx), cy, cphi, a=a, b=b, N=N, mu=mu, G=G, nu=nu,
                           speed=speed)
    assert all(_same(f, float(s)) for f, s in zip(fast[:3], slow[:3]))
    # ints are numbers too, a bool is not; the integer 520 is the double 520.0
    assert rr.creep_forces(0.001, a=0.004, b=0.003, N=520, mu=0.4) \
        == rr.creep_forces(0.001, a=0.004, b=0.003, N=520.0, mu=0.4)
    assert contact._scalar_creep("fastsim", {}, None, case[:5] + (True,) + case[6:]) is None


def test_what_the_scalar_path_leaves_to_the_general_one():
    k = dict(a=0.004, b=0.003, N=900.0, mu=0.35)
    # a bad case: the general path's message names the argument and value
    with pytest.raises(rr.RollerRigError, match=r"a = -1\.0"):
        rr.creep_forces(0.001, **{**k, "a": -1.0})
    # bad options, an unhashable value: the registry's messages
    with pytest.raises(rr.RollerRigError, match="nx"):
        rr.creep_forces(0.001, nx=0, **k)
    with pytest.raises(rr.RollerRigError, match="kA"):
        rr.creep_forces(0.001, method="fastsim", kA=0.5, **k)
    with pytest.raises(rr.RollerRigError, match="nx"):
        rr.creep_forces(0.001, nx=[3], **k)
    # an int beyond the doubles, a bool
    with pytest.raises(rr.RollerRigError):
        rr.creep_forces(0.001, **{**k, "N": 10 ** 400})
    with pytest.raises(rr.RollerRigError):
        rr.creep_forces(True, **k)
    # errors= given: the general path, and its policy
    r = rr.creep_forces(0.001, errors="ignore", **{**k, "N": -1.0})
    assert math.isnan(r.fx) and r.status < 0
    # falling friction without speed: an error status, so the general path raises
    with pytest.raises(rr.RollerRigError, match="speed"):
        rr.creep_forces(0.001, friction=rr.FallingFriction(), **k)


def test_options_are_parsed_once_and_the_cache_stays_bounded():
    k = dict(a=0.004, b=0.003, N=900.0, mu=0.35)
    contact._SCALAR_OPTIONS.clear()
    rr.creep_forces(0.001, nx=7, ny=5, **k)
    first = dict(contact._SCALAR_OPTIONS)
    rr.creep_forces(0.002, ny=5, nx=7, **k)            # the same options, in another order
    assert contact._SCALAR_OPTIONS == first and len(first) == 1
    for n in range(1, 2 * contact._SCALAR_OPTIONS_MAX):
        rr.creep_forces(0.001, nx=n, ny=3, **k)
    assert len(contact._SCALAR_OPTIONS) <= contact._SCALAR_OPTIONS_MAX


def test_hertz_scalar_equals_array_bitwise():
    for _ in range(200):
        A, B = float(RNG.uniform(1.0, 100.0)), float(RNG.uniform(1.0, 100.0))
        N = float(RNG.uniform(10.0, 1e5))
        E2, nu2 = float(RNG.uniform(1e10, 3e11)), float(RNG.uniform(0.0, 0.5))
        s = rr.hertz(A, B, N, E2=E2, nu2=nu2)
        v = rr.hertz(np.array([A]), B, N, E2=E2, nu2=nu2)
        for name in ("a", "b", "p0", "delta"):
            assert _same(getattr(s, name), getattr(v, name)[0])
        assert s.status == 0 and type(s.a) is float
    with pytest.raises(rr.RollerRigError, match="N = -1.0"):
        rr.hertz(40.0, 25.0, -1.0)
