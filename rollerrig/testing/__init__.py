"""Numeric regression tests for rollerrig's users: hold a simulate history,
a creep curve or any labelled array set against a stored reference.

With pytest (the plugin is registered on install; no conftest needed):

    def test_my_controller(rr_history_regression):
        res = rr.simulate(duration=5.0, controller=MyController())
        rr_history_regression.check(res, tolerances={"fx": {"atol": 1e-3}})

    def test_my_curve(rr_creep_regression):
        cx = np.linspace(0, 0.01, 50)
        rr_creep_regression.check(cx, rr.creep_forces(cx, 0, 0, a=a, b=b, N=N, mu=0.3))

The first run writes tests/<module>/<test>.npz (compared) and .csv (for a
person) and fails saying so; later runs compare; `pytest --rr-regen`
rewrites them.  Without pytest: assert_history_close,
assert_creep_curve_close, assert_fields_close.  docs/testing.md.

The fixtures' types (HistoryRegression, CreepCurveRegression, Regression),
for a test's annotations, are imported on first use: they need pytest,
the plain asserts do not.
"""
from typing import TYPE_CHECKING, Any

from ._assert import (CREEP_UNITS, RegressionError, assert_creep_curve_close,
                      assert_fields_close, assert_history_close, creep_curve_fields,
                      history_fields)
from ._compare import DEFAULT_ATOL, DEFAULT_RTOL, FieldDeviation
from ._store import read_reference, write_reference

__all__ = ["assert_history_close", "assert_creep_curve_close", "assert_fields_close",
           "RegressionError", "FieldDeviation", "history_fields", "creep_curve_fields",
           "read_reference", "write_reference", "DEFAULT_RTOL", "DEFAULT_ATOL", "CREEP_UNITS"]

_FIXTURE_TYPES = ("Regression", "HistoryRegression", "CreepCurveRegression")

if TYPE_CHECKING:
    from ._fixtures import CreepCurveRegression as CreepCurveRegression
    from ._fixtures import HistoryRegression as HistoryRegression
    from ._fixtures import Regression as Regression


def __getattr__(name: str) -> Any:
    if name in _FIXTURE_TYPES:
        from . import _fixtures
        return getattr(_fixtures, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
