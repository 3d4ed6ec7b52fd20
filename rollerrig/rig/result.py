"""The record of a rig run and RigResult, its time histories with the
run's schedule and parameters (summary, table, to_csv, to_xarray,
to_dataframe)."""
from __future__ import annotations

import json
import os
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from typing import Any, Dict, List, Mapping, Optional, Tuple, TypeVar, Union

from .. import _core
from .._typing import F64Array
from .._optional import require
from .._units import cf_unit


#: the per-sample record of the C rig (csrc/rig/rr_rig_params.c, in the order of
#: enum rr_rig_record_index): (name, unit, meaning); each sample is recorded at its end
RECORD = tuple((name, cf_unit(unit), meaning) for name, _, unit, meaning in _core.RIG_RECORD)
RECORD_FIELDS = tuple(name for name, _, _ in RECORD)
#: the unit of each record field, CF / UDUNITS ("1": dimensionless)
RECORD_UNITS = {name: unit for name, unit, _ in RECORD}
_RECORD_MEANING = {name: meaning for name, _, meaning in RECORD}
#: a file's path, returned as given (to_csv)
_Path = TypeVar("_Path", bound=Union[str, "os.PathLike[str]"])


@dataclass(repr=False)
class RigResult:
    """Time histories of a rig run, with its schedule and parameters.

    As :func:`simulate` returns it.  Each column of ``records`` is also an
    attribute: ``res.time`` [s], ``res.creepage`` [1], ``res.fx`` [N], ...
    (:data:`RECORD_FIELDS`, units in :data:`RECORD_UNITS`;
    ``res.sample_status`` as int8), and ``res.normal_load`` = left + right
    [N].

    Attributes
    ----------
    records : numpy.ndarray
        Float array (samples kept, len(RECORD_FIELDS)), one row per kept
        control sample, recorded at the sample's end.
    params : dict
        The merged parameters (nested dict of rig_default.toml).
    targets : tuple of float
        The creepage targets [1] (magnitudes, in the drive's sense).
    target_times : tuple of float
        Their start times [s].
    dt : float
        Control sample time [s].
    status : int
        The run's status (Notes).
    message : str
        "ok", "ok with warnings: ..." (how many samples), "not to be
        trusted: ..." (how many), or when and why the run stopped.
    wall : dict
        Wall-clock seconds: "setup" (parameters, contact table: a one-off,
        as the paper's offline database) and "run" (the stepping loop).
    record_every : int
        The records keep every record_every-th sample (1: all); the kept
        samples are k record_every dt apart.
    method : str
        The creep-force method of the run.
    samples : int
        Control samples stepped (default: len(records) * record_every).
    scenario : dict or None
        The scenario file the parameters were read from, if any:
        ``{"path": ..., "sha256": ...}`` (``simulate(params=path)`` and
        ``rollerrig simulate --scenario`` set it); None otherwise.

    See Also
    --------
    simulate : the run that makes it.
    replay : its kinematics through a contact model.

    Notes
    -----
    status: 0 the run finished; > 0 it finished but some samples warned
    (1: an inner iteration, e.g. the integrator's Newton iteration, ended
    above its tolerance; the samples' sample_status say which); -19
    (ERR_UNTRUSTED) it finished but more than one sample in 20 warned (20
    samples at least): its records are all there, not to be trusted; other
    < 0: it stopped at a sample whose state could not be computed (-1 NaN,
    -2 a normal load not positive: lift-off, -3 a wheel off its roller, -11
    a singular system, -18 a creep force beyond mu N;
    ``rollerrig.status_message(status)``), and the records end at the last
    good sample.
    """

    records: F64Array
    params: Dict[str, Dict[str, Any]]
    targets: Tuple[float, ...]
    target_times: Tuple[float, ...]
    dt: float
    status: int
    message: str
    wall: Optional[Dict[str, float]] = None
    record_every: int = 1
    method: Optional[str] = None
    samples: Optional[int] = None
    scenario: Optional[Dict[str, str]] = None

    def __getattr__(self, name: str) -> npt.NDArray[Any]:
        if name in RECORD_FIELDS:
            col = self.records[:, RECORD_FIELDS.index(name)]
            return col.astype(np.int8) if name == "sample_status" else col
        raise AttributeError(name)

    def __repr__(self) -> str:
        method = self.method or self.params.get("contact", {}).get("creep_method")
        return (f"RigResult(samples={self.samples_run}, duration={self.duration:g} s, "
                f"dt={self.dt:g} s, record_every={self.record_every}, method={method!r}, "
                f"status={self.status}, message={self.message!r})")

    @property
    def samples_run(self) -> int:
        """Control samples stepped."""
        return self.samples if self.samples is not None else len(self) * self.record_every

    @property
    def duration(self) -> float:
        """Simulated time [s]: samples stepped times dt."""
        return self.samples_run * self.dt

    @property
    def record_dt(self) -> float:
        """Time between two kept records [s]: record_every dt."""
        return self.record_every * self.dt

    @property
    def normal_load(self) -> npt.NDArray[Any]:
        """Sum of both wheels' normal loads [N]."""
        total: npt.NDArray[Any] = self.normal_load_left + self.normal_load_right
        return total

    def __len__(self) -> int:
        return int(self.records.shape[0])

    def metadata(self) -> Dict[str, str]:
        """The run's record, as to_csv's header, to_xarray's and
        to_dataframe's attrs carry it.

        Returns
        -------
        dict of str
            "rollerrig" (the library's version), "method", "scenario" (the
            file, or "none: the default parameters"), "scenario_sha256" (if
            a file), "changed_from_defaults" (the parameters that differ
            from rig_default.toml, "section.key = value; ..."), "targets",
            "target_times_s", "duration_s", "dt" [s], "record_every",
            "status", "message": all text.
        """
        from .._version import __version__
        from .params import default_parameters
        method = self.method or self.params.get("contact", {}).get("creep_method")
        scenario = self.scenario or {}
        meta = {"rollerrig": __version__, "method": str(method),
                "scenario": scenario.get("path", "none: the default parameters")}
        if "sha256" in scenario:
            meta["scenario_sha256"] = scenario["sha256"]
        changed = _changed(default_parameters(), self.params)
        meta["changed_from_defaults"] = "; ".join(
            f"{k} = {json.dumps(v, default=str)}" for k, v in changed) or "none"
        meta.update({"targets": json.dumps([float(x) for x in self.targets]),
                     "target_times_s": json.dumps([float(x) for x in self.target_times]),
                     "duration_s": repr(float(self.duration)),
                     "dt": repr(float(self.dt)), "record_every": str(int(self.record_every)),
                     "status": str(int(self.status)), "message": str(self.message)})
        return meta

    def to_dataframe(self) -> Any:
        """The records as a pandas DataFrame.

        Returns
        -------
        pandas.DataFrame
            One column per RECORD_FIELDS entry; ``DataFrame.attrs["units"]``
            {column: unit} (CF / UDUNITS, "1" dimensionless, as
            RECORD_UNITS), ``attrs["long_names"]`` their meanings and the
            run's :meth:`metadata` in the other attrs.

        Raises
        ------
        OptionalDependencyError
            pandas not installed (it needs the extra "sweep").

        Notes
        -----
        pandas keeps attrs through most operations, not all: copy them
        where it matters.
        """
        pd = require("pandas", "RigResult.to_dataframe", "sweep")
        frame = pd.DataFrame({name: getattr(self, name) for name in RECORD_FIELDS})
        frame.attrs.update(self.metadata())
        frame.attrs["units"] = dict(RECORD_UNITS)
        frame.attrs["long_names"] = dict(_RECORD_MEANING)
        return frame

    def to_xarray(self) -> Any:
        """The records as an xarray.Dataset.

        Returns
        -------
        xarray.Dataset
            Dimension "time" [s], one variable per record field with its
            unit (CF / UDUNITS) and meaning in attrs ("units",
            "long_name"); the Dataset's attrs hold the targets, their start
            times, the run's :meth:`metadata` (version, method, scenario
            file and hash, parameters changed from the defaults, dt,
            record_every, status, message) and the parameters (as JSON, key
            "params").

        Raises
        ------
        OptionalDependencyError
            xarray not installed (it needs the extra "sweep").
        """
        xr = require("xarray", "RigResult.to_xarray", "sweep")

        def attrs(name: str) -> Dict[str, str]:
            return {"units": RECORD_UNITS[name], "long_name": _RECORD_MEANING[name]}
        meta: Dict[str, Any] = self.metadata()
        del meta["targets"], meta["target_times_s"]           # as arrays below
        meta.update({"duration_s": float(self.duration), "dt": float(self.dt), "dt_units": "s",
                     "record_every": int(self.record_every),
                     "status": int(self.status)})
        return xr.Dataset(
            {name: ("time", getattr(self, name), attrs(name)) for name in RECORD_FIELDS[1:]},
            coords={"time": ("time", self.time, attrs("time"))},
            attrs={"targets": np.asarray(self.targets, dtype=float), "targets_units": "1",
                   "target_times": np.asarray(self.target_times, dtype=float),
                   "target_times_units": "s", **meta, "params": json.dumps(self.params)})

    def to_csv(self, path: _Path) -> _Path:
        """Write the records as CSV.

        The RECORD_FIELDS names, then '#' lines (the units, one per column,
        CF / UDUNITS; the run's :meth:`metadata`: version, method, scenario
        file and sha256, parameters changed from the defaults, ...), then
        one row per kept sample, each value the shortest text that reads
        back as the same double.  ``pandas.read_csv(path, comment="#")``,
        ``numpy.genfromtxt(path, delimiter=",", names=True)`` read it;
        rollerrig._csv.read_table gives the header too.

        Parameters
        ----------
        path : str or path-like
            A new path or a regular file, replaced whole (never a symbolic
            link, a device or a FIFO).

        Returns
        -------
        str or path-like
            The path.

        Raises
        ------
        RollerRigError
            A path that is not a new path or a regular file, naming it.
        """
        from .._csv import write_table
        from .._files import write_file
        meta = list(self.metadata().items())
        return write_file(path, lambda fh: write_table(fh, RECORD_FIELDS, self.records.tolist(),
                                                        RECORD_UNITS, meta),
                          what="RigResult.to_csv: path")

    def summary(self, tol: float = 0.05, window: float = 0.25) -> List[Dict[str, Any]]:
        """Per target, how the creepage controller held it.

        Parameters
        ----------
        tol : float, optional
            Settling tolerance, relative to the target [-].
        window : float, optional
            Length of the creepage's running mean [s].

        Returns
        -------
        list of dict
            Per target: "target"; "reached", the creepage held (mean over
            the last 80 % of its interval) [1]; "settling_s", the settling
            time [s] (when the creepage's running mean over `window`
            seconds first comes within tol of the target; eq. 14's
            recovery steps then make a small sawtooth about it; NaN if it
            never does); "adhesion", the adhesion coefficient held [1];
            "peak_force_over_muN", the peak ``|fx| / (mu0 N)`` over the
            interval.

        See Also
        --------
        table : the same as aligned text, with the reasons for NaN.

        Notes
        -----
        The creepage is taken in the drive's sense (braking cx, traction
        -cx).  Windows are in seconds, so decimated records (record_every >
        1) give the same rows to within their spacing.  NaN where an
        interval holds fewer records than the window (:meth:`table` says
        so, and why).
        """
        return [row for row, _ in self._summary(tol, window)]

    def _summary(self, tol: float, window: float) -> List[Tuple[Dict[str, Any], str]]:
        """summary()'s rows, each with the reason its numbers are NaN ("" if
        none is)."""
        mu0 = self.params["scenario"]["mu0"]
        sense = -1.0 if self.params["scenario"].get("drive_mode") == "traction" else 1.0
        rows: List[Tuple[Dict[str, Any], str]] = []
        t = self.time
        creepage = sense * self.creepage
        ends = list(self.target_times[1:]) + [np.inf]
        k = max(1, int(round(window / self.record_dt)))
        for xi, t0, t1 in zip(self.targets, self.target_times, ends):
            sel = (t > t0) & (t <= t1) & np.isfinite(creepage)
            if np.count_nonzero(sel) < k:
                held = min(t1, self.duration) - t0
                why = (f"the run stopped at t = {self.duration:.4g} s, before it"
                       if self.status < 0 and held <= 0 else
                       f"too short to judge: its interval holds {max(held, 0.0):.3g} s of "
                       f"records, the running mean takes {window:g} s")
                rows.append((dict(target=xi, reached=np.nan, settling_s=np.nan,
                                  adhesion=np.nan, peak_force_over_muN=np.nan), why))
                continue
            ts, cr = t[sel], creepage[sel]
            held = ts >= ts[0] + 0.2 * (ts[-1] - ts[0])
            mean = np.convolve(cr, np.ones(k) / k, mode="valid")   # ends at ts[k-1:]
            inside = np.flatnonzero(np.abs(mean - xi) <= tol * abs(xi))
            settle = ts[k - 1 + inside[0]] - t0 if inside.size else np.nan
            peak = np.max(np.abs(self.fx[sel]) / (mu0 * self.normal_load[sel]))
            why = "" if inside.size else (f"settling: the running mean never came within "
                                          f"{tol:.0%} of the target")
            rows.append((dict(target=xi, reached=float(np.mean(cr[held])),
                              settling_s=float(settle),
                              adhesion=float(np.mean(self.adhesion[sel][held])),
                              peak_force_over_muN=float(peak)), why))
        return rows

    def table(self, tol: float = 0.05) -> str:
        """:meth:`summary` as aligned text.

        Parameters
        ----------
        tol : float, optional
            Settling tolerance, relative to the target [-].

        Returns
        -------
        str
            One row per target; a value that is NaN shows as "-", with the
            reason at the end of its row.

        Examples
        --------
        >>> import rollerrig as rr
        >>> res = rr.simulate(duration=0.4, targets=[0.02], progress=False)
        >>> print(res.table())
          target   reached settling s  adhesion peak F/muN
           0.020   0.00722          -    0.3676     0.9895  settling: the running mean
           never came within 5% of the target
        """
        def cell(v: float, width: int, fmt: str) -> str:
            return f"{v:{width}{fmt}}" if np.isfinite(v) else f"{'-':>{width}}"
        lines = [f"{'target':>8} {'reached':>9} {'settling s':>10} {'adhesion':>9} "
                 f"{'peak F/muN':>10}"]
        for r, why in self._summary(tol, 0.25):
            lines.append(f"{r['target']:8.3f} {cell(r['reached'], 9, '.5f')} "
                         f"{cell(r['settling_s'], 10, '.3f')} {cell(r['adhesion'], 9, '.4f')} "
                         f"{cell(r['peak_force_over_muN'], 10, '.4f')}"
                         f"{'  ' + why if why else ''}")
        return "\n".join(lines)


def scenario_record(params: object) -> Optional[Dict[str, str]]:
    """RigResult.scenario of a run whose parameters came from `params`: the
    file's absolute path and sha256 when it is a path, else None."""
    import hashlib
    if not isinstance(params, (str, os.PathLike)):
        return None
    path = os.path.abspath(os.fspath(params))
    with open(path, "rb") as fh:
        return {"path": path, "sha256": hashlib.sha256(fh.read()).hexdigest()}


def _changed(defaults: Mapping[str, Any], params: Mapping[str, Any],
             prefix: str = "") -> List[Tuple[str, Any]]:
    """[(section.key, value)] of `params` that differ from `defaults`
    (nested dicts; a key the defaults lack counts as changed)."""
    out: List[Tuple[str, Any]] = []
    for key in sorted(params):
        value, default = params[key], defaults.get(key, _MISSING)
        if isinstance(value, dict) and isinstance(default, dict):
            out += _changed(default, value, f"{prefix}{key}.")
        elif value != default:
            out.append((f"{prefix}{key}", value))
    return out


_MISSING = object()
