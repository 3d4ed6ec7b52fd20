"""Limits of a profile and the checks of its points: numbers, kind, end
conditions, scale (unit mistakes), single-valuedness (folds), and the
preparation of raw points (any order, any folds) for a Profile."""
from __future__ import annotations

import warnings
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

from ..._errors import RollerRigError, RollerRigWarning
from ..._typing import F64Array

KINDS = ("wheel", "rail")  #: a profile's kinds (a roller is a "rail")
BCS = ("not-a-knot", "natural")  #: the spline's end conditions
MIN_POINTS = 4  #: fewest points of a profile
MIN_SPACING = 1e-12  #: [m] closer points are a mistake (measured profiles: 1e-9 at least)
MAX_POINTS = 100_000   #: more points than any measured profile has (MiniProf: ~1000)
MAX_COORD = 2.0     #: [m] larger coordinates are taken for a unit mistake
MIN_WIDTH = 1e-3    #: [m] a narrower profile is taken for a unit mistake
UNITS = {"m": 1.0, "cm": 1e-2, "mm": 1e-3}     # metres per unit

#: the labels of a profile's points in messages: (the line or index of each
#: point, "line" / "index" / "point")
Labels = Tuple[npt.NDArray[np.integer[Any]], str]


def _as_float_array(func: str, name: str, value: npt.ArrayLike) -> F64Array:
    arr = np.asarray(value)
    if arr.dtype.kind not in "iuf":
        raise RollerRigError(f"{func}: {name} must be real numbers, got dtype {arr.dtype} "
                             f"({value!r:.60})")
    return arr.astype(np.float64)


def _check_kind(func: str, kind: str) -> str:
    if kind not in KINDS:
        raise RollerRigError(f"{func}: kind must be 'wheel' or 'rail' (a roller is 'rail'), "
                             f"got {kind!r}")
    return kind


def _check_bc(func: str, bc: Optional[str], smoothing: Optional[float]) -> str:
    if bc is None:
        return "natural" if smoothing is not None else "not-a-knot"
    if bc not in BCS:
        raise RollerRigError(f"{func}: bc must be 'not-a-knot', 'natural' or None, got {bc!r}")
    if smoothing is not None and bc != "natural":
        raise RollerRigError(f"{func}: a smoothing spline is natural: bc = {bc!r} cannot go "
                             f"with smoothing = {smoothing!r} (leave bc = None)")
    return bc


def _label(labels: Labels, i: Union[int, np.integer[Any]]) -> str:
    """'line 12' (files) or 'point 12' (arrays) for point i."""
    return f"{labels[1]} {labels[0][i]}"


def _check_scale(where: str, y: F64Array, z: F64Array, labels: Labels) -> None:
    big = np.abs(np.concatenate([y, z]))
    k = int(np.argmax(big))
    if big[k] > MAX_COORD:
        i = k % len(y)
        raise RollerRigError(
            f"{where}: coordinate {big[k]:.6g} m at {_label(labels, i)} is beyond "
            f"{MAX_COORD:g} m: the numbers look like millimetres read as metres (units='mm')")
    width = float(y.max() - y.min())
    if width < MIN_WIDTH:
        raise RollerRigError(
            f"{where}: the profile's y spans only {width:.3g} m (< {MIN_WIDTH * 1e3:g} mm): "
            f"the numbers look like metres read as millimetres (units='m')")


def _single_valued(where: str, y: F64Array, z: F64Array, kind: str, labels: Labels,
                   on_fold: str) -> Tuple[npt.NDArray[np.bool_], str]:
    """Keep the single-valued branch through the running surface.

    y, z in the profile's (ascending) order.  Returns the boolean mask of the
    points kept and a description of the folds removed.  Raises on a pure
    duplicate, and on any fold when on_fold == 'raise'.
    """
    n = len(y)
    anchor = int(np.argmin(z)) if kind == "rail" else int(np.argmax(z))
    keep = np.zeros(n, dtype=bool)
    keep[anchor] = True
    runs: List[Tuple[List[int], float]] = []       # (indices, extreme y before the run)
    for step, indices in ((1, range(anchor + 1, n)), (-1, range(anchor - 1, -1, -1))):
        ext: float = y[anchor]
        run: List[int] = []
        for i in indices:
            if step * (y[i] - ext) > 0.0:
                if run:
                    runs.append((run, ext))
                    run = []
                keep[i] = True
                ext = y[i]
            else:
                run.append(i)
        if run:
            runs.append((run, ext))
    for run, ext in runs:
        if np.all(y[run] == ext):
            i = run[0]
            j = i - 1 if i > anchor else i + 1
            a, b = sorted((i, j))
            raise RollerRigError(
                f"{where}: duplicate y = {y[i]:.9g} m at {_label(labels, a)} and "
                f"{_label(labels, b)}: z(y) would be two-valued; remove one point")
    if not runs:
        return keep, ""
    dropped = np.flatnonzero(~keep)
    first = min(dropped, key=lambda i: labels[0][i])
    desc = (f"{len(dropped)} point(s) where the profile folds back (y steps back at "
            f"{_label(labels, first)}), y {y[dropped].min() * 1e3:.4g} .. "
            f"{y[dropped].max() * 1e3:.4g} mm, z {z[dropped].min() * 1e3:.4g} .. "
            f"{z[dropped].max() * 1e3:.4g} mm")
    if on_fold == "raise":
        raise RollerRigError(f"{where}: {desc}; pass on_fold='trim' to keep the "
                             f"single-valued branch through the running surface")
    return keep, desc


def _prepare(where: str, y: F64Array, z: F64Array, kind: str, labels: Labels, on_fold: str,
             mirror_y: bool = False,
             mirror_z: bool = False) -> Tuple[F64Array, F64Array, Dict[str, Any]]:
    """From raw points in metres (file order) to ascending, single-valued
    points.  Returns (y, z, notes dict)."""
    if on_fold not in ("trim", "raise"):
        raise RollerRigError(f"{where}: on_fold must be 'trim' or 'raise', got {on_fold!r}")
    n = len(y)
    bad = np.flatnonzero(~(np.isfinite(y) & np.isfinite(z)))
    if bad.size:
        i = int(bad[0])
        raise RollerRigError(f"{where}: non-finite value (y = {y[i]!r}, z = {z[i]!r}) at "
                             f"{_label(labels, i)}")
    if n < MIN_POINTS:
        raise RollerRigError(f"{where}: {n} point(s); a profile needs at least {MIN_POINTS}")
    if mirror_y:
        y = -y
    if mirror_z:
        z = -z
    _check_scale(where, y, z, labels)
    notes: Dict[str, Any] = {}
    if y[-1] < y[0]:
        y, z = y[::-1], z[::-1]
        labels = (labels[0][::-1], labels[1])
        notes["order"] = "reversed to ascending y"
    keep, desc = _single_valued(where, y, z, kind, labels, on_fold)
    if desc:
        warnings.warn(f"{where}: removed {desc}", RollerRigWarning, stacklevel=3)
        notes["folds_removed"] = int((~keep).sum())
        y, z = y[keep], z[keep]
    if len(y) < MIN_POINTS:
        raise RollerRigError(f"{where}: {len(y)} point(s) left after removing the folds; "
                             f"a profile needs at least {MIN_POINTS}")
    return np.ascontiguousarray(y), np.ascontiguousarray(z), notes
