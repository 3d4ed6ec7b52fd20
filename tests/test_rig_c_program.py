"""A C program alone (examples/rig_paper.c, `make -C csrc paper`) runs the
seed paper's scenario from the C declaration of the rig's parameters
(rr_rig_config_default, rr_rig_params_from), the C table builder
(rr_rig_table_build) and the C schedule (rr_rig_schedule): its records are
those of rr.simulate() on the default parameters, bit for bit."""
import subprocess

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import _core, rig

from test_c_core import CSRC, _make, _require_toolchain


def test_c_program_runs_the_paper_scenario_bitwise_as_simulate():
    _require_toolchain()
    _make("paper")
    out = subprocess.run([str(CSRC / "build" / "rig_paper")], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, timeout=600, check=True).stdout
    c = np.frombuffer(out, dtype=np.float64).reshape(-1, _core.REC_COUNT)
    py = rr.simulate().records
    assert c.shape == py.shape == (5000, len(rig.RECORD_FIELDS))
    # bitwise, NaNs (xi_ref before a target; none in the paper's run) as NaN
    assert np.array_equal(np.isnan(c), np.isnan(py))
    assert np.array_equal(c.view(np.uint64)[~np.isnan(c)], py.view(np.uint64)[~np.isnan(py)])
