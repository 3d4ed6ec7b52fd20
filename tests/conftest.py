"""Test configuration.

``python -m pytest`` puts the repository root first on ``sys.path``, where the
source folder ``rollerrig/`` would shadow the installed package; after a plain
``pip install .`` that folder has no compiled ``_core``.  Drop the root from
the path unless an in-place build (``pip install -e .``) put ``_core`` there.
"""
import glob
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "tests", "data")

_BUILT = ("_core*.so", "_core*.pyd")
if not any(glob.glob(os.path.join(ROOT, "rollerrig", pattern)) for pattern in _BUILT):
    sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != ROOT]
