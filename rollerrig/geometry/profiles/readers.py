"""Profile file readers and READERS, the table of formats by extension.

Each reader is read(path, where, kind, units) -> RawProfile: the points in
metres in the file's order, the line of each, the kind the file says (or
the caller's, checked against it), the header values as meta, and for plain
text the units and end conditions it declares.  read_profile (_profile)
looks the extension up in READERS, checks what is common to all formats
and makes the Profile; a new format is one reader and one entry in READERS.
The readers make no Profile: this module imports nothing of _profile.
"""
from __future__ import annotations

import math
import os
import re
import stat
import warnings
from typing import Any, Callable, Collection, Dict, List, Mapping, NamedTuple, Optional, Union

import numpy as np
import numpy.typing as npt

from ..._errors import RollerRigError, RollerRigWarning
from ..._typing import F64Array
from ._checks import BCS, KINDS, UNITS

#: a header value as _value reads it
HeaderValue = Union[int, float, str]


class RawProfile(NamedTuple):
    """What a reader returns: the points as the file gives them."""

    y: F64Array            #: lateral [m], the file's order
    z: F64Array            #: vertical [m], downward
    lines: npt.NDArray[np.integer[Any]]  #: the line of each point (for messages)
    kind: Optional[str]    #: "wheel"/"rail" the file says or the caller gave, else None
    meta: Dict[str, Any]   #: header values
    units: Optional[str] = None   #: the units read (plain text), else None
    bc: Optional[str] = None      #: end conditions the file declares, else None


def _value(text: str) -> HeaderValue:
    """A header value: int, float or string (quotes removed)."""
    t = text.strip()
    if len(t) >= 2 and t[0] == t[-1] and t[0] in "'\"":
        return t[1:-1]
    try:
        return int(t)
    except ValueError:
        pass
    try:
        return float(t)
    except ValueError:
        return t


def _numbers(where: str, lineno: int, text: str, expect: str) -> List[float]:
    """The numbers of a data line, or a RollerRigError naming the line."""
    fields = [f for f in re.split(r"[\s,;]+", text.strip()) if f]
    try:
        vals = [float(f) for f in fields]
    except ValueError:
        raise RollerRigError(f"{where}: line {lineno}: expected {expect}, got "
                             f"{text.strip()!r:.80}") from None
    bad = [v for v in vals if not math.isfinite(v)]
    if bad:
        raise RollerRigError(f"{where}: line {lineno}: non-finite value {bad[0]!r} in "
                             f"{text.strip()!r:.80}")
    return vals


def _strip_comment(line: str) -> str:
    """Text before a '!' that is not inside quotes (SIMPACK comments)."""
    quote: Optional[str] = None
    for k, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            return line[:k]
    return line


#: largest profile file read [bytes]: measured profiles are a few hundred kB
MAX_FILE_BYTES = 64 * 2**20


def _read_text_lines(path: str, where: str) -> List[str]:
    """The lines of a profile file.  Only a regular file is read: a FIFO or a
    device (even through a symlink) would block or never end, so the file is
    opened without blocking and checked before any byte is read."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except FileNotFoundError:
        raise RollerRigError(f"{where}: no such file") from None
    except IsADirectoryError:
        raise RollerRigError(f"{where}: is a directory, not a profile file") from None
    except OSError as e:
        raise RollerRigError(f"{where}: cannot be opened: {e.strerror}") from None
    st = os.fstat(fd)
    problem = ("is a directory, not a profile file" if stat.S_ISDIR(st.st_mode)
               else "is not a regular file (a FIFO, a device or a socket): give a profile "
                    "file" if not stat.S_ISREG(st.st_mode)
               else f"is {st.st_size / 2**20:.0f} MiB; a profile file is at most "
                    f"{MAX_FILE_BYTES // 2**20} MiB" if st.st_size > MAX_FILE_BYTES
               else None)
    if problem:
        os.close(fd)
        raise RollerRigError(f"{where}: {problem}")
    with os.fdopen(fd, "rb") as f:
        try:
            data = f.read(MAX_FILE_BYTES + 1)
        except OSError as e:
            raise RollerRigError(f"{where}: cannot be read: {e.strerror}") from None
    return data.decode("utf-8", errors="replace").splitlines()


def _read_simpack(path: str, where: str, kind: Optional[str],
                  units: Optional[str]) -> RawProfile:
    """SIMPACK .prw/.prr: sections header.begin/end (version, type: 0 rail,
    1 wheel) and spline.begin/end with 'key = value' lines and a nested
    point.begin/end block of 'y z [weight]' rows; '!' starts a comment (a
    commented-out point is no point; the S1002 file comments out its first,
    y = 70 mm on the flange back).  The points are then
    processed in the order of the numbers SIMPACK writes beside the keys, as
    CONTACT's reader does: 1 point.dist.min (drop a point closer than that to
    the last one kept), 2 shift.y/shift.z (added), 3 rotate (about x, from y
    towards z, in the angle unit units.ang.f = unit per rad), 4 bound.y
    (points outside dropped) and bound.z (clipped), each when min < max,
    5 mirror.y/mirror.z = 1 (y -> -y, z -> -z), 6 inversion = 1 (the point
    order reversed: it changes the direction SIMPACK walks the profile, not
    its shape), 7 units.len.f (length unit per metre: 1000 for mm; without it
    units.len 'mm'/'cm'/'m', else metres).  S1002: mirror.y = 1 turns the
    file's flange-side-positive points into ours (flange at y < 0),
    inversion = 1 only reorders.
    The header type beats the extension (with a warning); a caller's kind
    must agree with the header."""
    header: Dict[str, HeaderValue] = {}
    spline: Dict[str, HeaderValue] = {}
    rows: List[List[float]] = []
    lines: List[int] = []
    stack: List[str] = []
    text = _read_text_lines(path, where)
    for lineno, raw in enumerate(text, 1):
        s = _strip_comment(raw).strip()
        if not s:
            continue
        m = re.fullmatch(r"([A-Za-z_]\w*)\.(begin|end)", s)
        if m:
            sec, what = m.groups()
            if sec not in ("header", "spline", "point"):
                raise RollerRigError(f"{where}: line {lineno}: unknown section '{s}'")
            if what == "begin":
                if sec in stack or (sec == "point" and stack != ["spline"]) \
                        or (sec != "point" and stack):
                    raise RollerRigError(f"{where}: line {lineno}: '{s}' out of place "
                                         f"(open sections: {stack or 'none'})")
                stack.append(sec)
            elif stack and stack[-1] == sec:
                stack.pop()
            elif stack:
                raise RollerRigError(f"{where}: line {lineno}: '{s}' while section "
                                     f"'{stack[-1]}' is open")
            else:
                raise RollerRigError(f"{where}: line {lineno}: '{s}' without its "
                                     f"'{sec}.begin'")
            continue
        if stack == ["spline", "point"]:
            vals = _numbers(where, lineno, s, "'y z [weight]' numbers")
            if len(vals) not in (2, 3):
                raise RollerRigError(f"{where}: line {lineno}: expected 2 or 3 numbers "
                                     f"(y z [weight]), got {len(vals)}")
            rows.append(vals[:2])
            lines.append(lineno)
        elif "=" in s and stack in (["header"], ["spline"]):
            key, val = s.split("=", 1)
            (header if stack == ["header"] else spline)[key.strip()] = _value(val)
        else:
            raise RollerRigError(f"{where}: line {lineno}: unexpected text {s!r:.80} "
                                 f"(open sections: {stack or 'none'})")
    if stack:
        raise RollerRigError(f"{where}: file ends inside section '{stack[-1]}'")
    if not rows:
        raise RollerRigError(f"{where}: no points (no point.begin .. point.end block)")
    pts = np.array(rows, dtype=float)
    line_of = np.array(lines)

    def num(key: str, default: float) -> float:
        v = spline.get(key, default)
        try:
            x = math.nan if isinstance(v, (str, bool)) else float(v)
        except OverflowError:                      # an integer beyond the doubles
            x = math.inf
        if not math.isfinite(x):
            raise RollerRigError(f"{where}: {key} = {str(v)[:40]!r} is not a finite number")
        return x

    def flag(key: str) -> bool:
        v = spline.get(key, 0)
        if v not in (0, 1):
            raise RollerRigError(f"{where}: {key} must be 0 or 1, got {v!r}")
        return v == 1

    # 1 minimum point distance
    dmin = num("point.dist.min", 0.0)
    if dmin > 0.0:
        keep = [0]
        for i in range(1, len(pts)):
            if math.hypot(*(pts[i] - pts[keep[-1]])) > dmin:
                keep.append(i)
        pts, line_of = pts[keep], line_of[keep]
    # 2 shift
    pts = pts + np.array([num("shift.y", 0.0), num("shift.z", 0.0)])
    # 3 rotation about x
    ang_f = num("units.ang.f", 1.0)
    if ang_f <= 0.0:
        raise RollerRigError(f"{where}: units.ang.f must be > 0, got {ang_f!r}")
    rot = num("rotate", 0.0) / ang_f
    if rot != 0.0:
        c, s_ = math.cos(rot), math.sin(rot)
        pts = pts @ np.array([[c, s_], [-s_, c]])
    # 4 bounds
    ylo, yhi = num("bound.y.min", 1.0), num("bound.y.max", 0.0)
    if ylo < yhi:
        inside = (pts[:, 0] >= ylo) & (pts[:, 0] <= yhi)
        pts, line_of = pts[inside], line_of[inside]
    zlo, zhi = num("bound.z.min", 1.0), num("bound.z.max", 0.0)
    if zlo < zhi:
        pts[:, 1] = np.clip(pts[:, 1], zlo, zhi)
    # 5 mirroring, 6 inversion
    if flag("mirror.y"):
        pts[:, 0] = -pts[:, 0]
    if flag("mirror.z"):
        pts[:, 1] = -pts[:, 1]
    if flag("inversion"):
        pts, line_of = pts[::-1], line_of[::-1]
    # 7 units
    if "units.len.f" in spline:
        len_f = num("units.len.f", 1.0)
        if len_f <= 0.0:
            raise RollerRigError(f"{where}: units.len.f must be > 0, got {len_f!r}")
        name = spline.get("units.len")
        if isinstance(name, str) and name in UNITS and \
                not math.isclose(1.0 / UNITS[name], len_f, rel_tol=1e-9):
            raise RollerRigError(f"{where}: units.len = {name!r} contradicts units.len.f = "
                                 f"{len_f!r}")
    elif "units.len" in spline:
        name = spline["units.len"]
        if not isinstance(name, str) or name not in UNITS:     # (no number is a unit)
            raise RollerRigError(f"{where}: units.len = {name!r} is not one of "
                                 f"{sorted(UNITS)}")
        len_f = 1.0 / UNITS[name]
    else:
        len_f = 1.0
    pts = pts / len_f

    if "type" in header:
        t = header["type"]
        if t not in (0, 1):
            raise RollerRigError(f"{where}: header type must be 0 (rail) or 1 (wheel), "
                                 f"got {t!r}")
        file_kind = "wheel" if t == 1 else "rail"
        ext = os.path.splitext(path)[1].lower()
        ext_kind = READERS[ext].kind if ext in READERS else None
        if kind is not None and file_kind != kind:
            raise RollerRigError(f"{where}: kind = {kind!r} but the header says type = "
                                 f"{t} ({file_kind})")
        if kind is None and ext_kind is not None and file_kind != ext_kind:
            warnings.warn(f"{where}: header type says {file_kind}, the extension "
                          f"{ext} {ext_kind}; read as {file_kind}", RollerRigWarning,
                          stacklevel=3)
        kind = file_kind
    meta = {f"header.{k}": v for k, v in header.items()}
    meta.update({f"spline.{k}": v for k, v in spline.items()})
    if spline.get("approx.smooth", 0) not in (0, 0.0):
        warnings.warn(f"{where}: approx.smooth = {spline['approx.smooth']!r} (SIMPACK's "
                      f"smoothing) is not applied; pass smoothing= for ours",
                      RollerRigWarning, stacklevel=3)
    return RawProfile(pts[:, 0], pts[:, 1], line_of, kind, meta)


def _read_miniprof(path: str, where: str, kind: Optional[str],
                   units: Optional[str]) -> RawProfile:
    """MiniProf .whl/.ban: 'Key=value' header lines, then one point per line
    (fields separated by blanks or commas) in millimetres, in the columns
    that ColumnDef names (default 'X,Y'): X lateral, Y vertical, both already
    in our orientation (field side positive, downward positive; wheels with
    y = 0 at the flange back).  XYPoints, when given, must equal the number
    of points.  Returns (y [m], z [m], line numbers, None, meta)."""
    meta: Dict[str, Any] = {}
    rows: List[List[float]] = []
    lines: List[int] = []
    text = _read_text_lines(path, where)
    for lineno, raw in enumerate(text, 1):
        s = raw.strip()
        if not s:
            continue
        if "=" in s:
            if rows:
                raise RollerRigError(f"{where}: line {lineno}: header line {s!r:.60} after "
                                     f"the points")
            key, val = s.split("=", 1)
            meta[key.strip()] = _value(val)
            continue
        if s.startswith("["):
            raise RollerRigError(f"{where}: line {lineno}: sections like {s!r:.40} belong to "
                                 f"multi-part MiniProf files (.mpt), not read here")
        rows.append(_numbers(where, lineno, s, "numbers"))
        lines.append(lineno)
    coldef = str(meta.get("ColumnDef", "X,Y"))
    cols = [c.strip().upper() for c in coldef.split(",")]
    if "X" not in cols or "Y" not in cols:
        raise RollerRigError(f"{where}: ColumnDef = {coldef!r} must name the columns X and Y")
    for vals, lineno in zip(rows, lines):
        if len(vals) != len(cols):
            raise RollerRigError(f"{where}: line {lineno}: {len(vals)} number(s) but "
                                 f"ColumnDef = {coldef!r} declares {len(cols)}")
    if "XYPoints" in meta:
        count = meta["XYPoints"]
        if not isinstance(count, int) or count != len(rows):
            raise RollerRigError(f"{where}: XYPoints = {count!r} but the file has "
                                 f"{len(rows)} points")
    pts = np.array(rows, dtype=float).reshape(len(rows), len(cols))
    ix, iz = cols.index("X"), cols.index("Y")
    return RawProfile(pts[:, ix] * 1e-3, pts[:, iz] * 1e-3, np.array(lines, dtype=int), kind,
                      meta)


def _read_text(path: str, where: str, kind: Optional[str],
               units: Optional[str]) -> RawProfile:
    """Plain text: one point per line, 'lateral vertical' separated by blanks,
    a comma or a semicolon, in our orientation.  Empty lines and lines
    starting with '#', '!' or '%' are skipped; comment lines of the form
    '# key = value' become meta (name, kind, units and bc are used).  A first
    line whose fields are all non-numeric is taken as column names.  A
    caller's kind and units must agree with the file's."""
    meta: Dict[str, Any] = {}
    rows: List[List[float]] = []
    lines: List[int] = []
    text = _read_text_lines(path, where)
    seen_data = False
    for lineno, raw in enumerate(text, 1):
        s = raw.strip()
        if not s:
            continue
        if s[0] in "#!%":
            m = re.fullmatch(r"[#!%]\s*([A-Za-z_][\w.]*)\s*=\s*(.*)", s)
            if m:
                meta[m.group(1)] = _value(m.group(2))
            continue
        fields = [f for f in re.split(r"[\s,;]+", s) if f]
        if not seen_data and fields and all(_not_number(f) for f in fields):
            meta["columns"] = " ".join(fields)
            seen_data = True
            continue
        seen_data = True
        vals = _numbers(where, lineno, s, "two numbers 'lateral vertical'")
        if len(vals) != 2:
            raise RollerRigError(f"{where}: line {lineno}: expected two numbers "
                                 f"'lateral vertical', got {len(vals)}")
        rows.append(vals)
        lines.append(lineno)
    file_units = _header_value(where, meta, "units", UNITS, f"one of {sorted(UNITS)}", units)
    units = units or file_units or "mm"
    if not rows:
        raise RollerRigError(f"{where}: no points")
    pts = np.array(rows, dtype=float) * UNITS[units]
    file_kind = _header_value(where, meta, "kind", KINDS, "'wheel' or 'rail'", kind)
    bc = _header_value(where, meta, "bc", BCS, f"one of {BCS}")
    return RawProfile(pts[:, 0], pts[:, 1], np.array(lines, dtype=int), kind or file_kind,
                      meta, units, bc)


def _header_value(where: str, meta: Mapping[str, Any], key: str, allowed: Collection[str],
                  shown: str, given: Optional[str] = None) -> Optional[str]:
    """A header key's value (None if absent): one of `allowed`, and the same
    as the caller's `given` where both are set."""
    value: Optional[str] = meta.get(key)    # a str once found in `allowed`
    if value is not None and value not in allowed:
        raise RollerRigError(f"{where}: {key} = {value!r} in the file is not {shown}")
    if value is not None and given is not None and given != value:
        raise RollerRigError(f"{where}: {key} = {given!r} contradicts the file's "
                             f"{key} = {value!r}")
    return value


def _not_number(field: str) -> bool:
    try:
        float(field)
    except ValueError:
        return True
    return False


class Format(NamedTuple):
    """A file format of READERS, read_profile's table by extension."""

    name: str               #: the format's name (meta["format"])
    read: Callable[..., RawProfile]  #: its reader: (path, where, kind, units) -> RawProfile
    #: the kind its extension implies (None: the file or the caller must say)
    kind: Optional[str]
    takes_units: bool       #: whether read_profile's units apply (other formats fix their own)


#: the formats by file extension (lower case): read_profile dispatches on it
READERS = {
    ".prr": Format("simpack", _read_simpack, "rail", False),
    ".prw": Format("simpack", _read_simpack, "wheel", False),
    ".ban": Format("miniprof", _read_miniprof, "rail", False),
    ".whl": Format("miniprof", _read_miniprof, "wheel", False),
    ".txt": Format("text", _read_text, None, True),
    ".csv": Format("text", _read_text, None, True),
    ".dat": Format("text", _read_text, None, True),
}
# the old per-format tables, derived
SIMPACK_EXT = {e: f.kind for e, f in READERS.items() if f.name == "simpack"}
MINIPROF_EXT = {e: f.kind for e, f in READERS.items() if f.name == "miniprof"}
TEXT_EXT = tuple(e for e, f in READERS.items() if f.name == "text")
