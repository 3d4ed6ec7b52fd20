"""Parameter sweeps (rollerrig.analysis.sweep): grid order, backends, output, errors."""
import _thread
import signal
import sys
import time

import numpy as np
import pytest

import rollerrig as rr
from rollerrig._optional import OptionalDependencyError
from rollerrig.analysis.sweep import UNITS, sweep, sweep_rig

# a small FASTSIM case on the rig's scale (a ~ b ~ 4 mm, N ~ 500 N)
FIXED = dict(a=4e-3, b=3.5e-3, G=8.2e10, nu=0.28, method="fastsim", nx=20, ny=20)
GRID = {"cx": np.linspace(0.0, 0.01, 41), "N": np.array([200.0, 500.0, 1000.0]),
        "mu": np.array([0.2, 0.3, 0.4])}
FIELDS = ("fx", "fy", "mz", "status")


def direct():
    """The same cases by one broadcast call: the reference."""
    return rr.creep_forces(GRID["cx"][:, None, None], N=GRID["N"][None, :, None],
                           mu=GRID["mu"][None, None, :], **FIXED)


def values(res, field):
    """A field of a Dataset or of the plain-dict fallback."""
    return res["data"][field] if isinstance(res, dict) else res[field].values


def assert_bitwise(res, ref):
    for field in FIELDS:
        a, b = values(res, field), np.asarray(getattr(ref, field))
        assert a.shape == b.shape and a.dtype == b.dtype, field
        # bitwise: every case is computed on its own, whatever the chunking
        assert np.array_equal(a.view(np.uint8), b.view(np.uint8)), field


@pytest.fixture(scope="module")
def dask_client():
    """A local Dask cluster: two worker processes of one thread each."""
    distributed = pytest.importorskip("distributed")
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None)
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()


# (1) the grid in order, the same bits on every backend

@pytest.mark.parametrize("backend, chunk", [("serial", None), ("serial", 17),
                                            ("threads", None), ("threads", 50)])
def test_creep_forces_sweep_equals_broadcast_call(backend, chunk):
    res = sweep("creep_forces", GRID, backend=backend, chunk=chunk, progress=False, **FIXED)
    assert_bitwise(res, direct())


def test_threads_with_one_or_several_workers_agree():
    one = sweep("creep_forces", GRID, workers=1, chunk=40, progress=False, **FIXED)
    four = sweep("creep_forces", GRID, workers=4, chunk=40, progress=False, **FIXED)
    assert one.identical(four)


def test_hertz_sweep_in_grid_order():
    grid = {"A": np.array([5.0, 8.0, 12.0]), "N": np.geomspace(100.0, 1e4, 5)}
    res = sweep("hertz", grid, backend="serial", progress=False, B=20.0)
    ref = rr.hertz(grid["A"][:, None], 20.0, grid["N"][None, :])
    for field in ("a", "b", "p0", "delta", "status"):
        assert np.array_equal(res[field].values, getattr(ref, field)), field
    assert res["a"].dims == ("A", "N")


# (2) a Dask cluster of two worker processes

def test_dask_cluster_matches_threads_bitwise(dask_client):
    threads = sweep("creep_forces", GRID, progress=False, **FIXED)
    dask = sweep("creep_forces", GRID, client=dask_client, chunk=60, progress=False, **FIXED)
    assert dask.identical(threads)
    assert_bitwise(dask, direct())


def test_dask_client_need_not_be_the_default(dask_client):
    """A second client on the same cluster, not set as default, is the one used."""
    distributed = pytest.importorskip("distributed")
    other = distributed.Client(dask_client.cluster, set_as_default=False)
    try:
        res = sweep("creep_forces", GRID, client=other, progress=False, **FIXED)
        assert_bitwise(res, direct())
    finally:
        other.close()


def test_dask_runs_a_callable_and_rig_sweeps(dask_client):
    def ratio(cx, mu):
        f = rr.creep_forces(cx, a=4e-3, b=4e-3, N=500.0, mu=mu, nx=10, ny=10)
        return {"force_over_muN": -f.fx / (mu * 500.0), "status": f.status}
    grid = {"cx": np.linspace(0, 0.02, 30), "mu": [0.25, 0.4]}
    assert sweep(ratio, grid, client=dask_client, chunk=7, progress=False).identical(
        sweep(ratio, grid, backend="serial", progress=False))
    grid = {"scenario.mu0": [0.3, 0.4]}
    kw = dict(duration=0.5, targets=[0.02], progress=False)
    assert sweep_rig(grid, client=dask_client, **kw).identical(sweep_rig(grid, **kw))


# (3) output: xarray with names and units, or plain numpy

def test_dataset_has_named_dims_coords_and_units():
    xr = pytest.importorskip("xarray")
    ds = sweep("creep_forces", GRID, progress=False, **FIXED)
    assert isinstance(ds, xr.Dataset)
    assert dict(ds.sizes) == {"cx": 41, "N": 3, "mu": 3}
    for name, axis in GRID.items():
        assert np.array_equal(ds[name].values, axis)
    assert ds.fx.dims == ("cx", "N", "mu") and ds.status.dtype == np.int8
    units = {n: ds[n].attrs.get("units") for n in ("cx", "N", "mu", "fx", "fy", "mz")}
    assert units == {"cx": "1", "N": "N", "mu": "1", "fx": "N", "fy": "N", "mz": "N m"}
    assert ds.attrs["function"] == "creep_forces" and ds.attrs["a"] == 4e-3
    assert ds.attrs["method"] == "fastsim"
    # selection by value works: fx at cx = 0.01, N = 500, mu = 0.3 is that call's
    one = rr.creep_forces(0.01, N=500.0, mu=0.3, **FIXED)
    assert float(ds.fx.sel(cx=0.01, N=500.0, mu=0.3)) == one.fx


def test_one_unit_per_name_friction_and_curvature():
    """Polach's friction law is swept as friction.A [-] and friction.B [s/m];
    hertz's A, B are its curvature sums [1/m]: each name has one unit, the
    one of its function.  A friction axis gives each case FallingFriction
    with that field (the other from the fixed law) bitwise."""
    fixed = dict(cx=2e-3, a=4e-3, b=3.5e-3, N=500.0, mu=0.3, speed=5.0, method="polach")
    B = np.array([0.0, 0.3, 0.6, 2.0])
    out = sweep("creep_forces", {"friction.B": B}, output="dict", progress=False,
                friction=rr.FallingFriction(A=0.5), **fixed)
    assert out["units"]["friction.B"] == "s/m" and out["dims"]["fx"] == ("friction.B",)
    one = rr.creep_forces(**fixed, friction=rr.FallingFriction(A=0.5, B=B))
    assert np.array_equal(out["data"]["fx"], one.fx)
    out = sweep("creep_forces", {"friction.A": [0.4, 1.0]}, output="dict", progress=False,
                **fixed)
    assert out["units"]["friction.A"] == "1"
    assert np.array_equal(out["data"]["fx"], rr.creep_forces(
        **fixed, friction=rr.FallingFriction(A=np.array([0.4, 1.0]))).fx)
    out = sweep("hertz", {"A": [0.5, 0.8], "B": [0.2, 0.3]}, output="dict", progress=False,
                N=1e5)
    assert out["units"]["A"] == "1/m" and out["units"]["B"] == "1/m"
    # a name that means nothing of its own gets no unit rather than another's
    out = sweep(lambda A, B: {"y": A * B}, {"A": [1.0], "B": [2.0]}, output="dict",
                progress=False)
    assert "A" not in out["units"] and "B" not in out["units"]
    assert "A" not in UNITS and "B" not in UNITS
    # the rig's friction law: its parameter file's keys carry their units
    ds = sweep_rig({"contact.polach_A": [0.4], "contact.polach_B_s_per_m": [0.6]},
                   duration=0.1, targets=[0.02], backend="serial", progress=False,
                   output="dict")
    assert ds["units"]["polach_A"] == "1" and ds["units"]["polach_B_s_per_m"] == "s/m"
    # the friction axes are creep_forces' and set a FallingFriction only
    with pytest.raises(rr.RollerRigError, match=r"\['friction.B'\] are creep_forces' "
                                                r"friction law; hertz has none"):
        sweep("hertz", {"friction.B": [0.6]}, A=0.5, B=0.3, N=1e5)
    with pytest.raises(rr.RollerRigError, match="the fixed friction must be None or a "
                                                "FallingFriction, got 'coulomb'"):
        sweep("creep_forces", {"friction.B": [0.6]}, friction="coulomb", **fixed)


def test_without_xarray_the_sweep_refuses_before_running(monkeypatch):
    """The result's type does not change with what is installed: without
    xarray the default output raises an ImportError naming the extra, before
    any case runs; output="dict" is the plain-numpy result on request."""
    with_xr = sweep("creep_forces", GRID, progress=False, **FIXED)
    monkeypatch.setitem(sys.modules, "xarray", None)      # import xarray now fails
    calls = []

    def counted(cx):
        calls.append(cx)
        return {"y": cx}
    for call in (lambda: sweep("creep_forces", GRID, progress=False, **FIXED),
                 lambda: sweep(counted, {"cx": [1.0, 2.0]}, progress=False),
                 lambda: sweep_rig({"scenario.mu0": [0.3]}, duration=0.1, progress=False)):
        with pytest.raises(ImportError) as e:
            call()
        assert isinstance(e.value, OptionalDependencyError)
        assert "needs xarray, which is not installed: pip install 'rollerrig[sweep]'" \
            in str(e.value) and "output='dict'" in str(e.value)
    assert calls == []
    plain = sweep("creep_forces", GRID, progress=False, output="dict", **FIXED)
    assert isinstance(plain, dict) and set(plain) == {"coords", "data", "dims", "units",
                                                      "attrs", "coord_attrs"}
    assert list(plain["coords"]) == ["cx", "N", "mu"]
    for name, axis in GRID.items():
        assert np.array_equal(plain["coords"][name], axis)
    for field in FIELDS:
        assert np.array_equal(plain["data"][field], with_xr[field].values)
        assert plain["data"][field].shape == (41, 3, 3)
    assert plain["units"]["fx"] == "N" and plain["dims"]["fx"] == ("cx", "N", "mu")
    assert plain["attrs"]["method"] == "fastsim"
    assert_bitwise(plain, direct())
    with pytest.raises(rr.RollerRigError, match="output must be 'xarray' or 'dict', got 'np'"):
        sweep("creep_forces", GRID, output="np", **FIXED)


def test_dask_backend_without_distributed_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)
    with pytest.raises(OptionalDependencyError,
                       match=r"sweep\(backend='dask'\) needs dask.distributed, which is not "
                             r"installed: pip install 'rollerrig\[distributed\]'"):
        sweep("creep_forces", GRID, backend="dask", **FIXED)


def test_progress_bar_is_optional(monkeypatch):
    monkeypatch.setitem(sys.modules, "tqdm", None)
    monkeypatch.setitem(sys.modules, "tqdm.auto", None)
    res = sweep("creep_forces", GRID, progress=True, **FIXED)
    assert_bitwise(res, direct())


# (4) rig-parameter sweeps

def test_sweep_rig_over_mu0():
    ds = sweep_rig({"scenario.mu0": [0.3, 0.4]}, duration=1.0, targets=[0.01, 0.02],
                   progress=False)
    metrics = ("reached", "settling_s", "adhesion", "peak_force_over_muN")
    # a dotted path's dimension is its last part, usable as a keyword
    for m in metrics:
        assert ds[m].dims == ("mu0", "target") and ds[m].attrs["long_name"]
    assert ds.mu0.attrs == {"units": "1", "parameter": "scenario.mu0"}
    assert list(ds.target.values) == [0.01, 0.02]
    assert ds.status.dtype == np.int8 and list(ds.status.values) == [
        rr.simulate(duration=1.0, targets=[0.01, 0.02], params={"scenario": {"mu0": m}}).status
        for m in (0.3, 0.4)]
    assert ds.settling_s.attrs["units"] == "s"
    # each point is the summary of its own run
    for mu0 in (0.3, 0.4):
        rows = rr.simulate(duration=1.0, targets=[0.01, 0.02],
                           params={"scenario": {"mu0": mu0}}).summary()
        for m in metrics:
            np.testing.assert_array_equal(ds[m].sel(mu0=mu0).values, [r[m] for r in rows])
    # the adhesion held scales with mu0
    assert np.all(ds.adhesion.sel(mu0=0.4) > ds.adhesion.sel(mu0=0.3))


def test_sweep_rig_takes_simulate_arguments_and_base_params(tmp_path):
    base = tmp_path / "base.toml"
    base.write_text("[scenario]\nmu0 = 0.35\n")
    ds = sweep_rig({"method": ["fastsim", "polach"], "wheelset.mass_kg": [12.0, 15.0]},
                   duration=0.4, targets=[0.02], params=str(base),
                   backend="serial", progress=False)
    # simulate's "method" is "creep_method": .sel(method=...) is xarray's keyword
    assert ds.reached.dims == ("creep_method", "mass_kg", "target")
    assert ds.mass_kg.attrs == {"units": "kg", "parameter": "wheelset.mass_kg"}
    assert ds.creep_method.attrs == {"argument": "method"}
    assert list(ds.creep_method.values) == ["fastsim", "polach"]
    ref = rr.simulate(duration=0.4, targets=[0.02], method="polach",
                      params={"scenario": {"mu0": 0.35}, "wheelset": {"mass_kg": 15.0}})
    assert ds.adhesion.sel(creep_method="polach", mass_kg=15.0).values[0] \
        == ref.summary()[0]["adhesion"]


def test_sweep_rig_dimension_names_when_last_parts_clash():
    """Two paths ending alike, or a path ending as a simulate argument on the
    same grid: the whole path, '.' -> '_', names the dimension."""
    ds = sweep_rig({"roller_drive.kp_N_m_s_per_rad": [300.0],
                    "wheelset_drive.kp_N_m_s_per_rad": [100.0, 120.0],
                    "integration.substeps": [1], "substeps": [1, 2]},
                   duration=0.2, targets=[0.02], backend="serial", progress=False)
    assert ds.reached.dims == ("roller_drive_kp_N_m_s_per_rad",
                               "wheelset_drive_kp_N_m_s_per_rad", "integration_substeps",
                               "substeps", "target")
    assert ds.wheelset_drive_kp_N_m_s_per_rad.attrs["parameter"] == \
        "wheelset_drive.kp_N_m_s_per_rad"
    assert "parameter" not in ds.substeps.attrs
    ds.reached.sel(wheelset_drive_kp_N_m_s_per_rad=120.0, substeps=2)
    ds = sweep_rig({"integration.method": ["trbdf2"], "method": ["polach"]}, duration=0.2,
                   targets=[0.02], backend="serial", progress=False)
    assert ds.reached.dims == ("integration_method", "creep_method", "target")


# (5) bad input names what is wrong; failures carry their place in the grid

@pytest.mark.parametrize("grid, match", [
    ({"cx": []}, "grid axis 'cx' is empty"),
    ({"cx": np.zeros((2, 2))}, r"grid axis 'cx' must be 1-D, got shape \(2, 2\)"),
    ({"cx": ["a", "b"]}, "grid axis 'cx' must be real numbers"),
    ({}, "grid must be a non-empty dict"),
])
def test_bad_grid(grid, match):
    with pytest.raises(rr.RollerRigError, match=match):
        sweep("creep_forces", grid, progress=False, **FIXED)


def test_bad_function_backend_and_arguments():
    with pytest.raises(rr.RollerRigError, match="unknown function 'creep_force'"):
        sweep("creep_force", GRID, **FIXED)
    with pytest.raises(rr.RollerRigError, match="backend must be .* got 'processes'"):
        sweep("creep_forces", GRID, backend="processes", **FIXED)
    with pytest.raises(rr.RollerRigError, match="creep_forces: missing a required argument"):
        sweep("creep_forces", GRID, b=4e-3)
    with pytest.raises(rr.RollerRigError, match="'mu'.* both as a grid axis and as a fixed"):
        sweep("creep_forces", GRID, **dict(FIXED, mu=0.3))
    with pytest.raises(rr.RollerRigError, match="fixed argument 'b' must be a scalar"):
        sweep("creep_forces", GRID, **dict(FIXED, b=[1e-3, 2e-3]))
    with pytest.raises(rr.RollerRigError, match=r"chunk must be an integer >= 1 .*, got 0"):
        sweep("creep_forces", GRID, chunk=0, **FIXED)
    with pytest.raises(rr.RollerRigError, match="workers must be an integer >= 1, got 0"):
        sweep("creep_forces", GRID, workers=0, **FIXED)
    with pytest.raises(rr.RollerRigError, match="unknown parameter 'scenario.mu'"):
        sweep_rig({"scenario.mu": [0.3]})
    with pytest.raises(rr.RollerRigError, match="'mu0' is neither a parameter path"):
        sweep_rig({"mu0": [0.3]})
    with pytest.raises(rr.RollerRigError, match="'scenario.targets' is not a single value"):
        sweep_rig({"scenario.targets": [0.3]})


def test_bad_cases_warn_once_for_the_grid():
    grid = {"cx": [0.001, 0.002], "mu": [0.3, -0.1]}
    with pytest.warns(rr.RollerRigWarning, match=r"mu = -0.1 at index \(0, 1\).*"
                                                 r"\(2 of 4 elements failed"):
        res = sweep("creep_forces", grid, chunk=1, progress=False, N=500.0, **FIXED)
    assert np.isnan(res.fx.values[:, 1]).all() and (res.status.values[:, 1] < 0).all()


def test_exception_in_a_chunk_names_its_cases():
    def boom(x):
        if np.any(x == 25.0):
            raise ZeroDivisionError("no twenty-five")
        return {"y": x * 2}
    for backend in ("serial", "threads"):
        with pytest.raises(rr.RollerRigError,
                           match=r"chunk 2 of 5 \(cases 20 to 29, grid index \(20,\) to "
                                 r"\(29,\)\) failed: ZeroDivisionError: no twenty-five") as e:
            sweep(boom, {"x": np.arange(50.0)}, chunk=10, backend=backend, progress=False)
        assert isinstance(e.value.__cause__, ZeroDivisionError)
    # the library's own errors, when asked to raise
    with pytest.raises(rr.RollerRigError, match=r"grid index \(0, 1\).*mu = -0.1"):
        sweep("creep_forces", {"cx": [0.001], "mu": [0.3, -0.1]}, chunk=1, progress=False,
              N=500.0, errors="raise", **FIXED)
    # a bad parameter value is refused before any run, naming the axis and value
    with pytest.raises(rr.RollerRigError, match=r"sweep_rig: grid axis 'scenario.mu0' = -0.2: "
                                                r"scenario.mu0 must be a finite number in \(0, 1e\+100\]"):
        sweep_rig({"scenario.mu0": [0.3, -0.2]}, duration=0.2, progress=False)
    with pytest.raises(rr.RollerRigError, match=r"grid axis 'roller_drive.gear_ratio' = 2.0: "
                                                r".*does not act on the model"):
        sweep_rig({"roller_drive.gear_ratio": [2.0]}, duration=0.2, progress=False)
    # a run that raises is named by its parameters
    with pytest.raises(rr.RollerRigError, match=r"run 1 \(grid index \(1,\): dt = 0.5\) "
                                                r"failed.*dt must be a finite number in"):
        sweep_rig({"dt": [0.004, 0.5]}, duration=1.0, targets=[0.02], progress=False)


@pytest.fixture
def python_sigint():
    """Python's SIGINT handler for the test: interrupt_main does nothing while
    SIGINT is ignored (a run started as a background job of a
    non-interactive shell)."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


def test_ctrl_c_cancels_pending_chunks(python_sigint):
    started = []

    def slow(x):
        started.append(x[0])
        if x[0] == 0:
            _thread.interrupt_main()     # as Ctrl-C would, while the main thread waits
        time.sleep(0.05)
        return {"y": x}
    with pytest.raises(KeyboardInterrupt, match="sweep.* interrupted: .* cancelled"):
        sweep(slow, {"x": np.arange(100.0)}, chunk=1, workers=2, progress=False)
    # the pending chunks were dropped, and nothing runs on after the interrupt
    n = len(started)
    assert n < 100
    time.sleep(0.2)
    assert len(started) == n
