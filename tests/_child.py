"""Child interpreters for tests that must survive a crash, a hang or a signal.

A child started in the repository root would put that root first on its
``sys.path`` and import the source folder ``rollerrig/``, which after a plain
``pip install .`` has no compiled ``_core`` (conftest.py does the same for the
test run itself).  Children start in ``tests/`` instead: there the installed
package, or an editable install's in-place build, is what ``import rollerrig``
finds.
"""
import os
import subprocess
import sys

CWD = os.path.dirname(os.path.abspath(__file__))


def run_python(args, **kwargs):
    """subprocess.run of this interpreter with `args`, started in tests/."""
    return subprocess.run([sys.executable, *args], cwd=CWD, **kwargs)


def start_python(args, **kwargs):
    """subprocess.Popen of this interpreter with `args`, started in tests/."""
    return subprocess.Popen([sys.executable, *args], cwd=CWD, **kwargs)
