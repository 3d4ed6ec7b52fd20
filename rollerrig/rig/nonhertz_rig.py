"""The rig on the non-Hertzian contact (contact.patch = "nonhertz",
csrc/rig/rr_rig_contact.h, Patch): the table of the rig's own pair::

    rr.simulate(params={"wheelset": {"profile": "s1002"}, "roller": {"profile": "uic60"},
                        "contact": {"patch": "nonhertz"}})

contact.nonhertz_table = "" (the default): the table is built from the rig's
profiles (both sides, profile_right), scale, gauge and material by
rollerrig.nonhertz_table (the exact theory, rows in threads), for the rig's
static wheel load (its nodes reach 1.85 times it, extrapolated by Hertz's
law up to 5 times), over y within contact.nonhertz_half_range_m every
contact.nonhertz_row_spacing_m (a quarter of it near the rigid contact
point's jumps), and kept in memory for the session.  A file's path: a table
saved by rollerrig.rig_nonhertz_table(params, path) (rig.build), read and checked against the
rig's pair (every quantity that differs is named) before the run.
"""
from __future__ import annotations

import hashlib
import json
import os
import sys
import time
import warnings
from typing import Any, Dict, Iterable, List, Mapping, Tuple, Union

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError, RollerRigWarning
from .._typing import F64Array
from ..geometry.nonhertz import (LOAD_SPAN, MAX_ROWS, MAX_SPAN, NonHertzSide, NonHertzTable,
                                 nonhertz_table)
from ..geometry.wheelset import ContactTable, RigGeometry, wheelset_contact
from . import real_profiles as _real_profiles

#: the full-size table's choices (rollerrig.geometry.nonhertz), scaled to the
#: rig by its profile scale: a jump of the rigid contact point is a lateral
#: move over 0.5 mm between shifts 0.01 mm apart; rows within 0.3 mm of one
#: are a quarter as far apart; regions within CONTACT's D_COMB (4 mm) form
#: one patch
JUMP, JUMP_ZONE, COMBINE = 0.5e-3, 0.3e-3, 4e-3
#: tables kept in memory, by pair and settings
_KEEP = 4
_BUILT: Dict[Tuple[str, Tuple[float, float, int], float, float], NonHertzTable] = {}
#: checked parameters {section: {key: value}}
_Params = Mapping[str, Mapping[str, Any]]
#: a table as the binding takes it: (rows, head) per side
_CTable = Tuple[F64Array, Tuple[float, float, float, float, float]]
_KEY_VALUES = ("wheelset.wheel_radius_m", "roller.radius_m", "wheelset.contact_half_spacing_m",
               "contact.youngs_modulus_Pa", "contact.poisson_ratio")
_CONE_VALUES = ("wheelset.conicity", "wheelset.profile_half_width_m", "roller.crown_radius_m")
_REAL_VALUES = ("wheelset.profile_scale", "roller.profile_scale", "roller.gauge_m")


def _value(P: _Params, name: str) -> Any:
    section, key = name.split(".")
    return P[section][key]


def _scale(P: _Params) -> float:
    """The length factor of the rig's profiles (1 for the cone)."""
    return (float(P["wheelset"]["profile_scale"])
            if _real_profiles.profile_points(P) is not None else 1.0)


def pair_key(P: _Params) -> Dict[str, Union[float, str]]:
    """What makes the rig's pair and its table.

    Parameters
    ----------
    P : dict
        Checked parameters.

    Returns
    -------
    dict
        ``{name: value}``, the profiles' points (as the C rig takes them)
        as a digest per slot.
    """
    key: Dict[str, Union[float, str]] = {name: float(_value(P, name)) for name in _KEY_VALUES}
    points = _real_profiles.profile_points(P)
    if points is None:
        key.update({name: float(_value(P, name)) for name in _CONE_VALUES})
        return key
    key.update({name: float(_value(P, name)) for name in _REAL_VALUES})
    for slot, s in zip(_real_profiles.SLOT_KEYS, points):
        if s is not None:
            h = hashlib.sha256()
            for a in s[:2]:
                h.update(np.ascontiguousarray(a, dtype="<f8").tobytes())
            h.update(bytes([int(s[2])]))
            key[f"{slot} points"] = h.hexdigest()[:16]
    return key


def static_load(P: _Params) -> float:
    """The wheel's static vertical load.

    Parameters
    ----------
    P : dict
        Checked parameters.

    Returns
    -------
    float
        Half of the preload and weight [N].
    """
    return 0.5 * (float(P["suspension"]["preload_total_N"])
                  + float(P["wheelset"]["mass_kg"]) * float(P["scenario"]["g_m_s2"]))


def _rows(geometry: RigGeometry, side: str, half: float, dy: float, scale: float) -> F64Array:
    """One side's row shifts: every dy over [-half, half], every dy / 4
    within JUMP_ZONE (scaled) of the rigid contact point's jumps."""
    n = int(np.ceil(half / dy - 1e-9))
    ys = list(dy * np.arange(-n, n + 1))
    fine = 0.01e-3 * scale
    y = np.arange(-n * dy, n * dy + 0.5 * fine, fine)
    with warnings.catch_warnings():
        # a search that stops short at a few shifts moves no jump: not the user's concern
        warnings.simplefilter("ignore", RollerRigWarning)
        c = getattr(wheelset_contact(geometry, y), side)
    k = np.flatnonzero(np.abs(np.diff(c.y)) > JUMP * scale)
    for j in 0.5 * (y[k] + y[k + 1]):
        zone = JUMP_ZONE * scale
        ys += list(np.arange(j - zone, j + zone + 1e-12, dy / 4))
    shifts = np.unique(np.round(np.array(ys), 12))
    return shifts[(shifts >= -n * dy - 1e-15) & (shifts <= n * dy + 1e-15)]


def _settings(P: _Params) -> Tuple[float, float, int]:
    """(half range, row spacing, elements); rows and range bounded as
    nonhertz_table bounds them, checked before the build's long work."""
    C = P["contact"]
    half, dy = float(C["nonhertz_half_range_m"]), float(C["nonhertz_row_spacing_m"])
    if not 2.0 * half <= MAX_SPAN:
        raise RollerRigError(f"contact.nonhertz_half_range_m = {half!r}: the table's shifts "
                             f"span at most {MAX_SPAN:g} m")
    if not 2.0 * half / dy <= MAX_ROWS:
        raise RollerRigError(f"contact.nonhertz_row_spacing_m = {dy!r} over "
                             f"contact.nonhertz_half_range_m = {half!r} would make "
                             f"{2.0 * half / dy:.3g} rows a side, at most {MAX_ROWS}")
    return half, dy, int(C["nonhertz_elements"])


#: rows built together (two threads)
CHUNK = 8


def _side_rows(g: RigGeometry, side: str, ys: npt.ArrayLike,
               kw: Mapping[str, Any]) -> Tuple[List[F64Array], str]:
    """One side's rows from the centre outwards, in chunks; a direction
    ends at the first row the exact theory cannot build (deep flange
    contact at the largest load node): (rows sorted by y, why it ended or
    "")."""
    ys = np.asarray(ys)
    out: Dict[float, F64Array] = {}
    why = ""
    for direction in (ys[ys >= 0.0], ys[ys < 0.0][::-1]):
        k = 0
        while k < len(direction):
            chunk = direction[k:k + CHUNK]
            try:
                got = _chunk(g, side, chunk, kw)
            except RollerRigError:
                got = []
                for j in range(len(chunk)):     # one by one, to the first that fails
                    try:
                        got += _chunk(g, side, chunk[j:j + 1], kw)
                    except RollerRigError as e:
                        why = str(e)
                        break
                for r in got:
                    out[float(r[0])] = r
                break
            for r in got:
                out[float(r[0])] = r
            k += CHUNK
    return [out[y] for y in sorted(out)], why


def _chunk(g: RigGeometry, side: str, ys: Iterable[float],
           kw: Mapping[str, Any]) -> List[F64Array]:
    """The rows at shifts ys (nonhertz_table needs two: a lone row is built
    beside a twin 1 nm away, which is dropped)."""
    shifts = [float(y) for y in ys]
    twin = len(shifts) == 1
    t = nonhertz_table(g, None, None, y=shifts + [shifts[0] + 1e-9] if twin else shifts,
                       sides=(side,), **kw).side(side)
    rows = list(t.rows)
    return rows[:1] if twin else rows


def _build(P: _Params, table: ContactTable, key: Mapping[str, object]) -> NonHertzTable:
    """The table of the rig's pair (rollerrig.nonhertz_table per side)."""
    half, dy, n = _settings(P)
    scale = _scale(P)
    g = table.geometry
    Fz = static_load(P)
    E, nu = float(P["contact"]["youngs_modulus_Pa"]), float(P["contact"]["poisson_ratio"])
    rows = {side: _rows(g, side, half, dy, scale) for side in ("left", "right")}
    total = sum(len(r) for r in rows.values())
    # 0.08 s a row at n = 40: the default tables' builds on 2 free cores
    # (benchmarks/RESULTS.md, rig_nonhertz: 395 rows in 33 s, 358 in 30 s)
    print(f"rollerrig: building the non-Hertzian contact's table of the rig's pair ({total} "
          f"rows, about {0.08 * total * (n / 40) ** 2:.0f} s on 2 free cores; kept for this "
          f"session, or save it: rollerrig.rig_nonhertz_table(params, path))", file=sys.stderr)
    t0 = time.perf_counter()
    kw: Dict[str, Any] = dict(Fz=Fz, mu_ref=float(P["scenario"]["mu0"]), E=E, nu=nu, n=n,
              n_corr=max(8, (3 * n) // 4), richardson=False, combine=COMBINE * scale)
    sides: Dict[str, NonHertzSide] = {}
    ends: List[str] = []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", RollerRigWarning)
        for side in ("left", "right"):
            built, end = _side_rows(g, side, rows[side], kw)
            if len(built) < 2:
                raise RollerRigError(f"the {side} wheel's non-Hertzian table: the exact "
                                     f"theory's rows fail at the centre: {end}")
            if end:
                ends.append(f"the {side} wheel's from {built[0][0]:.6g} to {built[-1][0]:.6g} m "
                            f"({end})")
            sides[side] = NonHertzSide(np.ascontiguousarray(np.array(built)),
                                       1.0 if side == "left" else -1.0, float(g.roller_radius),
                                       E / (2.0 * (1.0 + nu)), nu, kw["mu_ref"]).check()
    excluded = [str(w.message) for w in caught if "not tabulated" in str(w.message)]
    if excluded:
        warnings.warn(f"the rig's nonhertz table: {len(excluded)} row(s) have a region of the "
                      f"gap beyond combine = {COMBINE * scale:g} m of the deepest, not "
                      f"tabulated (one patch per row; first: {excluded[0]})", RollerRigWarning,
                      stacklevel=4)
    if ends:
        warnings.warn(f"the rig's nonhertz table ends where the exact theory's rows fail (a "
                      f"wheel beyond stops the run): {'; '.join(ends)}", RollerRigWarning,
                      stacklevel=4)
    return NonHertzTable(sides["left"], sides["right"], Fz, time.perf_counter() - t0)


def _read(path: str, key: Mapping[str, object], P: _Params) -> NonHertzTable:
    """A saved table, checked against the rig's pair and load."""
    name = f"contact.nonhertz_table = {path!r}"
    if not os.path.isfile(path):
        raise RollerRigError(f"{name}: no such file")
    try:
        with np.load(path, allow_pickle=False) as f:
            saved = json.loads(str(f["rig_pair"])) if "rig_pair" in f else None
        nh = NonHertzTable.load(path)
    except RollerRigError as e:
        raise RollerRigError(f"{name}: {e}") from None
    except Exception as e:                      # not an .npz, truncated, a key missing
        raise RollerRigError(f"{name}: not a readable table ({type(e).__name__}: "
                             f"{str(e)[:120]})") from None
    if saved is None:
        raise RollerRigError(f"{name}: the file records no rig pair (make it with "
                             f"rollerrig.rig_nonhertz_table(params, path))")
    if nh.left is None or nh.right is None:
        raise RollerRigError(f"{name}: the table needs both sides")
    differ = [f"{k} (table {saved.get(k)!r}, rig {v!r})" for k, v in key.items()
              if saved.get(k) != v]
    differ += [f"{k} (table {v!r}, rig none)" for k, v in saved.items() if k not in key]
    if differ:
        raise RollerRigError(f"{name} was built for another pair: {'; '.join(differ)}")
    if not LOAD_SPAN * nh.Fz >= static_load(P):
        raise RollerRigError(f"{name}: built for loads up to {LOAD_SPAN * nh.Fz:g} N, below the "
                             f"rig's static wheel load {static_load(P):g} N")
    return nh


def table_for(P: _Params, table: ContactTable) -> NonHertzTable:
    """The non-Hertzian table of the rig's pair.

    Parameters
    ----------
    P : dict
        Checked parameters.
    table : ContactTable
        Their contact table (their geometry).

    Returns
    -------
    NonHertzTable
        Read from contact.nonhertz_table, or built and kept (the last few,
        by pair and settings).

    Raises
    ------
    RollerRigError
        A file that is missing or not a readable table, that records no
        rig pair, lacks a side, was built for another pair (every quantity
        that differs named) or for loads below the rig's static wheel
        load; a build that fails.
    """
    key = pair_key(P)
    path = P["contact"]["nonhertz_table"]
    if path:
        return _read(os.path.abspath(path), key, P)
    k = (json.dumps(key, sort_keys=True), _settings(P), static_load(P),
         float(P["scenario"]["mu0"]))
    if k not in _BUILT:
        if len(_BUILT) >= _KEEP:
            _BUILT.pop(next(iter(_BUILT)))
        _BUILT[k] = _build(P, table, key)
    return _BUILT[k]


def c_tables(nh: NonHertzTable) -> Tuple[_CTable, ...]:
    """The binding's form of a table.

    Parameters
    ----------
    nh : NonHertzTable
        The table, both sides built.

    Returns
    -------
    tuple
        ``((left rows, head), (right rows, head))``.
    """
    return tuple((np.ascontiguousarray(s.rows, dtype=float), s.head)
                 for s in (nh.side("left"), nh.side("right")))


def save(nh: NonHertzTable, P: _Params, path: str) -> None:
    """Save the table as .npz, with the rig's pair recorded.

    NonHertzTable.save's arrays, readable by NonHertzTable.load.

    Parameters
    ----------
    nh : NonHertzTable
        The table, both sides built.
    P : dict
        The checked parameters it was built for.
    path : str or path-like
        The file.
    """
    from .. import _core
    out: Dict[str, Any] = dict(Fz=nh.Fz, build_seconds=nh.build_seconds,
               layout=np.array([_core.NH_ROW_LEN, _core.NH_NODES, _core.NH_MAX_PATCHES]),
               rig_pair=np.array(json.dumps(pair_key(P), sort_keys=True)))
    for name in ("left", "right"):
        s = getattr(nh, name)
        out[f"{name}_rows"] = s.rows
        out[f"{name}_head"] = np.array(s.head)
    from .._files import write_file
    write_file(path, lambda fh: np.savez(fh, **out), what="rig_nonhertz_table: path",
               binary=True)
