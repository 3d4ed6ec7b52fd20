"""examples/rig_paper.c on the non-Hertzian contact (issue 24): the C
program given the points and the two tables rollerrig.rig.build.write_points
writes (-s contact.patch=nonhertz) runs the paper's scenario: the records of
rr.simulate() on the same scenario, bit for bit, on both pairs."""
import os
import subprocess
import warnings

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import _core, rig
from rollerrig.rig import params as rig_params
from rollerrig.rig.build import write_points

from test_c_core import CSRC, _make, _require_toolchain
from test_rig_profiles_c import _c_args

pytestmark = pytest.mark.slow     # a C program built and run

DATA = os.path.join(os.path.dirname(rr.__file__), "data")
NARROW = {"patch": "nonhertz", "nonhertz_half_range_m": 8e-5, "nonhertz_elements": 16}


@pytest.mark.parametrize("scenario", ["rig_s1002_uic60.toml", "rig_measured_pair.toml"])
def test_c_program_on_the_nonhertz_contact_is_simulate_bitwise(tmp_path, scenario):
    _require_toolchain()
    _make("paper")
    params = rr.load_parameters(os.path.join(DATA, scenario))
    params["contact"] = dict(NARROW)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)   # folds; S1002's second region
        files = write_points(params, tmp_path)
        P = rig_params._parameters("test", params)
        py = rr.simulate(params=params).records
    assert {"nonhertz_left", "nonhertz_right"} <= set(files)
    args = _c_args(P) + [f"{k}={v}" for k, v in files.items()]
    assert "contact.patch=nonhertz" in args
    out = subprocess.run([str(CSRC / "build" / "rig_paper")] + args, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, timeout=600, check=True).stdout
    c = np.frombuffer(out, dtype=np.float64).reshape(-1, _core.REC_COUNT)
    assert c.shape == py.shape == (5000, len(rig.RECORD_FIELDS))
    assert np.array_equal(np.isnan(c), np.isnan(py))
    assert np.array_equal(c.view(np.uint64)[~np.isnan(c)], py.view(np.uint64)[~np.isnan(py)])


def test_c_program_without_tables_refuses_the_nonhertz_patch(tmp_path):
    _require_toolchain()
    _make("paper")
    run = subprocess.run([str(CSRC / "build" / "rig_paper"), "-s", "contact.patch=nonhertz"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=60)
    assert run.returncode == 1 and b"rig_paper: " in run.stderr and run.stdout == b""
    bad = tmp_path / "t.txt"
    bad.write_text("1 0.16 8e10 0.28 0.4 2\n1 2 3\n")
    run = subprocess.run([str(CSRC / "build" / "rig_paper"), f"nonhertz_left={bad}"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=60)
    assert run.returncode == 2 and b"expected 640 numbers a row" in run.stderr
