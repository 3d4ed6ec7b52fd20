"""Property-based tests of the contact core: hertz, kalker_coefficients,
creep_forces (every method and option), fastsim_field (issue 11).

Run:  python -m pytest tests/test_properties_contact.py          (profile "ci")
      HYPOTHESIS_PROFILE=long python -m pytest tests/test_properties_*.py
      (10x the examples, freshly random; see tests/_hypothesis_profiles.py)

Every failure found is kept as an explicit @example so it stays a regression
case; the inputs are drawn physically plausible most of the time and from
the whole double range (subnormals, 1e300, NaN, inf, 0, negatives) otherwise.
"""
import math

import numpy as np
import pytest
from hypothesis import assume, example, given, strategies as st
from hypothesis.extra import numpy as hnp

import rollerrig as rr
from _options import own
from rollerrig import RollerRigError, _core
from _properties import (BAD_TYPES, FASTSIMS, FRICTIONAL, METHODS, _units,
                         assert_batch_consistent, assert_finite, creep_options,
                         assert_names_argument, assert_same, assert_truthful, batches, cases,
                         examples, log_uniform, or_zero, signed, subset, uniform, watchdog,
                         wild, table_refuses)

assert watchdog  # the autouse hang detector, imported to take effect here

NU = uniform(0.0, 0.5)                       # 0.5 (incompressible) is physical
NU_OPEN = uniform(0.0, 0.49999999999999994)

HERTZ = dict(A=log_uniform(1e-2, 1e2), B=log_uniform(1e-2, 1e2), N=log_uniform(1.0, 1e6),
             E=log_uniform(1e9, 1e12), nu=NU, E2=log_uniform(1e9, 1e12), nu2=NU)
KALKER = dict(a_over_b=log_uniform(1e-2, 1e2), nu=NU)
CREEP = dict(cx=signed(1e-8, 1.0), cy=signed(1e-8, 1.0), cphi=signed(1e-6, 50.0),
             a=log_uniform(1e-4, 3e-2), b=log_uniform(1e-4, 3e-2), N=log_uniform(1.0, 3e5),
             mu=log_uniform(0.01, 1.5), G=log_uniform(1e9, 3e11), nu=NU,
             speed=or_zero(log_uniform(0.01, 100.0)))
CREEP_OK = dict(CREEP, nu=NU_OPEN, speed=log_uniform(0.01, 100.0))   # every input valid

CREEP_ARGS = ("cx", "cy", "cphi", "a", "b", "N", "mu", "G", "nu", "speed", "friction",
              "friction.A", "friction.B", "method", "nx", "ny", "bound", "grid", "slip_speed",
              "k0", "alpha_inf", "beta", "kA", "kS", "flex", "geometry")

# plausible falling friction: A from 0.01 (a kinetic friction far below the
# static one); a tiny A with fast slip drives mu p below FASTSIM's range
# (1e-80 Pa: RR_ERR_RANGE), which wild_frictions reach
frictions = st.one_of(st.none(), st.builds(rr.FallingFriction, A=st.floats(0.01, 1.0),
                                           B=st.floats(0.0, 20.0)))
wild_frictions = st.one_of(frictions, st.builds(rr.FallingFriction, A=wild, B=wild))


def creep(args, opts, friction, errors=None):
    """The call; a method for Coulomb friction only (fastrip) gets none (its
    refusal of a falling law: test_fastrip.py)."""
    kw = {k: v for k, v in args.items() if k not in ("cx", "cy", "cphi")}
    if rr.METHODS[opts.get("method", "fastsim")].coulomb_only:
        friction = None
    return rr.creep_forces(args["cx"], args["cy"], args["cphi"], friction=friction,
                           errors=errors, **kw, **opts)


def inputs(args, friction):
    """The numbers a creep call was given, friction's included."""
    extra = [friction.A, friction.B] if isinstance(friction, rr.FallingFriction) else []
    return list(args.values()) + extra


def forces(f):
    return dict(fx=f.fx, fy=f.fy, mz=f.mz)


def succeeded(f):
    """Elements with a success status and finite forces: the physics holds
    there (a non-finite success is the batch tests' failure, not repeated)."""
    return (f.status >= 0) & np.isfinite(f.fx) & np.isfinite(f.fy) & np.isfinite(f.mz)


# the known defects of today's main, kept as regression cases
DEFECT_TINY_A = dict(cx=0.0068, cy=0.001, cphi=0.094, a=2.2e-308, b=0.0068, N=1e4, mu=0.3,
                     G=8.2e10, nu=0.28, speed=0.0)
DEFECT_LINEAR_INF = dict(cx=1e300, cy=0.0, cphi=0.0, a=1e12, b=0.0068, N=1e4, mu=0.3,
                         G=8.2e10, nu=0.28, speed=0.0)
DEFECT_POLACH_BOUND = dict(cx=0.0, cy=-0.0019, cphi=0.38, a=0.01, b=0.001, N=1e4, mu=0.5,
                           G=8.2e10, nu=0.28, speed=0.0)
POLACH_04 = dict(method="polach", kA=1.0, kS=0.4)
CREEP_EXAMPLE = dict(cx=1.0, cy=0.0, cphi=0.0, a=0.01, b=0.01, N=1.0, mu=1.0, G=1e9, nu=0.0,
                     speed=0.0)


# ================================================================== hertz

def hertz(args, errors=None):
    return rr.hertz(errors=errors, **args)


@examples(10)
@given(args=cases(HERTZ))
@example(args=dict(A=1e300, B=1e300, N=1e4, E=2.1e11, nu=0.28, E2=2.1e11, nu2=0.28))
@example(args=dict(A=1.0, B=1.0, N=6e307, E=2.1e11, nu=0.28, E2=2.1e11, nu2=0.28))
@example(args=dict(A=5.7e-218, B=1.0, N=1.0, E=5.7e-218, nu=0.0, E2=1e9, nu2=0.0))
def test_hertz_scalar_finite_or_named_error(args):
    try:
        h = hertz(args)
    except RollerRigError as e:
        assert_names_argument(e, "hertz", HERTZ)
        assert_truthful(e, args.values())
        assert hertz(args, errors="ignore").status < 0
        return
    assert_finite(h._asdict())
    assert_same(h, hertz(args, errors="ignore"))


@examples(8)
@given(args=batches(HERTZ))
@example(args=dict(A=np.array([1e300, 1.0]), B=1e300, N=1e4, E=2.1e11, nu=0.28, E2=2.1e11,
                   nu2=0.28))
def test_hertz_batch_good_elements_unaffected(args):
    h = hertz(args, errors="ignore")
    assert_batch_consistent(dict(a=h.a, b=h.b, p0=h.p0, delta=h.delta), h.status)
    good = np.flatnonzero(h.status >= 0)
    if good.size:
        assert_same([v[good] for v in h], hertz(subset(args, good), errors="ignore"))


@examples(10)
@given(args=cases(dict(HERTZ, nu=NU_OPEN, nu2=NU_OPEN), wild_share=0))
def test_hertz_physics(args):
    """Plausible inputs succeed; a, b, p0, delta > 0; p0 = 3 N / (2 pi a b);
    swapping A and B swaps a and b and keeps p0 and delta."""
    h = hertz(args, errors="ignore")
    assert h.status >= 0, h
    assert min(h.a, h.b, h.p0, h.delta) > 0, h
    # the definition of the peak pressure, other operation order: 1e-12
    assert h.p0 == pytest.approx(1.5 * args["N"] / (math.pi * h.a * h.b), rel=1e-12)
    s = hertz(dict(args, A=args["B"], B=args["A"]), errors="ignore")
    # the ellipticity is solved on the ratio min/max, so the semi-axes swap
    # bitwise; p0 and delta follow in another order: 4 ulp (measured 3)
    assert (s.a, s.b) == (h.b, h.a)
    assert s.p0 == pytest.approx(h.p0, rel=1e-15) and s.delta == pytest.approx(h.delta,
                                                                               rel=1e-15)
    # the longer semi-axis lies along the smaller curvature sum
    assert (h.a >= h.b) == (args["A"] <= args["B"]) or args["A"] == args["B"]


# ================================================================== Kalker

def kalker(args, errors=None):
    return rr.kalker_coefficients(errors=errors, **args)


@examples(10)
@given(args=cases(KALKER))
@example(args=dict(a_over_b=5e-324, nu=0.28))
@example(args=dict(a_over_b=1.7976931348623157e308, nu=0.28))
@example(args=dict(a_over_b=1.8874197489868974e+207, nu=0.0))
def test_kalker_scalar_finite_or_named_error(args):
    try:
        k = kalker(args)
    except RollerRigError as e:
        assert_names_argument(e, "kalker_coefficients", KALKER)
        assert_truthful(e, args.values())
        return
    assert_finite(k._asdict())
    assert_same(k, kalker(args, errors="ignore"))


@examples(8)
@given(args=batches(KALKER))
@example(args=dict(a_over_b=np.array([5e-324, 1.0, np.nan]), nu=0.28))
def test_kalker_batch_good_elements_unaffected(args):
    k = kalker(args, errors="ignore")
    assert_batch_consistent(dict(c11=k.c11, c22=k.c22, c23=k.c23, c33=k.c33), k.status)
    good = np.flatnonzero(k.status >= 0)
    if good.size:
        assert_same([v[good] for v in k], kalker(subset(args, good), errors="ignore"))


@examples(6)
@given(args=cases(dict(KALKER, nu=NU_OPEN), wild_share=0))
def test_kalker_plausible_positive(args):
    k = kalker(args, errors="ignore")
    assert k.status >= 0 and min(k.c11, k.c22, k.c23, k.c33) > 0, k


# ================================================================== Poisson's ratio

@examples(1)
@given(nu=NU.strategy, aob=log_uniform(0.05, 20.0).strategy)
@example(nu=0.5, aob=1.0)
def test_poisson_ratio_up_to_one_half_accepted(nu, aob):
    """nu in [0, 0.5] is physical (0.5: incompressible, a column of Kalker's
    table): every function of the contact core takes it."""
    assert kalker(dict(a_over_b=aob, nu=nu)).status >= 0
    assert rr.hertz(1.0, aob, 1e4, nu=nu).status >= 0
    for method in METHODS:
        f = rr.creep_forces(1e-3, 2e-4, 0.1, a=5e-3, b=5e-3 / aob, N=1e4, mu=0.3, nu=nu,
                            errors="ignore", **own(method, nx=8, ny=8))
        if table_refuses(method, f.status, 5e-3, 5e-3 / aob, nu):
            continue        # the table holds one nu: another is refused, not approximated
        assert f.status >= 0 and np.isfinite(f.fx)


# ================================================================== creep forces

@examples(16)
@given(args=cases(CREEP), opts=creep_options(), friction=wild_frictions)
@example(args=DEFECT_TINY_A, opts=dict(method="fastsim"), friction=None)
@example(args=DEFECT_LINEAR_INF, opts=dict(method="linear"), friction=None)
@example(args=dict(DEFECT_TINY_A, a=5e-324), opts=dict(method="polach"), friction=None)
@example(args=dict(DEFECT_TINY_A, N=1e300, mu=1e300), opts=dict(method="fastsim"),
         friction=None)
@example(args=dict(DEFECT_TINY_A, cx=0.0, cy=1.0, cphi=1.0, a=3.436870981342377e+100),
         opts=dict(method="linear"), friction=None)
@example(args=dict(DEFECT_TINY_A, cx=1.0, cy=0.0, cphi=1.0, a=3.068592347899445e+149),
         opts=dict(method="fastsim", nx=2, ny=1), friction=None)
def test_creep_forces_scalar_finite_or_named_error(args, opts, friction):
    try:
        f = creep(args, opts, friction)
    except RollerRigError as e:
        assert_names_argument(e, "creep_forces", CREEP_ARGS)
        assert_truthful(e, inputs(args, friction))
        assert creep(args, opts, friction, errors="ignore").status < 0
        return
    assert_finite(forces(f))
    assert_same(f, creep(args, opts, friction, errors="ignore"))


@examples(12)
@given(args=batches(CREEP), opts=creep_options(), friction=frictions)
@example(args=dict(DEFECT_TINY_A, a=np.array([2.2e-308, 5e-3])), opts=dict(method="fastsim"),
         friction=None)
def test_creep_forces_batch_good_elements_unaffected(args, opts, friction):
    f = creep(args, opts, friction, errors="ignore")
    assert_batch_consistent(forces(f), f.status)
    good = np.flatnonzero(f.status >= 0)
    if good.size:
        alone = creep(subset(args, good), opts, friction, errors="ignore")
        assert_same([v[good] for v in f], alone, "good elements alone: ")
        k = int(good[-1])
        one = creep({n: (v[k] if isinstance(v, np.ndarray) else v) for n, v in args.items()},
                    opts, friction, errors="ignore")
        assert (one.fx, one.fy, one.mz) == (f.fx[k], f.fy[k], f.mz[k])


@examples(6)
@given(args=batches(CREEP_OK, wild_share=0), opts=creep_options(), friction=frictions)
@example(args=dict(CREEP_EXAMPLE, cx=np.array([1.0]), speed=100.0), opts=dict(method="polach"),
         friction=rr.FallingFriction(A=2.2250738585e-313, B=7.0))
def test_creep_forces_plausible_inputs_succeed(args, opts, friction):
    f = creep(args, opts, friction, errors="ignore")
    ok = ~table_refuses(opts["method"], f.status, args["a"], args["b"], args["nu"])
    assert np.all((f.status >= 0) | ~ok), f.status
    assert_finite({k: np.broadcast_to(v, ok.shape)[ok] for k, v in forces(f).items()})


def _bound(args):
    with np.errstate(over="ignore"):
        return np.asarray(args["mu"]) * np.asarray(args["N"])


@examples(12)
@given(args=batches(CREEP, wild_share=8), opts=creep_options(FRICTIONAL), friction=frictions)
@example(args=DEFECT_POLACH_BOUND, opts=POLACH_04, friction=None)
@example(args=dict(CREEP_EXAMPLE, cx=0.0, cphi=np.array([1e16])), opts=dict(method="polach"),
         friction=None)
@example(args=dict(CREEP_EXAMPLE, cy=1.0, cphi=np.array([1.0]), G=1.7880739981722642e+20),
         opts=dict(method="polach"), friction=None)
def test_creep_force_bounded_by_mu_N(args, opts, friction):
    """|(fx, fy)| <= mu N for every frictional method; with falling friction
    mu(w) <= mu0 = mu, so the same bound.  Every element's traction is clipped
    to mu p and the pressure sums to N: rounding only, 1e-12 relative.
    FaStrip's geometry="contact" (CONTACT's pressure at the centres, not
    summed to N) is left out: its bound is the grid's sum (test_fastrip.py)."""
    assume(opts.get("geometry") != "contact")
    f = creep(args, opts, friction, errors="ignore")
    ok = succeeded(f)
    F = np.hypot(f.fx, f.fy)
    lim = np.broadcast_to(_bound(args), F.shape) * (1 + 1e-12)
    assert np.all(F[ok] <= lim[ok]), (F / lim)[ok]


def _negated(args):
    return dict(args, cx=-np.asarray(args["cx"]), cy=-np.asarray(args["cy"]),
                cphi=-np.asarray(args["cphi"]))


@examples(8)
@given(args=batches(CREEP, wild_share=8), opts=creep_options(), friction=frictions)
def test_creep_forces_odd_in_creepage(args, opts, friction):
    """F(-cx, -cy, -cphi) = -F for every method and option, bitwise: negating
    every creepage negates every rigid slip and traction exactly (IEEE
    rounding is symmetric in sign), the pressure, the grid, the bound and
    the friction law see magnitudes only; the FASTSIM grid is symmetric."""
    f = creep(args, opts, friction, errors="ignore")
    g = creep(_negated(args), opts, friction, errors="ignore")
    np.testing.assert_array_equal(g.status, f.status)
    ok = succeeded(f) & succeeded(g)
    for a, b in ((f.fx, g.fx), (f.fy, g.fy), (f.mz, g.mz)):
        np.testing.assert_array_equal(b[ok], -a[ok])


@examples(8)
@given(args=batches(CREEP, wild_share=8), opts=creep_options(), friction=frictions)
# a = 479 km with spin 50/m: FASTSIM's middle element stood at x = 6e-11 m,
# not 0 (aj - 1.5 h), 3e-9 of its rigid slip: fx +-9e-15, 1.9e-12 mu N apart.
# The grid's centres are now exact mirror images
@example(args={"cx": np.array([0.0]), "cy": np.array([-1.0]),
               "cphi": np.array([-50.000000000000014]), "a": np.array([479145.0]),
               "b": np.array([0.00010000000000000009]), "N": np.array([1.0]),
               "mu": np.array([0.010000000000000004]), "G": np.array([9.999999999999993e+08]),
               "nu": np.array([0.0]), "speed": np.array([0.0])},
         opts={"method": "fastsim", "nx": 3, "ny": 5, "bound": "parabolic", "grid": "strips",
               "slip_speed": None}, friction=None)
def test_creep_forces_mirror_in_y(args, opts, friction):
    """Mirroring y: (cx, -cy, -cphi) gives (fx, -fy, -mz).  The FASTSIM rows
    are mirror images but summed in the other order: rounding of a sum of
    at most 24 rows, 1e-12 of the summands' scale (mu N or |F| for forces,
    times max(a, b) for the moment)."""
    f = creep(args, opts, friction, errors="ignore")
    m = creep(dict(args, cy=-np.asarray(args["cy"]), cphi=-np.asarray(args["cphi"])), opts,
              friction, errors="ignore")
    np.testing.assert_array_equal(m.status, f.status)
    ok = succeeded(f) & succeeded(m)
    scale = np.broadcast_to(_bound(args), f.fx.shape)
    scale = np.maximum(scale, np.abs(f.fx) + np.abs(f.fy))[ok]
    arm = np.broadcast_to(np.maximum(args["a"], args["b"]), f.fx.shape)[ok]
    with np.errstate(over="ignore"):
        tol, tol_m = 1e-12 * scale, 1e-12 * (scale * arm + np.abs(f.mz[ok]))
    assert np.all(np.abs(m.fx[ok] - f.fx[ok]) <= tol)
    assert np.all(np.abs(m.fy[ok] + f.fy[ok]) <= tol)
    assert np.all(np.abs(m.mz[ok] + f.mz[ok]) <= tol_m)


@examples(5)
@given(aob=log_uniform(0.05, 20.0).strategy, nu=NU_OPEN.strategy, nx=st.integers(6, 40),
       ny=st.integers(6, 40),
       grid=st.sampled_from(("rect", "strips")), method=st.sampled_from(("fastsim",
                                                                        "fastsim_blended")),
       c=log_uniform(5e-4, 1e-2).strategy, G=log_uniform(1e10, 3e11).strategy)
def test_fastsim_small_creepage_slope_is_linear_theory(aob, nu, nx, ny, grid, method, c, G):
    """Far below saturation FASTSIM's slope is the linear theory's G a b C11
    (C22) up to its grid error, first order: measured up to 2.67/n on the
    rect grid at n = 6 and 1.10/n on strips; allowed 3 / min(nx, ny)."""
    a, b, N, mu = c * math.sqrt(aob), c / math.sqrt(aob), 1e4, 0.3
    k = rr.kalker_coefficients(aob, nu)
    cr = 1e-7 * mu * N / (G * a * b)             # a millionth of the saturation creepage
    kw = dict(a=a, b=b, N=N, mu=mu, G=G, nu=nu, nx=nx, ny=ny, grid=grid, method=method)
    fx = rr.creep_forces(cr, 0.0, 0.0, **kw).fx
    fy = rr.creep_forces(0.0, cr, 0.0, **kw).fy
    tol = 3.0 / min(nx, ny)
    assert fx / (-G * a * b * k.c11 * cr) == pytest.approx(1.0, abs=tol)
    assert fy / (-G * a * b * k.c22 * cr) == pytest.approx(1.0, abs=tol)


@pytest.mark.parametrize("nx, ny", [(4096, 1), (1, 4096), (512, 512)])
@pytest.mark.parametrize("method", FASTSIMS)
def test_largest_grids(nx, ny, method):
    """The dedicated large inputs: grids at FASTSIM_MAX_GRID stay finite and bounded."""
    f = rr.creep_forces(2e-3, -1e-3, 0.5, a=6e-3, b=4e-3, N=2e4, mu=0.3, method=method,
                        nx=nx, ny=ny, friction=rr.FallingFriction(), speed=10.0)
    assert f.status >= 0 and np.isfinite([f.fx, f.fy, f.mz]).all()
    assert math.hypot(f.fx, f.fy) <= 0.3 * 2e4 * (1 + 1e-12)


# ------------------------------------------------------------------ arguments of every kind

SHAPED = {"creep_forces": CREEP_OK, "hertz": dict(HERTZ, nu=NU_OPEN, nu2=NU_OPEN),
          "kalker_coefficients": dict(KALKER, nu=NU_OPEN)}


def call(func, args, errors="ignore"):
    if func == "creep_forces":
        return creep(args, {"nx": 6, "ny": 5}, None, errors)
    return getattr(rr, func)(errors=errors, **args)


@examples(5)
@given(data=st.data(), func=st.sampled_from(sorted(SHAPED)))
def test_shapes_that_broadcast(data, func):
    spec = SHAPED[func]
    shapes = data.draw(hnp.mutually_broadcastable_shapes(num_shapes=len(spec), max_dims=3,
                                                         max_side=3))
    args = {}
    for name, shape in zip(spec, shapes.input_shapes):
        size = int(np.prod(shape))
        u = _units(data.draw(st.binary(min_size=4 * size, max_size=4 * size)), size)
        args[name] = np.asarray(spec[name](u), dtype=float).reshape(shape)
    res = call(func, args)
    for v in res:
        assert np.shape(v) == shapes.result_shape
    idx = data.draw(st.tuples(*(st.integers(0, n - 1) for n in shapes.result_shape)))
    one = call(func, {k: float(np.broadcast_to(v, shapes.result_shape)[idx])
                      for k, v in args.items()})
    assert_same([np.asarray(v)[idx] for v in res], list(one))


@examples(3)
@given(data=st.data(), func=st.sampled_from(sorted(SHAPED)))
def test_shapes_that_do_not_broadcast(data, func):
    names = sorted(SHAPED[func])
    first, second = data.draw(st.lists(st.sampled_from(names), min_size=2, max_size=2,
                                       unique=True))
    n = data.draw(st.integers(2, 5))
    m = data.draw(st.integers(2, 5).filter(lambda m: m != n))
    args = data.draw(cases(SHAPED[func], wild_share=0))
    args[first] = np.full(n, args[first])
    args[second] = np.full(m, args[second])
    with pytest.raises(RollerRigError, match="shapes do not broadcast") as exc:
        call(func, args)
    assert first in str(exc.value) and second in str(exc.value)


@examples(2)
@given(data=st.data(), func=st.sampled_from(sorted(SHAPED)),
       empty=st.sampled_from(((0,), (0, 3), (2, 0))))
def test_empty_arrays_raise_naming_argument(data, func, empty):
    spec = SHAPED[func]
    name = data.draw(st.sampled_from(sorted(spec)))
    args = data.draw(cases(spec, wild_share=0))
    args[name] = np.zeros(empty)
    with pytest.raises(RollerRigError) as exc:
        call(func, args)
    assert_names_argument(exc.value, func, [name])


@examples(2)
@given(data=st.data(), func=st.sampled_from(sorted(SHAPED)),
       bad=st.sampled_from(sorted(BAD_TYPES)))
def test_wrong_types_raise_naming_argument(data, func, bad):
    spec = SHAPED[func]
    name = data.draw(st.sampled_from(sorted(set(spec) - {"E2", "nu2"} if bad == "None"
                                            else spec)))
    args = data.draw(cases(spec, wild_share=0))
    args[name] = BAD_TYPES[bad]
    with pytest.raises(RollerRigError) as exc:
        call(func, args)
    assert_names_argument(exc.value, func, [name])


OPTION_JUNK = st.one_of(st.integers(), st.integers(-3, 5000), wild, st.text(max_size=8),
                        st.none(), st.booleans(), st.sampled_from(("fastsim", "rect", "local")))


@examples(8)
@given(opts=creep_options(), option=st.sampled_from(("method", "nx", "ny", "bound", "grid",
                                                     "slip_speed", "k0", "alpha_inf", "beta",
                                                     "kA", "kS", "friction", "flex",
                                                     "geometry")),
       value=OPTION_JUNK, field=st.booleans())
@example(opts=dict(method="fastsim"), option="nx", value=2 ** 31 - 1, field=False)
@example(opts=dict(method="fastsim"), option="ny", value=2 ** 64, field=True)
@example(opts=dict(method="linear"), option="k0", value=-2 ** 63 - 1, field=False)
def test_any_option_value_is_taken_or_named(opts, option, value, field):
    """Any value of an option: a valid call, or RollerRigError naming that option."""
    if option == "nx" or option == "ny":
        assume(not (isinstance(value, int) and 64 < value <= 4096))   # valid, and slow
    func = rr.fastsim_field if field else rr.creep_forces
    if field:
        if option in ("kA", "kS"):
            return                                  # not options of the field
        opts = {k: v for k, v in opts.items() if k not in ("kA", "kS")}
        if opts["method"] not in FASTSIMS:
            # a method without a field (fastrip): FASTSIM with the options it has
            opts = {k: v for k, v in opts.items() if k in rr.METHODS["fastsim"].options}
            opts["method"] = "fastsim"
    opts = dict(opts, **{option: value})
    # kS is checked against kA: a valid kA below the default kS = 1 blames kS
    names = [option] + (["kA", "kS"] if option in ("kA", "kS") else [])
    try:
        r = func(1e-3, 2e-4, 0.1, a=5e-3, b=4e-3, N=1e4, mu=0.3, speed=5.0, **opts)
    except RollerRigError as e:
        assert_names_argument(e, func.__name__, names)
        return
    assert np.isfinite([r.fx, r.fy, r.mz]).all() and r.status >= 0


@examples(4)
@given(option=st.sampled_from(("method", "nx", "ny", "bound", "grid", "slip_speed")),
       value=st.one_of(st.integers(), st.sampled_from((2 ** 32, 2 ** 32 + 1, 2 ** 32 + 4,
                                                       -2 ** 32, 2 ** 63, 2 ** 64 + 1))))
@example(option="method", value=2 ** 32 + 1)
@example(option="method", value=-2 ** 32 + 4)
@example(option="nx", value=2 ** 63)
def test_binding_option_integers_never_wrap(option, value):
    """The binding takes an option integer as it is: a value outside the
    option's range is an error (ValueError, or a negative status), never
    wrapped round into a valid one."""
    # the binding takes a method and the choices by name: any integer is
    # refused for those, and for nx, ny any integer outside [1, 4096]
    valid = {"method": (), "bound": (), "grid": (), "slip_speed": (),
             "nx": range(1, 4097), "ny": range(1, 4097)}[option]
    assume(value not in valid)
    arrays = [np.array([v]) for v in (1e-3, 2e-4, 0.1, 5e-3, 4e-3, 1e4, 0.3, 8.2e10, 0.28,
                                      5.0, 0.4, 0.6)]
    # the grid options are FASTSIM's: the other methods do not read them
    kw = {option: value} if option == "method" else {"method": "fastsim", option: value}
    try:
        fx, fy, mz, status = _core.creep_forces(*arrays, **kw)
    except ValueError as e:
        assert option in str(e) or "invalid options" in str(e)
        return
    assert status[0] < 0, f"{option} = {value} taken as a valid option: fx = {fx[0]}"


# ================================================================== traction field

@examples(12)
@given(args=cases(CREEP), opts=creep_options(FASTSIMS), friction=wild_frictions)
@example(args=DEFECT_TINY_A, opts=dict(method="fastsim"), friction=None)
@example(args=dict(CREEP_EXAMPLE, cx=0.0, G=1.7624442498650158e+307), opts=dict(method="fastsim",
         nx=1, ny=1), friction=None)
@example(args=dict(CREEP_EXAMPLE, cx=0.0, cphi=1.0, a=1.797693134862316e+306),
         opts=dict(method="fastsim", nx=1, ny=1), friction=None)
def test_fastsim_field_finite_or_named_error(args, opts, friction):
    kw = {k: v for k, v in args.items() if k not in ("cx", "cy", "cphi")}
    try:
        t = rr.fastsim_field(args["cx"], args["cy"], args["cphi"], friction=friction, **kw,
                             **opts)
    except RollerRigError as e:
        assert_names_argument(e, "fastsim_field", CREEP_ARGS)
        assert_truthful(e, inputs(args, friction))
        return
    assert_finite(dict(x=t.x, y=t.y, pn=t.pn, px=t.px, py=t.py, area=t.area, fx=t.fx,
                       fy=t.fy, mz=t.mz))
    assert np.all(t.pn >= 0)
    # every element within its bound; mu(w) <= mu: 1e-12 rounding
    assert np.all(np.hypot(t.px, t.py) <= args["mu"] * t.pn * (1 + 1e-12))
    f = creep(args, opts, friction)
    assert (f.fx, f.fy, f.mz) == (t.fx, t.fy, t.mz)     # the same C routine: bitwise
