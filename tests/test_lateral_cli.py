"""rollerrig stability (issue 25): the table, the critical speed, bad input."""
import pytest

import rollerrig as rr
from rollerrig.cli import main


def test_stability_command_prints_the_critical_speed(tmp_path, capsys):
    f = tmp_path / "soft.toml"
    f.write_text("[suspension]\nkx_N_per_m = 2e4\nky_N_per_m = 2e4\n")
    assert main(["stability", "--speeds", "60:100:5", "--track", "--scenario", str(f)]) == 0
    out = capsys.readouterr().out
    assert "on the track" in out and len(out.strip().splitlines()) == 2 + 5 + 1
    # the same number as the function's
    want = rr.stability([60, 70, 80, 90, 100], str(f), track=True).critical_speed
    assert f"critical speed: {want:.6g} m/s" in out


def test_stability_command_without_a_crossing(capsys):
    assert main(["stability", "--speeds", "5,10"]) == 0
    assert "critical speed: none in 5 to 10 m/s" in capsys.readouterr().out


@pytest.mark.parametrize("speeds", ["0:3:3", "5,-1", "a:b:c", "10,5", "nan"])
def test_stability_command_refuses_bad_speeds(speeds, capsys):
    assert main(["stability", "--speeds", speeds]) == 2
    err = capsys.readouterr().err
    assert "--speeds" in err and speeds in err


def test_stability_command_names_a_bad_scenario(tmp_path, capsys):
    f = tmp_path / "bad.toml"
    f.write_text("[suspension]\nkx_N_per_m = -1\n")
    assert main(["stability", "--speeds", "5,10", "--scenario", str(f)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("rollerrig stability") and "kx_N_per_m" in err
