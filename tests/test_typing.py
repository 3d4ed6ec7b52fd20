"""The typed API: mypy --strict on the package, on the README's and the
guide's code as a user's script, and the precision of a few results.

The configuration is pyproject.toml's [tool.mypy]: strict over every module,
none exempted (only fmpy, which ships no types, is let off its missing
stubs).  mypy runs as a subprocess
from the checkout, so that it reads that configuration and the package's
sources (rollerrig/_core.pyi for the extension).
"""
import os
import re
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from conftest import ROOT

pytestmark = pytest.mark.slow     # mypy over the package: some 20-60 s cold

pytest.importorskip("mypy")

ERROR = re.compile(r":\d+: error: ")


def mypy(*args):
    """mypy --strict with the project's configuration, from the checkout;
    (exit status, output)."""
    r = subprocess.run([sys.executable, "-m", "mypy", "--config-file",
                        str(Path(ROOT) / "pyproject.toml"), "--strict", "--no-color-output",
                        "--no-error-summary", *args],
                       cwd=ROOT, capture_output=True, text=True, timeout=900)
    return r.returncode, r.stdout + r.stderr


def user_script(tmp_path, name, source):
    path = tmp_path / name
    path.write_text(source, encoding="utf-8")
    return str(path)


def test_package_is_strict_clean():
    status, out = mypy("rollerrig")
    assert status == 0 and not ERROR.search(out), out


def stubtest(*args):
    # run from a folder of its own, so that the import is of the installed
    # package (CI's `pip install .` leaves the checkout's folder without the
    # built extension), and mypy finds the stub beside that package
    import tempfile

    import rollerrig
    installed = Path(rollerrig.__file__).resolve().parent.parent
    env = dict(os.environ)
    if installed.name not in ("site-packages", "dist-packages"):
        env["MYPYPATH"] = str(installed)    # an editable install: mypy finds site-packages itself
    with tempfile.TemporaryDirectory() as here:
        r = subprocess.run([sys.executable, "-m", "mypy.stubtest", "rollerrig._core",
                            "--mypy-config-file", str(Path(ROOT) / "pyproject.toml"), *args],
                           cwd=here, capture_output=True, text=True, timeout=900, env=env)
    return r.returncode, r.stdout + r.stderr


def test_stub_matches_the_extension():
    # mypy.stubtest: every name of the built extension in rollerrig/_core.pyi
    # and no other, its classes final as at run time (the one deliberate
    # difference is in the allowlist, with its reason)
    status, out = stubtest("--allowlist", str(Path(ROOT) / "tests" / "stubtest_allowlist.txt"))
    assert status == 0, out


def test_stubtest_finds_a_difference():
    # the check can fail: without the allowlist its one entry is reported
    status, out = stubtest()
    assert status == 1 and "rollerrig._core.CreepOptions.__init__" in out, out


def test_bad_call_is_reported(tmp_path):
    # the check can fail: a wrong argument type and a wrong field are errors
    script = user_script(tmp_path, "bad.py", textwrap.dedent("""\
        import rollerrig as rr
        f = rr.creep_forces(1e-4, a=6e-3, b=4e-3, N=1e4, mu=0.3, method=3)
        f.fz
        rr.status_message("ok")
        """))
    status, out = mypy(script)
    errors = ERROR.findall(out)
    assert status == 1 and len(errors) == 3, out
    assert '"method"' in out and '"fz"' in out and '"status_message"' in out, out


def test_results_are_precise(tmp_path):
    # assert_type: an error unless the type is exactly this one (whatever
    # mypy's and numpy's spelling of it)
    script = user_script(tmp_path, "precise.py", textwrap.dedent("""\
        from typing import Dict, Mapping, Union
        import numpy as np
        import numpy.typing as npt
        from typing_extensions import assert_type
        import rollerrig as rr
        from rollerrig._binding import OptionInfo
        from rollerrig.analysis.closed_loop import ClosedLoopLinearization

        F64 = npt.NDArray[np.float64]
        f = rr.creep_forces(np.array([1e-4, 2e-4]), a=6e-3, b=4e-3, N=1e4, mu=0.3)
        assert_type(f, rr.CreepForces)
        assert_type(f.fx, Union[float, F64])
        assert_type(f.status, Union[int, npt.NDArray[np.int8]])
        assert_type(rr.hertz(1 / 0.45, 1 / 0.3, 1e4).p0, Union[float, F64])
        assert_type(rr.kalker_coefficients(0.8).c11, Union[float, F64])
        t = rr.fastsim_field(1e-4, a=6e-3, b=4e-3, N=1e4, mu=0.3)
        assert_type(t, rr.TractionField)
        assert_type(t.px, F64)
        assert_type(t.slip, npt.NDArray[np.bool_])
        assert_type(t.fx, float)
        assert_type(rr.status_message(-2), str)
        assert_type(rr.STATUS, Dict[int, str])
        assert_type(rr.METHODS["fastsim"].options, Mapping[str, OptionInfo])
        assert_type(rr.get_include(), str)
        assert_type(rr.FallingFriction(A=0.4, B=0.6).A, float)
        assert_type(rr.simulate(0.1), rr.RigResult)
        assert_type(rr.linearize(), rr.Linearization)
        assert_type(rr.linearize(closed_loop=True), ClosedLoopLinearization)
        assert_type(rr.stability([10.0, 20.0]), rr.Stability)
        assert_type(rr.hunting([30.0, 20.0]), rr.Hunting)
        assert_type(rr.critical_speed(lambda V: [[-V]], [1.0, 2.0]), float)
        # rig_contact's wheels by patch (its overloads), either where patch is a str
        from rollerrig.rig.contact import NonHertzWheel
        table = rr.build_rig()[2]
        c = rr.rig_contact(table, spin=10.0, roller_spin=10.0, N_left=1e3, N_right=1e3)
        assert_type(c, rr.RigContact[rr.WheelContact])
        nh = rr.rig_contact(table, spin=10.0, roller_spin=10.0, Fz_left=1e3, Fz_right=1e3,
                            patch="nonhertz")
        assert_type(nh.left, NonHertzWheel)
        patch: str = "hertz"
        either = rr.rig_contact(table, spin=10.0, roller_spin=10.0, N_left=1e3, N_right=1e3,
                                patch=patch)
        assert_type(either.left, Union[rr.WheelContact, NonHertzWheel])
        assert_type(either.left.force, F64)
        assert_type(rr.replay(rr.simulate(0.1)).right, rr.WheelContact)
        """))
    status, out = mypy(script)
    assert status == 0 and not ERROR.search(out), out


def _python_chains():
    """The README's ```python blocks and the guide's (test_readme's chains:
    each run in order in one namespace), one script each."""
    import test_readme
    return {name: "\n\n".join(f"# {b!r}\n{b.source}" for b in blocks)
            for name, blocks in test_readme.CHAINS.items()}


# The guide's code as a user's script: one namespace over its pages (no name
# reused for another type), its functions annotated, fmpy (no types) named in
# pyproject's overrides; rig_contact's overloads give its wheels' type by patch.
@pytest.mark.parametrize("chain", ["README", "guide"])
def test_documented_code_is_strict_clean(chain, tmp_path):
    script = user_script(tmp_path, f"{chain.lower()}_examples.py", _python_chains()[chain])
    status, out = mypy(script)
    assert status == 0 and not ERROR.search(out), out


def test_no_module_is_exempt_from_strict():
    # the package's bodies are all checked: an ignore_errors override (36
    # modules had one until issue 26's typing was done) would let a module's
    # errors pass this file's mypy run unseen
    try:
        import tomllib
    except ImportError:                 # Python < 3.11: the package's own dependency
        import tomli as tomllib
    with open(Path(ROOT) / "pyproject.toml", "rb") as f:
        mypy_config = tomllib.load(f)["tool"]["mypy"]
    assert mypy_config["strict"] is True
    exempt = [o["module"] for o in mypy_config.get("overrides", []) if o.get("ignore_errors")]
    assert exempt == [], exempt
