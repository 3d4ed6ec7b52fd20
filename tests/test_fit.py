"""Fitting Polach's method and modified FASTSIM to creep curves (rollerrig.analysis.fit)."""
import itertools
import math

import numpy as np
import pytest

pytest.importorskip("scipy")

import rollerrig as rr  # noqa: E402
from rollerrig.analysis.fit import fit_modified_fastsim, fit_polach  # noqa: E402
from reference_cases import MM, N_PER_MM2, read_csv  # noqa: E402

# CONTACT's tractcurv case (Polach's Eurosprinter wheel): a/b = 0.5, N = 106.7 kN
CASE = dict(a=6.304 * MM, b=12.61 * MM, N=106700.0, G=82000.0 * N_PER_MM2, nu=0.28)
SPEEDS = [5.0, 15.0, 30.0]
# 10 points on the rising branch, 15 into the falling one (up to 4.5 m/s slip at 30 m/s)
CX = np.concatenate([np.linspace(2e-4, 4e-3, 10), np.geomspace(5e-3, 0.15, 15)])


def synthetic(method, mu0, A, B, seed, **params):
    """Three curves, one per speed, with Gaussian noise of 1 % of mu0 N."""
    rng = np.random.default_rng(seed)
    out = []
    for v in SPEEDS:
        f = rr.creep_forces(CX, method=method, mu=mu0, friction=rr.FallingFriction(A, B),
                            speed=v, errors="raise", **params, **CASE)
        out.append(f.fx + rng.normal(0.0, 0.01 * mu0 * CASE["N"], CX.size))
    return out


# ------------------------------------------------------------------ recovery, Polach

POLACH_TRUE = dict(mu0=0.38, A=0.35, B=0.9, kA=0.7, kS=0.25)   # away from the defaults


def fit_synthetic_polach(seed):
    t = POLACH_TRUE
    data = synthetic("polach", t["mu0"], t["A"], t["B"], seed, kA=t["kA"], kS=t["kS"])
    return fit_polach([CX] * 3, data, speed=SPEEDS, **CASE)


def test_polach_recovers_parameters():
    res = fit_synthetic_polach(seed=20250101)
    assert res.success and res.sign == 1 and res.at_bound == ()
    assert res.fitted == ("mu0", "A", "B", "kA", "kS")
    for name, true in POLACH_TRUE.items():
        fitted, se = res.params[name], res.stderr[name]
        # the standard errors are honest (test_polach_stderr_calibrated), so 4 of them is
        # a 6e-5 two-sided chance per parameter of a false failure for a Gaussian
        # estimate; measured |z| 0.1 to 2.4 (A)
        assert abs(fitted - true) < 4.0 * se, (name, fitted, true, se)
        # three speeds into the falling branch pin every parameter: measured relative
        # standard errors 0.9 % (mu0) to 3.5 % (B); 5 % would flag lost identifiability
        assert se < 0.05 * true, (name, se)
    assert res.params["kS"] <= res.params["kA"]
    # the residuals are the noise: RMS near 1 % of mu0 N (measured 0.0089)
    assert 0.006 < res.rms / (POLACH_TRUE["mu0"] * CASE["N"]) < 0.013
    assert len(res.residuals) == 3 and all(r.shape == CX.shape for r in res.residuals)


@pytest.mark.slow    # hundreds of fits
def test_polach_stderr_calibrated():
    """Over 40 noise draws the scatter of each estimate matches its mean standard
    error: with 40 draws the sample standard deviation is good to about 11 %, so
    0.7 to 1.4 is a 3-sigma band (measured 0.98 to 1.20)."""
    est, se = [], []
    for seed in range(40):
        res = fit_synthetic_polach(seed)
        est.append([res.params[n] for n in res.fitted])
        se.append([res.stderr[n] for n in res.fitted])
    ratio = np.std(est, axis=0, ddof=1) / np.mean(se, axis=0)
    assert np.all((ratio > 0.7) & (ratio < 1.4)), dict(zip(res.fitted, ratio))


# ------------------------------------------------------------------ recovery, modified FASTSIM

FRICTION = dict(mu0=0.36, A=0.38, B=0.7)                 # CONTACT's series 4 law, held
MF_TRUE = dict(k0=0.6, alpha_inf=0.25, beta=1.0)


def test_modified_fastsim_recovers_parameters():
    data = synthetic("modified_fastsim", FRICTION["mu0"], FRICTION["A"], FRICTION["B"],
                     seed=20250102, nx=20, ny=20, **MF_TRUE)
    res = fit_modified_fastsim([CX] * 3, data, speed=SPEEDS, x0=FRICTION, **CASE)
    assert res.success and res.at_bound == ()
    assert res.fitted == ("k0", "alpha_inf", "beta")
    for name in FRICTION:                                 # held exactly
        assert res.params[name] == FRICTION[name]
    for name, true in MF_TRUE.items():
        fitted, se = res.params[name], res.stderr[name]
        # 4 standard errors as for Polach; 20 noise draws measured the standard errors
        # within 20 % of the scatter and a bias of about half a standard error in k0 and
        # beta (the estimate is nonlinear in them), which 4 absorb
        assert abs(fitted - true) < 4.0 * se, (name, fitted, true, se)
        # measured relative standard errors 3 % (k0), 6 % (alpha_inf), 11 % (beta):
        # beta only shapes the knee of the curve
        assert se < 0.2 * true, (name, se)


# ------------------------------------------------------------------ CONTACT's exact theory

# the corners of the property suite's ranges (tests/test_properties_rig.py),
# one and two speeds, and the sets that settled elsewhere before (issue 22)
ROUND_TRIP = [*itertools.product((0.2, 0.6), (0.3, 1.0), (0.1, 1.0), (0.2, 0.9), (0.1, 2.0),
                                 ((5.0,), (30.0,), (5.0, 30.0))),
              (0.6, 0.3, 0.1, 0.4625, 0.575, (30.0,)),   # 2.6 % off: mu0 0.757, B 5.92
              (0.92, 0.27, 0.029, 0.9, 3.0, (37.0, 3.1))]  # wider than the suite: 11 % off


@pytest.mark.slow    # 98 fits
def test_polach_round_trip_on_a_grid():
    """Noise-free curves of Polach's method: the fit recovers the parameters
    that made them, from the default start.  Before the steps were scaled
    by 1 (not by the Jacobian, which at a soft contact's start led to
    another minimum) and the initial slope gave a stiffness start, the
    issue's set settled at 2.6 % of the peak with mu0 0.757, B 5.92.
    Tolerances: the fit stops at the first start within 1e-4 of the peak
    (rms); on this grid the parameters come within 1.5e-3 (A of a weakly
    falling law, B = 0.1 s/m at 5 m/s), so 1 %."""
    a, b, N = 6e-3, 4e-3, 2e4
    cx = np.geomspace(1e-4, 0.3, 40)
    bad = []
    for mu0, kA, ratio, A, B, speeds in ROUND_TRIP:
        curves = [rr.creep_forces(cx, a=a, b=b, N=N, mu=mu0, speed=v, method="polach", kA=kA,
                                  kS=kA * ratio, friction=rr.FallingFriction(A, B)).fx
                  for v in speeds]
        res = fit_polach([cx] * len(speeds), curves, a=a, b=b, N=N, speed=list(speeds))
        peak = max(np.max(np.abs(c)) for c in curves)
        true = dict(mu0=mu0, A=A, B=B, kA=kA, kS=kA * ratio)
        off = {n: res.params[n] / v - 1.0 for n, v in true.items()}
        if not (res.rms <= 1e-4 * peak and all(abs(e) <= 0.01 for e in off.values())):
            bad.append((true, speeds, res.rms / peak, off))
    assert not bad, f"{len(bad)} of {len(ROUND_TRIP)}: {bad[:3]}"


def series2():
    """Series 2: CONTACT's exact theory with falling friction mu0 = 0.33, A = 0.14/0.33,
    B = ln 2 / 1.25 s/m and an interfacial layer, at 10 m/s."""
    rows = [r for r in read_csv("creep_curves_exact_vs_fastsim.csv")[1] if r["series"] == "2"]
    return (np.array([float(r["cksi"]) for r in rows]),
            np.array([float(r["FX"]) for r in rows]))


MU_S2, A_S2, B_S2 = 0.33, 0.14 / 0.33, math.log(2.0) / 1.25


@pytest.fixture(scope="module")
def series2_fit():
    cx, fx = series2()
    return cx, fx, fit_polach(cx, fx, speed=10.0, **CASE)


def test_polach_fits_exact_theory(series2_fit):
    cx, fx, res = series2_fit
    assert res.success and res.sign == 1
    mun = MU_S2 * CASE["N"]
    # Polach's five parameters follow the exact curve to 0.35 % of mu N RMS, 0.77 % at
    # worst (measured); with CONTACT's friction law and kA = kS = 1 Polach is off by
    # 17 % RMS, so the bound tests the fit, with room for other optimiser versions
    assert res.rms / mun < 0.005
    assert np.max(np.abs(res.residuals)) / mun < 0.01
    np.testing.assert_allclose(res.predict(cx) - fx, res.residuals, atol=1e-9 * mun)
    # plausible: Polach takes mu at the rigid slip speed where the exact theory has each
    # element's own, so A, B need not be CONTACT's; measured mu0 0.339, A 0.459,
    # B 0.68 s/m against 0.33, 0.424, 0.555
    p = res.params
    assert abs(p["mu0"] - MU_S2) < 0.02
    assert abs(p["A"] - A_S2) < 0.1
    assert B_S2 / 1.5 < p["B"] < 1.5 * B_S2
    # the soft interfacial layer lowers the initial slope: kA = kS = 0.27 (measured; kS
    # ends on its bound kS = kA)
    assert 0.2 < p["kS"] <= p["kA"] < 0.35
    assert res.at_bound == ("kS",)


def test_magnitudes_are_flipped(series2_fit):
    cx, fx, res = series2_fit
    flipped = fit_polach(cx, -fx, speed=10.0, **CASE)
    assert flipped.sign == -1 and "other way" in flipped.message
    for n in res.fitted:
        assert flipped.params[n] == pytest.approx(res.params[n], rel=1e-6)
    assert np.all(flipped.predict(cx[1:]) > 0)                     # the data's sign
    np.testing.assert_allclose(flipped.residuals, -np.asarray(res.residuals), atol=1e-3)


def test_held_parameters_and_order():
    cx, fx = series2()
    x0 = dict(mu0=MU_S2, A=A_S2, B=B_S2, kA=0.5, kS=0.2)
    res = fit_polach(cx, fx, speed=10.0, fit=("kS", "kA"), x0=x0, **CASE)
    assert res.fitted == ("kA", "kS") and set(res.stderr) == {"kA", "kS"}
    for n in ("mu0", "A", "B"):
        assert res.params[n] == x0[n]
    assert 0 < res.params["kS"] <= res.params["kA"] <= 1
    # kS held: kA may not go below it
    res = fit_polach(cx, fx, speed=10.0, fit="kA", x0=dict(x0, kS=0.4), **CASE)
    assert res.params["kA"] >= 0.4


def test_predict_needs_speed_for_several_curves():
    t = POLACH_TRUE
    data = synthetic("polach", t["mu0"], t["A"], t["B"], 1, kA=t["kA"], kS=t["kS"])
    res = fit_polach([CX] * 3, data, speed=SPEEDS, **CASE)
    with pytest.raises(rr.RollerRigError, match="give speed"):
        res.predict(CX)
    assert res.predict(CX, speed=15.0).shape == CX.shape


# ------------------------------------------------------------------ bad input

CX2, FX2 = series2()
BASE = dict(speed=10.0, **CASE)


def nan_at(arr, i):
    arr = arr.copy()
    arr[i] = np.nan
    return arr


@pytest.mark.parametrize("args, kwargs, match", [
    ((CX2, nan_at(FX2, 3)), {}, r"force\[3\] = nan is not finite"),
    ((nan_at(CX2, 0), FX2), {}, r"cx\[0\] = nan"),
    ((CX2, FX2[:-1]), {}, r"force has 29 points but cx has 30"),
    (([CX2, CX2], [FX2, FX2[:5]]), dict(speed=[5.0, 10.0]),
     r"force\[1\] has 5 points but cx\[1\] has 30"),
    (([CX2, CX2], FX2), dict(speed=[5.0, 10.0]), r"cx has 2 curve\(s\) but force has one"),
    (([], []), {}, r"cx is empty"),
    ((np.array([]), np.array([])), {}, r"cx is empty"),
    ((CX2, FX2), dict(fit=("mu0", "C")), r"unknown parameter 'C' in fit"),
    ((CX2, FX2), dict(fit=()), r"fit names no parameter"),
    ((CX2, FX2), dict(x0={"A": 1.5}), r"x0\['A'\] = 1.5 is outside \(0, 1\]"),
    ((CX2, FX2), dict(x0={"mu0": -0.1}), r"x0\['mu0'\] = -0.1 is outside"),
    ((CX2, FX2), dict(x0={"kA": 0.3, "kS": 0.5}), r"x0\['kS'\] = 0.5 is above x0\['kA'\]"),
    ((CX2, FX2), dict(x0={"mu": 0.3}), r"unknown parameter 'mu' in x0"),
    ((CX2, FX2), dict(bounds={"B": (1.0, 2.0)}), r"x0\['B'\] = 0.6 is outside bounds"),
    ((CX2, FX2), dict(bounds={"kS": (0.1, 0.5)}), r"bound 'kS/kA' instead"),
    ((CX2, FX2), dict(bounds={"B": (2.0, 1.0)}), r"need lo < hi"),
    ((CX2, FX2), dict(loss="l2"), r"loss must be one of"),
    ((CX2, FX2), dict(speed=-1.0), r"speed must be > 0, got -1.0"),
    (([CX2, CX2], [FX2, FX2]), dict(speed=[5.0, 10.0, 20.0]),
     r"speed must be a scalar or one value per curve \(2\)"),
    ((CX2, FX2), dict(N=-1.0), r"N must be a finite number > 0, got -1.0"),
    ((CX2, FX2), dict(a=10 ** 400), r"a must be a finite number > 0, got 1000"),  # no OverflowError
    ((CX2, 0 * FX2), {}, r"force is zero everywhere"),
    ((CX2, FX2), dict(weights=np.ones(3)), r"weights has 3 points but cx has 30"),
])
def test_bad_input_raises(args, kwargs, match):
    kw = dict(BASE, **kwargs)
    with pytest.raises(rr.RollerRigError, match=match) as info:
        fit_polach(*args, **kw)
    assert isinstance(info.value, ValueError)
    assert str(info.value).startswith("fit_polach: ")


def test_bad_input_modified_fastsim():
    with pytest.raises(rr.RollerRigError, match=r"unknown parameter 'kA' in fit"):
        fit_modified_fastsim(CX2, FX2, fit=("k0", "kA"), **BASE)
    with pytest.raises(rr.RollerRigError, match=r"x0\['k0'\] = 0.0 is outside \(0, 1\]"):
        fit_modified_fastsim(CX2, FX2, x0={"k0": 0.0}, **BASE)
    with pytest.raises(rr.RollerRigError, match=r"nx must be an integer"):
        fit_modified_fastsim(CX2, FX2, nx=0, **BASE)


def test_without_scipy_the_fits_name_the_extra(monkeypatch):
    import sys
    from rollerrig._optional import OptionalDependencyError
    cx = np.linspace(1e-4, 0.01, 10)
    fx = rr.creep_forces(cx, method="polach", mu=0.3, speed=5.0, **CASE).fx
    monkeypatch.setitem(sys.modules, "scipy.optimize", None)
    for fit in (fit_polach, fit_modified_fastsim):
        with pytest.raises(OptionalDependencyError) as e:
            fit(cx, fx, speed=5.0, **CASE)
        assert str(e.value).startswith(f"{fit.__name__} needs scipy, which is not installed: "
                                       f"pip install 'rollerrig[fit]'")
