"""Contact geometry of the wheelset on two rollers (rollerrig.geometry)."""
import csv
import os

import numpy as np
import pytest

import rollerrig as rr
from conftest import DATA


def manchester_rows():
    with open(os.path.join(DATA, "manchester_a22_contact.csv")) as f:
        assert f.readline().startswith("#")
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


@pytest.fixture(scope="module")
def manchester():
    """S1002 on UIC60 as in the Manchester benchmark: wheel origins at 750 mm
    from the wheelset centre, rail origins at 760.53 mm (gauge 1435 mm,
    back-to-back 1360 mm, rail canted 1:40 in the profile), radius 460 mm."""
    g = rr.RigGeometry(wheel=rr.Profile.s1002(), roller=rr.Profile.uic60(), wheel_radius=0.46,
                       roller_radius=0.46, wheel_y=0.75, roller_y=0.76053)
    rows = manchester_rows()
    y = np.array([r["y_ws_mm"] for r in rows]) * 1e-3
    # the benchmark's y_ws moves the wheelset to the right rail: our -Y
    return rows, rr.wheelset_contact(g, -y, errors="ignore")


def test_conical_wheel_on_crowned_roller():
    alpha, rho = 0.05, 0.1
    g = rr.RigGeometry(wheel=rr.Profile.conical(alpha, (-0.03, 0.03), r0=0.1),
                       roller=rr.Profile.cylinder((-0.03, 0.03), crown_radius=rho),
                       wheel_radius=0.1, roller_radius=0.2, wheel_y=0.75, roller_y=0.75)
    y = np.linspace(-0.005, 0.005, 9)
    c = rr.wheelset_contact(g, y)
    assert np.all(c.status == 0)
    # 2 tan(alpha) y, within 1.5 %: the wheelset's roll on the crowns moves the
    # contact points (the C tests check that term exactly)
    assert np.allclose(c.left.r - c.right.r, 2 * np.tan(alpha) * y, rtol=0.015, atol=1e-12)
    # the mean contact angle is alpha; the roll tilts one up and one down
    assert np.allclose(0.5 * (c.left.delta + c.right.delta), alpha, atol=1e-9)
    assert not c.left.two_point.any() and not c.right.two_point.any()


@pytest.mark.parametrize("i", range(2, 10))
def test_manchester_tread_contact(manchester, i):
    """1 to 4.5 mm: one contact point on the tread.  CONTACT's numbers carry the
    benchmark's yaw (2.4 mrad/mm) and the elastic patch, which we leave out:
    contact positions within 0.5 mm, contact angles within 0.4 degrees."""
    rows, c = manchester
    r = rows[i]
    assert c.status[i] == 0
    assert c.right.s_roller[i] * 1e3 == pytest.approx(r["right_ycp_rail_mm"], abs=0.5)
    assert c.right.s_wheel[i] * 1e3 == pytest.approx(r["right_ycp_wheel_mm"], abs=0.5)
    assert abs(c.right.delta[i]) == pytest.approx(abs(r["right_delta_rad"]),
                                                  abs=np.radians(0.4))
    assert abs(c.left.delta[i]) == pytest.approx(abs(r["left_delta_rad"]), abs=np.radians(0.4))


def test_manchester_at_3mm_is_close(manchester):
    """At 3 mm the geometric and the elastic contact points coincide within
    0.05 mm and 0.05 degrees (measured: 0.01 mm, 0.01 degrees)."""
    rows, c = manchester
    i = 6
    assert rows[i]["y_ws_mm"] == 3.0
    assert c.right.s_roller[i] * 1e3 == pytest.approx(rows[i]["right_ycp_rail_mm"], abs=0.05)
    assert c.right.s_wheel[i] * 1e3 == pytest.approx(rows[i]["right_ycp_wheel_mm"], abs=0.05)
    assert abs(c.right.delta[i]) == pytest.approx(abs(rows[i]["right_delta_rad"]),
                                                  abs=np.radians(0.05))
    # the wheelset's roll, which the benchmark prescribes, within 3 %
    assert c.roll[i] == pytest.approx(rows[i]["roll_rad"], rel=0.03)


def test_manchester_jumps_and_flange(manchester):
    """The contact point jumps where the profiles say so: onto the flange
    root between 4.5 and 5 mm and onto the flange between 6 and 6.5 mm; the
    flange contact angle is about 67 degrees (CONTACT: 66.4)."""
    rows, c = manchester
    s = c.right.s_roller * 1e3
    assert s[10] - s[9] < -10.0            # 4.5 -> 5 mm: > 10 mm toward the gauge
    assert s[13] - s[12] < -5.0            # 6 -> 6.5 mm: onto the flange
    assert np.degrees(abs(c.right.delta[13])) == pytest.approx(66.4, abs=2.0)
    for i in (10, 13):
        assert s[i] == pytest.approx(rows[i]["right_ycp_rail_mm"], abs=0.7)
    # CONTACT finds two patches at 0 mm; the search reports two-point contact
    assert c.right.two_point[0] and c.left.two_point[0]


def test_contact_table_matches_direct_search():
    g = rr.RigGeometry(wheel=rr.Profile.s1002(), roller=rr.Profile.uic60(), wheel_radius=0.46,
                       roller_radius=0.46, wheel_y=0.75, roller_y=0.76053)
    t = rr.contact_table(g, -0.004, 0.004, 161)
    y = np.linspace(-0.0039, 0.0039, 37)
    direct = rr.wheelset_contact(g, y)
    looked = t.lookup(y)
    # away from jumps the tread geometry is smooth: linear interpolation at
    # 0.05 mm spacing keeps the rolling radius within 1 micrometre
    smooth = np.abs(y) > 0.0006
    assert np.max(np.abs(looked.left.r - direct.left.r)[smooth]) < 1e-6
    outside = t.lookup(np.array([0.01]), errors="ignore")
    assert np.all(np.isnan(outside.z)) and outside.status[0] == -3
    with pytest.raises(rr.RollerRigError, match="y_ws = 0.01"):
        t.lookup(0.01)


def test_contact_table_lookup_at_its_own_rows():
    """Every row's shift, both ends included, is inside the table; an ulp
    past either end of y_range is not.  The reproducer's last row divided
    back into an index landed an ulp past n - 1 and was refused (issue 22)."""
    t = rr.contact_table(rr.RigGeometry.standard(), -0.002164674744325865,
                         0.0075946696529369225, 8, nsamples=100)
    c = t.lookup(t.y_ws)
    assert np.all(c.status == 0) and np.all(np.isfinite(c.left.r))
    rows = t.data.reshape(t.n, -1)
    # the rows' own axle heights (a + 1 (b - a) at the last row: an ulp or so)
    np.testing.assert_allclose(c.z[[0, -1]], rows[[0, -1], 26], rtol=1e-12, atol=0)
    lo, hi = t.y_range
    off = t.lookup(np.array([np.nextafter(lo, -1.0), np.nextafter(hi, 1.0)]), errors="ignore")
    assert list(off.status) == [-3, -3]


def test_wheel_off_the_roller():
    g = rr.RigGeometry(wheel=rr.Profile.s1002(), roller=rr.Profile.uic60(), wheel_radius=0.46,
                       roller_radius=0.46, wheel_y=0.75, roller_y=0.76053)
    with pytest.raises(rr.RollerRigError, match="y_ws"):
        rr.wheelset_contact(g, 0.3)
    with pytest.raises(rr.RollerRigError, match="wheel_radius"):
        rr.wheelset_contact(rr.RigGeometry(wheel=g.wheel, roller=g.roller, wheel_radius=-1,
                                           roller_radius=0.46, wheel_y=0.75, roller_y=0.76),
                            0.0)


def test_the_pose_converges_on_the_flange():
    """The zero-gap pose's Newton on (z, roll) takes the exact d gap / d roll:
    the contact point's arm plus r tan(delta) (the wheel's point moves across
    as it turns, along a surface of slope tan delta).  With the arm alone it
    contracted by r tan(delta) / arm a step, 2 % on the tread but near 1 on
    S1002's flange (delta 1.2 rad): from 6.4 mm out it ran out of its 50
    steps with gaps above 1e-9 m and the axle up to 6 um off (status 1).
    Now every shift to 8 mm converges, both gaps within the 1e-13 m the
    Newton stops at (on the tread in two steps: six searches a pose on
    CONTACT's roller cases, seventeen before)."""
    y = np.linspace(-0.008, 0.008, 321)
    for g in (rr.RigGeometry.standard(), rr.RigGeometry.measured_pair()):
        c = rr.wheelset_contact(g, y, errors="ignore")
        assert (c.status == 0).all(), y[c.status != 0]
        assert np.abs(c.left.gap).max() < 1e-13 and np.abs(c.right.gap).max() < 1e-13


def test_an_axle_beyond_the_gaps_rounding_is_no_pose():
    """A wheel radius of 1e300 m puts the axle where a gap's rounding is
    1e284 m: a gap that rounds to 0 there is no pose found (RR_ERR_RANGE),
    not a converged one."""
    g = rr.RigGeometry(wheel=rr.Profile.conical(0.05, (-0.015, 0.015), r0=1e300),
                       roller=rr.Profile.cylinder((-0.015, 0.015), crown_radius=0.06),
                       wheel_radius=1e300, roller_radius=0.16, wheel_y=0.15, roller_y=0.15)
    c = rr.wheelset_contact(g, [0.0, 0.001], errors="ignore")
    assert (c.status < 0).all() and np.isnan(c.z).all()


def test_core_evaluates_the_profiles_own_spline():
    """The core takes each Profile's spline (knots, values, second
    derivatives), so its radii are the Profile's heights exactly."""
    g = rr.RigGeometry(wheel=rr.Profile.s1002(), roller=rr.Profile.uic60(), wheel_radius=0.46,
                       roller_radius=0.46, wheel_y=0.75, roller_y=0.76053)
    c = rr.wheelset_contact(g, np.linspace(-0.006, 0.006, 41), errors="ignore")
    ok = c.status >= 0
    # the same cubic evaluated from the same coefficients: equal to rounding
    assert np.allclose(c.left.r[ok], 0.46 + g.wheel.z_at(c.left.s_wheel[ok]), rtol=0, atol=1e-15)
    assert np.allclose(c.right.R[ok], 0.46 - g.roller.z_at(c.right.s_roller[ok]), rtol=0,
                       atol=1e-15)


def test_standard_placement_is_the_manchester_benchmark():
    """Gauge 1435 mm (14 mm below the top), back-to-back 1360 mm, taping
    line 70 mm from the flange back: the benchmark's rail origins at
    760.53 mm (its input) to 0.01 mm, the wheel origins at 750 mm."""
    g = rr.RigGeometry.standard()
    assert g.wheel_y == pytest.approx(0.75, abs=1e-12)
    assert g.roller_y == pytest.approx(0.76053, abs=1e-5)
    # a wider gauge moves the rollers out by half the difference
    assert rr.RigGeometry.standard(gauge=1.445).roller_y == pytest.approx(g.roller_y + 0.005,
                                                                          abs=1e-9)
    # canting the (already canted) head further turns its top toward the track centre
    canted = rr.Profile.uic60().canted(1 / 40)
    assert canted.slope(0.0) > rr.Profile.uic60().slope(0.0)
    with pytest.raises(rr.RollerRigError, match="inclination"):
        rr.Profile.uic60().canted(0.5)
    with pytest.raises(rr.RollerRigError, match="gauge"):
        rr.RigGeometry.standard(gauge=float("nan"))
