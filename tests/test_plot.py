"""rollerrig.plot: every function draws the expected artists on a new figure
or on the axes given, and rejects bad input with RollerRigError."""
import os
import sys

import numpy as np
import pytest

import rollerrig as rr
from _child import run_python

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.axes import Axes  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402
from matplotlib.quiver import Quiver  # noqa: E402

from rollerrig import plot as rp  # noqa: E402

CASE = dict(a=6.304e-3, b=12.61e-3, N=106.7e3, G=8.2e10, nu=0.28, speed=10.0)
MU = 0.33


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


@pytest.fixture(scope="module")
def run():
    return rr.simulate(duration=2.0, targets=[0.03], target_times=[0.0])


@pytest.fixture(scope="module")
def polach_fit():
    s2 = rr.reference.creep_curves()[2]
    kw = {k: v for k, v in s2.case.items() if k not in ("mu", "friction")}
    return rr.fit_polach(s2.cx, s2.fx, **kw), s2


def labels(ax):
    return [line.get_label() for line in ax.get_lines()]


def test_matplotlib_is_imported_on_use_only():
    code = ("import sys, rollerrig, rollerrig.plot; "
            "print('matplotlib' in sys.modules)")
    out = run_python(["-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"


# ------------------------------------------------------------------ creep curves

def test_creep_curves_with_reference_normalises_by_its_mu_N():
    cx = np.geomspace(1e-5, 0.25, 100)
    ref = rr.reference.creep_curves()[1]
    forces = {m: rr.creep_forces(cx, method=m, mu=MU, **CASE) for m in ("fastsim", "polach")}
    ax = rp.creep_curves(cx, forces, reference=ref, title="Coulomb")
    assert isinstance(ax, Axes)
    assert labels(ax) == ["fastsim", "polach", "exact theory (CONTACT), series 1"]
    assert ax.get_xscale() == "log"
    assert ax.get_ylabel() == "-fx / (mu N)"
    assert ax.get_legend() is not None and ax.get_title() == "Coulomb"
    y = ax.get_lines()[0].get_ydata()
    np.testing.assert_allclose(y, -forces["fastsim"].fx / (MU * CASE["N"]))
    np.testing.assert_allclose(ax.get_lines()[2].get_ydata(), -ref.fx / (MU * CASE["N"]))


def test_creep_curves_on_given_axes_and_units():
    fig, (a1, a2) = plt.subplots(1, 2)
    cx = np.linspace(-0.01, 0.01, 41)
    f = rr.creep_forces(cx, method="polach", mu=MU, **CASE)
    out = rp.creep_curves(cx, {"polach": f.fx, "again": f}, ax=a2)
    assert out is a2 and len(a1.get_lines()) == 0 and len(a2.get_lines()) == 2
    assert a2.get_xscale() == "linear" and a2.get_ylabel() == "-fx [N]"
    out = rp.creep_curves(cx, f, N=CASE["N"], sign=1, ax=a1, component="|f|")
    assert out is a1 and a1.get_ylabel() == "|f| / N" and a1.get_legend() is None


def test_creep_curve_single_line():
    cx = np.geomspace(1e-4, 0.1, 20)
    f = rr.creep_forces(cx, method="fastsim", mu=MU, **CASE)
    ax = rp.creep_curve(cx, f, label="fastsim", mu=MU, N=CASE["N"], color="r")
    assert labels(ax) == ["fastsim"] and ax.get_lines()[0].get_color() == "r"
    ax2 = rp.creep_curve(cx, f.fx, ax=ax, label="again")
    assert ax2 is ax and len(ax.get_lines()) == 2
    assert ax.get_ylabel() == "-fx / (mu N)"                 # the first call's labels stay


@pytest.mark.parametrize("call", [
    lambda: rp.creep_curves([1e-3, 2e-3], {"x": [1.0]}),                  # length
    lambda: rp.creep_curves([1e-3], {"x": "abc"}),                        # type
    lambda: rp.creep_curves([1e-3], {}),                                  # empty
    lambda: rp.creep_curves([1e-3], [1.0], mu=0.3),                       # mu without N
    lambda: rp.creep_curves([1e-3], [1.0], N=-1.0),
    lambda: rp.creep_curves([1e-3], [1.0], reference=[1, 2]),
    lambda: rp.creep_curves([1e-3], [1.0], component="mz"),
    lambda: rp.creep_curves([1e-3], [1.0], ax="axes"),
    lambda: rp.creep_curve([1e-3], [1.0], sign=0),
    lambda: rp.creep_curve([[1e-3]], [1.0]),
])
def test_creep_curves_bad_input(call):
    with pytest.raises(rr.RollerRigError):
        call()


# ------------------------------------------------------------------ traction field

def test_traction_field_artists():
    t = rr.fastsim_field(1.0e-3, 0.5e-3, 0.3, mu=MU, nx=20, ny=20, **CASE)
    ax = rp.traction_field(t)
    kinds = [type(c) for c in ax.collections]
    assert kinds == [PolyCollection, PolyCollection, LineCollection, Quiver]
    assert [c.get_label() for c in ax.collections] == [
        "elements", "slip area", "adhesion/slip boundary", "tractions"]
    inside = t.pn > 0
    cells = ax.collections[0]
    assert len(cells.get_paths()) == np.count_nonzero(inside)
    np.testing.assert_allclose(np.sort(cells.get_array()),
                               np.sort(np.hypot(t.px, t.py)[inside] * 1e-6))
    assert len(ax.collections[1].get_paths()) == np.count_nonzero(inside & t.slip)
    assert len(ax.collections[2].get_segments()) > 0
    assert [h.get_text() for h in ax.get_legend().get_texts()] == ["adhesion", "slip"]
    assert len(ax.figure.axes) == 2                      # the colour bar
    assert "slip area" in ax.get_title()


def test_traction_field_on_given_axes_without_slip_or_arrows():
    t = rr.fastsim_field(2e-4, 0.0, 0.0, mu=MU, nx=12, ny=10, grid="strips", **CASE)
    fig, ax = plt.subplots()
    out = rp.traction_field(t, ax=ax, quantity="slip", show_slip=False, arrows=False)
    assert out is ax and len(ax.collections) == 1 and ax.get_legend() is None
    assert len(fig.axes) == 1                            # no colour bar on given axes
    # all elements adhere at a tiny creepage: no slip hatch, boundary still drawn
    t0 = rr.fastsim_field(1e-7, 0.0, 0.0, mu=MU, nx=12, ny=10, **CASE)
    ax = rp.traction_field(t0, quantity="px", colorbar=False)
    assert [c.get_label() for c in ax.collections] == [
        "elements", "adhesion/slip boundary", "tractions"]


@pytest.mark.parametrize("call", [
    lambda t: rp.traction_field(rr.creep_forces(1e-3, mu=MU, **CASE)),
    lambda t: rp.traction_field(t, quantity="shear"),
    lambda t: rp.traction_field(t, ax=plt.figure()),
])
def test_traction_field_bad_input(call):
    t = rr.fastsim_field(1e-3, mu=MU, nx=8, ny=8, **CASE)
    with pytest.raises(rr.RollerRigError):
        call(t)


# ------------------------------------------------------------------ the rig run

def test_rig_history_and_force(run):
    axes = rp.rig_history(run)
    assert isinstance(axes, np.ndarray) and axes.shape == (2,)
    assert labels(axes[0]) == ["creepage cx (contact model, mean of both wheels)",
                               "estimate from the encoders (eq. 16)", "target"]
    assert axes[0].get_ylabel() == "longitudinal creepage cx [-]"
    assert labels(axes[1]) == ["roller surface speed", "wheel surface speed"]
    assert axes[1].get_xlabel() == "time [s]" and axes[1].get_ylabel() == "surface speed [m/s]"
    assert "cx" in axes[0].figure._suptitle.get_text() and "> 0 when braking" in \
        axes[0].figure._suptitle.get_text()
    np.testing.assert_array_equal(axes[0].get_lines()[0].get_xdata(), run.time)
    ax = rp.rig_force(run)
    # the axis names the quantity and its sign: -fx, since fx < 0 when braking
    assert ax.get_ylabel() == "braking force -fx [N]"
    assert labels(ax) == ["braking force -fx on the wheels (both)",
                          "friction limit mu0 N (mu0 = 0.4, N both normal loads)"]
    assert "fx < 0 on the wheel when braking" in ax.get_title()
    np.testing.assert_allclose(ax.get_lines()[0].get_ydata(), -run.fx)
    assert np.all(run.fx[1:] < 0)


def test_rig_plots_under_traction_keep_the_drive_sense():
    """Driving, cx < 0 and fx > 0: the figures draw -cx and fx (positive, on
    the scale), and say so."""
    res = rr.simulate(duration=1.0, targets=[0.02],
                      params={"scenario": {"drive_mode": "traction"}})
    assert np.all(res.creepage[50:] < 0) and np.all(res.fx[50:] > 0)
    axes = rp.rig_history(res)
    assert axes[0].get_ylabel() == "longitudinal creepage -cx [-]"
    np.testing.assert_allclose(axes[0].get_lines()[0].get_ydata(), -res.creepage)
    ax = rp.rig_force(res)
    assert ax.get_ylabel() == "traction force fx [N]"
    np.testing.assert_allclose(ax.get_lines()[0].get_ydata(), res.fx)
    assert ax.get_ylim()[0] <= 0 and ax.get_ylim()[1] >= res.fx.max()


def test_rig_force_keeps_a_force_beyond_the_limit_on_the_scale():
    """A force beyond mu0 N (the rig stops at one, but a RigResult may hold
    records of any source) shows on the axis rather than clipped at 1.1
    mu0 N."""
    import dataclasses
    run = rr.simulate(duration=1.0, targets=[0.02])
    records = run.records.copy()
    records[:, rr.rig.RECORD_FIELDS.index("fx")] *= 1.5
    res = dataclasses.replace(run, records=records)
    ax = rp.rig_force(res)
    assert np.max(-res.fx) > 1.2 * np.max(0.4 * res.normal_load)
    assert ax.get_ylim()[1] >= np.max(-res.fx)


def test_rig_plots_on_given_axes(run):
    fig, axs = plt.subplots(1, 3)
    out = rp.rig_history(run, axes=axs[:2])
    assert out[0] is axs[0] and out[1] is axs[1]
    assert rp.rig_force(run, ax=axs[2]) is axs[2]
    assert [len(a.get_lines()) for a in axs] == [3, 2, 2]


def test_rig_plots_bad_input(run):
    with pytest.raises(rr.RollerRigError):
        rp.rig_history(run.records)
    with pytest.raises(rr.RollerRigError):
        rp.rig_force({"fx": 1.0})
    _, ax = plt.subplots()
    with pytest.raises(rr.RollerRigError):
        rp.rig_history(run, axes=ax)                       # needs two
    with pytest.raises(rr.RollerRigError):
        rp.plot_run("result", "out")


def test_plot_run_writes_both_figures(run, tmp_path):
    paths = rp.plot_run(run, str(tmp_path / "out"))
    assert [os.path.basename(p) for p in paths] == ["rig_creepage.png", "rig_force.png"]
    assert all(os.path.getsize(p) > 1000 for p in paths)
    assert plt.get_fignums() == []
    assert sorted(os.listdir(tmp_path / "out")) == ["rig_creepage.png", "rig_force.png"]


@pytest.mark.skipif(not hasattr(os, "symlink"), reason="no symlinks here")
def test_plot_run_refuses_a_planted_symlink_before_drawing(run, tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    victim = tmp_path / "victim.txt"
    victim.write_text("precious")
    os.symlink(victim, out / "rig_force.png")
    with pytest.raises(rr.RollerRigError, match=r"plot_run: .*rig_force\.png: is a symbolic "
                                                 r"link"):
        rp.plot_run(run, str(out))
    assert victim.read_text() == "precious" and os.listdir(out) == ["rig_force.png"]
    assert plt.get_fignums() == []             # refused before either figure was drawn


def test_decimated_records_plot_the_same_run(run):
    """Figures take their times from the records: a run recorded every 5th
    sample draws the same curves at those samples."""
    coarse = rr.simulate(duration=2.0, targets=[0.03], target_times=[0.0], record_every=5)
    ax = rp.rig_force(coarse)
    np.testing.assert_array_equal(ax.get_lines()[0].get_xdata(), run.time[4::5])
    np.testing.assert_array_equal(ax.get_lines()[0].get_ydata(), -run.fx[4::5])


# ------------------------------------------------------------------ profiles

def test_profiles_draws_roller_wheels_and_contact_points():
    g = rr.RigGeometry.standard()
    shifts = (0.0, 0.002, 0.004)
    ax = rp.profiles(g, y_ws=shifts)
    lab = labels(ax)
    assert lab[0] == "roller" and len(ax.get_lines()) == 1 + 2 * len(shifts)
    points = [lbl for lbl in lab if lbl.startswith("y_ws")]
    assert len(points) == 3 and "+2 mm" in points[1] and "contact angle" in points[1]
    c = rr.wheelset_contact(g, list(shifts))
    marker = ax.get_lines()[-1]
    np.testing.assert_allclose(marker.get_ydata(), [c.left.z[2] * 1e3])
    np.testing.assert_allclose(marker.get_xdata(), [(c.left.y[2] - g.roller_y) * 1e3])
    assert len(ax.collections) == 1                          # the roller's fill


def test_profiles_right_side_on_given_axes_some_wheels():
    g = rr.RigGeometry.standard()
    fig, ax = plt.subplots()
    out = rp.profiles(g, y_ws=[0.0, -0.004], ax=ax, side="right", wheels=[-0.004],
                      window=(-60, 30, -35, 10), legend=False)
    assert out is ax and len(ax.get_lines()) == 1 + 1 + 2 and ax.get_legend() is None
    assert ax.get_xlim() == (-60.0, 30.0)
    c = rr.wheelset_contact(g, [0.0, -0.004])
    np.testing.assert_allclose(ax.get_lines()[-2].get_xdata(),
                               [(-c.right.y[0] - g.roller_y) * 1e3])


@pytest.mark.parametrize("kw", [dict(geometry="S1002"), dict(side="middle"),
                                dict(y_ws="zero"), dict(y_ws=[]), dict(window=(1, 2))])
def test_profiles_bad_input(kw):
    args = dict(geometry=rr.RigGeometry.standard())
    args.update(kw)
    with pytest.raises(rr.RollerRigError):
        rp.profiles(**args)


# ------------------------------------------------------------------ fits

def test_fit_plot(polach_fit):
    res, s2 = polach_fit
    ax = rp.fit(res, s2.cx, s2.fx, mu=MU)
    assert isinstance(ax, Axes) and len(ax.get_lines()) == 2
    assert labels(ax)[0] == "data" and labels(ax)[1].startswith("polach fit: mu0")
    # the friction law's B carries its unit, s/m (A, mu0, kA, kS are dimensionless)
    assert {"A", "B"} <= set(res.fitted)
    assert f"B {res.params['B']:.3g} s/m" in labels(ax)[1]
    assert f"A {res.params['A']:.3g}," in labels(ax)[1] + ","
    assert ax.get_ylabel() == "-fx / (mu N)"
    np.testing.assert_allclose(ax.get_lines()[0].get_ydata(), -s2.fx / (MU * CASE["N"]))
    line = ax.get_lines()[1]
    np.testing.assert_allclose(line.get_ydata(),
                               -res.predict(line.get_xdata()) / (MU * CASE["N"]))


def test_fit_plot_with_residuals_on_given_axes(polach_fit):
    res, s2 = polach_fit
    fig, axs = plt.subplots(2, 1)
    out = rp.fit(res, s2.cx, s2.fx, ax=axs, residuals=True, label="Polach")
    assert out[0] is axs[0] and out[1] is axs[1]
    assert labels(axs[0]) == ["data", "Polach"]
    assert len(axs[1].get_lines()) == 2                      # residuals and the zero line
    np.testing.assert_allclose(axs[1].get_lines()[0].get_ydata(),
                               -res.residuals / CASE["N"], atol=1e-12)


def test_fit_plot_bad_input(polach_fit):
    res, s2 = polach_fit
    with pytest.raises(rr.RollerRigError):
        rp.fit(res.params, s2.cx, s2.fx)
    with pytest.raises(rr.RollerRigError):
        rp.fit(res, s2.cx[:-1], s2.fx)
    with pytest.raises(rr.RollerRigError):
        rp.fit(res, [s2.cx, s2.cx], [s2.fx, s2.fx])          # one speed fitted
    _, ax = plt.subplots()
    with pytest.raises(rr.RollerRigError):
        rp.fit(res, s2.cx, s2.fx, ax=ax, residuals=True)     # needs two axes


def test_without_matplotlib_the_figures_name_the_extra(run, monkeypatch, tmp_path):
    from rollerrig._optional import OptionalDependencyError
    monkeypatch.setitem(sys.modules, "matplotlib.pyplot", None)
    with pytest.raises(OptionalDependencyError, match=r"rollerrig.plot needs matplotlib, which "
                                                      r"is not installed: pip install "
                                                      r"'rollerrig\[plot\]'"):
        rp.rig_force(run)
    with pytest.raises(OptionalDependencyError, match=r"rollerrig.plot needs matplotlib"):
        rp.plot_run(run, str(tmp_path))
    res = rr.reference.score("polach")
    with pytest.raises(OptionalDependencyError, match=r"rollerrig.plot needs matplotlib"):
        rp.error_map(res)


def test_plot_run_leaves_the_backend_alone(run, tmp_path):
    """plot_run writes files and closes its figures; it does not switch the
    caller's backend (a notebook's inline backend stays)."""
    plt.switch_backend("pdf")                 # another non-interactive backend
    try:
        paths = rp.plot_run(run, str(tmp_path))
        assert matplotlib.get_backend() == "pdf"
    finally:
        plt.switch_backend("Agg")
    assert all(open(p, "rb").read(4) == b"\x89PNG" for p in paths)


def test_only_rollerrig_plot_draws():
    """Every drawing function lives in rollerrig.plot (a package): no other
    module of the package names matplotlib, except the command line, which
    picks the non-interactive backend before rollerrig.plot draws its figures."""
    import pathlib
    package = pathlib.Path(rr.__file__).parent
    others = {str(p.relative_to(package)) for p in package.rglob("*.py")
              if "matplotlib" in p.read_text() and p.name != "_optional.py"
              and p.parent.name != "plot"}
    assert others == {"cli.py"}
    assert "matplotlib" not in (package / "cli.py").read_text().replace(
        'require("matplotlib", "rollerrig simulate\'s figures", "plot").use("Agg")', "")


def test_rig_force_shows_the_adhesion_and_names_the_friction_law(run):
    """The adhesion panel: F / N on a scale that separates the targets'
    adhesion (0.37-0.39 in the paper's scenario, a few pixels on the force's
    0-450 N axis), titled with the law that sets them."""
    ax = rp.rig_force(run)
    low = ax.adhesion_axis
    (line,) = low.get_lines()
    with np.errstate(divide="ignore", invalid="ignore"):
        np.testing.assert_allclose(line.get_ydata(), -run.fx / run.normal_load)
    lo, hi = low.get_ylim()
    late = run.time > 2.0
    mu = -run.fx[late] / run.normal_load[late]
    assert lo <= mu.min() and mu.max() <= hi and hi - lo < 0.1
    title = low.get_title()
    assert "Polach's falling friction" in title and "A = 0.4" in title and "B = 0.6 s/m" in title
    assert [t.get_text() for t in low.texts] == [f"target {x:g}" for x in run.targets]
    coulomb = dict(run.params, contact=dict(run.params["contact"], friction_law="coulomb"))
    assert rp.friction_law_text(coulomb) == "Coulomb friction, mu0 = 0.4"


def test_rig_force_on_a_given_axes_draws_no_adhesion_panel(run):
    _, axs = plt.subplots(1, 2)
    ax = rp.rig_force(run, ax=axs[0])
    assert not hasattr(ax, "adhesion_axis")
    with pytest.raises(rr.RollerRigError, match="adhesion=True draws its own two panels"):
        rp.rig_force(run, ax=axs[1], adhesion=True)
