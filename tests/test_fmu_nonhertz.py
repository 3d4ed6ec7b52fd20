"""The FMU on the non-Hertzian contact (issue 24): `rollerrig fmu` of a
scenario with contact.patch = "nonhertz" carries the tables simulate() runs
on as generated data (sources/fmu_start.c, rr_fmu_start_nonhertz), and
FMPy's run of it is rollerrig.simulate()'s, bit for bit, on S1002/UIC60 and
on the measured pair, FMI 2 and 3 (the pattern of
tests/test_rig_profiles_fmu.py)."""
import warnings
import zipfile

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import fmu

fmpy = pytest.importorskip("fmpy", reason="the test extra installs FMPy")
from fmpy import read_model_description, simulate_fmu  # noqa: E402
from fmpy.simulation import instantiate_fmu  # noqa: E402
from test_fmu import _bits_differ, cache  # noqa: E402,F401  (bit for bit; one core build)
import test_rig_profiles_fmu as profiles_fmu  # noqa: E402  (its pairs)

pytestmark = pytest.mark.slow     # FMUs compiled and run by FMPy

T = 0.004
SHORT = {**profiles_fmu.SHORT,
         "contact": {"patch": "nonhertz", "nonhertz_half_range_m": 8e-5,
                     "nonhertz_elements": 16}}
PAIRS = profiles_fmu.PAIRS


def _scenario(pair):
    return profiles_fmu._scenario(pair, SHORT)


@pytest.mark.parametrize("pair", sorted(PAIRS))
@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_fmu_on_the_nonhertz_contact_is_simulate_bit_for_bit(tmp_path, cache, pair, version):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)     # folds; S1002's second region
        path = fmu.build_fmu(tmp_path / "rig.fmu", scenario=_scenario(pair),
                             fmi_version=version, cache_dir=cache)
        ref = rr.simulate(params=_scenario(pair)).records
    with zipfile.ZipFile(path) as z:
        start = z.read("sources/fmu_start.c").decode()
    assert "static const double nonhertz_rows0[" in start and "nonhertz_rows1" in start
    md = read_model_description(str(path))
    by_name = {v.name: v for v in md.modelVariables}
    assert by_name["contact.patch"].start == "1"          # the item "nonhertz" (from 0)
    messages = []

    def log(*args):
        # FMPy's default logger goes through a C proxy whose callback a
        # previous simulate_fmu(logger=...) in the process may have freed
        # (FMPy's fmpy.logging.addLoggerProxy keeps one global): our own
        messages.append(args[-1])
    res = simulate_fmu(str(path), output_interval=T, logger=log)
    assert len(res) == 501 and _bits_differ(res, ref) == []
    # a sample that warns in simulate (its inner iteration) warns here too, and nothing else
    assert all(b"samples warned: inner iteration did not converge" in m for m in messages)


def test_an_fmu_without_tables_refuses_the_nonhertz_patch(tmp_path, cache):
    """The default FMU (Hertz) set to contact.patch = nonhertz: the
    initialisation fails, saying the FMU carries no table."""
    path = fmu.build_fmu(tmp_path / "rig.fmu", fmi_version=2, cache_dir=cache)
    unz = tmp_path / "u"
    with zipfile.ZipFile(path) as z:
        z.extractall(unz)
    md = read_model_description(str(unz))
    messages = []

    def log(*args):
        m = args[-1]
        messages.append(m.decode() if isinstance(m, bytes) else m)
    f = instantiate_fmu(str(unz), md, "CoSimulation", logger=log)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    f.setInteger([vr["contact.patch"]], [1])              # "nonhertz"
    f.setupExperiment(startTime=0.0)
    f.enterInitializationMode()
    with pytest.raises(Exception):
        f.exitInitializationMode()
    assert any("this FMU carries no non-Hertzian table" in m for m in messages), messages
    f.freeInstance()


@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_fmu_state_reproduces_a_nonhertz_run(tmp_path, cache, version):
    """An FMU state taken mid-run on the non-Hertzian contact (the rig's
    state holds each wheel's balance seed, rr_wheel_contact.nh_tz) set back
    in the same and in a fresh instance: the run goes on bit for bit."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)
        path = fmu.build_fmu(tmp_path / "rig_state.fmu", scenario=_scenario("s1002_uic60"),
                             fmi_version=version, cache_dir=cache)
    unz = tmp_path / "u"
    with zipfile.ZipFile(path) as z:
        z.extractall(unz)
    md = read_model_description(str(unz))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    outs = [vr[n] for n in ("fx", "fy", "creepage", "left.N", "left.force[2]")]

    messages = []

    def log(*args):                  # kept alive for the instances' whole life
        messages.append(args[-1])

    def start():
        f = instantiate_fmu(str(unz), md, "CoSimulation", logger=log)
        if version == 2:
            f.setupExperiment(startTime=0.0)
            f.enterInitializationMode()
        else:
            f.enterInitializationMode(startTime=0.0)
        f.exitInitializationMode()
        return f

    def get(f):
        return np.array(f.getReal(outs) if version == 2 else f.getFloat64(outs))

    def run(f):
        rows = []
        for k in range(100, 250):
            f.doStep(k * T, T)
            rows.append(get(f))
        return np.array(rows)
    f = start()
    for k in range(100):
        f.doStep(k * T, T)
    state = f.getFMUState()
    blob = f.serializeFMUState(state)
    first = run(f)
    f.setFMUState(state)
    again = run(f)
    f.freeFMUState(state)
    g = instantiate_fmu(str(unz), md, "CoSimulation", logger=log)
    restored = g.deserializeFMUState(blob)
    g.setFMUState(restored)
    g.freeFMUState(restored)
    elsewhere = run(g)
    assert np.array_equal(first.view(np.uint64), again.view(np.uint64))
    assert np.array_equal(first.view(np.uint64), elsewhere.view(np.uint64))
    for x in (f, g):
        x.freeInstance()
