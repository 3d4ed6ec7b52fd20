"""The plain assertions: assert_fields_close (any labelled array set),
assert_history_close (a simulate result), assert_creep_curve_close (creep
forces over a creepage axis)."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import math
import os
import warnings

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError
from .._units import cf_unit
from . import _compare
from ._compare import DEFAULT_ATOL, DEFAULT_RTOL, Fields

if TYPE_CHECKING:
    from ._compare import FieldDeviation

#: a path as the functions take it (a reference file, a figure)
_Path = Union[str, "os.PathLike[str]"]


class RegressionError(AssertionError):
    """Data differ from their reference: the message names each field, its
    first and worst deviation; .deviations holds them
    (rollerrig.testing.FieldDeviation), .figure the comparison figure's
    path (None: .figure_note says why there is none)."""

    def __init__(self, message: str, deviations: List[FieldDeviation],
                 figure: Optional[str] = None, figure_note: Optional[str] = None) -> None:
        super().__init__(message)
        self.deviations, self.figure, self.figure_note = deviations, figure, figure_note


def history_fields(result: Any, fields: Optional[Sequence[str]] = None,
                   window: Optional[float] = None) -> Tuple[Fields, Dict[str, str]]:
    """({name: column}, {name: unit}) of a simulate result (RigResult): the
    record's fields (rollerrig.rig.RECORD_FIELDS), or those of `fields`.

    window: None, every kept sample; or a length of time [s], a whole
    number of the records' spacing (record_every dt): the means over
    consecutive windows of that length (NaN ignored, a window all NaN gives
    NaN; "time" the mean time of the window; a last, shorter window is left
    out).  The rig's history is sensitive sample by sample -- its encoders
    count whole lines, and a change in the 16th digit anywhere (another
    libm) flips a count at some sample, which the controllers answer --
    while means over a second are not: docs/testing.md gives the figures."""
    from ..rig.result import RECORD_FIELDS, RECORD_UNITS
    if not hasattr(result, "records") or not hasattr(result, "params"):
        raise RollerRigError(f"a simulate result (RigResult) is needed, got "
                             f"{type(result).__name__}")
    names = list(RECORD_FIELDS) if fields is None else list(fields)
    unknown = [n for n in names if n not in RECORD_FIELDS]
    if unknown or not names:
        raise RollerRigError(f"fields must name record fields (rollerrig.rig.RECORD_FIELDS), "
                             f"got {unknown or names!r}")
    records = np.asarray(result.records)
    if window is not None:
        records = _window_means(records, window, result.record_dt)
    cols = {n: records[:, RECORD_FIELDS.index(n)] for n in names}
    return cols, {n: cf_unit(RECORD_UNITS[n]) for n in names}


def _window_means(records: npt.NDArray[Any], window: Any,
                  spacing: float) -> npt.NDArray[Any]:
    try:
        w = float(window)
    except (TypeError, ValueError):
        w = math.nan
    k = round(w / spacing) if math.isfinite(w) and w > 0 else 0
    if k < 1 or abs(k * spacing - w) > 1e-9 * w:
        raise RollerRigError(f"window must be a whole number (>= 1) of the records' spacing "
                             f"{spacing:g} s (record_every dt), got {window!r:.40}")
    n = len(records) // k
    if n == 0:
        raise RollerRigError(f"window = {w:g} s is longer than the history "
                             f"({len(records) * spacing:g} s)")
    blocks = records[:n * k].reshape(n, k, records.shape[1])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)     # a window all NaN: NaN
        means: npt.NDArray[Any] = np.nanmean(blocks, axis=1)
    return means


#: the creep forces' units (rollerrig.creep_forces: fx, fy [N], mz [N m])
CREEP_UNITS = {"fx": "N", "fy": "N", "mz": "N m", "status": "1"}


def creep_curve_fields(creepage: npt.ArrayLike, forces: Any,
                       creepage_name: str = "creepage") -> Tuple[Fields, Dict[str, str]]:
    """({name: array}, units) of a creep curve: the creepage axis, then the
    forces (a rollerrig.CreepForces, or a mapping such as {"fx": ...})."""
    if hasattr(forces, "_asdict"):
        forces = forces._asdict()
    if not hasattr(forces, "items"):
        raise RollerRigError(f"forces must be a rollerrig.CreepForces or a mapping name -> "
                             f"array, got {type(forces).__name__}")
    fields = {creepage_name: np.asarray(creepage)}
    fields.update({str(k): np.asarray(v) for k, v in forces.items()})
    units = {k: CREEP_UNITS.get(k, "") for k in fields}
    units[creepage_name] = "1"
    return fields, units


def _reference(func: str, expected: Any) -> Tuple[Any, Mapping[str, str]]:
    """A mapping of the expected data: as given, or read from a reference
    file (NAME.npz written by the plugin)."""
    if isinstance(expected, (str, os.PathLike)):
        from ._store import read_reference
        path = os.fspath(expected)
        base = path[:-4] if path.endswith(".npz") else path
        got = read_reference(base)
        if got is None:
            raise RollerRigError(f"{func}: expected {path}: no such reference file")
        return got[0], got[1].get("units", {})
    return expected, {}


def assert_fields_close(actual: Mapping[str, npt.ArrayLike],
                        expected: Union[Mapping[str, npt.ArrayLike], _Path], *,
                        rtol: float = DEFAULT_RTOL, atol: float = DEFAULT_ATOL,
                        tolerances: Optional[Mapping[str, Mapping[str, float]]] = None,
                        units: Optional[Mapping[str, str]] = None, x: Optional[str] = None,
                        figure: Optional[_Path] = None, where: str = "the reference",
                        func: str = "assert_fields_close") -> None:
    """Assert that two labelled array sets ({name: array}) agree field by
    field, each value within atol + rtol |expected| (numpy.isclose's rule;
    NaN equals NaN).  tolerances: {field: {"rtol": ..., "atol": ...}} over
    the defaults; units {field: unit} for the message; x: the field that is
    the abscissa (the message says where on it a deviation is); figure: a
    PNG path for the comparison figure on failure (None: none drawn).
    Raises RegressionError (an AssertionError) naming every differing
    field, its first and worst deviation with the values on both sides."""
    expected, stored_units = _reference(func, expected)
    got = _compare.as_fields(func, "actual", actual)
    ref = _compare.as_fields(func, "expected", expected)
    tol = _compare.field_tolerances(func, list(dict.fromkeys([*ref, *got])), rtol, atol,
                                    tolerances)
    units = {**stored_units, **(units or {})}
    deviations = _compare.compare(got, ref, tol, units)
    if not deviations:
        return
    xs = None
    if x is not None and x in ref and ref[x].ndim == 1:
        xs = ref[x]
    x_unit = units.get(x) if x is not None else None
    message = _compare.describe(deviations, len(tol), where, xs, x, x_unit)
    path: Optional[str] = None
    note: Optional[str] = None
    if figure is not None:
        from ..plot._regression import figure as draw
        path, note = draw(os.fspath(figure), deviations, got, ref, xs, x, x_unit,
                          title=f"{func}: this run against {where}")
        message += f"\ncomparison figure: {path}" if path else f"\n{note}"
    raise RegressionError(message, deviations, path, note)


def assert_history_close(actual: Any, expected: Any, *, fields: Optional[Sequence[str]] = None,
                         window: Optional[float] = None, rtol: float = DEFAULT_RTOL,
                         atol: float = DEFAULT_ATOL,
                         tolerances: Optional[Mapping[str, Any]] = None,
                         figure: Any = None) -> None:
    """Assert that a simulate result's history agrees with an expected one:
    a RigResult, a mapping {field: column} or the path of a reference .npz
    (the plugin's).  fields: the record fields compared (default all);
    window: compare means over windows of that many seconds
    (history_fields); rtol, atol, tolerances, figure: as
    assert_fields_close.  A failure names the field, the time of its first
    and worst deviation and the values on both sides."""
    func = "assert_history_close"
    got, units = history_fields(actual, fields, window)
    if hasattr(expected, "records"):
        expected = history_fields(expected, fields, window)[0]
    elif fields is not None and not isinstance(expected, (str, os.PathLike)):
        expected = {k: v for k, v in expected.items() if k in set(fields)}
    elif fields is not None:
        ref, _ = _reference(func, expected)
        expected = {k: v for k, v in ref.items() if k in set(fields)}
    assert_fields_close(got, expected, rtol=rtol, atol=atol, tolerances=tolerances,
                        units=units, x="time", figure=figure, func=func)


def assert_creep_curve_close(creepage: npt.ArrayLike, actual: Any, expected: Any, *,
                             rtol: float = DEFAULT_RTOL, atol: float = DEFAULT_ATOL,
                             tolerances: Optional[Mapping[str, Mapping[str, float]]] = None,
                             figure: Optional[_Path] = None,
                             creepage_name: str = "creepage") -> None:
    """Assert that creep forces over a creepage axis (`actual`: a
    rollerrig.CreepForces or a mapping {"fx": ...}) agree with `expected`
    (the same kinds, or the path of a reference .npz holding the axis too).
    The message says at which creepage a force first and worst departs."""
    func = "assert_creep_curve_close"
    got, units = creep_curve_fields(creepage, actual, creepage_name)
    if isinstance(expected, (str, os.PathLike)):
        expected, _ = _reference(func, expected)
    else:
        expected = creep_curve_fields(creepage, expected, creepage_name)[0]
    assert_fields_close(got, expected, rtol=rtol, atol=atol, tolerances=tolerances,
                        units=units, x=creepage_name, figure=figure, func=func)
