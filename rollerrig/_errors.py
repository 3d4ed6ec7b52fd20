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


# Which arguments each error status is about, to name them in messages.
_STATUS_ARGS = {
    -2: ("N",),
    -3: ("A", "B", "a", "b", "a_over_b"),
    -4: ("E", "nu", "E2", "nu2", "G"),
    -5: ("mu", "friction.A", "friction.B"),
    -7: ("speed",),
}


def _culprits(code, args, index):
    """'name = value' for the arguments that explain status `code` at `index`."""
    found = []
    for name, arr in args.items():
        value = arr.reshape(-1)[index if arr.size > 1 else 0]
        if code == -1:
            bad = not np.isfinite(value)
        else:
            bad = name in _STATUS_ARGS.get(code, ())
        if bad:
            found.append(f"{name} = {float(value)!r}")
    return ", ".join(found) or "(options)"


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
