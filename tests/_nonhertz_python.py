"""The Python construction of the non-Hertzian patch and of rig_exact, as
they were before the C core took them over (rollerrig/geometry/patch.py and
rollerrig/rig/exact.py up to issue 24): kept here, unchanged but for their
imports, as the independent reference that tests/test_nonhertz.py holds the
C version (csrc/geometry/rr_gap.c, rr_wheel_exact.c) to.  Not part of the
package."""
import warnings
from dataclasses import dataclass

import numpy as np

from rollerrig import _core
from rollerrig._errors import RollerRigError, RollerRigWarning
from rollerrig.contact.exact import ExactSolution, _edge, _exact_solve
from rollerrig.geometry.patch import patch_shape
from rollerrig.geometry.wheelset import RigGeometry, contact_table, wheelset_contact
from rollerrig.rig.contact import rig_contact

__all__ = ["undeformed_distance", "rig_exact"]

#: spacing of the profile samples h is interpolated from [m], at most
_SAMPLE = 2e-5
#: and at least (elements under a micrometre given: 8e5 samples over the
#: window, where a tenth of the element would ask for any number)
_SAMPLE_MIN = 1e-7
#: lateral half-width of the profiles' window around the reference point [m]
_WINDOW = 0.04


@dataclass(frozen=True, eq=False)
class Patch:
    """The undeformed distance of one wheel-roller contact on a grid, and its
    frame.  h has shape (my, mx): rows along y, columns along x, element
    (i, j) centred at (x0 + j dx, y0 + i dy) from the reference point, as
    rollerrig.exact_solve takes it."""

    h: np.ndarray        #: undeformed distance [m], least value 0
    dx: float            #: element size along x (t1) [m]
    dy: float            #: element size along y (t2) [m]
    x0: float            #: centre of element (0, 0) from the reference point [m]
    y0: float
    point: np.ndarray    #: reference point P in the rig frame (on the roller) [m], (3,)
    wheel_point: np.ndarray  #: P moved into the roller by the pose's interpenetration
                             #: (the least h before the shift), where the wheel's
                             #: velocity is taken (CONTACT's point Q) [m], (3,)
    t1: np.ndarray       #: rolling direction (+X), rig frame, (3,)
    t2: np.ndarray       #: lateral direction in the plane, toward +Y
    n: np.ndarray        #: normal into the wheel
    delta: float         #: contact angle of the plane [rad], > 0 toward the flange
    s_roller: float      #: roller profile coordinate of P [m]
    s_wheel: float       #: wheel profile coordinate where P's normal meets the wheel [m]
    r: float             #: wheel rolling radius there [m]
    R: float             #: roller radius at P [m]
    side: str            #: "left" or "right"
    y_ws: float          #: the wheelset's lateral shift [m]
    z: float             #: axle height [m] of the pose h was built at
    lowered: float       #: how far that lies below the zero-gap height [m]
    roll: float          #: roll angle [rad]
    approach: float      #: the approach the grid was sized for [m]
    cover: float         #: the grid covers where h <= cover * approach
    regions: tuple       #: lateral intervals (y_lo, y_hi) [m] where h <= cover * approach,
                         #: in the plane's y: those on the grid
    excluded: tuple      #: intervals left out: farther than `combine` (a separate patch)

    @property
    def shape(self):
        return self.h.shape

    @property
    def x(self):
        """Element centres along x [m], (my, mx)."""
        my, mx = self.h.shape
        return np.broadcast_to(self.x0 + self.dx * np.arange(mx), (my, mx))

    @property
    def y(self):
        """Element centres along y [m], (my, mx)."""
        my, mx = self.h.shape
        return np.broadcast_to((self.y0 + self.dy * np.arange(my))[:, None], (my, mx))


class _Pair:
    """One side's wheel and roller, placed in the rig at a pose; their
    cross-sections at longitudinal position x, in the rig's (Y, Z)."""

    def __init__(self, geometry, side, y_ws, z, roll):
        r0, R0, wheel_y, roller_y = geometry._params()[:4]
        left = side == "left"
        self.sigma = 1.0 if left else -1.0
        self.wheel = geometry.wheel if left else (geometry.wheel_right or geometry.wheel)
        self.roller = geometry.roller if left else (geometry.roller_right or geometry.roller)
        self.r0, self.R0, self.wheel_y, self.roller_y = r0, R0, wheel_y, roller_y
        self.y_ws, self.z, self.roll = float(y_ws), float(z), float(roll)

    @staticmethod
    def _drop(radius, x):
        """radius - sqrt(radius^2 - x^2), without cancellation."""
        x2 = np.square(x)
        return x2 / (radius + np.sqrt(np.maximum(np.square(radius) - x2, 0.0)))

    def roller_yz(self, sr, x=0.0, zr=None):
        """Rig (Y, Z) of the roller's cross-section at x; zr: the profile's
        heights at sr if known (z_r = R - R0, up)."""
        zr = -self.roller.z_at(sr) if zr is None else zr
        return (self.sigma * (self.roller_y + sr),
                zr - self._drop(self.R0 + zr, x))

    def wheel_yz(self, s, x=0.0, zw=None):
        """Rig (Y, Z) of the wheel's cross-section at x; zw: the profile's
        heights at s if known (z_w = r0 - r)."""
        zw = -self.wheel.z_at(s) if zw is None else zw
        yl = self.sigma * (self.wheel_y + s)
        zl = -self.r0 + zw + self._drop(self.r0 - zw, x)
        c, sn = np.cos(self.roll), np.sin(self.roll)
        return self.y_ws + yl * c - zl * sn, self.z + yl * sn + zl * c

    def roller_radius(self, sr):
        return self.R0 - self.roller.z_at(sr)

    def wheel_radius(self, s):
        return self.r0 + self.wheel.z_at(s)

    def roller_angle(self, sr):
        """Inclination of the roller's surface [rad], > 0 rising outward."""
        return np.arctan(-self.roller.slope(sr))


class _Frame:
    """The tangent plane through P (rig (Y, Z)) at angle delta."""

    def __init__(self, sigma, P, delta):
        self.P = np.asarray(P, dtype=float)
        self.delta = float(delta)
        c, s = np.cos(delta), np.sin(delta)
        self.t2 = np.array([c, sigma * s])
        self.n = np.array([-sigma * s, c])

    def project(self, Y, Z):
        dY, dZ = Y - self.P[0], Z - self.P[1]
        return dY * self.t2[0] + dZ * self.t2[1], dY * self.n[0] + dZ * self.n[1]

    def vectors(self):
        t1 = np.array([1.0, 0.0, 0.0])
        t2 = np.array([0.0, *self.t2])
        n = np.array([0.0, *self.n])
        return t1, t2, n


def _samples(profile, centre, window, step):
    lo = max(profile.y_min, centre - window)
    hi = min(profile.y_max, centre + window)
    if not hi > lo:
        raise RollerRigError(f"undeformed_distance: the reference point lies off the "
                             f"{profile.kind} profile ({centre!r} m, profile from "
                             f"{profile.y_min:g} to {profile.y_max:g} m)")
    k = int(np.ceil((hi - lo) / step)) + 1
    return np.linspace(lo, hi, k)


def _single_valued(yc, zeta, k0):
    """The run of samples around index k0 along which yc is strictly
    monotonic and finite (the cross-section is a function of yc there),
    ordered by increasing yc."""
    d = np.diff(yc)
    k0 = int(np.clip(k0, 0, d.size - 1))
    sgn = np.sign(d[k0])
    good = np.isfinite(d) & (np.sign(d) == sgn) & np.isfinite(zeta[1:]) & np.isfinite(zeta[:-1])
    if not good[k0]:
        raise RollerRigError("undeformed_distance: a profile folds at the reference point")
    bad = np.flatnonzero(~good)
    lo = bad[bad < k0]
    hi = bad[bad > k0]
    lo = int(lo[-1]) + 1 if lo.size else 0
    hi = int(hi[0]) if hi.size else d.size
    y, z = yc[lo:hi + 1], zeta[lo:hi + 1]
    return (y, z) if sgn > 0 else (y[::-1], z[::-1])


class _Sections:
    """Both bodies' cross-sections at x in the plane's (y, zeta): the gap
    along n at any (x, y), from dense profile samples (linear between
    samples _SAMPLE apart: 1e-8 m where the profile's radius is 5 mm)."""

    def __init__(self, pair, frame, sr_P, sw_P, window, step):
        self.pair, self.frame = pair, frame
        self.sr = _samples(pair.roller, sr_P, window, step)
        self.sw = _samples(pair.wheel, sw_P, window, step)
        self._zr = -pair.roller.z_at(self.sr)
        self._zw = -pair.wheel.z_at(self.sw)
        self.k_r = int(np.argmin(np.abs(self.sr - sr_P)))
        self.k_w = int(np.argmin(np.abs(self.sw - sw_P)))
        self._roller_s = self._wheel_s = None
        yr, _ = self._section(0.0, "roller")
        yw, _ = self._section(0.0, "wheel")
        self.lo, self.hi = max(yr[0], yw[0]), min(yr[-1], yw[-1])
        if not self.hi > self.lo:
            _apart(pair)

    def _section(self, x, body):
        if body == "roller":
            Y, Z = self.pair.roller_yz(self.sr, x, self._zr)
            k0 = self.k_r
        else:
            Y, Z = self.pair.wheel_yz(self.sw, x, self._zw)
            k0 = self.k_w
        yc, zeta = self.frame.project(Y, Z)
        return _single_valued(yc, zeta, k0)

    def gap(self, x, y):
        """h along n at longitudinal x (a number) and lateral positions y;
        NaN outside both sections."""
        y = np.asarray(y, dtype=float)
        yr, zr = self._section(x, "roller")
        yw, zw = self._section(x, "wheel")
        g = np.interp(y, yw, zw) - np.interp(y, yr, zr)
        g[(y < max(yr[0], yw[0])) | (y > min(yr[-1], yw[-1]))] = np.nan
        return g

    def roller_at(self, y):
        """Roller profile coordinate of the roller's point at lateral y of
        the plane (x = 0)."""
        if self._roller_s is None:
            yc, _ = self.frame.project(*self.pair.roller_yz(self.sr, 0.0, self._zr))
            self._roller_s = _single_valued(yc, self.sr, self.k_r)
        return np.interp(y, *self._roller_s)

    def wheel_at(self, y):
        """Wheel profile coordinate of the wheel's point at lateral y."""
        if self._wheel_s is None:
            yc, _ = self.frame.project(*self.pair.wheel_yz(self.sw, 0.0, self._zw))
            self._wheel_s = _single_valued(yc, self.sw, self.k_w)
        return np.interp(y, *self._wheel_s)


def _apart(pair):
    """RollerRigError: the cross-sections lie side by side (the pose given
    puts the wheel beside its roller)."""
    raise RollerRigError(f"undeformed_distance: at y_ws = {pair.y_ws!r} m, axle height z = "
                         f"{pair.z!r} m and roll {pair.roll!r} rad the wheel's and the "
                         f"roller's cross-sections do not overlap laterally: no patch")


def _runs(mask):
    """(start, stop) index pairs of the runs of True in a 1-D mask."""
    m = np.concatenate(([False], mask, [False])).astype(np.int8)
    d = np.diff(m)
    return list(zip(np.flatnonzero(d == 1), np.flatnonzero(d == -1)))


def _number(func, name, v, positive=True, allow_none=False):
    if v is None and allow_none:
        return None
    if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)) \
            or not np.isfinite(v) or (positive and not v > 0):
        raise RollerRigError(f"{func}: {name} must be a finite "
                             f"{'positive ' if positive else ''}number, got {v!r}")
    return float(v)


def _pose_and_point(func, geometry, y_ws, side):
    if not isinstance(geometry, RigGeometry):
        raise RollerRigError(f"{func}: geometry must be a RigGeometry, got {geometry!r:.60}")
    if side not in ("left", "right"):
        raise RollerRigError(f"{func}: side must be 'left' or 'right', got {side!r}")
    y_ws = _number(func, "y_ws", y_ws, positive=False)
    c = wheelset_contact(geometry, y_ws)
    return float(c.z[0]), float(c.roll[0]), getattr(c, side)


def undeformed_distance(geometry, y_ws, *, side="left", N=None, approach=None, n=40, E=2.1e11,
                        nu=0.28, cover=1.5, dx=None, dy=None, reference="weighted",
                        combine=4e-3, z=None, roll=None, sample=None):
    """The undeformed distance h(x, y) of one wheel on its roller, on a grid.

    geometry: RigGeometry; y_ws: the wheelset's lateral shift [m]; side:
    "left" or "right".  The pose: wheelset_contact's axle height and roll
    at y_ws (both surfaces just touching), or z [m], roll [rad] given: a
    loaded pose (the wheelset lowered by its approach over cos(delta), as
    CONTACT builds h and rig_exact does by default), CONTACT's prescribed
    roll.
    reference: the tangent plane's point P and angle: "weighted" (default;
    CONTACT's: the centre of the vertical interpenetration at `approach`,
    each lateral strip weighted by the integral over x of its squared
    interpenetration, and the roller's inclination averaged with the same
    weights), "point" (rollerrig's contact point, the least vertical gap,
    and its contact angle: the frame of rig_contact) or (s_roller, delta):
    P on the roller at that profile coordinate [m], the angle [rad] given.
    approach [m]: the expected approach; None: Hertz's at the rollerrig
    contact point for the normal load N [N] (E [Pa], nu of both bodies).
    The grid covers the region where h <= cover * approach (cover >= 1:
    the contact lies where h <= the approach found), plus one element on
    every side, with about n elements across its longer side and square
    elements, unless dx, dy [m] are given (a grid of more than the exact
    solver's 1024 elements a side is refused before it is built).  A load
    or approach whose region reaches past the profiles in the plane, or a
    pose whose cross-sections do not overlap, is refused, naming it.
    combine [m]: lateral intervals
    of that region at most this far from the deepest one are on the grid,
    the rest are a separate patch (Patch.excluded, a warning).
    Returns a Patch (h with least value 0, its grid and frame).
    """
    func = "undeformed_distance"
    z_ws, roll_ws, cpt = _pose_and_point(func, geometry, y_ws, side)
    z = z_ws if z is None else _number(func, "z", z)
    roll = roll_ws if roll is None else _number(func, "roll", roll, positive=False)
    for name, v in (("N", N), ("approach", approach)):
        _number(func, name, v, allow_none=True)
    if approach is None:
        if N is None:
            raise RollerRigError(f"{func}: give the normal load N [N] or the approach [m]")
        from rollerrig.contact.creep import hertz
        approach = float(hertz(float(cpt.A[0]), float(cpt.B[0]), float(N), E=E, nu=nu).delta)
    approach = float(approach)
    cover = _number(func, "cover", cover)
    if cover < 1.0:
        raise RollerRigError(f"{func}: cover must be >= 1, got {cover!r}")
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 4 <= n <= 1000:
        raise RollerRigError(f"{func}: n must be an integer from 4 to 1000, got {n!r}")
    dx = _number(func, "dx", dx, allow_none=True)
    dy = _number(func, "dy", dy, allow_none=True)
    combine = _number(func, "combine", combine, positive=False)
    pair = _Pair(geometry, side, y_ws, z, roll)

    # the reference point and angle
    if isinstance(reference, str) and reference in ("point", "weighted"):
        sr_P, delta = float(cpt.s_roller[0]), float(cpt.delta[0])
    elif isinstance(reference, (tuple, list)) and len(reference) == 2:
        sr_P = _number(func, "reference s_roller", reference[0], positive=False)
        delta = _number(func, "reference delta", reference[1], positive=False)
        if not abs(delta) < 0.5 * np.pi:
            raise RollerRigError(f"{func}: the reference angle must be within +-pi/2, got "
                                 f"{delta!r}")
    else:
        raise RollerRigError(f"{func}: reference must be 'point', 'weighted' or "
                             f"(s_roller, delta), got {reference!r:.60}")
    step = max(min(_SAMPLE, 0.1 * min(v for v in (dx, dy, 1.0) if v is not None)), _SAMPLE_MIN)
    if sample is not None:                 # rr_gap_opts.sample (rig_exact's coarse pass)
        step = float(sample)
    sw_P = float(cpt.s_wheel[0])

    def sections(sr, dl, sw):
        frame = _Frame(pair.sigma, pair.roller_yz(sr), dl)
        return _Sections(pair, frame, sr, sw, _WINDOW, step)

    sec = sections(sr_P, delta, sw_P)
    if reference == "weighted":
        sr_P, delta = _weighted_reference(pair, sr_P, sw_P, approach, delta, combine, step)
        sec = sections(sr_P, delta, sw_P)
    sw_P = float(sec.wheel_at(0.0))   # where P's normal meets the wheel
    sec = sections(sr_P, delta, sw_P)

    # the region to cover, at x = 0: its lateral intervals
    level = cover * approach
    yf = np.linspace(sec.lo, sec.hi, int(np.ceil((sec.hi - sec.lo) / step)) + 1)
    hy = sec.gap(0.0, yf)
    hmin = np.nanmin(hy)
    runs, rest = _group(yf, hy - hmin <= level, int(np.nanargmin(hy)), combine)
    lo, hi = min(a for a, _ in runs), max(b for _, b in runs)
    kept = tuple(runs)
    load = f"N = {float(N)!r} N" if N is not None else f"approach = {approach!r} m"

    def too_large(where):
        raise RollerRigError(f"{func}: at y_ws = {y_ws!r} m and {load} the region to cover "
                             f"(h <= cover x approach = {level:.3g} m) {where}: a load or "
                             f"approach beyond one planar patch on these profiles")
    if lo <= yf[0] or hi >= yf[-1]:
        too_large(f"reaches the end of the profiles in the tangent plane (y from "
                  f"{sec.lo:g} to {sec.hi:g} m from the reference point)")
    if rest:
        warnings.warn(f"{func}: at y_ws = {y_ws!r} m the {side} wheel has "
                      f"{len(rest)} more interpenetration region(s) farther than "
                      f"combine = {combine:g} m from the deepest one (at y = "
                      f"{', '.join(f'{0.5 * (a + b):.4g}' for a, b in rest)} m in the plane): "
                      f"a separate patch, left out", RollerRigWarning, stacklevel=2)

    # the half-length: where h reaches the level along x, at the widest strip
    in_region = (yf >= lo) & (yf <= hi) & (hy - hmin <= level)
    r_P, R_P = pair.wheel_radius(sw_P), pair.roller_radius(sr_P)
    x_t = np.sqrt(2.0 * level / (np.cos(delta) * (1.0 / r_P + 1.0 / R_P)))
    if not x_t < 0.5 * min(r_P, R_P):
        too_large(f"is {2 * x_t:.3g} m long, as long as the radii ({r_P:.3g}, {R_P:.3g} m)")
    rise = np.maximum((sec.gap(x_t, yf) - hy)[in_region], 1e-3 * level) / x_t ** 2
    xh = float(np.max(np.sqrt((level - (hy - hmin)[in_region]) / rise)))
    if not np.isfinite(xh):
        too_large(f"ends, {x_t:.3g} m ahead and behind, beyond the profiles in the tangent plane")
    if dx is None or dy is None:
        d = max(2.0 * xh, hi - lo) / n
        dx = d if dx is None else dx
        dy = d if dy is None else dy
    i_lo, i_hi = int(np.floor(-xh / dx)) - 1, int(np.ceil(xh / dx)) + 1
    j_lo, j_hi = int(np.floor(lo / dy)) - 1, int(np.ceil(hi / dy)) + 1

    def bounded():
        # the solver's largest grid, checked before h's memory is asked for
        mx, my = i_hi - i_lo + 1, j_hi - j_lo + 1
        if max(mx, my) > _core.EXACT_MAX_GRID:
            raise RollerRigError(f"{func}: dx = {dx!r} m, dy = {dy!r} m: this patch "
                                 f"({2.0 * xh:.3g} m by {hi - lo:.3g} m) would need {my} x "
                                 f"{mx} elements, at most {_core.EXACT_MAX_GRID} a side (give "
                                 f"larger elements)")
    bounded()
    # grow the grid until the region has an exterior element on every side
    for _ in range(1000):
        xs = dx * np.arange(i_lo, i_hi + 1)
        ys = dy * np.arange(j_lo, j_hi + 1)
        if ys[0] < sec.lo or ys[-1] > sec.hi:
            raise RollerRigError(f"{func}: at y_ws = {y_ws!r} m and {load} the patch reaches "
                                 f"where a profile folds or ends in the tangent plane (y from "
                                 f"{sec.lo:g} to {sec.hi:g} m from the reference point)")
        h = np.stack([sec.gap(x, ys) for x in xs], axis=1)
        inside = h - hmin <= level
        inside[(ys < lo - 0.5 * dy) | (ys > hi + 0.5 * dy), :] = False   # left out
        grow = (inside[:, 0].any(), inside[:, -1].any(), inside[0].any(), inside[-1].any())
        if not any(grow):
            break
        i_lo -= grow[0]
        i_hi += grow[1]
        j_lo -= grow[2]
        j_hi += grow[3]
        bounded()
    if not np.all(np.isfinite(h)):
        raise RollerRigError(f"{func}: at y_ws = {y_ws!r} m and {load} the patch reaches "
                             f"where a profile folds or ends in the tangent plane")
    hmin_grid = float(np.min(h))
    h = h - hmin_grid
    pen = max(0.0, -hmin_grid)      # the pose's interpenetration along n (0 at zero gap)
    t1, t2, nn = sec.frame.vectors()
    P = np.array([0.0, *sec.frame.P])
    return Patch(h=h, dx=float(dx), dy=float(dy), x0=float(xs[0]), y0=float(ys[0]), point=P,
                 wheel_point=P - pen * nn, lowered=z_ws - z,
                 t1=t1, t2=t2, n=nn, delta=float(delta), s_roller=float(sr_P),
                 s_wheel=float(sw_P), r=float(r_P), R=float(R_P), side=side,
                 y_ws=float(y_ws), z=z, roll=float(roll), approach=approach,
                 cover=cover, regions=kept, excluded=tuple(rest))


def _group(y, mask, deep, combine):
    """The runs of True in mask (as (y_lo, y_hi)): those within `combine`
    of the one holding index `deep`, merged step by step, and the rest."""
    runs = [tuple(sorted((y[a], y[b - 1]))) for a, b in _runs(mask)]
    lo, hi = next((a, b) for a, b in runs if a <= y[deep] <= b)
    kept, rest = [], []
    pending = sorted(runs, key=lambda iv: min(abs(iv[0] - y[deep]), abs(iv[1] - y[deep])))
    grown = True
    while grown:
        grown = False
        for iv in list(pending):
            if iv[0] - hi <= combine and lo - iv[1] <= combine:
                lo, hi = min(lo, iv[0]), max(hi, iv[1])
                kept.append(iv)
                pending.remove(iv)
                grown = True
    rest = pending
    return sorted(kept), sorted(rest)


def _weighted_reference(pair, sr_P, sw_P, approach, delta, combine, step):
    """CONTACT's reference of a patch (its locate_interpen_1d and
    set_cpatch_reference): at the pose lowered by approach / cos(delta),
    the centre of the vertical interpenetration pen(Y) and the roller's
    mean inclination, each lateral strip weighted by the integral over x of
    its squared interpenetration, pen^2 (1 - x^2/t0^2)^2 over |x| < t0 =
    sqrt(pen / a), that is 16/15 pen^2.5 / sqrt(a) (a = (1/r + 1/R)/2 the
    strip's longitudinal curvature); delta, which sets the lowering, is
    iterated.  Lowering the wheel by d takes d off every vertical gap, so
    the pose's own gap g(Y), shifted to least value 0, stands for the
    lowered one.  Returns (s_roller, delta) of the reference."""
    sr = _samples(pair.roller, sr_P, _WINDOW, step)
    Yr, Zr = pair.roller_yz(sr)
    sw = _samples(pair.wheel, sw_P, _WINDOW, step)
    Yw, Zw = pair.wheel_yz(sw)
    k = int(np.argmin(np.abs(Yw - pair.sigma * (pair.roller_y + sr_P))))
    Ys, Zs = _single_valued(Yw, Zw, k)
    _, ss = _single_valued(Yw, sw, k)
    inside = (Yr >= Ys[0]) & (Yr <= Ys[-1])
    if not inside.any():
        _apart(pair)
    Yr, Zr, sr = Yr[inside], Zr[inside], sr[inside]
    g = np.interp(Yr, Ys, Zs) - Zr
    g -= np.min(g)
    r = pair.wheel_radius(np.interp(Yr, Ys, ss))
    a = 0.5 * (1.0 / r + 1.0 / pair.roller_radius(sr))
    alpha = pair.roller_angle(sr)
    deep = int(np.argmin(g))
    for _ in range(50):
        pen = approach / np.cos(delta) - g
        runs, _ = _group(Yr, pen > 0, deep, combine)
        keep = np.zeros(Yr.size, dtype=bool)
        for lo, hi in runs:
            keep |= (Yr >= lo) & (Yr <= hi)
        w = np.where(keep, np.maximum(pen, 0.0) ** 2.5 / np.sqrt(a), 0.0)
        new = float(np.sum(w * alpha) / np.sum(w))
        done = abs(new - delta) < 1e-13
        delta = new
        if done:
            break
    Yc = float(np.sum(w * Yr) / np.sum(w))
    order = slice(None) if Yr[-1] > Yr[0] else slice(None, None, -1)
    return float(np.interp(Yc, Yr[order], sr[order])), delta




# ---------------------------------------------------------------- rig_exact





@dataclass(frozen=True, eq=False)
class RigExact:
    """One wheel of the rig solved by the exact theory on its own patch."""

    solution: ExactSolution  #: fields and forces: fx along t1, fy along t2, mz about n at P
    patch: Patch             #: h, the grid and the frame
    cx: float                #: creepages at the patch's reference point [-], [-], [rad/m]
    cy: float
    cphi: float
    V: float                 #: rolling speed [m/s] (0 where the creepages were given)
    N: float                 #: normal load [N]
    passes: int              #: grids solved (the first ones find the approach and load)

    @property
    def shape(self):
        """PatchShape of the contact area."""
        return patch_shape(self.solution.contact, self.patch.dx, self.patch.dy)

    @property
    def force(self):
        """Contact force on the wheel in the rig frame [N]:
        fx t1 + fy t2 + fn n."""
        s, p = self.solution, self.patch
        return s.fx * p.t1 + s.fy * p.t2 + s.fn * p.n


def _creepages(geometry, p, spin, roller_spin, vy, yaw_rate, vmin, table):
    """Kalker's creepages of patch p, as rr_creepage.h, from the rigid
    motions of the wheelset (rig_contact's at y_ws, x = yaw = 0, its centre
    lowered as p's pose) and of the roller (about the rig's roller axis):
    the slip of the wheel's material point at p.wheel_point relative to
    the roller's at P, over the rolling speed, in p's frame.  At the
    zero-gap pose both are P (rig_contact's creepages, at rollerrig's
    contact point); at the loaded pose the wheel's point is P moved by the
    pose's interpenetration along -n, CONTACT's point Q: with the centre
    lowered by pen / cos(delta) its distance from the axle is then the
    zero-gap one less pen sin^2(delta) / cos(delta), 3e-5 of cx at the
    flange root (delta = 0.34 rad), where the wheel's material point
    taken at P with the zero-gap centre would differ by that."""
    if table is None:
        table = contact_table(geometry, p.y_ws - 1e-5, p.y_ws + 1e-5, 3)
    c = rig_contact(table, y=p.y_ws, vy=vy, yaw_rate=yaw_rate, spin=spin,
                    roller_spin=roller_spin, N_left=1.0, N_right=1.0, kinematics_only=True,
                    vmin=vmin, errors="raise")
    pose = c.pose
    R0 = float(geometry.roller_radius)
    centre = np.asarray(pose.c) - np.array([0.0, 0.0, p.lowered])
    vw = np.asarray(pose.v) + np.cross(np.asarray(pose.w), p.wheel_point - centre)
    wr = np.array([0.0, -float(roller_spin), 0.0])
    vr = np.cross(wr, p.point - np.array([0.0, 0.0, -R0]))
    V = max(abs(float(np.dot(vw + vr, p.t1))) / 2.0, vmin)
    slip = vw - vr
    return (float(np.dot(slip, p.t1)) / V, float(np.dot(slip, p.t2)) / V,
            float(np.dot(np.asarray(pose.w) - wr, p.n)) / V, V)


def rig_exact(geometry, y_ws, *, mu, N=None, Fz=None, side="left", spin=None,
              roller_spin=None, vy=0.0, yaw_rate=0.0, cx=None, cy=None, cphi=None, E=2.1e11,
              nu=0.28, n=40, reference="weighted", loaded=True, passes=2, vmin=1e-3,
              table=None, tol=1e-6, maxit=5000, **patch_options):
    """One wheel of the rig at lateral shift y_ws [m] solved by Kalker's exact
    theory on its non-Hertzian patch (undeformed_distance).

    The load: N [N] along the patch's normal, or Fz [N] the vertical force
    on the wheel (the rig's wheel load, CONTACT's FZ): N is then iterated
    until the contact force's vertical component, N n_z + fy t2_z, is Fz
    to tol (at least 1e-7).  mu: Coulomb friction; E [Pa], nu: both bodies.
    Creepages: cx, cy, cphi given (at the patch's reference point, in its
    frame), or from the kinematics: spin, roller_spin [rad/s] as for
    rig_contact (vy [m/s], yaw_rate [rad/s]; zero yaw and longitudinal
    shift; see _creepages for the material points); table: a ContactTable
    of geometry for the wheelset's pose and rates (default: one built
    around y_ws).  reference: as undeformed_distance (default "weighted",
    CONTACT's reference: the patch's centre, not its deepest point).
    loaded: h at the loaded pose, the wheelset lowered from its zero-gap
    height by the approach over cos(delta) (as CONTACT: the load moves the
    wheelset vertically, not along the normal, so the wheel also slides by
    approach tan(delta) along the plane); False: at the zero-gap pose.
    passes: 2 (default): a first grid of n/2 across (elements twice dx, dy
    where those are given) at the zero-gap pose, sized from Hertz's
    approach, finds the approach; the second, with n
    across, covers where h <= 1.1 times it (1.03 on elements of given
    dx, dy); 1: one grid sized from Hertz's
    approach (or the approach given).  Either way a solution whose contact
    reaches the grid's edge, or whose approach exceeds what the grid
    covers, is solved again on a grid sized from the approach found.
    tol, maxit: the solver's.  **patch_options: further options of
    undeformed_distance (approach, cover, dx, dy, combine, z, roll).
    Returns RigExact (the ExactSolution, the Patch, the creepages used).
    """
    func = "rig_exact"
    if (N is None) == (Fz is None):
        raise RollerRigError(f"{func}: give the normal load N or the vertical load Fz [N]")
    N = _number(func, "N", N, allow_none=True)
    Fz = _number(func, "Fz", Fz, allow_none=True)
    if passes not in (1, 2):
        raise RollerRigError(f"{func}: passes must be 1 or 2, got {passes!r}")
    given = [v is not None for v in (cx, cy, cphi)]
    if any(given) and not all(given):
        raise RollerRigError(f"{func}: give all three creepages cx, cy, cphi or none")
    if not all(given) and (spin is None or roller_spin is None):
        raise RollerRigError(f"{func}: give spin and roller_spin [rad/s] (or cx, cy, cphi)")
    unknown = set(patch_options) - {"approach", "cover", "dx", "dy", "combine", "z", "roll"}
    if unknown:
        raise RollerRigError(f"{func}: unknown option(s) {sorted(unknown)}")
    G = E / (2.0 * (1.0 + nu))
    opts = dict(patch_options)
    approach = opts.pop("approach", None)
    cover = opts.pop("cover", 1.5)
    z_given = opts.pop("z", None)
    z0, _, cpt = _pose_and_point(func, geometry, y_ws, side)
    delta0 = float(cpt.delta[0])
    first_ref = "point" if reference == "weighted" else reference
    count = 0

    def build(load, nn, a, cov, ref, lower, coarse=1.0):
        z = z_given if z_given is not None else (z0 - a / np.cos(delta0) if lower else None)
        o = {k: coarse * v if k in ("dx", "dy") and v is not None else v
             for k, v in opts.items()}
        if coarse != 1.0:
            # rr_wheel_exact.c's COARSE_SAMPLE: samples 4 x 2e-5 m apart, or a
            # tenth of the coarse elements where given and smaller
            given = [v for v in (o.get("dx"), o.get("dy")) if v]
            o["sample"] = max(min(4 * _SAMPLE, 0.1 * min(given)) if len(given) == 2
                              else 4 * _SAMPLE, _SAMPLE_MIN)
        try:
            return undeformed_distance(geometry, y_ws, side=side, N=load, n=nn, E=E, nu=nu,
                                       approach=a, cover=cov, reference=ref, z=z, **o)
        except RollerRigError as e:
            if coarse == 1.0 or (o.get("dx") is None and o.get("dy") is None):
                raise
            raise RollerRigError(f"{func}: the first pass, on elements twice dx, dy: "
                                 f"{e}") from None

    def solve(p, load):
        nonlocal count
        count += 1
        if all(given):
            k = (float(cx), float(cy), float(cphi), 0.0)
        else:
            k = _creepages(geometry, p, spin, roller_spin, vy, yaw_rate, vmin, table)
        # a contact at the grid's edge is taken here: it sizes the next grid
        s = _exact_solve(func, p.h, dict(dx=p.dx, dy=p.dy, x0=p.x0, y0=p.y0, N=load, mu=mu,
                                         G=G, nu=nu, cx=k[0], cy=k[1], cphi=k[2]),
                         dict(tol=tol, maxit=maxit), edge_ok=True)
        return s, k

    def at(load, a):
        """Patch, solution and creepages for the normal load; a: an
        estimate of the approach (None: find it)."""
        # elements of given size: 1.03 (rr_wheel_exact.c, GIVEN_COVER)
        cov = 1.03 if opts.get("dx") and opts.get("dy") else 1.1
        if a is None:
            if passes == 2:
                s, _ = solve(build(load, max(4, n // 2), approach, cover, first_ref, False,
                                   coarse=2.0), load)
                a = s.delta
            else:
                a, cov = approach, cover
                if a is None:
                    from rollerrig.contact.creep import hertz
                    a = float(hertz(float(cpt.A[0]), float(cpt.B[0]), load, E=E,
                                    nu=nu).delta)
        p = build(load, n, a, cov, reference, loaded)
        s, k = solve(p, load)
        # the contact lies where h <= the approach found: a grid that covers
        # less, or a contact that reaches the grid's edge, is solved again
        for _ in range(4):
            if not (_edge(s.contact) or s.delta > p.approach * p.cover):
                return p, s, k
            p = build(load, n, s.delta, 1.3, reference, loaded)
            s, k = solve(p, load)
        raise RollerRigError(f"{func}: at y_ws = {y_ws!r} m the contact keeps reaching the "
                             f"grid's edge")

    if Fz is None:
        p, s, k = at(N, None)
    else:
        # vertical balance: Fz = N n_z + fy t2_z (t1 is horizontal), by the
        # secant method on N on a fixed grid (fy depends on N only weakly: a
        # few solves), then once more on the grid and pose of the load found
        # where the approach moved by over 1 %
        N = Fz / np.cos(delta0)
        p, s, k = at(N, None)
        sized = all(float(patch_options.get(d) or 0.0) > 0.0 for d in ("dx", "dy"))
        cov_loaded = 1.03 if sized else 1.1
        for rebuild in (False, True):
            if rebuild:
                # rr_wheel_exact.c's REBUILD_TOL: a grid built for an
                # approach within 1 % of the one found is kept (elements
                # from n: where its cover is the loaded grid's)
                if ((sized or p.cover == cov_loaded)
                        and abs(s.delta / p.approach - 1.0) <= 0.01):
                    break
                p, s, k = at(N, s.delta)
            last = None
            for _ in range(30):
                r = (Fz - s.fy * p.t2[2]) / p.n[2] - N     # the fixed point's residual
                if abs(r) <= max(tol, 1e-7) * Fz:          # rr_wheel_exact.c's FZ_TOL
                    break
                if (not rebuild and abs(r) <= 1e-3 * Fz    # EARLY_TOL: a grid to be rebuilt
                        and abs(s.delta / p.approach - 1.0) > 0.01):
                    break
                if last is not None:
                    step = r if last[1] == r else -r * (N - last[0]) / (r - last[1])
                else:
                    # rr_wheel_exact.c's first_step: Newton's with fy's slope
                    # d ln fy / d ln N = 1 - k (1 - k)^2 / f, f = |F| / (mu N),
                    # k = 1 - (1 - f)^(1/3) (the slope 0 before)
                    f = min(np.hypot(s.fx, s.fy) / (mu * N), 1.0)
                    kk = 1.0 - np.cbrt(1.0 - f)
                    slope = 1.0 - kk * (1.0 - kk) ** 2 / f if f > 0.0 else 2.0 / 3.0
                    d = 1.0 + slope * s.fy * p.t2[2] / (p.n[2] * N)
                    step = r / d if np.isfinite(d) and d > 0.2 else r
                last = (N, r)
                N += step                                   # secant after the first step
                s, k = solve(p, N)
            else:
                raise RollerRigError(f"{func}: the normal load for Fz = {Fz!r} N did not "
                                     f"settle")
    return RigExact(solution=s, patch=p, cx=k[0], cy=k[1], cphi=k[2], V=k[3], N=N,
                    passes=count)
