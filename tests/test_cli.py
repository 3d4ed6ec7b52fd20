"""The command line: rollerrig simulate."""
import csv
import hashlib
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
        lines = fh.readlines()
    rows = list(csv.reader(line for line in lines if not line.startswith("#")))
    assert tuple(rows[0]) == rig.RECORD_FIELDS and len(rows) == 1 + 500
    # the header's record of the run: the scenario file, its hash, what it changed
    header = dict(line[2:].strip().split(": ", 1) for line in lines if line.startswith("#"))
    assert header["scenario"] == str(scenario)
    assert header["scenario_sha256"] == hashlib.sha256(scenario.read_bytes()).hexdigest()
    assert header["changed_from_defaults"] == (
        "scenario.duration_s = 2.0; scenario.mu0 = 0.35; scenario.target_start_s = [0.0]; "
        "scenario.targets = [0.03]")
    assert header["method"] == "fastsim" and header["units"].startswith("s,1,1,1,m/s,")


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
def test_planted_symlinks_are_refused_before_the_run(tmp_path, capsys):
    """A symbolic link at an output's name is neither written through nor
    replaced: the run is refused before it starts, naming the path."""
    pytest.importorskip("matplotlib")
    out = tmp_path / "outdir"
    out.mkdir()
    victim = tmp_path / "victim.txt"
    victim.write_text("precious")
    for name in ("rig_history.csv", "rig_creepage.png", "rig_force.png"):
        os.symlink(victim, out / name)
        code, text, err = run_cli(capsys, "--duration", "0.4", "--out", str(out))
        assert code == 2 and "simulated" not in text
        assert err == (f"rollerrig simulate: --out {out / name}: is a symbolic link; a file is "
                       f"written only to a regular file or a new path, never through a link\n")
        assert victim.read_text() == "precious" and os.listdir(out) == [name]
        os.remove(out / name)


def test_outputs_replace_regular_files_readable_as_usual(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    out = tmp_path / "outdir"
    out.mkdir()
    names = ("rig_history.csv", "rig_creepage.png", "rig_force.png")
    for name in names:
        (out / name).write_text("old")
    code, text, err = run_cli(capsys, "--duration", "0.4", "--out", str(out))
    assert code == 0, err
    for name in names:
        assert os.path.getsize(out / name) > 100, name
    # no temporary file left behind, and the files are readable as usual
    assert sorted(os.listdir(out)) == sorted(names)
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
        assert len([line for line in fh if not line.startswith("#")]) == 1 + 25
    code, out, err = run_cli(capsys, "--duration", "0.001", "--out", str(tmp_path))
    assert code == 2 and "duration = 0.001 s is shorter than one sample (scenario.control_sample_time_s = 0.004 s)" in err
    assert cli.main(["simulate", "--record-every", "0"]) == 2
    assert capsys.readouterr().err == ("rollerrig simulate: argument --record-every: must be "
                                       "an integer >= 1, got '0'\n")


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


# ------------------------------------------------------------------ issue 22: paths and errors

def one_line(err):
    """The single stderr line of a refusal (no usage block, no traceback)."""
    assert "Traceback" not in err and "usage:" not in err, err
    assert err.endswith("\n") and err.count("\n") == 1, err
    return err[:-1]


def test_an_output_file_that_is_a_directory_is_refused_before_the_run(tmp_path, capsys):
    """simulate --out outx, outx/rig_history.csv a folder: the run was made,
    then refused naming a hidden temporary."""
    (tmp_path / "rig_history.csv").mkdir()
    code, out, err = run_cli(capsys, "--duration", "0.4", "--out", str(tmp_path))
    assert code == 2 and "simulated" not in out
    assert one_line(err) == (f"rollerrig simulate: --out {tmp_path / 'rig_history.csv'}: is a "
                             f"directory; give the name of a file in it")
    assert os.listdir(tmp_path) == ["rig_history.csv"]


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_an_output_file_that_is_a_fifo_is_refused_before_the_run(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    os.mkfifo(tmp_path / "rig_force.png")
    code, out, err = run_cli(capsys, "--duration", "0.4", "--out", str(tmp_path))
    assert code == 2 and "simulated" not in out
    assert one_line(err) == (f"rollerrig simulate: --out {tmp_path / 'rig_force.png'}: is a "
                             f"FIFO, not a regular file; give a regular file or a new path")
    assert os.listdir(tmp_path) == ["rig_force.png"]


@pytest.mark.parametrize("argv, option", [
    (["--duration", "-1"], "--duration must be a finite number in (0, 100000] s, got -1.0"),
    (["--duration", "nan"], "--duration must be a finite number"),
    (["--duration", "0.001"], "--duration = 0.001 s is shorter than one sample"),
    (["--dt", "0"], "--dt must be a finite number in [1e-06, 0.1] s, got 0.0"),
    (["--dt", "inf"], "--dt must be a finite number"),
    (["--duration", "0.4", "--record-every", "1000"],
     "--record-every must be an integer from 1 to the number of samples (100), got 1000"),
])
def test_errors_after_parsing_name_the_option(argv, option, tmp_path, capsys):
    """... and bad input leaves nothing behind, not even the --out folder."""
    code, out, err = run_cli(capsys, *argv, "--out", str(tmp_path / "new" / "out"))
    assert code == 2 and "simulated" not in out
    assert one_line(err).startswith(f"rollerrig simulate: {option}"), err
    assert os.listdir(tmp_path) == []


def test_every_problem_of_a_list_names_the_option(tmp_path, capsys):
    """A sample time at which both drives' loops ring is two problems (the C
    report's "loop", one per drive); each line names --dt, not simulate's
    dt (only the message's first word was renamed)."""
    code, out, err = run_cli(capsys, "--dt", "0.01", "--out", str(tmp_path / "out"))
    lines = err.splitlines()
    assert code == 2 and lines[0] == "rollerrig simulate: 2 problems:", err
    assert [line[:40] for line in lines[1:]] == [
        "  --dt = 0.01 s: the roller drive's samp", "  --dt = 0.01 s: the wheelset drive's sa"]
    assert not (tmp_path / "out").exists()


def test_methods_offered_are_the_rigs_from_the_registry(capsys):
    """--method's help, its choices and its error list the methods of the
    registry the rig steps with (in_rig), and only those."""
    from rollerrig._binding import METHODS
    loop = [name for name, m in METHODS.items() if m.in_rig]
    assert "exact" in METHODS and "exact" not in loop and "exact_table" in loop
    assert "linear" in METHODS and "linear" not in loop
    action = next(a for a in cli.build_parser().commands["simulate"]._actions
                  if "--method" in a.option_strings)
    assert list(action.choices) == loop and ", ".join(loop) in action.help
    for method in loop:
        assert cli.build_parser().parse_args(["simulate", "--method", method]).method == method
    listed = ", ".join(map(repr, loop))
    for bad in ("exact", "linear", "bogus"):
        assert cli.main(["simulate", "--method", bad]) == 2
        assert one_line(capsys.readouterr().err) == (
            f"rollerrig simulate: argument --method: invalid choice: {bad!r} (choose from "
            f"{listed})")


@pytest.mark.parametrize("argv, message", [
    (["simulate", "--bogus"], "rollerrig simulate: unrecognized arguments: --bogus"),
    (["simulate", "--dt", "x"], "rollerrig simulate: argument --dt: invalid float value: 'x'"),
    (["fmu", "x.fmu", "--bogus", "1"], "rollerrig fmu: unrecognized arguments: --bogus 1"),
    (["fmu"], "rollerrig fmu: the following arguments are required: OUT.fmu"),
    (["exact-table", "t.c", "--shape", "3,4,4,5"],
     "rollerrig exact-table: argument --shape: four node counts >= 4 like 17,11,19,21, "
     "got '3,4,4,5'"),
    (["exact-table", "t.c", "--nx", "511"],
     "rollerrig exact-table: argument --nx: must be an integer from 1 to 510 (the finer grid "
     "of the pair, 2 nx, at most 1020), got '511'"),
    (["exact-table", "t.c", "--nu", "0.7"],
     "rollerrig exact-table: argument --nu: Poisson's ratio must be in [0, 0.5], got '0.7'"),
    (["--bogus"], "rollerrig: unrecognized arguments: --bogus"),
    (["bogus"], "rollerrig: argument COMMAND: invalid choice: 'bogus' (choose from "
                "'simulate', 'exact-table', 'fmu', 'stability')"),
])
def test_argument_errors_are_one_line_naming_the_option(argv, message, capsys):
    """No usage block; an unknown option after a command is named by that
    command, not the top-level parser."""
    assert cli.main(argv) == 2
    out, err = capsys.readouterr()
    assert one_line(err) == message and out == ""


# ------------------------------------------------------------------ rollerrig fmu

@pytest.fixture
def no_compiler(tmp_path, monkeypatch):
    """CC missing: an FMU the checks let through stops before any compile."""
    monkeypatch.setenv("CC", str(tmp_path / "no-such-cc"))


@pytest.mark.skipif(not hasattr(os, "mkfifo") or not hasattr(os, "symlink"),
                    reason="no FIFOs or symlinks here")
def test_fmu_writes_only_a_regular_file_or_a_new_path(tmp_path, capsys, no_compiler):
    """rollerrig fmu replaced a device, a FIFO, a symlink's target."""
    os.mkfifo(tmp_path / "fifo.fmu")
    os.mkfifo(tmp_path / "fifo")
    victim = tmp_path / "victim"
    victim.write_text("precious")
    os.symlink(victim, tmp_path / "link.fmu")
    (tmp_path / "afile").write_text("x")
    ok = " not a regular file; give a regular file or a new path"
    for path, why in (
            ("/dev/null", "is a character device," + ok),      # refused before any work
            (tmp_path / "fifo.fmu", "is a FIFO," + ok),
            (tmp_path / "fifo", "is a FIFO," + ok),
            (tmp_path / "link.fmu", "is a symbolic link; a file is written only to a "
                                    "regular file or a new path, never through a link"),
            (tmp_path, "is a directory; give the name of a file in it"),
            (tmp_path / "afile" / "x.fmu", f"{tmp_path / 'afile'} is not a directory"),
            (tmp_path / "no" / "x.fmu", f"the folder {tmp_path / 'no'} does not exist"),
            (tmp_path / "rig.txt", "the file name must end in .fmu")):
        assert cli.main(["fmu", str(path)]) == 2
        assert one_line(capsys.readouterr().err) == f"rollerrig fmu: {path}: {why}"
    assert sorted(os.listdir(tmp_path)) == ["afile", "fifo", "fifo.fmu", "link.fmu", "victim"]
    assert victim.read_text() == "precious"
    assert cli.main(["fmu", str(tmp_path / "x.fmu")]) == 2          # past every check
    assert "the C compiler $CC" in capsys.readouterr().err


@pytest.mark.parametrize("text, key", [("[wheelset]\nmass_kg = 1e300\n", "wheelset.mass_kg"),
                                       ("[scenario]\nmu0 = 1e100\n", "scenario.mu0")])
def test_fmu_refuses_a_scenario_simulate_refuses(text, key, tmp_path, capsys, no_compiler):
    """The same check of the scenario for both commands, before the compile."""
    scenario = tmp_path / "s.toml"
    scenario.write_text(text)
    for command, argv in (("simulate", ["--out", str(tmp_path / "o")]),
                          ("fmu", [str(tmp_path / "x.fmu")])):
        assert cli.main([command, *argv, "--scenario", str(scenario)]) == 2
        err = one_line(capsys.readouterr().err)
        assert err.startswith(f"rollerrig {command}: --scenario {scenario}: the rig cannot "
                              f"start with params {key} = "), err
    assert not (tmp_path / "x.fmu").exists()
    assert cli.main(["fmu", str(tmp_path / "x.fmu"), "--scenario", str(tmp_path / "no")]) == 2
    assert one_line(capsys.readouterr().err) == (f"rollerrig fmu: --scenario {tmp_path / 'no'}: "
                                                 f"cannot open it: No such file or directory")


# ------------------------------------------------------------------ rollerrig exact-table

@pytest.fixture
def no_build(monkeypatch):
    """The build of the table, which must not start (about 40 CPU minutes)."""
    def build(*args, **kwargs):
        raise AssertionError("the build started")
    monkeypatch.setattr("rollerrig.analysis.exact_table.build_exact_table", build)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_exact_table_checks_its_outputs_before_the_build(tmp_path, capsys, no_build):
    (tmp_path / "afile").write_text("x")
    os.mkfifo(tmp_path / "fifo.npz")
    good = str(tmp_path / "t.c")
    cases = [([str(tmp_path)], f"{tmp_path}: is a directory; give the name of a file in it"),
             ([str(tmp_path / "afile" / "out.c")],
              f"{tmp_path / 'afile' / 'out.c'}: {tmp_path / 'afile'} is not a directory"),
             ([str(tmp_path / "t.h")], f"{tmp_path / 't.h'}: the file name must end in .c"),
             ([good, "--npz", str(tmp_path / "fifo.npz")],
              f"--npz {tmp_path / 'fifo.npz'}: is a FIFO, not a regular file; give a regular "
              f"file or a new path"),
             ([good, "--npz", str(tmp_path / "t")],
              f"--npz {tmp_path / 't'}: the file name must end in .npz")]
    if os.path.isdir("/proc/self"):
        cases.append((["/proc/out.c"], "/proc/out.c: cannot write in the folder /proc: No such "
                                       "file or directory"))
    for argv, message in cases:
        assert cli.main(["exact-table", *argv, "--quiet"]) == 2
        assert one_line(capsys.readouterr().err) == f"rollerrig exact-table: {message}"
    assert sorted(os.listdir(tmp_path)) == ["afile", "fifo.npz"]


def _small_table():
    import numpy as np
    from rollerrig.analysis.exact_table import ExactTable
    return ExactTable((0.0,) * 4, (1.0,) * 4, np.zeros((4, 4, 4, 5, 3), np.float32), 0.28,
                      1.0, 3)


def _build_planting(plant):
    """A build that puts something at an output meanwhile."""
    def build(*args, **kwargs):
        plant()
        return _small_table()
    return build


def test_exact_table_writes_the_npz_first_and_names_a_path_taken_meanwhile(tmp_path, capsys,
                                                                          monkeypatch):
    """What is put at OUT during the build is not replaced; the .npz, written
    first, keeps the table."""
    from rollerrig.analysis.exact_table import ExactTable
    out, npz = tmp_path / "t.c", tmp_path / "t.npz"
    monkeypatch.setattr("rollerrig.analysis.exact_table.build_exact_table", _build_planting(out.mkdir))
    assert cli.main(["exact-table", str(out), "--npz", str(npz), "--quiet"]) == 2
    assert one_line(capsys.readouterr().err) == (f"rollerrig exact-table: {out}: is a "
                                                 f"directory; give the name of a file in it")
    assert ExactTable.load(npz).shape == (4, 4, 4, 5) and os.listdir(out) == []


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_exact_table_a_lost_npz_keeps_the_c_file(tmp_path, capsys, monkeypatch):
    out, npz = tmp_path / "t.c", tmp_path / "t.npz"
    monkeypatch.setattr("rollerrig.analysis.exact_table.build_exact_table",
                        _build_planting(lambda: os.mkfifo(npz)))
    assert cli.main(["exact-table", str(out), "--npz", str(npz), "--quiet"]) == 2
    assert one_line(capsys.readouterr().err) == (f"rollerrig exact-table: {npz}: is a FIFO, not "
                                                 f"a regular file; give a regular file or a new "
                                                 f"path")
    assert "const rr_exact_table rr_exact_table_builtin" in out.read_text()


def test_exact_table_an_unreachable_scheduler_is_one_line(tmp_path, capsys, no_build):
    pytest.importorskip("distributed")
    import dask
    with dask.config.set({"distributed.comm.timeouts.connect": "1s"}):
        for address, why in (("tcp://127.0.0.1:1", "Timed out trying to connect to "
                                                   "tcp://127.0.0.1:1 after 1 s"),
                             ("nonsense", "missing port number in address 'nonsense'")):
            assert cli.main(["exact-table", str(tmp_path / "t.c"), "--dask", address,
                             "--quiet"]) == 2
            assert one_line(capsys.readouterr().err) == (
                f"rollerrig exact-table: --dask {address}: cannot reach the scheduler: {why}")
    assert os.listdir(tmp_path) == []


def test_a_scenario_warning_is_one_line_said_once(tmp_path, capsys, monkeypatch):
    """A scenario whose duration_s is shorter than the default start times
    (scaled, with a warning): the warning is one line of the command, said
    once, not Python's warning format with its source line (it was printed
    raw from the scenario's check, before the run)."""
    scenario = tmp_path / "short.toml"
    scenario.write_text("[scenario]\nduration_s = 0.2\n")
    monkeypatch.setenv("CC", str(tmp_path / "no-compiler"))   # fmu: refused after the check
    for argv in (["simulate", "--quiet", "--scenario", str(scenario), "--out",
                  str(tmp_path / "out")],
                 ["fmu", str(tmp_path / "x.fmu"), "--scenario", str(scenario)]):
        code = cli.main(argv)
        err = capsys.readouterr().err
        lines = [line for line in err.splitlines() if "warning:" in line]
        assert len(lines) == 1, err
        assert lines[0].startswith(f"rollerrig {argv[0]}: warning: --scenario {scenario}: "
                                   f"the default target start times"), err
        assert "RollerRigWarning" not in err and ".py:" not in err, err
        assert code == (0 if argv[0] == "simulate" else 2)   # fmu: no compiler


def test_a_duration_from_the_scenario_is_named_so(tmp_path, capsys):
    """--dt 0.003 on the scenario's 20 s: the warning that the run takes
    20.001 s names scenario.duration_s, not an option the user never typed."""
    code, out, err = run_cli(capsys, "--dt", "0.003", "--duration", "0.2", "--out",
                             str(tmp_path))
    assert code == 0 and "warning: --duration = 0.2 s is not a whole number" in err, err
    scenario = tmp_path / "s.toml"
    scenario.write_text("[scenario]\nduration_s = 0.2\ntarget_start_s = [0.0, 0.05, 0.1, 0.15]\n")
    code, out, err = run_cli(capsys, "--dt", "0.003", "--scenario", str(scenario), "--out",
                             str(tmp_path))
    assert code == 0, err
    assert ("warning: scenario.duration_s = 0.2 s is not a whole number of samples of dt = "
            "0.003 s: the run takes 67 samples, 0.201 s") in err, err
