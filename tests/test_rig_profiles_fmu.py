"""The FMU on real profiles (issue 24 item 2): `rollerrig fmu` carries the
profiles' points as generated data (sources/fmu_start.c,
rr_fmu_start_profiles) and FMPy's run of it is rollerrig.simulate()'s, bit
for bit, on S1002/UIC60 and on the measured pair (the pattern of
tests/test_fmu.py's test_default_run_is_simulate_bit_for_bit)."""
import os
import warnings
import zipfile

import pytest

import rollerrig as rr
from rollerrig import fmu

fmpy = pytest.importorskip("fmpy", reason="the test extra installs FMPy")
from fmpy import read_model_description, simulate_fmu  # noqa: E402
from fmpy.simulation import instantiate_fmu  # noqa: E402
from test_fmu import _bits_differ, cache  # noqa: E402,F401  (bit for bit; one core build)
from fmpy.validation import validate_fmu  # noqa: E402

pytestmark = pytest.mark.slow     # FMUs compiled and run by FMPy

T = 0.004
DATA = os.path.join(os.path.dirname(rr.__file__), "data")
SHORT = {"scenario": {"duration_s": 2.0, "targets": [0.04, 0.015], "target_start_s": [0.0, 1.0]}}
PAIRS = {"s1002_uic60": {"wheelset": {"profile": "s1002"}, "roller": {"profile": "uic60"}},
         "measured": os.path.join(DATA, "rig_measured_pair.toml")}


def _scenario(pair, short=SHORT):
    p = PAIRS[pair]
    if isinstance(p, str):
        p = rr.load_parameters(p)
    return {**p, **short}


@pytest.mark.parametrize("pair", sorted(PAIRS))
@pytest.mark.parametrize("version", fmu.FMI_VERSIONS)
def test_fmu_on_real_profiles_is_simulate_bit_for_bit(tmp_path, cache, pair, version):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)     # the rollers' folds
        path = fmu.build_fmu(tmp_path / "rig.fmu", scenario=_scenario(pair),
                             fmi_version=version, cache_dir=cache)
        ref = rr.simulate(params=_scenario(pair)).records
    assert validate_fmu(str(path)) == []
    with zipfile.ZipFile(path) as z:
        start = z.read("sources/fmu_start.c").decode()
    assert "static const double wheel_y[" in start and "static const double roller_y[" in start
    assert ("wheel_right_y" in start) == (pair == "measured")
    md = read_model_description(str(path))
    by_name = {v.name: v for v in md.modelVariables}
    assert by_name["wheelset.profile"].start == "1"      # the item "points" (from 0)
    res = simulate_fmu(str(path), output_interval=T)
    assert len(res) == 501 and _bits_differ(res, ref) == []


def test_an_fmu_without_points_refuses_points(tmp_path, cache):
    """The default FMU (the cone) set to wheelset.profile = points: the
    initialisation fails, saying the FMU carries no points."""
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
    f.setInteger([vr["wheelset.profile"]], [1])           # "points"
    f.setupExperiment(startTime=0.0)
    f.enterInitializationMode()
    with pytest.raises(Exception):
        f.exitInitializationMode()
    assert any("wheelset.profile = \"points\": this FMU carries no points" in m
               for m in messages), messages
    f.freeInstance()
