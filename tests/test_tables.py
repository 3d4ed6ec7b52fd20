"""The C builders of profiles and contact tables (csrc/geometry/rr_tables.h)
against the Python path: bit for bit, so that a C program and rr.simulate()
hold the same table."""
import math
import warnings

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import _core, rig
from rollerrig.geometry import contact_table
from rollerrig.geometry.profiles import Profile

DEFAULT = dict(r0=0.092, R0=0.160, hw=0.015, alpha=math.atan(0.05), crown=0.060, span=0.15,
               reach=0.008, rows=161)


def _python_rig_table(r0, R0, hw, alpha, crown, span, reach, rows):
    """The rig's table as rig.build._rig_table built it before the C builder."""
    g = rr.RigGeometry(wheel=Profile.conical(alpha, (-hw, hw), r0=r0, n=121),
                       roller=Profile.cylinder((-hw, hw), crown_radius=crown, n=121),
                       wheel_radius=r0, roller_radius=R0, wheel_y=span, roller_y=span)
    return contact_table(g, -reach, reach, rows)


def _same(a, b):
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.mark.parametrize("geo", [DEFAULT, dict(DEFAULT, alpha=math.atan(0.025), crown=0.3,
                                                hw=0.03, reach=0.012, rows=97, r0=0.23,
                                                R0=0.25, span=0.7)])
def test_c_rig_table_is_the_python_table_bitwise(geo):
    data, y0, dy, status, bad_y = _core.rig_table(*geo.values())
    assert status == 0 and math.isnan(bad_y)
    t = _python_rig_table(*geo.values())
    assert (y0, dy) == (t.y0, t.dy)
    assert _same(data, t.data)
    rig.build._rig_table.cache_clear()
    r = rig.build._rig_table(*geo.values())
    assert _same(r.data, t.data) and (r.y0, r.dy, r.n) == (t.y0, t.dy, t.n)
    assert not r.data.flags.writeable
    assert isinstance(r.geometry, rr.RigGeometry)


def test_simulate_uses_the_c_table():
    P = rr.default_parameters()
    t = rig.build._geometry(P)
    W, R, I = P["wheelset"], P["roller"], P["integration"]
    data, *_ = _core.rig_table(W["wheel_radius_m"], R["radius_m"], W["profile_half_width_m"],
                               math.atan(W["conicity"]), R["crown_radius_m"],
                               W["contact_half_spacing_m"], I["table_half_range_m"],
                               I["table_rows"])
    assert _same(t.data, data)


def _points_table(wheel, roller, place, y_min, y_max, n, ends=(0, 0)):
    dy = (y_max - y_min) / (n - 1)
    return _core.profile_table(wheel.y, wheel.z, ends[0], roller.y, roller.z, ends[1], place,
                               y_min, dy, n, 400, 1e-4, 2e-3)


@pytest.mark.parametrize("bc", ["not-a-knot", "natural"])
def test_c_points_table_is_the_python_table_bitwise(bc):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)
        w, r = Profile.s1002(), Profile.uic60()
    wheel = Profile(w.y, w.z, kind="wheel", bc=bc)
    roller = Profile(r.y, r.z, kind="rail", bc=bc)
    place = (0.46, 0.46, 0.75, 0.76053)
    g = rr.RigGeometry(wheel=wheel, roller=roller, wheel_radius=place[0],
                       roller_radius=place[1], wheel_y=place[2], roller_y=place[3])
    t = contact_table(g, -0.006, 0.006, 49)
    end = _core.SPLINE_NATURAL if bc == "natural" else _core.SPLINE_NOT_A_KNOT
    data, status, bad_y = _points_table(wheel, roller, place, -0.006, 0.006, 49, (end, end))
    assert status == 0
    assert _same(data, t.data)


def test_c_points_table_reports_the_shift_off_the_roller():
    wheel = Profile.conical(0.05, (-0.015, 0.015), n=61)
    roller = Profile.cylinder((-0.015, 0.015), crown_radius=0.06, n=61)
    data, status, bad_y = _points_table(wheel, roller, (0.092, 0.16, 0.15, 0.15), -0.05, 0.05,
                                        11)
    assert status == -3 and bad_y == -0.05


def test_analytic_profiles_are_numpys_points_bitwise():
    # the numpy arithmetic Profile.conical / Profile.cylinder used before the C
    for (y0, y1), n in (((-0.015, 0.015), 121), ((-0.021, 0.0333), 77), ((-0.4, 0.3), 1001)):
        y = np.linspace(y0, y1, n)
        for alpha in (0.0, 0.05, -0.3, 1.2):
            p = Profile.conical(alpha, (y0, y1), n=n)
            assert _same(p.y, y) and _same(p.z, -math.tan(alpha) * y)
        for R in (0.45, 2.0):
            p = Profile.cylinder((y0, y1), crown_radius=R, n=n)
            assert _same(p.y, y) and _same(p.z, y * y / (R + np.sqrt(R - y) * np.sqrt(R + y)))
        assert _same(Profile.cylinder((y0, y1), n=n).z, np.zeros(n))


# --- the numpy spline the C replaced (rollerrig.geometry.profiles before rr_spline_fit)

def _solve_tridiagonal(sub, diag, sup, rhs):
    n = len(diag)
    c, d = np.empty(n), np.empty(n)
    c[0] = sup[0] / diag[0]
    d[0] = rhs[0] / diag[0]
    for i in range(1, n):
        m = diag[i] - sub[i] * c[i - 1]
        c[i] = sup[i] / m if i < n - 1 else 0.0
        d[i] = (rhs[i] - sub[i] * d[i - 1]) / m
    x = np.empty(n)
    x[-1] = d[-1]
    for i in range(n - 2, -1, -1):
        x[i] = d[i] - c[i] * x[i + 1]
    return x


def _numpy_slopes(y, z, bc):
    n = len(y)
    h, d = np.diff(y), np.diff(z) / np.diff(y)
    sub, diag, sup, rhs = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
    sub[1:-1], diag[1:-1], sup[1:-1] = h[1:], 2.0 * (h[:-1] + h[1:]), h[:-1]
    rhs[1:-1] = 3.0 * (h[1:] * d[:-1] + h[:-1] * d[1:])
    if bc == "natural":
        diag[0], sup[0], rhs[0] = 2.0, 1.0, 3.0 * d[0]
        sub[-1], diag[-1], rhs[-1] = 1.0, 2.0, 3.0 * d[-1]
        return _solve_tridiagonal(sub, diag, sup, rhs)
    w0, w1 = h[0] + h[1], h[-1] + h[-2]
    a0, c0, an, bn = h[1], w0, h[-2], w1
    r0 = ((h[0] + 2.0 * w0) * h[1] * d[0] + h[0] ** 2 * d[1]) / w0
    rn = (h[-1] ** 2 * d[-2] + (2.0 * w1 + h[-1]) * h[-2] * d[-1]) / w1
    f, g = sub[1] / a0, sup[-2] / an
    diag[1] -= f * c0
    rhs[1] -= f * r0
    diag[-2] -= g * bn
    rhs[-2] -= g * rn
    s = np.empty(n)
    s[1:-1] = _solve_tridiagonal(sub[1:-1], diag[1:-1], sup[1:-1], rhs[1:-1])
    s[0] = (r0 - c0 * s[1]) / a0
    s[-1] = (rn - bn * s[-2]) / an
    return s


@pytest.mark.parametrize("bc", ["not-a-knot", "natural"])
@pytest.mark.parametrize("which", ["s1002", "uic60", "measured", "random"])
def test_c_spline_is_the_numpy_spline_bitwise(which, bc):
    if which == "random":
        rng = np.random.default_rng(12)
        y = np.cumsum(rng.uniform(1e-5, 1e-3, 300)) - 0.1
        z = 1e-3 * rng.standard_normal(300)
    else:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", rr.RollerRigWarning)
            p = (Profile.s1002() if which == "s1002" else Profile.uic60() if which == "uic60"
                 else rr.RigGeometry.measured_pair().roller)
        y, z = np.array(p.y), np.array(p.z)
    q = Profile(y, z, kind="rail", bc=bc)
    s = _numpy_slopes(y, z, bc)
    h, d = np.diff(y), np.diff(z) / np.diff(y)
    c2 = (3.0 * d - 2.0 * s[:-1] - s[1:]) / h
    c3 = (s[:-1] + s[1:] - 2.0 * d) / (h * h)
    assert _same(q._s, s) and _same(q._c2, c2) and _same(q._c3, c3)
    assert _same(q._d2, q.second_derivative(q.y))


def test_binding_refuses_bad_points():
    y = np.linspace(0, 0.01, 10)
    with pytest.raises(ValueError, match="spline_fit: y holds 3 points"):
        _core.spline_fit(y[:3], y[:3], 0)
    with pytest.raises(ValueError, match="spline_fit: y and z differ in length"):
        _core.spline_fit(y, y[:5], 0)
    with pytest.raises(ValueError, match="spline_fit: end must be an integer from 0 to 1"):
        _core.spline_fit(y, y, 2)
    assert _core.spline_fit(y[::-1], y, 0)[0] == -3          # RR_ERR_GEOMETRY
    bad = y.copy()
    bad[4] = np.nan
    st, s, *_ = _core.spline_fit(y, bad, 1)
    assert st == -1 and np.isnan(s).all()
    assert _core.analytic_profile(0, 1.6, -0.01, 0.01, 11)[0] == -9   # alpha > pi/2
    assert _core.analytic_profile(1, 0.005, -0.01, 0.01, 11)[0] == -3  # range beyond R
    with pytest.raises(ValueError, match="rig_table: rows must be an integer from 2"):
        _core.rig_table(*list(DEFAULT.values())[:-1], 1)
    assert _core.rig_table(*list(DEFAULT.values())[:-2], -0.008, 161)[3] == -9
