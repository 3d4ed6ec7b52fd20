"""The package's error and warning types and the one place where C status
codes become exceptions or warnings."""
import warnings

import numpy as np

from . import _core


class RollerRigError(ValueError):
    """Invalid input or a failed computation; a ValueError."""


class RollerRigWarning(UserWarning):
    """A result was computed but is less certain, or some batch elements failed."""


def status_message(code):
    """The C core's message for a status code."""
    return _core.status_message(int(code))


#: every status code of the C core with its message: 0 ok, > 0 a warning
#: (the result is usable), < 0 an error (the results are NaN)
STATUS = {code: status_message(code) for code in range(_core.STATUS_MIN, _core.STATUS_MAX + 1)}


def _positive(v):
    return v > 0.0


def _poisson(v):
    return 0.0 <= v <= 0.5


def _moderate(v):
    """Not among the values that push a result out of floating-point range."""
    return v == 0.0 or 1e-30 <= abs(v) <= 1e30


# For each error status, the arguments it may be about and the test their
# values must pass; a message names those that fail it.
_STATUS_ARGS = {
    -2: {"N": _positive, "N_left": _positive, "N_right": _positive},
    -3: {**{n: _positive for n in ("A", "B", "a", "b", "a_over_b")},
         "y_ws": lambda v: False,      # a shift that puts a wheel off its roller
         "y": lambda v: False, "x": lambda v: False},
    -4: {"E": _positive, "E2": _positive, "G": _positive, "nu": _poisson, "nu2": _poisson},
    -5: {"mu": _positive, "friction.A": lambda v: 0.0 < v <= 1.0,
         "friction.B": lambda v: v >= 0.0},
    -7: {"speed": _positive},
    # outside the exact-theory table: the semi-axes and nu together decide
    -14: {"a": lambda v: False, "b": lambda v: False, "nu": lambda v: False},
}
# a result out of range: any argument may share the blame; name the extreme ones
_RANGE = -12


def _culprits(code, args, index):
    """'name = value' for the arguments that explain status `code` at `index`."""
    found, group = [], []
    for name, arr in args.items():
        value = float(arr.reshape(-1)[index if arr.size > 1 else 0])
        test = _moderate if code == _RANGE else _STATUS_ARGS.get(code, {}).get(name)
        if code == -1 or test is not None:
            group.append(f"{name} = {value!r}")
        if (code == -1 and not np.isfinite(value)) or (test is not None and not test(value)):
            found.append(f"{name} = {value!r}")
    return ", ".join(found or group) or "(options)"


def check_status(func, status, args, errors):
    """Raise, warn or stay silent for the statuses of a call.

    func:   the public function's name, for the message
    status: int8 array of C statuses, shaped like the result
    args:   {name: float64 array} of the broadcast inputs, to name culprits
    errors: "raise" (any error raises RollerRigError), "warn" (errors and
            warnings become one RollerRigWarning; bad elements are NaN) or
            "ignore".
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
        msg = (f"{func}: {_culprits(code, args, i)}{where}: {status_message(code)}"
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
