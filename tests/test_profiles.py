"""Profiles: the readers on the shipped reference files, the cubic spline against
scipy, curvature, smoothing, the standard shapes, and every validation error.

Reference files (rollerrig/data/profiles, copied from CONTACT, github.com/eve70a/CONTACT
commit d431cdbd1250): the Manchester-benchmark S1002 wheel and UIC60 rail (SIMPACK) and a
measured wheel/roller pair of a full-scale roller rig (MiniProf).
"""
import configparser
import math
import os
import pickle
import warnings

import numpy as np
import pytest
from scipy.interpolate import CubicSpline, make_smoothing_spline

import rollerrig as rr
from rollerrig import RollerRigError, RollerRigWarning
from rollerrig.geometry.profiles import DATA_DIR, Profile, read_profile

MM = 1e-3
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def data(name):
    return os.path.join(DATA_DIR, name)


def read_quiet(path, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RollerRigWarning)
        return read_profile(path, **kw)


# ------------------------------------------------------------------ S1002 (SIMPACK .prw)

# S1002 section formulas of the standard (EN 13715 / UIC 510-2), mm, y towards the field
# side, z downward, in the form circulated by H. Netter (DLR Oberpfaffenhofen) and used in
# teaching code (e.g. Lund University, course NUMA41): section A (field-side chamfer),
# 32.15796 <= y <= 60: z = 1.364323640 - 0.066666667 y; section B (tread),
# -26 <= y <= 32.15796: the polynomial below; section G (flange tip), -62.7647 <= y <=
# -49.6625: z = 16 + sqrt(12^2 - (y + 55)^2).  The benchmark file samples these.
S1002_B = [0.0, -3.358537058e-02, 1.565681624e-03, -2.810427944e-05, 5.844240864e-08,
           -1.562379023e-08, 5.309217349e-15, -5.957839843e-12, 2.646656573e-13]


def s1002_b(y_mm, der=0):
    p = np.polynomial.Polynomial(S1002_B).deriv(der)
    return p(y_mm)


def test_s1002_reader_orientation_and_header():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        w = read_profile(data("MBench_S1002_v3.prw"))
    # 400 point rows in the file, the first commented out ('!7.0000000E+01 ...')
    assert len(w) == 399
    assert w.kind == "wheel" and w.name == "MBench_S1002_v3"
    assert w.meta["format"] == "simpack" and w.meta["header.type"] == 1
    assert w.meta["spline.mirror.y"] == 1 and w.meta["spline.inversion"] == 1
    assert w.meta["spline.units.len.f"] == 1000.0
    # mirror.y turns the file's flange-side-positive y into ours; inversion only reorders
    # (the processed points run from +60 to -69.6; the Profile stores them ascending)
    assert w.meta["order"] == "reversed to ascending y"
    assert w.y_min == pytest.approx(-69.612628 * MM, abs=1e-12)
    assert w.y_max == pytest.approx(60.0 * MM, abs=1e-12)
    assert np.all(np.diff(w.y) > 0)
    w2 = Profile.s1002()
    np.testing.assert_array_equal(w2.y, w.y)
    np.testing.assert_array_equal(w2.z, w.z)


def test_s1002_against_the_standard_formulas():
    w = Profile.s1002()
    # tread (section B): the file prints 8 digits (<= 1e-6 mm rounding) and its points are
    # 0.45 mm apart: measured 1.4e-4 um in z, 1.9e-6 in slope, 0.09 % in z''
    y = np.linspace(-25.0, 31.0, 501)
    assert np.max(np.abs(w.z_at(y * MM) - s1002_b(y) * MM)) < 5e-9
    assert np.max(np.abs(w.slope(y * MM) - s1002_b(y, 1))) < 1e-5
    d2 = w.second_derivative(y * MM) * MM
    assert np.max(np.abs(d2 - s1002_b(y, 2))) < 5e-3 * np.max(np.abs(s1002_b(y, 2)))
    # field-side chamfer (section A), slope -1/15: measured 1.0e-3 um, 6.3e-6
    y = np.linspace(33.0, 59.5, 101)
    assert np.max(np.abs(w.z_at(y * MM) - (1.364323640 - 0.066666667 * y) * MM)) < 1e-8
    assert np.max(np.abs(w.slope(y * MM) + 0.066666667)) < 5e-5
    # flange tip (section G, R = 12 mm): convex seen from the rail, so kappa = -1/R
    y = np.linspace(-60.0, -51.0, 91)
    z = 16.0 + np.sqrt(144.0 - (y + 55.0) ** 2)
    assert np.max(np.abs(w.z_at(y * MM) - z * MM)) < 1e-8
    np.testing.assert_allclose(w.curvature(y * MM), -1.0 / (12.0 * MM), rtol=5e-3)


def test_s1002_taping_line_and_flange():
    w = Profile.s1002()
    # taping line: y = 0, z = 0 (the standard's section B has no constant term)
    assert abs(w.z_at(0.0)) < 1e-9
    # tread slope at the taping line: dz/dy = -0.0335854, i.e. 1:29.8 (not 1:40): the radius
    # shrinks towards the field side (z rises, z being downward)
    assert w.slope(0.0) == pytest.approx(-3.358537e-2, abs=1e-6)
    # flange tip 28 mm below the taping line at y = -55 mm (fine grid, 1 um steps)
    y = np.linspace(-60e-3, -50e-3, 10001)
    z = w.z_at(y)
    assert y[np.argmax(z)] == pytest.approx(-55.0 * MM, abs=2e-6)
    assert z.max() == pytest.approx(28.0 * MM, abs=1e-8)
    # flange back ends the profile near y = -70 mm (back-to-back 1360, taping lines 1500)
    assert -70.0 * MM < w.y_min < -69.5 * MM
    # the wheel's lowest point is its flange, on the gauge side (y < 0)
    assert w.y[np.argmax(w.z)] < 0.0


# ------------------------------------------------------------------ UIC60 (SIMPACK .prr)

def test_uic60_reader_and_crown():
    r = read_profile(data("MBench_UIC60_v3.prr"))
    assert len(r) == 495 and r.kind == "rail"
    assert r.meta["header.type"] == 0 and r.meta["spline.mirror.y"] == 0
    assert "order" not in r.meta                       # already ascending
    assert r.y_min == pytest.approx(-43.704898 * MM) and r.y_max == pytest.approx(30.595912 * MM)
    # top of the head: z = 0 at y = -0.18 mm
    i = int(np.argmin(r.z))
    assert abs(r.z[i]) < 1e-7 and abs(r.y[i]) < 0.5 * MM
    # UIC60 head: crown R300 between R80 arcs, R13 gauge and field corners.  The benchmark
    # rail is canted 1:40, which moves the rail's axis 300/40 = 7.5 mm to the gauge side of
    # the top: the R300 arc spans y = -16.5 .. +1.5 mm here (not |y| < 10 mm).  Inside each
    # arc the spline's curvature is within 0.3 % (measured); 1 % allowed.
    for (lo, hi), R in (((-15.0, 0.0), 300.0), ((-30.0, -20.0), 80.0), ((5.0, 17.0), 80.0),
                        ((-42.0, -35.0), 13.0), ((20.0, 28.0), 13.0)):
        y = np.linspace(lo, hi, 41) * MM
        np.testing.assert_allclose(r.curvature(y), 1.0 / (R * MM), rtol=1e-2,
                                   err_msg=f"R{R:g} over {lo} .. {hi} mm")
    # the rail's gauge face is at the negative-y end: there the profile goes deepest
    assert r.z_at(r.y_min) > 38.0 * MM


def depth_crossing(p, depth, lo, hi):
    """The y in [lo, hi] where p.z crosses depth (bisection; z monotone there)."""
    up = p.z_at(hi) > p.z_at(lo)
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if (p.z_at(mid) > depth) == up:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def test_wheel_over_rail_conventions():
    """Both profiles in one frame: with the standard track and wheelset dimensions (gauge
    1435 mm at 14 mm below the rail top, flange backs 1360 mm apart, taping line 70 mm from
    the flange back) the centred wheel, moved laterally only, already sits on the rail
    head within 0.2 mm: rail top near z = 0, the tread just above it."""
    w, r = Profile.s1002(), Profile.uic60()
    # S1002 flange thickness: 32.5 mm from the flange back (-70) at 10 mm below the tape
    assert depth_crossing(w, 10 * MM, -55 * MM, 0.0) == pytest.approx(-37.5 * MM, abs=1e-5)
    y_gauge = depth_crossing(r, 14 * MM, r.y_min, 0.0)       # -43.03 mm
    dy = y_gauge + (750.0 - 717.5) * MM                       # taping line over y = -10.5
    placed = w.shifted(dy, 0.0)
    y = np.linspace(r.y_min, r.y_max, 20001)
    gap = r.z_at(y) - placed.z_at(y)
    k = int(np.nanargmin(gap))
    assert abs(gap[k]) < 0.2 * MM                              # measured +0.18 mm
    # the touching point lies on the tread near the taping line and near the rail top
    # (measured: 3.25 mm field side of the taping line, rail y = -7.28 mm)
    assert abs(y[k] - dy) < 10 * MM and abs(y[k]) < 10 * MM
    touching = placed.shifted(0.0, gap[k])
    assert np.nanmin(r.z_at(y) - touching.z_at(y)) == pytest.approx(0.0, abs=1e-15)


# ------------------------------------------------------------------ MiniProf .whl / .ban

@pytest.mark.parametrize("side, n", [("left", 667), ("right", 664)])
def test_miniprof_wheels(side, n):
    with warnings.catch_warnings():
        warnings.simplefilter("error")                 # no folds, no orientation warning
        w = read_profile(data(f"{side}-wheel-v1-pre-dry.whl"))
    assert len(w) == n and w.kind == "wheel" and w.meta["format"] == "miniprof"
    assert w.meta["XYPoints"] == n and w.meta["ColumnDef"] == "X,Y"
    assert w.meta["Side"] == ("%L" if side == "left" else "%R")
    # MiniProf wheels: y = 0 at the flange back, field side positive, z downward; the
    # file lists them from the field side, so they are reversed
    assert w.meta["order"] == "reversed to ascending y"
    assert 0.0 < w.y_min < 0.5 * MM and 143.0 * MM < w.y_max < 143.5 * MM
    tip = int(np.argmax(w.z))
    assert 18.5 * MM < w.y[tip] < 19.5 * MM
    tape = w.meta["WheelDiameterTaperline"] * MM       # 70 mm from the flange back
    z_tape = w.z_at(tape)
    assert abs(z_tape) < 0.5 * MM
    # the flange measures MiniProf computed (from its own fit) agree with the spline of
    # the saved points to 0.2 mm -- a unit slip or a mirror would be off by tens of mm:
    # Sh flange height (measured 0.02 / 0.17 mm off), Sd flange thickness 10 mm above the
    # taping line measured from the flange back (0.02 / 0.08 mm), qR (0.02 / 0.01 mm)
    assert (w.z[tip] - z_tape) == pytest.approx(w.meta["Sh"] * MM, abs=0.2 * MM)
    y = np.linspace(w.y[tip], tape, 20001)
    z = w.z_at(y)
    y_sd = y[np.argmin(np.abs(z - (z_tape + 10 * MM)))]
    assert y_sd == pytest.approx(w.meta["Sd"] * MM, abs=0.1 * MM)
    y_qr = y[np.argmin(np.abs(z - (w.z[tip] - 2 * MM)))]
    assert y_sd - y_qr == pytest.approx(w.meta["qR"] * MM, abs=0.05 * MM)
    # worn tread near the taping line: rising to the field side, steeper than 1:40
    # (measured -0.046 / -0.044)
    assert -0.06 < w.slope(tape) < -0.03


@pytest.mark.parametrize("side, n, folds", [("left", 345, 6), ("right", 329, 4)])
def test_miniprof_rollers_fold(side, n, folds):
    path = data(f"{side}-roller-v1-pre-dry.ban")
    with pytest.warns(RollerRigWarning, match=rf"removed {folds} point\(s\) where the profile "
                                              r"folds back"):
        r = read_profile(path)
    assert r.kind == "rail" and r.meta["XYPoints"] == n
    assert len(r) == n - folds and r.meta["folds_removed"] == folds
    # the fold is the gauge face 17 .. 52 mm below the top, far from any contact
    assert r.z_at(r.y_min) > 17.0 * MM
    # top of the head in the interior, z near 0 (measured -0.27 / -0.23 mm)
    i = int(np.argmin(r.z))
    assert 5 * MM < r.y[i] < 12 * MM and abs(r.z[i]) < 0.5 * MM
    assert r.meta["RailGaugePoint"] == 14
    with pytest.raises(RollerRigError, match=r"folds back \(y steps back at line 3[67]\).*"
                                             r"on_fold='trim'"):
        read_profile(path, on_fold="raise")


# ------------------------------------------------------------------ spline

def random_points(seed, n, noise=0.0):
    """Randomly spaced points (at least 10 um apart) on a random smooth curve, plus
    white noise of the given size [m]."""
    rng = np.random.default_rng(seed)
    y = np.sort(rng.uniform(-0.03, 0.04, n))
    y = y[np.concatenate([[True], np.diff(y) > 1e-5])]
    z = 1e-3 * np.sin(80.0 * y + rng.uniform(0, 6)) + 0.02 * y ** 2 \
        + noise * rng.normal(size=len(y))
    return y, z


@pytest.mark.parametrize("bc", ["not-a-knot", "natural"])
@pytest.mark.parametrize("seed, noise", [(1, 0.0), (2, 0.0), (3, 1e-4)])
def test_spline_matches_scipy(bc, seed, noise):
    y, z = random_points(seed, 60, noise)
    p = Profile(y, z, kind="rail", bc=bc)
    ref = CubicSpline(y, z, bc_type=bc)
    t = np.linspace(y[0], y[-1], 2001)
    # same spline, different solver (Thomas vs banded LU): round-off only.  z ~ 1e-3 m,
    # slopes ~ 0.1, z'' ~ 10 /m: 1e-10 relative to each
    np.testing.assert_allclose(p.z_at(t), ref(t), atol=1e-13)
    np.testing.assert_allclose(p.slope(t), ref(t, 1), atol=1e-10)
    np.testing.assert_allclose(p.second_derivative(t), ref(t, 2), atol=1e-8)
    # exact at the nodes
    np.testing.assert_allclose(p.z_at(y), z, rtol=0, atol=1e-18)


@pytest.mark.parametrize("n", [4, 5, 6])
def test_spline_few_points_matches_scipy(n):
    y = np.linspace(0.0, 0.01, n) + np.linspace(0, 1e-3, n) ** 2
    z = np.cos(300 * y) * 1e-3
    for bc in ("not-a-knot", "natural"):
        p = Profile(y, z, kind="wheel", bc=bc)
        t = np.linspace(y[0], y[-1], 101)
        np.testing.assert_allclose(p.z_at(t), CubicSpline(y, z, bc_type=bc)(t), atol=1e-15)


def test_spline_converges():
    """z converges as h^4 and curvature as h^2 on a smooth profile (halving h divides
    the errors by ~16 and ~4; 12 and 3.5 allowed for the pre-asymptotic range)."""
    def errors(n):
        y = np.linspace(-0.03, 0.03, n)
        p = Profile(y, 1e-3 * np.sin(100 * y), kind="rail")
        t = np.linspace(-0.03, 0.03, 7001)
        z, dz, d2z = 1e-3 * np.sin(100 * t), 0.1 * np.cos(100 * t), -10 * np.sin(100 * t)
        kappa = d2z / (1 + dz ** 2) ** 1.5
        return (np.max(np.abs(p.z_at(t) - z)), np.max(np.abs(p.curvature(t) - kappa)))
    (ez1, ek1), (ez2, ek2) = errors(61), errors(121)
    assert ez1 / ez2 > 12 and ek1 / ek2 > 3.5
    assert ez2 < 1e-8 and ek2 < 0.05


def test_evaluation_shapes_and_range():
    p = Profile.uic60()
    assert isinstance(p.z_at(0.0), float) and isinstance(p.curvature(0.0), float)
    y = np.zeros((3, 4))
    assert p.z_at(y).shape == (3, 4) and p.slope(y).shape == (3, 4)
    z, dz, d2z = p.evaluate([0.0, 1e-3])
    assert z.shape == dz.shape == d2z.shape == (2,)
    # NaN outside [y_min, y_max] and for NaN input; the ends themselves are inside
    out = p.z_at([p.y_min - 1e-9, p.y_max + 1e-9, np.nan])
    assert np.all(np.isnan(out))
    assert np.isfinite(p.z_at(p.y_min)) and p.z_at(p.y_max) == pytest.approx(p.z[-1], abs=1e-15)
    with pytest.raises(RollerRigError, match=r"Profile.z_at: y must be real numbers"):
        p.z_at("a")


# ------------------------------------------------------------------ curvature, shapes

@pytest.mark.parametrize("R", [0.013, 0.08, 0.3, 5.0])
def test_curvature_of_sampled_circle(R):
    # a rail crown of radius R sampled at 0.5 mm over +-R/2 (at most 2.5 cm): kappa = +1/R;
    # the same arc as a wheel surface seen from its material (z -> -z): -1/R.  Spline error
    # O(h^2 / R^2) (measured <= 2.5e-4 for R = 13 mm), 1e-3 allowed away from the ends
    half = min(R / 2, 0.025)
    n = int(round(2 * half / 0.5e-3)) + 1
    y = np.linspace(-half, half, n)
    z = R - np.sqrt(R * R - y * y)
    t = np.linspace(-0.8 * half, 0.8 * half, 201)
    np.testing.assert_allclose(Profile(y, z, kind="rail").curvature(t), 1.0 / R, rtol=1e-3)
    np.testing.assert_allclose(Profile(y, -z, kind="wheel").curvature(t), -1.0 / R,
                               rtol=1e-3)


def test_crowned_and_flat_roller():
    c = Profile.cylinder(y_range=(-0.015, 0.015), crown_radius=0.1)
    assert c.kind == "rail" and c.meta["crown_radius"] == 0.1
    np.testing.assert_allclose(c.curvature(np.linspace(-0.012, 0.012, 25)), 10.0, rtol=1e-3)
    f = Profile.cylinder()
    assert f.z_at(0.01) == 0.0 and f.slope(-0.01) == 0.0 and f.curvature(0.0) == 0.0
    with pytest.raises(RollerRigError, match="beyond the crown radius"):
        Profile.cylinder(y_range=(-0.02, 0.02), crown_radius=0.01)


@pytest.mark.parametrize("alpha", [0.025, 0.05, 0.2, -0.1])
def test_conical_wheel(alpha):
    w = Profile.conical(alpha, y_range=(-0.03, 0.03), r0=0.46 / 5)
    assert w.kind == "wheel" and w.meta["r0"] == pytest.approx(0.092)
    t = np.linspace(-0.03, 0.03, 301)
    # z = -tan(alpha) y: rolling radius r0 + z shrinks towards the field side; a straight
    # line is reproduced by the cubic spline to round-off
    np.testing.assert_allclose(w.slope(t), -math.tan(alpha), rtol=1e-12)
    np.testing.assert_allclose(w.z_at(t), -math.tan(alpha) * t, atol=1e-16)
    np.testing.assert_allclose(w.curvature(t), 0.0, atol=1e-10)
    assert w.z_at(0.0) == pytest.approx(0.0, abs=1e-18)


def test_conical_and_cylinder_arguments():
    with pytest.raises(RollerRigError, match=r"alpha must be within"):
        Profile.conical(2.0)
    with pytest.raises(RollerRigError, match=r"alpha must be a finite number"):
        Profile.conical(float("nan"))
    with pytest.raises(RollerRigError, match=r"y_range must be finite with y_min < y_max"):
        Profile.conical(0.05, y_range=(0.01, -0.01))
    with pytest.raises(RollerRigError, match=r"r0 must be a finite number > 0"):
        Profile.conical(0.05, r0=-1.0)
    with pytest.raises(RollerRigError, match=r"n must be an integer from 4 to 100000"):
        Profile.cylinder(n=3)
    # n = 1e9 allocated gigabytes before any check (the process was killed)
    with pytest.raises(RollerRigError, match=r"n must be an integer from 4 to 100000"):
        Profile.conical(0.05, n=10**9)


# ------------------------------------------------------------------ immutability, copies

def test_shifted_mirrored_immutable_pickle():
    w = Profile.s1002()
    t = np.linspace(-0.05, 0.05, 101)
    s = w.shifted(2e-3, -1e-3)
    np.testing.assert_allclose(s.z_at(t + 2e-3), w.z_at(t) - 1e-3, atol=1e-15)
    assert "shifted" in s.meta["derived"][-1]
    m = w.mirrored()
    assert m.kind == "wheel" and m.y_min == -w.y_max
    np.testing.assert_allclose(m.z_at(-t), w.z_at(t), atol=1e-15)
    np.testing.assert_allclose(m.slope(-t), -w.slope(t), atol=1e-12)
    np.testing.assert_allclose(m.curvature(-t), w.curvature(t), rtol=1e-9, atol=1e-9)
    with pytest.raises(AttributeError, match="immutable"):
        w.kind = "rail"
    with pytest.raises(ValueError):
        w.y[0] = 0.0                                   # read-only array
    with pytest.raises(TypeError):
        w.meta["x"] = 1                                # read-only mapping
    q = pickle.loads(pickle.dumps(w))
    np.testing.assert_array_equal(q.z_at(t), w.z_at(t))
    assert q.name == w.name and dict(q.meta) == dict(w.meta)
    # the caller's arrays are copied, not frozen
    y = np.linspace(0, 0.01, 5)
    Profile(y, y * 0, kind="rail")
    y[0] = -1.0


# ------------------------------------------------------------------ smoothing

def test_smoothing_matches_scipy_smoothing_spline():
    """smoothing = L is scipy's make_smoothing_spline with w = the trapezoid lengths of
    the points and lam = (L / 2 pi)^4 (same objective, independent solver)."""
    y, z = random_points(7, 200, noise=1e-4)
    L = 2e-3
    p = Profile(y, z, kind="rail", smoothing=L)
    assert p.bc == "natural" and p.smoothing == L
    np.testing.assert_array_equal(p.z_input, z)
    h = np.diff(y)
    w = np.concatenate([[h[0] / 2], (h[:-1] + h[1:]) / 2, [h[-1] / 2]])
    ref = make_smoothing_spline(y, z, w=w, lam=(L / (2 * np.pi)) ** 4)
    t = np.linspace(y[0], y[-1], 3001)
    # two solvers of one linear problem (condition ~1e6 here): 1e-11 m on z ~ 1e-3 m
    np.testing.assert_allclose(p.z_at(t), ref(t), atol=1e-11)
    np.testing.assert_allclose(p.z, ref(y), atol=1e-11)


def test_smoothing_transfer_and_polynomials():
    """Gain 1/(1 + (L/W)^4) for a ripple of wavelength W; a cubic passes unchanged."""
    L = 1e-3
    y = np.arange(-0.03, 0.03 + 1e-9, 0.05e-3)
    mid = np.abs(y) < 0.015                            # away from the natural ends
    for W, gain in ((L, 0.5), (4 * L, 1 / (1 + 4.0 ** -4)), (L / 3, 1 / (1 + 3.0 ** 4))):
        z = 1e-5 * np.sin(2 * np.pi * y / W)
        p = Profile(y, z, kind="rail", smoothing=L)
        amp = np.max(np.abs(p.z[mid])) / 1e-5
        # discrete sampling (20 to 60 points per wavelength) shifts the gain by < 1 %
        assert amp == pytest.approx(gain, abs=0.01), W
    cubic = 0.5 * y ** 2 + 3 * y ** 3
    p = Profile(y, cubic, kind="rail", smoothing=L)
    np.testing.assert_allclose(p.z[mid], cubic[mid], atol=1e-14)
    # noise: 1 um white noise on a 300 mm crown sampled every 0.25 mm ruins the raw
    # spline's curvature (error > 1000 %); smoothing over 10 mm brings it back within
    # 10 % (measured at most 4.8 % over 20 noise seeds)
    rng = np.random.default_rng(3)
    yc = np.arange(-0.04, 0.04, 0.25e-3)
    zc = 0.3 - np.sqrt(0.09 - yc ** 2) + 1e-6 * rng.normal(size=yc.size)
    t = np.linspace(-0.01, 0.01, 101)
    raw = Profile(yc, zc, kind="rail").curvature(t)
    smooth = Profile(yc, zc, kind="rail", smoothing=10e-3).curvature(t)
    assert np.max(np.abs(raw * 0.3 - 1)) > 10.0
    assert np.max(np.abs(smooth * 0.3 - 1)) < 0.1


def test_smoothing_arguments_and_copies():
    y, z = random_points(8, 50, noise=1e-4)
    p = Profile(y, z, kind="rail", smoothing=1e-3)
    # shifting and mirroring commute with the smoothing
    np.testing.assert_allclose(p.shifted(1e-3, 2e-3).z, p.z + 2e-3, atol=1e-14)
    np.testing.assert_allclose(p.mirrored().z, p.z[::-1], atol=1e-14)
    with pytest.raises(RollerRigError, match=r"smoothing spline is natural"):
        Profile(y, z, kind="rail", smoothing=1e-3, bc="not-a-knot")
    with pytest.raises(RollerRigError, match=r"smoothing must be a finite number > 0"):
        Profile(y, z, kind="rail", smoothing=0.0)
    r = Profile.uic60(smoothing=0.5e-3)
    assert r.curvature(-7.5e-3) == pytest.approx(1 / 0.3, rel=1e-3)


# ------------------------------------------------------------------ constructor checks

@pytest.mark.parametrize("y, z, kw, match", [
    ([0, 1e-3, 2e-3], [0, 0, 0], {}, r"3 point\(s\); a profile has from 4 to 100000"),
    (np.linspace(0, 1, 100001), np.zeros(100001), {}, r"100001 point\(s\); a profile has"),
    ([0, 1e-3, 1e-3, 2e-3], [0, 0, 1e-4, 0], {}, r"duplicate y at index 2"),
    ([0, 2e-3, 1e-3, 3e-3], [0, 0, 0, 0], {}, r"y decreases at index 2"),
    ([0, 1e-3, 2e-3, np.nan], [0, 0, 0, 0], {}, r"non-finite value at index 3"),
    ([0, 1e-3, 2e-3, 3e-3], [0, 0, 0], {}, r"1-D arrays of one length"),
    (["a", "b", "c", "d"], [0, 0, 0, 0], {}, r"y must be real numbers"),
    ([0, 10, 20, 30], [0, 0, 0, 0], {}, r"beyond 2 m: .*millimetres read as metres"),
    ([0, 1e-5, 2e-5, 3e-5], [0, 0, 0, 0], {}, r"y spans only 3e-05 m.*metres read as milli"),
    ([0, 1e-3, 2e-3, 3e-3], [0, 0, 0, 0], {"kind": "roller"}, r"kind must be 'wheel' or"),
    ([0, 1e-3, 2e-3, 3e-3], [0, 0, 0, 0], {"bc": "clamped"}, r"bc must be"),
])
def test_constructor_errors(y, z, kw, match):
    kw = {"kind": "rail", **kw}
    with pytest.raises(RollerRigError, match=match):
        Profile(y, z, **kw)


def test_gaps_beyond_the_doubles_are_the_scale_error_without_a_warning():
    # y's gaps overflow (3.4e308 m): the scale check's error, and no
    # RuntimeWarning from the gaps before it (a property test's find)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(RollerRigError, match=r"beyond 2 m"):
            Profile([-1.7e308, 1.7e308, 1.71e308, 1.72e308], [0, 0, 0, 0], kind="rail")


def test_from_points():
    y = np.array([3.0, 2.0, 1.0, 0.0, -1.0])
    p = Profile.from_points(y, y ** 2, kind="rail", units="mm")
    np.testing.assert_allclose(p.y, [-1e-3, 0, 1e-3, 2e-3, 3e-3])
    assert p.meta["order"] == "reversed to ascending y"
    with pytest.warns(RollerRigWarning, match=r"removed 1 point\(s\).*point 4"):
        q = Profile.from_points([0, 1, 2, 3, 2.5, 4, 5], [3, 1, 0, 1, 2, 4, 6], kind="rail",
                                units="mm")
    assert len(q) == 6
    with pytest.raises(RollerRigError, match=r"Profile.from_points: duplicate y = 0.002 m "
                                             r"at point 2 and point 3"):
        Profile.from_points([0, 1, 2, 2, 3], [1, 0.5, 0, 0.5, 1], kind="rail", units="mm")
    with pytest.raises(RollerRigError, match="units must be one of"):
        Profile.from_points([0, 1, 2, 3], [0, 0, 0, 0], kind="rail", units="inch")


# ------------------------------------------------------------------ validation on files

def write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


GOOD_ROWS = "0 0\n1 -0.1\n2 -0.3\n3 -0.6\n4 -1.0\n"


@pytest.mark.parametrize("text, kw, match", [
    ("0 0\n1 abc\n2 1\n3 2\n", {}, r"line 2: expected two numbers"),
    ("0 0\n1 nan\n2 1\n3 2\n", {}, r"line 2: non-finite value nan"),
    ("0 0\n1 inf\n2 1\n3 2\n", {}, r"line 2: non-finite value inf"),
    ("0 0\n1 0.5\n2 1\n", {}, r"3 point\(s\); a profile needs at least 4"),
    ("0 0\n1 0.5\n1 0.7\n2 1\n3 2\n", {}, r"duplicate y = 0.001 m at line 2 and line 3"),
    ("0 0\n1 0.5 7\n2 1\n3 2\n", {}, r"line 2: expected two numbers 'lateral vertical', got 3"),
    ("0 0\n1 1\n2 0.5\n1.5 0.7\n3 1\n", {"on_fold": "raise"},
     r"1 point\(s\) where the profile folds back \(y steps back at line 4\)"),
    (GOOD_ROWS, {"kind": None}, r"kind unknown: pass kind="),
    (GOOD_ROWS, {"units": "m"},
     r"coordinate 4 m at line 5 is beyond 2 m: the numbers look like millimetres"),
    ("0 0\n0.001 0\n0.002 0.0001\n0.003 0.0003\n", {},
     r"the profile's y spans only 3e-06 m .*metres read as millimetres \(units='m'\)"),
    ("# units = m\n" + GOOD_ROWS, {"units": "mm"}, r"units = 'mm' contradicts the file's"),
    ("# kind = wheel\n" + GOOD_ROWS, {}, r"kind = 'rail' contradicts the file's kind = 'wheel'"),
    (GOOD_ROWS, {"units": "furlong"}, r"units must be one of"),
    (GOOD_ROWS, {"on_fold": "keep"}, r"on_fold must be 'trim' or 'raise'"),
    ("", {}, r"no points"),
])
def test_text_validation_errors(tmp_path, text, kw, match):
    path = write(tmp_path, "p.txt", text)
    kw = {"kind": "rail", **kw}
    with pytest.raises(RollerRigError, match=r"read_profile: .*p\.txt: " + match):
        read_profile(path, **kw)


def test_text_fold_trimmed_with_warning(tmp_path):
    path = write(tmp_path, "fold.csv",
                 "y,z\n0,5\n0.5,2\n1,1\n2,0\n3,1\n4,3\n3.9,6\n3.95,7\n4.1,9\n")
    with pytest.warns(RollerRigWarning, match=r"fold\.csv: removed 2 point\(s\) where the "
                                              r"profile folds back \(y steps back at line 8\)"):
        p = read_profile(path, kind="rail")
    assert p.meta["columns"] == "y z" and p.meta["folds_removed"] == 2
    np.testing.assert_allclose(p.y * 1e3, [0, 0.5, 1, 2, 3, 4, 4.1])


def test_text_round_trip(tmp_path):
    w = Profile.s1002()
    for units in ("mm", "m"):
        path = str(tmp_path / f"s1002_{units}.txt")
        w.write_text(path, units=units)
        q = read_profile(path)                         # kind, units, name from the header
        assert q.kind == "wheel" and q.name == w.name and q.meta["units"] == units
        # mm: one multiplication and one division by 1000 (<= 2 ulp); m: exact
        np.testing.assert_allclose(q.y, w.y, rtol=5e-16, atol=0)
        np.testing.assert_allclose(q.z, w.z, rtol=5e-16, atol=1e-30)
        t = np.linspace(-0.06, 0.05, 111)
        np.testing.assert_allclose(q.z_at(t), w.z_at(t), rtol=1e-13, atol=1e-18)
    s = Profile.uic60(smoothing=1e-3)
    path = str(tmp_path / "smooth.dat")
    s.write_text(path)
    q = read_profile(path)
    assert q.bc == "natural" and q.smoothing is None   # the smoothed nodes, natural spline
    t = np.linspace(-0.04, 0.03, 71)
    np.testing.assert_allclose(q.z_at(t), s.z_at(t), atol=1e-15)


def test_text_mirrored_wheel_warns(tmp_path):
    path = str(tmp_path / "w.txt")
    Profile.s1002().mirrored().write_text(path)
    with pytest.warns(RollerRigWarning, match=r"flange .* lies on the field-side half"):
        read_profile(path)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        back = read_profile(path, mirror_y=True)
    assert back.meta["mirrored"] == "y"
    np.testing.assert_allclose(back.z, Profile.s1002().z, atol=1e-15)


SIMPACK = """! test file
  header.begin
    version = 1
    type    = {type}        ! 0=rail, 1=wheel
  header.end
  spline.begin
    comment = 'a test! with a bang'
{keys}
    point.begin
    ! y z
{points}
    point.end
  spline.end
"""
PTS = "10 0.5\n20 0.1\n30 0.0\n40 0.2\n50 0.9\n"


def simpack(tmp_path, keys="    units.len.f = 1000", points=PTS, type=0, name="t.prr"):
    return write(tmp_path, name, SIMPACK.format(type=type, keys=keys, points=points))


def test_simpack_processing_order(tmp_path):
    """shift (file units) -> mirror -> inversion -> units, as the numbers beside the keys."""
    keys = ("    shift.y = 1\n    shift.z = -0.1\n    mirror.y = 1\n    mirror.z = 0\n"
            "    inversion = 1\n    units.len.f = +1.000e+03")
    p = read_profile(simpack(tmp_path, keys))
    np.testing.assert_allclose(p.y * 1e3, [-51, -41, -31, -21, -11])
    np.testing.assert_allclose(p.z * 1e3, [0.8, 0.1, -0.1, 0.0, 0.4], atol=1e-12)
    assert p.meta["spline.comment"] == "a test! with a bang"
    # mirror.z
    keys = "    mirror.z = 1\n    units.len.f = 1000"
    p = read_profile(simpack(tmp_path, keys))
    np.testing.assert_allclose(p.z * 1e3, [-0.5, -0.1, 0.0, -0.2, -0.9], atol=1e-12)
    # rotation about x from y towards z, here 2 degrees given in degrees (units.ang.f =
    # 180/pi degrees per rad), applied after the shift and before the mirroring
    keys = ("    rotate = 2\n    units.ang.f = 57.29577951308232\n    shift.y = 5\n"
            "    mirror.y = 1\n    units.len.f = 1000")
    p = read_profile(simpack(tmp_path, keys))
    a = math.radians(2.0)
    y0 = np.array([10, 20, 30, 40, 50.0]) + 5
    z0 = np.array([0.5, 0.1, 0.0, 0.2, 0.9])
    yr, zr = y0 * math.cos(a) - z0 * math.sin(a), y0 * math.sin(a) + z0 * math.cos(a)
    np.testing.assert_allclose(p.y * 1e3, -yr[::-1], rtol=1e-14)
    np.testing.assert_allclose(p.z * 1e3, zr[::-1], rtol=1e-14)
    # bound.y drops points outside, bound.z clips
    keys = ("    bound.y.min = 15\n    bound.y.max = 55\n    bound.z.min = 0.05\n"
            "    bound.z.max = 0.5\n    units.len = 'mm'")
    p = read_profile(simpack(tmp_path, keys))
    np.testing.assert_allclose(p.y * 1e3, [20, 30, 40, 50])
    np.testing.assert_allclose(p.z * 1e3, [0.1, 0.05, 0.2, 0.5])
    # without any unit the numbers are metres
    with pytest.raises(RollerRigError, match=r"beyond 2 m"):
        read_profile(simpack(tmp_path, ""))


@pytest.mark.parametrize("keys, points, kw, match", [
    ("    units.len.f = 1000", "10 0.5\n20 x\n30 0\n40 0.2\n", {},
     r"line 12: expected 'y z \[weight\]' numbers"),
    ("    units.len.f = 1000", "10 0.5\n20 nan\n30 0\n40 0.2\n", {}, r"line 12: non-finite"),
    ("    units.len.f = 1000", "10 0.5\n20 0.1 1 2\n30 0\n40 0.2\n", {},
     r"line 12: expected 2 or 3 numbers"),
    ("    units.len.f = 1000", "10 0.5\n20 0.1\n30 0\n", {}, r"3 point\(s\)"),
    ("    units.len.f = 1000", "10 0.5\n20 0.1\n20 0\n40 0.2\n", {},
     r"duplicate y = 0.02 m at line 12 and line 13"),
    ("    units.len.f = 1000\n    mirror.y = 2", PTS, {}, r"mirror.y must be 0 or 1, got 2"),
    ("    units.len.f = -1", PTS, {}, r"units.len.f must be > 0"),
    ("    units.len.f = 1000\n    units.len = 'm'", PTS, {},
     r"units.len = 'm' contradicts units.len.f = 1000"),
    ("    units.len = 'ft'", PTS, {}, r"units.len = 'ft' is not one of"),
    ("    units.len.f = 1000\n    shift.y = abc", PTS, {}, r"shift.y = 'abc' is not a finite number"),
    ("    units.len.f = 1000\n    junk line", PTS, {}, r"line 9: unexpected text"),
    ("    units.len.f = 1000\n    foo.begin", PTS, {}, r"line 9: unknown section 'foo.begin'"),
    ("    units.len.f = 1000", PTS, {"kind": "wheel"},
     r"kind = 'wheel' but the header says type = 0"),
    ("    units.len.f = 1000", PTS, {"units": "mm"}, r"units is for plain text"),
])
def test_simpack_validation_errors(tmp_path, keys, points, kw, match):
    path = simpack(tmp_path, keys, points)
    with pytest.raises(RollerRigError, match=r"read_profile: .*t\.prr: " + match):
        read_profile(path, **kw)


def test_simpack_structure_errors_and_warnings(tmp_path):
    path = write(tmp_path, "a.prw", "header.begin\ntype = 1\nheader.end\n")
    with pytest.raises(RollerRigError, match=r"a\.prw: no points"):
        read_profile(path)
    path = write(tmp_path, "b.prw", "spline.begin\npoint.begin\n1 2\n")
    with pytest.raises(RollerRigError, match=r"b\.prw: file ends inside section 'point'"):
        read_profile(path)
    path = write(tmp_path, "c.prw", "point.begin\n1 2\npoint.end\n")
    with pytest.raises(RollerRigError, match=r"c\.prw: line 1: 'point.begin' out of place"):
        read_profile(path)
    path = write(tmp_path, "d.prw", "header.end\n")
    with pytest.raises(RollerRigError, match=r"d\.prw: line 1: 'header.end' without its"):
        read_profile(path)
    path = write(tmp_path, "d2.prw", "spline.begin\npoint.begin\n1 2\nspline.end\n")
    with pytest.raises(RollerRigError, match=r"line 4: 'spline.end' while section 'point'"):
        read_profile(path)
    path = write(tmp_path, "e.prw", "version = 1\n")
    with pytest.raises(RollerRigError, match=r"e\.prw: line 1: unexpected text"):
        read_profile(path)
    # header type beats the extension, with a warning; SIMPACK smoothing is not applied
    path = simpack(tmp_path, "    units.len.f = 1000\n    approx.smooth = 0.5", name="f.prw")
    with pytest.warns(RollerRigWarning) as rec:
        p = read_profile(path)
    msgs = " | ".join(str(r.message) for r in rec)
    assert "approx.smooth = 0.5" in msgs and "header type says rail" in msgs
    assert p.kind == "rail"


def miniprof(tmp_path, header="ColumnDef=X,Y\nXYPoints=5\n", points=PTS, name="m.ban"):
    return write(tmp_path, name, "ProgramName=MiniProf for Windows\nSide=%L\n" + header
                 + "\n" + points)


@pytest.mark.parametrize("header, points, match", [
    ("ColumnDef=X,Y\nXYPoints=6\n", PTS, r"XYPoints = 6 but the file has 5 points"),
    ("ColumnDef=A,Y\nXYPoints=5\n", PTS, r"ColumnDef = 'A,Y' must name the columns X and Y"),
    ("ColumnDef=X,Y,A\nXYPoints=5\n", PTS, r"line 6: 2 number\(s\) but ColumnDef = 'X,Y,A' "
                                           r"declares 3"),
    ("ColumnDef=X,Y\nXYPoints=5\n", PTS + "Gauge=1435\n", r"line 11: header line"),
    ("ColumnDef=X,Y\nXYPoints=5\n", "10 0.5\n20 0.1\n30 zero\n40 0.2\n50 1\n",
     r"line 8: expected numbers"),
    ("[ProfilePoints]\n", PTS, r"line 3: sections like '\[ProfilePoints\]'"),
])
def test_miniprof_validation_errors(tmp_path, header, points, match):
    with pytest.raises(RollerRigError, match=r"read_profile: .*m\.ban: " + match):
        read_profile(miniprof(tmp_path, header, points))


def test_miniprof_columns_and_separators(tmp_path):
    pts = "9, 10, 1, 0.5\n9, 20, 1, 0.1\n9, 30, 1, 0.0\n9, 40, 1, 0.2\n"
    p = read_profile(miniprof(tmp_path, "ColumnDef=A,X,C,Y\nXYPoints=4\n", pts))
    np.testing.assert_allclose(p.y * 1e3, [10, 20, 30, 40])
    np.testing.assert_allclose(p.z * 1e3, [0.5, 0.1, 0.0, 0.2])
    q = read_profile(miniprof(tmp_path, "XYPoints=5\n"))   # no ColumnDef: X,Y
    np.testing.assert_allclose(q.y * 1e3, [10, 20, 30, 40, 50])


def test_read_profile_general_errors(tmp_path):
    with pytest.raises(RollerRigError, match=r"nofile\.txt: no such file"):
        read_profile(str(tmp_path / "nofile.txt"), kind="rail")
    path = write(tmp_path, "p.xyz", GOOD_ROWS)
    with pytest.raises(RollerRigError, match=r"p\.xyz: unknown extension '\.xyz'"):
        read_profile(path)
    with pytest.raises(RollerRigError, match=r"read_profile: kind must be 'wheel' or 'rail'"):
        read_profile(path, kind="roller")


# ------------------------------------------------------------------ package

def test_package_exports_and_data():
    assert rr.profiles.Profile is rr.Profile and rr.read_profile is read_profile
    names = {"MBench_S1002_v3.prw", "MBench_UIC60_v3.prr", "left-wheel-v1-pre-dry.whl",
             "right-wheel-v1-pre-dry.whl", "left-roller-v1-pre-dry.ban",
             "right-roller-v1-pre-dry.ban"}
    present = set(os.listdir(DATA_DIR))
    assert names <= present and "README.md" in present
    readme = open(os.path.join(DATA_DIR, "README.md")).read()
    assert "eve70a/CONTACT" in readme and "d431cdbd1250" in readme
    for n in names:
        assert n in readme
    cfg = configparser.ConfigParser()
    cfg.read(os.path.join(ROOT, "setup.cfg"))
    assert "data/profiles/*" in cfg["options.package_data"]["rollerrig"].split()


def test_readers_table_is_the_dispatch(tmp_path, monkeypatch):
    # a new format is one reader returning RawProfile and one READERS entry
    from rollerrig.geometry.profiles import READERS, Format, RawProfile
    assert set(READERS) == {".prr", ".prw", ".ban", ".whl", ".txt", ".csv", ".dat"}
    seen = []

    def read_xyz(path, where, kind, units):
        seen.append((path, kind, units))
        y = np.linspace(-0.02, 0.02, 9)
        return RawProfile(y, 1e-3 * y * y, np.arange(1, 10), None, {"source": "xyz"})

    monkeypatch.setitem(READERS, ".xyz", Format("xyz", read_xyz, "rail", False))
    path = tmp_path / "p.xyz"
    path.write_text("anything")
    p = read_profile(path)
    assert seen == [(str(path), None, None)]
    assert p.kind == "rail" and p.meta["format"] == "xyz" and p.meta["source"] == "xyz"
    assert len(p) == 9 and p.name == "p"
    with pytest.raises(RollerRigError, match=r"units is for plain text"):
        read_profile(path, units="mm")
