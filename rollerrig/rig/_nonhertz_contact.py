"""rig_contact's patch="nonhertz": each wheel by the non-Hertzian,
multi-patch contact (rr_nonhertz_wheel, csrc/geometry/rr_nonhertz.h) from a
rollerrig.NonHertzTable, over a state or arrays of states; the wheels'
types, NonHertzWheel and its NonHertzPatch.  rollerrig.rig.contact
dispatches here and re-exports the types, and hands in what it owns (the
Hertzian rig_contact for the pose and the words of a failed kinematics,
RigContact, the settling's tolerance), so that this module does not import
it back."""
from __future__ import annotations

import warnings
from typing import Any, Callable, Dict, List, Mapping, NamedTuple, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

from .. import _core
from .._binding import core
from .._errors import RollerRigError, RollerRigWarning, status_message
from .._typing import F64Array
from ..geometry.wheelset import ContactTable

#: a wheel's status, and the worse of both (RigContact.status): an int8
#: array, a numpy int8 on the Hertzian call's scalars, an int here on one state
_Status = Union[int, np.int8, npt.NDArray[np.int8]]
#: rig_contact's loads: ("N" or "Fz", left, right)
_Loads = Tuple[str, Any, Any]
#: rig_contact itself, handed in by rollerrig.rig.contact
_RigContactFn = Callable[..., Any]


class NonHertzPatch(NamedTuple):
    """One patch of a wheel's non-Hertzian contact (rig frame; fx, fy along the
    patch's t1, t2, mz about its normal at the pressure's centroid)."""
    N: float            #: normal load [N]
    fx: float           #: creep forces on the wheel [N]
    fy: float
    mz: float           #: spin moment [N m]
    force: F64Array     #: fx t1 + fy t2 + N n [N]
    point: F64Array     #: the pressure's centroid [m]
    t1: F64Array        #: the patch's frame: rolling direction,
    t2: F64Array        #: lateral in its plane,
    n: F64Array         #: and its normal into the wheel
    delta: float        #: the plane's angle [rad]
    cx: float           #: creepages at the centroid [-], [-], [rad/m]
    cy: float
    cphi: float
    area: float         #: contact area [m^2]
    pmax: float         #: peak pressure [Pa]


#: a number of a call on one state, an array of them on arrays of states
_Number = Union[float, F64Array]


class NonHertzWheel(NamedTuple):
    """One wheel's non-Hertzian contact (rig_contact(..., patch="nonhertz")):
    numbers for a call on one state; for arrays of states each field an
    array of their broadcast shape (3-vectors (3, ...), ``patches`` an object
    array of the states' tuples)."""
    force: F64Array     #: total contact force on the wheel, rig frame [N]
    moment: F64Array    #: its moment about the wheelset centre [N m]
    N: _Number          #: the patches' normal loads summed [N]
    area: _Number       #: their areas summed [m^2]
    pmax: _Number       #: the largest peak pressure [Pa]
    centre: F64Array    #: the load-weighted force centre [m]
    #: NonHertzPatch per patch (per state: an object array of tuples)
    patches: Union[Tuple[NonHertzPatch, ...], npt.NDArray[np.object_]]
    Fz: _Number         #: the vertical load carried [N]
    status: _Status     #: 0 ok, < 0 the wheel failed (NaN numbers, no patches)


def _nonhertz_patch(p: Mapping[str, Any]) -> NonHertzPatch:
    """A patch of the core's (a dict) as a NonHertzPatch, its vectors arrays."""
    fields: Dict[str, Any] = {f: (np.array(p[f]) if f in ("force", "point", "t1", "t2", "n")
                                  else p[f]) for f in NonHertzPatch._fields}
    return NonHertzPatch(**fields)


class _StateFailure(RollerRigError):
    """A state the non-Hertzian contact cannot take (both wheels fail): its
    message and the status its elements get in an array call."""

    def __init__(self, msg: str, status: int) -> None:
        super().__init__(msg)
        self.status = status


def nonhertz_rig_contact(func: str, table: ContactTable, nonhertz: object, loads: _Loads, *,
                          x: npt.ArrayLike, y: npt.ArrayLike, yaw: npt.ArrayLike,
                          vx: npt.ArrayLike, vy: npt.ArrayLike, yaw_rate: npt.ArrayLike,
                          spin: npt.ArrayLike, roller_spin: npt.ArrayLike, mu: float,
                          friction: object, E: float, nu: float, vmin: float, method: str,
                          options: Mapping[str, Any], errors: Optional[str],
                          rig_contact: _RigContactFn, make: Callable[..., Any],
                          settle: Tuple[float, int]) -> Any:
    """rig_contact's patch="nonhertz": the states broadcast, one at a time
    (each wheel one rr_nonhertz_wheel call), the results as the
    Hertzian call's (arrays of the broadcast shape, 3-vectors (3, ...),
    numbers for a call on scalars).  errors as for the Hertzian call (None:
    "raise" on scalars, "warn" on arrays).  On a scalar call with "warn" or
    "ignore" a wheel that fails has NaN numbers, no patches and its status
    (< 0), the other wheel is kept; on arrays so has every element whose state
    fails, and "warn" warns once, naming the first and how many."""
    if errors not in (None, "raise", "warn", "ignore"):
        raise RollerRigError(f"{func}: errors must be 'raise', 'warn' or 'ignore', "
                             f"got {errors!r}")
    from ..geometry.nonhertz import NonHertzTable
    if not isinstance(nonhertz, NonHertzTable):
        raise RollerRigError(f"{func}: patch='nonhertz' needs nonhertz=, an rr.NonHertzTable "
                             f"(rr.nonhertz_table), got {nonhertz!r:.60}")
    if friction is not None:
        raise RollerRigError(f"{func}: patch='nonhertz' takes Coulomb friction (friction=None)")
    if options or method != "fastsim":
        raise RollerRigError(f"{func}: patch='nonhertz' has its own creep method: no method or "
                             f"options")
    model: Dict[str, float] = {}
    for k, v in dict(mu=mu, vmin=vmin, E=E, nu=nu).items():
        a = np.asarray(v)
        if a.ndim != 0 or isinstance(v, bool) or a.dtype.kind not in "fiu":
            raise RollerRigError(f"{func}: patch='nonhertz': {k} must be a number, "
                                 f"got {v!r:.60}")
        model[k] = float(a)
        if not np.isfinite(model[k]):
            raise RollerRigError(f"{func}: {k} = {model[k]!r}: {status_message(-1)}")
    G = model["E"] / (2.0 * (1.0 + model["nu"]))
    for side in ("left", "right"):
        t = nonhertz.side(side)
        if abs(t.G / G - 1) > 1e-9 or abs(t.nu - model["nu"]) > 1e-12:
            raise RollerRigError(f"{func}: E, nu give G = {G:g} Pa, nu = {model['nu']:g}; the "
                                 f"nonhertz table was built for G = {t.G:g} Pa, "
                                 f"nu = {t.nu:g}")
    named = dict(x=x, y=y, yaw=yaw, vx=vx, vy=vy, yaw_rate=yaw_rate, spin=spin,
                 roller_spin=roller_spin, load_left=loads[1], load_right=loads[2])
    arrays = {}
    for k, v in named.items():
        a = np.asarray(v)
        if isinstance(v, bool) or a.dtype.kind not in "fiu":
            raise RollerRigError(f"{func}: {k} must be numbers, got {v!r:.60}")
        if a.size == 0:
            raise RollerRigError(f"{func}: {k} is empty")
        arrays[k] = a.astype(np.float64)
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrays.values()))
    except ValueError:
        raise RollerRigError(f"{func}: the states' shapes do not broadcast: " + ", ".join(
            f"{k} {a.shape}" for k, a in arrays.items())) from None
    scalar = shape == ()
    if errors is None:
        errors = "raise" if scalar else "warn"
    flat = {k: np.broadcast_to(a, shape).ravel() for k, a in arrays.items()}
    if scalar:
        vals = {k: float(a[0]) for k, a in flat.items()}
        wheels = _nonhertz_state(func, table, nonhertz, loads[0], vals, model, errors,
                                 rig_contact, settle)
        pose = rig_contact(table, x=vals["x"], y=vals["y"], yaw=vals["yaw"], vx=vals["vx"],
                           vy=vals["vy"], yaw_rate=vals["yaw_rate"], spin=vals["spin"],
                           roller_spin=vals["roller_spin"], vmin=model["vmin"],
                           kinematics_only=True, errors="raise").pose
        return make(pose, wheels["left"], wheels["right"],
                    min(wheels["left"].status, wheels["right"].status))
    n = int(np.prod(shape, dtype=np.int64))
    motions = {side: _row_motions(table, nonhertz.side(side), flat, model["vmin"])
               for side in ("left", "right")}
    out: Dict[str, List[NonHertzWheel]] = {"left": [], "right": []}
    first, bad = None, 0
    for i in range(n):
        vals = {k: float(a[i]) for k, a in flat.items()}
        try:
            wheels = _nonhertz_state(func, table, nonhertz, loads[0], vals, model, "collect",
                                     rig_contact, settle,
                                     {side: m[i] for side, m in motions.items()})
        except _StateFailure as e:
            wheels = {side: _failed_wheel(vals[f"load_{side}"], e.status)
                      for side in ("left", "right")}
            wheels["left"].message.append(str(e))         # (the element's, once)
        msgs = wheels["left"].message + wheels["right"].message
        if msgs:
            bad += 1
            if first is None:
                first = (i, msgs[0])
        for side in ("left", "right"):
            out[side].append(wheels[side].wheel)
    if first is not None and errors != "ignore":
        # the Hertzian call's wording: the first bad element, how many failed
        where = tuple(int(j) for j in np.unravel_index(first[0], shape))
        text = (f"{first[1]} at index {where} ({bad} of {n} elements failed; their results "
                f"are NaN)")
        if errors == "raise":
            raise RollerRigError(text)
        warnings.warn(text, RollerRigWarning, stacklevel=3)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RollerRigWarning)
        st = {k: a.reshape(shape) for k, a in flat.items()}
        pose = rig_contact(table, x=st["x"], y=st["y"], yaw=st["yaw"], vx=st["vx"],
                           vy=st["vy"], yaw_rate=st["yaw_rate"], spin=st["spin"],
                           roller_spin=st["roller_spin"], vmin=model["vmin"],
                           kinematics_only=True, errors="ignore").pose
    left, right = (_stack_wheels(out[side], shape) for side in ("left", "right"))
    return make(pose, left, right, np.minimum(left.status, right.status))


class _Outcome(NamedTuple):
    """A wheel's result in an array call, and what went wrong with it."""
    wheel: NonHertzWheel
    message: List[str]


def _failed_wheel(Fz: float, status: int) -> _Outcome:
    nan3 = np.full(3, np.nan)
    return _Outcome(NonHertzWheel(nan3, nan3.copy(), np.nan, np.nan, np.nan, nan3.copy(), (),
                                  Fz, status), [])


def _stack_wheels(ws: List[NonHertzWheel], shape: Tuple[int, ...]) -> NonHertzWheel:
    """The wheels of an array call's states as one NonHertzWheel of arrays."""
    def vec(name: str) -> F64Array:
        return np.stack([getattr(w, name) for w in ws], axis=1).reshape((3,) + shape)

    def num(name: str) -> F64Array:
        return np.array([getattr(w, name) for w in ws], dtype=np.float64).reshape(shape)
    patches = np.empty(len(ws), dtype=object)
    for i, w in enumerate(ws):
        patches[i] = w.patches
    return NonHertzWheel(vec("force"), vec("moment"), num("N"), num("area"), num("pmax"),
                         vec("centre"), patches.reshape(shape), num("Fz"),
                         np.array([w.status for w in ws], dtype=np.int8).reshape(shape))


_Motion = Tuple[Tuple[float, float, float], ...]


def _row_kinematics(table: ContactTable, vmin: float, state: Mapping[str, Any],
                    rows: npt.ArrayLike) -> Tuple[npt.NDArray[np.int8], F64Array, F64Array,
                                                 F64Array]:
    """(status, c, v, w) of the wheelset at the shifts rows (any shape; c,
    v, w (3,) + that shape), the state's other numbers broadcast to it,
    moving as at its own y: the vertical and roll rates its lateral speed
    gives there (rr_rig_kinematics_rates_at: between two rows the other
    wheel's contact may jump, and those rates with it)."""
    rows = np.asarray(rows, dtype=float)

    def flat(a: Any) -> F64Array:
        return np.ascontiguousarray(np.broadcast_to(np.asarray(a, dtype=float),
                                                    rows.shape)).ravel()
    st, pose = core(_core.rig_row_kinematics, table.data, table.y0, table.dy,
                    (float(table.geometry.roller_radius), float(vmin)), flat(state["x"]),
                    flat(rows), *(flat(state[k]) for k in ("yaw", "vx", "vy", "yaw_rate",
                                                           "spin", "roller_spin")),
                    flat(state["y"]))
    shape = (3,) + rows.shape
    return (st.reshape(rows.shape), pose[0:3].reshape(shape), pose[5:8].reshape(shape),
            pose[8:11].reshape(shape))


def _row_motions(table: ContactTable, t: Any, flat: Mapping[str, F64Array],
                 vmin: float) -> List[Optional[Tuple[_Motion, _Motion]]]:
    """Per state of an array call, the wheelset's (centre, velocity, angular
    velocity) at the two rows of side table t around its y, moving with the
    state's own rates (one kinematics call for them all, _row_kinematics;
    None where y has no rows: the state fails there)."""
    from ..geometry.nonhertz import nonhertz_locate
    n = flat["y"].size
    rows = np.full((2, n), np.nan)
    for i, y in enumerate(flat["y"]):
        if np.isfinite(y):
            st, j, _ = nonhertz_locate(t, float(y))
            if st >= 0:
                rows[:, i] = t.rows[[j, j + 1], 0]
    _, c, v, w = _row_kinematics(table, vmin, flat, rows)       # (3, 2, n) each
    ok = np.all(np.isfinite(c) & np.isfinite(v) & np.isfinite(w), axis=(0, 1)).tolist()
    cl, vl, wl = (a.transpose(2, 1, 0).tolist() for a in (c, v, w))        # [state][row][k]
    out: List[Optional[Tuple[_Motion, _Motion]]] = []
    for i in range(n):
        m0, m1 = (tuple((a[i][r][0], a[i][r][1], a[i][r][2]) for a in (cl, vl, wl))
                  for r in range(2))
        out.append((m0, m1) if ok[i] else None)
    return out


def _nonhertz_state(func: str, table: ContactTable, nonhertz: Any, kind: str,
                    vals: Mapping[str, float], model: Mapping[str, float],
                    errors: str, rig_contact: _RigContactFn, settle: Tuple[float, int],
                    motions: Optional[Mapping[str, Optional[Tuple[_Motion, _Motion]]]] = None
                    ) -> Dict[str, Any]:
    """Both wheels of one state.  A state the contact cannot take (an input
    not finite, y beyond the table's rows) raises _StateFailure; a wheel that
    fails raises (errors "raise"), or has NaN numbers and its status ("warn"
    warns, "ignore"), or ("collect") the same with its message kept: the
    values are then _Outcome(wheel, messages), else NonHertzWheel.  motions:
    the wheelset's motion at each side's rows (_row_motions), else found here."""
    from ..geometry.nonhertz import LOAD_SPAN, nonhertz_locate, nonhertz_wheel
    FZ_TOL, FZ_ITER = settle
    for k, v in vals.items():
        if not np.isfinite(v):
            raise _StateFailure(f"{func}: {k} = {v!r}: {status_message(-1)}", -1)
    y = vals["y"]
    wheels: Dict[str, Any] = {}
    for side in ("left", "right"):
        t = nonhertz.side(side)
        given = motions[side] if motions is not None else None
        if given is not None:                # its rows located by _row_motions
            motion0, motion1 = given
        else:
            st, i, w = nonhertz_locate(t, y)
            if st < 0:
                ys = t.rows[:, 0]
                raise _StateFailure(f"{func}: y = {y!r} m: beyond the nonhertz table's rows "
                                    f"({ys[0]:g} to {ys[-1]:g} m): {status_message(st)}", st)
            yr = t.rows[[i, i + 1], 0]
            kst, *cvw = _row_kinematics(table, model["vmin"], vals, yr)
            if np.min(kst) < 0:
                # the rows' kinematics fail (an extreme x or yaw): the state does,
                # in the words of the call that raises
                code = int(np.min(kst))
                try:
                    rig_contact(table, x=vals["x"], y=yr, yaw=vals["yaw"], vx=vals["vx"],
                                vy=vals["vy"], yaw_rate=vals["yaw_rate"], spin=vals["spin"],
                                roller_spin=vals["roller_spin"], vmin=model["vmin"],
                                kinematics_only=True, errors="raise")
                except RollerRigError as e:
                    raise _StateFailure(str(e), code) from None
                raise _StateFailure(f"{func}: {status_message(code)}", code)
            # the wheelset's centre, velocity, angular velocity at the two rows
            motion0, motion1 = [tuple((float(a[0, j]), float(a[1, j]), float(a[2, j]))
                                      for a in cvw)
                                for j in range(2)]
        load = vals[f"load_{side}"]

        def run(Fz: float) -> Tuple[Dict[str, Any], Tuple[Dict[str, Any], ...]]:
            st, res, pts = nonhertz_wheel(t, y, Fz, model["mu"], vals["roller_spin"], motion0,
                                          motion1, vmin=model["vmin"], x=vals["x"],
                                          yaw=vals["yaw"])
            if st == -12:        # RR_ERR_RANGE: the vertical balance (rr_nonhertz.h)
                raise _StateFailure(f"{func}: the {side} wheel at y = {y!r} m, Fz = {Fz!r} N: "
                                    f"the vertical load has no balance on the table's "
                                    f"patches (the creep forces' vertical share near or "
                                    f"beyond Fz: the flange climbs) or a load far beyond "
                                    f"its nodes: {status_message(st)}", st)
            if st == -14:        # RR_ERR_TABLE: y is inside, so the load is not
                raise _StateFailure(f"{func}: the {side} wheel at y = {y!r} m, Fz = {Fz!r} N: "
                                    f"a load beyond the nonhertz table's (built for Fz = "
                                    f"{nonhertz.Fz:g} N, its nodes to {LOAD_SPAN:.3g} times "
                                    f"that, extrapolated to 2.8 times more), or on a flange "
                                    f"whose creep forces pull the wheel down no vertical "
                                    f"balance at all (the flange climbs): "
                                    f"{status_message(st)}", st)
            if st < 0:
                raise _StateFailure(f"{func}: the {side} wheel at y = {y!r} m, Fz = {Fz!r} N: "
                                    f"{status_message(st)}", st)
            return res, pts
        Fz = load
        try:
            if not load > 0:
                raise _StateFailure(f"{func}: the {side} wheel's load must be > 0, "
                                    f"got {load!r}", -2)
            res, pts = run(Fz)
            if kind == "N":
                # the vertical load that gives the normal load asked for (N ~ Fz / n_z)
                for _ in range(FZ_ITER):
                    Fz *= load / res["N"]
                    res, pts = run(Fz)
                    if abs(res["N"] - load) <= FZ_TOL * load:
                        break
                else:
                    raise _StateFailure(f"{func}: the {side} wheel's vertical load for N = "
                                        f"{load!r} N did not settle", -12)
        except _StateFailure as e:
            if errors == "raise":
                raise RollerRigError(str(e)) from None
            failed = _failed_wheel(Fz, e.status)
            if errors == "collect":
                failed.message.append(str(e))
                wheels[side] = failed
                continue
            if errors == "warn":
                warnings.warn(str(e), RollerRigWarning, stacklevel=4)
            wheels[side] = failed.wheel
            continue
        patches = tuple(_nonhertz_patch(p) for p in pts)
        wheel = NonHertzWheel(np.array(res["force"]), np.array(res["moment"]), res["N"],
                              res["area"], res["pmax"], np.array(res["centre"]), patches, Fz, 0)
        wheels[side] = _Outcome(wheel, []) if errors == "collect" else wheel
    return wheels


