"""The undeformed distance of one wheel on its roller, for the exact theory.

Kalker's exact theory (rollerrig.contact.exact) takes any undeformed
distance h(x, y) on a grid; this module builds it from the rig's profiles,
so that a patch that is not an ellipse (near the flange root, two regions
close together, a measured profile's uneven curvature) comes out as what it
is (rollerrig.rig.exact solves one wheel of the rig on it, rig_exact)::

    g = rr.RigGeometry.measured_pair()
    p = rr.undeformed_distance(g, 0.0035, N=6e4)            # the left wheel
    s = rr.exact_solve(p.h, dx=p.dx, dy=p.dy, x0=p.x0, y0=p.y0, N=6e4, mu=0.5,
                       cx=0.002, cphi=-0.16)
    rr.patch_shape(s.contact, p.dx, p.dy)                   # its length, width, regions

Planar contact, as CONTACT's (its D = 2, not its "conformal" extension): one
tangent plane through a reference point P on the roller's surface with
contact angle delta; x along t1 (the rolling direction, +X of the rig), y
along t2 = n x t1 (lateral in the plane, toward +Y) and n = (0, -sigma sin
delta, cos delta) into the wheel (sigma = +1 left, -1 right): the frame of
rollerrig.rig.contact at zero yaw and longitudinal shift, so fx, fy, mz of
a solution are rollerrig's (on the wheel; mz about n at P).  Both bodies
are bodies of revolution: the roller about the rig's roller axis, the wheel
about its axle (after the wheelset's roll); at longitudinal position x the
cross-section of each is its profile with every point moved toward the
body's axis by R - sqrt(R^2 - x^2) (R that point's radius: the exact
circle, not the parabola).  h(x, y) is the distance along n from the
roller's cross-section to the wheel's at lateral position y of the plane,
shifted so that its least value is 0 (the approach is the solver's
unknown).  At x = 0 that is the sum of the two profile heights above the
common tangent plane; in x it adds about x^2/2 cos(delta) (1/r(y) + 1/R(y)),
the curvature sum A of Hertz's theory.  The profiles are their own splines
(rollerrig.Profile), sampled 0.02 mm apart and interpolated linearly in the
plane (1e-8 m where a profile's radius is 5 mm): no parabola in y.

The grid: uniform, square elements (unless dx, dy are given), centres at
whole multiples of (dx, dy) from P (CONTACT's alignment), about n across the
longer side of the region where h <= cover * approach, and one exterior
element beyond it on every side.  Lateral intervals of that region farther
than `combine` from the deepest one (CONTACT's D_COMB, 4 mm) are a separate
patch with a plane of its own: left out, listed in Patch.excluded, with a
warning.

The pose: CONTACT builds h with the wheelset where the load puts it,
lowered vertically by about the approach over cos(delta); the wheel has
then also slid by approach tan(delta) along the plane, which changes h
where a profile's curvature varies (measured on CONTACT's cases: at the
S1002 flange root, 0.3 % of the approach and 1 % of mu N in the forces).
undeformed_distance builds h at the pose given (z, roll; default the
zero-gap pose of wheelset_contact); rig_exact (rollerrig.rig.exact) gives it
the loaded one.

What the planar approach leaves out, here as in CONTACT with D = 2: the
profiles' change of direction across the patch (at the flange root the
normal turns by some degrees within it, and the half-space assumption
degrades).  Zero yaw and longitudinal shift only (a yawed wheel crosses its
roller at an angle: h and the frame change).

The construction is the C core's (csrc/geometry/rr_gap.h, rr_gap_build),
which a C program calls as well; this module checks the arguments, finds
the zero-gap pose and Hertz's approach, and words the core's reasons for
a patch it cannot build.  tests/_nonhertz_python.py keeps the Python
construction it replaced, and tests/test_gap.py holds the two together.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import Any, List, Mapping, NamedTuple, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

from .. import _core
from .._errors import RollerRigError, RollerRigWarning, check_number, status_message
from .._typing import F64Array
from .wheelset import ContactSide, RigGeometry, wheelset_contact

__all__ = ["Patch", "undeformed_distance", "patch_shape", "PatchShape"]

#: spacing of the profile samples h is interpolated from [m], at most
_SAMPLE = 2e-5
#: and at least (elements under a micrometre given: 8e5 samples over the
#: window, where a tenth of the element would ask for any number)
_SAMPLE_MIN = 1e-7
#: lateral half-width of the profiles' window around the reference point [m]
_WINDOW = 0.04

#: the tangent plane's reference: "point", "weighted" or (s_roller [m], delta [rad])
Reference = Union[str, Tuple[float, float], List[float]]


@dataclass(frozen=True, eq=False)
class Patch:
    """The undeformed distance of one wheel-roller contact on a grid, and its frame.

    As :func:`undeformed_distance` returns it.  h has shape (my, mx): rows
    along y, columns along x, element (i, j) centred at (x0 + j dx, y0 + i
    dy) from the reference point, as :func:`rollerrig.exact_solve` takes it.
    """

    h: np.ndarray        #: undeformed distance [m], least value 0
    dx: float            #: element size along x (t1) [m]
    dy: float            #: element size along y (t2) [m]
    x0: float            #: x of the centre of element (0, 0) from the reference point [m]
    y0: float            #: y of the centre of element (0, 0) from the reference point [m]
    point: np.ndarray    #: reference point P in the rig frame (on the roller) [m], (3,)
    #: P moved into the roller by the pose's interpenetration (the least h
    #: before the shift), where the wheel's velocity is taken (CONTACT's point
    #: Q) [m], (3,)
    wheel_point: np.ndarray
    t1: np.ndarray       #: rolling direction (+X), rig frame, (3,)
    t2: np.ndarray       #: lateral direction in the plane, toward +Y, rig frame, (3,)
    n: np.ndarray        #: normal into the wheel, rig frame, (3,)
    delta: float         #: contact angle of the plane [rad], > 0 toward the flange
    s_roller: float      #: roller profile coordinate of P [m]
    s_wheel: float       #: wheel profile coordinate where P's normal meets the wheel [m]
    r: float             #: wheel rolling radius there [m]
    R: float             #: roller radius at P [m]
    side: str            #: "left" or "right"
    y_ws: float          #: the wheelset's lateral shift [m]
    z: float             #: axle height [m] of the pose h was built at
    lowered: float       #: how far that lies below the zero-gap height [m]
    roll: float          #: roll angle [rad]
    approach: float      #: the approach the grid was sized for [m]
    cover: float         #: the grid covers where h <= cover * approach
    #: lateral intervals (y_lo, y_hi) [m] where h <= cover * approach, in the
    #: plane's y: those on the grid
    regions: Tuple[Tuple[float, float], ...]
    #: intervals left out: farther than `combine` (a separate patch)
    excluded: Tuple[Tuple[float, float], ...]

    @property
    def shape(self) -> Tuple[int, ...]:
        """The grid's shape (my, mx), h's."""
        return self.h.shape

    @property
    def x(self) -> F64Array:
        """Element centres along x [m], (my, mx)."""
        my, mx = self.h.shape
        return np.broadcast_to(self.x0 + self.dx * np.arange(mx), (my, mx))

    @property
    def y(self) -> F64Array:
        """Element centres along y [m], (my, mx)."""
        my, mx = self.h.shape
        return np.broadcast_to((self.y0 + self.dy * np.arange(my))[:, None], (my, mx))


def _runs(mask: npt.ArrayLike) -> List[Tuple[np.intp, np.intp]]:
    """(start, stop) index pairs of the runs of True in a 1-D mask."""
    m = np.concatenate(([False], mask, [False])).astype(np.int8)
    d = np.diff(m)
    return list(zip(np.flatnonzero(d == 1), np.flatnonzero(d == -1)))


def _pose_and_point(func: str, geometry: RigGeometry, y_ws: float,
                    side: str) -> Tuple[float, float, ContactSide]:
    if not isinstance(geometry, RigGeometry):
        raise RollerRigError(f"{func}: geometry must be a RigGeometry, got {geometry!r:.60}")
    if side not in ("left", "right"):
        raise RollerRigError(f"{func}: side must be 'left' or 'right', got {side!r}")
    y_ws = check_number(func, "y_ws", y_ws)
    c = wheelset_contact(geometry, y_ws, errors="ignore")
    if c.status[0] < 0:
        raise RollerRigError(f"{func}: y_ws = {y_ws!r} m: no rigid contact of the wheelset "
                             f"there: {status_message(int(c.status[0]))}")
    if c.status[0] > 0:
        warnings.warn(f"{func}: y_ws = {y_ws!r} m: the wheelset's rigid contact: "
                      f"{status_message(int(c.status[0]))}", RollerRigWarning, stacklevel=3)
    return float(c.z[0]), float(c.roll[0]), getattr(c, side)


def _reference(func: str, reference: Reference) -> Tuple[int, float, float]:
    """(code, s_roller, delta) of the core (rr_gap.h) for a reference."""
    if isinstance(reference, str) and reference in ("point", "weighted"):
        return (_core.GAP_POINT if reference == "point" else _core.GAP_WEIGHTED), 0.0, 0.0
    if isinstance(reference, (tuple, list)) and len(reference) == 2:
        sr = check_number(func, "reference s_roller", reference[0])
        delta = check_number(func, "reference delta", reference[1])
        if not abs(delta) < 0.5 * np.pi:
            raise RollerRigError(f"{func}: the reference angle must be within +-pi/2, got "
                                 f"{delta!r}")
        return _core.GAP_GIVEN, sr, delta
    raise RollerRigError(f"{func}: reference must be 'point', 'weighted' or "
                         f"(s_roller, delta), got {reference!r:.60}")


def _combine(func: str, combine: float) -> float:
    combine = check_number(func, "combine", combine)
    if combine < 0:
        # a negative one kept not even the deepest interval (issue 24: min()
        # of an empty sequence)
        raise RollerRigError(f"{func}: combine must be >= 0 [m], got {combine!r}")
    return combine


def _gap_error(func: str, status: int, info: Mapping[str, Any], geometry: RigGeometry,
               side: str, y_ws: float, load: str, z: float, roll: float) -> RollerRigError:
    """The RollerRigError of a failed rr_gap_build: its reason (info["why"])
    in words, with the numbers the core left for it."""
    why = info["why"]
    level = info["level"]

    def too_large(where: str) -> str:
        return (f"{func}: at y_ws = {y_ws!r} m and {load} the region to cover (h <= cover x "
                f"approach = {level:.3g} m) {where}: a load or approach beyond one planar "
                f"patch on these profiles")
    if why == _core.GAP_OFF_PROFILE:
        left = side == "left"
        prof = (geometry.roller if left else (geometry.roller_right or geometry.roller)) \
            if info["off_body"] == 0 else \
            (geometry.wheel if left else (geometry.wheel_right or geometry.wheel))
        msg = (f"{func}: the reference point lies off the {prof.kind} profile "
               f"({info['off_s']!r} m, profile from {info['off_lo']:g} to {info['off_hi']:g} m)")
    elif why == _core.GAP_FOLD:
        msg = f"{func}: a profile folds at the reference point"
    elif why == _core.GAP_APART:
        msg = (f"{func}: at y_ws = {y_ws!r} m, axle height z = {z!r} m and roll {roll!r} rad "
               f"the wheel's and the roller's cross-sections do not overlap laterally: no patch")
    elif why == _core.GAP_REGION_ENDS:
        msg = too_large(f"reaches the end of the profiles in the tangent plane (y from "
                        f"{info['plane_lo']:g} to {info['plane_hi']:g} m from the reference "
                        f"point)")
    elif why == _core.GAP_REGION_LONG:
        msg = too_large(f"is {2 * info['x_t']:.3g} m long, as long as the radii "
                        f"({info['r']:.3g}, {info['R']:.3g} m)")
    elif why == _core.GAP_REGION_BEYOND:
        msg = too_large(f"ends, {info['x_t']:.3g} m ahead and behind, beyond the profiles in "
                        f"the tangent plane")
    elif why == _core.GAP_TOO_MANY:
        msg = (f"{func}: dx = {info['dx']!r} m, dy = {info['dy']!r} m: this patch "
               f"({2.0 * info['half_length']:.3g} m by {info['hi'] - info['lo']:.3g} m) would "
               f"need {_count(info['need_my'])} x {_count(info['need_mx'])} elements, at most "
               f"{_core.EXACT_MAX_GRID} a side (give larger elements)")
    elif why == _core.GAP_PATCH_REACHES:
        msg = (f"{func}: at y_ws = {y_ws!r} m and {load} the patch reaches where a profile "
               f"folds or ends in the tangent plane (y from {info['plane_lo']:g} to "
               f"{info['plane_hi']:g} m from the reference point)")
    elif why == _core.GAP_PATCH_NONFINITE:
        msg = (f"{func}: at y_ws = {y_ws!r} m and {load} the patch reaches where a profile "
               f"folds or ends in the tangent plane")
    elif why == _core.GAP_RUNS:
        msg = too_large(f"has more than {_core.GAP_MAX_RUNS} separate intervals")
    elif why == _core.GAP_WEIGHTS:
        msg = (f"{func}: at y_ws = {y_ws!r} m and {load} the weighted reference's weights "
               f"vanish or overflow (the interpenetration ** 2.5): give a larger approach or "
               f"reference='point'")
    elif why == _core.GAP_FAR:
        msg = (f"{func}: dy = {info['dy']!r} m: the region to cover ({info['lo']:.3g} to "
               f"{info['hi']:.3g} m in the plane) lies more than 1e8 elements from the "
               f"reference point: elements far too small for where it is")
    elif why == _core.GAP_SCAN:
        msg = (f"{func}: at y_ws = {y_ws!r} m the cross-sections in the tangent plane are far "
               f"longer than the profiles' window ({info['plane_lo']:g} to "
               f"{info['plane_hi']:g} m): profiles with coordinates in the wrong unit?")
    else:
        msg = f"{func}: {status_message(status)}"
    return RollerRigError(msg)


def _count(v: float) -> Union[int, float]:
    """An element count the core gave as a double, as an integer."""
    return int(v) if np.isfinite(v) else v


def _patch(h: F64Array, info: Mapping[str, Any], side: str, y_ws: float, z: float,
           roll: float, approach: float, cover: float, lowered: float) -> Patch:
    """The Patch of a built grid (rr_gap_build's h and numbers)."""
    def vec(k: str) -> F64Array:
        return np.array(info[k], dtype=float)
    return Patch(h=h, dx=info["dx"], dy=info["dy"], x0=info["x0"], y0=info["y0"],
                 point=vec("point"), wheel_point=vec("wheel_point"), lowered=lowered,
                 t1=vec("t1"), t2=vec("t2"), n=vec("n"), delta=info["delta"],
                 s_roller=info["s_roller"], s_wheel=info["s_wheel"], r=info["r"], R=info["R"],
                 side=side, y_ws=y_ws, z=z, roll=roll, approach=approach, cover=cover,
                 regions=tuple(info["regions"]), excluded=tuple(info["excluded"]))


def _warn_excluded(func: str, info: Mapping[str, Any], y_ws: float, side: str,
                   combine: float, stacklevel: int = 3) -> None:
    rest = info["excluded"]
    if rest:
        warnings.warn(f"{func}: at y_ws = {y_ws!r} m the {side} wheel has "
                      f"{len(rest)} more interpenetration region(s) farther than "
                      f"combine = {combine:g} m from the deepest one (at y = "
                      f"{', '.join(f'{0.5 * (a + b):.4g}' for a, b in rest)} m in the plane): "
                      f"a separate patch, left out", RollerRigWarning, stacklevel=stacklevel)


def undeformed_distance(geometry: RigGeometry, y_ws: float, *, side: str = "left",
                        N: Optional[float] = None, approach: Optional[float] = None,
                        n: int = 40, E: float = 2.1e11, nu: float = 0.28, cover: float = 1.5,
                        dx: Optional[float] = None, dy: Optional[float] = None,
                        reference: Reference = "weighted", combine: float = 4e-3,
                        z: Optional[float] = None, roll: Optional[float] = None) -> Patch:
    """The undeformed distance h(x, y) of one wheel on its roller, on a grid.

    Parameters
    ----------
    geometry : RigGeometry
        The profiles and their placement.
    y_ws : float
        The wheelset's lateral shift [m].
    side : {"left", "right"}, optional
        The wheel.
    N : float, optional
        Normal load [N], for Hertz's approach when `approach` is None.
    approach : float, optional
        The expected approach [m]; None: Hertz's at the rollerrig contact
        point for the normal load N (E, nu of both bodies).
    n : int, optional
        About n elements across the longer side of the region, square
        elements (unless dx, dy are given).
    E : float, optional
        Young's modulus of both bodies [Pa].
    nu : float, optional
        Poisson ratio of both bodies [-].
    cover : float, optional
        The grid covers the region where h <= cover * approach (cover >= 1:
        the contact lies where h <= the approach found), plus one element
        on every side.
    dx, dy : float, optional
        The element size [m] (a grid of more than the exact solver's 1024
        elements a side is refused before it is built).
    reference : str or tuple, optional
        The tangent plane's point P and angle: "weighted" (default;
        CONTACT's: the centre of the vertical interpenetration at
        `approach`, each lateral strip weighted by the integral over x of
        its squared interpenetration, and the roller's inclination averaged
        with the same weights), "point" (rollerrig's contact point, the
        least vertical gap, and its contact angle: the frame of rig_contact)
        or (s_roller, delta): P on the roller at that profile coordinate
        [m], the angle [rad] given.
    combine : float, optional
        [m], >= 0: lateral intervals of that region at most this far from
        the deepest one are on the grid, the rest are a separate patch
        (Patch.excluded, a warning).
    z, roll : float, optional
        The pose: by default wheelset_contact's axle height and roll at
        y_ws (both surfaces just touching); given, z [m] and roll [rad]: a
        loaded pose (the wheelset lowered by its approach over cos(delta),
        as CONTACT builds h and rig_exact does by default), CONTACT's
        prescribed roll.

    Returns
    -------
    Patch
        h with least value 0, its grid and frame (:class:`Patch`), built by
        the C core (csrc/geometry/rr_gap.h).

    Raises
    ------
    RollerRigError
        Naming the argument: bad numbers, side or reference; a load or
        approach whose region reaches past the profiles in the plane, or a
        pose whose cross-sections do not overlap; a grid too large.

    Warns
    -----
    RollerRigWarning
        When intervals farther than `combine` are left out.

    See Also
    --------
    rollerrig.exact_solve : solves the contact on h.
    patch_shape : the extent of the solution's contact area.
    rig_exact : one wheel of the rig solved this way.

    Examples
    --------
    >>> import rollerrig as rr
    >>> g = rr.RigGeometry.standard()
    >>> p = rr.undeformed_distance(g, 0.0, N=1e4)
    >>> p.shape, round(p.delta, 4)
    ((44, 19), 0.0303)
    >>> s = rr.exact_solve(p.h, dx=p.dx, dy=p.dy, x0=p.x0, y0=p.y0, N=1e4, mu=0.3, cx=2e-4)
    >>> shape = rr.patch_shape(s.contact, p.dx, p.dy)
    >>> print(f"{shape.length * 1e3:.2f} x {shape.width * 1e3:.2f} mm, {shape.regions} region")
    3.53 x 16.64 mm, 1 region
    """
    func = "undeformed_distance"
    z_ws, roll_ws, cpt = _pose_and_point(func, geometry, y_ws, side)
    z = z_ws if z is None else check_number(func, "z", z, positive=True)
    roll = roll_ws if roll is None else check_number(func, "roll", roll)
    for name, v in (("N", N), ("approach", approach)):
        check_number(func, name, v, allow_none=True, positive=True)
    if approach is None:
        if N is None:
            raise RollerRigError(f"{func}: give the normal load N [N] or the approach [m]")
        from ..contact.creep import hertz
        try:
            approach = float(hertz(float(cpt.A[0]), float(cpt.B[0]), float(N), E=E,
                                   nu=nu).delta)
        except RollerRigError as e:      # Hertz's approach at the contact point
            raise RollerRigError(f"{func}: Hertz's approach for N at the contact point: "
                                 f"{e}") from None
    approach = float(approach)
    cover = check_number(func, "cover", cover, positive=True)
    if cover < 1.0:
        raise RollerRigError(f"{func}: cover must be >= 1, got {cover!r}")
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) \
            or not 4 <= n <= _core.GAP_MAX_N:
        raise RollerRigError(f"{func}: n must be an integer from 4 to {_core.GAP_MAX_N}, "
                             f"got {n!r}")
    dx = check_number(func, "dx", dx, allow_none=True, positive=True)
    dy = check_number(func, "dy", dy, allow_none=True, positive=True)
    combine = _combine(func, combine)
    code, ref_s, ref_d = _reference(func, reference)
    y_ws = float(y_ws)
    status, h, info = _core.gap_build(
        *geometry._arrays(), geometry._params(), 0 if side == "left" else 1, y_ws, z, roll,
        float(cpt.s_roller[0]), float(cpt.s_wheel[0]), float(cpt.delta[0]), code, ref_s, ref_d,
        approach, cover, int(n), dx or 0.0, dy or 0.0, combine)
    if status < 0:
        load = f"N = {float(N)!r} N" if N is not None else f"approach = {approach!r} m"
        raise _gap_error(func, status, info, geometry, side, y_ws, load, z, roll)
    _warn_excluded(func, info, y_ws, side, combine)
    return _patch(h, info, side, y_ws, z, roll, approach, cover, z_ws - z)


# ---------------------------------------------------------------- the patch's shape

class PatchShape(NamedTuple):
    """The extent of a contact area in CONTACT's terms, as :func:`patch_shape` gives it."""

    length: float      #: along x: (last - first column holding contact + 1) dx [m]
    width: float       #: along y: (last - first row holding contact + 1) dy [m]
    length_cols: float  #: columns holding contact times dx [m]
    width_rows: float  #: rows holding contact times dy [m] (< width: lateral gaps)
    regions: int       #: connected regions of contact elements (8-neighbours)
    lateral_regions: int  #: runs of rows holding contact


def patch_shape(contact: npt.ArrayLike, dx: float, dy: float) -> PatchShape:
    """The extent of a contact area, in CONTACT's terms.

    Parameters
    ----------
    contact : array_like of bool, shape (my, mx)
        The elements in contact, e.g. ExactSolution.contact.
    dx, dy : float
        The element size [m].

    Returns
    -------
    PatchShape
        Its length and width as the bounding extent of the elements in
        contact [m], the columns and rows that hold contact [m], and the
        number of separate regions (:class:`PatchShape`); all 0 without
        contact.
    """
    c = np.asarray(contact, dtype=bool)
    cols = np.flatnonzero(c.any(axis=0))
    rows = np.flatnonzero(c.any(axis=1))
    if cols.size == 0:
        return PatchShape(0.0, 0.0, 0.0, 0.0, 0, 0)
    return PatchShape(float((cols[-1] - cols[0] + 1) * dx),
                      float((rows[-1] - rows[0] + 1) * dy),
                      float(cols.size * dx), float(rows.size * dy), _label_count(c),
                      len(_runs(c.any(axis=1))))


def _label_count(c: npt.NDArray[np.bool_]) -> int:
    """Connected components of True elements, 8-neighbour connectivity."""
    seen = np.zeros_like(c)
    count = 0
    my, mx = c.shape
    for i0, j0 in zip(*np.nonzero(c)):
        if seen[i0, j0]:
            continue
        count += 1
        stack = [(i0, j0)]
        seen[i0, j0] = True
        while stack:
            i, j = stack.pop()
            for a in (i - 1, i, i + 1):
                for b in (j - 1, j, j + 1):
                    if 0 <= a < my and 0 <= b < mx and c[a, b] and not seen[a, b]:
                        seen[a, b] = True
                        stack.append((a, b))
    return count
