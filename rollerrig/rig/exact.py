"""One wheel of the rig solved by Kalker's exact theory on its own patch:
the undeformed distance from the rig's profiles (rollerrig.geometry.patch,
a patch that need not be an ellipse), the load along the patch's normal or
the wheel's vertical load, the creepages from the rig's kinematics.

    g = rr.RigGeometry.measured_pair()
    e = rr.rig_exact(g, 0.0035, Fz=6e4, spin=12.4, roller_spin=5.587, mu=0.5)
    e.solution.fx, e.patch.point, e.shape.regions, e.force

The pose, as CONTACT's: h at the wheelset where the load puts it, lowered
vertically by the approach over cos(delta) (loaded=True; the patch module
says what that changes), and the creepages at CONTACT's material points
(_creepages).  The frame is the patch's, that of rollerrig.rig.contact at
zero yaw and longitudinal shift: fx, fy, mz are rollerrig's (on the wheel;
mz about n at P).
"""
from dataclasses import dataclass

import numpy as np

from .._errors import RollerRigError
from ..contact.exact import ExactSolution, _edge, _exact_solve
from ..geometry.patch import Patch, _number, _pose_and_point, patch_shape, undeformed_distance
from ..geometry.wheelset import contact_table
from .contact import rig_contact

__all__ = ["RigExact", "rig_exact"]


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
    to 1e-7.  mu: Coulomb friction; E [Pa], nu: both bodies.
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
    across, covers where h <= 1.1 times it; 1: one grid sized from Hertz's
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
        cov = 1.1
        if a is None:
            if passes == 2:
                s, _ = solve(build(load, max(4, n // 2), approach, cover, first_ref, False,
                                   coarse=2.0), load)
                a = s.delta
            else:
                a, cov = approach, cover
                if a is None:
                    from ..contact.creep import hertz
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
        N = Fz / np.cos(delta0)
        p, s, k = at(N, None)
        for rebuild in (False, True):
            if rebuild:
                p, s, k = at(N, s.delta)
            last = None
            for _ in range(30):
                r = (Fz - s.fy * p.t2[2]) / p.n[2] - N     # the fixed point's residual
                if abs(r) <= 1e-7 * Fz:
                    break
                step = r if last is None or last[1] == r else -r * (N - last[0]) / (r - last[1])
                last = (N, r)
                N += step                                   # secant after the first step
                s, k = solve(p, N)
            else:
                raise RollerRigError(f"{func}: the normal load for Fz = {Fz!r} N did not "
                                     f"settle")
    return RigExact(solution=s, patch=p, cx=k[0], cy=k[1], cphi=k[2], V=k[3], N=N,
                    passes=count)
