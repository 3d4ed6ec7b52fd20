"""rollerrig.plot's helpers: matplotlib on use, the axes, argument checks."""
from __future__ import annotations

import numbers
from types import ModuleType
from typing import TYPE_CHECKING, Any, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError
from .._optional import require
from .._typing import F64Array

if TYPE_CHECKING:                      # matplotlib is imported on use only
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure, SubFigure

#: an array of matplotlib Axes (dtype object), as the functions return several
AxesArray = npt.NDArray[np.object_]

MM = 1e-3

#: quantity -> (label, unit scale, unit) of traction_field
TRACTION_QUANTITIES = {
    "|p_t|": ("tangential traction |p_t|", 1e-6, "MPa"),
    "px": ("traction px on the wheel", 1e-6, "MPa"),
    "py": ("traction py on the wheel", 1e-6, "MPa"),
    "pn": ("pressure pn", 1e-6, "MPa"),
    "|p_t|/pn": ("traction bound used |p_t| / pn", 1.0, "-"),
    "slip": ("adhesion / slip", 1.0, ""),
}


# ------------------------------------------------------------------ helpers

def _pyplot() -> ModuleType:
    # matplotlib is a dependency of the base install, but may have been left out
    return require("matplotlib.pyplot", "rollerrig.plot", "plot", package="matplotlib")


def _one_axes(func: str, ax: object,
              figsize: Tuple[float, float]) -> Tuple[Union[Figure, SubFigure], Axes, bool]:
    """(figure, axes, made here) for an ax= argument."""
    plt = _pyplot()
    from matplotlib.axes import Axes
    if ax is None:
        fig, made = plt.subplots(figsize=figsize)
        return fig, made, True
    if not isinstance(ax, Axes):
        raise RollerRigError(f"{func}: ax must be a matplotlib Axes or None, "
                             f"got {type(ax).__name__}")
    return ax.figure, ax, False


def _many_axes(func: str, axes: object, n: int, figsize: Tuple[float, float],
               **subplots: Any) -> Tuple[Union[Figure, SubFigure], AxesArray, bool]:
    """(figure, array of n axes, made here) for an axes= argument."""
    plt = _pyplot()
    from matplotlib.axes import Axes
    if axes is None:
        fig, axs = plt.subplots(n, 1, figsize=figsize, squeeze=False, **subplots)
        return fig, axs[:, 0], True
    arr: AxesArray = np.asarray(axes, dtype=object).ravel() if not isinstance(axes, Axes) \
        else np.array([axes], dtype=object)
    if arr.size != n or not all(isinstance(a, Axes) for a in arr):
        raise RollerRigError(f"{func}: axes must be None or {n} matplotlib Axes, got "
                             f"{axes!r:.80}")
    return arr[0].figure, arr, False


def _real_1d(func: str, name: str, value: object) -> F64Array:
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise RollerRigError(f"{func}: {name} must be real numbers, got "
                             f"{type(value).__name__}") from None
    if arr.ndim != 1 or arr.size == 0:
        raise RollerRigError(f"{func}: {name} must be a non-empty 1-D array, got shape "
                             f"{arr.shape}")
    return arr


def _positive(func: str, name: str, value: object) -> float:
    # (numpy's stubs take no numbers.Real, which np.isfinite does take)
    if isinstance(value, bool) or not isinstance(value, numbers.Real) \
            or not np.isfinite(value) or value <= 0:  # type: ignore[call-overload]
        raise RollerRigError(f"{func}: {name} must be a positive number, got {value!r}")
    return float(value)


def _scale(func: str, mu: object, N: object) -> Tuple[float, Optional[str]]:
    """(divisor, text) of the normalisation: mu N, N, or none."""
    if mu is not None and N is None:
        raise RollerRigError(f"{func}: mu given without N; normalising needs both (or N "
                             "alone for force / N)")
    if N is None:
        return 1.0, None
    n = _positive(func, "N", N)
    if mu is None:
        return n, "N"
    return _positive(func, "mu", mu) * n, "(mu N)"


def _ylabel(comp: str, sign: int, norm: Optional[str]) -> str:
    name = ("-" if sign < 0 else "") + comp
    return f"{name} / {norm}" if norm else f"{name} [N]"


def _xscale(cx: F64Array, xscale: Optional[str]) -> str:
    if xscale is None:
        good = cx[np.isfinite(cx)]
        return "log" if good.size and np.all(good > 0) else "linear"
    if xscale not in ("log", "linear"):
        raise RollerRigError(f"xscale must be 'log', 'linear' or None, got {xscale!r}")
    return xscale


def _sign(func: str, sign: object) -> int:
    if sign not in (1, -1):
        raise RollerRigError(f"{func}: sign must be +1 or -1, got {sign!r}")
    return sign
