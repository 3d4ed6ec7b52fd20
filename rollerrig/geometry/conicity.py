"""Equivalent conicity of a wheel-roller (or wheel-rail) pair.

A conical wheelset of cone angle gamma has the rolling-radius difference
Delta r(y) = r_left - r_right = 2 tan(gamma) y at the lateral shift y, and
Klingel's kinematic hunting wavelength L = 2 pi sqrt(e0 r0 / tan(gamma))
(e0 half the distance between the contact points, r0 the rolling radius).
Real profiles give a nonlinear Delta r(y); the equivalent conicity
tan(gamma_e) is the cone that stands for them at an amplitude y^ of the
lateral motion.  EN 15302 (UIC 519) sets down the principle and a benchmark
but no single numerical method; three definitions are computed here, all
from Delta r(y) of ``rollerrig.wheelset_contact`` (rigid contact, no yaw):

``"harmonic"``  harmonic linearisation (describing function): for
    y = c + y^ sin t, tan(gamma_e) = b1 / (2 y^) with b1 the first Fourier
    sine coefficient of Delta r(c + y^ sin t),
    b1 = (1/pi) integral_0^2pi Delta r(c + y^ sin t) sin t dt.
    The same as a linear least-squares fit of Delta r over the stroke,
    weighted by the time the harmonic motion spends at each y.
``"klingel"``   the kinematic wavelength of the nonlinear wheelset equation
    y'' = -Delta r(y) / (2 e0 r0) (x the distance rolled) at amplitude y^,
    put into Klingel's formula tan(gamma_e) = e0 r0 (2 pi / L)^2.  With
    u = x / sqrt(2 e0 r0) the equation is y'' = -Delta r(y) and
    tan(gamma_e) = 2 pi^2 / L_u^2, free of e0 and r0.  This is the method
    that secondary sources describe as EN 15302 Annex B ("integration of the
    nonlinear differential equation", Delta y <= 0.1 mm); the standard itself
    was not available to check it against.
``"simple"``    the secant (Delta r(c + y^) - Delta r(c - y^)) / (4 y^), which
    is Delta r(y^) / (2 y^) for a symmetric pair: for comparison only.

EN 15302 Annex C (informative) also describes a "linear regression of the
Delta r function"; its weighting and range could not be verified, so it is
not offered under that name ("harmonic" is the time-weighted regression).

All three give tan(gamma) exactly for a conical wheelset.  A jump of
Delta r at y = 0 (two-point contact, as S1002 on UIC60 1:40 at gauge
1435 mm) raises "harmonic" and "klingel" well above "simple" at small
amplitudes: the jump acts at once, the secant sees it only as an offset.

Centre of the motion.  For a symmetric pair (Delta r odd) the motion is
centred on y = 0.  Otherwise a kinematic oscillation is centred where the
yaw it builds up over a cycle cancels: ``centre="balance"`` solves, per
amplitude, integral Delta r(c + y^ sin t) dt = 0 over the cycle for
"harmonic", and integral_{c-y^}^{c+y^} Delta r dy = 0 (equal potential at
both turning points) for "klingel" and "simple".  A number fixes c [m]
for "harmonic" and "simple" (EN 15302's symmetric case is c = 0);
"klingel" always balances, since a kinematic oscillation has equal
potential at its turning points.  Where several centres balance (a
Delta r that pushes the wheelset off y = 0 and holds it at two off-centre
points), bisection takes one of them.

References
----------
EN 15302:2008+A1:2010, Railway applications - Method for determining the
equivalent conicity (CEN); UIC Code 519, 1st ed. 2004 (same content).
Klingel, W. (1883), Ueber den Lauf der Eisenbahnwagen auf gerader Bahn,
Organ fuer die Fortschritte des Eisenbahnwesens 20.
Polach, O. (2010), Characteristic parameters of nonlinear wheel/rail
contact geometry, Vehicle System Dynamics 48 (suppl.), 19-36.
Gelb, A., Vander Velde, W.E. (1968), Multiple-input describing functions and
nonlinear system design, McGraw-Hill (harmonic linearisation).

Example::

    import rollerrig as rr
    from rollerrig.geometry.conicity import equivalent_conicity
    g = rr.RigGeometry(wheel=rr.Profile.s1002(), roller=rr.Profile.uic60(),
                       wheel_radius=0.46, roller_radius=0.46,
                       wheel_y=0.75, roller_y=0.76053)
    equivalent_conicity(g, [0.001, 0.003, 0.005], method="harmonic")
"""
from __future__ import annotations

import math
import sys
import numbers
import warnings
from typing import Any, Callable, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError, RollerRigWarning
from .._typing import F64Array, FloatResult
from .wheelset import RigGeometry, wheelset_contact

__all__ = ["CONICITY_METHODS", "equivalent_conicity", "rolling_radius_difference"]

#: the definitions equivalent_conicity offers (module docstring)
CONICITY_METHODS = ("harmonic", "klingel", "simple")

_FUNC = "equivalent_conicity"
_MAX_AMPLITUDE = 0.05   #: [m] a larger amplitude is taken for millimetres given as metres


@overload
def rolling_radius_difference(geometry: RigGeometry, y_ws: float, **search: Any) -> float: ...
@overload
def rolling_radius_difference(geometry: RigGeometry, y_ws: npt.ArrayLike,
                              **search: Any) -> FloatResult: ...
def rolling_radius_difference(geometry: RigGeometry, y_ws: npt.ArrayLike,
                              **search: Any) -> FloatResult:
    """Delta r = r_left - r_right [m] at the lateral shifts y_ws [m].

    Parameters
    ----------
    geometry : RigGeometry
        The profiles and their placement.
    y_ws : float or array_like
        Lateral shifts [m], a number or a 1-D array.  Positive y_ws moves
        the wheelset to the left, so Delta r rises with y_ws.
    **search
        Options of wheelset_contact (nsamples, two_point_tol, two_point_sep).

    Returns
    -------
    float or ndarray
        Delta r [m] from ``wheelset_contact``; NaN where a wheel has no
        contact.

    See Also
    --------
    equivalent_conicity : the conicity from Delta r.

    Examples
    --------
    >>> import rollerrig as rr
    >>> g = rr.RigGeometry.standard()
    >>> rr.rolling_radius_difference(g, [0.0, 0.003]).round(6)
    array([0.      , 0.000994])
    """
    c = wheelset_contact(geometry, y_ws, errors="ignore", **search)
    dr = np.where(c.status >= 0, c.left.r - c.right.r, np.nan)
    return dr if np.ndim(y_ws) else float(dr[0])


def _is_number(v: object) -> bool:
    return isinstance(v, numbers.Real) and not isinstance(v, bool)


class _DeltaR:
    """A tabulated Delta r(y), linear between the nodes, and its integral
    (the potential of the kinematic equation), exact for that interpolant."""

    def __init__(self, y: F64Array, dr: F64Array) -> None:
        self.y, self.dr = y, dr
        self.slope = np.diff(dr) / np.diff(y)
        # NaN cells add nothing: differences of V within a finite run stay exact
        self.V = np.concatenate(([0.0], np.nancumsum(0.5 * (dr[1:] + dr[:-1]) * np.diff(y))))

    @overload
    def __call__(self, y: float) -> float: ...
    @overload
    def __call__(self, y: F64Array) -> F64Array: ...
    def __call__(self, y: Union[float, F64Array]) -> Union[float, F64Array]:
        return np.interp(y, self.y, self.dr, left=np.nan, right=np.nan)

    def potential(self, y: npt.ArrayLike) -> F64Array:
        y = np.asarray(y, dtype=float)
        k = np.clip(np.searchsorted(self.y, y, side="right") - 1, 0, self.y.size - 2)
        h = y - self.y[k]
        v = self.V[k] + self.dr[k] * h + 0.5 * self.slope[k] * h * h
        return np.where((y >= self.y[0]) & (y <= self.y[-1]), v, np.nan)


def _bisect(g: Callable[[float], float], lo: float, hi: float) -> Optional[float]:
    """The root of g in [lo, hi] (g increasing through it), by bisection."""
    glo, ghi = g(lo), g(hi)
    if not (np.isfinite(glo) and np.isfinite(ghi)) or glo > 0.0 or ghi < 0.0:
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        gm = g(mid)
        if not np.isfinite(gm):
            return None
        if gm == 0.0:
            return mid
        lo, hi = (mid, hi) if gm < 0.0 else (lo, mid)
        if hi - lo < 1e-13:
            break
    return 0.5 * (lo + hi)


def _finite_run(f: _DeltaR, y0: float) -> Optional[Tuple[float, float]]:
    """The widest interval [lo, hi] of table nodes around y0 with finite Delta r."""
    ok = np.isfinite(f.dr)
    k = int(np.clip(np.searchsorted(f.y, y0), 0, f.y.size - 1))
    if not ok[k]:
        return None
    lo = k
    while lo > 0 and ok[lo - 1]:
        lo -= 1
    hi = k
    while hi < f.y.size - 1 and ok[hi + 1]:
        hi += 1
    return f.y[lo], f.y[hi]


def _centre(f: _DeltaR, amp: float, method: str, centre: Union[str, float],
            t_sin: F64Array) -> float:
    if not isinstance(centre, str):
        return float(centre)
    run = _finite_run(f, 0.0)
    if run is None:
        raise RollerRigError(f"{_FUNC}: Delta r is not known at y = 0 (no contact, or no "
                             f"Hertz ellipse there)")
    if method == "harmonic":
        def g(c: float) -> float:
            return float(np.mean(f(c + amp * t_sin)))
    else:
        def g(c: float) -> float:
            return float(f.potential(c + amp) - f.potential(c - amp))
    inset = amp * (1.0 + 1e-9)               # the stroke stays inside despite rounding
    lo, hi = run[0] + inset, run[1] - inset
    c = _bisect(g, lo, hi) if lo < hi else None
    if c is None:
        raise RollerRigError(
            f"{_FUNC}: amplitude = {amp!r} m: no centre of oscillation found with the whole "
            f"stroke inside the known Delta r ({run[0]:.6g} .. {run[1]:.6g} m): Delta r does "
            f"not change sign there, or the amplitude is too large for the clearance")
    return c


def _one(f: _DeltaR, amp: float, method: str, centre: Union[str, float],
         n: int) -> Union[float, np.floating[Any]]:
    t = 2.0 * math.pi * (np.arange(n) + 0.5) / n
    st = np.sin(t)
    c = _centre(f, amp, method, centre, st)
    lo, hi = c - amp, c + amp
    nodes = np.r_[lo, f.y[(f.y > lo) & (f.y < hi)], hi]
    unknown = nodes[~np.isfinite(f(nodes))]
    if unknown.size:
        raise RollerRigError(
            f"{_FUNC}: amplitude = {amp!r} m: Delta r is not known over the whole stroke "
            f"{lo:.6g} .. {hi:.6g} m (first at y = {unknown[0]:.6g} m: no contact, or no Hertz "
            f"ellipse, or beyond the table)")
    if method == "simple":
        return (f(hi) - f(lo)) / (4.0 * amp)
    if method == "harmonic":
        b1 = 2.0 * np.mean(f(c + amp * st) * st)
        return b1 / (2.0 * amp)
    # klingel: half period of y'' = -Delta r(y) between the turning points,
    # with y = c + amp sin(theta) taking out the inverse-square-root ends
    th = math.pi * ((np.arange(n) + 0.5) / n - 0.5)
    y = c + amp * np.sin(th)
    vb = 0.5 * (f.potential(hi) + f.potential(lo))
    drop = vb - f.potential(y)
    if np.any(drop <= 0.0):
        warnings.warn(f"{_FUNC}: amplitude = {amp!r} m: no kinematic oscillation of this "
                      f"amplitude (Delta r does not push the wheelset back over the whole "
                      f"stroke); result NaN", RollerRigWarning, stacklevel=4)
        return math.nan
    half = np.sum(amp * np.cos(th) / np.sqrt(2.0 * drop)) * (math.pi / n)
    return 2.0 * math.pi ** 2 / (2.0 * half) ** 2


#: a tabulated Delta r: (y, delta_r), two 1-D arrays [m]
DeltaRTable = Tuple[npt.ArrayLike, npt.ArrayLike]


@overload
def equivalent_conicity(geometry: Union[RigGeometry, DeltaRTable], amplitude: float = ...,
                        method: str = ..., *, centre: Union[str, float] = ...,
                        dy: Optional[float] = ..., y_span: Optional[float] = ..., n: int = ...,
                        **search: Any) -> float: ...
@overload
def equivalent_conicity(geometry: Union[RigGeometry, DeltaRTable], amplitude: npt.ArrayLike,
                        method: str = ..., *, centre: Union[str, float] = ...,
                        dy: Optional[float] = ..., y_span: Optional[float] = ..., n: int = ...,
                        **search: Any) -> Union[float, npt.NDArray[np.float64]]: ...
def equivalent_conicity(geometry: Union[RigGeometry, DeltaRTable],
                        amplitude: npt.ArrayLike = 0.003,
                        method: str = "harmonic", *, centre: Union[str, float] = "balance",
                        dy: Optional[float] = None, y_span: Optional[float] = None, n: int = 2048,
                        **search: Any) -> Union[float, npt.NDArray[np.float64]]:
    """Equivalent conicity tan(gamma_e) at the amplitude(s) y^ [m].

    Parameters
    ----------
    geometry : RigGeometry or tuple of array_like
        A RigGeometry (Delta r is computed with wheelset_contact on a grid
        of step dy), or a pair (y, delta_r) of 1-D arrays [m]: a tabulated
        Delta r = r_left - r_right, y strictly increasing, used as it is
        (linear between the points).
    amplitude : float or array_like, optional
        y^ [m], a number or an array of them, each > 0 (and < 50 mm).
    method : {"harmonic", "klingel", "simple"}, optional
        The definition (Notes; the module docstring has the details).
    centre : "balance" or float, optional
        "balance" (the kinematic centre of the motion; 0 for a symmetric
        pair) or, for "harmonic" and "simple", a lateral position [m].
    dy : float, optional
        Grid step for Delta r from a RigGeometry [m], 0 < dy <= 1e-4 (EN
        15302 asks for 0.1 mm or finer); default 2e-5.
    y_span : float, optional
        The grid from a RigGeometry spans -y_span .. +y_span [m]; default 2
        max(y^) + 4 mm, room for the centre of an asymmetric pair to move
        off y = 0.
    n : int, optional
        Quadrature points over the cycle (integer from 64 to 1e6).
    **search
        Options of wheelset_contact (nsamples, two_point_tol, ...).

    Returns
    -------
    float or ndarray
        tan(gamma_e) [-]: a float for a scalar amplitude, else an array of
        its shape.

    Raises
    ------
    RollerRigError
        For bad arguments (naming them) and where Delta r is unknown over a
        stroke (a wheel off its roller).

    Warns
    -----
    RollerRigWarning
        "klingel" returns NaN with a warning at an amplitude that no
        kinematic oscillation reaches.

    See Also
    --------
    rolling_radius_difference : Delta r at given shifts.

    Notes
    -----
    For y = c + y^ sin t: "harmonic" is the harmonic linearisation,
    tan(gamma_e) = b1 / (2 y^) with b1 the first Fourier sine coefficient
    of Delta r (a least-squares fit of Delta r over the stroke weighted by
    the time spent at each y); "klingel" puts the kinematic wavelength L of
    the nonlinear wheelset equation y'' = -Delta r(y) / (2 e0 r0) into
    Klingel's formula tan(gamma_e) = e0 r0 (2 pi / L)^2 (described by
    secondary sources as EN 15302 Annex B); "simple" is the secant (Delta
    r(c + y^) - Delta r(c - y^)) / (4 y^), for comparison only.  All three
    give tan(gamma) exactly for a conical wheelset.

    Examples
    --------
    A conical pair (Delta r = 2 tan(gamma) y) gives its cone, a nonlinear
    one three different values:

    >>> import numpy as np
    >>> import rollerrig as rr
    >>> y = np.linspace(-0.01, 0.01, 201)
    >>> round(rr.equivalent_conicity((y, 2 * 0.05 * y), 0.003), 6)
    0.05
    >>> dr = 2 * 0.05 * y + 2e-4 * np.sign(y) + 40 * y**3
    >>> for m in ("harmonic", "klingel", "simple"):
    ...     print(m, rr.equivalent_conicity((y, dr), [0.002, 0.004], method=m).round(4))
    harmonic [0.1137 0.0821]
    klingel [0.1125 0.0817]
    simple [0.1001 0.0753]
    """
    if not isinstance(method, str) or method not in CONICITY_METHODS:
        raise RollerRigError(f"{_FUNC}: method must be one of {CONICITY_METHODS}, "
                             f"got {method!r}")
    try:
        amp = np.asarray(amplitude, dtype=float)
    except (TypeError, ValueError):
        raise RollerRigError(f"{_FUNC}: amplitude must be a number or an array of numbers "
                             f"[m], got {amplitude!r:.60}") from None
    if amp.size == 0:
        raise RollerRigError(f"{_FUNC}: amplitude is empty")
    bad = np.flatnonzero(~(np.isfinite(amp) & (amp > 0.0)).reshape(-1))
    if bad.size:
        raise RollerRigError(f"{_FUNC}: amplitude must be finite and > 0 [m], got "
                             f"{float(amp.reshape(-1)[bad[0]])!r}")
    if np.max(amp) > _MAX_AMPLITUDE:
        raise RollerRigError(f"{_FUNC}: amplitude = {float(np.max(amp))!r} m is larger than "
                             f"{_MAX_AMPLITUDE} m: amplitudes are in metres")
    if isinstance(centre, str):
        if centre != "balance":
            raise RollerRigError(f"{_FUNC}: centre must be 'balance' or a number [m], "
                                 f"got {centre!r}")
    elif not (_is_number(centre) and abs(centre) <= sys.float_info.max):   # finite, ints too
        raise RollerRigError(f"{_FUNC}: centre must be 'balance' or a number [m], "
                             f"got {centre!r:.60}")
    elif method == "klingel":
        raise RollerRigError(f"{_FUNC}: method 'klingel' finds the centre of the motion "
                             f"itself (equal potential at both turning points): centre must "
                             f"be 'balance', got {centre!r}")
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 64 <= n <= 1_000_000:
        raise RollerRigError(f"{_FUNC}: n must be an integer from 64 to 1e6, got {n!r}")

    if isinstance(geometry, RigGeometry):
        if dy is None:
            dy = 2e-5
        elif not (_is_number(dy) and 0.0 < dy <= 1e-4):
            raise RollerRigError(f"{_FUNC}: dy must be a number in (0, 1e-4] m, got {dy!r}")
        if y_span is None:
            y_span = 2.0 * float(np.max(amp)) + 4e-3
        elif not (_is_number(y_span) and np.max(amp) <= y_span <= 0.1):
            raise RollerRigError(f"{_FUNC}: y_span must be a number between the largest "
                                 f"amplitude and 0.1 m, got {y_span!r}")
        steps = y_span / dy
        if not steps <= 50_000:
            raise RollerRigError(f"{_FUNC}: y_span / dy = {steps:.3g} grid steps each side; "
                                 f"at most 50000 (a larger dy or a smaller y_span)")
        k = int(math.ceil(steps))
        y = dy * np.arange(-k, k + 1, dtype=np.float64)
        # (y is 1-D: Delta r an array, which np.asarray passes through)
        f = _DeltaR(y, np.asarray(rolling_radius_difference(geometry, y, **search)))
    elif isinstance(geometry, (tuple, list)) and len(geometry) == 2:
        extra = sorted(search) + [k for k, v in (("dy", dy), ("y_span", y_span))
                                  if v is not None]
        if extra:
            raise RollerRigError(f"{_FUNC}: options {extra} apply only to a RigGeometry, "
                                 f"not to a tabulated Delta r")
        try:
            y, dr = (np.asarray(v, dtype=float) for v in geometry)
        except (TypeError, ValueError):
            raise RollerRigError(f"{_FUNC}: geometry as (y, delta_r) must hold two arrays "
                                 f"of numbers") from None
        if y.ndim != 1 or y.shape != dr.shape or y.size < 3:
            raise RollerRigError(f"{_FUNC}: geometry as (y, delta_r) needs two 1-D arrays "
                                 f"of one length >= 3, got shapes {y.shape}, {dr.shape}")
        if not np.all(np.isfinite(y)) or np.any(np.diff(y) <= 0.0):
            raise RollerRigError(f"{_FUNC}: geometry as (y, delta_r): y must be finite "
                                 f"and strictly increasing")
        # shifts and radius differences of a wheelset are millimetres: a metre
        # of either is a unit mistake, and larger values overflow the quadrature
        if np.max(np.abs(y)) > 1.0 or np.nanmax(np.abs(dr), initial=0.0) > 1.0 \
                or np.any(np.isinf(dr)):
            raise RollerRigError(f"{_FUNC}: geometry as (y, delta_r): |y| and |delta_r| "
                                 f"must be at most 1 m (NaN marks a missing delta_r)")
        if np.min(np.diff(y)) < 1e-12:
            raise RollerRigError(f"{_FUNC}: geometry as (y, delta_r): points of y less than "
                                 f"1e-12 m apart")
        f = _DeltaR(y, dr)
    else:
        raise RollerRigError(f"{_FUNC}: geometry must be a RigGeometry or a pair "
                             f"(y, delta_r) of arrays, got {geometry!r:.60}")

    out = np.array([_one(f, float(a), method, centre, int(n)) for a in amp.reshape(-1)])
    return float(out[0]) if amp.ndim == 0 else out.reshape(amp.shape)
