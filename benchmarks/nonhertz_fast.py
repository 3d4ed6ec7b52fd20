"""Fast non-Hertzian multi-patch contact: the study's prototypes (numpy).

Every method takes one wheel's state as the rig has it (lateral shift y,
vertical load Fz, the wheelset's spin and lateral velocity and the rollers'
speed, friction mu) and returns the contact force on the wheel in the rig
frame with the normal solution (load, area, peak pressure, force centre):

- hertz(method): today's rig_contact, one Hertz ellipse at the rigid
  contact point (FASTSIM 20 x 20 or exact_table), the normal load from the
  vertical one (N n_z + fy t2_z = Fz);
- multi_hertz: every separate region of the gap its own equivalent
  ellipse from a virtual interpenetration (Kik-Piotrowski's idea), the
  load split by a shared approach and each patch's Hertz law with the
  effective curvatures of its region, exact_table per patch;
- TableMethod: tables per lateral shift built by the exact solver (Row,
  build_row): per patch and per approach node the exact normal solution
  (load, plane, area, peak, centre, pressure moments) and its exact linear
  creep coefficients; at run time the shared approach from Fz, each
  patch's node data interpolated, and the tangential problem by
    "area":       the ellipse of the pressure's moments, area-matched, exact_table;
    "calibrated": the ellipse whose exact_table linear coefficients are the
                  patch's (c^2 from C11, cy and cphi scaled to C22, C23), exact_table;
    "fastsim":    FASTSIM on the exact pressure, flexibilities from the same
                  coefficients;
    "corrected":  "calibrated" plus the exact theory's departure from it at a
                  few creepage nodes per patch node, interpolated (see Row).
"""
from dataclasses import dataclass, field

import numpy as np

import rollerrig as rr
import nonhertz_geom as ng

G_DEF, NU_DEF = 8.2e10, 0.28
ESTAR = lambda G, nu: G / (1.0 - nu)      # E / (2 (1 - nu^2)) with E = 2 G (1 + nu)


# ------------------------------------------------------------------ results

@dataclass
class Result:
    force: np.ndarray       # contact force on the wheel, rig frame [N]
    N: float                # sum of the patches' normal loads
    area: float
    pmax: float
    centre: np.ndarray      # force centre (load-weighted), rig frame
    patches: list = field(default_factory=list)   # (N, point, fx, fy, a, b) per patch
    dz: float = 0.0
    normal: np.ndarray = None  # the patches' normal forces summed, rig frame [N]

    @property
    def creep(self):
        """The creep forces summed (the force less the normal forces)."""
        return self.force - self.normal


def _combine(patches):
    """Result of patch tuples (N, force(3), area, pmax, centre(3), extra,
    normal force(3))."""
    if not patches:
        return Result(np.zeros(3), 0.0, 0.0, 0.0, np.full(3, np.nan), normal=np.zeros(3))
    N = sum(p[0] for p in patches)
    return Result(force=sum(p[1] for p in patches), N=N, area=sum(p[2] for p in patches),
                  pmax=max(p[3] for p in patches),
                  centre=sum(p[0] * p[4] for p in patches) / N,
                  patches=[p[5] for p in patches], normal=sum(p[6] for p in patches))


def exact_table(cx, cy, cphi, a, b, N, mu, G=G_DEF, nu=NU_DEF):
    f = rr.creep_forces(cx, cy, cphi, a=a, b=b, N=N, mu=mu, G=G, nu=nu, method="exact_table",
                        errors="raise")
    return float(f.fx), float(f.fy), float(f.mz)


#: the exact table's a/b range, a hair inside: rr_kalker's coefficients jump
#: at a/b = 10 (C11 11.83 -> 11.40 from 10 to 10 (1 + 2e-16), Kalker's table
#: to its asymptote), and exact_table's forces with them (0.017 mu N seen)
AB_LO, AB_HI = 0.1 * (1 + 1e-9), 10.0 * (1 - 1e-9)


def clamp_ab(a, b, lo=AB_LO, hi=AB_HI):
    """The same c^2 = ab with a/b inside the exact table's range."""
    r = min(max(a / b, lo), hi)
    c = np.sqrt(a * b)
    return c * np.sqrt(r), c / np.sqrt(r)


# ------------------------------------------------------------------ baseline: one Hertz ellipse

def hertz(table, y, Fz, side, *, spin, roller_spin, vy=0.0, mu=0.52, G=G_DEF, nu=NU_DEF,
          method="exact_table"):
    """rig_contact's single ellipse, the normal load from the vertical one."""
    E = 2 * G * (1 + nu)
    c = getattr(rr.rig_contact(table, y=y, spin=spin, roller_spin=roller_spin, vy=vy,
                               N_left=1.0, N_right=1.0, kinematics_only=True), side)
    N = Fz / float(c.n[2])
    for _ in range(30):
        w = getattr(rr.rig_contact(table, y=y, spin=spin, roller_spin=roller_spin, vy=vy,
                                   N_left=N, N_right=N, mu=mu, E=E, nu=nu, method=method), side)
        Nn = (Fz - float(w.fy) * float(w.t2[2])) / float(w.n[2])
        if abs(Nn - N) < 1e-7 * Fz:
            break
        N = Nn
    area = np.pi * float(w.a) * float(w.b)
    return Result(force=np.asarray(w.force, dtype=float), N=float(w.N), area=area,
                  pmax=float(w.p0), centre=np.asarray(w.p, dtype=float),
                  patches=[(float(w.N), np.asarray(w.p), float(w.fx), float(w.fy),
                            float(w.a), float(w.b))], normal=float(w.N) * np.asarray(w.n))


# ------------------------------------------------------------------ (a) multi-patch Hertz

def virtual_regions(wheel, pose0, dz, eps=0.55, combine=ng.COMBINE):
    """Every group of the vertical gap's regions under the approach: its
    plane, its own gap and, at the virtual penetration eps * pen, the
    equivalent ellipse's effective curvatures."""
    pt = ng.Patches(wheel, pose0, dz, cover=1.0, combine=combine)
    out = []
    for j, gr in enumerate(pt.groups):
        pen = (dz - gr["g"]) * np.cos(gr["delta"])
        if pen <= 0:
            continue
        pl = pt.plane(j, gr["g"])          # the group's own zero-gap pose
        lo, hi = pt.y_range(pl, j)
        ys = np.arange(lo, hi, 2e-5)
        h0 = pl.gap(0.0, ys)
        h0 = h0 - np.nanmin(h0)
        inside = h0 <= eps * pen
        if not inside.any():
            continue
        yi = ys[inside]
        # the longitudinal curvature of each strip: h(x) - h(0) = A(y) x^2
        xt = 2e-3
        A = (pl.gap(xt, yi) - pl.gap(0.0, yi)) / xt ** 2
        L = np.sqrt(np.maximum(eps * pen - h0[inside], 0.0) / A)   # half-lengths
        w = L / L.sum()
        # moments of the region weighted by its strips' lengths (area)
        area = 2.0 * L.sum() * 2e-5
        yc = float(np.sum(w * yi))
        # an ellipse of that area with the region's width and its mean length
        b = 0.5 * (yi.max() - yi.min() + 2e-5)
        a = area / (np.pi * b)
        out.append(dict(plane=pl, pen=pen, g=gr["g"], delta=gr["delta"], a=a, b=b, yc=yc,
                        A=eps * pen / a ** 2, B=eps * pen / b ** 2))
    return out


def multi_hertz(wheel, table, y, Fz, *, spin, roller_spin, vy=0.0, mu=0.52, G=G_DEF,
                nu=NU_DEF, eps=0.55):
    """(a): each region an ellipse from the virtual interpenetration eps * pen,
    its load from Hertz's law with the curvatures that make that ellipse
    (A = eps pen / a^2, B = eps pen / b^2), the shared lowering dz from
    sum N_j n_z,j = Fz (secant), exact_table per patch at its own centre."""
    E = 2 * G * (1 + nu)
    pose0 = ng.pose_at(wheel.g, y)
    kin = ng.Kinematics(table, y, spin, roller_spin, vy=vy)
    c = getattr(rr.wheelset_contact(wheel.g, y), wheel.side)
    d = float(c.delta[0])
    dz = float(rr.hertz(float(c.A[0]), float(c.B[0]), Fz / np.cos(d), E=E, nu=nu).delta) \
        / np.cos(d)

    def at(dz):
        regs = virtual_regions(wheel, pose0, dz, eps)
        out, S = [], 0.0
        for r in regs:
            d1 = float(rr.hertz(r["A"], r["B"], 1.0, E=E, nu=nu).delta)
            N = (r["pen"] / d1) ** 1.5
            hz = rr.hertz(r["A"], r["B"], N, E=E, nu=nu)
            a, b = clamp_ab(float(hz.a), float(hz.b))
            t1, t2, n = r["plane"].vectors()
            P = np.array([0.0, *r["plane"].P])
            cx, cy, cphi, _ = kin.creepages(P, t1, t2, n, r["pen"], dz)
            fx, fy, mz = exact_table(cx - cphi * r["yc"], cy, cphi, a, b, N, mu, G, nu)
            centre = P + r["yc"] * t2
            out.append((N, fx * t1 + fy * t2 + N * n, np.pi * float(hz.a * hz.b),
                        float(hz.p0), centre, (N, centre, fx, fy, a, b), N * n))
            S += N * n[2] + fy * t2[2]
        return out, S

    dz, (out, S) = solve_dz(at, Fz, dz, tol=1e-6)
    res = _combine(out)
    res.dz = dz
    return res


# ------------------------------------------------------------------ tables per lateral shift

#: the correction's nodes: u = rho / (rho + 1) of the creepage in the
#: calibrated ellipse's normalised coordinates (x, y) = (K11 cx, K22 cy) / (mu N)
#: about the centroid, and its direction theta; the spin the row's own
CORR_U = np.array([0.2, 0.4, 0.6, 0.8])
CORR_TH = np.arange(8) * (np.pi / 4)
#: the nodes of approach that carry a correction (NODES' indices: about
#: 0.5 and 1.2 times 61 kN on these pairs; 4 nodes, 0.5 to 1.5, gained
#: nothing measurable)
CORR_NODES = (4, 6)
#: elements across the correction's grids (Richardson from these and twice)
CORR_N = 30


#: approach nodes of a patch: fractions of its largest lowering beyond its gap
NODES = np.array([0.03, 0.1, 0.2, 0.33, 0.46, 0.6, 0.75, 0.88, 1.0])
#: a tiny creepage for the linear coefficients (full adhesion), and a spin
EPS_C, EPS_PHI = 1e-7, 1e-4


def fastsim_pressure(pn, x, y, cx, cy, cphi, L, mu):
    """FASTSIM on any pressure pn (my, mx) on a grid (x along the columns,
    material entering at the last column): forces (fx, fy) and mz about
    the grid's origin.  L = (L1, L2, L3): flexibilities of cx, cy, cphi
    (the spin's in py; px's spin term uses L1)."""
    my, mx = pn.shape
    dx = x[0, 1] - x[0, 0]
    dA = dx * (y[1, 0] - y[0, 0]) if my > 1 else dx * dx
    L1, L2, L3 = L
    px = np.zeros(my)
    py = np.zeros(my)
    fx = fy = mz = 0.0
    yy = y[:, 0]
    for j in range(mx - 1, -1, -1):
        xj = x[0, j]
        on = pn[:, j] > 0
        px = np.where(on, px - dx * (cx - cphi * yy) / L1, 0.0)
        py = np.where(on, py - dx * (cy / L2 + cphi * xj / L3), 0.0)
        if np.isfinite(mu):
            g = mu * pn[:, j]
            t = np.hypot(px, py)
            s = np.where(t > g, g / np.maximum(t, 1e-300), 1.0)
            px, py = px * s, py * s
        fx += px.sum() * dA
        fy += py.sum() * dA
        mz += (xj * py - yy * px).sum() * dA
    return fx, fy, mz


class Field:
    """A node's pressure over its load on its grid (float32; x, y rebuilt)."""

    def __init__(self, pn1, grid):
        self.pn1 = pn1.astype(np.float32)
        self.x0, self.y0, self.dx, self.dy = grid.x0, grid.y0, grid.dx, grid.dy

    @property
    def xy(self):
        my, mx = self.pn1.shape
        x = np.broadcast_to(self.x0 + self.dx * np.arange(mx), (my, mx))
        y = np.broadcast_to((self.y0 + self.dy * np.arange(my))[:, None], (my, mx))
        return x, y


@dataclass
class PatchNodes:
    """One patch of a row at its approach nodes (arrays of length K)."""
    g: float                 # its vertical gap at the row's zero-gap pose [m]
    e: np.ndarray            # lowering of the wheelset beyond g [m]
    N: np.ndarray
    approach: np.ndarray
    s_roller: np.ndarray
    delta: np.ndarray
    P: np.ndarray            # (K, 3) reference point, rig frame
    area: np.ndarray
    pmax: np.ndarray
    xc: np.ndarray           # pressure centroid in the plane, from P
    yc: np.ndarray
    a5: np.ndarray           # sqrt(5 <(x - xc)^2>_p): Hertz's a for a Hertz pressure
    b5: np.ndarray
    K: np.ndarray            # (K, 3, 3) exact linear coefficients: column k the
                             # force (fx, fy, mz about the centroid) per unit cx, cy, cphi
                             # (spin about the centroid)
    fields: list = field(default_factory=list)    # (pn / N, x, y) per node, about P
    corr: list = field(default_factory=list)      # per node: correction data


@dataclass
class Row:
    y: float
    pose0: tuple
    patches: list
    solves: int = 0          # exact solves spent on the row
    dz_max: float = 0.0


def _richardson(grid, fine, N, mu, G, nu, cx, cy, cphi):
    s1 = ng._solve(grid, N, mu, G, nu, cx, cy, cphi)
    s2 = ng._solve(fine, N, mu, G, nu, cx, cy, cphi)
    return np.array([2 * s2.fx - s1.fx, 2 * s2.fy - s1.fy, 2 * s2.mz - s1.mz])


def _node(pt, j, gr, e, n, n_short, cover, Fz_max, dz_max, mu, G, nu, calibrate, row):
    """One approach node of patch j: its grid (cover), normal solution (load
    for the grid's own interpenetration), the fine grid's, the pressure's
    moments and the linear coefficients; None if the patch is not on a
    grid; RollerRigError if a contact reaches the grid's edge."""
    grid = pt.grid(j, gr["g"] + e, n=n, cover=cover, n_short=n_short)
    if grid is None:
        return None
    N0 = Fz_max * (grid.pen / (dz_max * np.cos(grid.delta))) ** 1.5
    N, s = ng.load_for_approach(grid, grid.pen, mu, G, nu, N0)
    row.solves += 4
    if ng._edge(s.contact):
        raise rr.RollerRigError("the contact reaches the grid's edge")
    fine = pt.grid(j, gr["g"] + e, cover=cover, dx=grid.dx / 2)
    sf = ng._solve(fine, N, mu, G, nu)      # the normal solution's numbers: the fine grid's
    row.solves += 1
    w = s.pn / s.pn.sum()
    xc, yc = float((w * s.x).sum()), float((w * s.y).sum())
    a5 = np.sqrt(5 * float((w * (s.x - xc) ** 2).sum()))
    b5 = np.sqrt(5 * float((w * (s.y - yc) ** 2).sum()))
    Kmat = np.full((3, 3), np.nan)
    if calibrate:
        Fx = _richardson(grid, fine, N, mu, G, nu, EPS_C, 0, 0) / EPS_C
        Fy = _richardson(grid, fine, N, mu, G, nu, 0, EPS_C, 0) / EPS_C
        Fp = _richardson(grid, fine, N, mu, G, nu, 0, 0, EPS_PHI) / EPS_PHI
        row.solves += 6
        # spin about the centroid: creepages at P cx = cphi yc, cy = -cphi xc
        Fpc = Fp + yc * Fx - xc * Fy
        # moments about the centroid: mz_c = mz_P - (xc fy - yc fx)
        K = np.stack([Fx, Fy, Fpc], axis=1)
        K[2] -= xc * K[1] - yc * K[0]
        Kmat = K
    return grid, fine, N, s, sf, xc, yc, a5, b5, Kmat


def build_row(wheel, y, Fz_max, *, mu=0.52, G=G_DEF, nu=NU_DEF, n=40, n_short=16,
              nodes=NODES, calibrate=True, fields=True, correct=None, corr_n=CORR_N):
    """One row of the table: every patch at its approach nodes, solved by the
    exact theory (nonhertz_geom's construction).  Fz_max: the largest
    vertical load the row must carry (sets the largest lowering, dz_max,
    from Hertz at the rigid contact point, times 1.1)."""
    E = 2 * G * (1 + nu)
    pose0 = ng.pose_at(wheel.g, y)
    c = getattr(rr.wheelset_contact(wheel.g, y), wheel.side)
    d = float(c.delta[0])
    dz_max = 1.1 * float(rr.hertz(float(c.A[0]), float(c.B[0]), Fz_max / np.cos(d), E=E,
                                  nu=nu).delta) / np.cos(d)
    # Hertz's estimate corrected by one exact normal solution of the deepest
    # patch at 0.6 of it (N ~ e^1.5): the nodes then span the loads asked for
    pt = ng.Patches(wheel, pose0, dz_max, cover=1.0)
    j0 = int(np.argmin([gr["g"] for gr in pt.groups]))
    grid = pt.grid(j0, 0.6 * dz_max, n=max(4, n // 2), cover=1.6, n_short=max(4, n_short // 2))
    if grid is not None:
        N06, _ = ng.load_for_approach(grid, grid.pen, mu, G, nu, Fz_max / np.cos(d) * 0.46)
        dz_max *= (0.6 ** 1.5 * 1.1 ** 1.5 * Fz_max / np.cos(grid.delta) / N06) ** (2 / 3)
        pt = ng.Patches(wheel, pose0, dz_max, cover=1.0)
    row = Row(y=y, pose0=pose0, patches=[], dz_max=dz_max)
    for j, gr in enumerate(pt.groups):
        if gr["g"] >= dz_max:
            continue
        recs = []
        for f in nodes:
            e = f * (dz_max - gr["g"])
            # the plane as exact_multi (and rig_exact) set it: the weighted
            # reference at the approach a first coarse solution finds
            pt.reference(j, e * np.cos(gr["delta"]))
            g1 = pt.grid(j, gr["g"] + e, n=max(4, n // 2), cover=1.5, n_short=max(4, n_short // 2))
            # and again at the approach on that plane, to a consistent plane
            for _ in range(3):
                if g1 is None:
                    break
                pt.reference(j, g1.pen)
                g2 = pt.grid(j, gr["g"] + e, n=max(4, n // 2), cover=1.5,
                             n_short=max(4, n_short // 2))
                done = g2 is None or abs(g2.pen / g1.pen - 1) < 0.01
                g1 = g2
                if done:
                    break
            node = None
            for cover in (1.3, 1.6, 2.0, 2.6):
                # a grid whose contact (coarse and fine, at every creepage)
                # keeps off its edge: else the next cover
                try:
                    node = _node(pt, j, gr, e, n, n_short, cover, Fz_max, dz_max, mu, G, nu,
                                 calibrate, row)
                except rr.RollerRigError:
                    continue
                if node is not None:
                    break
            if node is None:
                continue
            grid, fine, N, s, sf, xc, yc, a5, b5, Kmat = node
            recs.append(dict(e=e, N=N, approach=s.delta, s_roller=grid.s_roller,
                             delta=grid.delta, P=grid.point, area=sf.contact_area,
                             pmax=sf.pmax, xc=xc, yc=yc, a5=a5, b5=b5, K=Kmat,
                             field=Field(s.pn / N, grid) if fields else None,
                             grid=grid, fine=fine, cover=cover))
        if not recs:
            continue
        pn_ = PatchNodes(g=gr["g"], **{k: np.array([r[k] for r in recs]) for k in
                                       ("e", "N", "approach", "s_roller", "delta", "P",
                                        "area", "pmax", "xc", "yc", "a5", "b5", "K")},
                         fields=[r["field"] for r in recs])
        if correct is not None:
            # the row's own spin: the rig's kinematics at free rolling
            pn_.corr = []
            for k, r in enumerate(recs):
                if k not in CORR_NODES:
                    pn_.corr.append(None)
                    continue
                gr_ = r["grid"]
                cphi = correct.creepages(gr_.point, gr_.t1, gr_.t2, gr_.n, gr_.pen,
                                         pn_.g + r["e"])[2]
                res = None
                for grow in (1.0, 1.3, 1.7):
                    rk = r
                    if corr_n is not None:
                        # the correction's exact solutions on their own grids
                        pt.groups[j]["s_roller"] = r["s_roller"]
                        pt.groups[j]["delta"] = r["delta"]
                        gc = pt.grid(j, pn_.g + r["e"], n=corr_n, cover=grow * r["cover"],
                                     n_short=max(4, corr_n * n_short // n))
                        rk = dict(r, grid=gc, fine=pt.grid(j, pn_.g + r["e"],
                                                           cover=grow * r["cover"],
                                                           dx=gc.dx / 2))
                    try:
                        res = residual_at_node(rk, mu, G, nu, cphi)
                        break
                    except rr.RollerRigError:
                        continue
                if res is None:
                    raise rr.RollerRigError(f"build_row: y = {y}: the correction's contact "
                                            f"reaches its grid's edge")
                pn_.corr.append(res)
                row.solves += 2 * (1 + len(CORR_U) * len(CORR_TH))
        row.patches.append(pn_)
    return row


def calibrated_ellipse(K, a5, b5, G, nu):
    """The calibrated ellipse of a patch: a/b of its pressure's moments
    (clamped to the exact table's [0.1, 10]), c^2 from its exact C11, and
    the scales of cy and cphi that give its exact C22 and C23 (K: the
    patch's linear coefficients about its centroid, PatchNodes.K).
    Returns (a, b, sy, sp)."""
    r = min(max(a5 / b5, AB_LO), AB_HI)
    k = rr.kalker_coefficients(r, nu)
    c2 = -K[0, 0] / (G * float(k.c11))
    c = np.sqrt(c2)
    a, b = c * np.sqrt(r), c / np.sqrt(r)
    sy = -K[1, 1] / (G * c2 * float(k.c22))
    sp = -K[1, 2] / (G * c ** 3 * float(k.c23))
    return a, b, sy, sp


def residual_at_node(r, mu, G, nu, cphi, u=CORR_U, th=CORR_TH):
    """The exact theory (Richardson) minus the calibrated ellipse at the
    correction's nodes, over mu N: (R0 (3,) at zero creepage, R (nu, nth,
    3)); forces and mz about the centroid."""
    N, K, xc, yc = r["N"], r["K"], r["xc"], r["yc"]
    a, b, sy, sp = calibrated_ellipse(K, r["a5"], r["b5"], G, nu)
    muN = mu * N

    def res(cxc, cyc):
        cx, cy = cxc + cphi * yc, cyc - cphi * xc
        F = _richardson(r["grid"], r["fine"], N, mu, G, nu, cx, cy, cphi)
        F[2] -= xc * F[1] - yc * F[0]
        T = exact_table(cxc, sy * cyc, sp * cphi, a, b, N, mu, G, nu)
        return (F - np.array(T)) / muN
    R0 = res(0.0, 0.0)
    R = np.zeros((len(u), len(th), 3))
    for i, uu in enumerate(u):
        rho = uu / (1 - uu)
        for j, t in enumerate(th):
            R[i, j] = res(rho * np.cos(t) * muN / -K[0, 0], rho * np.sin(t) * muN / -K[1, 1])
    return dict(cphi=cphi, R0=R0, R=R)


def residual_eval(c, x, y):
    """A node's correction (over mu N) at normalised creepage (x, y):
    linear in u between 0 (R0), the nodes and 1 (zero), periodic linear in
    theta."""
    rho = np.hypot(x, y)
    u = rho / (1 + rho)
    th = np.arctan2(y, x) % (2 * np.pi)
    nth = len(CORR_TH)
    k = th / (2 * np.pi / nth)
    j0 = int(np.floor(k)) % nth
    tj = k - np.floor(k)
    j1 = (j0 + 1) % nth
    ring = lambda i: (1 - tj) * c["R"][i, j0] + tj * c["R"][i, j1]
    us = np.concatenate(([0.0], CORR_U, [1.0]))
    vals = [c["R0"]] + [ring(i) for i in range(len(CORR_U))] + [np.zeros(3)]
    i = int(np.clip(np.searchsorted(us, u) - 1, 0, len(us) - 2))
    t = (u - us[i]) / (us[i + 1] - us[i])
    return (1 - t) * vals[i] + t * vals[i + 1]


def solve_dz(at, Fz, dz, tol=1e-7, maxit=60):
    """The lowering dz at which at(dz) = (anything, S) has S = Fz: secant on
    S^(2/3) (nearly linear in dz), kept inside a bracket once one is found
    (bisection when the secant leaves it).  Returns (dz, at(dz))."""
    pts = []
    for _ in range(maxit):
        out = at(dz)
        S = out[1]
        if abs(S - Fz) < tol * Fz:
            return dz, out
        pts.append((dz, S))
        lo = max((d for d, v in pts if v < Fz), default=None)
        hi = min((d for d, v in pts if v > Fz), default=None)
        step = dz * (Fz / max(S, 1e-3 * Fz)) ** (2.0 / 3.0)
        if len(pts) > 1:
            (d0, S0), (d1, S1) = pts[-2], pts[-1]
            f0 = np.cbrt(max(S0, 0.0)) ** 2 - np.cbrt(Fz) ** 2
            f1 = np.cbrt(max(S1, 0.0)) ** 2 - np.cbrt(Fz) ** 2
            if f1 != f0 and d1 != d0:
                step = d1 - f1 * (d1 - d0) / (f1 - f0)
        if lo is not None and hi is not None and not lo < step < hi:
            step = 0.5 * (lo + hi)
        elif not (np.isfinite(step) and step > 0):
            step = 0.5 * dz if hi is not None else 2.0 * dz
        dz = step
    raise rr.RollerRigError(f"solve_dz: the vertical load {Fz} did not settle")


def _interp(e, nodes, values):
    """Linear interpolation along the nodes (arrays of any trailing shape),
    held at the ends."""
    values = np.asarray(values)
    if e <= nodes[0]:
        return values[0]
    if e >= nodes[-1]:
        return values[-1]
    k = int(np.searchsorted(nodes, e)) - 1
    t = (e - nodes[k]) / (nodes[k + 1] - nodes[k])
    return (1 - t) * values[k] + t * values[k + 1]


def _load(p, e):
    """A patch's normal load at lowering e beyond its gap: e^1.5 q(e), q
    interpolated (Hertz: q constant)."""
    if e <= 0:
        return 0.0
    q = p.N / p.e ** 1.5
    return e ** 1.5 * float(_interp(e, p.e, q))


class TableMethod:
    """Run time of a table method over rows (a list of Row at increasing y)."""

    def __init__(self, rows, wheel, tangential="calibrated", mu=0.52, G=G_DEF, nu=NU_DEF):
        self.rows = rows
        self.ys = np.array([r.y for r in rows])
        self.wheel = wheel
        self.tangential = tangential
        self.mu, self.G, self.nu = mu, G, nu

    # one patch's forces at its interpolated node data
    def patch_forces(self, p, e, kin, dz):
        N = _load(p, e)
        s_r = float(_interp(e, p.e, p.s_roller))
        delta = float(_interp(e, p.e, p.delta))
        w = self.wheel
        sig = w.sigma
        P = np.array([0.0, sig * (w.roller_y + s_r), -w.roller.z_at(s_r)])
        t1 = np.array([1.0, 0.0, 0.0])
        t2 = np.array([0.0, np.cos(delta), sig * np.sin(delta)])
        n = np.array([0.0, -sig * np.sin(delta), np.cos(delta)])
        pen = e * np.cos(delta)
        cx, cy, cphi, _ = kin.creepages(P, t1, t2, n, pen, dz)
        xc = float(_interp(e, p.e, p.xc))
        yc = float(_interp(e, p.e, p.yc))
        area = float(_interp(e, p.e, p.area / p.N ** (2 / 3))) * N ** (2 / 3)
        pmax = float(_interp(e, p.e, p.pmax / p.N ** (1 / 3))) * N ** (1 / 3)
        mu, G, nu = self.mu, self.G, self.nu
        # creepages about the pressure centroid
        cxc, cyc = cx - cphi * yc, cy + cphi * xc
        t = self.tangential
        if t in ("area", "calibrated", "corrected"):
            a5 = float(_interp(e, p.e, p.a5))
            b5 = float(_interp(e, p.e, p.b5))
            if t == "area":
                k = np.sqrt(area / (np.pi * a5 * b5))
                a, b = clamp_ab(a5 * k, b5 * k)
                fx, fy, mzc = exact_table(cxc, cyc, cphi, a, b, N, mu, G, nu)
            else:
                a, b, sy, sp = self.ellipse(p, e, N, a5, b5)
                fx, fy, mzc = exact_table(cxc, sy * cyc, sp * cphi, a, b, N, mu, G, nu)
                if t == "corrected" and p.corr:
                    d = self.correction(p, e, N, a, b, cxc, cyc, cphi)
                    fx, fy, mzc = fx + d[0], fy + d[1], mzc + d[2]
        elif t == "fsdiff":
            # the calibrated ellipse by exact_table, plus FASTSIM's difference
            # between the exact pressure and the ellipse's Hertz pressure, each
            # with flexibilities that give the patch's exact linear coefficients
            a5 = float(_interp(e, p.e, p.a5))
            b5 = float(_interp(e, p.e, p.b5))
            a, b, sy, sp = self.ellipse(p, e, N, a5, b5)
            fx, fy, mzc = exact_table(cxc, sy * cyc, sp * cphi, a, b, N, mu, G, nu)
            f_ex = np.array(self.fastsim(p, e, N, cx, cy, cphi))
            f_el = np.array(self.fastsim_ellipse(p, e, N, a, b, cxc, cyc, cphi))
            fx, fy, mzc = fx + f_ex[0] - f_el[0], fy + f_ex[1] - f_el[1], mzc + f_ex[2] - f_el[2]
        elif t == "fastsim":
            # FASTSIM on the two bracketing nodes' pressures, forces interpolated
            fx, fy, mzc = self.fastsim(p, e, N, cx, cy, cphi)
            a = b = np.nan
        else:
            raise ValueError(t)
        centre = P + xc * t1 + yc * t2
        force = fx * t1 + fy * t2 + N * n
        return ((N, force, area, pmax, centre, (N, centre, fx, fy, a, b), N * n),
                fy * t2[2] + N * n[2])

    def ellipse(self, p, e, N, a5, b5):
        return calibrated_ellipse(_interp(e, p.e, p.K), a5, b5, self.G, self.nu)

    def fastsim(self, p, e, N, cx, cy, cphi):
        k = int(np.clip(np.searchsorted(p.e, e) - 1, 0, len(p.e) - 2))
        t = float(np.clip((e - p.e[k]) / (p.e[k + 1] - p.e[k]), 0.0, 1.0))
        out = np.zeros(3)
        for kk, wgt in ((k, 1 - t), (k + 1, t)):
            if wgt == 0:
                continue
            fld = p.fields[kk]
            pn1 = fld.pn1.astype(float)
            x, y = fld.xy
            K = p.K[kk]
            # flexibilities from the exact linear coefficients (spin about P:
            # the centroid's coefficients moved back)
            xc, yc = p.xc[kk], p.yc[kk]
            u = fastsim_pressure(pn1 * N, x, y, 1.0, 0.0, 0.0, (1.0, 1.0, 1.0), np.inf)
            v = fastsim_pressure(pn1 * N, x, y, 0.0, 1.0, 0.0, (1.0, 1.0, 1.0), np.inf)
            sp = fastsim_pressure(pn1 * N, x, y, 0.0, 0.0, 1.0, (np.inf, 1.0, 1.0), np.inf)
            Kx, Ky = K[:, 0], K[:, 1]
            Kp_P = K[:, 2] - yc * Kx + xc * Ky        # spin about P
            L1 = u[0] / Kx[0]
            L2 = v[1] / Ky[1]
            L3 = sp[1] / Kp_P[1]
            f = fastsim_pressure(pn1 * N, x, y, cx, cy, cphi, (L1, L2, L3), self.mu)
            # mz about the centroid
            out += wgt * np.array([f[0], f[1], f[2] - (xc * f[1] - yc * f[0])])
        return tuple(out)

    def fastsim_ellipse(self, p, e, N, a, b, cxc, cyc, cphi, m=24):
        """FASTSIM on the ellipse (a, b) with Hertz's pressure, flexibilities
        from the patch's exact linear coefficients (spin about the centre)."""
        K = _interp(e, p.e, p.K)
        d = 2.0 / m
        u = -1.0 + d * (np.arange(m) + 0.5)
        X, Y = np.meshgrid(a * u, b * u)
        r2 = 1 - (X / a) ** 2 - (Y / b) ** 2
        pn = np.where(r2 > 0, 1.5 * N / (np.pi * a * b) * np.sqrt(np.maximum(r2, 0)), 0.0)
        pn *= N / (pn.sum() * (a * d) * (b * d))
        # FASTSIM's grid: x (columns) spacing a d, y (rows) spacing b d
        uu = fastsim_pressure(pn, X, Y, 1.0, 0.0, 0.0, (1.0, 1.0, 1.0), np.inf)
        vv = fastsim_pressure(pn, X, Y, 0.0, 1.0, 0.0, (1.0, 1.0, 1.0), np.inf)
        ss = fastsim_pressure(pn, X, Y, 0.0, 0.0, 1.0, (np.inf, 1.0, 1.0), np.inf)
        L = (uu[0] / K[0, 0], vv[1] / K[1, 1], ss[1] / K[1, 2])
        return fastsim_pressure(pn, X, Y, cxc, cyc, cphi, L, self.mu)

    def correction(self, p, e, N, a, b, cxc, cyc, cphi):
        """The tabulated correction at lowering e (linear between the nodes
        that carry one, held at the ends), in N."""
        K = _interp(e, p.e, p.K)
        muN = self.mu * N
        x, y = -K[0, 0] * cxc / muN, -K[1, 1] * cyc / muN
        ks = [k for k, c in enumerate(p.corr) if c is not None]
        es = p.e[ks]
        if e <= es[0]:
            d = residual_eval(p.corr[ks[0]], x, y)
        elif e >= es[-1]:
            d = residual_eval(p.corr[ks[-1]], x, y)
        else:
            i = int(np.searchsorted(es, e)) - 1
            t = (e - es[i]) / (es[i + 1] - es[i])
            d = (1 - t) * residual_eval(p.corr[ks[i]], x, y) \
                + t * residual_eval(p.corr[ks[i + 1]], x, y)
        return d * muN

    # ---- one row
    def eval_row(self, row, Fz, kin):
        """The row's patches at the shared lowering that carries Fz."""
        def at(dz):
            parts, S = [], 0.0
            for p in row.patches:
                e = dz - p.g
                if e <= 0:
                    continue
                part, s = self.patch_forces(p, e, kin, dz)
                parts.append(part)
                S += s
            return parts, S
        # dz from the primary patch's nodes, then the balance
        p0 = row.patches[0]
        dz0 = p0.g + float(np.interp(Fz, p0.N * np.cos(p0.delta), p0.e))
        dz, (parts, S) = solve_dz(at, Fz, dz0)
        res = _combine(parts)
        res.dz = dz
        return res

    def row_at(self, table, row, Fz, spin, roller_spin, vy):
        """A row evaluated as if the wheelset were at the row's shift (its
        pose and rates there)."""
        kin = ng.Kinematics(table, row.y, spin, roller_spin, vy=vy)
        return self.eval_row(row, Fz, kin)

    def __call__(self, table, y, Fz, *, spin, roller_spin, vy=0.0):
        """Rows i, i+1 around y evaluated, their results blended linearly."""
        ys = self.ys
        if len(ys) == 1:
            return self.row_at(table, self.rows[0], Fz, spin, roller_spin, vy)
        i = int(np.clip(np.searchsorted(ys, y) - 1, 0, len(ys) - 2))
        t = (y - ys[i]) / (ys[i + 1] - ys[i])
        if abs(t) < 1e-9:
            return self.row_at(table, self.rows[i], Fz, spin, roller_spin, vy)
        if abs(t - 1) < 1e-9:
            return self.row_at(table, self.rows[i + 1], Fz, spin, roller_spin, vy)
        r0 = self.row_at(table, self.rows[i], Fz, spin, roller_spin, vy)
        r1 = self.row_at(table, self.rows[i + 1], Fz, spin, roller_spin, vy)
        return blend(r0, r1, t)


def blend(r0, r1, t):
    return Result(force=(1 - t) * r0.force + t * r1.force, N=(1 - t) * r0.N + t * r1.N,
                  area=(1 - t) * r0.area + t * r1.area, pmax=(1 - t) * r0.pmax + t * r1.pmax,
                  centre=(1 - t) * r0.centre + t * r1.centre,
                  patches=r0.patches + r1.patches, dz=(1 - t) * r0.dz + t * r1.dz,
                  normal=(1 - t) * r0.normal + t * r1.normal)
