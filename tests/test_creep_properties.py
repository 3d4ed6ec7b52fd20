"""Physical and numerical properties of the creep-force methods."""
import itertools

import numpy as np
import pytest

import rollerrig as rr
from _options import own

FASTSIMS = ("fastsim", "fastsim_blended", "modified_fastsim")
BOUNDS = ("parabolic", "elliptic")
GRIDS = ("rect", "strips")
G, NU = 8.2e10, 0.28


def random_cases(seed, n=400, spin=True):
    """Random contact cases spanning adhesion to full sliding, a/b from 0.2 to 5."""
    rng = np.random.default_rng(seed)
    aob = 10.0 ** rng.uniform(-0.7, 0.7, n)
    c = 10.0 ** rng.uniform(-3.3, -2, n)            # sqrt(ab): 0.5 to 10 mm
    a, b = c * np.sqrt(aob), c / np.sqrt(aob)
    N = 10.0 ** rng.uniform(2, 5.5, n)
    mu = rng.uniform(0.05, 0.6, n)
    mag = 10.0 ** rng.uniform(-6, -1, n)              # creepage magnitude
    ang = rng.uniform(0, 2 * np.pi, n)
    cx, cy = mag * np.cos(ang), mag * np.sin(ang)
    cphi = (rng.normal(size=n) * mag / c) if spin else np.zeros(n)   # rad/m
    return dict(cx=cx, cy=cy, cphi=cphi, a=a, b=b, N=N, mu=mu)


def forces(case, **kw):
    return rr.creep_forces(case["cx"], case["cy"], case["cphi"], a=case["a"], b=case["b"],
                           N=case["N"], mu=case["mu"], G=G, nu=NU, errors="raise", **kw)


# ------------------------------------------------------------------ the friction bound

@pytest.mark.parametrize("method, bound, grid",
                         list(itertools.product(FASTSIMS, BOUNDS, GRIDS)))
@pytest.mark.parametrize("falling", [False, True], ids=["coulomb", "falling"])
def test_force_bounded_by_mu_N(method, bound, grid, falling):
    case = random_cases(1)
    kw = own(method, bound=bound, grid=grid, nx=12, ny=10)
    if falling:                               # mu(w) <= mu0: the bound still holds
        kw.update(friction=rr.FallingFriction(0.4, 0.6), speed=20.0)
    f = forces(case, **kw)
    # every element traction is clipped to mu p and the pressure sums to N:
    # rounding only, 1e-12 relative
    assert np.all(np.hypot(f.fx, f.fy) <= case["mu"] * case["N"] * (1 + 1e-12))


def test_polach_bounded_by_mu_N():
    case = random_cases(2, spin=False)
    # Polach (2005) has kS <= kA <= 1, which the API enforces; then
    # kA eps/(1 + (kA eps)^2) + atan(kS eps) <= u/(1 + u^2) + atan(u) < pi/2
    # (u = kA eps), so F < mu N.
    for kA, kS in ((1.0, 1.0), (0.6, 0.3), (1.0, 0.05), (0.2, 0.2)):
        f = forces(case, method="polach", kA=kA, kS=kS)
        # F = 2 mu N / pi [kA eps/(1 + (kA eps)^2) + atan(kS eps)] < mu N; 1e-12 rounding
        assert np.all(np.hypot(f.fx, f.fy) <= case["mu"] * case["N"] * (1 + 1e-12))


@pytest.mark.parametrize("method, bound, grid",
                         list(itertools.product(FASTSIMS, BOUNDS, GRIDS)))
def test_full_sliding_gives_mu_N(method, bound, grid):
    case = random_cases(3, n=200, spin=False)
    nx, ny = 15, 11
    # every element slides when the rigid slip over one element, |c| 3 C G / (4 nx),
    # exceeds mu p_max ~ 2 mu N / (pi a b), i.e. |c| >~ 8 nx mu N / (3 pi C G a b):
    # take 10 nx mu N / (G a b) (C >= 2.5)
    scale = (10.0 * nx * case["mu"] * case["N"] / (G * case["a"] * case["b"])
             / np.hypot(case["cx"], case["cy"]))
    case["cx"] = case["cx"] * scale
    case["cy"] = case["cy"] * scale
    f = forces(case, **own(method, bound=bound, grid=grid, nx=nx, ny=ny))
    # every element slides in the same direction at mu p, the pressure sums to N on the
    # grid: |F| = mu N up to rounding, 1e-12 relative
    np.testing.assert_allclose(np.hypot(f.fx, f.fy), case["mu"] * case["N"], rtol=1e-12)
    # and the force opposes the creepage
    assert np.all(f.fx * case["cx"] <= 0) and np.all(f.fy * case["cy"] <= 0)


# ------------------------------------------------------------------ symmetry

@pytest.mark.parametrize("method", FASTSIMS + ("linear", "polach"))
@pytest.mark.parametrize("grid", GRIDS)
def test_odd_symmetry(method, grid):
    """Reversing every creepage reverses every force, bitwise (the computation only
    changes signs)."""
    case = random_cases(4, n=200)
    neg = dict(case, cx=-case["cx"], cy=-case["cy"], cphi=-case["cphi"])
    for kw in ({}, dict(friction=rr.FallingFriction(0.4, 0.6), speed=15.0)):
        if method == "linear" and kw:
            continue
        f1 = forces(case, **own(method, grid=grid, nx=9, ny=8, **kw))
        f2 = forces(neg, **own(method, grid=grid, nx=9, ny=8, **kw))
        np.testing.assert_array_equal(f2.fx, -f1.fx)
        np.testing.assert_array_equal(f2.fy, -f1.fy)
        np.testing.assert_array_equal(f2.mz, -f1.mz)


@pytest.mark.parametrize("method", FASTSIMS)
@pytest.mark.parametrize("grid", GRIDS)
def test_lateral_mirror_symmetry(method, grid):
    """Mirroring y (cy -> -cy, cphi -> -cphi) keeps fx and reverses fy and mz; the rows
    are mirrored exactly but summed in the other order: 1e-12 of mu N (mu N a for mz)."""
    case = random_cases(5, n=200)
    mir = dict(case, cy=-case["cy"], cphi=-case["cphi"])
    f1 = forces(case, **own(method, grid=grid, nx=10, ny=9))
    f2 = forces(mir, **own(method, grid=grid, nx=10, ny=9))
    s = case["mu"] * case["N"]
    np.testing.assert_allclose(f2.fx / s, f1.fx / s, rtol=0, atol=1e-12)
    np.testing.assert_allclose(f2.fy / s, -f1.fy / s, rtol=0, atol=1e-12)
    np.testing.assert_allclose(f2.mz / (s * case["a"]), -f1.mz / (s * case["a"]), rtol=0,
                               atol=1e-12)


# ------------------------------------------------------------------ small creepage

@pytest.mark.parametrize("grid", GRIDS)
@pytest.mark.parametrize("aob", [0.3, 1.0, 3.0])
def test_small_creepage_slope_converges_to_linear_theory(grid, aob):
    """FASTSIM's initial slope exceeds G a b C11 (C22) by about 1/nx (Kalker's explicit
    scheme, first order in the grid): 0 < ratio - 1 < 2/nx, and the excess falls as
    the grid is refined."""
    a, b, N, mu = 5e-3 * np.sqrt(aob), 5e-3 / np.sqrt(aob), 1e4, 0.3
    k = rr.kalker_coefficients(aob, NU)
    cr = 1e-9                        # far below saturation: no element slips
    prev = None
    for n in (10, 20, 40, 80):
        fx = rr.creep_forces(cr, 0, 0, a=a, b=b, N=N, mu=mu, G=G, nu=NU, nx=n, ny=n,
                             grid=grid).fx
        fy = rr.creep_forces(0, cr, 0, a=a, b=b, N=N, mu=mu, G=G, nu=NU, nx=n, ny=n,
                             grid=grid).fy
        ex = fx / (-G * a * b * k.c11 * cr) - 1.0
        ey = fy / (-G * a * b * k.c22 * cr) - 1.0
        # measured: strips (1 + 1/n), rect (1.1 .. 1.6)/n with the staircase boundary
        assert 0 < ex < 2.0 / n, (n, ex)
        assert 0 < ey < 2.0 / n, (n, ey)
        if prev is not None:
            assert ex < prev[0] and ey < prev[1], (n, ex, ey, prev)
        prev = (ex, ey)


def test_small_creepage_variants():
    """Blended FASTSIM equals FASTSIM at vanishing creepage (the blend weight is
    ~1e-6 here), modified FASTSIM has its slope reduced by k0."""
    a, b, N, mu = 6e-3, 4e-3, 2e4, 0.3
    cr = 1e-9
    base = rr.creep_forces(cr, cr, 0.0, a=a, b=b, N=N, mu=mu)
    blended = rr.creep_forces(cr, cr, 0.0, a=a, b=b, N=N, mu=mu, method="fastsim_blended")
    # w ~ |creepage| G c^2 C / (3 mu N) ~ 1e-6 moves the flexibilities by that: 1e-5
    assert blended.fx == pytest.approx(base.fx, rel=1e-5)
    assert blended.fy == pytest.approx(base.fy, rel=1e-5)
    for k0 in (0.54, 0.8):
        mod = rr.creep_forces(cr, cr, 0.0, a=a, b=b, N=N, mu=mu, method="modified_fastsim",
                              k0=k0)
        # k = k0 (alpha + (1 - alpha)/(1 + beta eps)), eps ~ 1e-6: 1e-5
        assert mod.fx == pytest.approx(k0 * base.fx, rel=1e-5)
        assert mod.fy == pytest.approx(k0 * base.fy, rel=1e-5)


@pytest.mark.parametrize("aob", [0.25, 1.0, 4.0])
def test_polach_small_creepage_is_linear_theory(aob):
    a, b, N, mu = 5e-3 * np.sqrt(aob), 5e-3 / np.sqrt(aob), 1e4, 0.3
    c = np.sqrt(a * b)
    k = rr.kalker_coefficients(aob, NU)
    kw = dict(a=a, b=b, N=N, mu=mu, G=G, nu=NU, method="polach")
    cr = 1e-9
    # relative deviation (2/3) eps^2 with eps ~ 1e-6: 1e-9
    assert rr.creep_forces(cr, 0, 0, **kw).fx == pytest.approx(-G * a * b * k.c11 * cr, rel=1e-9)
    assert rr.creep_forces(0, cr, 0, **kw).fy == pytest.approx(-G * a * b * k.c22 * cr, rel=1e-9)
    # combined creepage: Polach uses one coefficient C = |(C11 cx, C22 cy)|/|(cx, cy)| along
    # the creepage direction, so only the magnitude equals the linear theory's
    f = rr.creep_forces(cr, 0.6 * cr, 0, **kw)
    lin = rr.creep_forces(cr, 0.6 * cr, 0, **dict(kw, method="linear"))
    assert np.hypot(f.fx, f.fy) == pytest.approx(np.hypot(lin.fx, lin.fy), rel=1e-9)
    # reduction factors: small-creepage slope times (kA + kS)/2
    for kA, kS in ((1.0, 0.5), (0.7, 0.2)):
        fr = rr.creep_forces(cr, 0, 0, kA=kA, kS=kS, **kw)
        assert fr.fx == pytest.approx(-G * a * b * k.c11 * cr * (kA + kS) / 2, rel=1e-9)
    # spin limit: Polach's spin force tends to Kalker's -G c^3 C23 cphi; relative
    # deviation ~ eps_M with cphi = 1e-6 rad/m: 1e-9 (measured 1e-11)
    cphi = 1e-6
    fs = rr.creep_forces(0, 0, cphi, **kw)
    assert fs.fy == pytest.approx(-G * c ** 3 * k.c23 * cphi, rel=1e-9)
    assert fs.fx == 0.0 and fs.mz == 0.0           # Polach gives no spin moment


def test_linear_theory_formulas():
    a, b, N = 7e-3, 3e-3, 1e4
    c = np.sqrt(a * b)
    k = rr.kalker_coefficients(a / b, NU)
    cx, cy, cphi = 1e-3, -2e-3, 0.5
    f = rr.creep_forces(cx, cy, cphi, a=a, b=b, N=N, mu=0.3, G=G, nu=NU, method="linear")
    # the documented formulas, other operation order: 1e-13
    assert f.fx == pytest.approx(-G * c ** 2 * k.c11 * cx, rel=1e-13)
    assert f.fy == pytest.approx(-G * c ** 2 * k.c22 * cy - G * c ** 3 * k.c23 * cphi, rel=1e-13)
    assert f.mz == pytest.approx(G * c ** 3 * k.c23 * cy - G * c ** 4 * k.c33 * cphi, rel=1e-13)


# ------------------------------------------------------------------ falling friction

@pytest.mark.parametrize("method, slip_speed", [
    ("fastsim", "local"), ("fastsim", "rigid"), ("fastsim_blended", "local"),
    ("modified_fastsim", "rigid"), ("modified_fastsim", "local"), ("polach", None)])
def test_falling_friction_peaks_then_falls_to_kinetic(method, slip_speed):
    a, b, N, mu0 = 5e-3, 4e-3, 1e4, 0.4
    fr = rr.FallingFriction(A=0.4, B=0.6)
    cx = np.geomspace(1e-5, 20.0, 80)
    f = rr.creep_forces(cx, a=a, b=b, N=N, mu=mu0, G=G, nu=NU, speed=10.0, friction=fr,
                        errors="raise", **own(method, nx=20, ny=20, slip_speed=slip_speed))
    F = np.abs(f.fx) / (mu0 * N)
    i = int(np.argmax(F))
    assert 0 < i < cx.size - 1, "the peak must lie inside the creepage range"
    # Coulomb would saturate at 1; falling friction peaks clearly above the kinetic
    # level A and falls back toward it
    assert F[i] > fr.A + 0.3
    assert np.all(np.diff(F[:i + 1]) >= 0)
    # monotone fall past the peak, up to rounding noise on the plateau (1e-12)
    assert np.all(np.diff(F[i:]) <= 1e-12)
    # at cx = 20, 10 m/s the slip speed is 200 m/s: exp(-0.6 * 200) = 1e-52, so mu = A mu0
    # and the force is A mu0 N up to rounding (FASTSIM: full sliding) or the last
    # atan(eps) deficit (Polach, ~1e-11): 1e-9
    assert F[-1] == pytest.approx(fr.A, rel=1e-9)


def test_falling_friction_needs_speed_only_when_falling():
    kw = dict(a=5e-3, b=4e-3, N=1e4, mu=0.3)
    # A = 1 or B = 0 is Coulomb: no speed needed, same result as no friction law
    for fr in (rr.FallingFriction(A=1.0, B=0.6), rr.FallingFriction(A=0.4, B=0.0)):
        f = rr.creep_forces(2e-3, friction=fr, **kw)
        g = rr.creep_forces(2e-3, **kw)
        assert (f.fx, f.fy, f.mz) == (g.fx, g.fy, g.mz)


# ------------------------------------------------------------------ traction field

@pytest.mark.parametrize("method, bound, grid",
                         list(itertools.product(FASTSIMS, BOUNDS, GRIDS)))
def test_traction_field_sums_to_forces(method, bound, grid):
    a, b, N, mu = 6e-3, 4.5e-3, 3e4, 0.35
    for cx, cy, cphi, kw in ((1e-3, -5e-4, 0.8, {}),
                             (2e-4, 1e-4, -0.3,
                              dict(friction=rr.FallingFriction(0.5, 0.8), speed=5.0))):
        t = rr.fastsim_field(cx, cy, cphi, a=a, b=b, N=N, mu=mu, method=method, bound=bound,
                             grid=grid, nx=17, ny=13, **kw)
        assert t.px.shape == t.area.shape == (13, 17)
        s = mu * N
        # the C core sums the same element values row by row: rounding, 1e-12 of mu N
        assert np.sum(t.px * t.area) == pytest.approx(t.fx, abs=1e-12 * s)
        assert np.sum(t.py * t.area) == pytest.approx(t.fy, abs=1e-12 * s)
        assert np.sum((t.x * t.py - t.y * t.px) * t.area) == pytest.approx(t.mz,
                                                                           abs=1e-12 * s * a)
        # the pressure is scaled to sum to N on the grid: 1e-12
        assert np.sum(t.pn * t.area) == pytest.approx(N, rel=1e-12)
        # every element within its bound (1e-12), empty elements carry nothing
        assert np.all(np.hypot(t.px, t.py) <= mu * t.pn * (1 + 1e-12))
        assert not np.any(t.slip[t.pn == 0])
        # same forces as creep_forces (same C routine): bitwise
        f = rr.creep_forces(cx, cy, cphi, a=a, b=b, N=N, mu=mu, method=method, bound=bound,
                            grid=grid, nx=17, ny=13, **kw)
        assert (f.fx, f.fy, f.mz) == (t.fx, t.fy, t.mz)
        # layout: rows at increasing y, columns at increasing x
        assert np.all(np.diff(t.y[:, 0]) > 0) and np.all(np.diff(t.x, axis=1) > 0)
