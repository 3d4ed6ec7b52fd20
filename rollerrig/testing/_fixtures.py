"""What the plugin's fixtures hand a test: a store of references beside
the test file, and check() for a labelled array set, a simulate history or
a creep curve.

A reference lives in a folder named as the test module, beside it (the
convention of pytest-regressions' datadir): tests/test_rig.py's
test_paper -> tests/test_rig/test_paper.npz and .csv.  check():
  - no reference yet: writes it, and the test FAILS at its end (after its
    other checks have written theirs), saying what it wrote.  A first
    run that passed would let a CI job whose reference was never committed
    pass on every fresh clone without checking anything; failing makes the
    writer look at the new file and commit it (pytest-regressions does the
    same);
  - a reference: compares; a failure names each differing field (first and
    worst deviation, values on both sides), and leaves this run's data and
    a comparison figure in the test's tmp_path, named in the message;
  - --rr-regen: rewrites the reference and the test fails at its end,
    saying so (so a run with the flag never passes for a check).
"""
from __future__ import annotations

import os
import re
from typing import Any, List, Mapping, Optional, Sequence, Set

import numpy.typing as npt
import pytest

from .._errors import RollerRigError
from . import _assert
from ._compare import DEFAULT_ATOL, DEFAULT_RTOL
from ._store import read_reference, write_reference

REGEN_OPTION = "--rr-regen"
#: the test item's list of references written in its run (the plugin's)
WRITTEN_ATTR = "_rollerrig_written"


class Regression:
    """The fixture rr_regression: check(data) holds any labelled array set
    ({name: array}) against its reference."""

    def __init__(self, request: pytest.FixtureRequest, tmp_path: "os.PathLike[str]",
                 regen: bool) -> None:
        self._request, self._tmp, self._regen = request, tmp_path, regen
        self._used: Set[str] = set()
        path = request.path
        self.folder = os.path.join(os.path.dirname(path), os.path.splitext(
            os.path.basename(path))[0])

    def reference_path(self, basename: Optional[str] = None) -> str:
        """The reference's path without its suffix (.npz, .csv)."""
        if basename is not None and (not isinstance(basename, str) or not basename.strip(".")
                                     or re.search(r"[/\\\0]", basename)):
            raise RollerRigError(f"basename must be a file name without a folder (it names the "
                             f"reference in {self.folder}), got {basename!r}")
        name = basename or re.sub(r"[^\w.-]+", "_", self._request.node.name).strip("_")
        return os.path.join(self.folder, name)

    def check(self, data: Mapping[str, npt.ArrayLike], basename: Optional[str] = None, *,
              units: Optional[Mapping[str, str]] = None, x: Optional[str] = None,
              rtol: float = DEFAULT_RTOL, atol: float = DEFAULT_ATOL,
              tolerances: Optional[Mapping[str, Mapping[str, float]]] = None) -> None:
        """Hold `data` ({name: array}) against the reference `basename`
        (default: the test's name); units {name: unit} and x (the abscissa
        field) for the files and the message; rtol, atol, tolerances as
        rollerrig.testing.assert_fields_close."""
        return self._check(data, basename, units or {}, x, rtol, atol, tolerances,
                           "rr_regression.check")

    def _check(self, data: object, basename: Optional[str], units: Mapping[str, str],
               x: Optional[str], rtol: float, atol: float,
               tolerances: Optional[Mapping[str, Mapping[str, float]]], func: str) -> None:
        from . import _compare
        fields = _compare.as_fields(func, "data", data)
        # the tolerances are checked before anything is written
        _compare.field_tolerances(func, list(fields), rtol, atol, tolerances)
        base = self.reference_path(basename)
        if base in self._used:
            raise RollerRigError(f"{func}: reference {os.path.basename(base)} is already checked "
                             f"in this test: give each check its own basename")
        self._used.add(base)
        rel = os.path.relpath(base, os.getcwd())
        stored = None if self._regen else read_reference(base)
        if stored is None:
            npz, csv_path = write_reference(base, fields, units, x)
            why = (f"{REGEN_OPTION}: rewrote the reference" if self._regen else
                   "no reference yet: wrote it")
            then = ("run without the flag to compare against it" if self._regen else
                    "look at it, commit both files; the next run compares against them")
            message = (f"{func}: {why} ({len(fields)} fields): {os.path.relpath(npz)} (for "
                       f"the comparison), {os.path.relpath(csv_path)} (to read); {then}")
            # the test goes on (its other checks write theirs too) and fails
            # at its end: the plugin's pytest_runtest_call (_rollerrig_pytest)
            written: Optional[List[str]] = getattr(self._request.node, WRITTEN_ATTR, None)
            if written is None:                    # the fixture used without the plugin
                pytest.fail(message, pytrace=False)
            written.append(message)
            return
        ref, record = stored
        units = {**record.get("units", {}), **units}
        name = os.path.basename(base)
        try:
            _assert.assert_fields_close(fields, ref, rtol=rtol, atol=atol, tolerances=tolerances,
                                        units=units, x=x if x in ref else record.get("x"),
                                        figure=os.path.join(self._tmp, name + ".png"),
                                        where=f"the reference {rel}.npz", func=func)
        except _assert.RegressionError as e:
            obtained = write_reference(os.path.join(self._tmp, name + ".obtained"),
                                       fields, units, x)[1]
            pytest.fail(f"{func}: {e}\nthis run's data: {obtained}\n"
                        f"if the change is intended, rerun with {REGEN_OPTION} to rewrite the "
                        f"reference", pytrace=False)


class HistoryRegression(Regression):
    """The fixture rr_history_regression: check(result) holds a simulate
    result's history (every record field, or `fields`) against its
    reference; a failure says at which time a field first departs."""

    # check takes each fixture's own data: not the base class's signature
    def check(self, result: Any, basename: Optional[str] = None, *,  # type: ignore[override]
              fields: Optional[Sequence[str]] = None, window: Optional[float] = None,
              rtol: float = DEFAULT_RTOL, atol: float = DEFAULT_ATOL,
              tolerances: Optional[Mapping[str, Mapping[str, float]]] = None) -> None:
        """window: compare the means over windows of this many seconds
        (rollerrig.testing.history_fields: robust where single samples are
        not, e.g. across machines)."""
        data, units = _assert.history_fields(result, fields, window)
        return self._check(data, basename, units, "time", rtol, atol, tolerances,
                           "rr_history_regression.check")


class CreepCurveRegression(Regression):
    """The fixture rr_creep_regression: check(creepage, forces) holds creep
    forces (a rollerrig.CreepForces or {"fx": ...}) over their creepage
    axis against the reference."""

    # check takes each fixture's own data: not the base class's signature
    def check(self, creepage: npt.ArrayLike, forces: Any,  # type: ignore[override]
              basename: Optional[str] = None, *, creepage_name: str = "creepage",
              rtol: float = DEFAULT_RTOL, atol: float = DEFAULT_ATOL,
              tolerances: Optional[Mapping[str, Mapping[str, float]]] = None) -> None:
        data, units = _assert.creep_curve_fields(creepage, forces, creepage_name)
        return self._check(data, basename, units, creepage_name, rtol, atol, tolerances,
                           "rr_creep_regression.check")
