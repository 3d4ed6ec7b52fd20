"""The undeformed distance of one wheel on its roller for SEVERAL patches, and
the exact theory on them with a shared approach (the non-Hertzian study,
NONHERTZ_STUDY.md).

rr.undeformed_distance / rr.rig_exact build one planar patch: the deepest
interpenetration region and those within `combine` (4 mm, CONTACT's D_COMB)
of it, on one grid; regions farther away are left out with a warning.  On
S1002 / UIC60 at +4.0 to +5.2 mm the tread and the flange root are 10 mm
apart and both touch, so the study needs what CONTACT does there: each
group of regions its own patch with its own tangent plane, all at the one
pose of the wheelset (lowered vertically by dz from the zero-gap pose), each
patch's approach its own interpenetration at that pose, the load split
between the patches as the normal problems say, the vertical load their sum.

This module mirrors rollerrig/patch.py's construction (the profiles' own
splines sampled 0.02 mm apart, the exact circles in x, CONTACT's weighted
reference per patch, square elements on multiples of dx from the reference
point) using only the public API (Profile.z_at / slope, wheelset_contact,
rig_contact, exact_solve); check_against_rig_exact() compares it with
rr.undeformed_distance on the same inputs (h to 1e-12 m).
"""
from dataclasses import dataclass, field

import numpy as np

import rollerrig as rr

SAMPLE = 2e-5          # profile samples [m] (patch.py's _SAMPLE)
WINDOW = 0.04          # lateral half-window around a patch [m] (patch.py's _WINDOW)
COMBINE = 4e-3         # regions closer than this share a patch (CONTACT's D_COMB)


def _drop(radius, x):
    x2 = np.square(x)
    return x2 / (radius + np.sqrt(np.maximum(np.square(radius) - x2, 0.0)))


def _runs(mask):
    m = np.concatenate(([False], mask, [False])).astype(np.int8)
    d = np.diff(m)
    return list(zip(np.flatnonzero(d == 1), np.flatnonzero(d == -1)))


def _monotone(yc, zeta, k0):
    """The run of samples around k0 along which yc is strictly monotonic,
    ordered by increasing yc (patch.py's _single_valued)."""
    d = np.diff(yc)
    k0 = int(np.clip(k0, 0, d.size - 1))
    sgn = np.sign(d[k0])
    good = np.isfinite(d) & (np.sign(d) == sgn)
    bad = np.flatnonzero(~good)
    lo = bad[bad < k0]
    hi = bad[bad > k0]
    lo = int(lo[-1]) + 1 if lo.size else 0
    hi = int(hi[0]) if hi.size else d.size
    y, z = yc[lo:hi + 1], zeta[lo:hi + 1]
    return (y, z) if sgn > 0 else (y[::-1], z[::-1])


class Wheel:
    """One wheel of a RigGeometry on its roller: cross-sections at a pose."""

    def __init__(self, geometry, side):
        self.g = geometry
        self.side = side
        left = side == "left"
        self.sigma = 1.0 if left else -1.0
        self.wheel = geometry.wheel if left else (geometry.wheel_right or geometry.wheel)
        self.roller = geometry.roller if left else (geometry.roller_right or geometry.roller)
        self.r0 = float(geometry.wheel_radius)
        self.R0 = float(geometry.roller_radius)
        self.wheel_y = float(geometry.wheel_y)
        self.roller_y = float(geometry.roller_y)
        # dense samples of both profiles, once
        self.sw = np.arange(self.wheel.y_min, self.wheel.y_max, SAMPLE)
        self.zw = -self.wheel.z_at(self.sw)
        self.sr = np.arange(self.roller.y_min, self.roller.y_max, SAMPLE)
        self.zr = -self.roller.z_at(self.sr)
        self.alpha_r = np.arctan(-self.roller.slope(self.sr))

    # ---- cross-sections in the rig's (Y, Z)
    def roller_yz(self, x=0.0, idx=slice(None)):
        zr = self.zr[idx]
        return self.sigma * (self.roller_y + self.sr[idx]), zr - _drop(self.R0 + zr, x)

    def wheel_yz(self, pose, x=0.0, idx=slice(None)):
        y_ws, z, roll = pose
        zw = self.zw[idx]
        yl = self.sigma * (self.wheel_y + self.sw[idx])
        zl = -self.r0 + zw + _drop(self.r0 - zw, x)
        c, s = np.cos(roll), np.sin(roll)
        return y_ws + yl * c - zl * s, z + yl * s + zl * c

    def vertical_gap(self, pose):
        """At x = 0: the roller's samples' rig Y (increasing), the wheel's
        surface height minus the roller's there (the vertical gap), the
        roller profile coordinate, 1/r + 1/R and the roller's inclination."""
        Yr, Zr = self.roller_yz()
        Yw, Zw = self.wheel_yz(pose)
        ow = np.argsort(Yw)
        inside = (Yr > Yw[ow[0]]) & (Yr < Yw[ow[-1]])
        Yr, Zr = Yr[inside], Zr[inside]
        sr, alpha = self.sr[inside], self.alpha_r[inside]
        g = np.interp(Yr, Yw[ow], Zw[ow]) - Zr
        sw = np.interp(Yr, Yw[ow], self.sw[ow])
        curv = 1.0 / (self.r0 + self.wheel.z_at(sw)) + 1.0 / (self.R0 - self.roller.z_at(sr))
        o = np.argsort(Yr)
        return Yr[o], g[o], sr[o], curv[o], alpha[o]


def pose_at(geometry, y_ws):
    c = rr.wheelset_contact(geometry, y_ws)
    return float(y_ws), float(c.z[0]), float(c.roll[0])


def groups(Y, pen, combine=COMBINE):
    """Runs of pen > 0 (index ranges) grouped: runs within `combine` of each
    other share a group (transitively).  Returns a list of lists of (a, b)."""
    runs = _runs(pen > 0)
    out = []
    for a, b in runs:
        if out and Y[a] - Y[out[-1][-1][1] - 1] <= combine:
            out[-1].append((a, b))
        else:
            out.append([(a, b)])
    return out


#: split a group where the roller's inclination at two neighbouring gap
#: minima differs by more than this [rad] (None: never; CONTACT's A_SEP, 90
#: degrees in the 72 cases): each part its own patch and plane, cut at the
#: gap's largest value between them
A_SEP = None


def split_by_angle(Y, g, alpha, runs, a_sep):
    """A group's runs split into parts at the saddles between gap minima
    whose inclinations differ by more than a_sep.  Returns a list of lists
    of (a, b)."""
    idx = np.concatenate([np.arange(a, b) for a, b in runs])
    gi = g[idx]
    # local minima within the group (a run's ends count where they are lowest)
    m = np.flatnonzero((np.r_[np.inf, gi[:-1]] >= gi) & (np.r_[gi[1:], np.inf] > gi))
    if m.size < 2:
        return [runs]
    cuts = []
    last = m[0]
    for k in m[1:]:
        if abs(alpha[idx[k]] - alpha[idx[last]]) > a_sep:
            cuts.append(last + int(np.argmax(gi[last:k + 1])))
        if gi[k] < gi[last] or abs(alpha[idx[k]] - alpha[idx[last]]) > a_sep:
            last = k
    if not cuts:
        return [runs]
    bounds = [idx[0]] + [idx[c] for c in cuts] + [idx[-1] + 1]
    out = []
    for lo, hi in zip(bounds[:-1], bounds[1:]):
        part = [(max(a, lo), min(b, hi)) for a, b in runs if min(b, hi) > max(a, lo)]
        if part:
            out.append(part)
    return out


def weighted_reference(Y, g_shifted, curv, alpha, sr, approach, delta, runs):
    """CONTACT's reference of a patch (patch.py's _weighted_reference) over
    the sample runs of its group: each strip weighted by pen^2.5 / sqrt(a),
    pen = approach / cos(delta) - g; delta iterated."""
    keep = np.zeros(Y.size, dtype=bool)
    for a, b in runs:
        keep[a:b] = True
    a_ = 0.5 * curv
    w = None
    for _ in range(50):
        pen = approach / np.cos(delta) - g_shifted
        w = np.where(keep, np.maximum(pen, 0.0) ** 2.5 / np.sqrt(a_), 0.0)
        if not w.sum() > 0:
            break
        new = float(np.sum(w * alpha) / np.sum(w))
        done = abs(new - delta) < 1e-13
        delta = new
        if done:
            break
    Yc = float(np.sum(w * Y) / np.sum(w))
    return float(np.interp(Yc, Y, sr)), delta


@dataclass
class Grid:
    """h on a grid in one patch's plane (rollerrig.Patch's fields we use)."""
    h: np.ndarray          # [m], least value 0
    dx: float
    dy: float
    x0: float
    y0: float
    pen: float             # interpenetration at the pose (-least h before the shift)
    point: np.ndarray      # P in the rig frame (3,)
    t1: np.ndarray
    t2: np.ndarray
    n: np.ndarray
    delta: float
    s_roller: float
    r: float
    R: float
    extra: dict = field(default_factory=dict)

    @property
    def x(self):
        my, mx = self.h.shape
        return np.broadcast_to(self.x0 + self.dx * np.arange(mx), (my, mx))

    @property
    def y(self):
        my, mx = self.h.shape
        return np.broadcast_to((self.y0 + self.dy * np.arange(my))[:, None], (my, mx))


class Plane:
    """The tangent plane through the roller's point at s_roller, angle delta,
    and both bodies' cross-sections in it at a pose."""

    def __init__(self, wheel, pose, s_roller, delta):
        self.w, self.pose = wheel, pose
        self.s_roller, self.delta = float(s_roller), float(delta)
        sig = wheel.sigma
        zr = -wheel.roller.z_at(s_roller)
        self.P = np.array([sig * (wheel.roller_y + s_roller), zr])
        c, s = np.cos(delta), np.sin(delta)
        self.t2 = np.array([c, sig * s])
        self.n = np.array([-sig * s, c])
        kr = int(np.argmin(np.abs(wheel.sr - s_roller)))
        lo, hi = np.searchsorted(wheel.sr, [s_roller - WINDOW, s_roller + WINDOW])
        self.ir = slice(lo, hi)
        self.kr = kr - lo
        # the wheel's samples around where P's normal meets it: nearest in Y
        Yw, _ = wheel.wheel_yz(pose)
        kw = int(np.argmin(np.abs(Yw - self.P[0])))
        sw0 = wheel.sw[kw]
        lo, hi = np.searchsorted(wheel.sw, [sw0 - WINDOW, sw0 + WINDOW])
        self.iw = slice(lo, hi)
        self.kw = kw - lo

    def project(self, Y, Z):
        dY, dZ = Y - self.P[0], Z - self.P[1]
        return dY * self.t2[0] + dZ * self.t2[1], dY * self.n[0] + dZ * self.n[1]

    def sections(self, x):
        yr, zr = _monotone(*self.project(*self.w.roller_yz(x, self.ir)), self.kr)
        yw, zw = _monotone(*self.project(*self.w.wheel_yz(self.pose, x, self.iw)), self.kw)
        return yr, zr, yw, zw

    def gap(self, x, y):
        yr, zr, yw, zw = self.sections(x)
        g = np.interp(y, yw, zw) - np.interp(y, yr, zr)
        g = np.asarray(g, dtype=float)
        g[(y < max(yr[0], yw[0])) | (y > min(yr[-1], yw[-1]))] = np.nan
        return g

    def limits(self):
        yr, _, yw, _ = self.sections(0.0)
        return max(yr[0], yw[0]), min(yr[-1], yw[-1])

    def vectors(self):
        return (np.array([1.0, 0.0, 0.0]), np.array([0.0, *self.t2]),
                np.array([0.0, *self.n]))

    def grid(self, approach, y_range, n=40, cover=1.1, dx=None, n_short=16):
        """h on a grid covering where h <= cover * approach within the plane's
        lateral range y_range (the group's), one exterior element around;
        square elements, n across the region's longer side and at least
        n_short across its shorter one (dx given: that)."""
        lo_s, hi_s = self.limits()
        step = SAMPLE
        yf = np.arange(max(lo_s, y_range[0]), min(hi_s, y_range[1]), step)
        hy = self.gap(0.0, yf)
        hmin = np.nanmin(hy)
        level = cover * approach
        inside = hy - hmin <= level
        lo, hi = yf[inside].min(), yf[inside].max()
        w = self.w
        sw = np.interp(0.0, *self._wheel_s())
        r_P = w.r0 + w.wheel.z_at(sw)
        R_P = w.R0 - w.roller.z_at(self.s_roller)
        x_t = np.sqrt(2.0 * level / (np.cos(self.delta) * (1.0 / r_P + 1.0 / R_P)))
        rise = np.maximum((self.gap(x_t, yf) - hy)[inside], 1e-3 * level) / x_t ** 2
        xh = float(np.max(np.sqrt((level - (hy - hmin)[inside]) / rise)))
        if dx is None:
            dx = min(max(2.0 * xh, hi - lo) / n, min(2.0 * xh, hi - lo) / n_short)
        dy = dx
        i_lo, i_hi = int(np.floor(-xh / dx)) - 1, int(np.ceil(xh / dx)) + 1
        j_lo, j_hi = int(np.floor(lo / dy)) - 1, int(np.ceil(hi / dy)) + 1
        for _ in range(200):
            xs = dx * np.arange(i_lo, i_hi + 1)
            ys = dy * np.arange(j_lo, j_hi + 1)
            h = np.stack([self.gap(x, ys) for x in xs], axis=1)
            ins = h - hmin <= level
            ins[(ys < lo - 0.5 * dy) | (ys > hi + 0.5 * dy), :] = False
            grow = (ins[:, 0].any(), ins[:, -1].any(), ins[0].any(), ins[-1].any())
            if not any(grow):
                break
            i_lo -= grow[0]
            i_hi += grow[1]
            j_lo -= grow[2]
            j_hi += grow[3]
        if not np.all(np.isfinite(h)):
            raise rr.RollerRigError("nonhertz_geom: the patch reaches where a profile ends")
        # lateral positions outside the group's range: no contact there
        h[(ys < y_range[0]) | (ys > y_range[1]), :] = np.maximum(
            h[(ys < y_range[0]) | (ys > y_range[1]), :], hmin + 10 * level)
        hmin_g = float(np.min(h))
        t1, t2, nn = self.vectors()
        return Grid(h=h - hmin_g, dx=float(dx), dy=float(dy), x0=float(xs[0]),
                    y0=float(ys[0]), pen=max(0.0, -hmin_g), point=np.array([0.0, *self.P]),
                    t1=t1, t2=t2, n=nn, delta=self.delta, s_roller=self.s_roller,
                    r=float(r_P), R=float(R_P))

    def _wheel_s(self):
        Yw, Zw = self.w.wheel_yz(self.pose, 0.0, self.iw)
        yc, _ = self.project(Yw, Zw)
        return _monotone(yc, self.w.sw[self.iw], self.kw)

    def plane_y(self, Y):
        """The plane's y of the roller's surface point at rig Y (x = 0)."""
        Yr, Zr = self.w.roller_yz(0.0, self.ir)
        yc, _ = self.project(Yr, Zr)
        o = np.argsort(Yr)
        return np.interp(Y, Yr[o], yc[o])


# ------------------------------------------------------------------ kinematics

class Kinematics:
    """The rigid motions of the wheelset (rig_contact's pose and rates at
    y_ws, zero yaw and x) and the roller, and the creepages at a patch
    (patch.py's _creepages)."""

    def __init__(self, table, y_ws, spin, roller_spin, vy=0.0, yaw_rate=0.0, vmin=1e-3):
        c = rr.rig_contact(table, y=y_ws, vy=vy, yaw_rate=yaw_rate, spin=spin,
                           roller_spin=roller_spin, N_left=1.0, N_right=1.0,
                           kinematics_only=True, vmin=vmin, errors="raise")
        self.c = np.asarray(c.pose.c, dtype=float)
        self.v = np.asarray(c.pose.v, dtype=float)
        self.w = np.asarray(c.pose.w, dtype=float)
        self.R0 = float(table.geometry.roller_radius)
        self.roller_spin = float(roller_spin)
        self.vmin = vmin

    def creepages(self, point, t1, t2, n, pen, lowered):
        """(cx, cy, cphi, V) at P (the roller's point) with the wheel's
        material point P - pen n, the wheelset lowered by `lowered`."""
        centre = self.c - np.array([0.0, 0.0, lowered])
        q = point - pen * n
        vw = self.v + np.cross(self.w, q - centre)
        wr = np.array([0.0, -self.roller_spin, 0.0])
        vr = np.cross(wr, point - np.array([0.0, 0.0, -self.R0]))
        V = max(abs(float(np.dot(vw + vr, t1))) / 2.0, self.vmin)
        slip = vw - vr
        return (float(np.dot(slip, t1)) / V, float(np.dot(slip, t2)) / V,
                float(np.dot(self.w - wr, n)) / V, V)


def check_against_rig_exact(geometry, y_ws, side="left", N=61163.0):
    """h of this module against rr.undeformed_distance on the same pose,
    reference and grid: the largest difference [m]."""
    e = rr.rig_exact(geometry, y_ws, side=side, N=N, mu=0.5, cx=0.0, cy=0.0, cphi=0.0, n=30)
    p = e.patch
    w = Wheel(geometry, side)
    pl = Plane(w, (p.y_ws, p.z, p.roll), p.s_roller, p.delta)
    my, mx = p.h.shape
    xs = p.x0 + p.dx * np.arange(mx)
    ys = p.y0 + p.dy * np.arange(my)
    h = np.stack([pl.gap(x, ys) for x in xs], axis=1)
    h -= h.min()
    return float(np.max(np.abs(h - p.h)))


# ------------------------------------------------------------------ the exact theory, several patches

@dataclass
class PatchSolution:
    grid: Grid
    N: float
    fx: float
    fy: float
    mz: float              # about the patch's reference point P
    cx: float
    cy: float
    cphi: float
    area: float
    pmax: float
    centre: np.ndarray     # force centre (pressure centroid), rig frame
    approach: float
    solution: object = None

    @property
    def force(self):
        g = self.grid
        return self.fx * g.t1 + self.fy * g.t2 + self.N * g.n


@dataclass
class MultiExact:
    patches: list
    dz: float
    pose: tuple

    @property
    def force(self):
        return sum((p.force for p in self.patches), np.zeros(3))

    @property
    def N(self):
        return sum(p.N for p in self.patches)

    @property
    def area(self):
        return sum(p.area for p in self.patches)

    @property
    def pmax(self):
        return max(p.pmax for p in self.patches)

    @property
    def centre(self):
        return sum(p.N * p.centre for p in self.patches) / self.N


def _solve(grid, N, mu, G, nu, cx=0.0, cy=0.0, cphi=0.0):
    return rr.exact_solve(grid.h, dx=grid.dx, dy=grid.dy, x0=grid.x0, y0=grid.y0, N=N, mu=mu,
                          G=G, nu=nu, cx=cx, cy=cy, cphi=cphi)


def load_for_approach(grid, pen, mu, G, nu, N0, tol=1e-10):
    """The normal load whose exact approach on grid is pen (secant in log-log:
    N about pen^1.5); returns (N, solution)."""
    lp = np.log(pen)
    N = N0
    pts = []
    for _ in range(40):
        s = _solve(grid, N, mu, G, nu)
        r = np.log(s.delta) - lp
        if abs(r) < tol:
            return N, s
        pts.append((np.log(N), r))
        if len(pts) == 1:
            lN = np.log(N) - r / (2.0 / 3.0)
        else:
            (a0, r0), (a1, r1) = pts[-2], pts[-1]
            lN = a1 - r1 * (a1 - a0) / (r1 - r0) if r1 != r0 else a1 - 1.5 * r1
        N = float(np.exp(lN))
    raise rr.RollerRigError("load_for_approach did not settle")


class Patches:
    """The patches of one wheel at lateral shift y_ws: groups of the
    vertical gap's regions where it is under cover * dz_ref, each with its
    plane (CONTACT's weighted reference at its approach)."""

    def __init__(self, wheel, pose0, dz_ref, cover=1.5, combine=COMBINE, a_sep=None):
        self.wheel, self.pose0 = wheel, pose0
        Y, g, sr, curv, alpha = wheel.vertical_gap(pose0)
        g = g - g.min()
        self.Y, self.g, self.sr, self.curv, self.alpha = Y, g, sr, curv, alpha
        self.groups = []
        a_sep = A_SEP if a_sep is None else a_sep
        parts = groups(Y, cover * dz_ref - g, combine)
        if a_sep is not None:
            parts = [p for runs in parts for p in split_by_angle(Y, g, alpha, runs, a_sep)]
        for runs in parts:
            idx = np.concatenate([np.arange(a, b) for a, b in runs])
            k = idx[np.argmin(g[idx])]
            self.groups.append(dict(runs=runs, g=float(g[k]), k=int(k),
                                    Y=(float(Y[runs[0][0]]), float(Y[runs[-1][1] - 1]))))
            self.reference(len(self.groups) - 1, max(dz_ref - g[k], 0.05 * dz_ref)
                           * np.cos(alpha[k]))

    def reference(self, j, approach):
        """Set group j's plane: the weighted reference at this approach."""
        gr = self.groups[j]
        s_r, delta = weighted_reference(self.Y, self.g - gr["g"], self.curv, self.alpha,
                                        self.sr, approach, float(self.alpha[gr["k"]]),
                                        gr["runs"])
        gr["s_roller"], gr["delta"] = s_r, delta

    def plane(self, j, dz):
        y_ws, z0, roll = self.pose0
        gr = self.groups[j]
        return Plane(self.wheel, (y_ws, z0 - dz, roll), gr["s_roller"], gr["delta"])

    def y_range(self, plane, j, margin=1.0e-3):
        """The group's lateral range in the plane (its rig Y interval, widened
        by margin, halfway to the neighbouring groups at most)."""
        gr = self.groups[j]
        lo, hi = gr["Y"][0] - margin, gr["Y"][1] + margin
        if j > 0:
            lo = max(lo, 0.5 * (self.groups[j - 1]["Y"][1] + gr["Y"][0]))
        if j + 1 < len(self.groups):
            hi = min(hi, 0.5 * (gr["Y"][1] + self.groups[j + 1]["Y"][0]))
        a, b = plane.plane_y(np.array([lo, hi]))
        return (min(a, b), max(a, b))

    def grid(self, j, dz, n=40, cover=1.1, dx=None, n_short=16):
        """Group j's grid at the pose lowered by dz, or None if it does not
        touch there."""
        gr = self.groups[j]
        if dz - gr["g"] <= 0:
            return None
        pl = self.plane(j, dz)
        app = (dz - gr["g"]) * np.cos(gr["delta"])
        try:
            return pl.grid(app, self.y_range(pl, j), n=n, cover=cover, dx=dx, n_short=n_short)
        except (ValueError, rr.RollerRigError):
            return None


def _edge(contact):
    return contact[:, 0].any() or contact[:, -1].any() or contact[0].any() or contact[-1].any()


def exact_multi(wheel, table, y_ws, Fz, *, spin, roller_spin, vy=0.0, mu=0.52, G=8.2e10,
                nu=0.28, n=40, n_short=16, richardson=True, dz0=None, tol=1e-6,
                consistent_plane=True):
    """One wheel at y_ws under the vertical load Fz solved by the exact
    theory on every patch (see the module's docstring), as rig_exact does
    one: a first balance on grids from an estimate, each patch's reference
    set at the approach found, grids rebuilt at the pose found (cover 1.1,
    n across), the vertical balance N n_z + fy t2_z = Fz over the patches
    solved again with the tangential forces.  Returns MultiExact
    (Richardson's forces when richardson: the same planes and pose on
    elements half the size; the fine grid's normal solution)."""
    pose0 = pose_at(wheel.g, y_ws)
    kin = Kinematics(table, y_ws, spin, roller_spin, vy=vy)
    if dz0 is None:
        c = getattr(rr.wheelset_contact(wheel.g, y_ws), wheel.side)
        d = float(c.delta[0])
        dz0 = float(rr.hertz(float(c.A[0]), float(c.B[0]), Fz / np.cos(d), E=2 * G * (1 + nu),
                             nu=nu).delta) / np.cos(d)
    pt = Patches(wheel, pose0, dz0)

    def normal(grids, dz, dz_built, Ns):
        res = []
        for j, gr in enumerate(grids):
            pen = None if gr is None else gr.pen + (dz - dz_built) * np.cos(gr.delta)
            if gr is None or pen <= 1e-10:
                res.append((0.0, None))
                continue
            N0 = Ns[j] if Ns[j] else Fz * (pen / max(dz * np.cos(gr.delta), 1e-9)) ** 1.5
            res.append(load_for_approach(gr, pen, mu, G, nu, N0))
        return res

    def tangential(grids, dz, dz_built, res):
        out = []
        for gr, (N, s0) in zip(grids, res):
            if s0 is None:
                out.append(None)
                continue
            pen = gr.pen + (dz - dz_built) * np.cos(gr.delta)
            k = kin.creepages(gr.point, gr.t1, gr.t2, gr.n, pen, dz)
            out.append((_solve(gr, N, mu, G, nu, *k[:3]), k[:3]))
        return out

    def balance(grids, dz_built, dz, with_tangential):
        Ns = [None] * len(grids)
        pts = []
        for _ in range(40):
            res = normal(grids, dz, dz_built, Ns)
            Ns = [r[0] for r in res]
            tan = tangential(grids, dz, dz_built, res) if with_tangential else None
            S = 0.0
            for j, (gr, (N, s0)) in enumerate(zip(grids, res)):
                if s0 is not None:
                    S += N * gr.n[2] + (tan[j][0].fy * gr.t2[2] if tan else 0.0)
            if abs(S - Fz) <= tol * Fz:
                return dz, res, tan
            pts.append((dz, S))
            # secant on S^(2/3) (nearly linear in dz), kept inside the bracket
            lo = max((d for d, v in pts if v < Fz), default=None)
            hi = min((d for d, v in pts if v > Fz), default=None)
            step = dz * (Fz / max(S, 1e-3 * Fz)) ** (2.0 / 3.0)
            if len(pts) > 1:
                (d0, S0), (d1, S1) = pts[-2], pts[-1]
                f0, f1 = np.cbrt(S0) ** 2 - np.cbrt(Fz) ** 2, np.cbrt(S1) ** 2 - np.cbrt(Fz) ** 2
                if f1 != f0 and d1 != d0:
                    step = d1 - f1 * (d1 - d0) / (f1 - f0)
            if lo is not None and hi is not None and not lo < step < hi:
                step = 0.5 * (lo + hi)
            dz = max(step, 1e-9) if np.isfinite(step) else 0.5 * dz
        raise rr.RollerRigError(f"exact_multi: the vertical load did not settle at y = {y_ws}")

    # a first balance on coarse grids at the estimate's pose
    grids = [pt.grid(j, dz0, n=max(4, n // 2), cover=1.5, n_short=max(4, n_short // 2))
             for j in range(len(pt.groups))]
    dz, res, _ = balance(grids, dz0, dz0, False)
    # each patch's reference at its approach found, its grid at the pose found;
    # then (consistent_plane) again at the approach of the balance with the
    # tangential forces, until the plane is the final load's, as rig_exact's
    # rebuild makes it (the first balance leaves out the creep force's share
    # fy sin(delta) of Fz: at the flange root 20 % of the approach, 0.01 rad
    # of plane, 0.037 mu N in the forces)
    apps = [s0.delta if s0 is not None else None for (N, s0) in res]
    for _ in range(4 if consistent_plane else 1):
        for j, a in enumerate(apps):
            if a is not None:
                pt.reference(j, a)
        for cover in (1.1, 1.3, 1.6):
            grids = [pt.grid(j, dz, n=n, cover=cover, n_short=n_short)
                     for j in range(len(pt.groups))]
            dz_b = dz
            dz, res, tan = balance(grids, dz_b, dz, True)
            if not any(t is not None and (_edge(t[0].contact) or t[0].delta > 1.02 * cover *
                                          (dz_b - pt.groups[j]["g"]) * np.cos(grids[j].delta))
                       for j, t in enumerate(tan)):
                break
        new = [t[0].delta if t is not None else None for t in tan]
        if all(a is None or b is None or abs(b / a - 1) < 0.01 for a, b in zip(apps, new)):
            break
        apps = new
    patches = []
    for j, (gr, (N, s0), t) in enumerate(zip(grids, res, tan)):
        if t is None:
            continue
        s, (cx, cy, cphi) = t
        fx, fy, mz, sol = s.fx, s.fy, s.mz, s
        if richardson:
            fine = pt.grid(j, dz_b, cover=cover, dx=gr.dx / 2)
            sf = _solve(fine, N, mu, G, nu, cx, cy, cphi)
            fx, fy, mz, sol = 2 * sf.fx - s.fx, 2 * sf.fy - s.fy, 2 * sf.mz - s.mz, sf
        pn = sol.pn
        xc = float(np.sum(pn * sol.x) / np.sum(pn))
        yc = float(np.sum(pn * sol.y) / np.sum(pn))
        patches.append(PatchSolution(grid=gr, N=N, fx=fx, fy=fy, mz=mz, cx=cx, cy=cy,
                                     cphi=cphi, area=sol.contact_area, pmax=sol.pmax,
                                     centre=gr.point + xc * gr.t1 + yc * gr.t2,
                                     approach=sol.delta, solution=sol))
    return MultiExact(patches=patches, dz=dz, pose=pose0)
