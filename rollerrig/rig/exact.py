"""One wheel of the rig solved by Kalker's exact theory on its own patch:
the undeformed distance from the rig's profiles (rollerrig.geometry.patch,
a patch that need not be an ellipse), the load along the patch's normal or
the wheel's vertical load, the creepages from the rig's kinematics::

    g = rr.RigGeometry.measured_pair()
    e = rr.rig_exact(g, 0.0035, Fz=6e4, spin=12.4, roller_spin=5.587, mu=0.5)
    e.solution.fx, e.patch.point, e.shape.regions, e.force

The pose, as CONTACT's: h at the wheelset where the load puts it, lowered
vertically by the approach over cos(delta) (loaded=True; the patch module
says what that changes), and the creepages at CONTACT's material points
(_motion).  The frame is the patch's, that of rollerrig.rig.contact at
zero yaw and longitudinal shift: fx, fy, mz are rollerrig's (on the wheel;
mz about n at P).  The C core does the whole (csrc/geometry/rr_wheel_exact.h).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from typing import TYPE_CHECKING, Any, Dict, Mapping, Optional, Tuple

if TYPE_CHECKING:
    from .._typing import F64Array
    from ..geometry.patch import PatchShape
    from ..geometry.wheelset import ContactTable, RigGeometry

from .. import _core
from .._binding import METHODS, check_creep_options
from .._errors import RollerRigError, check_number, check_status, status_message
from ..contact.exact import ExactSolution, _solution
from ..geometry.patch import (Patch, _combine, _gap_error, _patch, _pose_and_point,
                              _reference, _warn_excluded, patch_shape)
from ..geometry.wheelset import contact_table
from .contact import rig_contact

__all__ = ["RigExact", "rig_exact"]


@dataclass(frozen=True, eq=False)
class RigExact:
    """One wheel of the rig solved by the exact theory on its own patch, as
    :func:`rig_exact` returns it.

    ``solution`` is the :class:`ExactSolution`, ``patch`` the
    :class:`Patch`; the properties ``shape`` (the :class:`PatchShape` of the
    contact area) and ``force`` (the contact force on the wheel in the rig
    frame) follow from them.
    """

    solution: ExactSolution  #: fields and forces: fx along t1, fy along t2, mz about n at P
    patch: Patch             #: h, the grid and the frame
    cx: float                #: creepages at the patch's reference point [-], [-], [rad/m]
    cy: float
    cphi: float
    V: float                 #: rolling speed [m/s] (0 where the creepages were given)
    N: float                 #: normal load [N]
    passes: int              #: grids solved (the first ones find the approach and load)
    builds: int = 0          #: patches built (the first pass's, the loaded one, rebuilds)

    @property
    def shape(self) -> PatchShape:
        """PatchShape of the contact area."""
        return patch_shape(self.solution.contact, self.patch.dx, self.patch.dy)

    @property
    def force(self) -> F64Array:
        """Contact force on the wheel in the rig frame [N]:
        fx t1 + fy t2 + fn n."""
        s, p = self.solution, self.patch
        return s.fx * p.t1 + s.fy * p.t2 + s.fn * p.n


def _motion(geometry: RigGeometry, y_ws: float, spin: float, roller_spin: float, vy: float,
            yaw_rate: float, vmin: float,
            table: Optional[ContactTable]) -> Tuple[Tuple[float, ...], ...]:
    """The wheelset's rigid motion at y_ws (rig_contact's pose at x = yaw =
    0: centre, velocity, angular velocity), from which the core takes the
    creepages of a patch (rr_wheel_exact.h: the slip of the wheel's
    material point at P - pen n, CONTACT's point Q, with the centre
    lowered as the patch's pose, relative to the roller's at P, over the
    rolling speed).  At the zero-gap pose both points are P (rig_contact's
    creepages, at rollerrig's contact point); at the loaded pose, with the
    centre lowered by pen / cos(delta), the wheel's point lies pen
    sin^2(delta) / cos(delta) nearer the axle than at the zero-gap pose,
    3e-5 of cx at the flange root (delta = 0.34 rad)."""
    if table is None:
        # y_ws a row, the slopes the next row's difference: a third row
        # before it (the table this was) gave the same doubles for one more
        # rigid search, 0.09 of a 1 ms call
        table = contact_table(geometry, y_ws, y_ws + 1e-5, 2)
    c = rig_contact(table, y=y_ws, vy=vy, yaw_rate=yaw_rate, spin=spin,
                    roller_spin=roller_spin, N_left=1.0, N_right=1.0, kinematics_only=True,
                    vmin=vmin, errors="raise")
    pose = c.pose
    return tuple(tuple(float(v) for v in np.asarray(a).reshape(3))
                 for a in (pose.c, pose.v, pose.w))


def rig_exact(geometry: RigGeometry, y_ws: float, *, mu: float, N: Optional[float] = None,
              Fz: Optional[float] = None, side: str = "left", spin: Optional[float] = None,
              roller_spin: Optional[float] = None, vy: float = 0.0, yaw_rate: float = 0.0,
              cx: Optional[float] = None, cy: Optional[float] = None,
              cphi: Optional[float] = None, E: float = 2.1e11, nu: float = 0.28, n: int = 40,
              reference: str = "weighted", loaded: bool = True, passes: int = 2,
              vmin: float = 1e-3, table: Optional[ContactTable] = None, tol: float = 1e-6,
              maxit: int = 5000, **patch_options: Any) -> RigExact:
    """One wheel of the rig solved by Kalker's exact theory on its
    non-Hertzian patch (:func:`undeformed_distance`).

    Parameters
    ----------
    geometry : RigGeometry
        The rig's wheel and roller profiles.
    y_ws : float
        The wheelset's lateral shift [m].
    mu : float
        Coulomb friction coefficient [-].
    N : float, optional
        The load along the patch's normal [N]; or
    Fz : float, optional
        The vertical force on the wheel [N] (the rig's wheel load,
        CONTACT's FZ): N is then iterated until the contact force's
        vertical component, N n_z + fy t2_z, is Fz to the solver's
        tolerance tol (at least 1e-7), and solved again on a grid built at
        the pose of the load found where its approach moved by over 1 %.
        Give N or Fz.
    side : {"left", "right"}, optional
        The wheel.
    spin, roller_spin : float, optional
        The wheelset's and the rollers' angular speeds [rad/s], as for
        :func:`rig_contact` (zero yaw and longitudinal shift; see _motion
        for the material points); needed unless cx, cy, cphi are given.
    vy : float, optional
        Lateral speed [m/s].
    yaw_rate : float, optional
        [rad/s].
    cx, cy, cphi : float, optional
        The creepages [-], [-], [rad/m] at the patch's reference point, in
        its frame: all three or none (then from the kinematics).
    E : float, optional
        Young's modulus of both bodies [Pa].
    nu : float, optional
        Poisson ratio of both bodies [-].
    n : int, optional
        Elements across the grid, 4 to GAP_MAX_N.
    reference : str, optional
        As :func:`undeformed_distance` (default "weighted", CONTACT's
        reference: the patch's centre, not its deepest point).
    loaded : bool, optional
        True: h at the loaded pose, the wheelset lowered from its zero-gap
        height by the approach over cos(delta) (as CONTACT: the load moves
        the wheelset vertically, not along the normal, so the wheel also
        slides by approach tan(delta) along the plane); False: at the
        zero-gap pose.
    passes : {2, 1}, optional
        2 (default): a first grid of n/2 across (elements twice dx, dy
        where those are given) at the zero-gap pose, sized from Hertz's
        approach, finds the approach; the second, with n across, covers
        where h <= 1.1 times it (1.03 where dx and dy are given: the
        elements stand on the same lattice whatever the cover, so only
        the exterior shrinks); 1: one grid sized from Hertz's approach
        (or the approach given).  Either way a solution whose contact
        reaches the grid's edge, or whose approach exceeds what the grid
        covers, is solved again on a grid sized from the approach found.
    vmin : float, optional
        Least rolling speed for the creepages [m/s].
    table : ContactTable, optional
        A table of geometry for the wheelset's pose and rates (default:
        one built at y_ws).
    tol, maxit : float, int, optional
        The solver's tolerance and iteration cap.
    **patch_options
        Further options of :func:`undeformed_distance` (approach, cover
        (>= 1), dx, dy, combine, z, roll).

    Returns
    -------
    RigExact
        The :class:`ExactSolution`, the :class:`Patch`, the creepages used
        (:class:`RigExact`).

    Raises
    ------
    RollerRigError
        Neither N nor Fz; passes not 1 or 2; some but not all of cx, cy,
        cphi; neither the creepages nor spin and roller_spin; an unknown
        option; cover < 1; n out of range; a failure of the patch, the
        load iteration or the solver, naming the status.

    See Also
    --------
    rig_contact : the Hertzian contact of both wheels.
    undeformed_distance : the patch's gap.
    exact_solve : the exact theory on an ellipse.

    Notes
    -----
    The whole of it, patches, load iteration and solves, runs in the C
    core (csrc/geometry/rr_wheel_exact.h).

    Examples
    --------
    The left wheel of the measured pair at 3.5 mm, on a coarse grid:

    >>> import rollerrig as rr
    >>> g = rr.RigGeometry.measured_pair()
    >>> e = rr.rig_exact(g, 0.0035, Fz=6e4, spin=12.4, roller_spin=5.587, mu=0.5, n=16)
    >>> print(f"N = {e.N:.0f} N, fx = {e.solution.fx:.0f} N")
    N = 59972 N, fx = -18156 N
    """
    func = "rig_exact"
    if (N is None) == (Fz is None):
        raise RollerRigError(f"{func}: give the normal load N or the vertical load Fz [N]")
    N = check_number(func, "N", N, allow_none=True, positive=True)
    Fz = check_number(func, "Fz", Fz, allow_none=True, positive=True)
    if passes not in (1, 2):
        raise RollerRigError(f"{func}: passes must be 1 or 2, got {passes!r}")
    given = [v is not None for v in (cx, cy, cphi)]
    if any(given) and not all(given):
        raise RollerRigError(f"{func}: give all three creepages cx, cy, cphi or none")
    if not all(given) and (spin is None or roller_spin is None):
        raise RollerRigError(f"{func}: give spin and roller_spin [rad/s] (or cx, cy, cphi)")
    unknown = set(patch_options) - {"approach", "cover", "dx", "dy", "combine", "z", "roll"}
    if unknown:
        raise RollerRigError(f"{func}: unknown option(s) {sorted(unknown)}")
    opts = dict(patch_options)
    approach = check_number(func, "approach", opts.pop("approach", None), positive=True,
                            allow_none=True)
    cover = check_number(func, "cover", opts.pop("cover", 1.5), positive=True)
    if cover < 1.0:
        raise RollerRigError(f"{func}: cover must be >= 1, got {cover!r}")
    z_given = check_number(func, "z", opts.pop("z", None), allow_none=True, positive=True)
    roll_given = check_number(func, "roll", opts.pop("roll", None), allow_none=True)
    dx = check_number(func, "dx", opts.pop("dx", None), allow_none=True, positive=True)
    dy = check_number(func, "dy", opts.pop("dy", None), allow_none=True, positive=True)
    combine = _combine(func, opts.pop("combine", 4e-3))
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) \
            or not 4 <= n <= _core.GAP_MAX_N:
        raise RollerRigError(f"{func}: n must be an integer from 4 to {_core.GAP_MAX_N}, "
                             f"got {n!r}")
    code, ref_s, ref_d = _reference(func, reference)
    E = check_number(func, "E", E, positive=True)
    nu = check_number(func, "nu", nu)
    mu = check_number(func, "mu", mu, positive=True)
    G = E / (2.0 * (1.0 + nu))
    # the solver's options by the registry's rules (names, ranges, integers)
    check_creep_options(func, "exact", dict(tol=tol, maxit=maxit))
    spin_shift = float(METHODS["exact"].options["spin_shift"].default)
    z0, roll0, cpt = _pose_and_point(func, geometry, y_ws, side)
    y_ws = float(y_ws)
    motion: Tuple[Tuple[float, ...], ...]
    if cx is not None and cy is not None and cphi is not None:     # all(given)
        creep = (1, float(cx), float(cy), float(cphi))
        motion = ((0.0,) * 3,) * 3
        roller_spin_ = 0.0
    else:
        assert spin is not None and roller_spin is not None         # (checked above)
        creep = (0, 0.0, 0.0, 0.0)
        try:
            motion = _motion(geometry, y_ws, spin, roller_spin, vy, yaw_rate, vmin, table)
        except RollerRigError as e:          # the rig's kinematics refuse the motion
            raise RollerRigError(f"{func}: the wheelset's motion: {e}") from None
        roller_spin_ = float(roller_spin)
    point = tuple(float(getattr(cpt, k)[0]) for k in ("s_roller", "s_wheel", "delta", "A", "B"))
    nan = float("nan")
    out = _core.wheel_exact(
        *geometry._arrays(), geometry._params(), 0 if side == "left" else 1, y_ws,
        (z0, roll0), point, (N or 0.0, Fz or 0.0, E, nu, mu), creep, motion, roller_spin_,
        float(vmin), (code, ref_s, ref_d, approach or 0.0, cover, int(n), dx or 0.0, dy or 0.0,
                      combine),
        (nan if z_given is None else z_given, nan if roll_given is None else roll_given,
         int(bool(loaded)), int(passes)), (float(tol), int(maxit), spin_shift))
    status, results, pn, px, py, sx, sy, state, h, pinfo, rinfo = out
    if status < 0:
        raise _wheel_error(func, status, pinfo, rinfo, geometry, side, y_ws, dx, dy,
                           dict(mu=mu, G=G, nu=nu))
    _warn_excluded(func, pinfo, y_ws, side, combine)
    p = _patch(h, pinfo, side, y_ws, rinfo["z"], rinfo["roll"], rinfo["approach"],
               rinfo["cover"], rinfo["lowered"])
    grid = (pinfo["mx"], pinfo["my"], p.dx, p.dy, p.x0, p.y0)
    args = dict(N=rinfo["N"], mu=mu, G=G, nu=nu, cx=rinfo["cx"], cy=rinfo["cy"],
                cphi=rinfo["cphi"])
    s = _solution(func, (status, None, grid, results, pn, px, py, sx, sy, state),
                  {k: np.array(v) for k, v in args.items()}, None, edge_ok=True)
    return RigExact(solution=s, patch=p, cx=rinfo["cx"], cy=rinfo["cy"], cphi=rinfo["cphi"],
                    V=rinfo["V"], N=rinfo["N"], passes=rinfo["passes"], builds=rinfo["builds"])


def _wheel_error(func: str, status: int, pinfo: Dict[str, Any], rinfo: Dict[str, Any],
                 geometry: RigGeometry, side: str, y_ws: float, dx: Optional[float],
                 dy: Optional[float], material: Mapping[str, float]) -> RollerRigError:
    """The RollerRigError of a failed rr_wheel_exact: its reason in words."""
    why = rinfo["why"]
    if why == _core.WHEEL_EXACT_GAP or why == _core.WHEEL_EXACT_HERTZ:
        load = f"N = {rinfo['fail_N']!r} N"
        if why == _core.WHEEL_EXACT_HERTZ:
            msg = f"undeformed_distance: N = {rinfo['fail_N']!r}: {status_message(status)}"
        else:
            msg = str(_gap_error("undeformed_distance", status, pinfo, geometry, side, y_ws,
                                 load, rinfo["z"], rinfo["roll"]))
        if rinfo["fail_pass"] and (dx is not None or dy is not None):
            return RollerRigError(f"{func}: the first pass, on elements twice dx, dy: {msg}")
        return RollerRigError(f"{func}: the patch: {msg}")
    if why == _core.WHEEL_EXACT_EDGE:
        return RollerRigError(f"{func}: at y_ws = {y_ws!r} m the contact keeps reaching the "
                              f"grid's edge")
    if why == _core.WHEEL_EXACT_SETTLE:
        return RollerRigError(f"{func}: the normal load for Fz did not settle")
    if why == _core.WHEEL_EXACT_SOLVE:
        args = dict(N=rinfo["fail_N"], **material, cx=rinfo["cx"], cy=rinfo["cy"],
                    cphi=rinfo["cphi"])
        try:
            check_status(func, np.array(status, dtype=np.int8),
                         {k: np.array(v) for k, v in args.items()}, "raise")
        except RollerRigError as e:
            return e
    return RollerRigError(f"{func}: {status_message(status)}")
