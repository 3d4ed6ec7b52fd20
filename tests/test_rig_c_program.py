"""A C program alone (examples/rig_paper.c, `make -C csrc paper`) runs the
seed paper's scenario from the C declaration of the rig's parameters
(rr_rig_config_default, rr_rig_params_from), the C table builder
(rr_rig_table_build) and the C schedule (rr_rig_schedule): its records are
those of rr.simulate() on the default parameters, bit for bit.  A C
controller in the loop (examples/rig_sil.c, `make -C csrc sil`) gives the
history of the same controller written in Python (examples/slide_protection.py)."""
import subprocess

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import _core, rig

from test_c_core import CSRC, _make, _require_toolchain

pytestmark = pytest.mark.slow     # C programs built and run


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


def test_c_controller_in_the_loop_is_the_python_controller_bit_for_bit(tmp_path):
    """rig_sil's slide protection in C (rr_rig_read, rr_rig_write,
    rr_rig_advance in a fixed-rate loop, here free running) against the
    same controller in Python through simulate(controller=...): the same
    records, bit for bit, through the dump, hold and re-apply in the patch."""
    import importlib.util
    _require_toolchain()
    _make("sil")
    out = tmp_path / "sil.f64"
    subprocess.run([str(CSRC / "build" / "rig_sil"), "4", "free", str(out)],
                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=600, check=True)
    c = np.fromfile(out, dtype=np.float64).reshape(-1, _core.REC_COUNT)
    spec = importlib.util.spec_from_file_location(
        "slide_protection", CSRC.parent / "examples" / "slide_protection.py")
    sp = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(sp)
    py = rr.simulate(controller=sp.SlideProtection(sp.DEMAND, start=sp.BRAKE_FROM),
                     targets=[0.0], duration=sp.DURATION, params=sp.ADHESION).records
    assert c.shape == py.shape == (1250, len(rig.RECORD_FIELDS))
    assert np.array_equal(np.isnan(c), np.isnan(py))
    assert np.array_equal(c.view(np.uint64)[~np.isnan(c)], py.view(np.uint64)[~np.isnan(py)])
    assert np.max(c[:, rig.RECORD_FIELDS.index("creepage")]) < 0.1
