"""Real profiles in the rig: the values of wheelset.profile, roller.profile
and their _right rows (a built-in name or a profile file), read into the
points the C rig's table is built from (csrc/geometry/rr_tables.h,
rr_rig_profiles, rr_rig_table_build_profiles).

The points are full size, referenced to the rig's nominal geometry, and the
C core scales them by wheelset.profile_scale / roller.profile_scale:

* a wheel: y = 0, z = 0 at its taping line (the nominal rolling circle,
  radius wheelset.wheel_radius_m, at wheelset.contact_half_spacing_m from
  the wheelset's centre).  SIMPACK and two-column files have their origin
  there (S1002: yes); a MiniProf .whl has it at the flange back, and the
  taping line at its header's WheelDiameterTaperline (70 mm).  Where both
  wheels are MiniProf files with DiameterTaperline, the right wheel keeps
  the difference of the two radii (the measured pair: 0.46 mm).
* a roller: z = 0 at its top (radius roller.radius_m) and y = 0 at its
  gauge point, RailGaugePoint (MiniProf) or 14 mm (EN 13848-1) below the
  top on the gauge side; the two gauge points sit roller.gauge_m apart.

With the defaults, S1002 on UIC60 sit as on standard track (gauge 1435,
back to back 1360 mm) at 1/5: wheelset.contact_half_spacing_m = (1360/2 +
70)/5 mm.  Files are smoothed over integration.profile_smoothing_m (full
size; the built-in S1002 and UIC60 are not).  A fold (a segment where y
steps back: a vertical or overhanging face) is an error naming the file and
line, except on a roller below its gauge point, out of any wheel's reach,
where it is trimmed (the shipped measured rollers fold 17-52 mm below their
top, on their gauge faces; as RigGeometry.measured_pair() trims them).
"""
from __future__ import annotations

import functools
import os
import re
import warnings
from typing import TYPE_CHECKING, Any, Dict, List, Mapping, Optional, Sequence, Tuple, cast

import numpy as np

from .. import _core
from .._errors import RollerRigError, RollerRigWarning
from .._typing import F64Array
from ..geometry.profiles import DATA_DIR, Profile, read_profile

if TYPE_CHECKING:
    from ..geometry.wheelset import RigGeometry

#: a profile's slot as the C rig takes it: (y, z, end: 0 not-a-knot, 1 natural)
Slot = Tuple[F64Array, F64Array, int]
#: the four slots of rr_rig_profiles (wheel, roller, wheel_right, roller_right)
Points = Tuple[Optional[Slot], Optional[Slot], Optional[Slot], Optional[Slot]]
#: the rig's geometry numbers (r0, R0, half width, alpha, crown, span, reach, rows)
Numbers = Tuple[float, float, float, float, float, float, float, int]
#: the files a profile row names: (path, modification time) per slot, None if none
Stamps = Tuple[Optional[Tuple[str, int]], ...]

#: the rows that name a profile, by section: (the left's, the right's)
PROFILE_ROWS = {"wheelset": ("profile", "profile_right"), "roller": ("profile", "profile_right")}
#: the analytic profiles of the C rig (rr_rig_table_build), by section
ANALYTIC = {"wheelset": "conical", "roller": "crowned cylinder"}
#: built-in real profiles by name, with the section they belong to
BUILTIN = {"s1002": ("wheelset", Profile.s1002), "uic60": ("roller", Profile.uic60)}
#: the taping line's distance from the flange back where a MiniProf header
#: gives none (EN 13715) [m]; the gauge point's depth below the top (EN 13848-1) [m]
TAPING_LINE, GAUGE_DEPTH = 0.070, 0.014
MM = 1e-3
#: most lateral distance between neighbouring points (csrc/geometry/rr_tables.h,
#: RR_PROFILE_MAX_GAP) [m]
MAX_GAP = 5e-3
#: the C rig's value for a profile whose points the caller gives
POINTS = "points"


def is_real(section: str, value: object) -> bool:
    """Whether a profile row's value names a real profile (not the analytic
    one, not "" for a right side)."""
    return isinstance(value, str) and value not in ("", ANALYTIC[section])


def c_value(section: str, key: str, value: object) -> object:
    """The C rig's value of a profile row: the analytic name, "" or "points"."""
    return POINTS if is_real(section, value) else value


def resolve(value: str) -> Optional[str]:
    """The file a profile row's value names: as given (absolute, or relative
    to the working folder; a scenario file's own are made absolute by
    relative_to), else a file of that name shipped in
    rollerrig/data/profiles; None if none is."""
    candidates = [value]
    candidates.append(os.path.join(DATA_DIR, os.path.basename(value)))
    return next((os.path.abspath(c) for c in candidates if os.path.isfile(c)), None)


def problems(P: Mapping[str, Mapping[str, Any]]) -> List[str]:
    """Sentences for the profile rows of the merged parameters P: each a
    string, a built-in name of its section, the analytic name (the left
    side), "" (the right side) or an existing file."""
    out = []
    for section, keys in PROFILE_ROWS.items():
        for key in keys:
            v = P[section][key]
            name = f"{section}.{key}"
            right = key.endswith("_right")
            names = [n for n, (s, _) in BUILTIN.items() if s == section]
            allowed = ([] if right else [ANALYTIC[section]]) + names
            if not isinstance(v, str):
                out.append(f"{name} must be a profile's name ({', '.join(map(repr, allowed))}) "
                           f"or a file's path, got {v!r:.60}")
            elif v == "" and not right:
                out.append(f"{name} must name a profile ({', '.join(map(repr, allowed))}) or "
                           f"a file, got ''")
            elif v in ANALYTIC.values() and v != ("" if right else ANALYTIC[section]) \
                    or v == POINTS or (v in BUILTIN and BUILTIN[v][0] != section):
                out.append(f"{name} must be {', '.join(map(repr, allowed))}"
                           f"{' or empty (the left mirrored)' if right else ''} or a profile "
                           f"file's path, got {v!r}")
            elif is_real(section, v) and v not in BUILTIN and resolve(v) is None:
                out.append(f"{name}: no such profile file {v!r} (nor in {DATA_DIR})")
    return out


_FOLD = re.compile(r"z (-?[0-9.e+-]+) \.\. (-?[0-9.e+-]+) mm")


def _read(name: str, value: str, kind: str, smoothing: float, notes: List[str]) -> Profile:
    """A profile row's profile: built-in, or read (folds as the module says:
    a roller's below its gauge point trimmed, with no warning, as
    RigGeometry.measured_pair() trims the measured rollers'; notes gets the
    reader's words for it)."""
    if value in BUILTIN:
        return BUILTIN[value][1]()
    path = cast(str, resolve(value))     # (a checked set's rows name files that exist: problems)
    sm = smoothing if smoothing > 0 else None
    try:
        if kind == "wheel":
            return read_profile(path, kind, on_fold="raise", smoothing=sm)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", RollerRigWarning)
            p = read_profile(path, kind, smoothing=sm)
        for w in caught:
            m = _FOLD.search(str(w.message)) if "folds back" in str(w.message) else None
            if m is None:                      # not a fold: the reader's word stands
                warnings.warn(f"{name}: {w.message}", RollerRigWarning, stacklevel=4)
                continue
            depth = GAUGE_DEPTH if "RailGaugePoint" not in p.meta \
                else float(p.meta["RailGaugePoint"]) * MM
            if m and float(m.group(1)) * MM - float(p.z.min()) <= depth:
                raise RollerRigError(f"{path}: {str(w.message).split(': ', 1)[-1]}, within "
                                     f"{depth * 1e3:g} mm of the top, where a wheel can touch: "
                                     f"give a single-valued profile")
            notes.append(f"{name}: {w.message}")
        return p
    except RollerRigError as e:
        raise RollerRigError(f"{name}: {e}") from None


def _wheel_points(p: Profile) -> Tuple[F64Array, F64Array, Optional[float]]:
    """(y, z, taping-line radius offset [m] or None): a wheel re-referenced to its taping line."""
    miniprof = p.meta.get("format") == "miniprof"
    tape = float(p.meta.get("WheelDiameterTaperline", TAPING_LINE / MM)) * MM if miniprof else 0.0
    if not p.y_min <= tape <= p.y_max:
        raise RollerRigError(f"the taping line y = {tape * 1e3:g} mm lies outside the wheel's "
                             f"points ({p.y_min * 1e3:.4g} .. {p.y_max * 1e3:.4g} mm)")
    radius = float(p.meta["DiameterTaperline"]) * MM / 2 if "DiameterTaperline" in p.meta \
        else None
    return p.y - tape, p.z - float(p.z_at(tape)), radius


def _roller_points(p: Profile) -> Tuple[F64Array, F64Array]:
    """(y, z): a roller re-referenced to its top and its gauge point."""
    top = float(p.z.min())
    depth = float(p.meta["RailGaugePoint"]) * MM if "RailGaugePoint" in p.meta else GAUGE_DEPTH
    top_profile = Profile(p.y, p.z - top, kind="rail", bc=p.bc)
    y_gauge = top_profile.gauge_point(depth)
    return p.y - y_gauge, p.z - top


@functools.lru_cache(maxsize=16)
def _points(wheel: object, roller: object, wheel_right: object, roller_right: object,
            smoothing: float, stamps: Stamps) -> Tuple[Points, Tuple[str, ...]]:
    """(the four slots of rr_rig_profiles: None or (y, z, end) each (end 0
    not-a-knot, 1 natural: the profile's own), read and re-referenced; the
    readers' words for the folds trimmed).  stamps: the
    files' modification times (a changed file is read again)."""
    out: List[Optional[List[Any]]] = []
    radii: Dict[int, Optional[float]] = {}
    notes: List[str] = []
    for slot, (section, value) in enumerate((("wheelset", wheel), ("roller", roller),
                                             ("wheelset", wheel_right),
                                             ("roller", roller_right))):
        key = f"{section}.{'profile_right' if slot >= 2 else 'profile'}"
        if not is_real(section, value):
            out.append(None)
            continue
        kind = "wheel" if section == "wheelset" else "rail"
        assert isinstance(value, str)                 # (is_real: a name or a path)
        p = _read(f"{key} = {value!r}", value, kind, smoothing, notes)
        try:
            if kind == "wheel":
                y, z, radii[slot] = _wheel_points(p)
            else:
                y, z = _roller_points(p)
        except RollerRigError as e:
            raise RollerRigError(f"{key} = {value!r}: {e}") from None
        out.append([np.ascontiguousarray(y), np.ascontiguousarray(z),
                    1 if p.bc == "natural" else 0])
    # the measured pair: the right wheel as much larger as its header says
    r0, r2, right = radii.get(0), radii.get(2), out[2]
    if right is not None and r0 is not None and r2 is not None:
        right[1] = right[1] + (r2 - r0)
    for s in out:
        if s is not None:
            for a in s[:2]:
                a.setflags(write=False)
    slots = [None if s is None else (s[0], s[1], s[2]) for s in out]
    return (slots[0], slots[1], slots[2], slots[3]), tuple(notes)


#: the shipped scenarios on real profiles
SCENARIOS = {name: os.path.join(os.path.dirname(DATA_DIR), f"rig_{name}.toml")
             for name in ("s1002_uic60", "measured_pair", "flange_excursion")}


def profile_points(P: Mapping[str, Mapping[str, Any]]) -> Optional[Points]:
    """The four slots (rr_rig_profiles: wheel, roller, wheel_right,
    roller_right) of the merged parameters P, or None where all are
    analytic (the cone on its crowned roller)."""
    W, R = P["wheelset"], P["roller"]
    values = (W["profile"], R["profile"], W["profile_right"], R["profile_right"])
    sections = ("wheelset", "roller", "wheelset", "roller")
    if not any(is_real(s, v) for s, v in zip(sections, values)):
        return None
    return _points(*values, *_stamps(P))[0]


def _stamps(P: Mapping[str, Mapping[str, Any]]) -> Tuple[float, Stamps]:
    """(smoothing, each file's path and modification time): what, besides the
    rows' values, makes the points (a file changed or moved is read again)."""
    W, R = P["wheelset"], P["roller"]
    values = (W["profile"], R["profile"], W["profile_right"], R["profile_right"])
    sections = ("wheelset", "roller", "wheelset", "roller")
    # the file each names (a relative name is the working folder's) and its time
    # (a checked set's real rows name files that exist: problems)
    stamps = tuple((cast(str, resolve(v)), os.stat(cast(str, resolve(v))).st_mtime_ns)
                   if is_real(s, v) and v not in BUILTIN else None
                   for s, v in zip(sections, values))
    return float(P["integration"]["profile_smoothing_m"]), stamps


def relative_to(params: Dict[str, Any], folder: str) -> Dict[str, Any]:
    """params (a scenario file's nested dict) with each profile row's
    relative path that names a file in `folder` made absolute (a scenario
    names its profiles relative to itself)."""
    for section, keys in PROFILE_ROWS.items():
        S = params.get(section)
        if not isinstance(S, dict):
            continue
        for key in keys:
            v = S.get(key)
            if isinstance(v, str) and is_real(section, v) and v not in BUILTIN \
                    and not os.path.isabs(v) and os.path.isfile(os.path.join(folder, v)):
                S[key] = os.path.abspath(os.path.join(folder, v))
    return params


SLOT_KEYS = ("wheelset.profile", "roller.profile", "wheelset.profile_right",
             "roller.profile_right")


def rig_profile_table(geometry: Numbers, scales: Tuple[float, float, float], points: Points,
                      values: Sequence[object]) -> Tuple[F64Array, float, float]:
    """The C table (data, y0, dy) on real profiles, or RollerRigError naming
    the profile row, its value (the file) and the point at fault
    (rr_rig_profiles_check) or the shift where the profiles do not touch."""
    from .._errors import status_message
    data, y0, dy, status, bad_y, which, point = _core.rig_profile_table(geometry, scales, points)
    if status >= 0:
        assert data is not None                  # (a status >= 0: the table was built)
        return data, y0, dy
    if which < 0:
        where = f"at y_ws = {bad_y!r} m: " if np.isfinite(bad_y) else ""
        raise RollerRigError(f"{where}{status_message(status)}")
    head = f"{SLOT_KEYS[which]} = {values[which]!r}"
    if point < 0:
        raise RollerRigError(f"{head}: its points (as referenced, full size): "
                             f"{status_message(status)}")
    slot = points[which]
    assert slot is not None                      # (the C check blames a slot it was given)
    y, z = slot[0], slot[1]
    at = f"point {point} of {len(y)} (y = {y[point] * 1e3:.6g} mm, z = {z[point] * 1e3:.6g} mm)"
    if point > 0 and not y[point] > y[point - 1]:
        why = "y does not increase there: a vertical or overhanging segment"
    elif point > 0 and y[point] - y[point - 1] > MAX_GAP:
        why = (f"{(y[point] - y[point - 1]) * 1e3:.4g} mm from the point before: a gap (at "
               f"most {MAX_GAP * 1e3:g} mm between points, or the spline invents the surface "
               f"under a contact patch)")
    else:
        why = status_message(status)
    raise RollerRigError(f"{head}: {at}: {why}")


def rig_geometry(numbers: Numbers, scales: Tuple[float, float, float],
                 points: Points) -> RigGeometry:
    """The RigGeometry of the rig's profiles (the points as the C build
    scales and places them; analytic slots as rr_rig_table_build makes
    them): for rollerrig.ContactTable.geometry and plots."""
    from ..geometry.wheelset import RigGeometry
    r0, R0, hw, alpha, crown, span, reach, rows = numbers
    ws, rs, gauge = scales
    n = _core.RIG_PROFILE_POINTS

    def profile(slot: int, kind: str) -> Optional[Profile]:
        s = points[slot]
        if s is None:
            return None
        scale = ws if kind == "wheel" else rs
        return Profile(scale * s[0], scale * s[1], kind=kind,
                       bc="natural" if s[2] else "not-a-knot")
    wheel = profile(0, "wheel") or Profile.conical(alpha, (-hw, hw), r0=r0, n=n)
    roller = profile(1, "rail") or Profile.cylinder((-hw, hw), crown_radius=crown, n=n)
    real_roller = points[1] is not None
    return RigGeometry(wheel=wheel, roller=roller, wheel_right=profile(2, "wheel"),
                       roller_right=profile(3, "rail"), wheel_radius=r0, roller_radius=R0,
                       wheel_y=span, roller_y=0.5 * gauge if real_roller else span)

