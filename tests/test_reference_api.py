"""rollerrig.analysis.reference: scoring methods against CONTACT's exact cases and creep curves."""
import filecmp
import math
import os
import re

import numpy as np
import pytest

import rollerrig as rr
from rollerrig.analysis import reference as ref
from reference_cases import DATA, read_csv


@pytest.fixture(scope="module")
def fastsim():
    return ref.score("fastsim", nx=30, ny=30)


@pytest.fixture(scope="module")
def blended():
    return ref.score("fastsim_blended", nx=30, ny=30)


@pytest.mark.parametrize("name", [ref.TABLE_FILE, ref.CURVES_FILE])
def test_shipped_data_is_the_tests_copy(name):
    """The package's CSVs are byte-identical to tests/data's (source line included)."""
    shipped = os.path.join(ref.DATA_DIR, name)
    assert filecmp.cmp(shipped, os.path.join(DATA, name), shallow=False)
    with open(shipped) as f:
        assert f.readline().startswith("# source: ")


def test_exact_cases_decoded():
    t = ref.exact_cases()
    assert t is ref.exact_cases()                      # cached
    assert t.cx.shape == (3220,) and not t.cx.flags.writeable
    assert (t.N, t.mu, t.G, t.nu) == (82000.0, 0.3, 82000.0e6, 0.28)
    assert sorted(set(t.spin.tolist())) == [0.0, 0.5, 1.0, 2.0]
    assert sorted(set(t.a_over_b.tolist())) == [0.2, 0.5, 1.0, 2.0, 5.0]
    # 5 a/b x 4 spins x 7 directions x 23 magnitudes, each combination once
    keys = set(zip(t.a_over_b.tolist(), t.spin.tolist(), t.angle.tolist(),
                   t.magnitude.tolist()))
    assert len(keys) == 3220
    np.testing.assert_allclose(np.arctan2(t.cy, t.cx)[t.magnitude > 0],
                               t.angle[t.magnitude > 0], atol=1e-12)
    np.testing.assert_allclose(t.a / t.b, t.a_over_b)
    # the first row: a/b = 0.2, aa = 4 mm, rho = 1772 mm, cp = 8.944 mm
    assert t.a[0] == pytest.approx(4e-3) and t.b[0] == pytest.approx(20e-3)
    assert t.cp[0] == pytest.approx(8.944e-3)
    i = 1                                               # magnitude 0.1, angle -pi/2
    assert t.cy[i] == pytest.approx(-0.1 * 0.3 * 8.944 / 1772.0)


def test_fastsim_reproduces_known_figures(fastsim):
    """FASTSIM 30 x 30 (rect, parabolic): median 0.0285, p95 0.108, max 0.173 (README,
    benchmarks/RESULTS.md), each within 0.005."""
    s = fastsim.overall
    assert s["n"] == 3220 and s["n_failed"] == 0
    assert s["median"] == pytest.approx(0.0285, abs=0.005)
    assert s["p95"] == pytest.approx(0.108, abs=0.005)
    assert s["max"] == pytest.approx(0.173, abs=0.005)
    # the per-case error is the vector difference over mu N
    t = fastsim.cases
    f = rr.creep_forces(t.cx[100], t.cy[100], t.cphi[100], a=t.a[100], b=t.b[100], N=t.N,
                        mu=t.mu, G=t.G, nu=t.nu, method="fastsim", nx=30, ny=30)
    dF = math.hypot(f.fx / (t.mu * t.N) - t.Fx[100], f.fy / (t.mu * t.N) - t.Fy[100])
    assert fastsim.error[100] == pytest.approx(dF, rel=1e-12, abs=1e-15)
    # FASTSIM's spin moment is close to the exact one (same sign convention)
    assert fastsim.mz_overall["median"] < 0.02


def test_blended_beats_fastsim_at_the_median(fastsim, blended):
    assert blended.overall["median"] < fastsim.overall["median"]
    assert blended.overall["p95"] < fastsim.overall["p95"]


@pytest.mark.parametrize("split", ["by_spin", "by_ellipticity", "mz_by_spin"])
def test_split_statistics_consistent(fastsim, split):
    groups = getattr(fastsim, split)
    overall = fastsim.mz_overall if split.startswith("mz") else fastsim.overall
    err = fastsim.mz_error if split.startswith("mz") else fastsim.error
    key = fastsim.cases.a_over_b if "ellipticity" in split else fastsim.cases.spin
    assert len(groups) == (5 if "ellipticity" in split else 4)
    assert sum(s["n"] for s in groups.values()) == overall["n"] == 3220
    assert max(s["max"] for s in groups.values()) == overall["max"]
    meds = [s["median"] for s in groups.values()]
    assert min(meds) <= overall["median"] <= max(meds)
    p95s = [s["p95"] for s in groups.values()]
    assert min(p95s) <= overall["p95"] <= max(p95s)
    for level, s in groups.items():
        assert s["median"] == pytest.approx(np.median(err[key == level]))
        assert s["median"] <= s["p95"] <= s["max"]


def test_fastsim_error_grows_with_spin(fastsim):
    meds = [fastsim.by_spin[s]["median"] for s in sorted(fastsim.by_spin)]
    assert meds == sorted(meds)


def test_table_text(fastsim, blended):
    text = ref.table([fastsim, blended])
    assert "fastsim (nx=30, ny=30)" in text and "fastsim_blended" in text
    assert "spin 0.5" in text and "a/b 5" in text
    assert f"{fastsim.overall['median']:.4f}" in text
    assert fastsim.table() == ref.table(fastsim)
    short = ref.table({"f": fastsim}, split=False)
    assert "spin" not in short.replace("|dF|", "")


def test_failed_cases_are_counted():
    # cases= takes modified cases; errors="ignore" keeps the failed ones as NaN
    t = ref.exact_cases()
    a = np.array(t.a)
    a[:10] = -1.0
    r = ref.score("fastsim", cases=t._replace(a=a), nx=5, ny=5, errors="ignore")
    assert r.overall["n_failed"] == 10 == int(np.sum(r.status < 0))
    assert r.overall["n"] == 3210 and np.isnan(r.error[:10]).all()
    assert math.isfinite(r.overall["max"])
    assert "3210+10!" in r.table() and "errors" not in r.label
    with pytest.raises(rr.RollerRigError):
        ref.score("fastsim", cases=t._replace(a=a), nx=5, ny=5)   # errors="raise"


@pytest.mark.parametrize("method, opts, match", [
    ("fastsimm", {}, "method must be one of"),
    ("fastsim", {"nx": 0}, "nx must be an integer"),
    ("fastsim", {"bound": "round"}, "bound must be"),
    ("fastsim", {"mesh": 30}, "unknown option 'mesh'"),
    ("fastsim", {"mu": 0.4}, "mu is set by the reference cases"),
])
def test_bad_method_or_option_raises(method, opts, match):
    with pytest.raises(rr.RollerRigError, match=match):
        ref.score(method, **opts)
    with pytest.raises(rr.RollerRigError, match=match):
        ref.score_curves(method, **opts)


# ------------------------------------------------------------------ creep curves

def _header_grid():
    comment = read_csv(ref.CURVES_FILE)[0]
    nx, ny = re.search(r"grid (\d+)x(\d+)", comment).groups()
    return int(nx), int(ny)


def test_creep_curves_settings():
    curves = ref.creep_curves()
    assert sorted(curves) == [1, 2, 3, 4]
    nx, ny = _header_grid()
    assert (nx, ny) == (48, 44)
    c3, c4 = curves[3], curves[4]
    assert c3.method == "fastsim" and c3.options["nx"] == nx and c3.options["ny"] == ny
    assert c4.method == "modified_fastsim"
    assert (c4.options["k0"], c4.options["alpha_inf"], c4.options["beta"]) == (0.54, 0.02, 0.62)
    assert curves[1].method is None and curves[2].method is None and "layer" in curves[2].note
    assert curves[1].options == {"nx": nx, "ny": ny}
    assert curves[1].case["mu"] == 0.33 and curves[1].case["friction"] is None
    assert c4.case["mu"] == pytest.approx(0.36)
    assert c4.case["friction"].A == pytest.approx(0.1368 / 0.36)
    assert c4.case["friction"].B == pytest.approx(math.log(2.0) / 0.99)
    assert curves[2].case["friction"].A == pytest.approx(0.14 / 0.33)
    for c in curves.values():
        assert c.case["a"] == pytest.approx(6.304e-3) and c.case["N"] == 106700.0
        np.testing.assert_allclose(c.fx_n, c.fx / (c.case["mu"] * c.case["N"]), rtol=2e-3,
                                   atol=2e-4)


def test_curves_series3_fastsim_on_its_own_grid():
    """CONTACT's FASTSIM on its 48 x 44 grid (from the header): our fastsim within
    0.003 of mu N RMS and 0.005 max (measured 0.0004, 0.0014; CONTACT prints 4 digits)."""
    nx, ny = _header_grid()
    s = ref.score_curves("fastsim", series=3, nx=nx, ny=ny, grid="rect", bound="parabolic")
    assert list(s) == [3]
    assert s[3].rms < 0.003 and s[3].max < 0.005
    assert s[3].rms <= s[3].max
    np.testing.assert_allclose(s[3].error, np.abs(s[3].model - s[3].reference))


def test_curves_series4_and_all_series():
    c4 = ref.creep_curves()[4]
    s4 = ref.score_curves(c4.method, series=[4], **c4.options)[4]
    assert s4.max < 0.01
    allc = ref.score_curves("fastsim", nx=20, ny=20)
    assert sorted(allc) == [1, 2, 3, 4]
    assert allc[1].rms < 0.03                       # FASTSIM vs the exact theory
    with pytest.raises(rr.RollerRigError, match="series must be among"):
        ref.score_curves("fastsim", series=7)


# ------------------------------------------------------------------ error map

def test_error_map_axes(fastsim):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    import rollerrig.plot as rp

    axes = rp.error_map(fastsim)
    assert len(axes) == 4
    assert all(isinstance(a, plt.Axes) for a in axes)
    mesh = axes[0].collections[0]
    # cells: 23 magnitudes x 7 directions; max over a/b never exceeds the overall max
    assert mesh.get_array().size == 23 * 7
    assert np.nanmax(mesh.get_array()) <= fastsim.overall["max"] + 1e-15
    plt.close(axes[0].figure)

    fig, ax = plt.subplots()
    out = rp.error_map(fastsim, ax=ax, spin=2.0, quantity="mz", ellipticity=1.0)
    assert out is ax
    with pytest.raises(rr.RollerRigError, match="spin level"):
        rp.error_map(fastsim, ax=ax)
    with pytest.raises(rr.RollerRigError, match="spin must be one of"):
        rp.error_map(fastsim, ax=ax, spin=3.0)
    with pytest.raises(rr.RollerRigError, match="quantity"):
        rp.error_map(fastsim, ax=ax, spin=0.0, quantity="fz")
    plt.close(fig)


def test_the_table_caption_names_the_cases_scored():
    """The caption comes from the cases, not a fixed text: CONTACT's table
    or the library's own exact cases."""
    contact = ref.score("linear")
    assert contact.table().splitlines()[-1].startswith(
        "|dF|/(mu N) against CONTACT's exact theory (11 x 11 grid, 3220 cases);")
    own = ref.score("linear", cases=ref.own_exact_cases(n=4, seed=3, nx=5))
    last = own.table().splitlines()[-1]
    assert last.startswith("|dF|/(mu N) against rollerrig's exact theory (Richardson 5/10 "
                           "across, 4 cases);") and "CONTACT" not in last
    both = ref.table([contact, own]).splitlines()[-1]
    assert "CONTACT's" in both and "rollerrig's" in both
