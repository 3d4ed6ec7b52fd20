"""Field-by-field comparison of two labelled array sets, and the message a
failure gives: which field, how many values, the first and the worst
deviation with the value on both sides and the tolerance it broke.

Closeness is numpy.isclose's: |got - ref| <= atol + rtol |ref| (the
reference's magnitude: a reference is the fixed side); NaN equals NaN and
an infinity the same infinity, so a history's "not yet defined" NaN (the
creepage target before the first target, a speed reference while a torque
is commanded) compares as the value it is.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError

#: a labelled array set as compared: {name: float or integer ndarray}
Fields = Dict[str, npt.NDArray[Any]]
#: {name: (rtol, atol)} of every field
Tolerances = Dict[str, Tuple[float, float]]

#: the tolerance of a field not named in `tolerances`: agreement to about
#: nine significant digits, far above a double's rounding (1e-16) and far
#: below any change of a parameter a user makes on purpose
DEFAULT_RTOL = 1e-9
DEFAULT_ATOL = 0.0

#: fields described with their worst deviation too; those after it in a line
MAX_DETAILED = 8


@dataclass(frozen=True)
class FieldDeviation:
    """How one field differs from its reference.

    problem:  set when the field cannot be compared value by value (missing
              on one side, another shape); then the counts are 0
    bad:      values outside the tolerance, of `size`
    first, worst: the index (a tuple) of the first value outside, and of
              the one furthest outside (largest |got - ref| / allowed)
    """
    name: str
    unit: str
    rtol: float
    atol: float
    problem: Optional[str] = None
    bad: int = 0
    size: int = 0
    first: Tuple[int, ...] = ()
    worst: Tuple[int, ...] = ()
    got_first: float = math.nan
    ref_first: float = math.nan
    got_worst: float = math.nan
    ref_worst: float = math.nan


def _number(what: str, value: Any) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise RollerRigError(f"{what} must be a number >= 0, got {value!r:.60}") from None
    if not math.isfinite(v) or v < 0:
        raise RollerRigError(f"{what} must be a finite number >= 0, got {value!r:.60}")
    return v


def field_tolerances(func: str, names: Sequence[str], rtol: Any, atol: Any,
                     tolerances: object) -> Tolerances:
    """{name: (rtol, atol)} for every field: `tolerances` ({field: {"rtol":
    ..., "atol": ...}}, either key optional) over the defaults rtol, atol.
    A field named in `tolerances` that the data lacks is refused (a typo
    would otherwise loosen nothing, silently)."""
    rtol = _number(f"{func}: rtol", rtol)
    atol = _number(f"{func}: atol", atol)
    tolerances = {} if tolerances is None else tolerances
    if not isinstance(tolerances, dict):
        raise RollerRigError(f"{func}: tolerances must be a dict field -> "
                             f"{{'rtol': ..., 'atol': ...}}, got {type(tolerances).__name__}")
    unknown = sorted(set(tolerances) - set(names))
    if unknown:
        raise RollerRigError(f"{func}: tolerances names {', '.join(map(repr, unknown))}, "
                             f"which the data does not hold (its fields: {', '.join(names)})")
    out: Tolerances = {}
    for name in names:
        given = tolerances.get(name, {})
        if not isinstance(given, dict) or set(given) - {"rtol", "atol"}:
            raise RollerRigError(f"{func}: tolerances[{name!r}] must be a dict with keys "
                                 f"'rtol' and/or 'atol', got {given!r:.60}")
        out[name] = (_number(f"{func}: tolerances[{name!r}]['rtol']", given.get("rtol", rtol)),
                     _number(f"{func}: tolerances[{name!r}]['atol']", given.get("atol", atol)))
    return out


def as_fields(func: str, what: str, data: object) -> Fields:
    """`data` (a mapping name -> array-like) as {name: float or integer
    ndarray}, checked: names non-empty strings without '/' (they are file
    names inside the .npz), values numeric, not empty."""
    if not hasattr(data, "items"):
        raise RollerRigError(f"{func}: {what} must be a mapping field name -> array, got "
                             f"{type(data).__name__}")
    out: Fields = {}
    for name, value in data.items():
        if not isinstance(name, str) or not name or "/" in name or name.startswith("__"):
            raise RollerRigError(f"{func}: {what}: field names must be non-empty strings "
                                 f"without '/' and not starting with '__', got {name!r}")
        arr = np.asarray(value)
        if arr.dtype.kind == "b":
            arr = arr.astype(np.int8)
        if arr.dtype.kind not in "iuf":
            raise RollerRigError(f"{func}: {what}[{name!r}] must hold real numbers, got dtype "
                                 f"{arr.dtype}")
        out[name] = arr
    if not out:
        raise RollerRigError(f"{func}: {what} holds no field")
    return out


def deviation(name: str, unit: str, got: npt.NDArray[Any], ref: npt.NDArray[Any],
              rtol: float, atol: float) -> FieldDeviation:
    """FieldDeviation of one field (bad == 0 and no problem: it agrees)."""
    if got.shape != ref.shape:
        return FieldDeviation(name, unit, rtol, atol,
                              problem=f"shape {got.shape}, the reference's {ref.shape}")
    g, r = got.astype(float).ravel(), ref.astype(float).ravel()
    same = (g == r) | (np.isnan(g) & np.isnan(r))
    with np.errstate(invalid="ignore", over="ignore"):
        diff = np.abs(g - r)
        allowed = atol + rtol * np.abs(r)
        close = same | (diff <= allowed)
    bad = np.flatnonzero(~close)
    if bad.size == 0:
        return FieldDeviation(name, unit, rtol, atol, size=g.size)
    # the worst: a NaN or infinity on one side only first, then the largest
    # excess over what is allowed (allowed 0: the largest difference)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        score = np.where(np.isfinite(diff[bad]), diff[bad] / np.where(allowed[bad] > 0,
                                                                      allowed[bad], 1.0), np.inf)
    worst = bad[int(np.argmax(np.nan_to_num(score, nan=np.inf)))]
    first = bad[0]

    def index(i: np.intp) -> Tuple[int, ...]:
        return tuple(int(k) for k in np.unravel_index(i, got.shape))
    return FieldDeviation(name, unit, rtol, atol, bad=int(bad.size), size=int(g.size),
                          first=index(first), worst=index(worst), got_first=float(g[first]),
                          ref_first=float(r[first]), got_worst=float(g[worst]),
                          ref_worst=float(r[worst]))


def compare(got: Mapping[str, npt.NDArray[Any]], ref: Mapping[str, npt.NDArray[Any]],
            tol: Mapping[str, Tuple[float, float]],
            units: Optional[Mapping[str, str]] = None) -> List[FieldDeviation]:
    """[FieldDeviation] of every field that differs, in the reference's
    order, then the fields only `got` holds.  tol: {name: (rtol, atol)}."""
    units = units or {}
    out: List[FieldDeviation] = []
    for name in list(ref) + [n for n in got if n not in ref]:
        rtol, atol = tol.get(name, (DEFAULT_RTOL, DEFAULT_ATOL))
        unit = units.get(name, "")
        if name not in got:
            out.append(FieldDeviation(name, unit, rtol, atol,
                                      problem="missing: the reference holds it, the data not"))
        elif name not in ref:
            out.append(FieldDeviation(name, unit, rtol, atol,
                                      problem="new: the data holds it, the reference not"))
        else:
            d = deviation(name, unit, got[name], ref[name], rtol, atol)
            if d.problem or d.bad:
                out.append(d)
    return out


def _value(v: float) -> str:
    return repr(float(v)) if math.isfinite(v) else str(v)


def _at(index: Tuple[int, ...], x: Optional[npt.NDArray[Any]], x_name: Optional[str],
        x_unit: Optional[str]) -> str:
    """Where a value stands: "time = 1.204 s (index 301)", or "index (3, 4)"."""
    where = f"index {index[0]}" if len(index) == 1 else f"index {index}"
    if x is not None and len(index) == 1 and index[0] < len(x):
        unit = f" {x_unit}" if x_unit and x_unit != "1" else ""
        return f"{x_name} = {x[index[0]]:.6g}{unit} ({where})"
    return where


def describe(deviations: Sequence[FieldDeviation], n_fields: int, where: str,
             x: Optional[npt.NDArray[Any]] = None, x_name: Optional[str] = None,
             x_unit: Optional[str] = None) -> str:
    """The failure's text: a line for the whole, then per field its counts,
    first and worst deviations."""
    lines = [f"{len(deviations)} of {n_fields} fields differ from {where}:"]
    for k, d in enumerate(deviations):
        unit = f" [{d.unit}]" if d.unit else ""
        if d.problem:
            lines.append(f"  {d.name}{unit}: {d.problem}")
            continue
        if k >= MAX_DETAILED:                   # the rest in a line each
            lines.append(f"  {d.name}{unit}: {d.bad} of {d.size} outside, first at "
                         f"{_at(d.first, x, x_name, x_unit)}: got {_value(d.got_first)}, "
                         f"reference {_value(d.ref_first)}")
            continue
        lines.append(f"  {d.name}{unit}: {d.bad} of {d.size} values outside rtol = {d.rtol:g}, "
                     f"atol = {d.atol:g}")
        lines.append(f"      first at {_at(d.first, x, x_name, x_unit)}: got "
                     f"{_value(d.got_first)}, reference {_value(d.ref_first)}")
        allowed = d.atol + d.rtol * abs(d.ref_worst) if math.isfinite(d.ref_worst) else d.atol
        lines.append(f"      worst at {_at(d.worst, x, x_name, x_unit)}: got "
                     f"{_value(d.got_worst)}, reference {_value(d.ref_worst)}, "
                     f"|got - reference| = {abs(d.got_worst - d.ref_worst):.3g} "
                     f"(allowed {allowed:.3g})")
    return "\n".join(lines)
