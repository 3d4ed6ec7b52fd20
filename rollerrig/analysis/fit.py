"""Fit Polach's method or modified FASTSIM to measured creep-force curves::

    import rollerrig as rr
    from rollerrig.analysis.fit import fit_polach
    res = fit_polach([cx_5, cx_10], [fx_5, fx_10], speed=[5.0, 10.0],
                     a=6.3e-3, b=12.6e-3, N=106.7e3)
    res.params            # {'mu0': ..., 'A': ..., 'B': ..., 'kA': ..., 'kS': ...}
    res.stderr            # standard errors of the fitted ones
    res.predict(cx, speed=10.0)

The data
    cx, force: one curve (1-D arrays) or several (lists of 1-D arrays, one
    per speed); force is the longitudinal force fx [N] at the longitudinal
    creepage cx, with cy and cphi held at the given values (scalars, shared
    by all curves).  speed [m/s] is a scalar or one value per curve: the
    curves are fitted at once, with one set of parameters.

Sign
    The library's forces act on the wheel and oppose the creepage (Kalker's
    sign: fx < 0 for cx > 0).  The fit uses the data's sign as given.  If
    the data point the other way (sum of force * sign(cx) > 0: forces on the
    roller, or magnitudes), they are negated for the fit, FitResult.sign is
    -1, the message says so, and predict() and the residuals are in the
    data's sign.

What the data determine
    Polach's mu0, kA and kS come from the shape of one curve: the initial
    slope fixes kA + kS, the curvature of the rise their split, the peak
    mu0.  The falling friction mu(w) = mu0 [(1 - A) exp(-B w) + A] depends
    on the slip speed w = speed * |creepage|, so A and B are only
    identifiable where the data reach well past the peak into the falling
    branch, and B (the speed scale of the fall) only robustly with several
    speeds: at one speed B trades off against kA, kS and mu0.  A parameter
    the data cannot fix shows as a large standard error (NaN where the
    Jacobian is singular); hold it with `fit` and `x0` instead.

The fit
    scipy.optimize.least_squares ('trf', bounds) on the residuals
    r = weights * (model - force) / F_ref, F_ref the data's peak |force|, with
    a robust loss (default soft_l1) whose f_scale (default 0.05: five per
    cent of the peak force) is the residual beyond which a point counts as
    an outlier.  Steps are scaled by 1 (the parameters are O(0.1 - 1); steps
    scaled by the Jacobian's columns led a soft contact's curve from the
    default start into another minimum).  Starts: x0, then the friction
    law's free parameters moved (mu0 doubled, a flat and a steep law), then
    the same with Polach's kA + kS from the data's initial slope; the best
    fit is kept, and the first that fits to 1e-4 of the peak ends the search.
    Bounds: mu0 > 0, 0 < A <= 1, B >= 0, 0 < kS <= kA <= 1
    (kS is fitted as the ratio kS/kA in (0, 1], so the order holds);
    modified FASTSIM: 0 < k0 <= 1, 0 <= alpha_inf <= 1, beta >= 0.  `bounds`
    narrows them: {name: (lo, hi)}; for the ratio, key "kS/kA".
    Standard errors: the Jacobian J of the unweighted-loss residuals at the
    solution (central differences), cov = (J^T J)^-1 s^2 with
    s^2 = sum r^2 / (m - p), m points, p fitted parameters; kS's from the
    ratio's by the delta method.  They assume independent errors of equal
    variance (after weighting) and a model that fits: for a model that does
    not fit the data exactly they measure how well the misfit pins the
    parameters, not the physics.

scipy is needed here only: the extra "fit" (pip install 'rollerrig[fit]');
without it the fits raise an ImportError naming the extra.
"""
from __future__ import annotations

from typing import Any, Callable, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple, Union

import numpy.typing as npt

from dataclasses import dataclass, field
import itertools
import math

import numpy as np

from .._errors import RollerRigError, check_number
from .._optional import require
from .._typing import F64Array, FloatResult
from .._units import cf_unit
from ..contact.creep import METHODS, FallingFriction, creep_forces
from ._fit_inputs import _RATIO, Curves, Spec, _data, _fail, _setup

__all__ = ["FitResult", "fit_polach", "fit_modified_fastsim", "POLACH_PARAMETERS",
           "MODIFIED_FASTSIM_PARAMETERS", "PARAMETER_UNITS", "LOSSES"]

_INF = np.inf

# name: (default, lower, upper, lower bound open, upper bound open); default None: the
# data's peak |force| / N.  The friction law's mu0, A, B are the fit's own; a
# method's options take their range from the registry (rollerrig.METHODS), with
# the fit's starting value.
_FRICTION_PARAMETERS: Dict[str, Tuple[Optional[float], float, float, bool, bool]] = {
    "mu0": (None, 0.0, _INF, True, True),
    "A": (0.4, 0.0, 1.0, True, False),
    "B": (0.6, 0.0, _INF, False, True),
}


def _method_parameters(method: str, **start: float) -> Spec:
    """The fitted options of a method: start value and the registry's range."""
    options = METHODS[method].options

    def spec(n: str, v: float) -> Tuple[Optional[float], float, float, bool, bool]:
        o = options[n]
        if o.lo is None or o.hi is None:        # a choice: the fits take real options only
            raise TypeError(f"{method}'s option {n} has no range to fit in")
        return v, o.lo, o.hi, o.lo_open, o.hi_open
    return {**_FRICTION_PARAMETERS, **{n: spec(n, v) for n, v in start.items()}}


#: fit_polach's parameters: name -> (start, lower, upper, lower bound open,
#: upper bound open); start None: the data's peak |force| / N.  Polach 2005,
#: dry rail: A = 0.4, B = 0.6 s/m, kA = 1, kS = 0.4
POLACH_PARAMETERS = _method_parameters("polach", kA=1.0, kS=0.4)
#: fit_modified_fastsim's parameters, as POLACH_PARAMETERS: Spiryagin, Polach
#: and Cole 2013 as in CONTACT's example: k0 0.54, alpha_inf 0.02, beta 0.62
MODIFIED_FASTSIM_PARAMETERS = _method_parameters("modified_fastsim", k0=0.54, alpha_inf=0.02,
                                                 beta=0.62)
#: units of the fitted parameters (CF / UDUNITS, "1": dimensionless); A, B are
#: the falling friction law's (FallingFriction; creep_forces' friction.A, friction.B)
PARAMETER_UNITS = {"mu0": "1", "A": "1", "B": "s/m",
                   **{n: cf_unit(METHODS[m].options[n].unit) or "1" for m, P in
                      (("polach", POLACH_PARAMETERS),
                       ("modified_fastsim", MODIFIED_FASTSIM_PARAMETERS))
                      for n in P if n not in _FRICTION_PARAMETERS}}
#: the robust losses of scipy.optimize.least_squares the fits take
LOSSES = ("linear", "soft_l1", "huber", "cauchy", "arctan")


@dataclass
class FitResult:
    """The result of :func:`fit_polach` or :func:`fit_modified_fastsim`.

    See Also
    --------
    rollerrig.plot.fit : draws the data and the fitted model.
    """

    model: str          #: "polach" or "modified_fastsim"
    #: every parameter of the model, fitted or held, {name: value} (units:
    #: rollerrig.analysis.fit.PARAMETER_UNITS)
    params: Dict[str, float]
    #: standard error of each fitted parameter, {name: value} (NaN where the
    #: Jacobian is singular or there are no more points than parameters)
    stderr: Dict[str, float]
    fitted: Tuple[str, ...]     #: the names fitted, in the model's order
    #: model - data [N], in the data's sign; a list of arrays if the data were
    #: a list of curves
    residuals: Union[F64Array, List[F64Array]]
    rms: float          #: root mean square of the residuals [N]
    #: least_squares' cost, 0.5 sum loss(r^2), r = weights (model - data) / F_ref
    cost: float
    success: bool       #: least_squares' success flag
    message: str        #: least_squares' message (also says when the data's sign was flipped)
    nfev: int           #: least_squares' number of function evaluations
    sign: int           #: +1, or -1 if the data were negated for the fit
    #: the fitted parameters that ended on a bound (kS: kS = kA); their
    #: standard errors mean little
    at_bound: Tuple[str, ...] = ()
    #: the fit's fixed settings (contact, speeds, held creepages, grid), for predict
    settings: Dict[str, Any] = field(repr=False, default_factory=dict)

    def predict(self, cx: npt.ArrayLike, speed: Optional[npt.ArrayLike] = None, *,
                cy: Optional[float] = None,
                cphi: Optional[float] = None) -> Union[float, npt.NDArray[np.float64]]:
        """The fitted model's force fx [N] at creepage cx, in the data's sign.

        Parameters
        ----------
        cx : float or array_like
            Longitudinal creepage [-].
        speed : float or array_like, optional
            Rolling speed [m/s]; default the fit's speed (if it had one).
        cy : float or array_like, optional
            Lateral creepage [-]; default the fit's.
        cphi : float or array_like, optional
            Spin [rad/m]; default the fit's.

        Returns
        -------
        float or ndarray
            fx [N], the arguments broadcast as in creep_forces.

        Raises
        ------
        RollerRigError
            If the fit had several speeds and `speed` is not given.
        """
        s = self.settings
        if speed is None:
            if len(s["speeds"]) != 1:
                raise RollerRigError(f"predict: the fit had speeds {list(s['speeds'])}; "
                                     "give speed")
            speed = s["speeds"][0]
        cy = s["cy"] if cy is None else cy
        cphi = s["cphi"] if cphi is None else cphi
        f = _model(self.model, self.params, s, np.asarray(cx, dtype=float), speed, cy, cphi,
                   errors=None)
        return self.sign * f


# ------------------------------------------------------------------ the models

def _model(model: str, p: Mapping[str, float], s: Mapping[str, Any], cx: npt.ArrayLike,
           speed: npt.ArrayLike, cy: npt.ArrayLike, cphi: npt.ArrayLike,
           errors: Optional[str] = "ignore") -> FloatResult:
    """fx of the model with parameters p at (cx, speed); settings s."""
    friction = FallingFriction(A=p["A"], B=p["B"])
    common: Dict[str, Any] = dict(a=s["a"], b=s["b"], N=s["N"], mu=p["mu0"], G=s["G"], nu=s["nu"],
                  speed=speed, friction=friction, errors=errors)
    if model == "polach":
        f = creep_forces(cx, cy, cphi, method="polach", kA=p["kA"], kS=p["kS"], **common)
    else:
        f = creep_forces(cx, cy, cphi, method="modified_fastsim", k0=p["k0"],
                         alpha_inf=p["alpha_inf"], beta=p["beta"], nx=s["nx"], ny=s["ny"],
                         grid=s["grid"], bound=s["bound"], slip_speed=s["slip_speed"],
                         **common)
    return f.fx


def _natural(start: Mapping[str, float], inner: Sequence[str],
             theta: F64Array) -> Dict[str, float]:
    p = dict(start)
    for n, v in zip(inner, theta):
        if n != _RATIO:
            p[n] = float(v)
    if _RATIO in inner:
        p["kS"] = p["kA"] * float(theta[inner.index(_RATIO)])
    return p


def _jacobian(fun: Callable[[F64Array], F64Array], theta: npt.ArrayLike, lo: F64Array,
              hi: F64Array) -> F64Array:
    """Central differences, one-sided against a bound."""
    theta = np.asarray(theta, dtype=float)
    f0 = fun(theta)
    J = np.empty((f0.size, theta.size))
    for j in range(theta.size):
        h = 1e-5 * max(abs(theta[j]), 0.1)
        up, dn = theta.copy(), theta.copy()
        if theta[j] + h <= hi[j] and theta[j] - h >= lo[j]:
            up[j] += h
            dn[j] -= h
            J[:, j] = (fun(up) - fun(dn)) / (2.0 * h)
        elif theta[j] + h <= hi[j]:
            up[j] += h
            J[:, j] = (fun(up) - f0) / h
        else:
            dn[j] -= h
            J[:, j] = (f0 - fun(dn)) / h
    return J


def _rms(v: F64Array) -> float:
    """The root mean square of finite v, scaled by its largest value so that
    no square overflows or underflows."""
    m = float(np.max(np.abs(v))) if v.size else 0.0
    return m * float(np.sqrt(np.mean((v / m) ** 2))) if m > 0.0 else 0.0


def _covariance(J: F64Array, r: F64Array) -> F64Array:
    """(J^T J)^-1 s^2, NaN in the rows and columns of ill-determined parameters."""
    m, p = J.shape
    if m <= p:
        return np.full((p, p), np.nan)
    s2 = float(r @ r) / (m - p)
    _, sv, vt = np.linalg.svd(J, full_matrices=False)
    keep = sv > np.sqrt(np.finfo(float).eps) * sv[0] if sv[0] > 0 else np.zeros_like(sv, bool)
    # singular values of data all but zero square to 0 (or of huge data to
    # inf): those variances come out infinite or NaN, and the caller names
    # them NaN (not a warning)
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        cov: F64Array = (vt[keep].T / sv[keep] ** 2) @ vt[keep] * s2
    bad = np.zeros(p, bool)
    for k in np.flatnonzero(~keep):
        bad |= np.abs(vt[k]) > 1e-3
    cov[bad, :] = np.nan
    cov[:, bad] = np.nan
    return cov


# ------------------------------------------------------------------ the fit

#: the other starts of the friction law: mu0 as given or doubled, A and B as
#: given, flat or steep (each change only where the fit may move it)
_MU0_FACTORS = (1.0, 2.0)
_LAWS: Tuple[Dict[str, float], ...] = ({}, {"A": 0.2, "B": 3.0}, {"A": 0.8, "B": 0.2})


def _starts(theta0: F64Array, inner: Sequence[str], lo: F64Array, hi: F64Array,
            x0: Optional[Mapping[str, float]],
            stiffness: Optional[Mapping[str, float]] = None) -> Iterator[F64Array]:
    """theta0, then starts with the friction law's fitted parameters (those
    x0 does not give) moved: mu0 doubled; A, B to a flat and to a steep law;
    then the same with the stiffness {internal name: value} the data's
    initial slope gives (_stiffness)."""
    yield theta0
    free = {n: k for k, n in enumerate(inner) if n not in (x0 or {})}
    seen = [tuple(theta0)]
    for stiff, factor, law in itertools.product(({}, stiffness or {}), _MU0_FACTORS, _LAWS):
        t = np.array(theta0, dtype=float)
        if "mu0" in free:
            t[free["mu0"]] *= factor
        for n, v in itertools.chain(law.items(), stiff.items()):
            if n in free:
                t[free[n]] = v
        t = np.clip(t, lo, hi)
        if tuple(t) not in seen:
            seen.append(tuple(t))
            yield t


def _stiffness(model: str, inner: Sequence[str], x0: Optional[Mapping[str, float]],
               start: Mapping[str, float], settings: Mapping[str, Any], c_all: F64Array,
               target: F64Array, f_ref: float) -> Dict[str, float]:
    """Polach's kA and kS/kA from the data's initial slope: at small
    creepage fx = -(kA + kS)/2 G a b c11 cx (Kalker's linear theory times
    (kA + kS)/2, whatever mu), so the slope through the origin of the
    (up to 3) points nearest cx = 0 below half the peak force fixes kA + kS;
    the split keeps the start's ratio kS/kA (kA at most 1).  {} unless both
    are fitted from the default start, or for data with no such points."""
    if model != "polach" or "kA" not in inner or _RATIO not in inner \
            or {"kA", "kS"} & set(x0 or {}):
        return {}
    near = np.flatnonzero((c_all != 0.0) & (np.abs(target) <= 0.5 * f_ref))
    near = near[np.argsort(np.abs(c_all[near]))][:3]
    if near.size == 0:
        return {}
    c, f = c_all[near], target[near]
    kalker = float(creep_forces(1.0, 0.0, 0.0, method="linear", a=settings["a"],
                                b=settings["b"], N=settings["N"], mu=start["mu0"],
                                G=settings["G"], nu=settings["nu"], errors="ignore").fx)
    with np.errstate(all="ignore"):             # any data: a start or none, never a warning
        ksum = float(2.0 * np.float64(f @ c) / np.float64(c @ c) / kalker)
    if not (math.isfinite(ksum) and ksum > 0.0):
        return {}
    ratio = start["kS"] / start["kA"]
    kA = min(ksum / (1.0 + ratio), 1.0)
    return {"kA": kA, _RATIO: min(max(ksum / kA - 1.0, 1e-3), 1.0)}


def _fit(func: str, model: str, spec: Spec, cx: object, force: object, a: object, b: object,
         N: object, G: object, nu: object, speed: object, cy: object, cphi: object,
         fit: Union[str, Sequence[str]], x0: Optional[Mapping[str, float]],
         bounds: Optional[Mapping[str, Tuple[float, float]]], loss: str,
         f_scale: Optional[float], weights: object, extra: Mapping[str, Any]) -> FitResult:
    least_squares = require("scipy.optimize", func, "fit", package="scipy").least_squares
    cxs, fs, speeds, ws, many = _data(func, cx, force, speed, weights)
    settings: Dict[str, Any] = dict(
        a=check_number(func, "a", a, positive=True), b=check_number(func, "b", b, positive=True),
        N=check_number(func, "N", N, positive=True), G=check_number(func, "G", G, positive=True),
        nu=check_number(func, "nu", nu), cy=check_number(func, "cy", cy),
        cphi=check_number(func, "cphi", cphi),
        speeds=tuple(float(v) for v in speeds), **extra)
    if loss not in LOSSES:
        _fail(func, f"loss must be one of {LOSSES}, got {loss!r}")
    f_scale = 0.05 if f_scale is None else check_number(func, "f_scale", f_scale, positive=True)

    c_all = np.concatenate(cxs)
    f_all = np.concatenate(fs)
    w_all = np.concatenate(ws)
    v_all = np.concatenate([np.full(c.size, v) for c, v in zip(cxs, speeds)])
    f_ref = float(np.max(np.abs(f_all)))
    if f_ref == 0.0:
        _fail(func, "force is zero everywhere; nothing to fit")
    if not np.any(c_all != 0.0):
        _fail(func, "cx is zero everywhere: a creep curve needs creepages to fit")
    if f_ref > 10.0 * settings["N"]:
        _fail(func, f"force reaches {f_ref:.6g} N, more than 10 N = {10 * settings['N']:.6g} "
                    f"N: a creep force is mu N at most (check the units of force and N)")
    # the curve's sense and the residuals in units of the largest force: sums,
    # differences and squares of forces near the double's range overflow
    sign = -1 if float(np.sum(f_all / f_ref * np.sign(c_all))) > 0.0 else 1
    target = sign * f_all
    target_n = target / f_ref

    start, fit, inner, lo, hi = _setup(func, spec, fit, x0, bounds, f_ref / settings["N"])
    # the start point through the library's own checks: a bad a, b, N, G, nu raises here,
    # naming the argument
    try:
        _model(model, start, settings, c_all, v_all, settings["cy"], settings["cphi"],
               errors="raise")
    except RollerRigError as e:                 # the model's own message, under our name
        _fail(func, f"the model at the start point: {e}")

    def residuals(theta: F64Array) -> F64Array:
        p = _natural(start, inner, theta)
        f = _model(model, p, settings, c_all, v_all, settings["cy"], settings["cphi"])
        r = w_all * (f / f_ref - target_n)
        if not np.all(np.isfinite(r)):
            raise RollerRigError(f"{func}: the model gives no finite force at the parameters "
                                 f"{p} for these data (cx, force, a, b, N, speed)")
        return r

    theta0 = np.array([start["kS"] / start["kA"] if n == _RATIO else start[n] for n in inner])
    theta0 = np.clip(theta0, lo, hi)          # a default start (mu0 from the data) may lie out
    # the friction law's parameters trade off against each other (one speed:
    # mu0 against A and B), and a start far off can settle in a shallow
    # minimum (a Polach curve at 30 m/s: 6 % of the peak off; a soft contact,
    # kA = 0.3, kS = 0.03, from the default kA = 1: 2.6 % off): a few more
    # starts, of the friction law and of the stiffness the initial slope
    # gives, unless one fits to 1e-4 of the peak
    sol = None
    stiffness = _stiffness(model, inner, x0, start, settings, c_all, target, f_ref)
    for t0 in _starts(theta0, inner, lo, hi, x0, stiffness):
        try:
            # data too extreme overflow in scipy's own arithmetic (its squares of
            # the Jacobian) before it gives up, and data all but zero (forces of
            # 1e-91 N) divide by zero in its trust-region step: the error below
            # says so, or the result is checked finite; numpy's warnings would
            # only come first
            with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
                s = least_squares(residuals, t0, bounds=(lo, hi), loss=loss,
                                  f_scale=f_scale, x_scale=1.0, method="trf")
        except ValueError as e:                 # scipy's SVD met an overflowed Jacobian
            _fail(func, f"the least-squares solve broke down on these data ({e}): the data "
                        f"(cx, force, N, speed) are too extreme for a creep curve")
        if sol is None or s.cost < sol.cost:
            sol = s
        if np.sqrt(np.mean(sol.fun ** 2)) <= 1e-4:      # fun: the residuals at x
            break
    assert sol is not None          # _starts yields theta0 first: one solve at least
    params = _natural(start, inner, sol.x)

    # standard errors from the plain (not loss-weighted) Jacobian at the solution
    r = residuals(sol.x)
    J = _jacobian(residuals, sol.x, lo, hi)
    cov = _covariance(J, r)
    T = np.eye(len(inner))                      # d natural / d internal
    if _RATIO in inner:
        i = inner.index(_RATIO)
        T[i, i] = params["kA"]
        if "kA" in inner:
            T[i, inner.index("kA")] = sol.x[i]
    cov = T @ cov @ T.T
    stderr = {n: float(np.sqrt(cov[k, k])) if np.isfinite(cov[k, k]) else math.nan
              for k, n in enumerate(fit)}

    near = 1e-6 * np.maximum(1.0, np.abs(sol.x))
    at_bound = tuple("kS" if n == _RATIO else n for n, x, l, h, d in
                     zip(inner, sol.x, lo, hi, near) if x - l <= d or h - x <= d)
    at_bound = tuple(n for n in fit if n in at_bound)
    model_f = _model(model, params, settings, c_all, v_all, settings["cy"], settings["cphi"])
    res_n = sign * (model_f / f_ref - target_n)    # sign * target_n is f_all / f_ref
    with np.errstate(over="ignore"):
        res_all = res_n * f_ref
    if not np.all(np.isfinite(res_all)):
        _fail(func, f"the residuals of the fit overflow (force up to {f_ref:.6g} N): the "
                    f"data (force, N) are too extreme for a creep curve")
    res_out: Union[F64Array, List[F64Array]]
    if many:
        cuts = np.cumsum([c.size for c in cxs])[:-1]
        res_out = np.split(res_all, cuts)
    else:
        res_out = res_all
    message = sol.message
    if sign < 0:
        message = ("force points the other way to the library's (Kalker's sign: fx < 0 "
                   "for cx > 0); fitted -force, and predict() returns the data's sign. "
                   + message)
    return FitResult(model=model, params=params, stderr=stderr, fitted=fit,
                     residuals=res_out, rms=_rms(res_all),
                     cost=float(sol.cost), success=bool(sol.success), message=message,
                     nfev=int(sol.nfev), sign=sign, at_bound=at_bound,
                     settings=settings)


def fit_polach(cx: Curves, force: Curves, *, a: float, b: float,
               N: npt.ArrayLike, G: float = 8.2e10, nu: float = 0.28, speed: npt.ArrayLike,
               cy: float = 0.0, cphi: float = 0.0,
               fit: Union[str, Sequence[str]] = ("mu0", "A", "B", "kA", "kS"),
               x0: Optional[Mapping[str, float]] = None,
               bounds: Optional[Mapping[str, Tuple[float, float]]] = None, loss: str = "soft_l1",
               f_scale: Optional[float] = None,
               weights: Optional[Curves] = None) -> FitResult:
    """Fit Polach's method (creep_forces(method="polach")) to creep curves.

    Parameters
    ----------
    cx : array_like or list of array_like
        Longitudinal creepage [-]: a 1-D array (one curve) or a list of them
        (one per speed); finite.
    force : array_like or list of array_like
        The longitudinal force fx [N] at each cx, shaped as cx (sign:
        Notes).
    a, b : float
        Semi-axes [m] of the contact, shared by the curves.
    N : float
        Normal load [N].
    G : float, optional
        Combined shear modulus [Pa].
    nu : float, optional
        Combined Poisson ratio [-].
    speed : float or array_like
        Rolling speed [m/s], > 0: a scalar or one per curve.
    cy : float, optional
        Lateral creepage [-], held.
    cphi : float, optional
        Spin [rad/m], held.
    fit : str or sequence of str, optional
        The parameters fitted, of mu0, A, B, kA, kS; the others are held at
        `x0`.
    x0 : dict, optional
        {name: start or held value}; defaults mu0 = the data's peak
        ``|force|`` / N, A = 0.4, B = 0.6 s/m, kA = 1, kS = 0.4 (Polach 2005,
        dry rail).
    bounds : dict, optional
        {name: (lo, hi)} narrowing the physical bounds (Notes); the ratio
        kS/kA is bounded as "kS/kA".
    loss : str, optional
        least_squares' robust loss: "linear", "soft_l1", "huber", "cauchy"
        or "arctan".
    f_scale : float, optional
        The loss's scale, a fraction of the data's peak ``|force|``
        (default 0.05).
    weights : array_like or list of array_like, optional
        Per-point weights >= 0 (not all 0), shaped as cx.

    Returns
    -------
    FitResult
        The parameters (fitted and held), their standard errors, the
        residuals [N] and the solver's report (:class:`FitResult`).

    Raises
    ------
    RollerRigError
        Naming the argument: data not finite, not 1-D, empty or of
        mismatched lengths; speed not > 0 or not one per curve; a, b, N, G,
        nu, cy, cphi not finite numbers (a, b, N, G > 0); an unknown or
        repeated parameter in fit, x0 or bounds; a start outside its
        bounds (kS above kA); bounds that leave no room; force zero
        everywhere, cx zero everywhere, or force above 10 times N; a model that
        gives no finite force.
    ImportError
        Without scipy (the extra "fit": ``pip install 'rollerrig[fit]'``).

    See Also
    --------
    fit_modified_fastsim : the same for modified FASTSIM.
    creep_forces : the model, method="polach".
    rollerrig.plot.fit : draws a fit over its data.

    Notes
    -----
    **Sign.**  The library's forces act on the wheel and oppose the
    creepage (Kalker's sign: fx < 0 for cx > 0).  The fit uses the data's
    sign as given.  If the data point the other way (sum of force *
    sign(cx) > 0: forces on the roller, or magnitudes), they are negated for
    the fit, FitResult.sign is -1, the message says so, and predict() and
    the residuals are in the data's sign.

    **What the data determine.**  mu0, kA and kS come from the shape of one
    curve: the initial slope fixes kA + kS, the curvature of the rise their
    split, the peak mu0.  The falling friction mu(w) = mu0 [(1 - A)
    exp(-B w) + A] depends on the slip speed w = speed * ``|creepage|``, so A
    and B are only identifiable where the data reach well past the peak
    into the falling branch, and B (the speed scale of the fall) only
    robustly with several speeds: at one speed B trades off against kA, kS
    and mu0.  A parameter the data cannot fix shows as a large standard
    error (NaN where the Jacobian is singular); hold it with `fit` and `x0`
    instead.

    **The fit.**  scipy.optimize.least_squares ('trf', bounds) on the
    residuals r = weights * (model - force) / F_ref, F_ref the data's peak
    ``|force|``, with a robust loss whose f_scale is the residual beyond
    which a point counts as an outlier.  Several starts (x0, then the
    friction law moved, then Polach's kA + kS from the data's initial
    slope); the best fit is kept, and the first that fits to 1e-4 of the
    peak ends the search.  Bounds: mu0 > 0, 0 < A <= 1, B >= 0,
    0 < kS <= kA <= 1 (kS is fitted as the ratio kS/kA in (0, 1], so the
    order holds).  Standard errors: cov = (J^T J)^-1 s^2 from the Jacobian
    J of the unweighted-loss residuals at the solution (central
    differences), s^2 = sum r^2 / (m - p), m points, p fitted parameters;
    kS's from the ratio's by the delta method.  They assume independent
    errors of equal variance (after weighting) and a model that fits
    (rollerrig.analysis.fit's module docstring has the details).

    Examples
    --------
    A curve made by the model itself, fitted back:

    >>> import numpy as np
    >>> import rollerrig as rr
    >>> cx = np.linspace(1e-4, 0.02, 25)
    >>> contact = dict(a=6.3e-3, b=12.6e-3, N=106.7e3)
    >>> fx = rr.creep_forces(cx, mu=0.35, speed=10.0, friction=rr.FallingFriction(0.4, 0.6),
    ...                      method="polach", kA=0.8, kS=0.3, **contact).fx
    >>> res = rr.fit_polach(cx, fx, speed=10.0, fit=("mu0", "kA", "kS"), **contact)
    >>> print({k: round(v, 4) for k, v in res.params.items()})
    {'mu0': 0.35, 'A': 0.4, 'B': 0.6, 'kA': 0.8, 'kS': 0.3}
    >>> print(f"{res.predict(0.01):.0f} N")
    -28281 N
    """
    return _fit("fit_polach", "polach", POLACH_PARAMETERS, cx, force, a, b, N, G, nu,
                speed, cy, cphi, fit, x0, bounds, loss, f_scale, weights, {})


def fit_modified_fastsim(cx: Curves, force: Curves, *, a: float, b: float, N: npt.ArrayLike,
                         G: float = 8.2e10, nu: float = 0.28, speed: npt.ArrayLike,
                         cy: float = 0.0, cphi: float = 0.0,
                         fit: Union[str, Sequence[str]] = ("k0", "alpha_inf", "beta"),
                         x0: Optional[Mapping[str, float]] = None,
                         bounds: Optional[Mapping[str, Tuple[float, float]]] = None,
                         loss: str = "soft_l1", f_scale: Optional[float] = None,
                         weights: Optional[Curves] = None, nx: int = 20, ny: int = 20,
                         grid: str = "rect", bound: str = "parabolic",
                         slip_speed: Optional[str] = None) -> FitResult:
    """Fit modified FASTSIM (Spiryagin, Polach and Cole 2013) to creep curves.

    Parameters
    ----------
    cx, force, a, b, N, G, nu, speed, cy, cphi, x0, bounds, loss, f_scale, weights
        As for :func:`fit_polach` (cx [-], force [N], a, b [m], N [N], G
        [Pa], speed [m/s], cphi [rad/m]).
    fit : str or sequence of str, optional
        The parameters fitted, of mu0, A, B (falling friction) and k0,
        alpha_inf, beta (the slope reduction k = k0 (alpha_inf + (1 -
        alpha_inf) / (1 + beta eps))).  By default only k0, alpha_inf, beta:
        the friction law is held at x0 (mu0 = the data's peak ``|force|`` /
        N, A = 0.4, B = 0.6 s/m); give the measured friction law in x0, or
        add "mu0", "A", "B" to fit.  Defaults of the others: k0 = 0.54,
        alpha_inf = 0.02, beta = 0.62 (CONTACT's example).
    nx, ny : int, optional
        FASTSIM's grid, passed to creep_forces.
    grid, bound : str, optional
        Passed to creep_forces.
    slip_speed : str, optional
        Passed to creep_forces; None: the method's default, the rigid slip
        speed.

    Returns
    -------
    FitResult
        As for fit_polach (:class:`FitResult`).

    Raises
    ------
    RollerRigError
        As for fit_polach, and for a FASTSIM option out of range.
    ImportError
        Without scipy (the extra "fit").

    See Also
    --------
    fit_polach : the method's notes on the sign, the data and the fit.

    Notes
    -----
    Each evaluation runs FASTSIM on every point, so a fit takes a few
    hundred calls on the data.

    Examples
    --------
    >>> import numpy as np
    >>> import rollerrig as rr
    >>> cx = np.linspace(1e-4, 0.02, 25)
    >>> contact = dict(a=6.3e-3, b=12.6e-3, N=106.7e3)
    >>> fx = rr.creep_forces(cx, mu=0.35, speed=10.0, friction=rr.FallingFriction(0.4, 0.6),
    ...                      method="modified_fastsim", k0=0.6, alpha_inf=0.1, beta=1.0,
    ...                      nx=20, ny=20, **contact).fx
    >>> res = rr.fit_modified_fastsim(cx, fx, speed=10.0, x0={"mu0": 0.35}, **contact)
    >>> print({k: round(res.params[k], 4) for k in res.fitted})
    {'k0': 0.6, 'alpha_inf': 0.1, 'beta': 1.0}
    """
    extra = dict(nx=nx, ny=ny, grid=grid, bound=bound, slip_speed=slip_speed)
    return _fit("fit_modified_fastsim", "modified_fastsim", MODIFIED_FASTSIM_PARAMETERS, cx,
                force, a, b, N, G, nu, speed, cy, cphi, fit, x0, bounds, loss, f_scale,
                weights, extra)
