"""rollerrig.testing: the pytest plugin as a user meets it (pytester runs a
user's test file in a folder of its own: first run writes, second passes,
a changed parameter fails with a message naming field, time and values,
--rr-regen rewrites), and the plain assertions."""
import os

# imported before pytester's in-process runs: a module first imported inside
# one is dropped when the run restores sys.modules, and imported anew later
# gives classes that are not the old ones (matplotlib's GridSpec for one)
import matplotlib.backends.backend_agg  # noqa: F401
import matplotlib.figure  # noqa: F401
import numpy as np
import pytest

import rollerrig as rr
from rollerrig.plot import _regression  # noqa: F401
from rollerrig.testing import _fixtures  # noqa: F401
from rollerrig import RollerRigError
from rollerrig._csv import read_table
from rollerrig.testing import (RegressionError, assert_creep_curve_close, assert_fields_close,
                               assert_history_close, history_fields, read_reference)

pytest_plugins = ["pytester"]

# a user's test file: a short run of the paper's scenario whose friction
# coefficient an environment variable may change
USER_TESTS = """
import os
import numpy as np
import rollerrig as rr

def run():
    p = rr.default_parameters()
    p["scenario"]["mu0"] = float(os.environ.get("USER_MU0", "0.4"))
    return rr.simulate(duration=1.0, targets=[0.04, 0.02], params=p)

def test_history(rr_history_regression):
    rr_history_regression.check(run())

def test_curve(rr_creep_regression):
    cx = np.linspace(0.0, 0.01, 21)
    mu = float(os.environ.get("USER_MU0", "0.4"))
    rr_creep_regression.check(cx, rr.creep_forces(cx, 0.0, 0.0, a=3e-3, b=3e-3, N=1e3, mu=mu))

def test_arrays(rr_regression):
    rr_regression.check({"x": np.arange(4.0), "y": np.arange(4.0) ** 2}, units={"x": "m"})
"""


def in_order(text, pieces):
    """Each piece in `text`, after the one before it."""
    at = 0
    for piece in pieces:
        found = text.find(piece, at)
        assert found >= 0, f"not found after position {at}: {piece!r}\n{text}"
        at = found + len(piece)


@pytest.fixture
def user(pytester):
    pytester.makepyfile(test_user=USER_TESTS)
    return pytester


def _refs(pytester):
    return sorted(os.listdir(pytester.path / "test_user"))


@pytest.mark.slow      # pytest runs in pytest, two or three times
def test_first_run_writes_and_fails_saying_so_then_the_second_passes(user):
    first = user.runpytest("-p", "no:cacheprovider")
    first.assert_outcomes(failed=3)
    first.stdout.fnmatch_lines(["*rr_history_regression.check: no reference yet: wrote it "
                                "(29 fields): test_user/test_history.npz (for the comparison),"
                                " test_user/test_history.csv (to read)*"])
    assert _refs(user) == sorted(f"test_{n}.{ext}" for n in ("history", "curve", "arrays")
                                 for ext in ("npz", "csv"))
    second = user.runpytest("-p", "no:cacheprovider")
    second.assert_outcomes(passed=3)


def test_the_reference_csv_is_readable_and_holds_the_npz_numbers(user):
    user.runpytest("-p", "no:cacheprovider")
    names, units, meta, rows = read_table(user.path / "test_user" / "test_history.csv")
    fields, record = read_reference(str(user.path / "test_user" / "test_history"))
    assert names == list(fields) == list(rr.rig.RECORD_FIELDS)
    assert units["time"] == "s" and units["creepage"] == "1" and units["torque_roller"] == "N m"
    assert record["units"] == units and record["x"] == "time"
    # repr of each double: the text reads back bit for bit
    assert np.array_equal(np.array(rows), np.column_stack(list(fields.values())), equal_nan=True)
    pd = pytest.importorskip("pandas")
    frame = pd.read_csv(user.path / "test_user" / "test_history.csv", comment="#")
    assert list(frame.columns) == names and len(frame) == 250


@pytest.mark.slow      # pytest runs in pytest, two or three times
def test_a_changed_parameter_fails_naming_field_time_and_values(user, monkeypatch):
    user.runpytest("-p", "no:cacheprovider")
    monkeypatch.setenv("USER_MU0", "0.38")
    run = user.runpytest("-p", "no:cacheprovider", "-k", "history or curve")
    run.assert_outcomes(failed=2)
    out = run.stdout.str()
    # the friction coefficient is in the record: its field is named with the
    # values on both sides and the time of its first deviation
    assert "rr_history_regression.check: " in out
    assert "fields differ from the reference test_user/test_history.npz:" in out
    in_order(out, [
        "  fx [N]: 250 of 250 values outside rtol = 1e-09, atol = 0\n"
        "      first at time = 0.004 s (index 0): got -9.14",
        "      worst at time = ", "|got - reference| = ", "(allowed ",
        "  mu_left [1]: 250 of 250 outside, first at time = 0.004 s (index 0): got 0.38, "
        "reference 0.4\n",
        "rerun with --rr-regen to rewrite the reference",
        "rr_creep_regression.check: ",
        "  fx [N]: 20 of 21 values outside",
        "      first at creepage = 0.0005 (index 1): got ",
    ])
    figures = {line.split("comparison figure: ")[1] for line in out.splitlines()
               if "comparison figure: " in line}
    assert len(figures) == 2 and all(os.path.getsize(f) > 10_000 for f in figures)
    obtained = {line.split("this run's data: ")[1] for line in out.splitlines()
                if "this run's data: " in line}
    assert len(obtained) == 2 and all(os.path.exists(f) for f in obtained)


@pytest.mark.slow      # pytest runs in pytest, two or three times
def test_the_failure_says_when_matplotlib_is_missing(user, monkeypatch):
    user.runpytest("-p", "no:cacheprovider")
    user.makeconftest("import sys\nsys.modules['matplotlib.figure'] = None\n")
    monkeypatch.setenv("USER_MU0", "0.38")
    run = user.runpytest("-p", "no:cacheprovider", "-k", "curve")
    run.assert_outcomes(failed=1)
    run.stdout.fnmatch_lines(["*no comparison figure: matplotlib does not import*"])


@pytest.mark.slow      # pytest runs in pytest, two or three times
def test_rr_regen_rewrites_the_references_and_fails_saying_so(user, monkeypatch):
    user.runpytest("-p", "no:cacheprovider")
    path = user.path / "test_user" / "test_curve.npz"
    before = read_reference(str(path)[:-4])[0]["fx"]
    monkeypatch.setenv("USER_MU0", "0.38")
    regen = user.runpytest("-p", "no:cacheprovider", "--rr-regen", "-k", "curve")
    regen.assert_outcomes(failed=1)
    regen.stdout.fnmatch_lines(["*--rr-regen: rewrote the reference (5 fields): "
                                "test_user/test_curve.npz*run without the flag*"])
    after = read_reference(str(path)[:-4])[0]["fx"]
    assert after[-1] == pytest.approx(before[-1] * 0.38 / 0.4, rel=1e-12)  # full slip: mu N
    user.runpytest("-p", "no:cacheprovider", "-k", "curve").assert_outcomes(passed=1)


@pytest.mark.slow      # pytest runs in pytest, two or three times
def test_each_check_of_a_test_needs_its_own_basename(pytester):
    pytester.makepyfile(test_checks="""
def test_two(rr_regression):
    rr_regression.check({"a": [1.0]}, "one")
    rr_regression.check({"a": [2.0]}, "two")
def test_same(rr_regression):
    rr_regression.check({"a": [1.0]}, "one")
    rr_regression.check({"a": [1.0]}, "one")
""")
    # the first run writes both references, then fails naming both
    first = pytester.runpytest("-p", "no:cacheprovider", "-k", "test_two")
    first.assert_outcomes(failed=1)
    first.stdout.fnmatch_lines(["*no reference yet: wrote it (1 fields): test_checks/one.npz*",
                                "*no reference yet: wrote it (1 fields): test_checks/two.npz*"])
    pytester.runpytest("-p", "no:cacheprovider", "-k", "test_two").assert_outcomes(passed=1)
    run = pytester.runpytest("-p", "no:cacheprovider", "-k", "test_same")
    run.stdout.fnmatch_lines(["*reference one is already checked in this test*"])


def test_a_basename_with_a_folder_is_refused(pytester):
    pytester.makepyfile(test_names="""
import pytest
@pytest.mark.parametrize("name", ["../up", "a/b", "", "..", 3])
def test_name(rr_regression, name):
    with pytest.raises(ValueError, match="basename must be a file name without a folder"):
        rr_regression.check({"a": [1.0]}, name)
""")
    pytester.runpytest("-p", "no:cacheprovider").assert_outcomes(passed=5)
    assert not (pytester.path / "test_names").exists() and not (pytester.path / "up.npz").exists()


def test_a_test_that_fails_after_writing_shows_its_own_failure(pytester):
    pytester.makepyfile(test_own="""
def test_own(rr_regression):
    rr_regression.check({"a": [1.0]})
    assert 1 == 2, "the test's own assertion"
""")
    run = pytester.runpytest("-p", "no:cacheprovider")
    run.assert_outcomes(failed=1)
    run.stdout.fnmatch_lines(["*the test's own assertion*"])
    assert (pytester.path / "test_own" / "test_own.npz").exists()


def test_the_plugin_loads_without_importing_rollerrig(pytester):
    """pytest loads the plugin before any conftest: it must not import
    rollerrig then (a checkout's rollerrig/ may lack the extension)."""
    pytester.makepyfile(test_lazy="""
import sys
def test_lazy():
    assert "rollerrig.testing" not in sys.modules
""")
    pytester.runpytest_subprocess("-p", "no:cacheprovider").assert_outcomes(passed=1)


# ------------------------------------------------------------------ the plain functions

@pytest.fixture(scope="module")
def short():
    return rr.simulate(duration=0.5, targets=[0.04, 0.02])


def test_assert_history_close_passes_on_the_same_run_and_names_what_differs(short, tmp_path):
    assert_history_close(short, rr.simulate(duration=0.5, targets=[0.04, 0.02]), rtol=0.0)
    p = rr.default_parameters()
    p["scenario"]["roller_speed_m_s"] = 5.1
    other = rr.simulate(duration=0.5, targets=[0.04, 0.02], params=p)
    with pytest.raises(RegressionError) as e:
        assert_history_close(other, short, fields=["roller_speed", "time"], rtol=1e-3,
                             figure=tmp_path / "f.png")
    text = str(e.value)
    assert text.startswith("1 of 2 fields differ from the reference:\n  roller_speed [m/s]: ")
    d = e.value.deviations[0]
    assert d.name == "roller_speed" and d.first == (0,)
    assert d.got_first == other.roller_speed[0] and d.ref_first == short.roller_speed[0]
    worst = np.argmax(np.abs(other.roller_speed - short.roller_speed)
                      / (1e-3 * np.abs(short.roller_speed)))
    assert d.worst == (worst,) and f"time = {short.time[worst]:.6g} s" in text
    assert e.value.figure == str(tmp_path / "f.png") and (tmp_path / "f.png").stat().st_size
    assert "comparison figure: " in text


def test_window_means_are_the_means_of_the_records(short):
    fields, units = history_fields(short, ["time", "fx"], window=0.1)
    k = 25                                                      # 0.1 s of 4 ms samples
    assert len(fields["fx"]) == len(short) // k
    assert np.allclose(fields["fx"], short.fx[:len(short) // k * k].reshape(-1, k).mean(axis=1),
                       rtol=1e-14, atol=0)
    assert units == {"time": "s", "fx": "N"}
    for bad in (0.0, -0.1, 0.005, float("nan"), "x", 10.0):
        with pytest.raises(RollerRigError, match="window"):
            history_fields(short, window=bad)


def test_assert_creep_curve_close_against_a_reference_file(tmp_path):
    cx = np.linspace(0.0, 0.01, 11)
    f = rr.creep_forces(cx, 0.0, 0.0, a=3e-3, b=3e-3, N=1e3, mu=0.3)
    from rollerrig.testing import creep_curve_fields, write_reference
    write_reference(str(tmp_path / "curve"), *creep_curve_fields(cx, f))
    assert_creep_curve_close(cx, f, tmp_path / "curve.npz")
    g = rr.creep_forces(cx, 0.0, 0.0, a=3e-3, b=3e-3, N=1e3, mu=0.31)
    with pytest.raises(RegressionError, match=r"fx \[N\]: 10 of 11 values outside"):
        assert_creep_curve_close(cx, g, tmp_path / "curve.npz")
    # full slip: fx = -mu N at the last creepage, the reference's -300 N
    # (mz: rounding noise about zero, 1e-17 N m: an atol holds it)
    with pytest.raises(RegressionError, match=r"1 of 5 fields .*\n.*\n.*got -309\.99\d*, "
                                              r"reference -299\.99\d*"):
        assert_creep_curve_close(cx, g, f, tolerances={"fx": {"rtol": 1e-3},
                                                       "mz": {"atol": 1e-12}})


def test_nan_matches_nan_but_not_a_number(tmp_path):
    assert_fields_close({"a": [1.0, np.nan]}, {"a": [1.0, np.nan]})
    with pytest.raises(RegressionError, match="got nan, reference 2.0"):
        assert_fields_close({"a": [1.0, np.nan]}, {"a": [1.0, 2.0]})
    with pytest.raises(RegressionError, match="got inf, reference 2.0"):
        assert_fields_close({"a": [1.0, np.inf]}, {"a": [1.0, 2.0]}, rtol=1.0)


def test_missing_new_and_reshaped_fields_are_named():
    with pytest.raises(RegressionError) as e:
        assert_fields_close({"a": [1.0], "c": [1.0, 2.0]}, {"a": [1.0], "b": [1.0], "c": [1.0]})
    assert str(e.value).splitlines()[1:] == [
        "  b: missing: the reference holds it, the data not",
        "  c: shape (2,), the reference's (1,)"]


@pytest.mark.parametrize("kw, match", [
    ({"rtol": -1.0}, "rtol must be a finite number >= 0, got -1.0"),
    ({"atol": float("nan")}, "atol must be a finite number >= 0, got nan"),
    ({"rtol": "x"}, "rtol must be a number >= 0, got 'x'"),
    ({"tolerances": {"z": {"rtol": 1}}}, "tolerances names 'z', which the data does not hold"),
    ({"tolerances": {"a": {"rel": 1}}}, r"tolerances\['a'\] must be a dict with keys"),
    ({"tolerances": {"a": {"atol": -1}}}, r"tolerances\['a'\]\['atol'\] must be a finite"),
])
def test_bad_tolerances_are_refused_by_name(kw, match):
    with pytest.raises(RollerRigError, match=match):
        assert_fields_close({"a": [1.0]}, {"a": [1.0]}, **kw)


@pytest.mark.parametrize("data, match", [
    ({}, "actual holds no field"),
    ([1.0], "actual must be a mapping"),
    ({"a/b": [1.0]}, "field names must be non-empty strings without '/'"),
    ({"a": ["x"]}, r"actual\['a'\] must hold real numbers, got dtype <U1"),
    ({"a": [1j]}, r"must hold real numbers, got dtype complex128"),
])
def test_bad_data_is_refused_by_name(data, match):
    with pytest.raises(RollerRigError, match=match):
        assert_fields_close(data, {"a": [1.0]})


def test_a_missing_reference_file_is_named(short, tmp_path):
    with pytest.raises(RollerRigError, match=r"expected .*nothing\.npz: no such reference file"):
        assert_history_close(short, tmp_path / "nothing.npz")
