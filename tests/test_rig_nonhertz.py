"""The rig in time on the non-Hertzian contact (issue 24): contact.patch =
"nonhertz" (csrc/rig/rr_rig_contact.h, Patch; rollerrig.rig.nonhertz_rig),
its table built from the rig's pair or read from a file checked against it.

Tables here are narrow (y within +-0.08 mm: the paper's scenario keeps the
wheelset within 4 um of the centre) and coarse where the check allows (16
elements across the rows' grids) so that a build takes about a second."""
import os
import warnings

import numpy as np
import pytest

import rollerrig as rr
from rollerrig.rig import nonhertz_rig

DATA = os.path.join(os.path.dirname(rr.__file__), "data")
S1002_UIC60 = {"wheelset": {"profile": "s1002"}, "roller": {"profile": "uic60"}}
MEASURED = os.path.join(DATA, "rig_measured_pair.toml")
NARROW = {"nonhertz_half_range_m": 8e-5, "nonhertz_elements": 16}


def with_contact(params, **contact):
    """params (a dict or a scenario file) with contact rows set."""
    P = rr.load_parameters(params) if isinstance(params, str) else dict(params)
    P = {k: dict(v) for k, v in P.items()}
    P["contact"] = {**P.get("contact", {}), **contact}
    return P


def quiet(fn, *a, **k):
    """fn without the measured rollers' fold warnings and the table's note on
    S1002's untabulated second region (one patch per row)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)
        return fn(*a, **k)


def hold_windows(res):
    ends = list(res.target_times[1:]) + [res.time[-1] + 1]
    for xi, t0, t1 in zip(res.targets, res.target_times, ends):
        yield xi, (res.time > t0 + 1.0) & (res.time <= t1)


def test_hertz_named_is_the_default_bit_for_bit():
    """contact.patch = "hertz" is today's rig, named or not."""
    a = rr.simulate(duration=0.5, targets=[0.02])
    b = rr.simulate(duration=0.5, targets=[0.02], params={"contact": {"patch": "hertz"}})
    assert np.array_equal(a.to_dataframe().to_numpy(dtype=float),
                          b.to_dataframe().to_numpy(dtype=float), equal_nan=True)


@pytest.mark.parametrize("pair", ["s1002_uic60", "measured"])
def test_the_default_elements_build_at_the_rigs_scale(pair):
    """The default 40 elements across, at the 1/5 rig's scale: the lightest
    node's patch (5 N) has elements under 10 um.  A regression: its grids
    were given their sizes, which set the profile samples a tenth of an
    element apart, finer than the row's workspace holds, and the default
    table failed at the centre (RR_ERR_WORKSPACE); square grids keep
    rr_gap's own elements and samples."""
    params = S1002_UIC60 if pair == "s1002_uic60" else MEASURED
    P = with_contact(params, patch="nonhertz", nonhertz_half_range_m=8e-5)
    nh = quiet(rr.rig_nonhertz_table, P)
    for side in (nh.left, nh.right):
        assert side.rows.shape[0] >= 5 and np.all(np.isfinite(side.rows))
        assert side.y.min() <= -8e-5 and side.y.max() >= 8e-5


def test_a_row_beyond_the_measured_profiles_says_why():
    """Where the measured pair's left table ends (+2.047 mm at the 1/5 scale:
    its heaviest node's flange-root region reaches the end of the measured
    profiles in the tangent plane) the error names that reason, not the
    status's generic words ("inputs too extreme")."""
    P = rr.load_parameters(MEASURED)
    g = rr.build_rig(P)[2].geometry
    Fz = nonhertz_rig.static_load(rr.rig.check_parameters(P))
    with pytest.raises(rr.RollerRigError, match=r"y = 0.002057 m, node 8 .*: the exact "
                       r"solution of a load node failed: the contact region reaches the end "
                       r"of the profiles in the tangent plane \(rr_wheel_exact why 1"):
        quiet(rr.nonhertz_table, g, None, None, y=[0.002057, 0.00206], Fz=Fz,
              sides=("left",), richardson=False)


@pytest.mark.slow
@pytest.mark.parametrize("pair", ["s1002_uic60", "measured"])
def test_paper_scenario_reaches_its_targets_on_the_nonhertz_contact(pair):
    """The paper's scenario on each pair with patch = "nonhertz": the checks
    tests/test_rig_profiles.py makes on Hertz (every target held within 5 %,
    the force within mu0 N, the roller at 5 m/s, the loads the preload and
    weight), and the adhesion within 3 % of mu0 of the Hertz run's in each
    hold window (the patch changes the creep curve's knee, not its
    saturation: both saturate at the falling law's mu)."""
    base = S1002_UIC60 if pair == "s1002_uic60" else MEASURED
    res = quiet(rr.simulate, params=with_contact(base, patch="nonhertz", **NARROW))
    ref = quiet(rr.simulate, params=base)
    assert res.status >= 0 and len(res) == 5000, res.message
    mu0 = res.params["scenario"]["mu0"]
    for xi, sel in hold_windows(res):
        assert res.creepage[sel].mean() == pytest.approx(xi, rel=0.05)
        assert abs(res.adhesion[sel].mean() - ref.adhesion[sel].mean()) < 0.03 * mu0
    assert np.all(np.abs(res.fx) <= mu0 * res.normal_load * (1 + 1e-12))
    assert np.all(np.abs(res.roller_speed - 5.0) < 0.1)
    assert np.allclose(res.normal_load, 900.85 + 14.504 * 9.81, rtol=2e-3)


@pytest.mark.slow    # the measured pair's default table: 436 rows, about 30 s on 2 free cores
def test_flange_excursion_on_the_default_table():
    """The issue's scenario that reaches flange contact (a lateral force up to
    3.25 kN, rig_flange_excursion.toml) on the nonhertz contact with the table
    a user gets by default (+-2.5 mm, 40 elements): it runs to its end, and
    the wheelset reaches the left flange root as on one Hertz ellipse.  The
    shifts agree within 1 % (the flange's lateral stiffness is the profiles',
    measured 2.041 against 2.046 mm); the peak lateral creep force within 20 %
    (the patches differ there: 206 against 187 N measured)."""
    P = rr.load_parameters(os.path.join(DATA, "rig_flange_excursion.toml"))
    res = quiet(rr.simulate, params=with_contact(P, patch="nonhertz"))
    ref = quiet(rr.simulate, params=P)
    assert res.status == 0 and len(res) == len(ref), res.message
    assert res.y.max() > 2e-3
    assert res.y.max() == pytest.approx(ref.y.max(), rel=0.01)
    assert res.fy.max() == pytest.approx(ref.fy.max(), rel=0.2)


@pytest.mark.slow
def test_on_an_elliptic_gap_the_nonhertz_rig_is_the_hertz_rig_with_the_exact_table():
    """Independent check: the cone on its crowned cylinder has an elliptic
    gap, where the non-Hertzian contact is Hertz's ellipse and its forces
    the exact theory's; the Hertz rig with the exact theory's table
    (method exact_table, Coulomb friction: the one that method takes) is
    the reference.  Per state the two agree within 0.01 mu N on an elliptic
    gap (benchmarks/RESULTS.md, nonhertz: the table's 40-element grids
    against the exact table's own); the closed loop passes that on, so the
    histories' longitudinal force agrees within 0.015 mu0 (N_left +
    N_right) at every sample and the creepage held in each window within
    0.5 %.  FASTSIM, the default, differs from the same reference by as
    much (printed beside it): the check can tell the contact models
    apart only through the tolerance, which is the per-state one."""
    coulomb = {"contact": {"friction_law": "coulomb"}}
    ref = rr.simulate(params=coulomb, method="exact_table")
    res = rr.simulate(params=with_contact(coulomb, patch="nonhertz",
                                          nonhertz_half_range_m=8e-5))
    assert res.status >= 0 and ref.status >= 0
    total = ref.normal_load_left + ref.normal_load_right
    dfx = np.abs(res.fx - ref.fx) / (0.4 * total)
    assert dfx.max() < 0.015, dfx.max()
    for xi, sel in hold_windows(res):
        assert res.creepage[sel].mean() == pytest.approx(ref.creepage[sel].mean(), rel=5e-3)


@pytest.mark.slow
def test_a_saved_table_is_reused_and_another_pairs_is_refused(tmp_path):
    """rig_nonhertz_table(params, path) saves the table the run would build;
    contact.nonhertz_table = path gives the same history bit for bit; the
    file on another pair is refused, naming what differs."""
    params = with_contact(S1002_UIC60, patch="nonhertz", **NARROW)
    path = tmp_path / "s1002.npz"
    quiet(rr.rig_nonhertz_table, params, path)
    a = quiet(rr.simulate, params=params, duration=1.0, targets=[0.02])
    b = quiet(rr.simulate, params=with_contact(params, nonhertz_table=str(path)),
              duration=1.0, targets=[0.02])
    assert np.array_equal(a.fx, b.fx) and np.array_equal(a.creepage, b.creepage)
    other = with_contact(MEASURED, patch="nonhertz", nonhertz_table=str(path))
    with pytest.raises(rr.RollerRigError, match=r"contact.nonhertz_table = .*built for another "
                       r"pair: .*wheelset.profile points"):
        quiet(rr.simulate, params=other, duration=1.0)
    # another scale too (the points the same)
    scaled = with_contact(params, nonhertz_table=str(path))
    scaled["wheelset"]["profile_scale"] = 0.21
    with pytest.raises(rr.RollerRigError, match=r"wheelset.profile_scale \(table 0.2, rig 0.21"):
        quiet(rr.simulate, params=scaled, duration=1.0)


def test_bad_patch_and_table_files_name_the_argument(tmp_path):
    with pytest.raises(rr.RollerRigError, match=r"contact.patch.*'hertz' or 'nonhertz'.*'foo'"):
        rr.simulate(params={"contact": {"patch": "foo"}}, duration=0.1, targets=[0.02])
    with pytest.raises(rr.RollerRigError, match=r"contact.nonhertz_table must be ''"):
        rr.simulate(params={"contact": {"patch": "nonhertz", "nonhertz_table": 3}},
                    duration=0.1, targets=[0.02])
    missing = str(tmp_path / "none.npz")
    with pytest.raises(rr.RollerRigError,
                       match=r"contact.patch = 'nonhertz': contact.nonhertz_table = .*none.npz.*"
                             r"no such file"):
        rr.simulate(params={"contact": {"patch": "nonhertz", "nonhertz_table": missing}},
                    duration=0.1, targets=[0.02])
    bad = tmp_path / "bad.npz"
    bad.write_bytes(b"not a zip file at all")
    with pytest.raises(rr.RollerRigError, match=r"bad.npz.*not a readable table"):
        rr.simulate(params={"contact": {"patch": "nonhertz", "nonhertz_table": str(bad)}},
                    duration=0.1, targets=[0.02])
    for key, v in (("nonhertz_half_range_m", -1.0), ("nonhertz_row_spacing_m", 0.0),
                   ("nonhertz_elements", 2)):
        with pytest.raises(rr.RollerRigError, match=f"contact.{key}"):
            rr.simulate(params={"contact": {"patch": "nonhertz", key: v}}, duration=0.1, targets=[0.02])
    # rows and range bounded before the build (a tiny spacing was numpy's ValueError)
    for key, v, msg in (("nonhertz_row_spacing_m", 1e-300, r"would make 5e\+297 rows a side, "
                                                          r"at most 20000"),
                        ("nonhertz_half_range_m", 10.0, r"span at most 0.1 m")):
        with pytest.raises(rr.RollerRigError, match=f"contact.{key} = .*{msg}"):
            rr.rig_nonhertz_table({"contact": {"patch": "nonhertz", key: v}})


def test_the_pair_key_names_profiles_and_scales():
    """What a saved table is checked against: the profiles' points (a digest
    per slot), their scales, the gauge, the radii and the material."""
    P = rr.rig.check_parameters(S1002_UIC60)
    k = nonhertz_rig.pair_key(P)
    assert {"wheelset.profile points", "roller.profile points", "wheelset.profile_scale",
            "roller.gauge_m", "contact.youngs_modulus_Pa"} <= set(k)
    cone = nonhertz_rig.pair_key(rr.default_parameters())
    assert "wheelset.conicity" in cone and "wheelset.profile points" not in cone
    assert nonhertz_rig.static_load(P) == pytest.approx(521.6, abs=0.1)


@pytest.mark.slow
def test_the_command_line_takes_patch(tmp_path):
    """rollerrig simulate --patch nonhertz on a scenario: the run is
    simulate()'s on contact.patch = "nonhertz"; --patch foo is refused naming
    the option."""
    import subprocess
    import sys
    scenario = tmp_path / "s.toml"
    scenario.write_text('[wheelset]\nprofile = "s1002"\n[roller]\nprofile = "uic60"\n'
                        '[contact]\nnonhertz_half_range_m = 8e-5\nnonhertz_elements = 16\n'
                        '[scenario]\nduration_s = 0.5\ntargets = [0.02]\ntarget_start_s = [0.0]\n')
    out = subprocess.run([sys.executable, "-m", "rollerrig", "simulate", "--scenario",
                          str(scenario), "--patch", "nonhertz", "--out", str(tmp_path / "run"),
                          "--quiet"], capture_output=True, text=True, cwd=tmp_path)
    assert out.returncode == 0, out.stdout + out.stderr
    assert "building the non-Hertzian contact's table" in out.stderr
    import csv
    with open(tmp_path / "run" / "rig_history.csv") as fh:
        rows = [r for r in csv.reader(fh) if r and not r[0].startswith("#")]
    ref = quiet(rr.simulate, params=with_contact(rr.load_parameters(str(scenario)),
                                                 patch="nonhertz"))
    fx = rows[0].index("fx")
    assert np.allclose([float(r[fx]) for r in rows[1:]], ref.fx, rtol=1e-12, atol=1e-9)
    bad = subprocess.run([sys.executable, "-m", "rollerrig", "simulate", "--patch", "foo"],
                         capture_output=True, text=True, cwd=tmp_path)
    assert bad.returncode == 2 and "--patch" in bad.stderr
