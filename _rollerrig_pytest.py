"""rollerrig's pytest plugin: the fixtures rr_regression,
rr_history_regression, rr_creep_regression and the option --rr-regen
(rollerrig.testing; docs/testing.md).

Registered by the entry point pytest11 "rollerrig" (setup.cfg), so any
project with rollerrig installed has it without a conftest; `-p
no:rollerrig` turns it off.  It stands outside the rollerrig package on
purpose: pytest loads it before any conftest, and importing rollerrig then
would import it from the current folder when that is a rollerrig checkout
(python -m pytest puts the folder first on sys.path), whose rollerrig/ has
no compiled extension after a plain `pip install .` (tests/conftest.py
takes that folder off the path, but only later).  So nothing of rollerrig
is imported until a fixture is used.
"""
import pytest


def pytest_addoption(parser):
    group = parser.getgroup("rollerrig", "rollerrig's regression references")
    group.addoption("--rr-regen", action="store_true", default=False,
                    help="rewrite the references of rr_regression, rr_history_regression and "
                         "rr_creep_regression with this run's data (those checks then fail, "
                         "saying so)")


# a check that writes a reference lets the test go on, so that all its
# references are written in one run, and the test fails at its end.  That
# needs pluggy's new-style wrappers (pluggy >= 1.1, any pytest >= 8); with an
# older pluggy the hook is not defined and a check that writes fails at once
_WRITTEN = "_rollerrig_written"          # rollerrig.testing._fixtures.WRITTEN_ATTR


def _pluggy_version():
    import pluggy
    try:
        return tuple(int(p) for p in pluggy.__version__.split(".")[:2])
    except (AttributeError, ValueError):
        return (0, 0)


if _pluggy_version() >= (1, 1):
    @pytest.hookimpl(wrapper=True)
    def pytest_runtest_call(item):
        setattr(item, _WRITTEN, [])
        try:
            result = yield               # the test's own failure comes first
            written = getattr(item, _WRITTEN)
            if written:
                pytest.fail("\n".join(written), pytrace=False)
            return result
        finally:
            delattr(item, _WRITTEN)


def _make(kind, request, tmp_path):
    from rollerrig.testing import _fixtures
    return getattr(_fixtures, kind)(request, tmp_path, request.config.getoption("--rr-regen"))


@pytest.fixture
def rr_regression(request, tmp_path):
    """check(data, basename=None, *, units, x, rtol, atol, tolerances): any
    labelled array set {name: array} against its reference."""
    return _make("Regression", request, tmp_path)


@pytest.fixture
def rr_history_regression(request, tmp_path):
    """check(result, basename=None, *, fields, rtol, atol, tolerances): a
    rollerrig.simulate result's history against its reference."""
    return _make("HistoryRegression", request, tmp_path)


@pytest.fixture
def rr_creep_regression(request, tmp_path):
    """check(creepage, forces, basename=None, *, rtol, atol, tolerances):
    creep forces over their creepage axis against the reference."""
    return _make("CreepCurveRegression", request, tmp_path)
