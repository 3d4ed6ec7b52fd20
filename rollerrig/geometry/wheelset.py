"""Contact geometry of the rig's wheelset on its two rollers.

A wheel profile and a roller profile (rollerrig.geometry.profiles.Profile, y to the
field side, z down) per side, the wheel's radius r0 and the roller's R0 at
the profiles' origins (y = 0), and where those origins sit laterally: the
C core (csrc/geometry/rr_geometry.h) finds on each side the point of least vertical
gap between the surfaces, and the wheelset's height and roll that make both
gaps zero, for any lateral shift of the wheelset::

    g = rr.RigGeometry(wheel=rr.Profile.s1002(), roller=rr.Profile.uic60(),
                       wheel_radius=0.46, roller_radius=0.46,
                       wheel_y=0.75, roller_y=0.76053)
    c = rr.wheelset_contact(g, np.linspace(-0.005, 0.005, 11))
    c.left.r - c.right.r          # rolling-radius difference [m]

The search is in the plane of the axle; rollerrig.rig.contact adds the
wheelset's longitudinal shift and yaw, which move the contact points round
the rollers (csrc/rig/rr_rig_contact.h).
"""
from __future__ import annotations

import os
import warnings
from dataclasses import dataclass
from typing import Any, List, NamedTuple, Optional, Tuple

import numpy as np
import numpy.typing as npt

from .. import _core
from .._errors import RollerRigError, RollerRigWarning, check_status, status_message
from .._binding import _as_float
from .._typing import F64Array
from .profiles import DATA_DIR, Profile, read_profile

__all__ = ["RigGeometry", "ContactSide", "WheelsetContact", "wheelset_contact",
           "ContactTable", "contact_table"]


@dataclass(frozen=True)
class RigGeometry:
    """Profiles and placement of the wheel-roller pairs.

    The right side uses the left side's profiles mirrored unless
    wheel_right, roller_right are given.  The values are checked where the
    geometry is used (RollerRigError naming the field).

    Attributes
    ----------
    wheel : Profile
        The left wheel's profile (y to the field side, z down).
    roller : Profile
        The left roller's profile (kind "rail").
    wheel_radius : float
        The wheel's radius where its profile has z = 0 at y = 0 [m].
    roller_radius : float
        The roller's radius where its profile has z = 0 at y = 0 [m].
    wheel_y : float
        Lateral distance of the wheel profile's origin from the wheelset's
        centre [m].
    roller_y : float
        Lateral distance of the roller profile's origin from the rig's
        centre line [m].
    wheel_right, roller_right : Profile or None
        The right side's own profiles (None: the left's mirrored).

    See Also
    --------
    wheelset_contact : the contact search on it.
    contact_table : its contact table.

    Examples
    --------
    >>> import rollerrig as rr
    >>> g = rr.RigGeometry.standard()        # S1002 on UIC60, as on track
    >>> g.wheel_y, round(g.roller_y, 5)
    (0.75, 0.76053)
    """

    # the fields are documented in the class docstring (Attributes): a #:
    # comment would document them twice, and numpydoc checks a default's
    # docstring (None has none)
    wheel: Profile
    roller: Profile
    wheel_radius: float
    roller_radius: float
    wheel_y: float
    roller_y: float
    wheel_right: Optional[Profile] = None
    roller_right: Optional[Profile] = None

    @classmethod
    def standard(cls, wheel: Optional[Profile] = None, roller: Optional[Profile] = None, *,
                 wheel_radius: float = 0.46, roller_radius: float = 0.46, gauge: float = 1.435,
                 back_to_back: float = 1.360, flange_back: float = -0.070,
                 gauge_depth: float = 0.014, inclination: float = 0.0) -> "RigGeometry":
        """A wheelset on rollers placed as on track by gauge and back-to-back distance.

        Parameters
        ----------
        wheel, roller : Profile, optional
            Profiles (default S1002 and the UIC60 head, which is already
            canted 1:40).
        wheel_radius, roller_radius : float, optional
            Radii at the profiles' origins [m].
        gauge, back_to_back : float, optional
            Track gauge and the wheels' back-to-back distance [m], > 0.
        flange_back : float, optional
            The wheel profile's y of the flange back [m] (S1002: the taping
            line, its origin, lies 70 mm from it).
        gauge_depth : float, optional
            The gauge is measured this far below the roller's top [m], > 0
            (EN 13848-1: 14 mm).
        inclination : float, optional
            A cant applied to the roller profile (Profile.canted) before
            placing it [-].

        Returns
        -------
        RigGeometry
            The Manchester benchmark's placement is RigGeometry.standard().

        Raises
        ------
        RollerRigError
            For a value not finite or not > 0, naming it, and as
            Profile.gauge_point and Profile.canted.
        """
        func = "RigGeometry.standard"
        wheel = Profile.s1002() if wheel is None else wheel
        roller = Profile.uic60() if roller is None else roller
        vals = dict(gauge=gauge, back_to_back=back_to_back, flange_back=flange_back,
                    gauge_depth=gauge_depth, inclination=inclination)
        for name, v in vals.items():
            if not (isinstance(v, (int, float, np.floating)) and np.isfinite(v)):
                raise RollerRigError(f"{func}: {name} must be a finite number, got {v!r}")
        if not (gauge > 0 and back_to_back > 0 and gauge_depth > 0):
            raise RollerRigError(f"{func}: gauge, back_to_back, gauge_depth must be > 0, got "
                                 f"{gauge!r}, {back_to_back!r}, {gauge_depth!r}")
        if inclination:
            roller = roller.canted(inclination)
        y_gauge = roller.gauge_point(gauge_depth)
        return cls(wheel=wheel, roller=roller, wheel_radius=wheel_radius,
                   roller_radius=roller_radius, wheel_y=back_to_back / 2 - flange_back,
                   roller_y=gauge / 2 - y_gauge)

    @classmethod
    def measured_pair(cls, *, roller_radius: float = 0.80010, back_to_back: float = 1.347,
                      smoothing: Optional[float] = 2e-3) -> "RigGeometry":
        """The measured wheels on the measured rollers shipped in rollerrig/data/profiles.

        MiniProf .whl/.ban of a full-scale single-wheelset roller rig, left
        and right each their own.

        Gauge: the mean of the two .ban headers (1436.91 and 1437.52 mm, at
        RailGaugePoint = 14 mm below the top); each roller's gauge face at half
        of it from the centre line (the right roller's profile moved by the
        0.27 mm its gauge point differs).  Flange backs `back_to_back` apart
        (1347 mm, CONTACT's roller-rig case dry_10mph_13750lbs: an assumption
        for these profiles).  Wheel radii from the .whl headers'
        DiameterTaperline (719.19 mm left, 720.11 mm right, at 70 mm from the
        flange back), so r0 = 0.35930 m and the right wheel 0.46 mm larger.
        Roller: `roller_radius` at the top of the left roller's crown (0.80010
        m, the nominal radius of the same CONTACT case).  Profiles smoothed
        over `smoothing` [m]: read raw, their curvature jitter makes the
        contact search reject shifts near -2.5 mm (B <= 0, no Hertz ellipse).
        """
        mm = 1e-3
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RollerRigWarning)   # the rollers' gauge-face folds
            wl, wr, rl, rrr = (read_profile(os.path.join(DATA_DIR, f), smoothing=smoothing)
                               for f in ("left-wheel-v1-pre-dry.whl",
                                         "right-wheel-v1-pre-dry.whl",
                                         "left-roller-v1-pre-dry.ban",
                                         "right-roller-v1-pre-dry.ban"))
        gauge = 0.5 * (rl.meta["Gauge"] + rrr.meta["Gauge"]) * mm
        gl, gr = (r.gauge_point(r.meta["RailGaugePoint"] * mm) for r in (rl, rrr))
        tape = wl.meta["WheelDiameterTaperline"] * mm
        r0 = 0.5 * wl.meta["DiameterTaperline"] * mm - wl.z_at(tape)
        dz_right = 0.5 * wr.meta["DiameterTaperline"] * mm - r0 - wr.z_at(tape)
        return cls(wheel=wl, roller=rl, wheel_right=wr.shifted(0.0, dz_right),
                   roller_right=rrr.shifted(gl - gr, 0.0), wheel_radius=r0,
                   roller_radius=roller_radius + rl.z.min(), wheel_y=back_to_back / 2,
                   roller_y=gauge / 2 - gl)

    def _arrays(self) -> List[F64Array]:
        """The four profiles as the core takes them: each the Profile's own
        spline (knots, values, the second derivatives at the knots that
        rr_spline_fit gave), heights up, so -z (rr_profile_surface does the
        same in C, csrc/geometry/rr_tables.h)."""
        def spline(p: object, kind: str) -> Tuple[F64Array, F64Array, F64Array]:
            if not isinstance(p, Profile):
                raise RollerRigError(f"RigGeometry: {kind} must be a Profile, got {p!r:.60}")
            return (np.ascontiguousarray(p.y), np.ascontiguousarray(-p.z),
                    np.ascontiguousarray(-p._d2))
        out: List[F64Array] = []
        for w, r in ((self.wheel, self.roller),
                     (self.wheel_right or self.wheel, self.roller_right or self.roller)):
            out += [*spline(w, "wheel"), *spline(r, "roller")]
        return out

    def _params(self) -> Tuple[float, ...]:
        vals = dict(wheel_radius=self.wheel_radius, roller_radius=self.roller_radius,
                    wheel_y=self.wheel_y, roller_y=self.roller_y)
        for name, v in vals.items():
            if not (isinstance(v, (int, float, np.floating)) and np.isfinite(v)) \
                    or (name.endswith("radius") and v <= 0):
                raise RollerRigError(f"RigGeometry: {name} must be a finite "
                                     f"{'positive ' if name.endswith('radius') else ''}"
                                     f"number, got {v!r}")
        side = (float(self.wheel_radius), float(self.roller_radius), float(self.wheel_y),
                float(self.roller_y))
        return side + side


class ContactSide(NamedTuple):
    """One side's contact point and its Hertz geometry, per shift (arrays)."""

    y: np.ndarray          #: lateral position of the contact point in the rig [m]
    z: np.ndarray          #: its height above the nominal roller top [m]
    s_wheel: np.ndarray    #: lateral profile coordinate on the wheel [m]
    s_roller: np.ndarray   #: lateral profile coordinate on the roller [m]
    r: np.ndarray          #: wheel rolling radius [m]
    R: np.ndarray          #: roller radius at the contact [m]
    delta: np.ndarray      #: contact angle [rad], > 0 toward the flange
    A: np.ndarray          #: Hertz curvature sum [1/m], rolling direction
    B: np.ndarray          #: Hertz curvature sum [1/m], lateral
    gap: np.ndarray        #: remaining gap [m] (0 after the pose solve)
    two_point: np.ndarray  #: True where a second contact point was found


class WheelsetContact(NamedTuple):
    """The wheelset's pose and both contacts, per lateral shift (1-D arrays).

    As :func:`wheelset_contact` and :meth:`ContactTable.lookup` return it.
    """

    y_ws: np.ndarray       #: lateral shift of the wheelset [m]
    z: np.ndarray          #: axle height [m]
    roll: np.ndarray       #: roll angle [rad], positive lifting the left wheel
    left: ContactSide      #: the left wheel's contact
    right: ContactSide     #: the right wheel's contact
    status: np.ndarray     #: C status per shift (0 OK, < 0: a wheel off its roller, NaN)


def _side(block: F64Array) -> ContactSide:
    fields = [block[k] for k in range(11)]
    fields[10] = fields[10] != 0
    return ContactSide(*fields)


def _shifts(func: str, y_ws: npt.ArrayLike) -> F64Array:
    """Lateral shifts as a 1-D float64 array, with a message naming y_ws."""
    y = _as_float(func, "y_ws", y_ws)
    if y.ndim > 1:
        raise RollerRigError(f"{func}: y_ws must be a number or a 1-D array, got shape "
                             f"{y.shape}")
    return np.ascontiguousarray(np.atleast_1d(y))


def _search(func: str, nsamples: int = 400, two_point_tol: float = 1e-4,
            two_point_sep: float = 2e-3) -> Tuple[int, float, float]:
    """The search options, checked: (nsamples, two_point_tol, two_point_sep)."""
    if isinstance(nsamples, bool) or not isinstance(nsamples, (int, np.integer)) \
            or not 3 <= nsamples <= _core.SEARCH_MAX_SAMPLES:
        raise RollerRigError(f"{func}: nsamples must be an integer from 3 to "
                             f"{_core.SEARCH_MAX_SAMPLES}, got {nsamples!r}")
    for name, v in (("two_point_tol", two_point_tol), ("two_point_sep", two_point_sep)):
        if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)) \
                or not (np.isfinite(v) and v >= 0):
            raise RollerRigError(f"{func}: {name} must be a finite number >= 0 [m], "
                                 f"got {v!r}")
    return int(nsamples), float(two_point_tol), float(two_point_sep)


def wheelset_contact(geometry: RigGeometry, y_ws: npt.ArrayLike, *, nsamples: int = 400,
                     two_point_tol: float = 1e-4, two_point_sep: float = 2e-3,
                     errors: Optional[str] = None) -> WheelsetContact:
    """Direct contact search at the lateral shifts y_ws.

    Parameters
    ----------
    geometry : RigGeometry
        The profiles and their placement.
    y_ws : float or array_like
        Lateral shifts of the wheelset [m], a number or a 1-D array
        (positive: the wheelset to the left).
    nsamples : int, optional
        Wheel samples of the coarse search (3 to SEARCH_MAX_SAMPLES,
        100 000; the cost grows with it).  Each sampled minimum of the gap
        is refined between its neighbours, so samples farther apart than
        two regions of the profiles that can touch (about two_point_sep)
        may settle in the wrong one: the default is 0.33 mm apart on S1002,
        65 samples the coarsest at 2 mm.
    two_point_tol : float, optional
        A second gap minimum this close to the first [m] counts as a second
        contact point, if more than two_point_sep away.
    two_point_sep : float, optional
        [m], >= 0.
    errors : {None, "raise", "warn", "ignore"}, optional
        "raise" (default for a scalar y_ws), "warn" (default for arrays: one
        RollerRigWarning for the bad elements) or "ignore".

    Returns
    -------
    WheelsetContact
        The pose (z [m], roll [rad]) and each side's contact point, radii,
        contact angle and curvature sums (lengths in m, angles in rad;
        :class:`WheelsetContact`, :class:`ContactSide`), as 1-D arrays (one
        element for a scalar y_ws).

    Raises
    ------
    RollerRigError
        For y_ws not a number or 1-D array of real numbers, bad search
        options, a geometry field not finite (radii > 0), and with
        errors="raise" a shift where a wheel leaves its roller (status -3).

    See Also
    --------
    contact_table : the search tabulated, looked up in O(1).
    rolling_radius_difference : Delta r from it.

    Notes
    -----
    Shifts where a wheel leaves its roller get NaN and a negative status.

    Examples
    --------
    >>> import rollerrig as rr
    >>> g = rr.RigGeometry.standard()
    >>> c = rr.wheelset_contact(g, [0.0, 0.003])
    >>> (c.left.r - c.right.r).round(6), c.status
    (array([0.      , 0.000994]), array([0, 0], dtype=int8))
    >>> c.left.delta.round(4)
    array([0.0243, 0.0922])
    """
    func = "wheelset_contact"
    y = _shifts(func, y_ws)
    opts = _search(func, nsamples, two_point_tol, two_point_sep)
    status, z, roll, left, right = _core.wheelset_contact(
        *geometry._arrays(), geometry._params(), y, *opts)
    if errors is None:
        errors = "raise" if np.ndim(y_ws) == 0 else "warn"
    # a scalar y_ws's message names no index (its results stay arrays of one)
    shape = np.shape(y_ws) if np.ndim(y_ws) == 0 else status.shape
    check_status(func, status.reshape(shape), {"y_ws": y.reshape(shape)}, errors)
    return WheelsetContact(y, z, roll, _side(left), _side(right), status)


@dataclass(frozen=True, eq=False)
class ContactTable:
    """The C core's contact table (csrc/geometry/rr_geometry.h).

    wheelset_contact at n equally spaced shifts y0 + i dy, interpolated
    linearly in O(1).  Build it with :func:`contact_table`; rig_contact()
    and the rig model read it.
    """

    geometry: RigGeometry   #: the geometry it was built for
    y0: float               #: the first row's shift [m]
    dy: float               #: the rows' spacing [m]
    n: int                  #: the number of rows
    data: np.ndarray        #: the rows, as the core stores them (read-only)

    @property
    def y_ws(self) -> F64Array:
        """The shifts of the rows [m]."""
        return self.y0 + self.dy * np.arange(self.n, dtype=np.float64)

    @property
    def y_range(self) -> Tuple[float, float]:
        """The first and last rows' shifts (y_min, y_max) [m]."""
        return self.y0, self.y0 + self.dy * (self.n - 1)

    def lookup(self, y_ws: npt.ArrayLike, *, errors: Optional[str] = None) -> WheelsetContact:
        """The geometry at y_ws [m], interpolated between rows.

        Parameters
        ----------
        y_ws : float or array_like
            Lateral shifts [m], a number or a 1-D array.
        errors : {None, "raise", "warn", "ignore"}, optional
            As for wheelset_contact.

        Returns
        -------
        WheelsetContact
            As wheelset_contact's (the two-point flag: the nearer row's;
            gap: 0).  Outside the table: NaN with status RR_ERR_GEOMETRY
            (-3, the wheel off its roller).
        """
        func = "ContactTable.lookup"
        y = _shifts(func, y_ws)
        status, z, roll, _, _, left, right = _core.table_lookup(self.data, self.y0, self.dy, y)
        if errors is None:
            errors = "raise" if np.ndim(y_ws) == 0 else "warn"
        check_status(func, status, {"y_ws": y}, errors)
        return WheelsetContact(y, z, roll, _side(left), _side(right), status)

    def slopes(self, y_ws: npt.ArrayLike) -> Tuple[F64Array, F64Array]:
        """The interpolant's slopes d z / d y_ws [-] and d roll / d y_ws [rad/m] at y_ws [m].

        The constraint's rates per unit lateral velocity; two 1-D arrays.
        """
        y = _shifts("ContactTable.slopes", y_ws)
        _, _, _, dz, droll, _, _ = _core.table_lookup(self.data, self.y0, self.dy, y)
        return dz, droll


#: most rows of a contact table (1e6 rows take about 6 minutes to build)
MAX_ROWS = 1_000_000


def contact_table(geometry: RigGeometry, y_min: float, y_max: float, n: int = 401,
                  **search: Any) -> ContactTable:
    """Contact table over [y_min, y_max] [m] with n rows.

    A direct search per row (:func:`wheelset_contact`), in C with the GIL
    released, Ctrl-C noticed between chunks of rows.

    Parameters
    ----------
    geometry : RigGeometry
        The profiles and their placement.
    y_min, y_max : float
        The table's shifts [m], y_min < y_max.
    n : int, optional
        Rows, 2 to MAX_ROWS (1 000 000: about 6 minutes to build).
    **search
        nsamples, two_point_tol, two_point_sep as for wheelset_contact.

    Returns
    -------
    ContactTable
        The table (:class:`ContactTable`).

    Raises
    ------
    RollerRigError
        For bad bounds, n or search options, and naming the first shift
        where a wheel leaves its roller.

    See Also
    --------
    ContactTable.lookup : the geometry at any shift of the table.
    rig_contact : the rig's contact from the table.

    Examples
    --------
    >>> import rollerrig as rr
    >>> table = rr.contact_table(rr.RigGeometry.standard(), -0.005, 0.005, n=21)
    >>> table.y_range
    (-0.005, 0.005)
    >>> c = table.lookup(0.003)
    >>> (c.left.r - c.right.r).round(6)
    array([0.000994])
    """
    func = "contact_table"
    for name, v in (("y_min", y_min), ("y_max", y_max)):
        if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)) \
                or not np.isfinite(v):
            raise RollerRigError(f"{func}: {name} must be a finite number [m], got {v!r}")
    if not y_max > y_min:
        raise RollerRigError(f"{func}: need y_min < y_max, got {y_min!r}, {y_max!r}")
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 2 <= n <= MAX_ROWS:
        raise RollerRigError(f"{func}: n must be an integer from 2 to {MAX_ROWS}, got {n!r}")
    unknown = set(search) - {"nsamples", "two_point_tol", "two_point_sep"}
    if unknown:
        raise RollerRigError(f"{func}: unknown option(s) {sorted(unknown)}")
    opts = _search(func, **search)
    dy = (float(y_max) - float(y_min)) / (n - 1)
    if not (np.isfinite(dy) and dy > 0.0):
        raise RollerRigError(f"{func}: the rows' spacing (y_max - y_min)/(n - 1) = {dy!r} "
                             f"is not a finite positive number")
    data, status, bad_y = _core.contact_table(
        *geometry._arrays(), geometry._params(), float(y_min), dy, int(n), *opts)
    if status < 0:
        raise RollerRigError(f"{func}: at y_ws = {bad_y!r}: {status_message(status)}")
    data.setflags(write=False)
    return ContactTable(geometry, float(y_min), dy, int(n), data)
