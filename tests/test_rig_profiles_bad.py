"""Bad real profiles in the rig (issue 24 item 2): every one refused with a
message naming the parameter and the file (and its line or point), never a
silent clamp or a crash."""
import os
import re

import numpy as np
import pytest

import rollerrig as rr
from rollerrig.geometry.profiles import DATA_DIR

S1002 = os.path.join(DATA_DIR, "MBench_S1002_v3.prw")


def s1002_text(tmp_path, name="w.txt", edit=None, units="mm"):
    """S1002 as a two-column text file (mm), edited by edit(y, z) -> (y, z)."""
    p = rr.Profile.s1002()
    y, z = p.y * 1e3, p.z * 1e3
    if edit:
        y, z = edit(y.copy(), z.copy())
    path = tmp_path / name
    path.write_text("# kind = wheel\n" + "".join(f"{float(a)!r} {float(b)!r}\n"
                                                 for a, b in zip(y, z)))
    return str(path)


def run(wheel, roller="uic60", **more):
    params = {"wheelset": {"profile": wheel}, "roller": {"profile": roller}}
    for k, v in more.items():
        section, key = k.split("__")
        params.setdefault(section, {})[key] = v
    return rr.build_rig(params)


def test_a_text_file_is_the_built_in_profile(tmp_path):
    """The reference of the edits below: the unedited file gives S1002's table
    (interpolated, not smoothed).  Tolerance 1e-9 relative: the text's
    millimetres back to metres differ from the SIMPACK reader's by an ulp
    (its points are exact in mm only), which the contact search carries."""
    a = run(s1002_text(tmp_path), integration__profile_smoothing_m=0.0)[2]
    b = run("s1002")[2]
    assert np.allclose(a.data, b.data, rtol=1e-9, atol=1e-12)


def test_nan_names_the_file_and_line(tmp_path):
    def nan(y, z):
        z[40] = np.nan
        return y, z
    path = s1002_text(tmp_path, edit=nan)
    with pytest.raises(rr.RollerRigError, match=rf"wheelset.profile = '{re.escape(path)}'.*"
                                                r"line 42: non-finite value nan"):
        run(path)


def test_a_gap_names_the_file_and_point(tmp_path):
    def gap(y, z):
        keep = (y < -20) | (y > -12)          # 8 mm of the flange root missing
        return y[keep], z[keep]
    path = s1002_text(tmp_path, edit=gap)
    with pytest.raises(rr.RollerRigError, match=rf"wheelset.profile = '{re.escape(path)}': "
                                                r"point \d+ of \d+ .*mm from the point before: "
                                                r"a gap"):
        run(path, integration__profile_smoothing_m=0.0)


def test_vertical_and_overhanging_segments(tmp_path):
    def vertical(y, z):
        y[100] = y[99]
        return y, z

    def overhang(y, z):
        y[100] = y[99] - 0.3
        return y, z
    path = s1002_text(tmp_path, "v.txt", edit=vertical)
    with pytest.raises(rr.RollerRigError, match=rf"{re.escape(path)}: duplicate y .* line"):
        run(path)
    path = s1002_text(tmp_path, "o.txt", edit=overhang)
    with pytest.raises(rr.RollerRigError, match=rf"wheelset.profile = '{re.escape(path)}'.*"
                                                r"folds back \(y steps back at line \d+\)"):
        run(path)


def test_a_roller_that_folds_where_a_wheel_touches(tmp_path):
    """A roller may fold below its gauge point (trimmed: the measured rollers
    do); within it, the fold is an error naming the file."""
    p = rr.Profile.uic60()
    y, z = p.y * 1e3, p.z * 1e3
    i = int(np.argmin(np.abs(y + 20)))              # 20 mm inward of the top, z ~ 1 mm
    y[i] = y[i - 1] - 0.2
    path = tmp_path / "r.txt"
    path.write_text("# kind = rail\n" + "".join(f"{float(a)!r} {float(b)!r}\n"
                                                for a, b in zip(y, z)))
    with pytest.raises(rr.RollerRigError, match=rf"roller.profile = '{re.escape(str(path))}'"
                                                r".*within 14 mm of the top"):
        run("s1002", str(path))
    # the measured rollers fold 17 to 52 mm below their top: trimmed, no warning
    # (the test run turns every RollerRigWarning into an error)
    rr.build_rig(os.path.join(os.path.dirname(rr.__file__), "data", "rig_measured_pair.toml"))


def test_wrong_units(tmp_path):
    """A file in metres read as millimetres, or the reverse (a profile 1000 x
    off): the file and why."""
    def metres(y, z):
        return y * 1e-3, z * 1e-3
    path = s1002_text(tmp_path, edit=metres)
    with pytest.raises(rr.RollerRigError, match=rf"{re.escape(path)}: the profile's y spans only "
                                                r".*metres read as millimetres"):
        run(path)
    path = tmp_path / "big.txt"
    p = rr.Profile.s1002()
    path.write_text("# kind = wheel\n# units = mm\n" + "".join(
        f"{float(a)!r} {float(b)!r}\n" for a, b in zip(p.y * 1e6, p.z * 1e6)))
    with pytest.raises(rr.RollerRigError, match=r"millimetres read as metres"):
        run(str(path))


def test_profiles_that_never_touch():
    """The rollers' gauge points 0.5 m apart: no wheel over its roller at any
    shift of the table; the message names the geometry's keys and the shift."""
    with pytest.raises(rr.RollerRigError, match=r"roller.gauge_m = 0.5.*gives no contact "
                                                r"table: at y_ws = -0.008 m"):
        run("s1002", roller__gauge_m=0.5)


def test_bad_names_and_values():
    for wheel, msg in (("uic60", r"wheelset.profile must be 'conical', 's1002' or a profile"),
                       ("points", r"wheelset.profile must be"),
                       ("", r"wheelset.profile must name a profile"),
                       (3, r"wheelset.profile must be a profile's name"),
                       ("no/such/file.whl", r"wheelset.profile: no such profile file "
                                            r"'no/such/file.whl'")):
        with pytest.raises(rr.RollerRigError, match=msg):
            run(wheel)
    with pytest.raises(rr.RollerRigError, match=r"roller.profile_right must be 'uic60' or "
                                                r"empty"):
        rr.build_rig({"roller": {"profile_right": "crowned cylinder"}})
    with pytest.raises(rr.RollerRigError, match=r"wheelset.profile_scale must be a finite "
                                                r"number > 0, got -0.2"):
        run("s1002", wheelset__profile_scale=-0.2)
    with pytest.raises(rr.RollerRigError, match=r"roller.gauge_m must be a finite number > 0"):
        run("s1002", roller__gauge_m=float("nan"))
    # a wheel file given as the roller: the SIMPACK header says it is a wheel
    with pytest.raises(rr.RollerRigError, match=r"roller.profile = .*MBench_S1002_v3.prw"):
        run("s1002", S1002)


def test_a_shift_beyond_the_table_is_an_error_not_a_clamp():
    """The wheelset moved beyond the table's range: the rig's status is
    RR_ERR_GEOMETRY (the wheel off its table), the state kept."""
    rig, _, tab = run("s1002")
    y = rig.y.copy()
    y[1] = tab.y_range[1] * 1.5
    geometry = -3                      # RR_ERR_GEOMETRY (csrc/util/rr_common.h)
    assert "off its roller" in rr.STATUS[geometry]
    assert rig.rhs(0.0, y)[1] == geometry
    assert rig.set_state(0.0, y) == 0 and rig.advance()[1] == geometry
