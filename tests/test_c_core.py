"""Run the standalone C core test suite (csrc/Makefile) from pytest.

These tests need the source tree (csrc/), `make` and a C compiler; they are
skipped when any of those is missing, e.g. when the installed package is
tested outside the repository.
"""
import os
import shlex
import shutil
import subprocess
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow     # make check, sanitize, valgrind: C builds

REPO = Path(__file__).resolve().parent.parent
CSRC = REPO / "csrc"
TIMEOUT = 1800  # seconds, per make invocation


def _compiler():
    """Command list for the C compiler make will use ($CC, default cc)."""
    cmd = shlex.split(os.environ.get("CC", "").strip() or "cc")
    return cmd if cmd and shutil.which(cmd[0]) else None


def _require_toolchain():
    if not (CSRC / "Makefile").is_file():
        pytest.skip(f"C sources not available ({CSRC / 'Makefile'} not found)")
    if shutil.which("make") is None:
        pytest.skip("`make` not found on PATH")
    if _compiler() is None:
        pytest.skip("no C compiler found ($CC or `cc`)")


def _make(target):
    jobs = str(os.cpu_count() or 1)
    proc = subprocess.run(
        ["make", "-C", str(CSRC), "-j", jobs, target],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        timeout=TIMEOUT,
    )
    print(proc.stdout)  # shown by pytest with -rP / -s
    assert proc.returncode == 0, (
        f"`make -C {CSRC} {target}` failed with exit status "
        f"{proc.returncode}; output:\n{proc.stdout}"
    )


@pytest.fixture(scope="module")
def sanitizers_usable(tmp_path_factory):
    """Skip unless the compiler can build and run an ASan/UBSan program."""
    _require_toolchain()
    tmp = tmp_path_factory.mktemp("sanprobe")
    src = tmp / "probe.c"
    exe = tmp / "probe"
    src.write_text(
        "#include <stdlib.h>\n"
        "int main(void) { char *p = malloc(4); p[0] = 0; free(p); return 0; }\n"
    )
    cmd = _compiler() + [
        "-fsanitize=address,undefined", "-fno-omit-frame-pointer",
        str(src), "-o", str(exe),
    ]
    try:
        link = subprocess.run(cmd, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True, timeout=120)
    except (OSError, subprocess.TimeoutExpired) as exc:
        pytest.skip(f"sanitizer probe compile failed: {exc}")
    if link.returncode != 0:
        pytest.skip("compiler cannot link -fsanitize=address,undefined:\n"
                    + link.stdout)
    try:
        run = subprocess.run([str(exe)], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True, timeout=120)
    except (OSError, subprocess.TimeoutExpired) as exc:
        pytest.skip(f"sanitized probe program cannot run here: {exc}")
    if run.returncode != 0:
        pytest.skip("sanitized probe program fails in this environment "
                    f"(exit status {run.returncode}):\n" + run.stdout)


def test_c_core_check():
    _require_toolchain()
    _make("check")


def test_c_core_sanitize(sanitizers_usable):
    _make("sanitize")


def test_fuzz_finds_stay_fixed(sanitizers_usable):
    """Every fuzz target, built with $CC under ASan and UBSan without
    libFuzzer, replays its seed corpus and every find kept in
    csrc/fuzz/regressions/ (make fuzz-replay): a bug the fuzzers found
    and that was fixed is checked on every run, not only when a fuzzer
    happens on it again."""
    _make("fuzz-replay")


def test_realtime_example_runs():
    """examples/rig_realtime.c builds against the C core alone and runs the
    paper's scenario in its fixed-rate loop (1 s at 4 ms; step times are
    printed, not asserted: the machine is shared)."""
    _require_toolchain()
    _make("example")
    proc = subprocess.run([str(CSRC / "build" / "rig_realtime"), "4", "1"],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          timeout=120)
    print(proc.stdout)
    assert proc.returncode == 0, proc.stdout
    assert "step time min" in proc.stdout and "p99" in proc.stdout
