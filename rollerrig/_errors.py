"""The package's error and warning types and the one place where C status
codes become exceptions or warnings."""
from __future__ import annotations

import math
import warnings
from typing import Callable, Dict, Iterable, Literal, Mapping, Optional, overload

import numpy as np
import numpy.typing as npt

from . import _core


class RollerRigError(ValueError):
    """Invalid input or a failed computation; a ValueError.

    The message names the function, the argument and its value (and, for
    an element of an array call, its index and the status message).

    Examples
    --------
    >>> import rollerrig as rr
    >>> try:
    ...     rr.hertz(1.0, 1.0, -5.0)
    ... except rr.RollerRigError as e:
    ...     print(e)
    hertz: N = -5.0: normal load not positive
    """


class RollerRigWarning(UserWarning):
    """A result was computed but is less certain, or some batch elements failed.

    Given once per call (errors="warn", the default for array calls), naming
    the first bad element and how many failed; the failed elements are NaN
    with a negative status.
    """


@overload
def check_number(func: str, name: str, value: object, positive: bool = ...,
                 allow_none: Literal[False] = ...) -> float: ...
@overload
def check_number(func: str, name: str, value: object, positive: bool = ...,
                 allow_none: bool = ...) -> Optional[float]: ...
def check_number(func: str, name: str, value: object, positive: bool = False,
                 allow_none: bool = False) -> Optional[float]:
    """value as a float: a finite real number (not a bool), > 0 where
    positive, None passed where allow_none; else a RollerRigError naming
    func, name and value (the rig's parameters say it in these words too)."""
    if value is None and allow_none:
        return None
    if isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool):
        try:
            v = float(value)
        except OverflowError:                  # an int beyond a double
            v = math.inf
        if math.isfinite(v) and (v > 0 or not positive):
            return v
    raise RollerRigError(f"{func}: {name} must be a finite number"
                         f"{' > 0' if positive else ''}{' or None' if allow_none else ''}"
                         f", got {value!r:.60}")


def status_message(code: int) -> str:
    """The C core's message for a status code.

    Parameters
    ----------
    code : int
        A status: 0 ok, > 0 a warning (the result usable), < 0 an error
        (the result NaN).

    Returns
    -------
    str
        The message ("unknown status" for a code the core does not have).

    See Also
    --------
    rollerrig.STATUS : every code with its message.

    Examples
    --------
    >>> import rollerrig as rr
    >>> rr.status_message(-2)
    'normal load not positive'
    """
    return _core.status_message(int(code))


#: every status code of the C core with its message: 0 ok, > 0 a warning
#: (the result is usable), < 0 an error (the results are NaN)
STATUS: Dict[int, str] = {code: status_message(code)
                          for code in range(_core.STATUS_MIN, _core.STATUS_MAX + 1)}


def _value(arr: npt.NDArray[np.float64], index: int) -> float:
    return float(arr.reshape(-1)[index if arr.size > 1 else 0])


def _culprits(args: Mapping[str, npt.NDArray[np.float64]], index: int,
              blamed: Optional[Iterable[str]] = None) -> str:
    """'name = value' for the arguments at `index` that the C core blamed
    (blamed: names, from its check's report or from the C function itself,
    never from rules restated here; one not in args is named alone, "h"),
    else for every argument."""
    if blamed:
        return ", ".join(f"{n} = {_value(args[n], index)!r}" if n in args else n
                         for n in blamed)
    return ", ".join(f"{n} = {_value(a, index)!r}" for n, a in args.items()) or "(options)"


def check_status(func: str, status: npt.NDArray[np.int8],
                 args: Mapping[str, npt.NDArray[np.float64]], errors: str,
                 blame: Optional[Callable[[int, int], Optional[Iterable[str]]]] = None) -> None:
    """Raise, warn or stay silent for the statuses of a call.

    Parameters
    ----------
    func : str
        The public function's name, for the message.
    status : ndarray of int8
        C statuses, shaped like the result.
    args : dict
        {name: float64 array} of the broadcast inputs, to name culprits.
    errors : {"raise", "warn", "ignore"}
        "raise": any error raises RollerRigError; "warn": errors and
        warnings become one RollerRigWarning (bad elements are NaN);
        "ignore": nothing.
    blame : callable, optional
        blame(flat index, status) -> the names of the arguments the C core
        blames for that element's status (its check's report mapped to the
        call's arguments, or the arguments whose own values give it:
        _binding.swap_blame), or None.
    """
    if errors == "ignore":
        return
    flat = status.reshape(-1)
    bad = np.flatnonzero(flat < 0)
    if bad.size:
        i = int(bad[0])
        code = int(flat[i])
        index = tuple(int(k) for k in np.unravel_index(i, status.shape))
        where = f" at index {index}" if status.ndim else ""
        blamed = blame(i, code) if blame is not None else None
        msg = (f"{func}: {_culprits(args, i, blamed)}{where}: {status_message(code)}"
               + (f" ({bad.size} of {flat.size} elements failed; their results are NaN)"
                  if flat.size > 1 else ""))
        if errors == "raise":
            raise RollerRigError(msg)
        warnings.warn(msg, RollerRigWarning, stacklevel=4)
    warn = np.flatnonzero(flat > 0)
    if warn.size:
        code = int(flat[warn[0]])
        warnings.warn(f"{func}: {status_message(code)} ({warn.size} of {flat.size} elements)",
                      RollerRigWarning, stacklevel=4)
