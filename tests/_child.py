"""Child interpreters for tests that must survive a crash, a hang or a signal.

A child started in the repository root would put that root first on its
``sys.path`` and import the source folder ``rollerrig/``, which after a plain
``pip install .`` has no compiled ``_core`` (conftest.py does the same for the
test run itself).  Children start in ``tests/`` instead: there the installed
package, or an editable install's in-place build, is what ``import rollerrig``
finds.
"""
import functools
import os
import signal
import subprocess
import sys

CWD = os.path.dirname(os.path.abspath(__file__))


def _setup(then=None):
    """In the child before exec: SIGINT to its default, so that Python turns
    it into KeyboardInterrupt even when the test run itself was started with
    SIGINT ignored (a background job of a non-interactive shell: Python
    then leaves it ignored); then the caller's own preexec_fn."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    if then is not None:
        then()


def _python(spawn, args, kwargs):
    kwargs["preexec_fn"] = functools.partial(_setup, kwargs.get("preexec_fn"))
    return spawn([sys.executable, *args], cwd=CWD, **kwargs)


def run_python(args, **kwargs):
    """subprocess.run of this interpreter with `args`, started in tests/."""
    return _python(subprocess.run, args, kwargs)


def start_python(args, **kwargs):
    """subprocess.Popen of this interpreter with `args`, started in tests/."""
    return _python(subprocess.Popen, args, kwargs)
