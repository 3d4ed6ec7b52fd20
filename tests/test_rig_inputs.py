"""simulate's own arguments at their limits: long runs in bounded memory
(record_every, max_record_bytes), durations below one sample, the run's
status and its short repr, RigResult.to_xarray / to_dataframe / to_csv, and
the optional dependencies' messages."""
import json
import os
import sys

import numpy as np
import pytest

import rollerrig as rr
from rollerrig._optional import OptionalDependencyError
from rollerrig.rig import RECORD_BYTES_CAP, RECORD_FIELDS, RECORD_UNITS

KW = dict(targets=[0.04, 0.015], target_times=[0.0, 0.6])


@pytest.fixture(scope="module")
def full():
    return rr.simulate(duration=1.2, **KW)


# ------------------------------------------------------------------ memory

#: bytes a kept sample's record takes: 8 per record field (29 fields)
BYTES = 8 * len(rr.rig.RECORD_FIELDS)


@pytest.mark.parametrize("duration, dt, fit", [(1e5, None, 6), (1e5, 1e-6, 21607),
                                               (300.0, 1e-5, 7)])
def test_a_run_over_the_record_cap_is_refused_before_it_starts(duration, dt, fit):
    """Today's cap (1 GiB of records, 232 bytes per sample) and the
    record_every that would fit, named before any memory is asked for: the
    refusal is immediate whatever the size (1e11 samples: 20 TB)."""
    n = int(round(duration / (dt or 0.004)))
    need = n * BYTES / 2 ** 30
    with pytest.raises(rr.RollerRigError) as e:
        rr.simulate(duration=duration, dt=dt)
    text = str(e.value)
    assert text.startswith(f"simulate: the records of {n} samples")
    assert f"would take {need:.3g} GiB, over max_record_bytes = 1 GiB" in text
    assert f"record_every={fit}" in text and f"--record-every {fit}" in text
    # the advice fits, one less does not
    assert n // fit * BYTES <= RECORD_BYTES_CAP < n // (fit - 1) * BYTES


def test_decimated_records_are_the_full_run_every_kth_sample(full):
    """record_every=k keeps samples k-1, 2k-1, ...: the same numbers as the
    full run (the stepping is the same), the last one at the duration, in
    runs of several chunks (max_record_bytes sized to the records kept)."""
    for k in (1, 3, 7, 300):
        res = rr.simulate(duration=1.2, record_every=k, max_record_bytes=300 // k * BYTES, **KW)
        assert res.record_every == k and len(res) == 300 // k
        np.testing.assert_array_equal(res.records, full.records[k - 1::k][:len(res)])
        assert res.samples_run == 300 and res.duration == pytest.approx(1.2)
        assert res.record_dt == pytest.approx(k * 0.004)
    with pytest.raises(rr.RollerRigError, match="the records of 300 samples .* over "
                                                "max_record_bytes"):
        rr.simulate(duration=1.2, max_record_bytes=299 * BYTES, **KW)


def test_summary_of_decimated_records_matches(full):
    """summary()'s windows are in seconds, not samples."""
    kw = dict(duration=5.0, targets=[0.04, 0.015], target_times=[0.0, 2.5])
    rows = rr.simulate(**kw).summary()
    coarse = rr.simulate(record_every=4, **kw).summary()
    for a, b in zip(rows, coarse):
        # means over every 4th sample of the same held creepage: within its
        # sawtooth (measured 0.1 %)
        assert b["reached"] == pytest.approx(a["reached"], rel=0.01)
        assert b["adhesion"] == pytest.approx(a["adhesion"], rel=0.01)
        # the first record of the running mean within tol: at most 4 samples later
        assert 0 <= b["settling_s"] - a["settling_s"] <= 4 * 0.004 + 1e-12


def test_a_run_of_many_chunks_in_bounded_memory():
    """A run longer than the bound of one C call (65 536 samples): the
    records stay in step across the chunks."""
    res = rr.simulate(duration=300.0, targets=[0.02], record_every=250)
    assert len(res) == 300 and res.status >= 0
    # warnings of samples not kept still count (the first braking transient
    # warns: the paper's scenario in test_rig.py)
    if res.status > 0:
        assert "samples warned" in res.message and " 0 of" not in res.message
    np.testing.assert_allclose(res.time, np.arange(1, 301) * 1.0, rtol=1e-12)
    assert res.summary()[0]["reached"] == pytest.approx(0.02, rel=0.05)


@pytest.mark.parametrize("kw, match", [
    (dict(record_every=0), "record_every must be an integer from 1 to the number of "
                           "samples"),
    (dict(record_every=1.5), "record_every must be an integer"),
    (dict(record_every=10 ** 6), "record_every must be an integer from 1 to the number of "
                                 "samples \\(300\\)"),
    (dict(max_record_bytes=0), "max_record_bytes must be a finite number > 0"),
])
def test_bad_record_options(kw, match):
    with pytest.raises(rr.RollerRigError, match=match):
        rr.simulate(duration=1.2, **KW, **kw)


# ------------------------------------------------------------------ durations

def test_a_duration_shorter_than_one_sample_is_refused():
    with pytest.raises(rr.RollerRigError, match=r"simulate: duration = 0.05 s is shorter than "
                                                r"one sample \(dt = 0.1 s\)"):
        rr.simulate(duration=0.05, dt=0.1)
    res = rr.simulate(duration=0.1, dt=0.1, targets=[0.02])      # exactly one sample
    assert len(res) == 1 and res.time[0] == pytest.approx(0.1)


@pytest.mark.parametrize("duration", [0.0, -1.0, float("nan"), float("inf"), 1e5 + 1, "20",
                                      True])
def test_bad_durations(duration):
    with pytest.raises(rr.RollerRigError, match="simulate: duration must be a finite number in "
                                                r"\(0, 100000\] s"):
        rr.simulate(duration=duration)


def test_numpy_scalars_are_numbers():
    res = rr.simulate(duration=np.float64(0.4), dt=np.float32(0.004), targets=[0.02],
                      roller_speed=np.int64(5))
    assert len(res) == 100


# ------------------------------------------------------------------ the result

def test_repr_is_short(full):
    text = repr(full)
    assert text.startswith("RigResult(samples=300, duration=1.2 s, dt=0.004 s, "
                           "record_every=1, method='fastsim', status=")
    assert len(text) < 300 and "array" not in text


def test_status_is_the_worst_sample_status(full):
    assert full.status == max(0, int(full.sample_status.max()))
    assert (full.message == "ok") == (full.status == 0)


def test_to_xarray(full):
    xr = pytest.importorskip("xarray")
    ds = full.to_xarray()
    assert isinstance(ds, xr.Dataset) and dict(ds.sizes) == {"time": 300}
    assert set(ds.data_vars) == set(RECORD_FIELDS) - {"time"}
    for name in RECORD_FIELDS:
        assert ds[name].attrs["units"] == RECORD_UNITS[name] and ds[name].attrs["long_name"]
    np.testing.assert_array_equal(ds.fx.values, full.fx)
    assert ds.fx.attrs["units"] == "N" and ds.time.attrs["units"] == "s"
    assert list(ds.attrs["targets"]) == [0.04, 0.015]
    assert list(ds.attrs["target_times"]) == [0.0, 0.6]
    assert ds.attrs["method"] == "fastsim" and ds.attrs["dt"] == 0.004
    assert json.loads(ds.attrs["params"]) == full.params
    assert float(ds.creepage.sel(time=0.6, method="nearest")) == full.creepage[149]


@pytest.mark.parametrize("module, call, extra", [
    ("xarray", lambda r: r.to_xarray(), "sweep"),
    ("pandas", lambda r: r.to_dataframe(), "sweep"),
])
def test_missing_optional_modules_name_the_extra(full, monkeypatch, module, call, extra):
    monkeypatch.setitem(sys.modules, module, None)         # import now fails
    with pytest.raises(OptionalDependencyError) as e:
        call(full)
    assert isinstance(e.value, ImportError)
    method = "to_xarray" if module == "xarray" else "to_dataframe"
    assert str(e.value).startswith(f"RigResult.{method} needs {module}, which is not "
                                   f"installed: pip install 'rollerrig[{extra}]'")


def test_to_csv_round_trip_and_symlink(full, tmp_path):
    path = tmp_path / "h.csv"
    assert full.to_csv(path) == path
    back = np.loadtxt(path, delimiter=",", skiprows=1)
    np.testing.assert_array_equal(back, full.records)
    with open(path) as fh:
        assert fh.readline().strip().split(",") == list(RECORD_FIELDS)
    if hasattr(os, "symlink"):
        victim = tmp_path / "victim.txt"
        victim.write_text("precious")
        link = tmp_path / "link.csv"
        os.symlink(victim, link)
        with pytest.raises(rr.RollerRigError, match=f"RigResult.to_csv: path {link}: is a "
                                                    f"symbolic link"):
            full.to_csv(link)                  # neither written through nor replaced
        assert victim.read_text() == "precious" and os.path.islink(link)
    assert sorted(os.listdir(tmp_path)) == sorted(
        ["h.csv"] + (["victim.txt", "link.csv"] if hasattr(os, "symlink") else []))


def test_creep_options_are_named():
    with pytest.raises(rr.RollerRigError, match=r"simulate: unknown option\(s\) \['kappa'\]; "
                                                r"the creep options are \['bound'"):
        rr.simulate(duration=0.1, targets=[0.02], kappa=1.0)


def test_rig_run_into_a_given_array():
    """Rig.run(out=...) writes the records in place (simulate's rows, no
    copy): the same numbers as a new array; a wrong array is named."""
    import numpy as np
    refs = (np.full(50, 31.25), np.full(50, 0.02))
    a, st_a = rr.build_rig()[0].run(*refs)
    out = np.empty((50, len(rr.rig.RECORD_FIELDS)))
    b, st_b = rr.build_rig()[0].run(*refs, out=out)
    assert b is out and st_a == st_b
    np.testing.assert_array_equal(a, b)
    for bad in (np.empty((49, out.shape[1])), np.empty(out.shape, dtype=np.float32),
                np.empty(out.shape, order="F"), [[0.0] * out.shape[1]] * 50):
        with pytest.raises(ValueError, match="out must be a writable C-contiguous float64"):
            rr.build_rig()[0].run(*refs, out=bad)
