"""The fast non-Hertzian contact, rig_contact(..., patch="nonhertz")
(csrc/geometry/rr_nonhertz.h, its table by rr_nonhertz_table.h), against
the library's exact non-Hertzian solver rr.rig_exact on CONTACT's 72 roller
cases (tests/data/roller_nonhertz_cases.csv: their shifts, creepages, load
and friction on both pairs), against Hertz on an elliptic gap, through a
two-point zone, and on bad input.

The reference and its tolerance.  The table's coefficients and correction
are extrapolated (Richardson) from elements half as large, so they aim at
the continuum; rig_exact on its default grid (n = 40) is itself 0.01 to
0.02 mu N (median, p95) from it (benchmarks/NONHERTZ_STUDY.md), so the
reference here is rig_exact with n = 80 (half of that).  Every case lies
half-way between two rows 0.1 mm apart (the rows' blend at its worst).  The
goal of issue 24 is the tolerance: |dF| / (mu N) of the wheel's total force,
p95 <= 0.02 and max <= 0.05 (measured 0.018 / 0.030; today's single Hertz
ellipse: 0.14 / 0.35, asserted above 0.1 so that the measure is seen to
tell them apart).
"""
import functools
import warnings

import numpy as np
import pytest

import rollerrig as rr
from reference_cases import read_columns

C = read_columns("roller_nonhertz_cases.csv")
HALF = 1e-4            # rows this far either side of a case
N_REF = 80             # rig_exact's elements across (see above)


@functools.lru_cache(maxsize=None)
def geometry(pair):
    if pair == "miniprof":
        return rr.RigGeometry.measured_pair()
    return rr.RigGeometry.standard(roller_radius=0.8001)


@functools.lru_cache(maxsize=None)
def ctable(pair):
    return rr.contact_table(geometry(pair), -0.0065, 0.0065, 261)


def _E(i):
    return 2 * C["G"][i] * (1 + C["nu"][i])


@functools.lru_cache(maxsize=None)
def nh_table(pair, ys):
    """The left side's rows at ys (the cases are left wheels; the right side
    is the left's table, unused)."""
    i = int(np.flatnonzero(C["pair"] == pair)[0])
    rows = np.unique(np.round(np.concatenate([np.array(ys) - HALF, np.array(ys) + HALF]), 9))
    t = rr.nonhertz_table(geometry(pair), None, None, y=rows, Fz=float(C["FZ"][i]),
                          mu_ref=float(C["mu"][i]), E=_E(i), sides=("left",))
    return rr.NonHertzTable(t.left, t.left, t.Fz)


def _kw(i):
    return dict(y=C["y_ws"][i], spin=C["spin"][i], roller_spin=C["roller_spin"][i],
                mu=C["mu"][i], E=_E(i), nu=C["nu"][i], Fz_left=C["FZ"][i],
                Fz_right=C["FZ"][i])


def _errors(cases):
    """Per case: |dF| / (mu N) of nonhertz and of Hertz (FASTSIM), and the
    normal solution's relative differences (N, area, peak) and the force
    centre's distance [m], all against rig_exact (n = N_REF)."""
    out = []
    for i in cases:
        pair = C["pair"][i]
        ys = tuple(sorted(set(float(C["y_ws"][k]) for k in cases if C["pair"][k] == pair)))
        tab = nh_table(pair, ys)
        ref = rr.rig_exact(geometry(pair), C["y_ws"][i], Fz=C["FZ"][i], mu=C["mu"][i],
                           spin=C["spin"][i], roller_spin=C["roller_spin"][i], E=_E(i),
                           nu=C["nu"][i], table=ctable(pair), n=N_REF)
        nh = rr.rig_contact(ctable(pair), patch="nonhertz", nonhertz=tab, **_kw(i)).left
        hz = rr.rig_contact(ctable(pair), **_kw(i)).left
        s, p = ref.solution, ref.patch
        w = s.pn / s.pn.sum()
        centre = p.point + (w * s.x).sum() * p.t1 + (w * s.y).sum() * p.t2
        muN = C["mu"][i] * ref.N
        out.append((np.linalg.norm(nh.force - ref.force) / muN,
                    np.linalg.norm(hz.force - ref.force) / muN,
                    abs(nh.N / ref.N - 1), abs(nh.area / s.contact_area - 1),
                    abs(nh.pmax / s.pmax - 1), np.linalg.norm(nh.centre - centre)))
    return np.array(out)


def test_a_few_cases_against_the_exact_solver():
    # MiniProf at +3.5 mm and S1002 at -2.5 mm, three creepages each (the
    # slow test below takes all 72 with the same table construction)
    pick = [i for i in range(C["key"].size)
            if (C["pair"][i], round(C["y_ws"][i] * 1e4)) in (("miniprof", 35),
                                                              ("s1002_uic60", -25))]
    assert len(pick) == 6
    e = _errors(pick)
    assert e[:, 0].max() <= 0.05, e[:, 0]
    # load within 0.5 % (the vertical balance settles to 1e-4 Fz; the plane's
    # tilt between rows), area within 5 % and peak within 8 % (the table's
    # nodes on their own grid; the reference's on a grid twice as fine),
    # force centre within 0.3 mm (S1002's wide tread patch, rows 0.2 mm apart)
    assert e[:, 2].max() <= 5e-3 and e[:, 3].max() <= 0.05 and e[:, 4].max() <= 0.08
    assert e[:, 5].max() <= 3e-4


@pytest.mark.slow
def test_the_72_cases_against_the_exact_solver():
    e = _errors(range(C["key"].size))
    dF, hertz = e[:, 0], e[:, 1]
    assert np.percentile(dF, 95) <= 0.02 and dF.max() <= 0.05, (np.percentile(dF, 95), dF.max())
    assert np.percentile(hertz, 95) > 0.1
    # normal solution (measured p95: load 2e-4, area 0.028, peak 0.018 on
    # MiniProf, 0.069 on S1002; centre 0.03 mm, S1002 0.26 mm)
    assert np.percentile(e[:, 2], 95) <= 5e-3
    assert np.percentile(e[:, 3], 95) <= 0.05
    assert np.percentile(e[:, 4], 95) <= 0.08
    assert np.percentile(e[:, 5], 95) <= 3e-4


def test_a_flange_row_against_the_exact_solver():
    # S1002/UIC60's left wheel at +6.7 mm, on a row: the flange flank (delta
    # 1.18 rad, spin -3.1 rad/m), a patch 30 mm long and 3 mm wide (a/b over
    # 10).  On square elements sized by its length the table's grids were 3
    # to 7 elements wide; with the spin their exact fx at zero creepage
    # wandered by 0.05 mu N between n and 2n, Richardson doubled it, and the
    # row's fx was off by a nearly constant 0.04 to 0.06 mu N at every
    # creepage (+6.5 to +6.9 mm; here |dF| 0.042, fx 0.041).  Now 0.0086
    # (fx 0.0026).  Tolerance 0.02, the p95: what is left is mostly
    # the reference's own (fy about 1 % low on its 0.37 mm elements along x,
    # which the vertical balance at the flank turns into |dF| 1 / cos(delta)
    # = 2.6 times larger)
    g = geometry("s1002_uic60")
    ct = rr.contact_table(g, 6.2e-3, 7.4e-3, 25)      # the sweep's nodes, 0.05 mm apart
    Fz, mu, rs, y = 61163.0, 0.52, 5.587302, 6.7e-3
    tab = rr.nonhertz_table(g, None, None, y=[y, y + 2e-4], Fz=Fz, mu_ref=mu,
                            sides=("left",))
    tab = rr.NonHertzTable(tab.left, tab.left, tab.Fz)
    p = rr.wheelset_contact(g, y).left
    for target in (5e-4, 2e-3):
        spin = rs * float(p.R[0]) / float(p.r[0]) * (1 - target)
        ref = rr.rig_exact(g, y, Fz=Fz, mu=mu, spin=spin, roller_spin=rs, table=ct, n=N_REF)
        nh = rr.rig_contact(ct, y=y, spin=spin, roller_spin=rs, mu=mu, Fz_left=Fz,
                            Fz_right=Fz, patch="nonhertz", nonhertz=tab).left
        dF = (nh.force - ref.force) / (mu * ref.N)
        assert np.linalg.norm(dF) <= 0.02, (target, dF)
        assert abs(dF[0]) <= 0.01, (target, dF)        # the fault's signature: fx


def test_the_rows_move_with_the_wheelsets_own_rates():
    # S1002/UIC60's right wheel at +6.3 mm, between its rows 6.2 and 6.4 mm,
    # with 1 cm/s of lateral speed: the left wheel's contact jumps from the
    # flange root to its flank at +6.27 mm, and the wheelset's vertical and
    # roll rates (the table's slopes times vy) jump with it, the right
    # wheel's lateral creepage from 0.0028 to 0.019.  The rows took their
    # own rates and blended them: cy 0.0090, 0.25 mu N off; now each row
    # moves with the state's (rr_rig_kinematics_rates_at): cy within 0.1 %,
    # the force 5e-4 mu N from rig_exact on 80 elements (here 40: the
    # tolerance is the p95, which that grid's own error fits in)
    g = geometry("s1002_uic60")
    ct = rr.contact_table(g, -0.0085, 0.0085, 341)
    Fz, mu, rs, y = 61163.0, 0.52, 5.587302, 6.3e-3
    tab = rr.nonhertz_table(g, None, None, y=[6.2e-3, 6.4e-3], Fz=Fz, mu_ref=mu,
                            sides=("right",))
    tab = rr.NonHertzTable(tab.right, tab.right, tab.Fz)
    p = rr.wheelset_contact(g, y).right
    spin = rs * float(p.R[0]) / float(p.r[0]) * (1 - 1e-3)
    ref = rr.rig_exact(g, y, side="right", Fz=Fz, mu=mu, spin=spin, roller_spin=rs, vy=0.01,
                       table=ct)
    nh = rr.rig_contact(ct, y=y, vy=0.01, spin=spin, roller_spin=rs, mu=mu, Fz_left=Fz,
                        Fz_right=Fz, patch="nonhertz", nonhertz=tab).right
    assert nh.patches[0].cy == pytest.approx(ref.cy, rel=1e-3)
    assert np.linalg.norm(nh.force - ref.force) / (mu * ref.N) <= 0.02


def test_a_saturated_flange_finds_its_vertical_balance():
    # S1002 right wheel at -6.4 mm with lateral slip (vy 0.01 m/s): the flank
    # at delta 1.21 rad in full slip, mu tan(delta) = 1.4, so the creep
    # forces' vertical share at the load Fz exceeds Fz.  The share's
    # safeguard then stood still (halfway between Tz and itself) and the
    # fast method found no balance where rig_exact finds one (N 73.2 kN,
    # the share 58 % of Fz); it now steps halfway to Fz.  |dF| 0.0012 mu N
    # against rig_exact at n = 80 (tolerance 0.02, the p95)
    g = geometry("s1002_uic60")
    ct = rr.contact_table(g, -7.4e-3, -6.2e-3, 25)
    Fz, mu, rs, y = 61163.0, 0.52, 5.587302, -6.4e-3
    tab = rr.nonhertz_table(g, None, None, y=[y, y + 2e-4], Fz=Fz, mu_ref=mu)
    p = rr.wheelset_contact(g, y).right
    spin = rs * float(p.R[0]) / float(p.r[0]) * (1 - 1e-3)
    ref = rr.rig_exact(g, y, side="right", Fz=Fz, mu=mu, spin=spin, roller_spin=rs, vy=0.01,
                       table=ct, n=N_REF)
    nh = rr.rig_contact(ct, y=y, vy=0.01, spin=spin, roller_spin=rs, mu=mu, Fz_left=Fz,
                        Fz_right=Fz, patch="nonhertz", nonhertz=tab).right
    assert np.linalg.norm(nh.force - ref.force) / (mu * ref.N) <= 0.02


# ------------------------------------------------------------ elliptic gap

@functools.lru_cache(maxsize=None)
def cone_on_crown():
    hw = 0.05
    g = rr.RigGeometry(wheel=rr.Profile.conical(0.025, (-hw, hw), r0=0.46, n=401),
                       roller=rr.Profile.cylinder((-hw, hw), crown_radius=0.3, n=401),
                       wheel_radius=0.46, roller_radius=0.8, wheel_y=0.75, roller_y=0.75)
    ct = rr.contact_table(g, -0.004, 0.004, 81)
    tab = rr.nonhertz_table(g, None, None, y=[-2e-4, 2e-4], Fz=5e4, mu_ref=0.4)
    return g, ct, tab


@pytest.mark.parametrize("creep", [0.0005, 0.003, 0.02])
def test_an_elliptic_gap_gives_hertz(creep):
    # a cone on a crowned cylinder: the gap is Hertz's, the patch an ellipse;
    # the fast method must give Hertz's load, area and peak, and the exact
    # table's forces on the Hertz ellipse (the Hertzian methods)
    g, ct, tab = cone_on_crown()
    kw = dict(y=1e-4, spin=10.0, roller_spin=10.0 * 0.46 / 0.8 * (1 + creep), mu=0.4,
              Fz_left=5e4, Fz_right=5e4)
    nh = rr.rig_contact(ct, patch="nonhertz", nonhertz=tab, **kw)
    ht = rr.rig_contact(ct, method="exact_table", **kw)
    hf = rr.rig_contact(ct, **kw)
    for side in ("left", "right"):
        a, b, f = getattr(nh, side), getattr(ht, side), getattr(hf, side)
        muN = 0.4 * b.N
        # the exact solver's discrete Hertz: load to 0.1 %, area to 4 % and
        # peak to 3 % (n = 40 elements across: the ring of edge elements,
        # whose pressure is nearly zero, is a tenth of the area; measured 2.8 %)
        assert abs(a.N / b.N - 1) < 1e-3
        assert abs(a.area / (np.pi * b.a * b.b) - 1) < 0.04
        assert abs(a.pmax / b.p0 - 1) < 0.03
        # the forces: the exact table's to 0.01 mu N (the table's own
        # interpolation and the exact solver's discretisation), FASTSIM's to
        # 0.05 (FASTSIM's error on ellipses, benchmarks/RESULTS.md)
        assert np.linalg.norm(a.force - b.force) / muN < 0.01
        assert np.linalg.norm(a.force - f.force) / muN < 0.05
        assert len(a.patches) == 1


@pytest.mark.parametrize("x, yaw", [(1e-3, 0.0), (0.0, 4e-3), (-2e-3, -3e-3)])
def test_a_yawed_wheelset_on_an_elliptic_gap_gives_hertz(x, yaw):
    # the patches' frames turned by the rig's first-order law for x and yaw
    # (rr_rig_contact.h): on the elliptic gap the Hertzian contact with the
    # same law and the exact table is the reference, to 0.01 mu N as above
    g, ct, tab = cone_on_crown()
    kw = dict(x=x, y=1e-4, yaw=yaw, spin=10.0, roller_spin=10.0 * 0.46 / 0.8 * 1.001, mu=0.4,
              yaw_rate=0.05, vy=0.002, Fz_left=5e4, Fz_right=5e4)
    nh = rr.rig_contact(ct, patch="nonhertz", nonhertz=tab, **kw)
    ht = rr.rig_contact(ct, method="exact_table", **kw)
    for side in ("left", "right"):
        a, b = getattr(nh, side), getattr(ht, side)
        assert np.linalg.norm(a.force - b.force) / (0.4 * b.N) < 0.01
        p = a.patches[0]
        # the frame: the Hertzian contact's, turned round the roller
        assert np.allclose(p.t1, b.t1, atol=2e-4) and np.allclose(p.n, b.n, atol=2e-4)
        assert abs(p.cy - b.cy) < 2e-5 and abs(p.cx - b.cx) < 2e-5


# --------------------------------------------------------------- continuity

@pytest.mark.slow
@pytest.mark.parametrize("pair, jump", [("miniprof", 3.93e-3), ("s1002_uic60", 0.20e-3)])
def test_force_is_continuous_through_a_two_point_zone(pair, jump):
    # the left wheel's rigid contact point jumps at MiniProf's +3.93 mm and
    # S1002's +0.20 mm; rows 0.2 mm apart, 0.05 mm near the jump
    # (nonhertz_table's refinement); the exact solution's own largest steps
    # per 0.01 mm there are 0.0012 and 0.004 mu N (NONHERTZ_STUDY.md), so
    # 0.01 mu N between neighbours is the criterion where the
    # reference is continuous.  S1002's +4.84 and +6.25 mm are not: at the
    # nominal load tread and flange root (and root and flank) lie within
    # combine, one region on one plane in the table as in the exact
    # reference, and that reference itself moves faster (0.024 mu N per 0.01
    # mm: the rolling radius changes by 0.7 mm at fixed wheelset speeds) or
    # jumps (one plane over root and flank, 0.5 rad apart).  Where two
    # separate regions share the load (Manchester's tread and flange root),
    # test_force_is_continuous_where_a_second_patch_takes_the_load.
    # Every region near S1002's +0.2 mm is now in the table: no warning
    # (the suite's warnings are errors)
    g, ct = geometry(pair), ctable(pair)
    tab = rr.nonhertz_table(g, jump - 4e-4, jump + 4e-4, Fz=61163.0, sides=("left",))
    tab = rr.NonHertzTable(tab.left, tab.left, tab.Fz)
    assert np.any(np.isclose(np.diff(tab.left.y), 5e-5))        # refined near the jump
    ys = np.arange(jump - 3e-4, jump + 3e-4 + 1e-9, 1e-5)
    kw = dict(spin=12.43673961, roller_spin=5.587302, mu=0.52, Fz_left=61163.0,
              Fz_right=61163.0)
    F = np.array([rr.rig_contact(ct, y=y, patch="nonhertz", nonhertz=tab, **kw).left.force
                  for y in ys])
    H = np.array([rr.rig_contact(ct, y=y, **kw).left.force for y in ys])
    muN = 0.52 * 61163.0
    step = np.linalg.norm(np.diff(F, axis=0), axis=1) / muN
    assert step.max() <= 0.01, (step.max(), ys[np.argmax(step)])
    # today's single ellipse fails the same criterion there (measured on
    # MiniProf 0.016 mu N)
    assert (np.linalg.norm(np.diff(H, axis=0), axis=1) / muN).max() > 0.01


# ------------------------------------------------------------ the table

def test_save_and_load_give_the_same_doubles(tmp_path):
    g, ct, tab = cone_on_crown()
    path = tmp_path / "t.npz"
    tab.save(path)
    back = rr.NonHertzTable.load(path)
    assert np.array_equal(back.left.rows, tab.left.rows)
    assert back.left.head == tab.left.head and back.Fz == tab.Fz
    kw = dict(y=0.0, spin=10.0, roller_spin=5.8, mu=0.4, Fz_left=5e4, Fz_right=5e4,
              patch="nonhertz")
    a = rr.rig_contact(ct, nonhertz=tab, **kw).left
    b = rr.rig_contact(ct, nonhertz=back, **kw).left
    assert np.array_equal(a.force, b.force) and np.array_equal(a.moment, b.moment)


def test_a_corrupt_table_file_names_its_row(tmp_path):
    g, ct, tab = cone_on_crown()
    rows = tab.left.rows.copy()
    rows[1, 20] = np.nan
    path = tmp_path / "bad.npz"
    rr.NonHertzTable(rr.NonHertzSide(rows, *tab.left.head), None, tab.Fz).save(path)
    with pytest.raises(rr.RollerRigError, match=r"row 1 \(y = 0.0002 m\)"):
        rr.NonHertzTable.load(path)


def test_the_wheel_total_is_its_patches_and_the_moment_their_arms():
    g, ct, tab = cone_on_crown()
    c = rr.rig_contact(ct, y=1e-4, spin=10.0, roller_spin=5.8, mu=0.4, Fz_left=5e4,
                       Fz_right=4e4, patch="nonhertz", nonhertz=tab)
    for w, Fz in ((c.left, 5e4), (c.right, 4e4)):
        assert np.allclose(w.force, sum(p.force for p in w.patches), rtol=1e-12, atol=0)
        # the vertical balance: to 1e-4 Fz (the creep forces' share settles there)
        assert abs(w.force[2] - Fz) <= 1e-4 * Fz
        p = w.patches[0]
        centre = np.array([0.0, 1e-4, float(c.pose.c[2])])
        n = np.cross([1.0, 0.0, 0.0], [0.0, np.cos(p.delta), (1 if w is c.left else -1)
                                       * np.sin(p.delta)])
        # the two rows' centres differ by 0.2 mm laterally; the moment is the
        # rows' blend of their own moments (rr_nonhertz.h): within that arm
        m = np.cross(p.point - centre, p.force) + p.mz * n
        assert np.linalg.norm(w.moment - m) <= 2e-4 * np.linalg.norm(p.force) * 1.01


def test_the_hertzian_contact_takes_vertical_loads():
    g, ct, tab = cone_on_crown()
    kw = dict(y=2e-3, spin=10.0, roller_spin=5.8, mu=0.4)
    c = rr.rig_contact(ct, Fz_left=5e4, Fz_right=3e4, **kw)
    assert abs(c.left.force[2] / 5e4 - 1) < 1e-9 and abs(c.right.force[2] / 3e4 - 1) < 1e-9
    d = rr.rig_contact(ct, N_left=c.left.N, N_right=c.right.N, **kw)
    assert np.array_equal(d.left.force, c.left.force)


# ------------------------------------------------------------ bad input

@pytest.mark.parametrize("kwargs, match", [
    (dict(y=1e-3), r"y = 0.001 m: beyond the nonhertz table's rows \(-0.0002 to 0.0002 m\)"),
    (dict(y=np.nan), r"y = nan"),
    (dict(Fz_left=-1.0), r"left wheel's load must be > 0"),
    (dict(Fz_left=np.inf), r"load_left = inf"),
    (dict(nonhertz=None), r"needs nonhertz=, an rr.NonHertzTable"),
    (dict(y="0.0"), r"y must be numbers"),
    (dict(y=np.zeros(0)), r"y is empty"),
    (dict(y=np.zeros(2), Fz_left=np.full(3, 5e4)), r"shapes do not broadcast"),
    (dict(N_left=1e4), r"not both"),
    (dict(patch="strips"), r"patch must be 'hertz' or 'nonhertz'"),
    (dict(E=2e11), r"the nonhertz table was built for G"),
    (dict(method="exact_table"), r"its own creep method"),
])
def test_bad_input_is_named(kwargs, match):
    g, ct, tab = cone_on_crown()
    kw = dict(y=0.0, spin=10.0, roller_spin=5.8, mu=0.4, Fz_left=5e4, Fz_right=5e4,
              patch="nonhertz", nonhertz=tab)
    kw.update(kwargs)
    with pytest.raises(rr.RollerRigError, match=match):
        rr.rig_contact(ct, **kw)


def test_one_wheel_that_fails_leaves_the_other():
    # a load beyond the table on the left (its nodes end near 1.85 x 5e4 N,
    # extrapolated to 2.8 times that; this is 1e6 times): raised by default, or the
    # left wheel NaN with its status and the right one kept
    g, ct, tab = cone_on_crown()
    kw = dict(y=0.0, spin=10.0, roller_spin=5.8, mu=0.4, Fz_left=5e10, Fz_right=5e4,
              patch="nonhertz", nonhertz=tab)
    with pytest.raises(rr.RollerRigError, match="the left wheel .* a load beyond the nonhertz "
                                                "table's \\(built for Fz = 50000 N"):
        rr.rig_contact(ct, **kw)
    c = rr.rig_contact(ct, errors="ignore", **kw)
    assert c.left.status < 0 and np.all(np.isnan(c.left.force)) and c.status < 0
    assert c.right.status == 0 and np.all(np.isfinite(c.right.force))
    with pytest.warns(rr.RollerRigWarning, match="the left wheel"):
        rr.rig_contact(ct, errors="warn", **kw)


def test_arrays_of_states_are_each_states_call():
    """An array call is the scalar call at every state, bit for bit (the
    rows' kinematics taken in one call), in the broadcast shape; a bad
    element is NaN with its status, the others kept, and "warn" names the
    first and the count, as the Hertzian call does."""
    g, ct, tab = cone_on_crown()
    kw = dict(spin=10.0, roller_spin=5.8, mu=0.4, patch="nonhertz", nonhertz=tab)
    y = np.array([[-1.5e-4, 0.0, 1e-4], [2e-5, -2e-5, 1.9e-4]])
    Fz = np.array([5e4, 4e4, 6e4])
    c = rr.rig_contact(ct, y=y, yaw=1e-3, Fz_left=Fz, Fz_right=5e4, **kw)
    assert c.left.force.shape == (3, 2, 3) and c.right.N.shape == (2, 3)
    assert c.left.patches.shape == (2, 3) and c.status.shape == (2, 3) and np.all(c.status == 0)
    for i, j in np.ndindex(2, 3):
        s = rr.rig_contact(ct, y=float(y[i, j]), yaw=1e-3, Fz_left=float(Fz[j]),
                           Fz_right=5e4, **kw)
        for side in ("left", "right"):
            a, b = getattr(s, side), getattr(c, side)
            assert np.array_equal(a.force, b.force[:, i, j])
            assert np.array_equal(a.moment, b.moment[:, i, j])
            assert (a.N, a.area, a.pmax, a.Fz) == (b.N[i, j], b.area[i, j], b.pmax[i, j],
                                                   b.Fz[i, j])
            assert [p.N for p in a.patches] == [p.N for p in b.patches[i, j]]
        assert np.array_equal(s.pose.c, c.pose.c[:, i, j])
    # normal loads given: the same settling per element
    n = rr.rig_contact(ct, y=y[0], N_left=5e4, N_right=5e4, **kw)
    assert np.allclose(n.left.N, 5e4, rtol=1e-8)
    # bad elements: y not finite, a load not positive (that wheel only), y beyond the rows
    yb = np.array([0.0, np.nan, 0.0, 1e-3])
    Fb = np.array([5e4, 5e4, -1.0, 5e4])
    with pytest.warns(rr.RollerRigWarning, match=r"y = nan: input is NaN or infinite at index "
                                                 r"\(1,\) \(3 of 4 elements failed"):
        b = rr.rig_contact(ct, y=yb, Fz_left=Fb, Fz_right=5e4, **kw)
    assert list(b.left.status) == [0, -1, -2, -14] and list(b.right.status) == [0, -1, 0, -14]
    assert np.all(np.isfinite(b.left.force[:, 0])) and np.all(np.isnan(b.left.force[:, 1:]))
    assert np.isfinite(b.right.N[2]) and b.left.patches[1] == ()
    ok = rr.rig_contact(ct, y=0.0, Fz_left=5e4, Fz_right=5e4, **kw)
    assert np.array_equal(b.left.force[:, 0], ok.left.force)
    with pytest.raises(rr.RollerRigError, match=r"at index \(1,\)"):
        rr.rig_contact(ct, y=yb, Fz_left=Fb, Fz_right=5e4, errors="raise", **kw)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        rr.rig_contact(ct, y=yb, Fz_left=Fb, Fz_right=5e4, errors="ignore", **kw)


@pytest.mark.parametrize("kwargs, match", [
    (dict(Fz=-5.0), r"Fz must be a finite number > 0"),
    (dict(Fz=np.nan), r"Fz must be"),
    (dict(Fz=10 ** 400), r"Fz must be a finite number > 0, got 1000000"),   # beyond a double
    (dict(n="40"), r"n must be a positive integer"),
    (dict(combine=-1e-3), r"combine must be >= 0 \[m\], got -0.001"),
    (dict(combine=np.nan), r"combine must be a finite number, got nan"),
    (dict(y=[0.0]), r"at least two finite rows"),
    (dict(sides=("middle",)), r"sides must name"),
    (dict(y_min=1e-3, y_max=0.0, y=None), r"y_max must exceed y_min"),
    # bounded before any row is made (a tiny step was numpy's ValueError)
    (dict(y_min=0.0, y_max=1e-4, dy=1e-300, y=None), r"would make 1e\+296 rows a side, "
                                                     r"at most 20000"),
    (dict(y_min=0.0, y_max=1e-4, dy_jump=1e-12, y=None), r"dy_jump = 1e-12 m would make"),
    (dict(y_min=-1.0, y_max=1.0, y=None), r"y_max - y_min = 2.0 m, at most 0.1 m"),
    (dict(y=np.arange(20001) * 1e-7), r"20001 rows a side, at most 20000"),
])
def test_the_table_refuses_bad_input(kwargs, match):
    g = cone_on_crown()[0]
    kw = dict(y_min=None, y_max=None, y=[0.0, 1e-4], Fz=5e4)
    kw.update(kwargs)
    with pytest.raises(rr.RollerRigError, match=match):
        rr.nonhertz_table(g, kw.pop("y_min"), kw.pop("y_max"), **kw)


def test_a_region_once_left_out_is_tabulated():
    # S1002 at +0.15 mm, next to its two-point zone: at the row's smallest
    # loads a second tread region more than combine (4 mm) from the deepest
    # touches.  Every separate region is now in a patch (rr_nonhertz_table.h:
    # the regions told apart at the nominal load, where these two are one,
    # so one patch holds both, on one plane): no warning
    g = geometry("s1002_uic60")
    with warnings.catch_warnings():
        warnings.simplefilter("error", rr.RollerRigWarning)
        t = rr.nonhertz_table(g, None, None, y=[1.5e-4, 1.55e-4], Fz=61163.0, sides=("left",))
    assert np.array_equal(t.left.rows[:, 1], [1.0, 1.0])
    tab = rr.NonHertzTable(t.left, t.left, t.Fz)
    # at 700 N both regions touch: the reference is the exact solution over
    # both together (rig_exact with combine 1 m: one plane, as the patch);
    # rig_exact with CONTACT's 4 mm leaves one out (0.03-0.04 mu N away).
    # Tolerance 0.05 mu N: the max; 700 N lies between the table's
    # two smallest nodes (588 N and 3.6 kN: 1 % and 6 % of the nominal
    # load), measured 0.029-0.034
    y, Fz, rs = 1.52e-4, 700.0, 5.587302
    p = rr.wheelset_contact(g, y).left
    spin = rs * float(p.R[0]) / float(p.r[0]) * (1 - 5e-4)
    kw = dict(spin=spin, roller_spin=rs, mu=0.52)
    ref = rr.rig_exact(g, y, Fz=Fz, table=ctable("s1002_uic60"), n=N_REF, combine=1.0, **kw)
    assert len(ref.patch.regions) == 2
    with pytest.warns(rr.RollerRigWarning, match="separate patch, left out"):
        rr.rig_exact(g, y, Fz=Fz, table=ctable("s1002_uic60"), n=N_REF, **kw)
    nh = rr.rig_contact(ctable("s1002_uic60"), y=y, patch="nonhertz", nonhertz=tab,
                        Fz_left=Fz, Fz_right=Fz, **kw).left
    assert np.linalg.norm(nh.force - ref.force) / (0.52 * ref.N) <= 0.05


@functools.lru_cache(maxsize=None)
def manchester():
    """The Manchester benchmark A-2.2's geometry (the rail a roller of 10 km)
    and the right wheel's table through its tread-to-flange-root zone."""
    g = rr.RigGeometry.standard(roller_radius=1e4)
    E = 2 * 8.2e10 * 1.28
    t = rr.nonhertz_table(g, -5.4e-3, -4.4e-3, dy=2e-4, dy_jump=5e-5, Fz=1e4, mu_ref=0.3,
                          E=E, nu=0.28, sides=("right",))
    ct = rr.contact_table(g, -0.011, 0.001, 241)
    return g, ct, rr.NonHertzTable(t.right, t.right, t.Fz), E


@pytest.mark.slow
def test_two_separate_regions_are_two_patches_sharing_the_lowering():
    # S1002 on UIC60 1:40, right wheel, -5.0 to -4.7 mm: the tread (delta
    # 0.12) and the flange root (0.3) 6-10 mm apart, CONTACT's separate
    # patches: each its own plane and gap g at the zero-gap pose, the load
    # split by the shared lowering
    g, ct, tab, E = manchester()
    rows = tab.right.rows
    two = rows[rows[:, 1] == 2]
    assert two.shape[0] >= 4
    kw = dict(spin=2.0 / 0.46, roller_spin=2.0 / 1e4, mu=0.3, E=E, nu=0.28, Fz_left=1e4,
              Fz_right=1e4)
    c = rr.rig_contact(ct, y=-4.9e-3, patch="nonhertz", nonhertz=tab, **kw).right
    assert len(c.patches) == 2
    a, b = c.patches
    assert abs(a.delta - b.delta) > 0.1                  # two planes
    assert min(a.N, b.N) > 0.3 * 1e4                     # both carry load
    assert 5e-3 < np.linalg.norm(a.point - b.point) < 12e-3    # measured 10.5 mm apart
    # the vertical balance over both patches (to 1e-4 Fz, rr_nonhertz.h)
    assert abs(c.force[2] - 1e4) <= 1e-4 * 1e4
    assert np.allclose(c.force, a.force + b.force, rtol=1e-12, atol=1e-9)


@pytest.mark.slow
def test_force_is_continuous_where_a_second_patch_takes_the_load():
    # the same zone at 0.01 mm steps: the load moves from the flange root to
    # the tread over 0.3 mm (the exact solution moves with it: CONTACT's Fy
    # is 2.8 kN at -5.0 mm and 0.8 kN at -4.5 mm, about 0.013 mu N per 0.01
    # mm on average), so 0.01 mu N between neighbours cannot hold; the
    # criterion is no jump: no step above 0.03 (measured 0.026 at the
    # steepest) and no second difference above 0.015 mu N (a jump J gives
    # one of J; the rows' linear blend turns at each row by the change of
    # slope between rows 0.05 mm apart: measured 0.013 at -5.0 mm, where the
    # root's share starts to fall; 2e-4 elsewhere)
    g, ct, tab, E = manchester()
    ys = np.arange(-5.3e-3, -4.5e-3 + 1e-9, 1e-5)
    kw = dict(spin=2.0 / 0.46, roller_spin=2.0 / 1e4, mu=0.3, E=E, nu=0.28, Fz_left=1e4,
              Fz_right=1e4)
    wheels = [rr.rig_contact(ct, y=y, patch="nonhertz", nonhertz=tab, **kw).right for y in ys]
    F = np.array([w.force for w in wheels])
    muN = 0.3 * 1e4
    step = np.linalg.norm(np.diff(F, axis=0), axis=1) / muN
    bend = np.linalg.norm(np.diff(F, 2, axis=0), axis=1) / muN
    assert step.max() <= 0.03, (step.max(), ys[np.argmax(step)])
    assert bend.max() <= 0.015, (bend.max(), ys[np.argmax(bend) + 1])
    # each patch is one region's, blended with the same region of the other
    # row (matched by place, weighted by load): loaded, and where its rows
    # put that region (measured within 0.14 mm; blended by index, a row's
    # root with the next's tread, or with an unloaded patch's zeros, it lay
    # up to 363 mm away)
    ry = tab.right.y
    regions = {float(y): [p.point for p in rr.rig_contact(ct, y=float(y), patch="nonhertz",
                                                          nonhertz=tab, **kw).right.patches]
               for y in ry}
    for y, w in zip(ys, wheels):
        i = int(np.clip(np.searchsorted(ry, y) - 1, 0, len(ry) - 2))
        near = regions[float(ry[i])] + regions[float(ry[i + 1])]
        for p in w.patches:
            assert p.N > 0.0, (y, p)
            d = min(np.linalg.norm(p.point - q) for q in near)
            assert d <= 0.5e-3, (y, d, p.point)


def test_a_row_that_cannot_be_built_is_named():
    # a load far beyond the profiles' reach: the patch leaves the profiles
    g = cone_on_crown()[0]
    with pytest.raises(rr.RollerRigError, match=r"the left side at y = 0.0 m, node \d"):
        rr.nonhertz_table(g, None, None, y=[0.0, 1e-4], Fz=1e12, sides=("left",))


def test_a_narrow_flange_patch_at_a_small_load_builds():
    # Manchester A-2.2's right wheel at -10.4 mm (rail as a roller of 10 km,
    # 10 kN): its first node (96 N) is a flange patch so narrow that n / 2
    # elements across it would be finer than the workspace's profile samples
    # hold (their halves, Richardson's grid, under DX_MIN): the narrow
    # elements stop at 2 DX_MIN and the row builds, one patch
    g = rr.RigGeometry.standard(roller_radius=1e4)
    t = rr.nonhertz_table(g, None, None, y=[-10.4e-3, -10.2e-3], Fz=1e4, mu_ref=0.3,
                          E=2 * 8.2e10 * 1.28, nu=0.28, sides=("right",))
    assert np.all(t.right.rows[:, 1] == 1) and np.all(np.isfinite(t.right.rows))
