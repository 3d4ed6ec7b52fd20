"""The fits' input checks (rollerrig.analysis.fit): the data as 1-D
curves, the scalar arguments, and the parameters fitted, their starts and
bounds, each refusal naming the argument and its value."""
from __future__ import annotations

import math
from typing import (Dict, List, Mapping, NoReturn, Optional, Sequence, Tuple, Union)

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError, check_number
from .._typing import F64Array

_TINY = 1e-6      # stands in for an open lower bound at 0 (all parameters are O(0.1 - 1))
#: Polach's kS is fitted as this ratio, so that kS <= kA holds
_RATIO = "kS/kA"
#: the fitted parameters, {name: (start, lower, upper, lower bound open, upper
#: bound open)}; start None: the data's peak |force| / N
Spec = Mapping[str, Tuple[Optional[float], float, float, bool, bool]]
#: a curve or a list of curves: cx, force or weights as the fits take them
Curves = Union[npt.ArrayLike, Sequence[npt.ArrayLike]]


def _fail(func: str, msg: str) -> NoReturn:
    raise RollerRigError(f"{func}: {msg}")


def _curve_array(func: str, name: str, value: object) -> F64Array:
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        _fail(func, f"{name} must be real numbers, got {value!r:.60}")
    if arr.ndim != 1:
        _fail(func, f"{name} must be one-dimensional, got shape {arr.shape}")
    if arr.size == 0:
        _fail(func, f"{name} is empty")
    bad = np.flatnonzero(~np.isfinite(arr))
    if bad.size:
        i = int(bad[0])
        _fail(func, f"{name}[{i}] = {float(arr[i])!r} is not finite")
    return arr


def _curves(func: str, name: str, value: object) -> Tuple[List[F64Array], bool]:
    """A list of 1-D float arrays and whether the input was a list of curves."""
    if isinstance(value, (list, tuple)) and value and all(
            isinstance(v, (list, tuple, np.ndarray)) for v in value):
        return [_curve_array(func, f"{name}[{k}]", v) for k, v in enumerate(value)], True
    if isinstance(value, (list, tuple)) and not value:
        _fail(func, f"{name} is empty")
    return [_curve_array(func, name, value)], False


def _data(func: str, cx: object, force: object, speed: object, weights: object
          ) -> Tuple[List[F64Array], List[F64Array], F64Array, List[F64Array], bool]:
    """The curves cx, force and weights (ones by default), and the speed per
    curve; whether the data were a list of curves."""
    cxs, many = _curves(func, "cx", cx)
    fs, many_f = _curves(func, "force", force)
    if many != many_f or len(cxs) != len(fs):
        _fail(func, f"cx has {len(cxs) if many else 'one'} curve(s) but force has "
                    f"{len(fs) if many_f else 'one'}")
    for k, (c, f) in enumerate(zip(cxs, fs)):
        tag = f"[{k}]" if many else ""
        if c.size != f.size:
            _fail(func, f"force{tag} has {f.size} points but cx{tag} has {c.size}")
    n = len(cxs)
    sp = np.asarray(speed, dtype=float) if speed is not None else None
    if sp is None or sp.ndim > 1 or (sp.ndim == 1 and sp.size != n):
        _fail(func, f"speed must be a scalar or one value per curve ({n}), got {speed!r}")
    sp = np.broadcast_to(sp, (n,)).astype(float)
    for k, v in enumerate(sp):
        if not (np.isfinite(v) and v > 0.0):
            tag = f"[{k}]" if sp.size > 1 else ""
            _fail(func, f"speed{tag} must be > 0, got {float(v)!r}")
    if weights is None:
        ws = [np.ones_like(c) for c in cxs]
    else:
        ws, many_w = _curves(func, "weights", weights)
        if many_w != many or len(ws) != n:
            _fail(func, "weights must have the shape of cx (one array per curve)")
        for k, (w, c) in enumerate(zip(ws, cxs)):
            tag = f"[{k}]" if many else ""
            if w.size != c.size:
                _fail(func, f"weights{tag} has {w.size} points but cx{tag} has {c.size}")
            if np.any(w < 0) or not np.any(w > 0):
                _fail(func, f"weights{tag} must be >= 0 and not all 0, got {w!r:.60}")
    return cxs, fs, sp, ws, many


def _interval(lo: float, hi: float, lo_open: bool, hi_open: bool) -> str:
    return f"{'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}"


def _in(v: float, lo: float, hi: float, lo_open: bool, hi_open: bool) -> bool:
    return (v > lo if lo_open else v >= lo) and (v < hi if hi_open else v <= hi)


def _setup(func: str, spec: Spec, fit: Union[str, Sequence[str]],
           x0: Optional[Mapping[str, float]],
           bounds: Optional[Mapping[str, Tuple[float, float]]], mu0_default: float
           ) -> Tuple[Dict[str, float], Tuple[str, ...], List[str], F64Array, F64Array]:
    """Natural start values, the internal names fitted and their bounds."""
    names = tuple(spec)
    if isinstance(fit, str):
        fit = (fit,)
    fit = tuple(fit)
    if not fit:
        _fail(func, "fit names no parameter")
    for n in fit:
        if n not in spec:
            _fail(func, f"unknown parameter {n!r} in fit; choose from {names}")
    if len(set(fit)) != len(fit):
        _fail(func, f"fit names a parameter twice: {fit!r}")
    fit = tuple(n for n in names if n in fit)          # the model's order
    x0 = {} if x0 is None else dict(x0)
    for n, v in x0.items():
        if n not in spec:
            _fail(func, f"unknown parameter {n!r} in x0; choose from {names}")
        check_number(func, f"x0[{n!r}]", v)
    start: Dict[str, float] = {}
    for n, (default, lo, hi, lo_open, hi_open) in spec.items():
        v = float(x0.get(n, mu0_default if default is None else default))
        if not _in(v, lo, hi, lo_open, hi_open):
            _fail(func, f"x0[{n!r}] = {v!r} is outside {_interval(lo, hi, lo_open, hi_open)}")
        start[n] = v
    if "kS" in spec and start["kS"] > start["kA"]:
        _fail(func, f"x0['kS'] = {start['kS']!r} is above x0['kA'] = {start['kA']!r}; "
                    "Polach's method needs kS <= kA")

    # internal variables: kS is fitted as the ratio kS/kA
    inner = [(_RATIO if n == "kS" else n) for n in fit]
    bounds = {} if bounds is None else dict(bounds)
    for n in bounds:
        if n == "kS":
            _fail(func, "bounds: kS is fitted as the ratio kS/kA; bound 'kS/kA' instead")
        if n not in inner:
            _fail(func, f"bounds given for {n!r}, which is not fitted ({inner})")
    lo_v: List[float] = []
    hi_v: List[float] = []
    for n in inner:
        if n == _RATIO:
            lo, hi, lo_open, hi_open = 0.0, 1.0, True, False
            v0 = start["kS"] / start["kA"]
        else:
            _, lo, hi, lo_open, hi_open = spec[n]
            v0 = start[n]
        if n == "kA" and "kS" not in fit:           # kS held: kA >= kS keeps the order
            lo, lo_open = start["kS"], False
        if n in bounds:
            try:
                blo, bhi = (float(x) for x in bounds[n])
            except (TypeError, ValueError):
                _fail(func, f"bounds[{n!r}] must be (lo, hi), got {bounds[n]!r}")
            if not (blo < bhi) or math.isnan(blo) or math.isnan(bhi):
                _fail(func, f"bounds[{n!r}] = {bounds[n]!r}: need lo < hi")
            if blo > lo or (blo == lo and not lo_open):
                lo, lo_open = blo, False
            if bhi < hi or (bhi == hi and not hi_open):
                hi, hi_open = bhi, False
            if not _in(v0, lo, hi, lo_open, hi_open):
                what = "x0['kS'] / x0['kA']" if n == _RATIO else f"x0[{n!r}]"
                _fail(func, f"{what} = {v0!r} is outside bounds[{n!r}] = "
                            f"{_interval(lo, hi, lo_open, hi_open)}")
        if lo_open:
            lo = max(lo, _TINY) if lo == 0.0 else lo * (1.0 + _TINY) + _TINY
        if lo >= hi:
            _fail(func, f"bounds for {n!r} leave no room: [{lo!r}, {hi!r}]")
        lo_v.append(lo)
        hi_v.append(hi)
    return start, fit, inner, np.array(lo_v), np.array(hi_v)
