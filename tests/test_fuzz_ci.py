"""csrc/Makefile's fuzz-ci on a stand-in fuzzer (a shell script): which
failures fail the step, which run once more, and the summary at the end.

CI keeps only the last lines of its log, so fuzz-ci ends with each failure
in short; a run that failed without leaving an input, or whose only input
timed out but runs within the limit alone, is the machine's and runs once
more.  Needs make and bash, not clang: the stand-in is never built (make -o).
"""
import os
import shutil
import stat
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
CSRC = REPO / "csrc"

# FAKE_MODE picks the behaviour; FAKE_STATE/once marks a first run done.
# libFuzzer's calls: a run (dirs, -options, -artifact_prefix=D/), or a
# replay of files (the timeout's input).
FAKE = r"""#!/bin/bash
prefix=""; replay=0
for a in "$@"; do
  case "$a" in
    -artifact_prefix=*) prefix=${a#-artifact_prefix=} ;;
    -*) ;;
    *) [ -f "$a" ] && replay=1 ;;
  esac
done
first=1; [ -f "$FAKE_STATE/once" ] && first=0
if [ $replay = 1 ]; then
  [ "$FAKE_MODE" = timeout_stall ] && exit 0
  echo "==1== ERROR: libFuzzer: timeout after 11 seconds"; exit 70
fi
touch "$FAKE_STATE/once"
case "$FAKE_MODE" in
  noinput_once)
    if [ $first = 1 ]; then echo "==1==AddressSanitizer: Shadow memory range interleaves"; exit 1; fi ;;
  crash)
    printf 'AB' > "${prefix}crash-abc"
    echo "fuzz oracle: rr_thing: OK with h[0] = -1"; echo "fuzz input: n 4 h -1"; exit 1 ;;
  timeout_stall|timeout_real)
    if [ $first = 1 ] || [ "$FAKE_MODE" = timeout_real ]; then
      printf 'T' > "${prefix}timeout-abc"; echo "==1== ERROR: libFuzzer: timeout after 11 seconds"; exit 70
    fi ;;
esac
echo "#5 DONE cov: 1"; echo "stat::number_of_executed_units: 5"; exit 0
"""


@pytest.fixture
def fuzz_ci(tmp_path):
    if not (CSRC / "Makefile").is_file():
        pytest.skip("C sources not available")
    if shutil.which("make") is None or shutil.which("bash") is None:
        pytest.skip("make or bash not found")
    build = tmp_path / "build"
    exe = build / "fuzz" / "fuzz_fake"
    exe.parent.mkdir(parents=True)
    exe.write_text(FAKE)
    exe.chmod(exe.stat().st_mode | stat.S_IXUSR)
    state = tmp_path / "state"
    state.mkdir()

    def run(mode):
        env = dict(os.environ, FAKE_MODE=mode, FAKE_STATE=str(state))
        p = subprocess.run(["make", "-s", "-C", str(CSRC), "fuzz-ci", f"BUILD={build}",
                            "FUZZ_NAMES=fuzz_fake", "FUZZ_SECONDS=1", "-o", str(exe)],
                           env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True, timeout=120)
        return p.returncode, p.stdout
    return run


def test_a_find_fails_the_step_and_is_summarised_at_the_end(fuzz_ci):
    rc, out = fuzz_ci("crash")
    assert rc != 0
    tail = out[out.index("=== the failures in short"):]
    assert "--- fuzz_fake: fuzz oracle: rr_thing: OK with h[0] = -1" in tail
    assert "fuzz input: n 4 h -1" in tail
    assert "crash-abc (base64): QUI=" in tail          # b"AB"
    assert ": once more" not in out


def test_a_failure_without_an_input_runs_once_more(fuzz_ci):
    rc, out = fuzz_ci("noinput_once")
    assert rc == 0, out
    assert "fuzz_fake failed but left no input: once more" in out
    assert "--- PASS fuzz_fake" in out
    tail = out[out.index("=== the failures in short"):]
    assert "Shadow memory range interleaves" in tail and "(left no input: run once more)" in tail


def test_a_timeout_that_runs_alone_within_the_limit_runs_once_more(fuzz_ci):
    rc, out = fuzz_ci("timeout_stall")
    assert rc == 0, out
    assert "timed out on an input that ran within the limit alone: once more" in out
    assert "--- PASS fuzz_fake" in out


def test_a_timeout_that_reproduces_fails(fuzz_ci):
    rc, out = fuzz_ci("timeout_real")
    assert rc != 0
    assert ": once more" not in out
    tail = out[out.index("=== the failures in short"):]
    assert "timeout-abc (base64): VA==" in tail        # b"T"
