"""The one progress mechanism (rollerrig._progress): a tqdm bar on stderr,
shown by default only once the work passes about a second, on simulate and
the sweeps alike; progress is checked and named."""
import sys

import pytest

import rollerrig as rr
from rollerrig import _progress


def test_a_quick_run_prints_nothing_by_default(capfd):
    rr.simulate(duration=0.2, targets=[0.02])
    rr.sweep("hertz", {"A": [0.5, 0.8]}, output="dict", B=0.3, N=1e3)
    assert capfd.readouterr().err == ""


@pytest.mark.parametrize("call", ["simulate", "sweep"])
def test_progress_true_shows_the_bar_from_the_start(call, capfd):
    if call == "simulate":
        rr.simulate(duration=0.2, targets=[0.02], progress=True)
    else:
        rr.sweep("hertz", {"A": [0.5, 0.8]}, output="dict", B=0.3, N=1e3, progress=True)
    err = capfd.readouterr().err            # tqdm's line (cleared at the end: leave=False)
    assert f"{call}" in err and ("sample" if call == "simulate" else "case") in err


def test_the_default_bar_waits_about_a_second(monkeypatch):
    seen = {}

    class Bar:
        def __init__(self, **kw):
            seen.update(kw)
    monkeypatch.setitem(sys.modules, "tqdm", type(sys)("tqdm"))
    sys.modules["tqdm"].tqdm = Bar
    _progress.bar(None, 10, "x", "case")
    assert seen["delay"] == _progress.DELAY_S == 1.0 and seen["file"] is sys.stderr
    _progress.bar(True, 10, "x", "case")
    assert seen["delay"] == 0.0


def test_progress_false_or_no_tqdm_is_silent(monkeypatch, capfd):
    rr.simulate(duration=0.2, targets=[0.02], progress=False)
    monkeypatch.setitem(sys.modules, "tqdm", None)
    rr.simulate(duration=0.2, targets=[0.02], progress=True)
    assert capfd.readouterr().err == ""


@pytest.mark.parametrize("bad", ["yes", 1, 0.5])
def test_a_bad_progress_is_named(bad):
    with pytest.raises(rr.RollerRigError, match=r"simulate: progress must be None"):
        rr.simulate(duration=0.2, progress=bad)
    with pytest.raises(rr.RollerRigError, match=r"sweep: progress must be None"):
        rr.sweep("hertz", {"A": [0.5]}, output="dict", B=0.3, N=1e3, progress=bad)
