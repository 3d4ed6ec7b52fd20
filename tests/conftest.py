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


import pytest  # noqa: E402


def pytest_configure(config):
    """The package's own warnings are errors.  Added here, after the path
    above is settled: as an ini line (pyproject.toml) pytest resolved the
    category while reading its configuration, before this file ran, and
    after a plain ``pip install .`` the source folder could not import it:
    the filter was dropped with a PytestConfigWarning and CI ran without it."""
    config.addinivalue_line("filterwarnings", "error::rollerrig.RollerRigWarning")


@pytest.fixture(scope="session", autouse=True)
def _fmu_core_cache(tmp_path_factory):
    """One compile of the C core for every FMU the tests build (test_fmu.py,
    the README's example): rollerrig.fmu.build_fmu's $ROLLERRIG_FMU_CACHE."""
    if "ROLLERRIG_FMU_CACHE" in os.environ:
        yield
        return
    os.environ["ROLLERRIG_FMU_CACHE"] = str(tmp_path_factory.mktemp("fmu-core"))
    try:
        yield
    finally:
        os.environ.pop("ROLLERRIG_FMU_CACHE", None)


def pytest_collection_modifyitems(items):
    """The randomized property suites (tests/test_properties_*.py) are slow:
    hundreds of generated cases each; the inner loop leaves them out."""
    for item in items:
        if item.path.name.startswith("test_properties_"):
            item.add_marker(pytest.mark.slow)
