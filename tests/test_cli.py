"""The command line: rollerrig simulate."""
import csv
import os

import pytest

from rollerrig import cli, rig


def test_simulate_writes_table_csv_and_figures(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    scenario = tmp_path / "scenario.toml"
    scenario.write_text('[scenario]\nmu0 = 0.35\ntargets = [0.03]\ntarget_start_s = [0.0]\n'
                        'duration_s = 2.0\n')
    out = tmp_path / "out"
    code = cli.main(["simulate", "--scenario", str(scenario), "--duration", "2",
                     "--out", str(out), "--quiet"])
    text = capsys.readouterr().out
    assert code == 0
    assert "real-time factor" in text and "target" in text and "0.030" in text
    for name in ("rig_history.csv", "rig_creepage.png", "rig_force.png"):
        assert os.path.getsize(out / name) > 1000
    with open(out / "rig_history.csv") as fh:
        rows = list(csv.reader(fh))
    assert tuple(rows[0]) == rig.RECORD_FIELDS and len(rows) == 1 + 500


def test_bad_scenario_gives_a_message_not_a_traceback(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text("[wheelset]\nmass_kg = -3.0\n")
    assert cli.main(["simulate", "--scenario", str(bad), "--out", str(tmp_path)]) == 2
    assert "wheelset.mass_kg" in capsys.readouterr().err
    assert cli.main(["simulate", "--scenario", str(tmp_path / "missing.toml")]) == 2


def test_help_and_version(capsys):
    assert cli.main([]) == 0
    with pytest.raises(SystemExit):
        cli.main(["--version"])
    assert "rollerrig" in capsys.readouterr().out
