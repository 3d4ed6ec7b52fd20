"""examples/rig_paper.c on real profiles (issue 24 item 2): the C program
given the points rollerrig.rig.build.write_points writes, and the
scenario's values (-s section.key=value), runs the paper's scenario with
the table of rr_rig_table_build_profiles: the records of rr.simulate() on
the same scenario, bit for bit."""
import os
import subprocess
import warnings

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import _core, rig
from rollerrig.rig import params as rig_params
from rollerrig.rig.build import write_points
from rollerrig.rig.real_profiles import PROFILE_ROWS

from test_c_core import CSRC, _make, _require_toolchain

pytestmark = pytest.mark.slow     # a C program built and run

DATA = os.path.join(os.path.dirname(rr.__file__), "data")


def _c_args(P):
    """-s name=value for each rig row of P that differs from its default (not
    the profile rows: the files say those), every digit."""
    D = rig_params._defaults()
    out = []
    for p in rig_params.PARAMETERS:
        section, key = p.name.split(".")
        if p.creep or key in PROFILE_ROWS.get(section, ()) or P[section][key] == D[section][key]:
            continue
        v = P[section][key]
        out += ["-s", f"{p.name}={v if isinstance(v, str) else repr(float(v))}"]
    return out


@pytest.mark.parametrize("scenario", ["rig_s1002_uic60.toml", "rig_measured_pair.toml"])
def test_c_program_on_real_profiles_is_simulate_bitwise(tmp_path, scenario):
    _require_toolchain()
    _make("paper")
    path = os.path.join(DATA, scenario)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)       # the rollers' folds
        files = write_points(path, tmp_path)
        P = rig_params._parameters("test", path)
        py = rr.simulate(params=path).records
    assert set(files) == ({"wheel", "roller"} if "s1002" in scenario else
                          {"wheel", "roller", "wheel_right", "roller_right"})
    args = _c_args(P) + [f"{k}={v}" for k, v in files.items()]
    out = subprocess.run([str(CSRC / "build" / "rig_paper")] + args, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, timeout=600, check=True).stdout
    c = np.frombuffer(out, dtype=np.float64).reshape(-1, _core.REC_COUNT)
    assert c.shape == py.shape == (5000, len(rig.RECORD_FIELDS))
    assert np.array_equal(np.isnan(c), np.isnan(py))
    assert np.array_equal(c.view(np.uint64)[~np.isnan(c)], py.view(np.uint64)[~np.isnan(py)])


def test_c_program_refuses_bad_points(tmp_path):
    _require_toolchain()
    _make("paper")
    bad = tmp_path / "w.txt"
    bad.write_text("0 0\n0.001 0\n0.001 0\n0.003 0\n")           # a vertical segment
    run = subprocess.run([str(CSRC / "build" / "rig_paper"), f"wheel={bad}"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=60)
    assert run.returncode == 1 and b"rig_paper: " in run.stderr and run.stdout == b""
    bad.write_text("0 0\nx y\n")
    run = subprocess.run([str(CSRC / "build" / "rig_paper"), f"wheel={bad}"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=60)
    assert run.returncode == 2 and b"line 2: expected two numbers" in run.stderr
