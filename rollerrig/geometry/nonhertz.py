"""A fast non-Hertzian contact of a wheel on its roller: tables per lateral
shift built by the exact theory, evaluated in microseconds.

    g = rr.RigGeometry.measured_pair()
    t = rr.nonhertz_table(g, -0.004, 0.004, Fz=6e4)        # both sides, rows 0.2 mm apart
    t.save("pair.npz"); t = rr.NonHertzTable.load("pair.npz")
    c = rr.rig_contact(ct, y=0.002, spin=..., roller_spin=..., Fz_left=6e4, Fz_right=6e4,
                       patch="nonhertz", nonhertz=t)

The method (benchmarks/NONHERTZ_STUDY.md, "The recommended method, for C"):
per row (a lateral shift of the wheelset) and per separate region of the
gap (a patch, with its own gap at the row's zero-gap pose) the exact normal
solution at nine vertical loads up to 1.85 times the nominal one (load
against lowering, plane, pressure centroid and moments, area, peak) and
its exact linear creep coefficients, and at two loads the exact creep
forces' departure from the calibrated ellipse on a grid of creepages; at
run time the two rows around y, the shared lowering from the vertical
load, per patch the calibrated ellipse by the exact-theory table plus the
tabulated correction (csrc/geometry/rr_nonhertz.h; the rows are built by
rr_nonhertz_table.h, in threads).
"""
from __future__ import annotations

import os
import warnings
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from .. import _core
from .._errors import RollerRigError, RollerRigWarning, check_number, status_message
from .._typing import F64Array
from .patch import _pose_and_point
from .wheelset import RigGeometry, wheelset_contact

__all__ = ["NonHertzSide", "NonHertzTable", "nonhertz_table"]

#: the rows' load nodes reach this multiple of the nominal vertical load
#: (the study's 1.1^1.5 x 1.6: its lowering 1.1 times that of 1.6 Fz)
LOAD_SPAN = 1.6 * 1.1 ** 1.5
#: the rigid contact point's jumps: a lateral move of the contact point
#: larger than this between rows 0.01 mm apart
JUMP = 0.5e-3
#: rows within this distance of a jump are refined
JUMP_ZONE = 0.3e-3
#: rows a side at most (640 doubles each: 100 MB), and the widest range of shifts [m]
MAX_ROWS, MAX_SPAN = 20000, 0.1

#: a wheelset's motion at a row as the core takes it: ((centre), (velocity),
#: (angular velocity)), rig frame
Motion = Tuple[Tuple[float, float, float], ...]


@dataclass(frozen=True, eq=False)
class NonHertzSide:
    """One side's table: its rows and how they were built.

    A side of a :class:`NonHertzTable` (:func:`nonhertz_table`).

    See Also
    --------
    NonHertzTable : both sides.
    """
    rows: np.ndarray   #: the rows, shape (n, NH_ROW_LEN); column 0 the shift y [m]
    sigma: float       #: +1 left, -1 right
    R0: float          #: the roller's nominal radius [m]
    G: float           #: shear modulus [Pa]
    nu: float          #: Poisson ratio [-]
    mu_ref: float      #: the friction the correction was built at

    @property
    def y(self) -> F64Array:
        """The rows' lateral shifts [m]."""
        return self.rows[:, 0].copy()

    @property
    def head(self) -> Tuple[float, float, float, float, float]:
        """The table's header (sigma, R0 [m], G [Pa], nu, mu_ref), as the C
        core takes it (rr_nonhertz.h)."""
        return (float(self.sigma), float(self.R0), float(self.G), float(self.nu),
                float(self.mu_ref))

    def check(self) -> NonHertzSide:
        """Check the header and every row by the C core's rules.

        Returns
        -------
        NonHertzSide
            self, when valid.

        Raises
        ------
        RollerRigError
            Naming the header or the first row (and its y) that is not a
            valid table row (a value not finite or out of its range,
            rr_nonhertz.h).
        """
        st, bad = _core.nonhertz_check(self.rows, self.head)
        if st < 0:
            where = ("the header" if bad < 0
                     else f"row {bad} (y = {float(self.rows[bad, 0])!r} m)")
            raise RollerRigError(f"NonHertzTable: {where} is not a valid table row (a value "
                                 f"not finite or out of its range, rr_nonhertz.h)")
        return self


@dataclass(frozen=True, eq=False)
class NonHertzTable:
    """A profile pair's non-Hertzian tables, one per side, as
    :func:`nonhertz_table` returns it.

    See Also
    --------
    nonhertz_table : the build.
    rig_nonhertz_table : the rig's table.
    rig_contact : its patch="nonhertz" takes one.
    """
    left: Optional[NonHertzSide]    #: the left side's table (None where not built)
    right: Optional[NonHertzSide]   #: the right side's table (None where not built)
    Fz: float                  #: the nominal vertical load the nodes were sized for [N]
    build_seconds: float = float("nan")   #: wall time of the build

    def side(self, name: str) -> NonHertzSide:
        """One side's table.

        Parameters
        ----------
        name : {"left", "right"}
            The side.

        Returns
        -------
        NonHertzSide
            Its table.

        Raises
        ------
        RollerRigError
            No table was built for that side.
        """
        s: Optional[NonHertzSide] = getattr(self, name)
        if s is None:
            raise RollerRigError(f"NonHertzTable: no table for the {name} side")
        return s

    def save(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Save as .npz (numpy arrays only: np.load needs no pickle).

        Parameters
        ----------
        path : str or path-like
            The file; :meth:`load` reads it back.
        """
        out: Dict[str, Any] = dict(Fz=self.Fz, build_seconds=self.build_seconds,
                   layout=np.array([_core.NH_ROW_LEN, _core.NH_NODES, _core.NH_MAX_PATCHES]))
        for name in ("left", "right"):
            s = getattr(self, name)
            if s is not None:
                out[f"{name}_rows"] = s.rows
                out[f"{name}_head"] = np.array(s.head)
        np.savez(path, **out)

    @classmethod
    def load(cls, path: Union[str, "os.PathLike[str]"]) -> "NonHertzTable":
        """A table saved by :meth:`save`; checked row by row.

        Parameters
        ----------
        path : str or path-like
            The .npz file.

        Returns
        -------
        NonHertzTable
            The table.

        Raises
        ------
        RollerRigError
            A layout that is not this library's; a header or row that is
            not valid (:meth:`NonHertzSide.check`).
        """
        with np.load(path, allow_pickle=False) as f:
            layout = tuple(int(v) for v in f["layout"])
            if layout != (_core.NH_ROW_LEN, _core.NH_NODES, _core.NH_MAX_PATCHES):
                raise RollerRigError(f"NonHertzTable.load: {path}: the layout {layout} is not "
                                     f"this library's")
            sides: Dict[str, Optional[NonHertzSide]] = {}
            for name in ("left", "right"):
                if f"{name}_rows" in f:
                    h = f[f"{name}_head"]
                    sides[name] = NonHertzSide(np.ascontiguousarray(f[f"{name}_rows"],
                                                                    dtype=float),
                                               *(float(v) for v in h)).check()
                else:
                    sides[name] = None
            return cls(sides["left"], sides["right"], float(f["Fz"]),
                       float(f["build_seconds"]))


def _jumps(geometry: RigGeometry, y_lo: float, y_hi: float, side: str) -> F64Array:
    """Lateral shifts where the side's rigid contact point jumps."""
    y = np.arange(y_lo - JUMP_ZONE, y_hi + JUMP_ZONE + 5e-6, 1e-5)
    c = getattr(wheelset_contact(geometry, y), side)
    k = np.flatnonzero(np.abs(np.diff(c.y)) > JUMP)
    return 0.5 * (y[k] + y[k + 1])


def row_shifts(geometry: RigGeometry, y_min: float, y_max: float, dy: float, side: str,
               dy_jump: Optional[float] = None) -> F64Array:
    """The rows: every dy from y_min to y_max, every dy_jump within
    JUMP_ZONE of the rigid contact point's jumps (none if dy_jump is None)."""
    n = int(np.ceil((y_max - y_min) / dy - 1e-9))
    ys = list(np.linspace(y_min, y_min + n * dy, n + 1))
    if dy_jump is not None:
        for j in _jumps(geometry, y_min, y_max, side):
            ys += list(np.arange(j - JUMP_ZONE, j + JUMP_ZONE + 1e-9, dy_jump))
    y = np.unique(np.round(np.array(ys), 9))
    return y[(y >= y_min - 1e-12) & (y <= y_min + n * dy + 1e-12)]


def nonhertz_table(geometry: RigGeometry, y_min: Optional[float], y_max: Optional[float],
                   *, Fz: float, dy: float = 2e-4, dy_jump: Optional[float] = 5e-5,
                   mu_ref: float = 0.52,
                   E: float = 2.1e11, nu: float = 0.28, sides: Sequence[str] = ("left", "right"),
                   n: int = 40, n_corr: int = 30, richardson: bool = True, combine: float = 4e-3,
                   tol: float = 1e-6, maxit: int = 5000, workers: int = 2,
                   y: Optional[npt.ArrayLike] = None) -> NonHertzTable:
    """The non-Hertzian contact's tables of a profile pair.

    Parameters
    ----------
    geometry : RigGeometry
        The profile pair.
    y_min, y_max : float
        The rows' range of lateral shifts [m], y_max > y_min (ignored when
        y is given).
    Fz : float
        The nominal vertical wheel load [N], > 0: the nodes reach 1.85 Fz;
        beyond them the loads are extrapolated by Hertz's law; the gap's
        separate regions are told apart at Fz's lowering.
    dy : float, optional
        Row spacing [m], > 0.
    dy_jump : float or None, optional
        Row spacing [m] within 0.3 mm of a jump of the rigid contact point
        (None: no refinement; the rows must not straddle a jump,
        NONHERTZ_STUDY.md).
    mu_ref : float, optional
        The friction of the correction [-], > 0.
    E : float, optional
        Young's modulus of both bodies [Pa], > 0.
    nu : float, optional
        Poisson ratio of both bodies [-].
    sides : sequence of {"left", "right"}, optional
        The sides to build (the others None).
    n, n_corr : int, optional
        Elements across the longer side of the nodes' and the correction's
        grids, >= 1 (at least half as many across the shorter: a flange
        patch, 10 times longer than wide, is resolved across its width).
    richardson : bool, optional
        Extrapolate the coefficients and the correction from elements half
        as large.
    combine : float, optional
        [m], >= 0: intervals of the gap farther apart are separate regions,
        each its own patch (CONTACT's D_COMB; up to two a row,
        rr_nonhertz_table.h).
    tol, maxit : float, int, optional
        The exact solver's tolerance and iteration cap.
    workers : int, optional
        Threads building rows side by side, >= 1.
    y : array_like, optional
        The rows' shifts [m] (instead of y_min, y_max, dy); at least two,
        finite.

    Returns
    -------
    NonHertzTable
        One :class:`NonHertzSide` per side (None where not built), with
        Fz and the build's wall time.

    Raises
    ------
    RollerRigError
        geometry not a RigGeometry; a number not finite or out of its
        range (naming it); sides naming neither side; fewer than two
        finite rows; a row whose build fails (naming the side, y, the
        patch, the load node and why).

    Warns
    -----
    RollerRigWarning
        A row with intervals of the gap farther than combine from its
        patches (not tabulated), or with more separate regions than
        patches a row (held in a neighbour's patch).

    See Also
    --------
    rig_nonhertz_table : the rig's table from its parameters.
    rig_contact : patch="nonhertz" uses the table.

    Examples
    --------
    Three rows of the left wheel of the rig's pair, on coarse grids:

    >>> import rollerrig as rr
    >>> rig, params, table = rr.build_rig()
    >>> nh = rr.nonhertz_table(table.geometry, 0.0, 2e-4, dy=1e-4, dy_jump=None,
    ...                        Fz=200.0, n=10, n_corr=8, richardson=False,
    ...                        sides=("left",))
    >>> print(nh.left.y, nh.right)
    [0.     0.0001 0.0002] None
    """
    import time
    func = "nonhertz_table"
    if not isinstance(geometry, RigGeometry):
        raise RollerRigError(f"{func}: geometry must be a RigGeometry, got {geometry!r:.60}")
    Fz = check_number(func, "Fz", Fz, positive=True)
    mu_ref = check_number(func, "mu_ref", mu_ref, positive=True)
    E = check_number(func, "E", E, positive=True)
    nu = check_number(func, "nu", nu)
    combine = check_number(func, "combine", combine)
    if combine < 0:
        raise RollerRigError(f"{func}: combine must be >= 0 [m], got {combine!r}")
    for name, v in (("n", n), ("n_corr", n_corr), ("workers", workers)):
        if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or v < 1:
            raise RollerRigError(f"{func}: {name} must be a positive integer, got {v!r}")
    if not set(sides) <= {"left", "right"} or not sides:
        raise RollerRigError(f"{func}: sides must name 'left' and/or 'right', got {sides!r}")
    if y is None:
        y_min = check_number(func, "y_min", y_min)
        y_max = check_number(func, "y_max", y_max)
        dy = check_number(func, "dy", dy, positive=True)
        if not y_max > y_min:
            raise RollerRigError(f"{func}: y_max must exceed y_min, got {y_min!r}, {y_max!r}")
        if not y_max - y_min <= MAX_SPAN:
            raise RollerRigError(f"{func}: y_max - y_min = {y_max - y_min!r} m, at most "
                                 f"{MAX_SPAN:g} m (a wheelset's lateral shifts)")
        if dy_jump is not None:
            dy_jump = check_number(func, "dy_jump", dy_jump, positive=True)
        # bounded before any is made: a tiny step asked for rows without end
        count = (y_max - y_min) / dy + (0.0 if dy_jump is None else 2 * JUMP_ZONE / dy_jump)
        if not count <= MAX_ROWS:
            raise RollerRigError(f"{func}: dy = {dy!r} m, dy_jump = {dy_jump!r} m would make "
                                 f"{count:.3g} rows a side, at most {MAX_ROWS} (give larger "
                                 f"steps)")
    G = E / (2.0 * (1.0 + nu))
    t0 = time.perf_counter()
    out: Dict[str, Optional[NonHertzSide]] = {}
    for side in ("left", "right"):
        if side not in sides:
            out[side] = None
            continue
        if y is not None:
            ys = np.unique(np.asarray(y, dtype=float))
        else:
            assert y_min is not None and y_max is not None    # checked above, y None
            ys = row_shifts(geometry, y_min, y_max, dy, side, dy_jump)
        if ys.size < 2 or not np.all(np.isfinite(ys)):
            raise RollerRigError(f"{func}: at least two finite rows are needed, got {ys!r:.80}")
        if ys.size > MAX_ROWS:
            raise RollerRigError(f"{func}: {ys.size} rows a side, at most {MAX_ROWS}")
        with ThreadPoolExecutor(max_workers=int(workers)) as ex:
            built = list(ex.map(lambda v: _row(geometry, side, float(v), Fz, E, nu, mu_ref, n,
                                               n_corr, richardson, combine, tol, maxit), ys))
        rows = [r for r, _ in built]
        for v, (_, info) in zip(ys, built):
            # every separate region within the bands is its own patch
            # (rr_nonhertz_table.h); what is not is said here (the main
            # thread), not dropped silently
            if info["excluded"] > 0:
                warnings.warn(f"nonhertz_table: the {side} side at y = {float(v)!r} m: "
                              f"{info['excluded']} interval(s) of the gap touching at the "
                              f"largest load lie farther than combine = {combine!r} m from "
                              f"the row's patches and are not tabulated", RollerRigWarning,
                              stacklevel=2)
            if info["merged"] > 0:
                warnings.warn(f"nonhertz_table: the {side} side at y = {float(v)!r} m: "
                              f"{info['merged'] + _core.NH_MAX_PATCHES} separate regions, "
                              f"at most {_core.NH_MAX_PATCHES} patches a row: "
                              f"{info['merged']} held in a neighbour's patch (its plane)",
                              RollerRigWarning, stacklevel=2)
        out[side] = NonHertzSide(np.ascontiguousarray(np.array(rows)),
                                 1.0 if side == "left" else -1.0, float(geometry.roller_radius),
                                 G, nu, mu_ref).check()
    return NonHertzTable(out["left"], out["right"], Fz, time.perf_counter() - t0)


def _row(geometry: RigGeometry, side: str, y: float, Fz: float, E: float, nu: float,
         mu_ref: float, n: int, n_corr: int, richardson: bool, combine: float, tol: float,
         maxit: int) -> Tuple[F64Array, Dict[str, int]]:
    """One row by the core (rr_nonhertz_row), the GIL released."""
    z0, roll0, p = _pose_and_point("nonhertz_table", geometry, y, side)
    point = tuple(float(getattr(p, k)[0]) for k in ("s_roller", "s_wheel", "delta", "A", "B"))
    # the wheelset's motion at free rolling (rig_contact's at zero yaw and
    # lateral speed: centre (0, y, z0), spin about the rolled axle); the
    # correction's spin creepage depends on the speeds' ratio only
    roller_spin = 10.0
    spin = roller_spin * float(p.R[0]) / float(p.r[0])
    motion = ((0.0, y, z0), (0.0, 0.0, 0.0),
              (0.0, spin * np.cos(roll0), spin * np.sin(roll0)))
    st, row, info = _core.nonhertz_row(
        *geometry._arrays(), geometry._params(), 0 if side == "left" else 1, y, (z0, roll0),
        point, (LOAD_SPAN * Fz, Fz, E, nu, mu_ref), motion, roller_spin, 1e-3,
        (int(n), int(n_corr), int(bool(richardson)), combine), (float(tol), int(maxit)))
    if st < 0:
        what = {_core.NH_ROW_NODE: "the exact solution of a load node",
                _core.NH_ROW_GRID: "a grid of a node or of the row's regions",
                _core.NH_ROW_SOLVE: "a creep solution of a node",
                _core.NH_ROW_COEFF: "a node's linear creep coefficient (not positive)"}
        patch = f"patch {info['patch']}, " if info["patch"] > 0 else ""
        # the patch's reason where a patch failed (a status alone, RR_ERR_RANGE,
        # would read "inputs too extreme"), else the status's
        detail = _GAP_WORDS.get(info["gap_why"], status_message(st))
        raise RollerRigError(f"nonhertz_table: the {side} side at y = {y!r} m, {patch}node "
                             f"{info['node']} (vertical load "
                             f"{LOAD_SPAN * Fz * _NODE_F[max(info['node'], 0)] ** 1.5:.6g} N): "
                             f"{what.get(info['why'], 'the row')} failed: {detail} "
                             f"(rr_wheel_exact why {info['wheel_why']}, rr_gap why "
                             f"{info['gap_why']})")
    return row, info


#: rr_gap_build's reasons in words (geometry.patch._gap_error says them with
#: the numbers a single build leaves; a row keeps only the reason)
_GAP_WORDS = {
    _core.GAP_OFF_PROFILE: "the reference point lies off a profile",
    _core.GAP_FOLD: "a profile folds at the reference point",
    _core.GAP_APART: "the cross-sections do not overlap laterally",
    _core.GAP_REGION_ENDS: "the contact region reaches the end of the profiles in the "
                           "tangent plane",
    _core.GAP_REGION_LONG: "the contact region is as long as the radii",
    _core.GAP_REGION_BEYOND: "the contact region's ends along x lie beyond the profiles",
    _core.GAP_TOO_MANY: "the grid would need more elements a side than it may have",
    _core.GAP_PATCH_REACHES: "the patch reaches where a profile folds or ends",
    _core.GAP_PATCH_NONFINITE: "the gap is not finite on the grid (a profile folds or ends)",
    _core.GAP_RUNS: "the gap has too many separate intervals",
    _core.GAP_WEIGHTS: "the weighted reference's weights vanish or overflow",
    _core.GAP_SCAN: "the cross-sections are far longer than the profiles' window",
    _core.GAP_FAR: "the region lies too many elements from the reference point",
}


_NODE_F = (0.03, 0.1, 0.2, 0.33, 0.46, 0.6, 0.75, 0.88, 1.0)


def nonhertz_wheel(side_table: NonHertzSide, y: float, Fz: float, mu: float,
                   roller_spin: float, motion0: Motion, motion1: Motion, vmin: float = 1e-3,
                   x: float = 0.0,
                   yaw: float = 0.0) -> Tuple[int, Dict[str, Any], Tuple[Dict[str, Any], ...]]:
    """One wheel's contact from a side's table (rr_nonhertz_wheel): (status,
    result dict, patch dicts); motion0/1: ((c), (v), (w)) of the wheelset at
    the rows around y (nonhertz_locate), at the longitudinal shift x and yaw."""
    return _core.nonhertz_wheel(side_table.rows, side_table.head,
                                (float(y), float(Fz), float(mu), float(roller_spin),
                                 float(vmin), float(x), float(yaw)), motion0, motion1)


def nonhertz_locate(side_table: NonHertzSide, y: float) -> Tuple[int, int, float]:
    """(status, row, w): the rows around y."""
    return _core.nonhertz_locate(side_table.rows, side_table.head, float(y))
