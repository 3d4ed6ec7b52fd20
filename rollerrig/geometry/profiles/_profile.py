"""The Profile class: an immutable profile z(y) with its cubic spline, and
read_profile, which makes one from a file by the table of formats READERS."""
from __future__ import annotations

import contextlib
import math
import os
import warnings
from types import MappingProxyType
from typing import (IO, Any, Callable, Dict, Iterator, Mapping, Optional, Sequence, Tuple,
                    Union, overload)

import numpy as np
import numpy.typing as npt

from ... import _core
from ..._errors import RollerRigError, RollerRigWarning, check_number, status_message
from ..._files import write_file
from ..._typing import F64Array, FloatResult
from ._checks import (MAX_COORD, MAX_POINTS, MIN_POINTS, MIN_SPACING, MIN_WIDTH,
                      UNITS, _as_float_array, _check_bc, _check_kind, _check_scale,
                      _prepare)
from ._spline import _smooth, _spline_fit
from .readers import READERS

#: the shipped profile files (rollerrig/data/profiles), read by Profile.s1002,
#: Profile.uic60 and RigGeometry.measured_pair
DATA_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                        "data", "profiles")


class Profile:
    """An immutable wheel or rail/roller profile z(y) with its cubic spline.

    Parameters
    ----------
    y, z : array_like
        1-D arrays [m]: y strictly increasing, towards the field side; z
        downward (rollerrig.geometry.profiles docstring).  At least 4 finite
        points, ``|y|``, ``|z|`` <= 2 m, at least 1 mm wide, points at least
        1e-12 m apart, at most 100 000 points.
    kind : {"wheel", "rail"}
        A roller is "rail".
    name : str, optional
        A label.
    meta : dict, optional
        Header values, read-only afterwards.
    bc : {"not-a-knot", "natural"}, optional
        Spline end conditions; default "not-a-knot" ("natural" with
        smoothing, which takes no other).
    smoothing : float, optional
        None (interpolate the points) or a wavelength L [m], up to 2 m: the
        natural smoothing spline with lam = (L / 2 pi)^4 (module
        docstring).  ``z`` then holds the smoothed values at the nodes and
        ``z_input`` the points given.

    Raises
    ------
    RollerRigError
        Naming the index and values: points out of order, duplicate or too
        close, non-finite, too few or too many, out of scale; a bad kind,
        bc or smoothing; smoothing numerically singular on the points.

    See Also
    --------
    read_profile : a Profile from a file.
    RigGeometry : places the profiles on the rig.

    Notes
    -----
    The constructor is strict (it raises RollerRigError for points out of
    order); ``Profile.from_points`` and ``read_profile`` reorder points and
    remove folds first.  Evaluation (``z_at``, ``slope``,
    ``second_derivative``, ``curvature``, ``evaluate``) takes numbers or
    arrays, returns floats or arrays of the same shape, and gives NaN
    outside [y_min, y_max].  A Profile is immutable: ``shifted``,
    ``mirrored``, ``canted`` give new ones.

    Examples
    --------
    >>> import rollerrig as rr
    >>> p = rr.Profile([0.0, 0.01, 0.02, 0.03], [0.0, 1e-4, 4e-4, 9e-4], kind="rail")
    >>> p
    Profile(kind='rail', name='', 4 points, y 0 .. 30 mm, bc='not-a-knot')
    >>> z, dz, d2z = p.evaluate(0.015)
    >>> print(f"{z:.6f} {dz:.4f} {d2z:.4f}")
    0.000225 0.0300 2.0000
    >>> w = rr.Profile.s1002()
    >>> print(f"{w.slope(0.01):.4f}", w.z_at(1.0))
    -0.0113 nan
    """

    __slots__ = ("_y", "_z", "_z_input", "_s", "_c2", "_c3", "_d2", "_kind", "_name",
                 "_meta", "_bc", "_smoothing")
    # (the slots' types; set once, by __init__ through object.__setattr__)
    _y: F64Array
    _z: F64Array
    _z_input: F64Array
    _s: F64Array
    _c2: F64Array
    _c3: F64Array
    _d2: F64Array
    _kind: str
    _name: str
    _meta: Mapping[str, Any]
    _bc: str
    _smoothing: Optional[float]

    def __init__(self, y: npt.ArrayLike, z: npt.ArrayLike, *, kind: str, name: str = "",
                 meta: Optional[Mapping[str, Any]] = None, bc: Optional[str] = None,
                 smoothing: Optional[float] = None) -> None:
        func = "Profile"
        _check_kind(func, kind)
        smoothing = check_number(func, "smoothing", smoothing, positive=True,
                                  allow_none=True)
        if smoothing is not None and smoothing > MAX_COORD:
            raise RollerRigError(f"{func}: smoothing is a wavelength [m] up to {MAX_COORD:g} "
                                 f"m (the profile's own scale), got {smoothing!r}")
        bc = _check_bc(func, bc, smoothing)
        y = _as_float_array(func, "y", y)
        z = _as_float_array(func, "z", z)
        if y.ndim != 1 or z.ndim != 1 or y.shape != z.shape:
            raise RollerRigError(f"{func}: y and z must be 1-D arrays of one length, got "
                                 f"shapes {y.shape} and {z.shape}")
        if not MIN_POINTS <= len(y) <= MAX_POINTS:
            raise RollerRigError(f"{func}: y and z hold {len(y)} point(s); a profile has "
                                 f"from {MIN_POINTS} to {MAX_POINTS}")
        bad = np.flatnonzero(~(np.isfinite(y) & np.isfinite(z)))
        if bad.size:
            i = int(bad[0])
            raise RollerRigError(f"{func}: non-finite value at index {i}: y = {y[i]!r}, "
                                 f"z = {z[i]!r}")
        with np.errstate(over="ignore"):     # gaps beyond 1.8e308 m: _check_scale's
            dy = np.diff(y)
        close = np.flatnonzero((dy > 0.0) & (dy < MIN_SPACING))
        if close.size:
            i = int(close[0])
            raise RollerRigError(
                f"{func}: y[{i}] = {y[i]!r} and y[{i + 1}] = {y[i + 1]!r} are less than "
                f"{MIN_SPACING:g} m apart: no spline through such points is meaningful")
        if np.any(dy <= 0.0):
            i = int(np.flatnonzero(dy <= 0.0)[0])
            what = "duplicate y" if dy[i] == 0.0 else "y decreases"
            raise RollerRigError(
                f"{func}: y must be strictly increasing: {what} at index {i + 1} "
                f"(y[{i}] = {y[i]!r}, y[{i + 1}] = {y[i + 1]!r}); Profile.from_points "
                f"reorders points and removes folds")
        _check_scale(func, y, z, (np.arange(len(y)), "index"))
        zn = z
        if smoothing is not None:
            smoothed, j = _smooth(y, z, (smoothing / (2.0 * math.pi)) ** 4)
            if smoothed is None:
                raise RollerRigError(
                    f"{func}: smoothing = {smoothing!r} m is numerically singular on these "
                    f"points near index {j} (y[{j}] = {y[j]!r}; point spacings from "
                    f"{np.min(np.diff(y)):.3g} to {np.max(np.diff(y)):.3g} m): space the "
                    f"points more evenly, remove near-duplicates, or smooth less")
            zn = smoothed
        s, c2, c3, d2 = _spline_fit(y, zn, bc)
        for arr in (y, zn, z, s, c2, c3, d2):
            arr.flags.writeable = False
        meta = dict(meta or {})
        set_ = object.__setattr__
        set_(self, "_y", y)
        set_(self, "_z", zn)
        set_(self, "_z_input", z)
        set_(self, "_s", s)
        set_(self, "_c2", c2)
        set_(self, "_c3", c3)
        set_(self, "_d2", d2)
        set_(self, "_kind", kind)
        set_(self, "_name", str(name))
        set_(self, "_meta", MappingProxyType(meta))
        set_(self, "_bc", bc)
        set_(self, "_smoothing", smoothing)

    # -- immutability, pickling, display

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"Profile is immutable (cannot set {name!r}); use shifted(), "
                             f"mirrored() or a new Profile")

    def __delattr__(self, name: str) -> None:
        raise AttributeError(f"Profile is immutable (cannot delete {name!r})")

    def __reduce__(self) -> Tuple[Callable[..., Profile], Tuple[Any, ...]]:
        return (_rebuild, (np.array(self._y), np.array(self._z_input), self._kind,
                           self._name, dict(self._meta), self._bc, self._smoothing))

    def __repr__(self) -> str:
        sm = f", smoothing={self._smoothing:g}" if self._smoothing is not None else ""
        return (f"Profile(kind={self._kind!r}, name={self._name!r}, {len(self._y)} points, "
                f"y {self._y[0] * 1e3:.4g} .. {self._y[-1] * 1e3:.4g} mm, bc={self._bc!r}{sm})")

    def __len__(self) -> int:
        return len(self._y)

    # -- attributes

    @property
    def y(self) -> F64Array:
        """Node abscissae [m], strictly increasing (read-only array)."""
        return self._y

    @property
    def z(self) -> F64Array:
        """Spline values at the nodes [m]: the points given, or their smoothed values."""
        return self._z

    @property
    def z_input(self) -> F64Array:
        """The z values given (equal to ``z`` unless smoothing is set)."""
        return self._z_input

    @property
    def kind(self) -> str:
        """The profile's kind: "wheel" or "rail" (a roller is a "rail")."""
        return self._kind

    @property
    def name(self) -> str:
        """The profile's label (a file's name without extension by default)."""
        return self._name

    @property
    def meta(self) -> Mapping[str, Any]:
        """Header values and reading notes (a read-only mapping)."""
        return self._meta

    @property
    def bc(self) -> str:
        """The spline's end conditions, "not-a-knot" or "natural"."""
        return self._bc

    @property
    def smoothing(self) -> Optional[float]:
        """The smoothing wavelength [m], or None (the spline interpolates the points)."""
        return self._smoothing

    @property
    def y_min(self) -> float:
        """The first node's y [m]: the profile's end on the flange / gauge side."""
        return float(self._y[0])

    @property
    def y_max(self) -> float:
        """The last node's y [m]: the profile's end on the field side."""
        return float(self._y[-1])

    # -- evaluation

    def _locate(self, func: str, y: npt.ArrayLike) -> Tuple[
            F64Array, npt.NDArray[np.intp], F64Array, npt.NDArray[np.bool_]]:
        arr = _as_float_array(f"Profile.{func}", "y", y)
        flat = arr.reshape(-1)
        i = np.clip(np.searchsorted(self._y, flat, side="right") - 1, 0, len(self._y) - 2)
        out = ~((flat >= self._y[0]) & (flat <= self._y[-1]))   # also NaN
        t = np.where(out, 0.0, flat - self._y[i])     # no overflow far outside
        return arr, i, t, out

    @staticmethod
    def _shape(arr: F64Array, values: F64Array) -> FloatResult:
        values = values.reshape(arr.shape)
        return float(values) if arr.ndim == 0 else values

    @overload
    def evaluate(self, y: float) -> Tuple[float, float, float]: ...
    @overload
    def evaluate(self, y: npt.ArrayLike) -> Tuple[FloatResult, FloatResult, FloatResult]: ...
    def evaluate(self, y: npt.ArrayLike) -> Tuple[FloatResult, FloatResult, FloatResult]:
        """The spline and its derivatives at y.

        Parameters
        ----------
        y : float or array_like
            Lateral positions [m].

        Returns
        -------
        z : float or ndarray
            z(y) [m].
        dz : float or ndarray
            dz/dy [-].
        d2z : float or ndarray
            d2z/dy2 [1/m].  All three NaN outside [y_min, y_max].
        """
        return self._evaluate("evaluate", y)

    def _evaluate(self, func: str,
                  y: npt.ArrayLike) -> Tuple[FloatResult, FloatResult, FloatResult]:
        arr, i, t, out = self._locate(func, y)
        s, c2, c3 = self._s[i], self._c2[i], self._c3[i]
        z = self._z[i] + t * (s + t * (c2 + t * c3))
        dz = s + t * (2.0 * c2 + 3.0 * c3 * t)
        d2z = 2.0 * c2 + 6.0 * c3 * t
        for v in (z, dz, d2z):
            v[out] = np.nan
        return self._shape(arr, z), self._shape(arr, dz), self._shape(arr, d2z)

    @overload
    def z_at(self, y: float) -> float: ...
    @overload
    def z_at(self, y: npt.ArrayLike) -> FloatResult: ...
    def z_at(self, y: npt.ArrayLike) -> FloatResult:
        """z(y) [m] at y [m] (float or array; NaN outside [y_min, y_max])."""
        arr, i, t, out = self._locate("z_at", y)
        z = self._z[i] + t * (self._s[i] + t * (self._c2[i] + t * self._c3[i]))
        z[out] = np.nan
        return self._shape(arr, z)

    @overload
    def slope(self, y: float) -> float: ...
    @overload
    def slope(self, y: npt.ArrayLike) -> FloatResult: ...
    def slope(self, y: npt.ArrayLike) -> FloatResult:
        """dz/dy [-] at y [m] (NaN outside [y_min, y_max]).

        z is down, y to the field side: a wheel coned as usual has slope
        -tan(cone angle) on its tread.
        """
        return self._evaluate("slope", y)[1]

    @overload
    def second_derivative(self, y: float) -> float: ...
    @overload
    def second_derivative(self, y: npt.ArrayLike) -> FloatResult: ...
    def second_derivative(self, y: npt.ArrayLike) -> FloatResult:
        """d2z/dy2 [1/m] at y [m] (NaN outside [y_min, y_max])."""
        return self._evaluate("second_derivative", y)[2]

    @overload
    def curvature(self, y: float) -> float: ...
    @overload
    def curvature(self, y: npt.ArrayLike) -> FloatResult: ...
    def curvature(self, y: npt.ArrayLike) -> FloatResult:
        """Signed curvature z'' / (1 + z'^2)^1.5 [1/m] at y [m].

        Positive where the curve bends downward (+z): convex for a rail or
        roller, concave for a wheel.  Hertz: B = (kappa_rail - kappa_wheel) /
        2.  NaN outside [y_min, y_max].
        """
        _, dz, d2z = self._evaluate("curvature", y)
        return d2z / (1.0 + np.square(dz)) ** 1.5

    # -- new profiles from this one

    def _derived(self, func: str, y: F64Array, z: F64Array, name: str, note: str) -> Profile:
        meta = dict(self._meta)
        meta["derived"] = tuple(meta.get("derived", ())) + (note,)
        with _named(func):
            return Profile(y, z, kind=self._kind, name=name, meta=meta, bc=self._bc,
                           smoothing=self._smoothing)

    def shifted(self, dy: float = 0.0, dz: float = 0.0) -> Profile:
        """The profile moved by dy laterally and dz downward [m] (a new Profile)."""
        dy = check_number("Profile.shifted", "dy", dy)
        dz = check_number("Profile.shifted", "dz", dz)
        return self._derived("Profile.shifted", self._y + dy, self._z_input + dz, self._name,
                             f"shifted by dy = {dy!r} m, dz = {dz!r} m")

    def gauge_point(self, depth: float = 0.014) -> float:
        """Lateral position [m] of a rail's (or roller's) gauge face at `depth` [m].

        `depth` (> 0) is measured below z = 0, the top of the head in rail
        profiles (the gauge is measured there: 14 mm, EN 13848-1); the point
        is on the gauge side of the top, found by bisection on the spline.
        RollerRigError if the profile does not reach that deep on the gauge
        side.

        Examples
        --------
        >>> import rollerrig as rr
        >>> print(f"{rr.Profile.uic60().gauge_point() * 1e3:.3f} mm")
        -43.033 mm
        """
        func = "Profile.gauge_point"
        depth = check_number(func, "depth", depth, positive=True)
        lo, hi = self.y_min, float(self._y[np.argmin(self._z)])
        if not self.z_at(lo) >= depth:
            raise RollerRigError(f"{func}: the profile does not reach {depth!r} m below z = 0 "
                                 "on the gauge side")
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if self.z_at(mid) > depth else (lo, mid)
        return 0.5 * (lo + hi)

    def canted(self, inclination: float) -> Profile:
        """The profile turned about its origin as a rail or roller head canted inward.

        `inclination` is a slope, e.g. 1/40, within [-0.1, 0.1]: the field
        side drops, y' = y cos c - z sin c, z' = y sin c + z cos c, c =
        atan(inclination).  Points where the turn folds the curve back (a
        steep face) are an error (RollerRigError).
        """
        func = "Profile.canted"
        inc = check_number(func, "inclination", inclination)
        if not abs(inc) <= 0.1:
            raise RollerRigError(f"{func}: inclination must be within [-0.1, 0.1], got {inc!r}")
        c = math.atan(inc)
        y = self._y * math.cos(c) - self._z_input * math.sin(c)
        z = self._y * math.sin(c) + self._z_input * math.cos(c)
        if not np.all(np.diff(y) > 0):
            raise RollerRigError(f"{func}: canting by {inc!r} folds the profile back "
                                 "(a face steeper than the cant)")
        return self._derived(func, y, z, self._name, f"canted by {inc!r}")

    def mirrored(self) -> Profile:
        """The mirror image y -> -y: the same profile for the other side of the track.

        The field side is positive again there.  Smoothing commutes with it.
        """
        return self._derived("Profile.mirrored", -self._y[::-1], self._z_input[::-1], self._name,
                             "mirrored y -> -y")

    def write_text(self, path: Union[str, os.PathLike[str]], units: str = "mm") -> None:
        """Write the nodes (y, z) as plain two-column text, readable by read_profile.

        '#' header lines 'key = value' carry name, kind, units and bc; 17
        significant digits.  `path` is a new path or a regular file,
        replaced whole (never a link, a device or a FIFO: RollerRigError);
        `units` is "mm" (default), "cm" or "m".
        """
        if units not in UNITS:
            raise RollerRigError(f"Profile.write_text: units must be one of {sorted(UNITS)}, "
                                 f"got {units!r}")
        f = UNITS[units]

        def write(out: IO[str]) -> None:
            out.write("# rollerrig profile: lateral y towards the field side, vertical z "
                      "downward\n")
            out.write(f"# name = {self._name}\n# kind = {self._kind}\n# units = {units}\n"
                      f"# bc = {self._bc}\n")
            for yy, zz in zip(self._y / f, self._z / f):
                out.write(f"{yy:.17g} {zz:.17g}\n")
        write_file(path, write, what="Profile.write_text: path")

    # -- other constructors

    @classmethod
    def from_points(cls, y: npt.ArrayLike, z: npt.ArrayLike, *, kind: str, name: str = "",
                    units: str = "m", on_fold: str = "trim", mirror_y: bool = False,
                    mirror_z: bool = False, bc: Optional[str] = None,
                    smoothing: Optional[float] = None,
                    meta: Optional[Mapping[str, Any]] = None) -> Profile:
        """A profile from points in any order.

        Converts units (`units`: "m", "cm", "mm"), mirrors on request
        (`mirror_y`, `mirror_z`), reverses descending points, removes folds
        (with a RollerRigWarning; on_fold="raise" to refuse them) and checks
        as read_profile does; the other arguments as for Profile.

        Examples
        --------
        >>> import rollerrig as rr
        >>> rr.Profile.from_points([30, 20, 10, 0], [9, 4, 1, 0], kind="rail", units="mm")
        Profile(kind='rail', name='', 4 points, y 0 .. 30 mm, bc='not-a-knot')
        """
        func = "Profile.from_points"
        _check_kind(func, kind)
        if units not in UNITS:
            raise RollerRigError(f"{func}: units must be one of {sorted(UNITS)}, "
                                 f"got {units!r}")
        y = _as_float_array(func, "y", y)
        z = _as_float_array(func, "z", z)
        if y.ndim != 1 or y.shape != z.shape:
            raise RollerRigError(f"{func}: y and z must be 1-D arrays of one length, got "
                                 f"shapes {y.shape} and {z.shape}")
        f = UNITS[units]
        y, z, notes = _prepare(func, y * f, z * f, kind, (np.arange(len(y)), "point"),
                               on_fold, mirror_y, mirror_z)
        with _named(func):
            return cls(y, z, kind=kind, name=name, meta={**(meta or {}), **notes}, bc=bc,
                       smoothing=smoothing)

    @classmethod
    def s1002(cls, smoothing: Optional[float] = None) -> "Profile":
        """The S1002 wheel of the Manchester contact benchmark.

        MBench_S1002_v3.prw, shipped in rollerrig/data/profiles: y = 0 at the
        taping line, flange at y < 0.  `smoothing` as for Profile.
        """
        return read_profile(os.path.join(DATA_DIR, "MBench_S1002_v3.prw"),
                            smoothing=smoothing)

    @classmethod
    def uic60(cls, smoothing: Optional[float] = None) -> "Profile":
        """The UIC60 rail of the Manchester contact benchmark.

        MBench_UIC60_v3.prr, already canted 1:40: top of head z = 0 near
        y = 0, gauge face at y < 0.  `smoothing` as for Profile.
        """
        return read_profile(os.path.join(DATA_DIR, "MBench_UIC60_v3.prr"),
                            smoothing=smoothing)

    @classmethod
    def conical(cls, alpha: float, y_range: Sequence[float] = (-0.02, 0.02),
                r0: Optional[float] = None, n: int = 41) -> Profile:
        """The paper's conical wheel: z = -tan(alpha) y on y_range [m].

        The rolling radius r0 + z decreases towards the field side for
        alpha > 0 (slope -tan(alpha)); alpha [rad] within (-pi/2, pi/2).  r0,
        the radius at y = 0 [m], is kept in meta for the contact geometry;
        n points (4 or more).

        Examples
        --------
        >>> import rollerrig as rr
        >>> w = rr.Profile.conical(0.025, r0=0.0625)
        >>> print(f"{w.slope(0.0):.6f}", w.meta["r0"])
        -0.025005 0.0625
        """
        func = "Profile.conical"
        alpha = check_number(func, "alpha", alpha)
        if not abs(alpha) < math.pi / 2:
            raise RollerRigError(f"{func}: alpha must be within (-pi/2, pi/2) rad, "
                                 f"got {alpha!r}")
        y0, y1, n = _range_points(func, y_range, n)
        r0 = check_number(func, "r0", r0, positive=True, allow_none=True)
        y, z = _analytic(func, 0, alpha, y0, y1, n)
        with _named(func):
            return cls(y, z, kind="wheel",
                       name=f"conical wheel, alpha = {alpha:.6g} rad",
                       meta={"alpha": alpha, "r0": r0})

    @classmethod
    def cylinder(cls, y_range: Sequence[float] = (-0.02, 0.02),
                 crown_radius: Optional[float] = None, n: int = 81) -> Profile:
        """A roller (kind "rail"): a cylinder, or crowned with radius `crown_radius` [m].

        Flat lateral profile z = 0 (a cylinder, crown_radius None), or a
        crown centred at y = 0: z = R - sqrt(R^2 - y^2), curvature +1/R;
        y_range [m] within the crown, n points.
        """
        func = "Profile.cylinder"
        y0, y1, n = _range_points(func, y_range, n)
        R = check_number(func, "crown_radius", crown_radius, positive=True, allow_none=True)
        if R is not None and max(abs(y0), abs(y1)) >= R:
            raise RollerRigError(f"{func}: y_range {y_range!r} reaches beyond the crown "
                                 f"radius {R!r} m")
        # z = y^2 / (R + sqrt(R - y) sqrt(R + y)): R - sqrt(R^2 - y^2) without its
        # cancellation, nor R^2 overflowing; R = 0 in C is the cylinder, z = 0
        y, z = _analytic(func, 1, 0.0 if R is None else R, y0, y1, n)
        name = "cylinder" if R is None else f"crowned roller, R = {R:.6g} m"
        with _named(func):
            return cls(y, z, kind="rail", name=name, meta={"crown_radius": R})


@contextlib.contextmanager
def _named(func: str) -> Iterator[None]:
    """Profile's own checks, reported under the constructor the caller used."""
    try:
        yield
    except RollerRigError as e:
        msg = str(e)
        raise RollerRigError(f"{func}: {msg[len('Profile: '):]}" if msg.startswith("Profile: ")
                             else msg) from None


def _rebuild(y: F64Array, z: F64Array, kind: str, name: str, meta: Dict[str, Any], bc: str,
             smoothing: Optional[float]) -> Profile:
    return Profile(y, z, kind=kind, name=name, meta=meta, bc=bc, smoothing=smoothing)


def _range_points(func: str, y_range: Sequence[float], n: int) -> Tuple[float, float, int]:
    """y_range and n checked: (y_min, y_max, n)."""
    try:
        y0, y1 = (float(v) for v in y_range)
    except (TypeError, ValueError):
        raise RollerRigError(f"{func}: y_range must be two numbers (y_min, y_max) [m], "
                             f"got {y_range!r}") from None
    if not (math.isfinite(y0) and math.isfinite(y1) and y1 > y0):
        raise RollerRigError(f"{func}: y_range must be finite with y_min < y_max, "
                             f"got {y_range!r}")
    if max(abs(y0), abs(y1)) > MAX_COORD:
        raise RollerRigError(f"{func}: y_range must lie within +-{MAX_COORD:g} m (metres, "
                             f"not millimetres), got {y_range!r}")
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) \
            or not MIN_POINTS <= n <= MAX_POINTS:
        raise RollerRigError(f"{func}: n must be an integer from {MIN_POINTS} to "
                             f"{MAX_POINTS}, got {n!r}")
    # (at most MAX_POINTS over MIN_WIDTH: the points are far over MIN_SPACING apart)
    if not y1 - y0 >= MIN_WIDTH:
        raise RollerRigError(f"{func}: y_range {y_range!r} spans less than "
                             f"{MIN_WIDTH * 1e3:g} mm: metres read as millimetres?")
    return y0, y1, int(n)


def _analytic(func: str, kind: int, param: float, y0: float, y1: float,
              n: int) -> Tuple[F64Array, F64Array]:
    """The points of an analytic profile from the C core (rr_profile_conical,
    kind 0, param alpha; rr_profile_crowned, kind 1, param the crown radius
    or 0), so that a C program has the same points: numpy.linspace(y0, y1,
    n) and z.  The arguments are checked already: an error is a bug."""
    status, y, z = _core.analytic_profile(kind, param, y0, y1, n)
    if status < 0:
        raise RollerRigError(f"{func}: {status_message(status)} (y_range ({y0!r}, {y1!r}), "
                             f"n = {n!r}, parameter {param!r})")
    return y, z


def read_profile(path: Union[str, os.PathLike[str]], kind: Optional[str] = None, *,
                 units: Optional[str] = None, on_fold: str = "trim", mirror_y: bool = False,
                 mirror_z: bool = False, smoothing: Optional[float] = None,
                 bc: Optional[str] = None, name: Optional[str] = None) -> Profile:
    """Read a wheel or rail/roller profile file into a Profile.

    Parameters
    ----------
    path : str or path-like
        A SIMPACK .prw (wheel) / .prr (rail), MiniProf .whl (wheel) / .ban
        (rail) or plain text .txt/.csv/.dat file: READERS by extension
        (package docstring; each reader's rules in _read_simpack,
        _read_miniprof, _read_text).
    kind : {"wheel", "rail"}, optional
        By default from the SIMPACK header type, else the extension, else a
        '# kind = ...' line of a text file (a text file without one needs
        kind).  Given, it must agree with a SIMPACK header.
    units : {"mm", "cm", "m"}, optional
        Plain text only: default "mm"; SIMPACK files declare theirs,
        MiniProf files are in mm.
    on_fold : {"trim", "raise"}, optional
        "trim" (default): drop the points where the profile folds back, with
        a RollerRigWarning; "raise": refuse them.
    mirror_y, mirror_z : bool, optional
        Mirror the points after reading (y -> -y: a profile of the other
        side; z -> -z: data with z upward).
    smoothing, bc : optional
        As for :class:`Profile` (smoothing a wavelength [m]).
    name : str, optional
        Default the file name without extension.

    Returns
    -------
    Profile
        Its meta holds the format, the path, the header values, the units
        and the reading notes.

    Raises
    ------
    RollerRigError
        Naming the file and line: no such file, an unknown extension, units
        for a format that fixes its own, numbers, NaN/inf, at least 4
        points, no duplicate y, a single-valued profile (on_fold),
        ``|y|``, ``|z|`` <= 2 m and width >= 1 mm after the unit conversion,
        MiniProf's XYPoints and ColumnDef, a kind unknown or disagreeing.

    Warns
    -----
    RollerRigWarning
        For a wheel whose flange (max z) lies at the field-side half: it is
        probably the other side's profile; for folds trimmed.

    See Also
    --------
    Profile.write_text : writes a file this reads.
    Profile.from_points : the same checks on points in memory.

    Examples
    --------
    >>> import os, tempfile
    >>> import rollerrig as rr
    >>> path = os.path.join(tempfile.mkdtemp(), "wheel.txt")
    >>> rr.Profile.conical(0.025).write_text(path)
    >>> p = rr.read_profile(path)
    >>> p.kind, p.meta["units"], len(p)
    ('wheel', 'mm', 41)
    """
    func = "read_profile"
    path = os.fspath(path)
    where = f"{func}: {path}"
    if kind is not None:
        _check_kind(func, kind)
    ext = os.path.splitext(path)[1].lower()
    if not os.path.exists(path):
        raise RollerRigError(f"{where}: no such file")
    fmt = READERS.get(ext)
    if fmt is None:
        raise RollerRigError(f"{where}: unknown extension {ext!r}; expected one of "
                             f"{list(READERS)}")
    if units is not None and not fmt.takes_units:
        raise RollerRigError(f"{where}: units is for plain text; {ext} files fix their "
                             f"own units")
    if units is not None and units not in UNITS:
        raise RollerRigError(f"{where}: units must be one of {sorted(UNITS)}, "
                             f"got {units!r}")
    y, z, lines, kind, meta, units_used, file_bc = fmt.read(path, where, kind, units)
    kind = kind or fmt.kind
    if kind is None:
        raise RollerRigError(f"{where}: kind unknown: pass kind='wheel' or 'rail' "
                             f"(or write '# kind = ...' in the file)")
    y, z, notes = _prepare(where, y, z, kind, (lines, "line"), on_fold, mirror_y, mirror_z)
    if kind == "wheel":
        i = int(np.argmax(z))
        if y[i] > 0.5 * (y[0] + y[-1]):
            warnings.warn(f"{where}: the flange (lowest point, y = {y[i] * 1e3:.4g} mm) lies "
                          f"on the field-side half: a profile of the other side? "
                          f"(mirror_y=True or .mirrored())", RollerRigWarning, stacklevel=2)
    meta = {"format": fmt.name, "path": path, **meta, **notes}
    if units_used is not None:
        meta["units"] = units_used
    if mirror_y or mirror_z:
        meta["mirrored"] = ("y" if mirror_y else "") + ("z" if mirror_z else "")
    if bc is None and smoothing is None:
        bc = file_bc
    if name is None:
        name = meta.get("name") if fmt.name == "text" and "name" in meta else \
            os.path.splitext(os.path.basename(path))[0]
    return Profile(y, z, kind=kind, name=str(name), meta=meta, bc=bc, smoothing=smoothing)
