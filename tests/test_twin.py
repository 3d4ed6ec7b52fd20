"""The C core against tests/twin.py, the pure-Python twin, function by function.

Each twin function is compared with the C function it mirrors, on seeded
random cases, with its tolerance and the reason for it next to the check:

    twin.kalker       rr.kalker_coefficients
    twin.friction_mu  rr.FallingFriction.mu, and the C friction law through
                      creep_forces at full sliding (rr_friction_mu has no binding)
    twin.linear       rr.creep_forces(method="linear")
    twin.polach       rr.creep_forces(method="polach")
    twin.fastsim      rr.creep_forces(method="fastsim" | "fastsim_blended" |
                      "modified_fastsim"), and with field=True rr.fastsim_field

Each C call passes only the options its method has (creep_forces refuses
the others): none for linear; speed, friction, kA, kS for polach; nx, ny,
bound, grid, speed, friction, slip_speed for the FASTSIM variants, blend_rule
for blended FASTSIM, and k0, alpha_inf, beta for modified FASTSIM.  A twin that no longer follows the C
core fails here; nothing is skipped.
"""
import zlib

import numpy as np
import pytest

import rollerrig as rr
import twin

G = 8.2e10

# C method name -> the twin's fastsim variant
VARIANTS = {"fastsim": "fastsim", "fastsim_blended": "blended",
            "modified_fastsim": "modified"}


def seed(*parts):
    return zlib.crc32("/".join(map(str, parts)).encode())


def ellipse(rng):
    """(a, b, c = sqrt(ab)) of a random contact ellipse, 0.2 <= a/b <= 5."""
    aob = 10.0 ** rng.uniform(-0.7, 0.7)
    c = 10.0 ** rng.uniform(-3.3, -2.2)
    return c * np.sqrt(aob), c / np.sqrt(aob), c


def creepages(rng, c):
    mag = 10.0 ** rng.uniform(-5, -1.5)
    ang = rng.uniform(0, 2 * np.pi)
    return mag * np.cos(ang), mag * np.sin(ang), rng.normal() * mag / c


def friction_law(rng, falling):
    """(A, B, speed, FallingFriction or None) of a random friction law."""
    if not falling:
        return 1.0, 0.0, 0.0, None
    A, B = rng.uniform(0.2, 0.9), rng.uniform(0.1, 2.0)
    return A, B, rng.uniform(1.0, 30.0), rr.FallingFriction(A, B)


# ------------------------------------------------------------------ Kalker

KALKER_RATIOS = np.concatenate([np.geomspace(1e-3, 1e3, 121),      # asymptotes and table
                                np.arange(1, 11) / 10.0,            # the table's nodes
                                10.0 / np.arange(1, 11), [1 / 3, 0.05, 20.0]])


@pytest.mark.parametrize("nu", [0.0, 0.1, 0.25, 0.28, 0.4, 0.5])
def test_kalker_matches_c(nu):
    k = rr.kalker_coefficients(KALKER_RATIOS, nu)
    for i, aob in enumerate(KALKER_RATIOS):
        c11, c22, c23, c33 = twin.kalker(float(aob), nu)
        # the same table, interpolation in g, parabola in 1/C over nu and asymptotes
        # below g = 0.1, in the C order of operations: 1e-14 relative (bitwise today)
        assert c11 == pytest.approx(k.c11[i], rel=1e-14, abs=0), (aob, nu)
        assert c22 == pytest.approx(k.c22[i], rel=1e-14, abs=0), (aob, nu)
        assert c23 == pytest.approx(k.c23[i], rel=1e-14, abs=0), (aob, nu)
        assert c33 == pytest.approx(k.c33[i], rel=1e-14, abs=0), (aob, nu)


# ------------------------------------------------------------------ friction law

def test_friction_mu_matches_falling_friction():
    rng = np.random.default_rng(seed("friction", "python"))
    for _ in range(200):
        mu0, A, B, w = rng.uniform(0.1, 0.6), rng.uniform(0.01, 1.0), rng.uniform(0, 5), \
            10.0 ** rng.uniform(-4, 2)
        # the same formula mu0 [(1 - A) exp(-B w) + A], the same operations: 1e-15
        # relative (a different exp would still be within a few ulp)
        assert twin.friction_mu(w, mu0, A, B) == pytest.approx(
            float(rr.FallingFriction(A, B).mu(mu0, w)), rel=1e-15, abs=0), (mu0, A, B, w)


def test_friction_mu_matches_c_at_full_sliding():
    """FASTSIM with slip_speed="rigid" and a creepage so large that every
    element slips gives |F| = mu(speed |cx|) N: the C friction law."""
    rng = np.random.default_rng(seed("friction", "c"))
    for _ in range(100):
        mu0, A, B, speed = rng.uniform(0.1, 0.5), rng.uniform(0.05, 1.0), \
            rng.uniform(0, 5), rng.uniform(0.5, 30)
        cx, N = rng.uniform(0.2, 1.0), 1e4
        f = rr.creep_forces(cx, a=5e-3, b=5e-3, N=N, mu=mu0, method="fastsim", nx=10, ny=10,
                            speed=speed, friction=rr.FallingFriction(A, B),
                            slip_speed="rigid", errors="raise")
        mu = twin.friction_mu(speed * cx, mu0, A, B)
        # the pressure is scaled to sum to N over the 10 x 10 elements; every one at
        # its bound mu pn sums to mu N up to the rounding of ~100 additions: 1e-13
        assert np.hypot(f.fx, f.fy) / N == pytest.approx(mu, rel=1e-13, abs=0), \
            (mu0, A, B, speed, cx)


# ------------------------------------------------------------------ linear theory

def test_linear_matches_c():
    rng = np.random.default_rng(seed("linear"))
    for i in range(300):
        a, b, c = ellipse(rng)
        cx, cy, cphi = creepages(rng, c)
        N, nu = 10.0 ** rng.uniform(3, 5), rng.uniform(0.0, 0.5)
        f = rr.creep_forces(cx, cy, cphi, a=a, b=b, N=N, mu=0.3, G=G, nu=nu, method="linear",
                            errors="raise")
        fx, fy, mz = twin.linear(cx, cy, cphi, a, b, N, G, nu)
        # products of the same coefficients in the C order: 1e-14 of the force
        # scale G ab (|cx| + |cy| + |cphi| c) (G ab c for the moment; bitwise today)
        s = G * a * b * (abs(cx) + abs(cy) + abs(cphi) * c)
        assert abs(f.fx - fx) <= 1e-14 * s, (i, f, fx)
        assert abs(f.fy - fy) <= 1e-14 * s, (i, f, fy)
        assert abs(f.mz - mz) <= 1e-14 * s * c, (i, f, mz)


# ------------------------------------------------------------------ Polach

@pytest.mark.parametrize("falling", [False, True])
def test_polach_matches_c(falling):
    rng = np.random.default_rng(seed("polach", falling))
    for i in range(300):
        a, b, c = ellipse(rng)
        cx, cy, cphi = creepages(rng, c)
        N, mu, nu = 10.0 ** rng.uniform(3, 5), rng.uniform(0.1, 0.5), rng.uniform(0.0, 0.5)
        A, B, speed, friction = friction_law(rng, falling)
        kA = rng.uniform(0.2, 1.0)
        kS = rng.uniform(0.05, kA)
        f = rr.creep_forces(cx, cy, cphi, a=a, b=b, N=N, mu=mu, G=G, nu=nu, method="polach",
                            speed=speed, friction=friction, kA=kA, kS=kS, errors="raise")
        fx, fy, mz = twin.polach(cx, cy, cphi, a, b, N, mu, G, nu, speed=speed, A=A, B=B,
                                 kA=kA, kS=kS)
        s = mu * N
        # the same closed formulas; hypot, atan and exp may round an ulp apart:
        # 1e-13 of mu N (measured: 3e-16)
        assert abs(f.fx - fx) <= 1e-13 * s, (i, f, fx)
        assert abs(f.fy - fy) <= 1e-13 * s, (i, f, fy)
        # Polach's method has no spin moment, in C and in the twin
        assert f.mz == 0.0 and mz == 0.0, (i, f, mz)


# ------------------------------------------------------------------ FASTSIM

def fastsim_cases(method, bound, grid, n=50):
    """(C keywords, twin keywords) per random case; each side gets only the
    options the method has."""
    rng = np.random.default_rng(seed(method, bound, grid))
    for _ in range(n):
        a, b, c = ellipse(rng)
        cx, cy, cphi = creepages(rng, c)
        A, B, speed, friction = friction_law(rng, rng.random() < 0.4)
        case = dict(cx=cx, cy=cy, cphi=cphi, a=a, b=b, N=10.0 ** rng.uniform(3, 5),
                    mu=rng.uniform(0.1, 0.5), G=G, nu=rng.uniform(0.0, 0.45))
        grid_opts = dict(nx=int(rng.integers(3, 13)), ny=int(rng.integers(3, 13)),
                         bound=bound, grid=grid, speed=speed)
        extra = {}
        if friction is not None:
            extra["slip_speed"] = str(rng.choice(["local", "rigid"]))
        if method == "fastsim_blended":
            extra["blend_rule"] = str(rng.choice(["contact", "spin"]))
        if method == "modified_fastsim":
            extra.update(k0=rng.uniform(0.2, 1.0), alpha_inf=rng.uniform(0.0, 1.0),
                         beta=rng.uniform(0.0, 2.0))
        c_kw = dict(case, method=method, friction=friction, **grid_opts, **extra)
        twin_kw = dict(case, variant=VARIANTS[method], A=A, B=B, **grid_opts, **extra)
        yield c_kw, twin_kw


@pytest.mark.parametrize("grid", ["rect", "strips"])
@pytest.mark.parametrize("bound", ["parabolic", "elliptic"])
@pytest.mark.parametrize("method", list(VARIANTS))
def test_fastsim_matches_c(method, bound, grid):
    for i, (c_kw, twin_kw) in enumerate(fastsim_cases(method, bound, grid)):
        f = rr.creep_forces(**c_kw, errors="raise")
        t = twin.fastsim(**twin_kw)
        s = c_kw["mu"] * c_kw["N"]
        # the twin follows the C operation order where rounding matters: 1e-12 of mu N
        # (mu N a for the moment)
        assert abs(f.fx - t[0]) <= 1e-12 * s, (i, c_kw, f, t)
        assert abs(f.fy - t[1]) <= 1e-12 * s, (i, c_kw, f, t)
        assert abs(f.mz - t[2]) <= 1e-12 * s * c_kw["a"], (i, c_kw, f, t)


@pytest.mark.parametrize("grid", ["rect", "strips"])
@pytest.mark.parametrize("method", list(VARIANTS))
def test_fastsim_field_matches_c(method, grid):
    for i, (c_kw, twin_kw) in enumerate(fastsim_cases(method, "elliptic", grid, n=10)):
        t = rr.fastsim_field(**c_kw)
        fx, fy, mz, field = twin.fastsim(**twin_kw, field=True)
        tw = {k: np.array(v, dtype=float) for k, v in field.items()}
        a, b, mu, N = c_kw["a"], c_kw["b"], c_kw["mu"], c_kw["N"]
        p = float(np.max(t.pn))
        # element centres of the same grid formula: 1e-14 of the semi-axis
        assert np.max(np.abs(t.x - tw["x"])) <= 1e-14 * a, (i, c_kw)
        assert np.max(np.abs(t.y - tw["y"])) <= 1e-14 * b, (i, c_kw)
        # pressure and tractions element by element, as the forces: 1e-12 of the
        # peak pressure (times mu for the tractions; measured 2e-15)
        assert np.max(np.abs(t.pn - tw["pn"])) <= 1e-12 * p, (i, c_kw)
        assert np.max(np.abs(t.px - tw["px"])) <= 1e-12 * mu * p, (i, c_kw)
        assert np.max(np.abs(t.py - tw["py"])) <= 1e-12 * mu * p, (i, c_kw)
        # the same slip test on tractions equal to 1e-15: no element of these seeded
        # cases lies within rounding of its bound, so the maps are identical
        np.testing.assert_array_equal(t.slip, tw["slip"].astype(bool), err_msg=str(c_kw))
        # the field's totals are creep_forces' (test_fastsim_matches_c): 1e-12 of mu N
        assert abs(t.fx - fx) <= 1e-12 * mu * N and abs(t.fy - fy) <= 1e-12 * mu * N
        assert abs(t.mz - mz) <= 1e-12 * mu * N * a, (i, c_kw)


# ------------------------------------------------------------------ bad input

CASE = dict(cx=1e-3, cy=0.0, cphi=0.0, a=5e-3, b=5e-3, N=1e4, mu=0.3, G=G, nu=0.28)

# (name, the twin's call, the C call): both refuse the value and name the argument
BAD = [
    ("a_over_b", lambda: twin.kalker(0.0, 0.28), lambda: rr.kalker_coefficients(0.0, 0.28)),
    ("nu", lambda: twin.kalker(1.0, 0.6), lambda: rr.kalker_coefficients(1.0, 0.6)),
    ("N", lambda: twin.linear(1e-3, 0.0, 0.0, 5e-3, 5e-3, -1.0, G, 0.28),
     lambda: rr.creep_forces(**dict(CASE, N=-1.0), method="linear")),
    ("kS", lambda: twin.polach(**CASE, kA=0.5, kS=0.8),
     lambda: rr.creep_forces(**CASE, method="polach", kA=0.5, kS=0.8)),
    ("speed", lambda: twin.polach(**CASE, A=0.4, B=0.6),
     lambda: rr.creep_forces(**CASE, method="polach", friction=rr.FallingFriction(0.4, 0.6))),
    ("nx", lambda: twin.fastsim(**CASE, nx=0),
     lambda: rr.creep_forces(**CASE, method="fastsim", nx=0)),
    ("blend_rule", lambda: twin.fastsim(**CASE, variant="blended", blend_rule="both"),
     lambda: rr.creep_forces(**CASE, method="fastsim_blended", blend_rule="both")),
    ("k0", lambda: twin.fastsim(**CASE, variant="modified", k0=1.5),
     lambda: rr.creep_forces(**CASE, method="modified_fastsim", k0=1.5)),
]


@pytest.mark.parametrize("name, twin_call, c_call", BAD, ids=[b[0] for b in BAD])
def test_bad_input_refused_by_both(name, twin_call, c_call):
    with pytest.raises(ValueError, match=name):
        twin_call()
    with pytest.raises(rr.RollerRigError, match=name):
        c_call()
