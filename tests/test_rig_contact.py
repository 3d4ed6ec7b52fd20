"""One contact evaluation of the wheelset on the rollers (rollerrig.rig.contact)."""
import warnings

import numpy as np
import pytest

import rollerrig as rr

V = 5.0          # roller surface speed of the seed paper's scenario [m/s]
R0 = 0.2         # roller radius [m]
r0 = 0.092       # 1/5 of a 0.46 m wheel [m]
ALPHA = 0.025    # 1:40 cone


@pytest.fixture(scope="module")
def cone():
    """The seed paper's first stage: a conical wheel (1:40) on a crowned cylindrical roller."""
    g = rr.RigGeometry(wheel=rr.Profile.conical(ALPHA, (-0.03, 0.03), r0=r0),
                       roller=rr.Profile.cylinder((-0.03, 0.03), crown_radius=0.1),
                       wheel_radius=r0, roller_radius=R0, wheel_y=0.15, roller_y=0.15)
    return rr.contact_table(g, -0.01, 0.01, 201)


@pytest.fixture(scope="module")
def s1002():
    """S1002 on a UIC60-headed roller of the wheel's radius (Manchester placement)."""
    g = rr.RigGeometry(wheel=rr.Profile.s1002(), roller=rr.Profile.uic60(), wheel_radius=0.46,
                       roller_radius=0.46, wheel_y=0.75, roller_y=0.76053)
    return rr.contact_table(g, -0.004, 0.004, 161)


def free_spins(table, y=0.0):
    """Wheel and roller speeds with equal surface speeds V at the left contact."""
    c = table.lookup(y)
    return float(V / c.left.r[0]), float(V / c.left.R[0])


def test_free_rolling_has_no_creepage_and_no_net_force(cone):
    spin, roller_spin = free_spins(cone)
    c = rr.rig_contact(cone, spin=spin, roller_spin=roller_spin, N_left=1000.0,
                       N_right=1000.0)
    assert c.status == 0
    for w in (c.left, c.right):
        assert abs(w.cx) < 1e-12 and abs(w.cy) < 1e-12
        # the cone's spin creepage -sigma sin(delta)(1/r + 1/R) (eq. 9) remains
        assert abs(w.cphi) == pytest.approx(np.sin(w.delta) * (1 / w.r + 1 / w.R), rel=1e-12)
        assert abs(w.fx) < 1e-9
    # spin pushes each wheel sideways, equal and opposite: no net lateral force
    assert c.left.fy == pytest.approx(-c.right.fy, rel=1e-12)
    total = c.left.force + c.right.force
    assert abs(total[0]) < 1e-9 and abs(total[1]) < 1e-9


def test_free_rolling_cylinder_gives_zero_force():
    g = rr.RigGeometry(wheel=rr.Profile.cylinder((-0.03, 0.03), crown_radius=0.5),
                       roller=rr.Profile.cylinder((-0.03, 0.03), crown_radius=0.1),
                       wheel_radius=r0, roller_radius=R0, wheel_y=0.15, roller_y=0.15)
    t = rr.contact_table(g, -0.005, 0.005, 11)
    c = rr.rig_contact(t, spin=V / r0, roller_spin=V / R0, N_left=800.0, N_right=800.0)
    for w in (c.left, c.right):
        assert max(abs(w.cx), abs(w.cy), abs(w.cphi)) < 1e-12
        assert max(abs(w.fx), abs(w.fy), abs(w.mz)) < 1e-9


def test_braking_signs_and_power(cone):
    """A braked wheelset: cx > 0, the creep force pushes the wheelset back and
    spins its wheels up; creep forces dissipate power (never create it)."""
    spin, roller_spin = free_spins(cone)
    rng = np.random.default_rng(3)
    n = 200
    c = rr.rig_contact(cone, y=rng.uniform(-0.005, 0.005, n), yaw=rng.uniform(-0.005, 0.005, n),
                       vy=rng.uniform(-0.05, 0.05, n), yaw_rate=rng.uniform(-0.2, 0.2, n),
                       spin=spin * (1 - rng.uniform(0.0, 0.05, n)), roller_spin=roller_spin,
                       N_left=1000.0, N_right=1000.0)
    assert np.all(c.status == 0)
    braked = rr.rig_contact(cone, spin=0.97 * spin, roller_spin=roller_spin, N_left=1000.0,
                            N_right=1000.0)
    assert braked.left.cx > 0 and braked.left.fx < 0
    assert (braked.left.force + braked.right.force)[0] < 0          # pushed backward
    assert (braked.left.moment + braked.right.moment)[1] > 0        # spun up about +Y
    for w in (c.left, c.right):
        # power of the tangential force on the wheel over the slip velocity
        # (creepages times V): fx cx + fy cy + mz cphi <= 0 for FASTSIM
        power = w.fx * w.cx + w.fy * w.cy + w.mz * w.cphi
        assert np.all(power <= 1e-9 * w.N)


def test_evaluation_is_the_sum_of_its_parts(s1002):
    """The pipeline equals table lookup -> hertz -> creep_forces by hand, and
    force, moment are assembled from them in the rig frame."""
    rng = np.random.default_rng(7)
    n = 50
    y = rng.uniform(-0.0035, 0.0035, n)
    spin, roller_spin = 5 / 0.46, 5 / 0.46
    N = rng.uniform(5e4, 1e5, n)
    friction = rr.FallingFriction(A=0.4, B=0.6)
    c = rr.rig_contact(s1002, x=rng.uniform(-0.01, 0.01, n), y=y,
                       yaw=rng.uniform(-0.003, 0.003, n), vx=rng.uniform(-0.01, 0.01, n),
                       vy=rng.uniform(-0.02, 0.02, n), spin=spin * (1 - 0.02 * rng.random(n)),
                       roller_spin=roller_spin, N_left=N, N_right=N[::-1], mu=0.4,
                       friction=friction)
    assert np.all(c.status == 0)
    geo = s1002.lookup(y)
    for w, side, load in ((c.left, geo.left, N), (c.right, geo.right, N[::-1])):
        # the table carries the ellipse per unit load (a ~ (N/E*)^(1/3)) and
        # interpolates it: within 1e-4 of Hertz at the interpolated A, B
        # (1e-6 typically), except across the two-point jump near y = 0.2 mm
        h = rr.hertz(side.A, side.B, load, E=2.1e11, nu=0.28)
        smooth = ~(geo.left.two_point | geo.right.two_point)
        assert np.allclose(w.a[smooth], h.a[smooth], rtol=1e-4)
        assert np.allclose(w.b[smooth], h.b[smooth], rtol=1e-4)
        assert np.allclose(w.p0, 1.5 * load / (np.pi * w.a * w.b), rtol=1e-14)
        f = rr.creep_forces(w.cx, w.cy, w.cphi, a=w.a, b=w.b, N=load, mu=0.4,
                            G=2.1e11 / 2.56, nu=0.28, speed=w.V, friction=friction, nx=20,
                            ny=20)
        assert np.allclose(w.fx, f.fx, rtol=1e-12, atol=1e-9)
        assert np.allclose(w.fy, f.fy, rtol=1e-12, atol=1e-9)
        force = w.fx * w.t1 + w.fy * w.t2 + load * w.n
        assert np.allclose(w.force, force, rtol=1e-13, atol=1e-8)
        moment = np.cross((w.p - c.pose.c).T, force.T).T + w.mz * w.n
        assert np.allclose(w.moment, moment, rtol=1e-12, atol=1e-8)
        # the frame is orthonormal and right-handed, the normal into the wheel
        assert np.allclose(np.einsum("i...,i...", w.t1, w.t2), 0, atol=1e-14)
        assert np.allclose(np.cross(w.t1.T, w.t2.T).T, w.n, atol=1e-14)
        assert np.all(w.n[2] > 0.99)


def test_linearised_creepages_agree_for_small_motions(cone):
    """The seed paper's eq. 7-9 against the exact kinematics: cx and cy differ
    at second order in the motion (the difference falls 4x when the motion
    halves), the spin at first order (eq. 9 leaves out the yaw rate and the
    speed change) and by under 1 % of itself at small motions."""
    base = dict(y=0.004, yaw=0.004, vx=0.02, vy=0.02, yaw_rate=0.05)
    diffs = []
    for eps in (0.5, 0.25, 0.125):
        st = {k: v * eps for k, v in base.items()}
        spin = V / r0 * (1 - 0.01 * eps)
        exact = rr.rig_contact(cone, **st, spin=spin, roller_spin=V / R0, N_left=1.0,
                               N_right=1.0, kinematics_only=True)
        lin = rr.linear_creepages(cone, **st, spin=spin, roller_spin=V / R0)
        d = []
        for w, l in zip((exact.left, exact.right), lin):
            d.append([abs(w.cx - l.cx), abs(w.cy - l.cy), abs(w.cphi - l.cphi) / abs(w.cphi)])
        diffs.append(np.max(d, axis=0))
    diffs = np.array(diffs)
    assert np.all(diffs[:-1, :2] / diffs[1:, :2] > 3.0)     # second order (4 in the limit)
    assert diffs[-1, 0] < 2e-6 and diffs[-1, 1] < 2e-6      # at 1/8 of the base motion
    assert diffs[-1, 2] < 0.01


def test_yaw_moves_the_contact_round_the_roller(s1002):
    """The contact point under yaw against an exact 3-D search: the wheel
    point deepest inside the roller (radial gap), on the table's pose.  At
    rig-sized yaws (<= 10 mrad) the first-order law puts the point within
    2 micrometres (the neglected terms are second order in yaw)."""
    from scipy.optimize import minimize

    g = s1002.geometry

    def exact_x(y, z, roll, yaw, sigma, s0):
        cz, sz, cr, sr = np.cos(yaw), np.sin(yaw), np.cos(roll), np.sin(roll)

        def point(q):
            s, th = q
            rho = g.wheel_radius + g.wheel.z_at(s)
            ly, lz = sigma * (g.wheel_y + s), -rho * np.cos(th)
            lx = rho * np.sin(th)
            ly, lz = cr * ly - sr * lz, sr * ly + cr * lz
            return np.array([cz * lx - sz * ly, y + sz * lx + cz * ly, z + lz])

        def gap(q):
            P = point(q)
            return np.hypot(P[0], P[2] + g.roller_radius) - (
                g.roller_radius - g.roller.z_at(sigma * P[1] - g.roller_y))
        res = minimize(gap, [s0, 0.0], method="Nelder-Mead",
                       options=dict(xatol=1e-12, fatol=1e-16, maxiter=20000))
        return point(res.x)

    for y in (0.0, 0.002):
        for yaw in (0.002, 0.01):
            c = rr.rig_contact(s1002, y=y, yaw=yaw, spin=10.0, roller_spin=10.0, N_left=1.0,
                               N_right=1.0, kinematics_only=True)
            for w, sigma in ((c.left, 1.0), (c.right, -1.0)):
                P = exact_x(y, c.pose.c[2], c.pose.roll, yaw, sigma, w.s_wheel)
                assert abs(w.p[0]) > 0.5e-3 * yaw / 0.002       # it does move
                assert w.p[0] == pytest.approx(P[0], abs=2e-6)


def test_longitudinal_shift_turns_the_wheelset_about_the_roller_axis(cone):
    spin, roller_spin = free_spins(cone)
    c = rr.rig_contact(cone, x=0.01, spin=spin, roller_spin=roller_spin, N_left=1.0,
                       N_right=1.0, kinematics_only=True)
    D = R0 + cone.lookup(0.0).z
    assert c.pose.beta == pytest.approx(np.arcsin(0.01 / D), rel=1e-14)
    assert c.pose.c[2] == pytest.approx(np.sqrt(D**2 - 0.01**2) - R0, rel=1e-14)
    for w in (c.left, c.right):
        # the contact point and normal turned by the same angle (r + R = D here)
        assert w.theta == pytest.approx(c.pose.beta, rel=1e-12)
        assert np.arctan2(w.n[0], w.n[2]) == pytest.approx(c.pose.beta, rel=1e-9)
        assert abs(w.cx) < 1e-12 and abs(w.cy) < 1e-12


def test_roller_radius_enters_the_patch_and_tends_to_track():
    """Same load, growing roller radius: the patch grows and G a b C11 rise
    toward the tangent-track values (a wheel on a straight rail, curvature
    sum A = cos(delta)/(2 r)), which they reach as 1/R -> 0."""
    N = 1000.0
    a, b, f11 = [], [], []
    radii = [0.1, 0.2, 0.5, 2.0, 10.0, 1e3, 1e5]
    for R in radii:
        g = rr.RigGeometry(wheel=rr.Profile.conical(ALPHA, (-0.03, 0.03), r0=r0),
                           roller=rr.Profile.cylinder((-0.03, 0.03), crown_radius=0.1),
                           wheel_radius=r0, roller_radius=R, wheel_y=0.15, roller_y=0.15)
        t = rr.contact_table(g, -0.002, 0.002, 5)
        c = rr.rig_contact(t, spin=V / r0, roller_spin=V / R, N_left=N, N_right=N,
                           method="linear")
        w = c.left
        a.append(w.a)
        b.append(w.b)
        # the creep stiffness G a b C11 = -fx/cx of the linear theory
        c2 = rr.rig_contact(t, spin=V / r0 * 0.999, roller_spin=V / R, N_left=N, N_right=N,
                            method="linear")
        f11.append(-(c2.left.fx - w.fx) / (c2.left.cx - w.cx))
    geo = t.lookup(0.0).left
    track = rr.hertz(np.cos(geo.delta) / (2 * geo.r), geo.B, N)
    k = rr.kalker_coefficients(track.a / track.b)
    f11_track = 2.1e11 / 2.56 * track.a * track.b * k.c11
    assert np.all(np.diff(a) > 0) and np.all(np.diff(f11) > 0)
    assert a[0] < 0.8 * track.a                                   # a small roller matters
    assert a[-1] == pytest.approx(track.a, rel=1e-5)
    assert b[-1] == pytest.approx(track.b, rel=1e-5)
    assert f11[-1] == pytest.approx(f11_track, rel=1e-4)


def test_bad_states_give_a_status_not_silent_nan(cone):
    spin, roller_spin = free_spins(cone)
    c = rr.rig_contact(cone, y=np.array([0.0, np.nan, 0.02, 0.0, 0.0]), spin=spin,
                       roller_spin=roller_spin, N_left=np.array([1e3, 1e3, 1e3, -5.0, 1e3]),
                       N_right=1e3, errors="ignore")
    assert list(c.status) == [0, -1, -3, -2, 0]
    assert list(c.left.status) == [0, -1, -3, -2, 0]
    assert list(c.right.status) == [0, -1, -3, 0, 0]    # the right wheel of row 3 is fine
    assert np.isfinite(c.right.fx[3]) and np.isnan(c.left.fx[3])
    assert np.all(np.isfinite(c.left.fx[[0, 4]]))
    with pytest.raises(rr.RollerRigError, match="y = nan"):
        rr.rig_contact(cone, y=np.nan, spin=spin, roller_spin=roller_spin, N_left=1e3,
                       N_right=1e3)
    with pytest.raises(rr.RollerRigError, match="y = 0.02"):
        rr.rig_contact(cone, y=0.02, spin=spin, roller_spin=roller_spin, N_left=1e3,
                       N_right=1e3)
    with pytest.raises(rr.RollerRigError, match="N_left = 0.0"):
        rr.rig_contact(cone, spin=spin, roller_spin=roller_spin, N_left=0.0, N_right=1e3)
    with pytest.warns(rr.RollerRigWarning, match="1 of 2"):
        rr.rig_contact(cone, y=[0.0, 0.5], spin=spin, roller_spin=roller_spin, N_left=1e3,
                       N_right=1e3)
    for kw, match in ((dict(mu=-1), "mu"), (dict(vmin=0.0), "vmin"), (dict(nu=0.6), "nu"),
                      (dict(method="magic"), "method"), (dict(nx=0), "nx")):
        with pytest.raises(rr.RollerRigError, match=match):
            rr.rig_contact(cone, spin=spin, roller_spin=roller_spin, N_left=1e3, N_right=1e3,
                           **kw)
    with pytest.raises(rr.RollerRigError, match="ContactTable"):
        rr.rig_contact("table", spin=1.0, roller_spin=1.0, N_left=1.0, N_right=1.0)


def test_standstill_stays_finite(cone):
    """V = 0: the creepages are slip velocities over vmin (the paper's
    special procedure), never NaN."""
    c = rr.rig_contact(cone, vy=0.001, spin=0.0, roller_spin=0.0, N_left=1e3, N_right=1e3,
                       vmin=0.01)
    assert c.status == 0
    # cy = vy/vmin, times 1 + A0 (r + delta a) of eq. 8 for the roll the shift brings
    assert c.left.V == 0.01 and c.left.cy == pytest.approx(0.001 / 0.01, rel=0.03)
    assert np.isfinite(c.left.fy) and abs(c.left.fy) <= 0.4 * 1e3 * (1 + 1e-12)


def test_scalar_and_broadcast_shapes(cone):
    spin, roller_spin = free_spins(cone)
    c = rr.rig_contact(cone, y=np.zeros((2, 3)), spin=spin, roller_spin=roller_spin,
                       N_left=1e3, N_right=1e3)
    assert c.left.fx.shape == (2, 3) and c.left.force.shape == (3, 2, 3)
    s = rr.rig_contact(cone, spin=spin, roller_spin=roller_spin, N_left=1e3, N_right=1e3)
    assert np.ndim(s.left.fx) == 0 and s.left.force.shape == (3,)
    assert s.left.force == pytest.approx(c.left.force[:, 1, 2], rel=0, abs=0)


@pytest.mark.parametrize("kw, which", [(dict(vx=1e300, roller_spin=1e-300), "cx overflows"),
                                       (dict(vy=1e308, roller_spin=1e-10), "cy overflows"),
                                       (dict(spin=1e308, roller_spin=1e-300), "cx overflows")])
def test_linear_creepages_overflow_is_an_error_not_a_warning(kw, which):
    """Rates over a tiny roller speed overflow: the clear error naming them,
    and no numpy RuntimeWarning before it (issue 22: 8 of the suite's 19
    warnings were this one's)."""
    t = rr.contact_table(rr.RigGeometry.standard(), -0.004, 0.004, 9, nsamples=100)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(rr.RollerRigError, match=which):
            rr.linear_creepages(t, y=0.0, **{"spin": 50.0, **kw})
