"""Every file writer keeps one rule (rollerrig/_files.py, issue 22): it writes
to a regular file or a new path only, never through a symbolic link, never
over a directory, a device, a FIFO or a socket; a refusal names the caller's
path (not a hidden temporary) and comes before the work; nothing is left
beside the path."""
import errno
import os
import stat

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import fmu
from rollerrig._files import OutputPathError, check_output, write_file
from rollerrig.analysis.exact_table import ExactTable
from rollerrig.geometry.profiles import Profile

needs_symlink = pytest.mark.skipif(not hasattr(os, "symlink"), reason="no symlinks here")
needs_fifo = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")

TABLE = ExactTable((0.0,) * 4, (1.0,) * 4, np.zeros((4, 4, 4, 5, 3), np.float32), 0.28, 1.0, 3)


@pytest.fixture(scope="module")
def result():
    return rr.simulate(duration=0.04, targets=[0.02], target_times=[0.0])


def _figures(res, path):
    """plot_run's figure of that name (it writes <prefix>_creepage.png too)."""
    plt = pytest.importorskip("matplotlib.pyplot")
    from rollerrig.plot import plot_run
    folder, name = os.path.split(path)
    try:
        return plot_run(res, folder, prefix=name[:-len("_force.png")])
    finally:
        plt.close("all")


#: name: (file name it writes, the call, the words that start its refusal)
WRITERS = {
    "to_csv": ("h.csv", lambda res, p: res.to_csv(p), "RigResult.to_csv: path"),
    "plot_run": ("rig_force.png", _figures, "plot_run:"),
    "ExactTable.save": ("t.npz", lambda res, p: TABLE.save(p), "ExactTable.save: path"),
    "ExactTable.write_c": ("t.c", lambda res, p: TABLE.write_c(p), "ExactTable.write_c: path"),
    "Profile.write_text": ("w.txt", lambda res, p: Profile.s1002().write_text(p),
                           "Profile.write_text: path"),
    "write_defaults": ("d.toml", lambda res, p: rr.rig.write_defaults(p),
                       "write_defaults: path"),
    # CC is missing in these tests: an FMU the checks let through stops before compiling
    "build_fmu": ("u.fmu", lambda res, p: fmu.build_fmu(p), "rollerrig fmu:"),
}


@pytest.fixture
def no_compiler(tmp_path, monkeypatch):
    monkeypatch.setenv("CC", str(tmp_path / "no-such-cc"))


def _plant(kind, path, victim):
    if kind == "symlink":
        os.symlink(victim, path)
    elif kind == "fifo":
        os.mkfifo(path)
    elif kind == "directory":
        os.mkdir(path)
    elif kind == "device":
        try:
            os.mknod(path, stat.S_IFCHR | 0o666, os.makedev(1, 3))   # a /dev/null of our own
        except (PermissionError, AttributeError):
            pytest.skip("cannot make a device node here (not root)")
    return {"symlink": "is a symbolic link; a file is written only to a regular file or a new "
                       "path, never through a link",
            "fifo": "is a FIFO, not a regular file; give a regular file or a new path",
            "directory": "is a directory; give the name of a file in it",
            "device": "is a character device, not a regular file; give a regular file or a "
                      "new path"}[kind]


@needs_symlink
@needs_fifo
@pytest.mark.parametrize("kind", ["symlink", "fifo", "directory", "device"])
@pytest.mark.parametrize("writer", list(WRITERS))
def test_every_writer_refuses_what_is_not_a_regular_file(writer, kind, result, tmp_path,
                                                         no_compiler):
    name, call, what = WRITERS[writer]
    victim = tmp_path / "victim.txt"
    victim.write_text("precious")
    out = tmp_path / "out"
    out.mkdir()
    path = out / name
    why = _plant(kind, path, victim)
    before = os.lstat(path)
    with pytest.raises(OutputPathError) as info:
        call(result, str(path))
    assert str(info.value) == f"{what} {path}: {why}"
    assert info.value.path == str(path) and info.value.reason == why
    after = os.lstat(path)                              # untouched, nothing beside it
    assert (after.st_mode, after.st_ino) == (before.st_mode, before.st_ino)
    assert os.listdir(out) == [name] and victim.read_text() == "precious"


@pytest.mark.parametrize("writer", list(WRITERS))
def test_every_writer_names_a_missing_or_false_folder(writer, result, tmp_path, no_compiler):
    name, call, what = WRITERS[writer]
    a_file = tmp_path / "a_file"
    a_file.write_text("x")
    cases = [(a_file / name, f"{a_file} is not a directory"),
             (a_file / "sub" / name, f"{a_file / 'sub'} is not a directory"),
             (tmp_path / "missing" / name, f"the folder {tmp_path / 'missing'} does not exist")]
    if writer == "plot_run":                    # it makes its folder (outdir), as documented
        what = "plot_run: outdir"
        cases = [(a_file / name, "not a directory"),
                 (a_file / "sub" / name, "cannot create the folder: Not a directory")]
    for path, why in cases:
        with pytest.raises(OutputPathError) as info:
            call(result, str(path))
        named = os.path.dirname(path) if writer == "plot_run" else path
        assert str(info.value) == f"{what} {named}: {why}"
    assert sorted(os.listdir(tmp_path)) == ["a_file"] and a_file.read_text() == "x"


@pytest.mark.skipif(not os.path.isdir("/proc/self"), reason="needs Linux's /proc")
@pytest.mark.parametrize("writer", ["to_csv", "ExactTable.write_c", "Profile.write_text",
                                    "build_fmu"])
def test_a_folder_that_takes_no_file_is_refused(writer, result, no_compiler):
    name, call, what = WRITERS[writer]
    with pytest.raises(OutputPathError, match=rf"^{what} /proc/{name}: cannot write in the "
                                              rf"folder /proc: "):
        call(result, f"/proc/{name}")


def test_the_suffix_is_required_where_a_format_has_one(tmp_path, no_compiler):
    """numpy's savez would append .npz to another name (a file beside the
    one asked for); an FMU is named .fmu (issue 22: `fmu rig.txt`)."""
    for call, path, what, suffix in (
            (TABLE.save, tmp_path / "t", "ExactTable.save: path", ".npz"),
            (TABLE.write_c, tmp_path / "t.h", "ExactTable.write_c: path", ".c"),
            (fmu.build_fmu, tmp_path / "rig.txt", "rollerrig fmu:", ".fmu")):
        with pytest.raises(OutputPathError) as info:
            call(path)
        assert str(info.value) == f"{what} {path}: the file name must end in {suffix}"
    assert os.listdir(tmp_path) == []
    TABLE.save(tmp_path / "T.NPZ")                     # the case of the suffix is free
    assert ExactTable.load(tmp_path / "T.NPZ").shape == TABLE.shape


@pytest.mark.parametrize("writer", list(WRITERS))
def test_every_writer_writes_a_new_path_and_replaces_a_regular_file(writer, result, tmp_path,
                                                                    no_compiler):
    name, call, what = WRITERS[writer]
    if writer == "build_fmu":
        with pytest.raises(fmu.FmuBuildError, match="the C compiler"):    # past the checks
            call(result, str(tmp_path / name))
        assert os.listdir(tmp_path) == []
        return
    for _ in range(2):                                  # new, then over the regular file
        call(result, str(tmp_path / name))
        assert os.path.getsize(tmp_path / name) > 100
        assert not [f for f in os.listdir(tmp_path) if f.startswith(".")], "a temporary left"


def test_the_fmu_scenario_is_checked_as_simulate_checks_it(tmp_path, no_compiler):
    """A scenario the rig cannot start from is refused before the compile,
    as simulate refuses it (issue 22: mass_kg = 1e300, mu0 = 1e100)."""
    for section, key, value in (("wheelset", "mass_kg", 1e300), ("scenario", "mu0", 1e100)):
        scenario = tmp_path / f"{key}.toml"
        scenario.write_text(f"[{section}]\n{key} = {value!r}\n")
        with pytest.raises(rr.RollerRigError) as sim:
            rr.simulate(params=str(scenario), duration=0.04, targets=[0.02], target_times=[0.0])
        assert f"{section}.{key} = {value!r}" in str(sim.value)
        with pytest.raises(rr.RollerRigError) as built:
            fmu.build_fmu(tmp_path / "x.fmu", scenario=str(scenario))
        assert str(built.value).startswith(f"rollerrig fmu: scenario {scenario}: the rig "
                                           f"cannot start with params {section}.{key} = ")
        with pytest.raises(rr.RollerRigError, match=rf"rollerrig fmu: scenario: the rig cannot "
                                                    rf"start with params {section}\.{key}"):
            fmu.build_fmu(tmp_path / "x.fmu", scenario={section: {key: value}})
    assert not (tmp_path / "x.fmu").exists()


# ------------------------------------------------------------------ write_file itself

@needs_symlink
@needs_fifo
@pytest.mark.parametrize("kind", ["symlink", "fifo", "directory"])
def test_what_is_planted_while_writing_is_not_replaced(kind, tmp_path):
    """The check is made again after the writing, before the rename: a link,
    FIFO or folder put at the path meanwhile is refused, named, kept."""
    path, victim = tmp_path / "f.csv", tmp_path / "victim.txt"
    victim.write_text("precious")

    def write(fh):
        fh.write("data")
        _plant(kind, path, victim)
    with pytest.raises(OutputPathError, match=f"^w {path}: is a "):
        write_file(path, write, what="w")
    assert sorted(os.listdir(tmp_path)) == ["f.csv", "victim.txt"]
    assert victim.read_text() == "precious" and not stat.S_ISREG(os.lstat(path).st_mode)


def test_a_failed_write_names_the_path_and_leaves_no_temporary(tmp_path):
    path = tmp_path / "f.csv"
    path.write_text("old")

    def write(fh):
        fh.write("part")
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    with pytest.raises(OSError) as info:
        write_file(path, write, what="w")
    assert info.value.errno == errno.ENOSPC and info.value.filename == str(path)
    assert os.listdir(tmp_path) == ["f.csv"] and path.read_text() == "old"


def test_paths_that_name_no_file(tmp_path):
    for path, why in (("", "'': an empty path"),
                      (f"{tmp_path}/", f"{tmp_path}/: not a file name"),
                      (f"{tmp_path}/..", f"{tmp_path}/..: not a file name"),
                      ("a\0b", "'a\\x00b': not a path (a NUL character)"),
                      (3.5, "3.5: not a path")):
        with pytest.raises(OutputPathError) as info:
            check_output(path, what="w")
        assert str(info.value) == f"w {why}"
    assert check_output(tmp_path / "new.txt", what="w") == str(tmp_path / "new.txt")
    assert os.listdir(tmp_path) == []                   # the probe is gone
