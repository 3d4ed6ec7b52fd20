"""Property-based test of the command line (issue 22): rollerrig.cli.main
driven with generated arguments, output paths (new, regular, a folder, a
FIFO, a symbolic link, a device, a file as the folder, missing folders) and
scenario files (valid, out of range, extreme, unknown keys, not TOML, not a
file), each in a fresh temporary folder.

It holds: the exit status is 0, 1 or 2; no traceback; on 2 one message whose
line names the option or a path the command was given (a scenario's several
problems follow it, indented: one message listing every problem) and nothing
written at all; nothing is ever written outside the outputs the command was
given (--out's files, OUT.fmu, OUT.c and --npz), and no temporary is left.

Kept fast: runs of at most 0.2 s; no FMU is compiled ($CC points nowhere:
an FMU that passes every check stops at the compiler); the exact table's
build (40 CPU minutes) is replaced by a small table, so what is tested is the
command's handling of its arguments and files.  A writer that opened a
FIFO (the defect's kind) would block: the suite's watchdog ends such a run.

Run:  python -m pytest tests/test_properties_cli.py     (profile "ci")
      HYPOTHESIS_PROFILE=long python -m pytest tests/test_properties_cli.py
"""
import contextlib
import io
import json
import math
import os
import re
import stat
import tempfile

import numpy as np
import pytest
from hypothesis import event, example, given, strategies as st

from _properties import examples, watchdog
from rollerrig import cli, rig
from rollerrig._binding import METHODS
from rollerrig.analysis.exact_table import ExactTable

assert watchdog  # the autouse hang detector, imported to take effect here

RIG_METHODS = [name for name, m in METHODS.items() if m.in_rig]
DEFAULTS = rig.default_parameters()
NAMES = [p.name for p in rig.PARAMETERS]          # what a scenario file may set


def mostly(good, bad, share=80):
    """`good` in `share` % of the draws, else `bad` (strategies or lists to
    sample); a failing case shrinks towards the good ones."""
    good, bad = (v if isinstance(v, st.SearchStrategy) else st.sampled_from(v)
                 for v in (good, bad))
    return st.integers(0, 99).flatmap(lambda i: good if i < share else bad)


# ------------------------------------------------------------------ scenario files


def _toml(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return "nan" if math.isnan(value) else ("inf" if value == math.inf else
                                                "-inf" if value == -math.inf else repr(value))
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    if isinstance(value, str):
        return json.dumps(value)
    return repr(value)


@st.composite
def values(draw, name):
    """A value for parameter `name`: its default, a nearby one, an extreme or
    a wrong type."""
    section, key = name.split(".")
    d = DEFAULTS[section][key]
    wrong = st.sampled_from([1e300, -1.0, 0.0, 1e-300, math.nan, math.inf, "text", True,
                             [1.0, "a"], 10 ** 30])
    if isinstance(d, bool) or isinstance(d, str):
        p = next(p for p in rig.PARAMETERS if p.name == name)
        good = st.sampled_from(list(p.choices) or [d]) if isinstance(d, str) else st.booleans()
    elif isinstance(d, (list, tuple)):
        good = st.lists(st.floats(0.0, 0.9), min_size=0, max_size=4)
    elif isinstance(d, int):
        good = st.integers(max(1, d // 2), max(2, 2 * d))
    else:
        good = st.floats(0.5, 2.0).map(lambda f: d * f)
    return draw(mostly(st.one_of(st.just(d), good), wrong, share=85))


@st.composite
def scenarios(draw):
    """(kind, text) of a --scenario: none, a TOML file of a few changes
    (maybe an unknown key), text that is not TOML, a missing path, a folder,
    a FIFO."""
    kind = draw(mostly(["none", "toml"], ["garbage", "missing", "folder", "fifo"]))
    if kind == "garbage":
        return kind, draw(st.sampled_from([b"[wheelset\nmass_kg = ", b"\xff\xfe", b"a = [[[",
                                           b"[scenario]\nmu0 = 1\nmu0 = 2\n"]))
    if kind != "toml":
        return kind, None
    changes = draw(st.lists(st.sampled_from(NAMES + ["wheelset.no_such_key",
                                                     "no_section.key"]),
                            max_size=3, unique=True))
    sections = {}
    for name in changes:
        section, key = name.split(".")
        value = draw(values(name)) if name in NAMES else 1.0
        sections.setdefault(section, []).append(f"{key} = {_toml(value)}")
    return kind, "".join(f"[{s}]\n" + "\n".join(lines) + "\n"
                         for s, lines in sections.items()).encode()


# ------------------------------------------------------------------ paths

def _make(root, kind, name, suffix):
    """The path of that kind in root (made there); its text as given."""
    path = os.path.join(root, name + suffix)
    if kind == "regular":
        with open(path, "w") as fh:
            fh.write("old")
    elif kind == "folder":
        os.mkdir(path)
    elif kind == "fifo":
        os.mkfifo(path)
    elif kind == "symlink":
        os.symlink(os.path.join(root, "victim"), path)
    elif kind == "device":
        try:        # a /dev/null of our own, in the temporary folder
            os.mknod(path, stat.S_IFCHR | 0o666, os.makedev(1, 3))
        except (PermissionError, AttributeError):
            os.mkfifo(path)
    elif kind == "file_parent":
        path = os.path.join(root, "victim", name + suffix)
    elif kind == "missing_folder":
        path = os.path.join(root, "no", "such", name + suffix)
    elif kind == "no_suffix":
        path = os.path.join(root, name + ".txt")
    return path


def _snapshot(root):
    """Every path under root: (type, inode, and for what is not a folder its
    size and mtime), links not followed.  A folder's own times change when
    a file is made and removed in it (check_output's probe): its entries
    are what counts."""
    seen = {}
    for folder, dirs, files in os.walk(root):
        for name in dirs + files:
            path = os.path.join(folder, name)
            s = os.lstat(path)
            kind = stat.S_IFMT(s.st_mode)
            seen[os.path.relpath(path, root)] = (kind, s.st_ino) + (
                () if kind == stat.S_IFDIR else (s.st_size, s.st_mtime_ns))
    return seen


# ------------------------------------------------------------------ commands

def _opt(name, good, bad):
    """An option left out or given a good value (mostly), or given a bad one."""
    return mostly([None] + good, bad).map(lambda v: [] if v is None else [name, v])


simulate_args = st.fixed_dictionaries(dict(
    duration=mostly(["0.02", "0.1", "0.2"],
                    ["-1", "0", "nan", "inf", "1e9", "abc", "", "0.001", "1e-300"]
                    ).map(lambda v: ["--duration", v]),
    dt=_opt("--dt", ["0.004", "0.002", "0.01"], ["0", "-0.004", "0.2", "nan", "x", "1e-7"]),
    method=_opt("--method", RIG_METHODS, ["exact", "linear", "bogus", ""]),
    record=_opt("--record-every", ["1", "3"], ["0", "-2", "x", "100000"]),
    out=mostly(["new", "nested", "existing"],
               ["a_file", "file_parent", "history_folder", "force_symlink", "creepage_fifo",
                "device_file", "dev_null", "empty"]),
))

GOOD_PATHS = ["new", "regular"]
BAD_PATHS = ["folder", "fifo", "symlink", "device", "file_parent", "missing_folder",
             "no_suffix"]

fmu_args = st.fixed_dictionaries(dict(
    out=mostly(GOOD_PATHS, BAD_PATHS, share=50),
    fmi=_opt("--fmi", ["2", "3"], ["4", "x"]),
))

table_args = st.fixed_dictionaries(dict(
    out=mostly(GOOD_PATHS, BAD_PATHS, share=60),
    npz=mostly([None] + GOOD_PATHS, BAD_PATHS, share=60),
    nu=_opt("--nu", ["0.28", "0.3"], ["0.7", "-1", "nan", "x"]),
    shape=_opt("--shape", ["4,4,4,5"], ["3,4,4,5", "a", "4,4,4"]),
    nx=_opt("--nx", ["3"], ["0", "x", "511"]),
))

#: now and then an option no command has
unknown = mostly([[]], [["--bogus"], ["--bogus", "1"]], share=90)


def _simulate_argv(root, a):
    """simulate's argv and the paths it may write."""
    out = os.path.join(root, "out")
    kind = a["out"]
    if kind == "nested":
        out = os.path.join(root, "a", "b", "out")
    elif kind in ("existing", "history_folder", "force_symlink", "creepage_fifo",
                  "device_file"):
        os.mkdir(out)
        if kind == "existing":
            for name in ("rig_history.csv", "rig_force.png"):
                with open(os.path.join(out, name), "w") as fh:
                    fh.write("old")
        elif kind == "history_folder":
            os.mkdir(os.path.join(out, "rig_history.csv"))
        elif kind == "force_symlink":
            os.symlink(os.path.join(root, "victim"), os.path.join(out, "rig_force.png"))
        elif kind == "creepage_fifo":
            os.mkfifo(os.path.join(out, "rig_creepage.png"))
        else:
            _make(out, "device", "rig_force", ".png")
    elif kind == "a_file":
        out = os.path.join(root, "victim")
    elif kind == "file_parent":
        out = os.path.join(root, "victim", "out")
    elif kind == "dev_null":
        out = os.devnull             # refused as not a folder: nothing is ever written there
    elif kind == "empty":
        out = ""
    argv = ["--out", out, "--quiet"] + sum((a[k] for k in ("duration", "dt", "method",
                                                           "record")), [])
    return argv, {os.path.join(out, n) for n in ("rig_history.csv", "rig_creepage.png",
                                                 "rig_force.png")}


def _scenario_path(root, kind, text):
    path = os.path.join(root, "scenario.toml")
    if kind == "none":
        return None
    if kind in ("toml", "garbage"):
        with open(path, "wb") as fh:
            fh.write(text)
    elif kind == "folder":
        os.mkdir(path)
    elif kind == "fifo":
        os.mkfifo(path)
    return path


def _small_table(*args, **kwargs):
    return ExactTable((0.0,) * 4, (1.0,) * 4, np.zeros((4, 4, 4, 5, 3), np.float32),
                      0.28, 1.0, 3)


def _named(line, argv):
    """The message names an option or a path of argv (or, for an FMU that
    passed every check, the missing compiler)."""
    words = [w for w in argv if w.startswith("--") or os.sep in w] + ["$CC"]
    return any(w in line for w in words)


needs_fifo_and_symlink = pytest.mark.skipif(
    not hasattr(os, "mkfifo") or not hasattr(os, "symlink"),
    reason="needs FIFOs and symbolic links")


@needs_fifo_and_symlink
@examples(0.2, deadline=None)
@given(args=simulate_args, scenario=scenarios(), extra=unknown)
# two samples for the four default targets: refused, the message naming no
# option (it began "2 of the 4 targets"; now "--duration = 0.02 s at ...")
@example(args={"duration": ["--duration", "0.02"], "dt": ["--dt", "0.01"], "method": [],
               "record": [], "out": "new"}, scenario=("none", None), extra=[])
# a sample time both drives' speed loops are unstable at: "2 problems:", each
# line naming --dt (the long profile's find: the first line names none)
@example(args={"duration": ["--duration", "0.1"], "dt": ["--dt", "0.01"], "method": [],
               "record": [], "out": "new"}, scenario=("none", None), extra=[])
def test_simulate_exits_cleanly_and_writes_only_its_outputs(args, scenario, extra):
    def argv(root):
        argv, allowed = _simulate_argv(root, args)
        path = _scenario_path(root, *scenario)
        return argv + (["--scenario", path] if path else []) + extra, allowed
    _check("simulate", argv)


@needs_fifo_and_symlink
@examples(0.2, deadline=None)
@given(args=fmu_args, scenario=scenarios(), extra=unknown)
def test_fmu_exits_cleanly_and_writes_only_its_output(args, scenario, extra):
    def argv(root):
        out = _make(root, args["out"], "unit", ".fmu")
        path = _scenario_path(root, *scenario)
        return [out] + args["fmi"] + (["--scenario", path] if path else []) + extra, {out}
    _check("fmu", argv)


@needs_fifo_and_symlink
@examples(0.2, deadline=None)
@given(args=table_args, extra=unknown)
def test_exact_table_exits_cleanly_and_writes_only_its_outputs(args, extra):
    def argv(root):
        out = _make(root, args["out"], "table", ".c")
        argv, allowed = [out, "--quiet"], {out}
        if args["npz"] is not None:
            npz = _make(root, args["npz"], "copy", ".npz")
            argv += ["--npz", npz]
            allowed.add(npz)
        return argv + args["nu"] + args["shape"] + args["nx"] + extra, allowed
    _check("exact-table", argv)


def _check(name, make_argv):
    """Run `rollerrig <name>` in a fresh folder (argv and the outputs it may
    write from make_argv(folder)) and hold the properties of the module."""
    with tempfile.TemporaryDirectory() as root, pytest.MonkeyPatch.context() as mp:
        mp.chdir(root)                       # a relative default (rollerrig-out) stays here
        mp.setenv("CC", os.path.join(root, "no-such-cc"))
        mp.setattr("rollerrig.analysis.exact_table.build_exact_table", _small_table)
        with open(os.path.join(root, "victim"), "w") as fh:
            fh.write("precious")
        argv, allowed = make_argv(root)
        argv = [name] + argv
        before = _snapshot(root)
        stdout, stderr = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
            code = cli.main(argv)
        err = stderr.getvalue()
        after = _snapshot(root)

    event(f"exit {code}")
    assert code in (0, 1, 2), (argv, code)
    assert "Traceback" not in err, (argv, err)
    if code == 2:
        lines = err.splitlines()
        assert lines and lines[0].startswith("rollerrig"), (argv, err)
        assert all(line.startswith("  ") for line in lines[1:]), (argv, err)
        # one problem: its line names the option; several ("N problems:"):
        # each listed one does
        listed = lines[1:] if re.search(r"\d+ problems:$", lines[0]) else lines[:1]
        assert listed and all(_named(line, argv) for line in listed), (argv, err)
    # nothing written but the outputs given (and the folders leading to --out),
    # and nothing at all when the command was refused
    allowed_rel = {os.path.relpath(p, root) for p in allowed if p}
    changed = {p for p in set(before) | set(after) if before.get(p) != after.get(p)}
    assert code != 2 or not changed, (argv, changed, err)
    for path in changed:
        assert path in after, (argv, path, "removed")
        kind = stat.S_IFMT(after[path][0])
        if path in allowed_rel:              # an output: a regular file, new or replaced
            assert before.get(path, (stat.S_IFREG,))[0] == kind == stat.S_IFREG, (argv, path)
        else:                                # a folder leading to one (--out made)
            assert kind == stat.S_IFDIR, (argv, path, err)
            assert any(a.startswith(path + os.sep) for a in allowed_rel), (argv, path, err)
    assert not [p for p in after if os.path.basename(p).endswith(".tmp")], (argv, after)
    assert after["victim"] == before["victim"]
    if code == 0 and name == "exact-table":
        assert allowed_rel <= changed, (argv, err)
    assert stat.S_ISCHR(os.stat(os.devnull).st_mode)
