"""The registry's claim: a new creep-force method is one C file plus one row.

A copy of the tracked tree gets csrc/contact/rr_scaled_linear.c ("scaled_linear":
Kalker's linear theory times an option `scale` in (0, 10], default 1) and one
row in csrc/contact/rr_methods.def; the copy is built, and a child interpreter
finds the method in rollerrig.METHODS, computes with it and has its bad options
refused by name, range and value.  Nothing else in the copy changes."""
import os
import shutil
import subprocess
import sys
import textwrap

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

METHOD_C = r'''
/* rr_scaled_linear.c - Kalker's linear theory times a factor (the registry's test). */
#include "util/rr_common.h"
#include "contact/rr_linear.h"

enum { SCALE = 0 };

static int scaled_forces(const rr_contact_problem *p, const rr_creep_opts *o,
                         double *work, rr_forces *out)
{
    int st;
    (void)work;
    if (!out)
        return RR_ERR_NULL;
    if ((st = rr_linear(p, out)) < 0)
        return st;
    out->fx *= o->v[SCALE];
    out->fy *= o->v[SCALE];
    out->mz *= o->v[SCALE];
    return rr_forces_checked(st, out);
}

static const rr_creep_option scaled_opts[] = {
    [SCALE] = {"scale", RR_OPT_REAL, "", 1.0, 0.0, 10.0, 1, 0, NULL, RR_ERR_PARAM,
               "factor on the linear theory's forces"},
};

const rr_method_desc rr_method_scaled_linear = {
    .name = "scaled_linear",
    .doc = "Kalker's linear theory times a factor",
    .nopts = RR_COUNTOF(scaled_opts),
    .opts = scaled_opts,
    .saturates = 0,
    .cost = rr_method_unit_cost,
    .slope_scale = rr_method_unit_slope,
    .workspace_len = rr_method_no_workspace,
    .forces = scaled_forces,
};
'''

CHILD = r'''
import os
import rollerrig as rr
assert rr.__file__.startswith(os.getcwd()), rr.__file__      # the copy's package
m = rr.METHODS["scaled_linear"]
op = m.options["scale"]
assert list(m.options) == ["scale"] and op.type == "real", m
assert (op.default, op.lo, op.hi, op.lo_open, op.hi_open) == (1.0, 0.0, 10.0, True, False), op
case = dict(a=6e-3, b=4e-3, N=1e4, mu=0.3)
lin = rr.creep_forces(1e-3, 2e-4, 0.1, method="linear", **case)
two = rr.creep_forces(1e-3, 2e-4, 0.1, method="scaled_linear", scale=2, **case)
assert (two.fx, two.fy, two.mz) == (2 * lin.fx, 2 * lin.fy, 2 * lin.mz), (lin, two)
assert rr.creep_forces(1e-3, method="scaled_linear", **case).fx == \
    rr.creep_forces(1e-3, method="linear", **case).fx
for bad, words in ((dict(scale=0), ("scale", "(0, 10]", "got 0")),
                   (dict(scale="x"), ("scale", "(0, 10]", "got 'x'")),
                   (dict(nx=20), ("scaled_linear", "nx", "'scale'", "got nx=20"))):
    try:
        rr.creep_forces(1e-3, method="scaled_linear", **case, **bad)
    except rr.RollerRigError as e:
        assert all(w in str(e) for w in words), (bad, str(e))
    else:
        raise AssertionError(f"{bad} accepted")
print("ok")
'''


def _git(*args, cwd):
    return subprocess.run(["git", *args], cwd=cwd, capture_output=True, text=True, check=True,
                          env=dict(os.environ, GIT_AUTHOR_NAME="t", GIT_AUTHOR_EMAIL="t@t",
                                   GIT_COMMITTER_NAME="t", GIT_COMMITTER_EMAIL="t@t")).stdout


@pytest.mark.slow    # builds the extension with a new method
def test_a_new_method_is_one_file_and_one_row(tmp_path):
    if shutil.which(os.environ.get("CC", "cc")) is None and shutil.which("gcc") is None:
        pytest.skip("no C compiler: the copy cannot be built")
    if shutil.which("git") is None or not os.path.isdir(os.path.join(ROOT, ".git")) and \
            not os.path.isfile(os.path.join(ROOT, ".git")):
        pytest.skip("not a git checkout: the tracked files are unknown")
    copy = tmp_path / "tree"
    for rel in _git("ls-files", "-z", cwd=ROOT).split("\0"):
        if rel and os.path.isfile(os.path.join(ROOT, rel)):
            (copy / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(os.path.join(ROOT, rel), copy / rel)
    _git("init", "-q", cwd=copy)
    _git("add", "-A", cwd=copy)
    _git("commit", "-q", "-m", "copy", cwd=copy)

    # the one file and the one row
    (copy / "csrc/contact/rr_scaled_linear.c").write_text(textwrap.dedent(METHOD_C))
    with open(copy / "csrc/contact/rr_methods.def", "a") as f:
        f.write("RR_METHOD(SCALED_LINEAR, rr_method_scaled_linear)\n")

    build = subprocess.run([sys.executable, "setup.py", "-q", "build_ext", "--inplace"],
                           cwd=copy, capture_output=True, text=True)
    assert build.returncode == 0, build.stdout + build.stderr
    env = dict(os.environ, PYTHONPATH=str(copy))
    child = subprocess.run([sys.executable, "-c", CHILD], cwd=copy, env=env,
                           capture_output=True, text=True)
    assert child.returncode == 0 and child.stdout.strip() == "ok", child.stdout + child.stderr

    # nothing else changed: contact.py, rig.py, _core_c/ ... untouched
    status = _git("status", "--porcelain", "--untracked-files=all", cwd=copy).splitlines()
    assert sorted(line[3:] for line in status) == ["csrc/contact/rr_methods.def",
                                                   "csrc/contact/rr_scaled_linear.c"], status
