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


# ------------------------------------------------------------------ the output folder

def run_cli(capsys, *argv):
    code = cli.main(["simulate", "--quiet", *argv])
    out, err = capsys.readouterr()
    assert "Traceback" not in err
    return code, out, err


@pytest.mark.skipif(not os.path.isdir("/proc/self"), reason="needs Linux's /proc")
def test_an_output_folder_that_cannot_be_made_is_refused_before_the_run(capsys):
    code, out, err = run_cli(capsys, "--out", "/proc/x")
    assert code == 2
    assert err.strip() == ("rollerrig simulate: --out /proc/x: cannot create the folder: "
                           "No such file or directory")
    assert "simulated" not in out                  # nothing was run


def test_an_output_path_that_is_not_a_folder_is_refused(tmp_path, capsys):
    a_file = tmp_path / "a_file"
    a_file.write_text("x")
    for path, why in (("/dev/null", "not a directory"), (str(a_file), "not a directory"),
                      (str(a_file / "sub"), "cannot create the folder: Not a directory")):
        code, out, err = run_cli(capsys, "--out", path)
        assert code == 2 and err.strip() == f"rollerrig simulate: --out {path}: {why}", err
        assert "simulated" not in out
    assert a_file.read_text() == "x"


@pytest.mark.skipif(not hasattr(os, "symlink"), reason="no symlinks here")
def test_outputs_replace_planted_symlinks_instead_of_writing_through_them(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    out = tmp_path / "outdir"
    out.mkdir()
    victims = {}
    for name in ("rig_history.csv", "rig_creepage.png", "rig_force.png"):
        victim = tmp_path / f"victim-{name}.txt"
        victim.write_text("precious")
        os.symlink(victim, out / name)
        victims[name] = victim
    code, text, err = run_cli(capsys, "--duration", "0.4", "--out", str(out))
    assert code == 0, err
    for name, victim in victims.items():
        assert victim.read_text() == "precious", name
        assert not os.path.islink(out / name) and os.path.getsize(out / name) > 100
    # no temporary file left behind, and the files are readable as usual
    assert sorted(os.listdir(out)) == sorted(victims)
    assert os.stat(out / "rig_history.csv").st_mode & 0o444 == 0o444 & ~_umask()


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


def test_record_every_and_a_short_run(tmp_path, capsys):
    code, out, err = run_cli(capsys, "--duration", "0.4", "--record-every", "4",
                             "--out", str(tmp_path))
    assert code == 0
    assert "one sample in 4 recorded" in out
    with open(tmp_path / "rig_history.csv") as fh:
        assert len(list(csv.reader(fh))) == 1 + 25
    code, out, err = run_cli(capsys, "--duration", "0.001", "--out", str(tmp_path))
    assert code == 2 and "duration = 0.001 s is shorter than one sample (dt = 0.004 s)" in err
    with pytest.raises(SystemExit):
        cli.main(["simulate", "--record-every", "0"])
    assert "--record-every: must be an integer >= 1, got '0'" in capsys.readouterr().err


def test_a_long_run_is_refused_with_the_record_every_that_fits(tmp_path, capsys):
    code, out, err = run_cli(capsys, "--duration", "1e5", "--out", str(tmp_path))
    assert code == 2
    assert "would take 5.4 GiB, over max_record_bytes = 1 GiB" in err
    assert "--record-every 6" in err


def test_a_closed_stdout_is_not_a_traceback(tmp_path):
    """rollerrig simulate | head -1: the reader goes away."""
    import subprocess
    from _child import start_python
    proc = start_python(["-m", "rollerrig", "simulate", "--quiet",
                         "--duration", "0.4", "--out", str(tmp_path)],
                        stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    proc.stdout.close()                           # before the program prints
    err = proc.stderr.read().decode()
    proc.wait(timeout=120)
    assert "Traceback" not in err and "cannot write" not in err, err
