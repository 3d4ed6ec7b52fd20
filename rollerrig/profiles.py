"""Wheel and rail/roller profiles: readers, checks and a C2 cubic spline.

A :class:`Profile` is the cross-section of a wheel tread or of a rail head
(a roller of the rig carries a rail-head shape: its kind is ``"rail"``) as a
single-valued curve z(y), held as points and interpolated by a cubic spline.

Conventions (SIMPACK's and MiniProf's, which CONTACT shares)
------------------------------------------------------------
* SI units: y and z in metres; slopes dimensionless; curvature in 1/m.
* y is lateral, positive towards the FIELD side (away from the track
  centre, outward), for the profile's own side of the track.  The flange
  of a wheel, and the gauge face of a rail, lie at the negative-y end.
* z is vertical, positive DOWNWARD, the same for wheels and rails.  A rail
  or roller has its material below the curve (z larger than the profile),
  a wheel above it (z smaller).
* References as the files give them: the UIC60 rail has z = 0 at the top of
  its head (at y = -0.2 mm; the benchmark rail is already canted 1:40); the
  S1002 wheel has y = 0 at the taping line with z = 0 there, the flange tip
  28 mm below at y = -55 mm and the flange back at y = -70 mm.  MiniProf
  wheels have y = 0 at the flange back (the taping line is then at
  ``WheelDiameterTaperline``, 70 mm) and MiniProf rails their own origin.
* So a wheel and a rail drawn in the same axes sit one above the other:
  the rail head's top near z = 0 and the wheel tread just above it; moved
  by ``wheel.shifted(dy, dz)`` the gap is ``rail.z_at(y) - wheel.z_at(y)``
  (>= 0 where they do not overlap).  The right-hand side of a track is the
  mirror image: ``profile.mirrored()``.
* Curvature ``kappa = z'' / (1 + z'^2)^1.5`` is signed: positive where the
  curve bends towards +z (down).  For a rail or roller that is a convex
  surface (the UIC60 crown: +1/0.3 m); for a wheel a concave one (the flange
  root), and its convex tread has kappa < 0.  The lateral curvature sum of
  the Hertz module (contact.hertz, gap h = A x^2 + B y^2) at a contact point
  is therefore ``B = (kappa_rail - kappa_wheel) / 2``, each profile's kappa
  taken at its own contact point (curvature does not change under the
  wheelset's roll rotation).
* Point order never matters: a Profile stores y strictly increasing.

Interpolation
-------------
A C2 cubic spline through the points (not-a-knot end conditions by default,
``bc="natural"`` on request), its slopes found by a tridiagonal solve.  The
paper interpolates with parabolas; a piecewise parabola is at best C1, so
its second derivative -- the profile curvature that sets the lateral
semi-axis of the Hertz ellipse -- jumps at every node: the contact patch
would jump as the contact point moves across a node, and contact tables
interpolated in y would inherit the steps.  The cubic spline has continuous
curvature (piecewise linear in y), is the interpolant of least bending
energy (it minimises the integral of z''^2, so it does not add wiggles), and
converges as h^4 in z and h^2 in curvature on smooth data.

Measured profiles carry noise that the curvature amplifies (1/h^2).
``smoothing=L`` [m] replaces the interpolating spline by the penalised
least-squares smoothing spline (Reinsch 1967): it minimises
``sum w_i (z_i - f(y_i))^2 + lam * integral f''^2 dy`` with w_i the lateral
length each point stands for (trapezoid weights, so the result does not
depend on the point density) and ``lam = (L / 2 pi)^4``.  A ripple of
wavelength W passes with the gain 1 / (1 + (L/W)^4): half its amplitude at
W = L, 0.4 % lost at W = 4 L, 99.6 % removed at W = L/4; straight lines,
parabolas and cubics pass unchanged away from the ends (a crown keeps its
radius).
The smoothing spline is natural (z'' = 0 at both ends).  On the shipped
MiniProf profiles (points 0.25 mm apart) 1 to 3 mm remove the point-to-point
jitter of the curvature and keep its features of 10 mm wavelength; noise
of 1 um on points 0.25 mm apart needs about 10 mm before a crown radius
shows within 10 % (tests).  Smoothing works on z(y): on steep faces
(|z'| >> 1, the flange back, a gauge face) it moves points vertically by
up to ~0.5 mm; it is meant for the running surface.

Reading files
-------------
``read_profile(path)`` chooses the format by the extension: SIMPACK ``.prw``
(wheel) and ``.prr`` (rail), MiniProf ``.whl`` (wheel) and ``.ban`` (rail),
and plain two-column text ``.txt``, ``.csv``, ``.dat`` (lateral, vertical;
millimetres unless ``units="m"``).  Each reader documents its own rules.
Checks raise RollerRigError naming the file and the line: text where a
number should be, NaN or infinite values, fewer than 4 points, repeated y,
coordinates beyond 2 m (millimetres read as metres) or a profile narrower
than 1 mm (metres read as millimetres), a point count that contradicts the
header.

Folds.  A measuring instrument that follows a vertical face (the flange
back, a rail's gauge face below the head) may return points whose y steps
back.  The profile is kept single-valued by the rule of CONTACT's
``delete_foldback``: starting at the point that certainly lies on the
running surface (the top of a rail head, min z; the flange tip of a wheel,
max z) the points are walked outward to both ends and each one is kept
only if it extends the lateral range covered so far; the points dropped
(the fold) are reported in a RollerRigWarning with their count and extent
(``on_fold="raise"`` makes a fold an error instead).  A point that only
repeats the y of the point before it, without stepping back, is not a fold
but a duplicate: always an error.  The shipped rollers fold on their gauge
face, 17 to 52 mm below the top, away from any contact: 6 and 4 points go.
"""
import contextlib
import math
import os
import re
import stat
import warnings
from types import MappingProxyType

import numpy as np

from ._errors import RollerRigError, RollerRigWarning

__all__ = ["Profile", "read_profile", "KINDS", "DATA_DIR", "MIN_POINTS"]

KINDS = ("wheel", "rail")
BCS = ("not-a-knot", "natural")
MIN_POINTS = 4
MIN_SPACING = 1e-12  #: [m] closer points are a mistake (measured profiles: 1e-9 at least)
MAX_POINTS = 100_000   #: more points than any measured profile has (MiniProf: ~1000)
MAX_COORD = 2.0     #: [m] larger coordinates are taken for a unit mistake
MIN_WIDTH = 1e-3    #: [m] a narrower profile is taken for a unit mistake
DATA_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "profiles")

UNITS = {"m": 1.0, "cm": 1e-2, "mm": 1e-3}     # metres per unit
SIMPACK_EXT = {".prw": "wheel", ".prr": "rail"}
MINIPROF_EXT = {".whl": "wheel", ".ban": "rail"}
TEXT_EXT = (".txt", ".csv", ".dat")


# ---------------------------------------------------------------- spline numerics

def _solve_tridiagonal(sub, diag, sup, rhs):
    """Thomas algorithm; sub[0] and sup[-1] are unused.  Stable for the
    diagonally dominant systems built below."""
    n = len(diag)
    c = np.empty(n)
    d = np.empty(n)
    c[0] = sup[0] / diag[0] if n > 1 else 0.0
    d[0] = rhs[0] / diag[0]
    for i in range(1, n):
        m = diag[i] - sub[i] * c[i - 1]
        c[i] = sup[i] / m if i < n - 1 else 0.0
        d[i] = (rhs[i] - sub[i] * d[i - 1]) / m
    x = np.empty(n)
    x[-1] = d[-1]
    for i in range(n - 2, -1, -1):
        x[i] = d[i] - c[i] * x[i + 1]
    return x


def _spline_slopes(y, z, bc):
    """Node slopes of the C2 cubic spline through (y, z).

    Continuity of z'' at the interior nodes gives, for i = 1 .. n-2,
        h_i s_{i-1} + 2 (h_{i-1} + h_i) s_i + h_{i-1} s_{i+1}
            = 3 (h_i d_{i-1} + h_{i-1} d_i),
    with h_i = y_{i+1} - y_i and d_i = (z_{i+1} - z_i) / h_i.  The natural
    ends (z'' = 0) add 2 s_0 + s_1 = 3 d_0 and s_{n-2} + 2 s_{n-1} = 3 d_{n-2}:
    diagonally dominant.  The not-a-knot ends (z''' continuous at the second
    and the last-but-one node) add rows that are not dominant; each is
    eliminated into its neighbour, which leaves a dominant system in
    s_1 .. s_{n-2}; s_0 and s_{n-1} follow from the end rows.
    """
    n = len(y)
    h = np.diff(y)
    d = np.diff(z) / h
    sub = np.zeros(n)
    diag = np.zeros(n)
    sup = np.zeros(n)
    rhs = np.zeros(n)
    sub[1:-1] = h[1:]
    diag[1:-1] = 2.0 * (h[:-1] + h[1:])
    sup[1:-1] = h[:-1]
    rhs[1:-1] = 3.0 * (h[1:] * d[:-1] + h[:-1] * d[1:])
    if bc == "natural":
        diag[0], sup[0], rhs[0] = 2.0, 1.0, 3.0 * d[0]
        sub[-1], diag[-1], rhs[-1] = 1.0, 2.0, 3.0 * d[-1]
        return _solve_tridiagonal(sub, diag, sup, rhs)
    # not-a-knot end rows
    w0 = h[0] + h[1]
    a0, c0 = h[1], w0
    r0 = ((h[0] + 2.0 * w0) * h[1] * d[0] + h[0] ** 2 * d[1]) / w0
    w1 = h[-1] + h[-2]
    an, bn = h[-2], w1
    rn = (h[-1] ** 2 * d[-2] + (2.0 * w1 + h[-1]) * h[-2] * d[-1]) / w1
    # row 1 -= (sub_1 / a0) row 0 ; row n-2 -= (sup_{n-2} / an) row n-1
    f = sub[1] / a0
    diag[1] -= f * c0
    rhs[1] -= f * r0
    sub[1] = 0.0
    g = sup[-2] / an
    diag[-2] -= g * bn
    rhs[-2] -= g * rn
    sup[-2] = 0.0
    s = np.empty(n)
    s[1:-1] = _solve_tridiagonal(sub[1:-1], diag[1:-1], sup[1:-1], rhs[1:-1])
    s[0] = (r0 - c0 * s[1]) / a0
    s[-1] = (rn - bn * s[-2]) / an
    return s


def _solve_pentadiagonal_spd(d0, d1, d2, b):
    """Solve M x = b for a symmetric positive definite M given by its main
    diagonal d0, first and second super-diagonals d1, d2 (LDL^T, no pivoting).
    Returns (x, None), or (None, i) if pivot i is below 1e-12 of its diagonal
    entry: M's condition number then exceeds 1e12 and x keeps no digits
    worth having (a pivot of 0 made x NaN)."""
    m = len(d0)
    D = np.empty(m)
    L1 = np.zeros(m)   # L[i, i-1]
    L2 = np.zeros(m)   # L[i, i-2]
    for i in range(m):
        if i >= 2:
            L2[i] = d2[i - 2] / D[i - 2]
        if i >= 1:
            t = d1[i - 1] - (L2[i] * D[i - 2] * L1[i - 1] if i >= 2 else 0.0)
            L1[i] = t / D[i - 1]
        D[i] = d0[i] - L1[i] ** 2 * (D[i - 1] if i >= 1 else 0.0) \
            - L2[i] ** 2 * (D[i - 2] if i >= 2 else 0.0)
        if not D[i] > 1e-12 * d0[i]:
            return None, i
    x = np.array(b, dtype=float)
    for i in range(1, m):
        x[i] -= L1[i] * x[i - 1] + (L2[i] * x[i - 2] if i >= 2 else 0.0)
    x /= D
    for i in range(m - 2, -1, -1):
        x[i] -= L1[i + 1] * x[i + 1] + (L2[i + 2] * x[i + 2] if i + 2 < m else 0.0)
    return x, None


def _smoothing_weights(y):
    """Trapezoid weights: the lateral length each point stands for."""
    h = np.diff(y)
    w = np.empty(len(y))
    w[0] = 0.5 * h[0]
    w[-1] = 0.5 * h[-1]
    w[1:-1] = 0.5 * (h[:-1] + h[1:])
    return w


def _smooth(y, z, lam):
    """Values at the nodes of the natural cubic smoothing spline minimising
    sum w_i (z_i - f_i)^2 + lam * integral f''^2 (Reinsch's algorithm, Green
    and Silverman 1994, sec. 2.3): (R + lam Q^T W^-1 Q) g = Q^T z and
    f = z - lam W^-1 Q g, g the second derivatives at the interior nodes.
    Returns (f, None), or (None, j) if the system is numerically singular
    near node j (points far closer together than the smoothing length)."""
    w = _smoothing_weights(y)
    h = np.diff(y)
    # column j (interior node j = 1 .. n-2) of Q: rows j-1, j, j+1
    a = 1.0 / h[:-1]                    # Q[j-1, j]
    c = 1.0 / h[1:]                     # Q[j+1, j]
    b = -a - c                          # Q[j, j]
    wm, w0, wp = w[:-2], w[1:-1], w[2:]
    d0 = (h[:-1] + h[1:]) / 3.0 + lam * (a * a / wm + b * b / w0 + c * c / wp)
    d1 = h[1:-1] / 6.0 + lam * (b[:-1] * a[1:] / w0[:-1] + c[:-1] * b[1:] / wp[:-1])
    d2 = lam * (c[:-2] * a[2:] / wp[:-2])
    dz = np.diff(z) / h
    g, bad = _solve_pentadiagonal_spd(d0, d1, d2, dz[1:] - dz[:-1])
    if g is None:
        return None, bad + 1
    qg = np.zeros(len(y))
    qg[:-2] += a * g
    qg[1:-1] += b * g
    qg[2:] += c * g
    return z - lam * qg / w, None


# ---------------------------------------------------------------- input checks

def _as_float_array(func, name, value):
    arr = np.asarray(value)
    if arr.dtype.kind not in "iuf":
        raise RollerRigError(f"{func}: {name} must be real numbers, got dtype {arr.dtype} "
                             f"({value!r:.60})")
    return arr.astype(np.float64)


def _check_number(func, name, value, positive=False, allow_none=False):
    if value is None and allow_none:
        return None
    ok = isinstance(value, (int, float, np.integer, np.floating)) \
        and not isinstance(value, bool) and math.isfinite(value) \
        and (value > 0 if positive else True)
    if not ok:
        what = "a positive finite number" if positive else "a finite number"
        raise RollerRigError(f"{func}: {name} must be {what}"
                             f"{' or None' if allow_none else ''}, got {value!r}")
    return float(value)


def _check_kind(func, kind):
    if kind not in KINDS:
        raise RollerRigError(f"{func}: kind must be 'wheel' or 'rail' (a roller is 'rail'), "
                             f"got {kind!r}")
    return kind


def _check_bc(func, bc, smoothing):
    if bc is None:
        return "natural" if smoothing is not None else "not-a-knot"
    if bc not in BCS:
        raise RollerRigError(f"{func}: bc must be 'not-a-knot', 'natural' or None, got {bc!r}")
    if smoothing is not None and bc != "natural":
        raise RollerRigError(f"{func}: a smoothing spline is natural: bc = {bc!r} cannot go "
                             f"with smoothing = {smoothing!r} (leave bc = None)")
    return bc


def _label(labels, i):
    """'line 12' (files) or 'point 12' (arrays) for point i."""
    return f"{labels[1]} {labels[0][i]}"


def _check_scale(where, y, z, labels):
    big = np.abs(np.concatenate([y, z]))
    k = int(np.argmax(big))
    if big[k] > MAX_COORD:
        i = k % len(y)
        raise RollerRigError(
            f"{where}: coordinate {big[k]:.6g} m at {_label(labels, i)} is beyond "
            f"{MAX_COORD:g} m: the numbers look like millimetres read as metres (units='mm')")
    width = float(y.max() - y.min())
    if width < MIN_WIDTH:
        raise RollerRigError(
            f"{where}: the profile's y spans only {width:.3g} m (< {MIN_WIDTH * 1e3:g} mm): "
            f"the numbers look like metres read as millimetres (units='m')")


def _single_valued(where, y, z, kind, labels, on_fold):
    """Keep the single-valued branch through the running surface.

    y, z in the profile's (ascending) order.  Returns the boolean mask of the
    points kept and a description of the folds removed.  Raises on a pure
    duplicate, and on any fold when on_fold == 'raise'.
    """
    n = len(y)
    anchor = int(np.argmin(z)) if kind == "rail" else int(np.argmax(z))
    keep = np.zeros(n, dtype=bool)
    keep[anchor] = True
    runs = []                                      # (indices, extreme y before the run)
    for step, indices in ((1, range(anchor + 1, n)), (-1, range(anchor - 1, -1, -1))):
        ext = y[anchor]
        run = []
        for i in indices:
            if step * (y[i] - ext) > 0.0:
                if run:
                    runs.append((run, ext))
                    run = []
                keep[i] = True
                ext = y[i]
            else:
                run.append(i)
        if run:
            runs.append((run, ext))
    for run, ext in runs:
        if np.all(y[run] == ext):
            i = run[0]
            j = i - 1 if i > anchor else i + 1
            a, b = sorted((i, j))
            raise RollerRigError(
                f"{where}: duplicate y = {y[i]:.9g} m at {_label(labels, a)} and "
                f"{_label(labels, b)}: z(y) would be two-valued; remove one point")
    if not runs:
        return keep, ""
    dropped = np.flatnonzero(~keep)
    first = min(dropped, key=lambda i: labels[0][i])
    desc = (f"{len(dropped)} point(s) where the profile folds back (y steps back at "
            f"{_label(labels, first)}), y {y[dropped].min() * 1e3:.4g} .. "
            f"{y[dropped].max() * 1e3:.4g} mm, z {z[dropped].min() * 1e3:.4g} .. "
            f"{z[dropped].max() * 1e3:.4g} mm")
    if on_fold == "raise":
        raise RollerRigError(f"{where}: {desc}; pass on_fold='trim' to keep the "
                             f"single-valued branch through the running surface")
    return keep, desc


def _prepare(where, y, z, kind, labels, on_fold, mirror_y=False, mirror_z=False):
    """From raw points in metres (file order) to ascending, single-valued
    points.  Returns (y, z, notes dict)."""
    if on_fold not in ("trim", "raise"):
        raise RollerRigError(f"{where}: on_fold must be 'trim' or 'raise', got {on_fold!r}")
    n = len(y)
    bad = np.flatnonzero(~(np.isfinite(y) & np.isfinite(z)))
    if bad.size:
        i = int(bad[0])
        raise RollerRigError(f"{where}: non-finite value (y = {y[i]!r}, z = {z[i]!r}) at "
                             f"{_label(labels, i)}")
    if n < MIN_POINTS:
        raise RollerRigError(f"{where}: {n} point(s); a profile needs at least {MIN_POINTS}")
    if mirror_y:
        y = -y
    if mirror_z:
        z = -z
    _check_scale(where, y, z, labels)
    notes = {}
    if y[-1] < y[0]:
        y, z = y[::-1], z[::-1]
        labels = (labels[0][::-1], labels[1])
        notes["order"] = "reversed to ascending y"
    keep, desc = _single_valued(where, y, z, kind, labels, on_fold)
    if desc:
        warnings.warn(f"{where}: removed {desc}", RollerRigWarning, stacklevel=3)
        notes["folds_removed"] = int((~keep).sum())
        y, z = y[keep], z[keep]
    if len(y) < MIN_POINTS:
        raise RollerRigError(f"{where}: {len(y)} point(s) left after removing the folds; "
                             f"a profile needs at least {MIN_POINTS}")
    return np.ascontiguousarray(y), np.ascontiguousarray(z), notes


# ---------------------------------------------------------------- the profile

class Profile:
    """An immutable wheel or rail/roller profile z(y) with its cubic spline.

    Profile(y, z, kind=..., name="", meta=None, bc=None, smoothing=None)

    y, z:      1-D arrays [m]: y strictly increasing, towards the field side;
               z downward (module docstring).  At least 4 finite points,
               |y|, |z| <= 2 m, at least 1 mm wide.
    kind:      "wheel" or "rail" (a roller is "rail").
    name:      a label; meta: a dict of header values, read-only afterwards.
    bc:        spline end conditions, "not-a-knot" (default) or "natural".
    smoothing: None (interpolate the points) or a wavelength L [m]: the
               natural smoothing spline with lam = (L / 2 pi)^4 (module
               docstring).  ``z`` then holds the smoothed values at the nodes
               and ``z_input`` the points given.

    The constructor is strict (it raises RollerRigError for points out of
    order); ``Profile.from_points`` and ``read_profile`` reorder points and
    remove folds first.  Evaluation (``z_at``, ``slope``, ``second_derivative``,
    ``curvature``, ``evaluate``) takes numbers or arrays, returns floats or
    arrays of the same shape, and gives NaN outside [y_min, y_max].
    """

    __slots__ = ("_y", "_z", "_z_input", "_s", "_c2", "_c3", "_kind", "_name", "_meta",
                 "_bc", "_smoothing")

    def __init__(self, y, z, *, kind, name="", meta=None, bc=None, smoothing=None):
        func = "Profile"
        _check_kind(func, kind)
        smoothing = _check_number(func, "smoothing", smoothing, positive=True,
                                  allow_none=True)
        if smoothing is not None and smoothing > MAX_COORD:
            raise RollerRigError(f"{func}: smoothing is a wavelength [m] up to {MAX_COORD:g} "
                                 f"m (the profile's own scale), got {smoothing!r}")
        bc = _check_bc(func, bc, smoothing)
        y = _as_float_array(func, "y", y)
        z = _as_float_array(func, "z", z)
        if y.ndim != 1 or z.ndim != 1 or y.shape != z.shape:
            raise RollerRigError(f"{func}: y and z must be 1-D arrays of one length, got "
                                 f"shapes {y.shape} and {z.shape}")
        if not MIN_POINTS <= len(y) <= MAX_POINTS:
            raise RollerRigError(f"{func}: y and z hold {len(y)} point(s); a profile has "
                                 f"from {MIN_POINTS} to {MAX_POINTS}")
        bad = np.flatnonzero(~(np.isfinite(y) & np.isfinite(z)))
        if bad.size:
            i = int(bad[0])
            raise RollerRigError(f"{func}: non-finite value at index {i}: y = {y[i]!r}, "
                                 f"z = {z[i]!r}")
        dy = np.diff(y)
        close = np.flatnonzero((dy > 0.0) & (dy < MIN_SPACING))
        if close.size:
            i = int(close[0])
            raise RollerRigError(
                f"{func}: y[{i}] = {y[i]!r} and y[{i + 1}] = {y[i + 1]!r} are less than "
                f"{MIN_SPACING:g} m apart: no spline through such points is meaningful")
        if np.any(dy <= 0.0):
            i = int(np.flatnonzero(dy <= 0.0)[0])
            what = "duplicate y" if dy[i] == 0.0 else "y decreases"
            raise RollerRigError(
                f"{func}: y must be strictly increasing: {what} at index {i + 1} "
                f"(y[{i}] = {y[i]!r}, y[{i + 1}] = {y[i + 1]!r}); Profile.from_points "
                f"reorders points and removes folds")
        _check_scale(func, y, z, (np.arange(len(y)), "index"))
        zn = z
        if smoothing is not None:
            zn, j = _smooth(y, z, (smoothing / (2.0 * math.pi)) ** 4)
            if zn is None:
                raise RollerRigError(
                    f"{func}: smoothing = {smoothing!r} m is numerically singular on these "
                    f"points near index {j} (y[{j}] = {y[j]!r}; point spacings from "
                    f"{np.min(np.diff(y)):.3g} to {np.max(np.diff(y)):.3g} m): space the "
                    f"points more evenly, remove near-duplicates, or smooth less")
        s = _spline_slopes(y, zn, bc)
        h = np.diff(y)
        d = np.diff(zn) / h
        c2 = (3.0 * d - 2.0 * s[:-1] - s[1:]) / h
        c3 = (s[:-1] + s[1:] - 2.0 * d) / (h * h)
        for arr in (y, zn, z, s, c2, c3):
            arr.flags.writeable = False
        meta = dict(meta or {})
        set_ = object.__setattr__
        set_(self, "_y", y)
        set_(self, "_z", zn)
        set_(self, "_z_input", z)
        set_(self, "_s", s)
        set_(self, "_c2", c2)
        set_(self, "_c3", c3)
        set_(self, "_kind", kind)
        set_(self, "_name", str(name))
        set_(self, "_meta", MappingProxyType(meta))
        set_(self, "_bc", bc)
        set_(self, "_smoothing", smoothing)

    # -- immutability, pickling, display

    def __setattr__(self, name, value):
        raise AttributeError(f"Profile is immutable (cannot set {name!r}); use shifted(), "
                             f"mirrored() or a new Profile")

    def __delattr__(self, name):
        raise AttributeError(f"Profile is immutable (cannot delete {name!r})")

    def __reduce__(self):
        return (_rebuild, (np.array(self._y), np.array(self._z_input), self._kind,
                           self._name, dict(self._meta), self._bc, self._smoothing))

    def __repr__(self):
        sm = f", smoothing={self._smoothing:g}" if self._smoothing is not None else ""
        return (f"Profile(kind={self._kind!r}, name={self._name!r}, {len(self._y)} points, "
                f"y {self._y[0] * 1e3:.4g} .. {self._y[-1] * 1e3:.4g} mm, bc={self._bc!r}{sm})")

    def __len__(self):
        return len(self._y)

    # -- attributes

    @property
    def y(self):
        """Node abscissae [m], strictly increasing (read-only array)."""
        return self._y

    @property
    def z(self):
        """Spline values at the nodes [m]: the points given, or their smoothed values."""
        return self._z

    @property
    def z_input(self):
        """The z values given (equal to ``z`` unless smoothing is set)."""
        return self._z_input

    @property
    def kind(self):
        return self._kind

    @property
    def name(self):
        return self._name

    @property
    def meta(self):
        """Header values and reading notes (a read-only mapping)."""
        return self._meta

    @property
    def bc(self):
        return self._bc

    @property
    def smoothing(self):
        return self._smoothing

    @property
    def y_min(self):
        return float(self._y[0])

    @property
    def y_max(self):
        return float(self._y[-1])

    # -- evaluation

    def _locate(self, func, y):
        arr = _as_float_array(f"Profile.{func}", "y", y)
        flat = arr.reshape(-1)
        i = np.clip(np.searchsorted(self._y, flat, side="right") - 1, 0, len(self._y) - 2)
        out = ~((flat >= self._y[0]) & (flat <= self._y[-1]))   # also NaN
        t = np.where(out, 0.0, flat - self._y[i])     # no overflow far outside
        return arr, i, t, out

    @staticmethod
    def _shape(arr, values):
        values = values.reshape(arr.shape)
        return float(values) if arr.ndim == 0 else values

    def evaluate(self, y):
        """(z, dz/dy, d2z/dy2) at y: three floats or arrays; NaN outside the profile."""
        return self._evaluate("evaluate", y)

    def _evaluate(self, func, y):
        arr, i, t, out = self._locate(func, y)
        s, c2, c3 = self._s[i], self._c2[i], self._c3[i]
        z = self._z[i] + t * (s + t * (c2 + t * c3))
        dz = s + t * (2.0 * c2 + 3.0 * c3 * t)
        d2z = 2.0 * c2 + 6.0 * c3 * t
        for v in (z, dz, d2z):
            v[out] = np.nan
        return self._shape(arr, z), self._shape(arr, dz), self._shape(arr, d2z)

    def z_at(self, y):
        """z(y) [m] (NaN outside [y_min, y_max])."""
        arr, i, t, out = self._locate("z_at", y)
        z = self._z[i] + t * (self._s[i] + t * (self._c2[i] + t * self._c3[i]))
        z[out] = np.nan
        return self._shape(arr, z)

    def slope(self, y):
        """dz/dy (z down, y to the field side: a wheel coned as usual has
        slope -tan(cone angle) on its tread)."""
        return self._evaluate("slope", y)[1]

    def second_derivative(self, y):
        """d2z/dy2 [1/m]."""
        return self._evaluate("second_derivative", y)[2]

    def curvature(self, y):
        """Signed curvature z'' / (1 + z'^2)^1.5 [1/m]: positive where the
        curve bends downward (+z): convex for a rail or roller, concave for a
        wheel.  Hertz: B = (kappa_rail - kappa_wheel) / 2."""
        _, dz, d2z = self._evaluate("curvature", y)
        return d2z / (1.0 + np.square(dz)) ** 1.5

    # -- new profiles from this one

    def _derived(self, func, y, z, name, note):
        meta = dict(self._meta)
        meta["derived"] = tuple(meta.get("derived", ())) + (note,)
        with _named(func):
            return Profile(y, z, kind=self._kind, name=name, meta=meta, bc=self._bc,
                           smoothing=self._smoothing)

    def shifted(self, dy=0.0, dz=0.0):
        """The profile moved by dy laterally and dz downward [m]."""
        dy = _check_number("Profile.shifted", "dy", dy)
        dz = _check_number("Profile.shifted", "dz", dz)
        return self._derived("Profile.shifted", self._y + dy, self._z_input + dz, self._name,
                             f"shifted by dy = {dy!r} m, dz = {dz!r} m")

    def gauge_point(self, depth=0.014):
        """Lateral position [m] of a rail's (or roller's) gauge face at `depth`
        below z = 0, the top of the head in rail profiles (the gauge is
        measured there: 14 mm, EN 13848-1), on the gauge side of the top;
        bisection on the spline."""
        func = "Profile.gauge_point"
        depth = _check_number(func, "depth", depth, positive=True)
        lo, hi = self.y_min, float(self._y[np.argmin(self._z)])
        if not self.z_at(lo) >= depth:
            raise RollerRigError(f"{func}: the profile does not reach {depth!r} m below z = 0 "
                                 "on the gauge side")
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if self.z_at(mid) > depth else (lo, mid)
        return 0.5 * (lo + hi)

    def canted(self, inclination):
        """The profile turned about its origin as a rail or roller head canted
        inward by `inclination` (a slope, e.g. 1/40): the field side drops,
        y' = y cos c - z sin c, z' = y sin c + z cos c, c = atan(inclination).
        Points where the turn folds the curve back (a steep face) are an
        error; keep |inclination| small (<= 0.1)."""
        func = "Profile.canted"
        inc = _check_number(func, "inclination", inclination)
        if not abs(inc) <= 0.1:
            raise RollerRigError(f"{func}: inclination must be within [-0.1, 0.1], got {inc!r}")
        c = math.atan(inc)
        y = self._y * math.cos(c) - self._z_input * math.sin(c)
        z = self._y * math.sin(c) + self._z_input * math.cos(c)
        if not np.all(np.diff(y) > 0):
            raise RollerRigError(f"{func}: canting by {inc!r} folds the profile back "
                                 "(a face steeper than the cant)")
        return self._derived(func, y, z, self._name, f"canted by {inc!r}")

    def mirrored(self):
        """The mirror image y -> -y: the same profile for the other side of the
        track (field side positive again there).  Smoothing commutes with it."""
        return self._derived("Profile.mirrored", -self._y[::-1], self._z_input[::-1], self._name,
                             "mirrored y -> -y")

    def write_text(self, path, units="mm"):
        """Write the nodes (y, z) as plain two-column text, readable by
        read_profile: '#' header lines 'key = value' carry name, kind, units
        and bc; 17 significant digits."""
        if units not in UNITS:
            raise RollerRigError(f"Profile.write_text: units must be one of {sorted(UNITS)}, "
                                 f"got {units!r}")
        f = UNITS[units]
        with open(path, "w", encoding="utf-8") as out:
            out.write("# rollerrig profile: lateral y towards the field side, vertical z "
                      "downward\n")
            out.write(f"# name = {self._name}\n# kind = {self._kind}\n# units = {units}\n"
                      f"# bc = {self._bc}\n")
            for yy, zz in zip(self._y / f, self._z / f):
                out.write(f"{yy:.17g} {zz:.17g}\n")

    # -- other constructors

    @classmethod
    def from_points(cls, y, z, *, kind, name="", units="m", on_fold="trim", mirror_y=False,
                    mirror_z=False, bc=None, smoothing=None, meta=None):
        """A profile from points in any order: converts units ("m", "cm",
        "mm"), mirrors on request, reverses descending points, removes folds
        (with a RollerRigWarning; on_fold="raise" to refuse them) and checks
        as read_profile does."""
        func = "Profile.from_points"
        _check_kind(func, kind)
        if units not in UNITS:
            raise RollerRigError(f"{func}: units must be one of {sorted(UNITS)}, "
                                 f"got {units!r}")
        y = _as_float_array(func, "y", y)
        z = _as_float_array(func, "z", z)
        if y.ndim != 1 or y.shape != z.shape:
            raise RollerRigError(f"{func}: y and z must be 1-D arrays of one length, got "
                                 f"shapes {y.shape} and {z.shape}")
        f = UNITS[units]
        y, z, notes = _prepare(func, y * f, z * f, kind, (np.arange(len(y)), "point"),
                               on_fold, mirror_y, mirror_z)
        with _named(func):
            return cls(y, z, kind=kind, name=name, meta={**(meta or {}), **notes}, bc=bc,
                       smoothing=smoothing)

    @classmethod
    def s1002(cls, smoothing=None):
        """The S1002 wheel of the Manchester contact benchmark (MBench_S1002_v3.prw,
        shipped in rollerrig/data/profiles): y = 0 at the taping line, flange at y < 0."""
        return read_profile(os.path.join(DATA_DIR, "MBench_S1002_v3.prw"),
                            smoothing=smoothing)

    @classmethod
    def uic60(cls, smoothing=None):
        """The UIC60 rail of the Manchester contact benchmark (MBench_UIC60_v3.prr),
        already canted 1:40: top of head z = 0 near y = 0, gauge face at y < 0."""
        return read_profile(os.path.join(DATA_DIR, "MBench_UIC60_v3.prr"),
                            smoothing=smoothing)

    @classmethod
    def conical(cls, alpha, y_range=(-0.02, 0.02), r0=None, n=41):
        """The paper's conical wheel: z = -tan(alpha) y on y_range [m], so the
        rolling radius r0 + z decreases towards the field side for alpha > 0
        (slope -tan(alpha)).  r0, the radius at y = 0 [m], is kept in meta
        for the contact geometry."""
        func = "Profile.conical"
        alpha = _check_number(func, "alpha", alpha)
        if not abs(alpha) < math.pi / 2:
            raise RollerRigError(f"{func}: alpha must be within (-pi/2, pi/2) rad, "
                                 f"got {alpha!r}")
        y = _range_points(func, y_range, n)
        r0 = _check_number(func, "r0", r0, positive=True, allow_none=True)
        with _named(func):
            return cls(y, -math.tan(alpha) * y, kind="wheel",
                       name=f"conical wheel, alpha = {alpha:.6g} rad",
                       meta={"alpha": alpha, "r0": r0})

    @classmethod
    def cylinder(cls, y_range=(-0.02, 0.02), crown_radius=None, n=81):
        """A roller (kind "rail") with a flat lateral profile z = 0 (a
        cylinder), or with a crown of the given radius [m] centred at y = 0:
        z = R - sqrt(R^2 - y^2), curvature +1/R."""
        func = "Profile.cylinder"
        y = _range_points(func, y_range, n)
        R = _check_number(func, "crown_radius", crown_radius, positive=True, allow_none=True)
        if R is None:
            z = np.zeros_like(y)
        else:
            if np.max(np.abs(y)) >= R:
                raise RollerRigError(f"{func}: y_range {y_range!r} reaches beyond the crown "
                                     f"radius {R!r} m")
            # R - sqrt(R^2 - y^2) without its cancellation, nor R^2 overflowing
            z = y * y / (R + np.sqrt(R - y) * np.sqrt(R + y))
        name = "cylinder" if R is None else f"crowned roller, R = {R:.6g} m"
        with _named(func):
            return cls(y, z, kind="rail", name=name, meta={"crown_radius": R})


@contextlib.contextmanager
def _named(func):
    """Profile's own checks, reported under the constructor the caller used."""
    try:
        yield
    except RollerRigError as e:
        msg = str(e)
        raise RollerRigError(f"{func}: {msg[len('Profile: '):]}" if msg.startswith("Profile: ")
                             else msg) from None


def _rebuild(y, z, kind, name, meta, bc, smoothing):
    return Profile(y, z, kind=kind, name=name, meta=meta, bc=bc, smoothing=smoothing)


def _range_points(func, y_range, n):
    try:
        y0, y1 = (float(v) for v in y_range)
    except (TypeError, ValueError):
        raise RollerRigError(f"{func}: y_range must be two numbers (y_min, y_max) [m], "
                             f"got {y_range!r}") from None
    if not (math.isfinite(y0) and math.isfinite(y1) and y1 > y0):
        raise RollerRigError(f"{func}: y_range must be finite with y_min < y_max, "
                             f"got {y_range!r}")
    if max(abs(y0), abs(y1)) > MAX_COORD:
        raise RollerRigError(f"{func}: y_range must lie within +-{MAX_COORD:g} m (metres, "
                             f"not millimetres), got {y_range!r}")
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) \
            or not MIN_POINTS <= n <= MAX_POINTS:
        raise RollerRigError(f"{func}: n must be an integer from {MIN_POINTS} to "
                             f"{MAX_POINTS}, got {n!r}")
    # (at most MAX_POINTS over MIN_WIDTH: the points are far over MIN_SPACING apart)
    if not y1 - y0 >= MIN_WIDTH:
        raise RollerRigError(f"{func}: y_range {y_range!r} spans less than "
                             f"{MIN_WIDTH * 1e3:g} mm: metres read as millimetres?")
    return np.linspace(y0, y1, int(n))


# ---------------------------------------------------------------- readers

def _value(text):
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


def _numbers(where, lineno, text, expect):
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


def _strip_comment(line):
    """Text before a '!' that is not inside quotes (SIMPACK comments)."""
    quote = None
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


def _read_text_lines(path, where):
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


def _read_simpack(path, where):
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
    Returns (y [m], z [m], line numbers, kind from header, meta)."""
    header, spline = {}, {}
    rows, lines = [], []
    stack = []
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
    lines = np.array(lines)

    def num(key, default):
        v = spline.get(key, default)
        try:
            x = math.nan if isinstance(v, (str, bool)) else float(v)
        except OverflowError:                      # an integer beyond the doubles
            x = math.inf
        if not math.isfinite(x):
            raise RollerRigError(f"{where}: {key} = {str(v)[:40]!r} is not a finite number")
        return x

    def flag(key):
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
        pts, lines = pts[keep], lines[keep]
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
        pts, lines = pts[inside], lines[inside]
    zlo, zhi = num("bound.z.min", 1.0), num("bound.z.max", 0.0)
    if zlo < zhi:
        pts[:, 1] = np.clip(pts[:, 1], zlo, zhi)
    # 5 mirroring, 6 inversion
    if flag("mirror.y"):
        pts[:, 0] = -pts[:, 0]
    if flag("mirror.z"):
        pts[:, 1] = -pts[:, 1]
    if flag("inversion"):
        pts, lines = pts[::-1], lines[::-1]
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
        if name not in UNITS:
            raise RollerRigError(f"{where}: units.len = {name!r} is not one of "
                                 f"{sorted(UNITS)}")
        len_f = 1.0 / UNITS[name]
    else:
        len_f = 1.0
    pts = pts / len_f

    kind = None
    if "type" in header:
        t = header["type"]
        if t not in (0, 1):
            raise RollerRigError(f"{where}: header type must be 0 (rail) or 1 (wheel), "
                                 f"got {t!r}")
        kind = "wheel" if t == 1 else "rail"
    meta = {f"header.{k}": v for k, v in header.items()}
    meta.update({f"spline.{k}": v for k, v in spline.items()})
    if spline.get("approx.smooth", 0) not in (0, 0.0):
        warnings.warn(f"{where}: approx.smooth = {spline['approx.smooth']!r} (SIMPACK's "
                      f"smoothing) is not applied; pass smoothing= for ours",
                      RollerRigWarning, stacklevel=3)
    return pts[:, 0], pts[:, 1], lines, kind, meta


def _read_miniprof(path, where):
    """MiniProf .whl/.ban: 'Key=value' header lines, then one point per line
    (fields separated by blanks or commas) in millimetres, in the columns
    that ColumnDef names (default 'X,Y'): X lateral, Y vertical, both already
    in our orientation (field side positive, downward positive; wheels with
    y = 0 at the flange back).  XYPoints, when given, must equal the number
    of points.  Returns (y [m], z [m], line numbers, None, meta)."""
    meta = {}
    rows, lines = [], []
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
    return (pts[:, ix] * 1e-3, pts[:, iz] * 1e-3, np.array(lines, dtype=int), None, meta)


def _read_text(path, where, units):
    """Plain text: one point per line, 'lateral vertical' separated by blanks,
    a comma or a semicolon, in our orientation.  Empty lines and lines
    starting with '#', '!' or '%' are skipped; comment lines of the form
    '# key = value' become meta (name, kind, units and bc are used).  A first
    line whose fields are all non-numeric is taken as column names.
    Returns (y [m], z [m], line numbers, kind or None, meta, units, bc)."""
    meta = {}
    rows, lines = [], []
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
    file_units = meta.get("units")
    if file_units is not None and file_units not in UNITS:
        raise RollerRigError(f"{where}: units = {file_units!r} in the file is not one of "
                             f"{sorted(UNITS)}")
    if units is not None and file_units is not None and units != file_units:
        raise RollerRigError(f"{where}: units = {units!r} contradicts the file's "
                             f"units = {file_units!r}")
    units = units or file_units or "mm"
    if not rows:
        raise RollerRigError(f"{where}: no points")
    pts = np.array(rows, dtype=float) * UNITS[units]
    kind = meta.get("kind")
    if kind is not None and kind not in KINDS:
        raise RollerRigError(f"{where}: kind = {kind!r} in the file is not 'wheel' or 'rail'")
    bc = meta.get("bc")
    if bc is not None and bc not in BCS:
        raise RollerRigError(f"{where}: bc = {bc!r} in the file is not one of {BCS}")
    return pts[:, 0], pts[:, 1], np.array(lines, dtype=int), kind, meta, units, bc


def _not_number(field):
    try:
        float(field)
    except ValueError:
        return True
    return False


def read_profile(path, kind=None, *, units=None, on_fold="trim", mirror_y=False,
                 mirror_z=False, smoothing=None, bc=None, name=None):
    """Read a wheel or rail/roller profile file into a Profile.

    path:      a SIMPACK .prw (wheel) / .prr (rail), MiniProf .whl (wheel) /
               .ban (rail) or plain text .txt/.csv/.dat file (module
               docstring; each reader's rules in _read_simpack,
               _read_miniprof, _read_text).
    kind:      "wheel" or "rail"; by default from the SIMPACK header type,
               else the extension, else a '# kind = ...' line of a text file
               (a text file without one needs kind).  Given, it must agree
               with a SIMPACK header.
    units:     plain text only: "mm" (default), "cm" or "m"; SIMPACK files
               declare theirs, MiniProf files are in mm.
    on_fold:   "trim" (default: drop the points where the profile folds
               back, with a RollerRigWarning) or "raise".
    mirror_y, mirror_z: mirror the points after reading (y -> -y: a profile
               of the other side; z -> -z: data with z upward).
    smoothing, bc: as for Profile.
    name:      default the file name without extension.

    Checks (RollerRigError naming the file and line): numbers, NaN/inf,
    at least 4 points, no duplicate y, a single-valued profile (on_fold),
    |y|, |z| <= 2 m and width >= 1 mm after the unit conversion, MiniProf's
    XYPoints and ColumnDef.  A wheel whose flange (max z) lies at the
    field-side half gets a warning: it is probably the other side's profile.
    """
    func = "read_profile"
    path = os.fspath(path)
    where = f"{func}: {path}"
    if kind is not None:
        _check_kind(func, kind)
    ext = os.path.splitext(path)[1].lower()
    if not os.path.exists(path):
        raise RollerRigError(f"{where}: no such file")
    file_bc = None
    if ext in SIMPACK_EXT or ext in MINIPROF_EXT:
        if units is not None:
            raise RollerRigError(f"{where}: units is for plain text; {ext} files fix their "
                                 f"own units")
        if ext in SIMPACK_EXT:
            fmt = "simpack"
            y, z, lines, file_kind, meta = _read_simpack(path, where)
            ext_kind = SIMPACK_EXT[ext]
            if file_kind is not None and kind is not None and file_kind != kind:
                raise RollerRigError(f"{where}: kind = {kind!r} but the header says type = "
                                     f"{meta['header.type']} ({file_kind})")
            if file_kind is not None and file_kind != ext_kind and kind is None:
                warnings.warn(f"{where}: header type says {file_kind}, the extension "
                              f"{ext} {ext_kind}; read as {file_kind}", RollerRigWarning,
                              stacklevel=2)
            kind = kind or file_kind or ext_kind
        else:
            fmt = "miniprof"
            y, z, lines, _, meta = _read_miniprof(path, where)
            kind = kind or MINIPROF_EXT[ext]
        units_used = None
    elif ext in TEXT_EXT:
        fmt = "text"
        if units is not None and units not in UNITS:
            raise RollerRigError(f"{where}: units must be one of {sorted(UNITS)}, "
                                 f"got {units!r}")
        y, z, lines, file_kind, meta, units_used, file_bc = _read_text(path, where, units)
        if file_kind is not None and kind is not None and file_kind != kind:
            raise RollerRigError(f"{where}: kind = {kind!r} contradicts the file's "
                                 f"kind = {file_kind!r}")
        kind = kind or file_kind
        if kind is None:
            raise RollerRigError(f"{where}: kind unknown: pass kind='wheel' or 'rail' "
                                 f"(or write '# kind = ...' in the file)")
    else:
        raise RollerRigError(f"{where}: unknown extension {ext!r}; expected one of "
                             f"{sorted(SIMPACK_EXT) + sorted(MINIPROF_EXT) + list(TEXT_EXT)}")
    y, z, notes = _prepare(where, y, z, kind, (lines, "line"), on_fold, mirror_y, mirror_z)
    if kind == "wheel":
        i = int(np.argmax(z))
        if y[i] > 0.5 * (y[0] + y[-1]):
            warnings.warn(f"{where}: the flange (lowest point, y = {y[i] * 1e3:.4g} mm) lies "
                          f"on the field-side half: a profile of the other side? "
                          f"(mirror_y=True or .mirrored())", RollerRigWarning, stacklevel=2)
    meta = {"format": fmt, "path": path, **meta, **notes}
    if units_used is not None:
        meta["units"] = units_used
    if mirror_y or mirror_z:
        meta["mirrored"] = ("y" if mirror_y else "") + ("z" if mirror_z else "")
    if bc is None and smoothing is None:
        bc = file_bc
    if name is None:
        name = meta.get("name") if fmt == "text" and "name" in meta else \
            os.path.splitext(os.path.basename(path))[0]
    return Profile(y, z, kind=kind, name=str(name), meta=meta, bc=bc, smoothing=smoothing)
