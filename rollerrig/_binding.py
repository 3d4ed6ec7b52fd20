"""The binding's Python half, shared by every module that calls rollerrig._core:
input conversion and broadcasting, status handling, friction laws, and the
creep-force methods as the C registry lists them (csrc/contact/rr_methods.def).

Private: the public names are re-exported by rollerrig.contact.creep."""
from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType
from typing import (Any, Callable, Dict, Iterable, List, Mapping, NamedTuple, Optional, Sequence,
                    Tuple, TypeVar, Union)

import numpy as np
import numpy.typing as npt

from . import _core
from ._errors import RollerRigError, check_status

_F64 = npt.NDArray[np.float64]
#: blame(flat index, status) -> the names of the blamed arguments, or None
Blame = Callable[[int, int], Optional[List[str]]]
_T = TypeVar("_T")


class OptionInfo(NamedTuple):
    """One option of a creep-force method, from its C descriptor
    (``rollerrig.METHODS[method].options[name]``)."""

    name: str          #: the option's keyword
    type: str          #: "int", "real" or "choice"
    unit: str          #: its unit ("" for a count, a choice or a dimensionless number)
    default: Union[float, int, str]  #: int, float, or a choice's name
    lo: Optional[float]  #: lower end of the valid range (None for a choice)
    hi: Optional[float]  #: upper end of the valid range (None for a choice)
    lo_open: bool      #: True: lo itself excluded
    hi_open: bool      #: True: hi itself excluded
    choices: Tuple[str, ...]  #: a choice's names
    doc: str           #: what the option does

    def describe(self) -> str:
        """The option's valid values as text, as the binding's messages give them."""
        if self.type == "choice":
            return "one of " + ", ".join(repr(c) for c in self.choices)
        kind = "an integer" if self.type == "int" else "a real number"
        return (f"{kind} in {'(' if self.lo_open else '['}{self.lo:g}, {self.hi:g}"
                f"{')' if self.hi_open else ']'}")


class MethodInfo(NamedTuple):
    """A creep-force method of the registry (``rollerrig.METHODS[name]``)."""

    name: str                   #: the method's name, creep_forces' ``method=``
    doc: str                    #: what the method is
    options: Mapping[str, OptionInfo]  #: option name -> OptionInfo, in the descriptor's order
    has_field: bool             #: it has a traction field (fastsim_field)
    saturates: bool             #: it keeps ``|F| <= mu N``
    #: a time-loop method: a case of bounded work, not solved iteratively to a
    #: tolerance (the rig's contact model, rig_contact, takes it)
    in_loop: bool
    coulomb_only: bool          #: it takes Coulomb friction only (no FallingFriction)
    #: the rig steps with it: a time-loop method that saturates (csrc/rig/rr_rig.h,
    #: rr_rig_method_check)
    in_rig: bool
    #: it takes a contact problem on a grid (an undeformed distance, as
    #: exact_solve's); the others the Hertz ellipse only
    takes_grid: bool

    def defaults(self) -> Dict[str, object]:
        """The options' defaults, as a dict option name -> default value."""
        return {n: o.default for n, o in self.options.items()}


#: name -> MethodInfo, in the registry's order (read-only)
METHODS: Mapping[str, MethodInfo] = MappingProxyType({
    name: MethodInfo(name, doc, MappingProxyType({o[0]: OptionInfo(*o) for o in opts}),
                     bool(field), bool(sat), bool(loop), bool(coulomb), bool(rig), bool(grid))
    for name, doc, opts, field, sat, loop, coulomb, rig, grid in _core.METHODS})


def _rst_text(text: str) -> str:
    """Text of the C registry as reStructuredText: its |x| (a norm) and *
    taken as characters, not markup."""
    return text.replace("\\", "\\\\").replace("|", "\\|").replace("*", "\\*").replace("`", "\\`")


def methods_doc() -> str:
    """The methods and their options as a reStructuredText definition list
    (for creep_forces' docstring): a method's name, its doc and a bullet
    per option (name=default [unit]: doc; valid values)."""
    lines = []
    for m in METHODS.values():
        lines.append(f"``{m.name!r}``")
        lines.append(f"    {_rst_text(m.doc)}.")
        if m.options:
            lines.append("")
            for o in m.options.values():
                unit = f" [{o.unit}]" if o.unit else ""
                lines.append(f"    - ``{o.name}={o.default!r}``{unit}: {_rst_text(o.doc)}; "
                             f"{o.describe()}")
        lines.append("")
    return "\n".join(lines).rstrip("\n")


def method_info(func: str, method: object) -> MethodInfo:
    """The MethodInfo of a method name, or RollerRigError naming it."""
    if isinstance(method, str) and method in METHODS:
        return METHODS[method]
    names = ", ".join(repr(k) for k in METHODS)
    raise RollerRigError(f"{func}: method must be one of {names}, got {method!r:.60}")


def loop_method(func: str, method: object) -> MethodInfo:
    """The MethodInfo of a method the rig's time loop can run, else
    RollerRigError saying why and naming the ones it can."""
    info = method_info(func, method)
    if not info.in_loop:
        names = ", ".join(repr(k) for k, m in METHODS.items() if m.in_loop)
        raise RollerRigError(f"{func}: method {method!r} is not a time-loop method (it solves "
                             f"each contact iteratively to a tolerance on a grid, milliseconds "
                             f"to seconds a case: no bound on its work a time step could plan "
                             f"on); the rig runs {names}")
    return info


def rig_method(func: str, method: object) -> MethodInfo:
    """The MethodInfo of a method the rig steps with (in_rig), else
    RollerRigError saying why and naming the ones it steps with."""
    info = loop_method(func, method)
    if not info.in_rig:
        names = ", ".join(repr(k) for k, m in METHODS.items() if m.in_rig)
        raise RollerRigError(f"{func}: method {method!r} has no friction limit (Kalker's linear "
                             f"theory: its force grows past mu N, an adhesion above mu0 the rig "
                             f"would report as measured); the rig runs {names}")
    return info


def core(call: Callable[..., _T], *args: Any, **kwargs: Any) -> _T:
    """A call into _core whose ValueErrors (bad options, named by the binding)
    become RollerRigError."""
    try:
        return call(*args, **kwargs)
    except RollerRigError:
        raise
    except ValueError as e:
        raise RollerRigError(str(e)) from None


def creep_options(func: str, method: object,
                  options: Mapping[str, object]) -> _core.CreepOptions:
    """The method and options parsed and checked once by the binding from
    the registry (RollerRigError naming the method, option, range and
    value), as the _core.CreepOptions its calls take in place of keywords."""
    method_info(func, method)
    return core(_core.check_creep_options, func, dict(options, method=method))


def check_creep_options(func: str, method: object,
                        options: Mapping[str, object]) -> Dict[str, object]:
    """As creep_options; returns the keywords for _core (method= and the
    options given)."""
    creep_options(func, method, options)
    return dict(options, method=method)


# one valid creep-force case, in the order of the binding's arguments (cx, cy,
# cphi, a, b, N, mu, G, nu, speed, friction.A, friction.B): swap_blame's
CREEP_VALID = dict(cx=0.0, cy=0.0, cphi=0.0, a=6e-3, b=4e-3, N=1e4, mu=0.3, G=8.2e10, nu=0.28,
                   speed=1.0, **{"friction.A": 1.0, "friction.B": 0.0})


def creep_blame(opts: _core.CreepOptions, flat: Sequence[_F64]) -> Blame:
    """blame(i, status) for check_status: the argument of a creep-force case
    (as _case names them) that the C core blames for element i's status
    (rr_creep_blame, mapped by the binding), from the CreepOptions opts and
    the case's flat inputs; where it blames no one member (a result out of
    range), those whose own values give the status (swap_blame)."""
    def status_of(*values: float) -> int:
        return _core.creep_forces1(opts, *values)[3]
    swapped = swap_blame(status_of, flat, list(CREEP_VALID), CREEP_VALID)

    def blame(i: int, code: int) -> Optional[List[str]]:
        values = [float(a[i if a.size > 1 else 0]) for a in flat]
        name = _core.creep_blame(opts, *values, code)
        return [name] if name else swapped(i, code)
    return blame


def swap_blame(status_of: Callable[..., int], flat: Sequence[npt.ArrayLike],
               names: Sequence[str], reference: Mapping[str, float]) -> Blame:
    """blame(i, status) for check_status, for a call whose C function reports
    no member: the arguments of element i whose own values give the status,
    found by the C function itself, not by restating its rules: each
    replaced by its value in a valid case (reference: name -> value), one at
    a time; where no single one clears the status (two bad values), all of
    them in turn, then each put back where the status stays cleared without
    it.  ``status_of(*values)`` -> the status of one case (names' order)."""
    def blame(i: int, code: int) -> Optional[List[str]]:
        values = [float(np.reshape(a, -1)[i if np.size(a) > 1 else 0]) for a in flat]
        swapped = [k for k, n in enumerate(names)
                   if status_of(*(reference[n] if j == k else v
                                  for j, v in enumerate(values))) != code]
        if not swapped:
            trial = list(values)
            for k, n in enumerate(names):
                trial[k] = reference[n]
                if status_of(*trial) != code:
                    break
            else:
                return None
            swapped = [j for j in range(k + 1) if values[j] != trial[j]]
            for j in list(swapped[:-1]):
                trial[j] = values[j]
                if status_of(*trial) == code:
                    trial[j] = reference[names[j]]
                else:
                    swapped.remove(j)
        return [names[k] for k in swapped]
    return blame


def used_numbers(method: str, options: Mapping[str, Any]) -> Dict[str, _F64]:
    """The method's real options as 0-d arrays, for messages on failed elements."""
    info = METHODS[method]
    return {n: np.asarray(float(options[n] if options.get(n) is not None else o.default))
            for n, o in info.options.items() if o.type == "real"}


@dataclass(frozen=True)
class FallingFriction:
    """Polach's falling friction law mu(w) = mu [(1 - A) exp(-B w) + A].

    mu is the static coefficient given to :func:`creep_forces` and w the
    slip speed [m/s].  Falling friction needs the rolling speed (``speed``
    > 0 in creep_forces).

    Parameters
    ----------
    A : float, optional
        Ratio of the friction at infinite slip to mu [-], 0 < A <= 1.
    B : float, optional
        Decay rate [s/m], >= 0.

    See Also
    --------
    creep_forces : takes it as ``friction=``.

    Notes
    -----
    Polach (Wear 258, 2005) fits dry rail with about A = 0.4, B = 0.6 s/m
    (the defaults).  A = 1 or B = 0 is Coulomb friction.  The values are
    checked where the law is used (creep_forces: status -5 for A, B out of
    range).

    Examples
    --------
    >>> import rollerrig as rr
    >>> law = rr.FallingFriction(A=0.4, B=0.6)
    >>> law.mu(0.3, [0.0, 1.0]).round(4)
    array([0.3   , 0.2188])
    """

    A: float = 0.4  #: friction at infinite slip over the static mu [-], 0 < A <= 1
    B: float = 0.6  #: decay rate of the friction with the slip speed [s/m], >= 0

    def mu(self, mu0: Union[float, _F64], w: npt.ArrayLike) -> Union[float, _F64]:
        """The friction coefficient [-] at slip speed `w` [m/s] for static value `mu0`.

        Parameters
        ----------
        mu0 : float or array_like
            Static friction coefficient [-].
        w : float or array_like
            Slip speed [m/s].

        Returns
        -------
        ndarray or float
            mu0 [(1 - A) exp(-B w) + A], broadcast over mu0 and w.
        """
        return mu0 * ((1.0 - self.A) * np.exp(-self.B * np.asarray(w, dtype=float)) + self.A)


def _friction(func: str, friction: object, method: Optional[str] = None) -> Tuple[float, float]:
    """(A, B) of the friction law; a falling law for a Coulomb-only method
    (METHODS[method].coulomb_only) is refused, naming both."""
    if friction is None or friction == "coulomb":
        return 1.0, 0.0
    if (isinstance(friction, FallingFriction) and method is not None and method in METHODS
            and METHODS[method].coulomb_only and friction.A < 1.0 and friction.B > 0.0):
        raise RollerRigError(f"{func}: method {method!r} is built for Coulomb friction; "
                             f"got {friction!r} (use friction=None)")
    if isinstance(friction, FallingFriction):
        return friction.A, friction.B
    raise RollerRigError(f"{func}: friction must be None, 'coulomb' or a FallingFriction, "
                         f"got {friction!r}")


def _choice(func: str, name: str, value: object, table: Iterable[str],
            none_ok: bool = False) -> None:
    """One of a table's names (a str: a list or a dict is not looked up)."""
    if (value is None and none_ok) or (isinstance(value, str) and value in table):
        return
    names = ", ".join(repr(k) for k in table) + (" or None" if none_ok else "")
    raise RollerRigError(f"{func}: {name} must be one of {names}, got {value!r:.60}")


def _as_float(func: str, name: str, value: object) -> _F64:
    arr = np.asarray(value)
    if arr.dtype.kind not in "iuf":
        raise RollerRigError(f"{func}: {name} must be real numbers, got dtype {arr.dtype} "
                             f"({value!r:.60})")
    if arr.size == 0:
        raise RollerRigError(f"{func}: {name} is empty")
    return arr.astype(np.float64, copy=False)


def _broadcast(func: str, named: Mapping[str, object]) -> Tuple[
        Tuple[int, ...], bool, Dict[str, _F64], List[_F64]]:
    """Convert, broadcast and flatten the inputs for the binding.

    Returns (shape, scalar, {name: array as given}, [1-D arrays]) where a
    1-element input stays 1 element long (the binding broadcasts it)."""
    arrays = {name: _as_float(func, name, v) for name, v in named.items()}
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrays.values()))
    except ValueError:
        shapes = ", ".join(f"{n}{a.shape}" for n, a in arrays.items() if a.ndim)
        raise RollerRigError(f"{func}: shapes do not broadcast: {shapes}") from None
    flat = []
    for a in arrays.values():
        if a.size == 1:
            flat.append(a.reshape(1))
        else:
            flat.append(np.ascontiguousarray(np.broadcast_to(a, shape)).reshape(-1))
    scalar = all(a.ndim == 0 for a in arrays.values())
    # broadcast_to only where a shape differs: it costs 5 us an input, most of
    # a scalar call's time (full is read, never written)
    full = {n: a if a.shape == shape else np.broadcast_to(a, shape) for n, a in arrays.items()}
    return shape, scalar, full, flat


def _finish(func: str, shape: Tuple[int, ...], scalar: bool, full: Mapping[str, _F64],
            outputs: Iterable[_F64], status: npt.NDArray[np.int8], errors: Optional[str],
            blame: Optional[Blame] = None) -> List[Any]:
    if errors is None:
        errors = "raise" if scalar else "warn"
    if errors not in ("raise", "warn", "ignore"):
        raise RollerRigError(f"{func}: errors must be 'raise', 'warn' or 'ignore', "
                             f"got {errors!r}")
    status = status.reshape(shape)
    check_status(func, status, full, errors, blame)
    outs = [o.reshape(shape) for o in outputs]
    if scalar:
        return [float(o) for o in outs] + [int(status)]
    return outs + [status]
