"""The roller rig in time: the seed paper's mechatronic model and scenario.

    import rollerrig as rr
    res = rr.simulate()                           # the paper's scenario, default parameters
    res.time, res.creepage, res.fx                # named numpy arrays, one value per sample
    res = rr.simulate(duration=4.0, dt=0.004, method="polach",
                      params={"scenario": {"mu0": 0.3}}, targets=[0.02])
    res = rr.simulate(params="my.toml")           # a parameter file: any subset of the defaults
    res = rr.simulate(controller=my_controller)   # a controller of one's own in the loop
    res = rr.simulate(params={"adhesion": {"schedule_times_s": [5, 6],
                                           "schedule_mu0": [0.4, 0.1]}})   # mu in time
    res.summary()                                 # per target: creepage reached, settling, ...
    res.to_xarray(), res.to_dataframe()           # with xarray / pandas (extra "sweep")

The model (csrc/rig/rr_rig.h): a wheelset on two rigidly joined rollers, its
axle boxes on springs and dampers, normal loads from its vertical and roll
balance, contact by rr_rig_contact (FASTSIM with falling friction by
default), roller and wheelset drives with PI speed controllers (eq. 10-11),
torque limiters and first-order lags, encoders (eq. 12) and the creepage
controller (eq. 13-16), sampled every dt; the plant is integrated between
samples by a fixed-step L-stable method.  Default parameters:
rollerrig/data/rig_default.toml, every value with its origin
(docs/parameters.md).

Parameters are checked as a whole (check_parameters): every unknown key,
every bad value and every documentation-only key given a new value is
reported at once, in one RollerRigError that names the file or `params`.
"""
import copy
import difflib
import functools
import json
import math
import numbers
import os
import stat
import sys
import time
import warnings
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from . import _core
from . import control as _control
from ._errors import RollerRigError, RollerRigWarning, status_message
from ._optional import require
from ._binding import METHODS, _as_float, check_creep_options, core, loop_method, rig_method
from .geometry import MAX_ROWS, ContactTable, RigGeometry
from .profiles import Profile

try:
    import tomllib
except ImportError:                                     # Python < 3.11
    import tomli as tomllib

__all__ = ["PARAMETERS", "default_parameters", "load_parameters", "check_parameters", "build_rig", "Rig",
           "simulate", "replay", "RigResult", "RECORD_FIELDS", "RECORD_UNITS",
           "RECORD_BYTES_CAP", "RIG_METHODS"]

DEFAULTS_PATH = os.path.join(os.path.dirname(__file__), "data", "rig_default.toml")

#: the per-sample record of the C rig (csrc/rig/rr_rig_params.c, in the order of
#: enum rr_rig_record_index): (name, unit, meaning); each sample is recorded at its end
RECORD = tuple((name, unit, meaning) for name, _, unit, meaning in _core.RIG_RECORD)
RECORD_FIELDS = tuple(name for name, _, _ in RECORD)
#: the unit of each record field ("-": dimensionless)
RECORD_UNITS = {name: unit for name, unit, _ in RECORD}
_RECORD_MEANING = {name: meaning for name, _, meaning in RECORD}

#: the default cap on the memory of a run's records [bytes]: 1 GiB, about
#: 4.6 million samples (5.1 hours at the 4 ms sample); simulate refuses a run
#: whose records would not fit and says which record_every would
RECORD_BYTES_CAP = 1 << 30
_BYTES_PER_SAMPLE = 8 * len(RECORD_FIELDS)
# samples stepped per call into the C loop: bounds the temporary records
# (14 MB) whatever the run's length and decimation
_CHUNK_SAMPLES = 1 << 16


class RigParameter(NamedTuple):
    """A row of the rig's parameter declaration (csrc/rig/rr_rig_params.c)."""
    name: str           #: "section.key" of rig_default.toml
    unit: str           #: "-" dimensionless, "" a name or a flag
    type: str           #: "real", "int", "flag", "choice" or "list"
    default: object     #: float, int, bool, str or tuple of floats (None: a creep row)
    lo: float           #: range of a real, an int or each entry of a list
    hi: float
    lo_open: bool
    hi_open: bool
    choices: tuple      #: the names of a choice
    text: str           #: the default as TOML text (None: a choice, its name)
    creep: bool         #: the creep-force method or an option of it (rollerrig.contact)
    origin: str         #: where the default comes from
    option: str         #: a creep row's option of the method ("nx"; None: not one)


#: every parameter of the rig, declared once in C: name, unit, type,
#: default, range, origin (rig_default.toml is generated from it)
PARAMETERS = tuple(RigParameter(*row) for row in _core.RIG_PARAMETERS)
_PARAMETER = {p.name: p for p in PARAMETERS}

#: the integrators of integration.method
ODE_METHODS = _PARAMETER["integration.method"].choices
#: control sample time [s], simulated time [s] (27.8 h)
MIN_DT, MAX_DT = _PARAMETER["scenario.control_sample_time_s"][4:6]
MAX_DURATION = _PARAMETER["scenario.duration_s"].hi
#: the creep-force methods the rig steps with (the registry's in_rig: no
#: workspace, and |F| <= mu N; csrc/rig/rr_rig.h, rr_rig_method_check)
RIG_METHODS = tuple(name for name, m in METHODS.items() if m.in_rig)
#: a run whose samples did not converge more often than UNTRUSTED_SHARE of
#: them, and in at least UNTRUSTED_MIN samples, ends with status ERR_UNTRUSTED
#: (-19): the integrator fails again and again, its results cannot be
#: trusted.  Measured against the same runs converged (20 substeps, 3 Newton
#: iterations): the paper's scenario at 8 ms (208 of 2500 samples not
#: converged) misses its creepage by 40 % rms, mu0 stepped from 0.1 to 0.8
#: (24 of 100) by 89 %, a start from rest at 2 m/s (45 of 150) by 124 %;
#: the paper's at 4 ms (none) by 1.2 %.  A transient (a braking onset, a
#: step of the adhesion) leaves a few such samples, a warning (status 1):
#: in the tests' short runs 1 to 6 (up to 1 in 15)
UNTRUSTED_SHARE = 0.05
UNTRUSTED_MIN = 20
MAX_PARAMETER_FILE_BYTES = 1 << 20  # the default file is 12 kB


# ------------------------------------------------------------------ reading files

class _Problems(Exception):
    """What is wrong with a parameter set or file: a list of sentences, each
    naming its key; the public functions turn it into one RollerRigError."""

    def __init__(self, problems):
        super().__init__(problems)
        self.problems = list(problems)


_SHOWN_PROBLEMS = 30     # a file of thousands of bad keys gives a readable message


def _error(source, problems):
    if len(problems) == 1:
        return RollerRigError(f"{source}: {problems[0]}")
    shown = [f"  {p}" for p in problems[:_SHOWN_PROBLEMS]]
    if len(problems) > _SHOWN_PROBLEMS:
        shown.append(f"  ... and {len(problems) - _SHOWN_PROBLEMS} more")
    return RollerRigError(f"{source}: {len(problems)} problems:\n" + "\n".join(shown))


def _short(value, width=60):
    text = repr(value)
    return text if len(text) <= width else text[:width - 3] + "..."


def _read_parameter_file(path):
    """The parsed TOML of `path`, or _Problems saying why not.  Only a
    regular file of at most MAX_PARAMETER_FILE_BYTES of UTF-8 is read (a
    FIFO is never waited on, a device never read from)."""
    try:
        # O_NONBLOCK: opening a FIFO for reading must not wait for a writer;
        # the type is then checked on the open descriptor, so it cannot change
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0)
                     | getattr(os, "O_BINARY", 0))
    except IsADirectoryError:
        raise _Problems(["is a directory, not a parameter file"]) from None
    except OSError as e:
        raise _Problems([f"cannot open it: {e.strerror or e}"]) from None
    try:
        info = os.fstat(fd)
        if stat.S_ISDIR(info.st_mode):
            raise _Problems(["is a directory, not a parameter file"])
        if not stat.S_ISREG(info.st_mode):
            raise _Problems(["is not a regular file (a FIFO, a device or a socket); give a "
                             "TOML parameter file"])
        if info.st_size > MAX_PARAMETER_FILE_BYTES:
            raise _Problems([f"is {info.st_size} bytes; a parameter file is at most "
                             f"{MAX_PARAMETER_FILE_BYTES} bytes (rig_default.toml: 12 kB)"])
        with os.fdopen(fd, "rb") as fh:
            fd = None
            data = fh.read(MAX_PARAMETER_FILE_BYTES + 1)
    except OSError as e:
        raise _Problems([f"cannot read it: {e.strerror or e}"]) from None
    finally:
        if fd is not None:
            os.close(fd)
    if len(data) > MAX_PARAMETER_FILE_BYTES:             # grew while being read
        raise _Problems([f"is more than {MAX_PARAMETER_FILE_BYTES} bytes"])
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise _Problems([f"is not UTF-8 text (byte {e.start}); a parameter file is TOML "
                         f"text"]) from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise _Problems([f"is not valid TOML: {e}"]) from None
    except RecursionError:
        raise _Problems(["is nested too deeply or malformed (TOML arrays or tables inside "
                         "each other beyond Python's recursion limit)"]) from None


def load_parameters(path):
    """A parameter file (TOML, the layout of rig_default.toml, any subset of
    it) as a nested dict, not yet checked (check_parameters does).  Raises
    RollerRigError naming the file and why: missing, a directory or FIFO,
    over 1 MiB, not UTF-8, not TOML, nested too deeply."""
    try:
        return _read_parameter_file(path)
    except _Problems as p:
        raise _error(f"load_parameters: {os.fspath(path)}", p.problems) from None


def _default_value(p):
    if p.default is None:                        # a creep row: its TOML text
        return tomllib.loads(f"v = {p.text}")["v"]
    return list(p.default) if p.type == "list" else p.default


@functools.lru_cache(maxsize=1)
def _defaults():
    """The defaults as a nested dict, from the C declaration (PARAMETERS)."""
    D = {}
    for p in PARAMETERS:
        section, key = p.name.split(".")
        D.setdefault(section, {})[key] = _default_value(p)
    return D


def defaults_toml():
    """The text of rollerrig/data/rig_default.toml: the declaration of
    PARAMETERS (csrc/rig/rr_rig_params.c) with every origin as a comment.
    tests/test_rig_params.py checks that the shipped file equals it;
    rollerrig.rig.write_defaults() rewrites it."""
    notes = dict(_core.RIG_SECTIONS)
    lines = [line.rstrip() for line in _TOML_HEADER.splitlines()]
    section = None
    for p in PARAMETERS:
        sec, key = p.name.split(".")
        if sec != section:
            section = sec
            lines += ["", f"[{sec}]"]
            lines += [f"# {line}" for line in _wrap(notes.get(sec, ""), 93)]
        text = p.text if p.text is not None else f'"{p.default}"'
        lines.append(f"{key} = {text}".ljust(32) + f" # {p.origin}")
    return "\n".join(lines) + "\n"


def _wrap(text, width):
    import textwrap
    return textwrap.wrap(text, width) if text else []


_TOML_HEADER = """\
# Default parameters of the rollerrig model of the Politecnico di Torino 1/5 scaled roller rig
# (Bosso, Gugliotta, Soma, Spiryagin, "Model of scaled test rig for real time applications",
# the "seed paper"; section and equation numbers below are the paper's).
#
# GENERATED from the declaration of the rig's parameters, csrc/rig/rr_rig_params.c (names,
# units, defaults, ranges, origins): edit that table, then run
#     python -c "import rollerrig.rig; rollerrig.rig.write_defaults()"
# (tests/test_rig_params.py checks that this file is current).  A copy of this file, edited, is
# a valid scenario file (rollerrig simulate --scenario my.toml).
#
# SI units throughout (m, kg, s, N, Pa, rad); the unit is in each key's name.
# Every value names its origin:
#   "paper ..."      a number printed in the seed paper;
#   "scaled ..."     full-scale value X / factor, by the similarity law of docs/parameters.md
#                    (same material, same contact stresses, same speed; length factor 5),
#                    from the Manchester benchmark vehicle 1 (docs/parameters.md);
#   "cited ..."      a published or public source, named in the comment;
#   "choice ..."     a value this project chose, with the reason.
# The paper does not publish the rig's masses, inertias, radii, stiffnesses or profiles
# (shared/reference/rig-parameters.csv: NOT_FOUND rows). Derivations, checks and
# uncertainties: docs/parameters.md."""


def default_parameters():
    """The default parameter set (a fresh nested dict: change it freely)."""
    return copy.deepcopy(_defaults())


# ------------------------------------------------------------------ checking parameters

def _real(lo=-math.inf, hi=math.inf, lo_open=False, hi_open=False):
    """A check: a finite real number in the interval."""
    if lo == -math.inf and hi == math.inf:
        need = ""
    elif hi == math.inf:
        need = f" {'>' if lo_open else '>='} {lo:g}"
    else:
        need = f" in {'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}"

    def check(v):
        ok = isinstance(v, numbers.Real) and not isinstance(v, bool)
        if ok:
            try:
                x = float(v)
            except OverflowError:                        # an int beyond a double
                ok = False
            else:
                ok = (math.isfinite(x) and (x > lo if lo_open else x >= lo)
                      and (x < hi if hi_open else x <= hi))
        return None if ok else f"must be a finite number{need}"
    return check


def _integer(lo, hi):
    def check(v):
        ok = isinstance(v, numbers.Integral) and not isinstance(v, bool) and lo <= v <= hi
        return None if ok else f"must be an integer from {lo} to {hi}"
    return check


def _choice(*values):
    shown = " or ".join(repr(v) for v in values)

    def check(v):
        return None if isinstance(v, str) and v in values else f"must be {shown}"
    return check


def _flag(v):
    return None if isinstance(v, bool) else "must be true or false"


def _numbers(item, need, most=math.inf, empty=False):
    """A check: a list of numbers (at most `most`, empty only if `empty`),
    each passing `item`."""
    def check(v):
        if not isinstance(v, (list, tuple)) or (not v and not empty) or len(v) > most \
                or any(item(x) for x in v):
            return f"must be a {'' if empty else 'non-empty '}list of {need}"
        return None
    return check


def _rule(p):
    """The check of a declared parameter (PARAMETERS row)."""
    if p.type == "real":
        return _real(p.lo, p.hi, p.lo_open, p.hi_open)
    if p.type == "int":
        return _integer(int(p.lo), int(p.hi))
    if p.type == "flag":
        return _flag
    if p.type == "choice":
        return _choice(*p.choices)
    entry = _real(p.lo, p.hi, p.lo_open, p.hi_open)
    need = entry(math.nan)[len("must be a finite number"):]
    # a list whose default is empty may be empty (rr_rig_params.h)
    return _numbers(entry, f"at most {_core.RIG_MAX_LIST} numbers{need}",
                    _core.RIG_MAX_LIST, empty=not p.default)

#: the parameter file's keys (contact section) that set a creep-force option:
#: key -> the option's name in the registry (rollerrig.METHODS), as each
#: creep row declares it (its option column, csrc/rig/rr_rig_params.c, which
#: the C rig and the FMU read too); each is given to the chosen method where
#: it has that option, and checked as the registry says
_FILE_OPTIONS = {p.name.split(".", 1)[1]: p.option for p in PARAMETERS if p.option}


def _option_rule(name):
    """A parameter check from the registry's option `name` (its range or names)."""
    op = next(m.options[name] for m in METHODS.values() if name in m.options)
    if op.type == "choice":
        return _choice(*op.choices)
    if op.type == "int":
        return _integer(op.lo + op.lo_open, op.hi - op.hi_open)
    return _real(op.lo, op.hi, lo_open=op.lo_open, hi_open=op.hi_open)


#: the check of every key the model reads: the declared ones (PARAMETERS),
#: and the creep-force method's options
_RULES = {}
for _p in PARAMETERS:
    if not _p.creep:
        _section, _key = _p.name.split(".")
        _RULES.setdefault(_section, {})[_key] = _rule(_p)
_RULES["contact"].update({
    "creep_method": _choice(*METHODS),
    **{key: _option_rule(option) for key, option in _FILE_OPTIONS.items()},
})

#: keys (or whole sections) the parameters no longer have, since they acted
#: on nothing, with what sets the quantity instead (csrc/rig/rr_rig_params.c):
#: giving one is refused with that reason
RETIRED = dict(_core.RIG_RETIRED)


def _retired(name):
    return RETIRED.get(name) or RETIRED.get(name.split(".", 1)[0])


def _merge(base, over, problems, where=""):
    """Override nested dict `base` by `over` in place, appending a sentence
    to `problems` for each key that cannot be taken."""
    for key, value in over.items():
        name = f"{where}{key}"
        reason = _retired(name) if isinstance(key, str) else None
        if reason is not None:
            problems.append(f"{name} does not act on the model ({reason}); it is no longer a "
                            f"parameter, got {_short(value)}")
            continue
        if not isinstance(key, str) or key not in base:
            near = difflib.get_close_matches(str(key), [k for k in base if isinstance(k, str)],
                                             n=1)
            hint = f" (did you mean '{where}{near[0]}'?)" if near else ""
            problems.append(f"unknown parameter '{name}'{hint}")
            continue
        default = base[key]
        if isinstance(default, dict):
            if not isinstance(value, dict):
                problems.append(f"'{name}' is a section: give a table of its keys, got "
                                f"{_short(value)}")
            else:
                _merge(default, value, problems, name + ".")
            continue
        if isinstance(value, dict):
            problems.append(f"{name} is a value, not a section, got a table")
            continue
        base[key] = value


def _check_values(P):
    """Sentences for every value of the merged parameters that breaks its
    rule, then for the rules between keys."""
    problems = []
    for section, rules in _RULES.items():
        for key, rule in rules.items():
            v = P[section][key]
            need = rule(v)
            if need:
                problems.append(f"{section}.{key} {need}, got {_short(v)}")
    bad = {p.split(" ", 1)[0] for p in problems}
    S, C = P["scenario"], P["contact"]
    if not bad & {"scenario.targets", "scenario.target_start_s"}:
        targets, starts = S["targets"], S["target_start_s"]
        if len(targets) != len(starts):
            problems.append(f"scenario.targets has {len(targets)} entries but "
                            f"scenario.target_start_s has {len(starts)}: give one start "
                            f"time per target")
        elif any(b <= a for a, b in zip(starts, starts[1:])):
            problems.append(f"scenario.target_start_s must increase (one start time per "
                            f"entry of scenario.targets, in order), got {_short(starts)}")
        elif "scenario.duration_s" not in bad and starts[-1] >= S["duration_s"]:
            problems.append(f"scenario.target_start_s must fall inside scenario.duration_s "
                            f"= {S['duration_s']!r} s, got {_short(starts)}")
    A = P["adhesion"]
    if not bad & {f"adhesion.{k}" for k in A if k.startswith("schedule_")}:
        times = A["schedule_times_s"]
        for key in ("schedule_mu0", "schedule_polach_A", "schedule_polach_B_s_per_m"):
            if len(A[key]) != len(times) and (key == "schedule_mu0" or A[key]):
                problems.append(f"adhesion.{key} has {len(A[key])} entries but "
                                f"adhesion.schedule_times_s has {len(times)}: give one per time"
                                f"{'' if key == 'schedule_mu0' else ', or none'}")
        if any(b < a for a, b in zip(times, times[1:])):
            problems.append(f"adhesion.schedule_times_s must not decrease (two equal times make "
                            f"a step), got {_short(times)}")
    if not bad & {"adhesion.patch_length_m", "roller.radius_m"} \
            and A["patch_length_m"] > 2 * math.pi * P["roller"]["radius_m"]:
        problems.append(f"adhesion.patch_length_m must be at most the roller's circumference "
                        f"2 pi roller.radius_m = {2 * math.pi * P['roller']['radius_m']:.6g} m, "
                        f"got {A['patch_length_m']!r}")
    if not bad & {"contact.polach_kA", "contact.polach_kS"} \
            and C["polach_kS"] > C["polach_kA"]:
        problems.append(f"contact.polach_kS must be at most contact.polach_kA = "
                        f"{C['polach_kA']!r} (Polach: kS <= kA), got {C['polach_kS']!r}")
    return problems


def check_parameters(params=None, *, source="check_parameters: params"):
    """The default parameters overridden by `params` (a nested dict as the
    layout of rig_default.toml, any subset of it), every value checked.

    Returns the merged nested dict.  Raises one RollerRigError, prefixed by
    `source`, that lists every problem at once: unknown keys, values out of
    range (the message names the key, the range and the value), a section
    given a value or the reverse, the lengths and order of
    scenario.targets / target_start_s, and a key the parameters no longer
    have (RETIRED: the similarity law, the full-scale reference, the gear
    ratios, ...): such a key acted on nothing.
    """
    if params is not None and not isinstance(params, dict):
        raise RollerRigError(f"{source} must be a nested dict (or, for simulate and "
                             f"build_rig, the path of a TOML file), got "
                             f"{type(params).__name__}")
    P, problems = _parameter_problems(params)
    if problems:
        raise _error(source, problems)
    scaled = _scaled_starts(params, P)
    if scaled:
        warnings.warn(f"{source}: {scaled}", RollerRigWarning, stacklevel=2)
    return P


def _parameter_problems(params):
    """(the merged parameters, the list of their problems) of a nested dict."""
    P = default_parameters()
    problems = []
    if params:
        _merge(P, copy.deepcopy(params), problems)
        _scale_starts(params, P)
    return P, problems + _check_values(P)


def _starts_not_given(params, P):
    """True where params set scenario.duration_s (valid) but not
    scenario.target_start_s, and the default start times do not all fall
    inside that duration."""
    S = params.get("scenario") if isinstance(params, dict) else None
    if not (isinstance(S, dict) and "duration_s" in S and "target_start_s" not in S):
        return False
    duration = P["scenario"]["duration_s"]
    if _real(0.0, MAX_DURATION, lo_open=True)(duration):
        return False
    return _defaults()["scenario"]["target_start_s"][-1] >= duration


def _scale_starts(params, P):
    """One rule for a duration too short for the target start times, whether
    scenario.duration_s or simulate's duration gives it: start times the
    caller did not give (the defaults, written for the default duration)
    are scaled to the duration, as simulate(duration=...) scales the
    scenario's (_target_schedule); start times given with a duration they do
    not fit are refused (_check_values)."""
    if _starts_not_given(params, P):
        D = _defaults()["scenario"]
        scale = P["scenario"]["duration_s"] / D["duration_s"]
        P["scenario"]["target_start_s"] = [x * scale for x in D["target_start_s"]]


def _scaled_starts(params, P):
    """The warning's text where _scale_starts scaled the start times, else ""."""
    if not _starts_not_given(params, P):
        return ""
    D = _defaults()["scenario"]
    return (f"the default target start times {D['target_start_s']} s (for the default "
            f"scenario.duration_s = {D['duration_s']:g} s; scenario.target_start_s not given) "
            f"do not all fall inside scenario.duration_s = {P['scenario']['duration_s']:g} s: "
            f"scaled by {P['scenario']['duration_s'] / D['duration_s']:g} to "
            f"{[float(f'{x:.6g}') for x in P['scenario']['target_start_s']]} s")


def _parameters(func, params):
    """The checked parameters of a call: params None, a dict, or a file path."""
    if params is None:
        return default_parameters()
    if isinstance(params, (str, os.PathLike)):
        source = f"{func}: params {os.fspath(params)}"
        try:
            params = _read_parameter_file(params)
        except _Problems as p:
            raise _error(source, p.problems) from None
        return check_parameters(params, source=source)
    if not isinstance(params, dict):
        raise RollerRigError(f"{func}: params must be a nested dict or the path of a TOML "
                             f"file, got {type(params).__name__}")
    return check_parameters(params, source=f"{func}: params")


# ------------------------------------------------------------------ the C rig

def _c_params(P, dt, substeps, ode):
    """The C rig's primary values {"section.key": value} (csrc/rig/rr_rig_params.h,
    rr_rig_config) of checked parameters, with the call's sample time,
    substeps and integrator; the C side derives the rig's parameters."""
    cp = {p.name: P[p.name.split(".")[0]][p.name.split(".")[1]]
          for p in PARAMETERS if not p.creep}
    cp["scenario.control_sample_time_s"] = float(dt)
    cp["integration.substeps"] = int(substeps)
    cp["integration.method"] = ode
    return cp


#: the parameters that make the rig's profiles and contact table
GEOMETRY_KEYS = ("wheelset.wheel_radius_m", "roller.radius_m", "wheelset.profile_half_width_m",
                 "wheelset.conicity", "roller.crown_radius_m", "wheelset.contact_half_spacing_m",
                 "integration.table_half_range_m", "integration.table_rows")


def _geometry(P):
    """The conical wheel on the crowned roller (the paper's first stage) and
    its table; a geometry that yields none is the parameters' fault, and the
    message says which ones made it."""
    W, R, I = P["wheelset"], P["roller"], P["integration"]
    try:
        return _rig_table(float(W["wheel_radius_m"]), float(R["radius_m"]),
                          float(W["profile_half_width_m"]), math.atan(float(W["conicity"])),
                          float(R["crown_radius_m"]), float(W["contact_half_spacing_m"]),
                          float(I["table_half_range_m"]), int(I["table_rows"]))
    except RollerRigError as e:
        values = ", ".join(f"{k} = {P[k.split('.')[0]][k.split('.')[1]]!r}"
                           for k in GEOMETRY_KEYS)
        raise RollerRigError(f"params: the rig's geometry ({values}) gives no contact "
                             f"table: {e}") from None


# The table is a pure function of these numbers and read-only, so runs on the
# same geometry (a sweep over controller or friction settings, a notebook
# re-running a cell) share one build instead of repeating its ~50 ms.
# The rows come from the C core's rr_rig_table_build (csrc/geometry/rr_tables.h),
# so a C program building the rig's table has this one, bit for bit; the
# profiles made here (the same points and spline, by the same C) are the
# table's geometry and check the numbers with messages that name them.
@functools.lru_cache(maxsize=8)
def _rig_table(r0, R0, hw, alpha, crown, span, reach, rows):
    n = _core.RIG_PROFILE_POINTS
    g = RigGeometry(wheel=Profile.conical(alpha, (-hw, hw), r0=r0, n=n),
                    roller=Profile.cylinder((-hw, hw), crown_radius=crown, n=n),
                    wheel_radius=r0, roller_radius=R0, wheel_y=span, roller_y=span)
    g._params()
    if not (math.isfinite(reach) and reach > 0):
        raise RollerRigError(f"rig_table: the table's half range must be > 0 [m], got {reach!r}")
    if not 2 <= rows <= MAX_ROWS:
        raise RollerRigError(f"rig_table: the table's rows must be from 2 to {MAX_ROWS}, "
                             f"got {rows!r}")
    data, y0, dy, status, bad_y = _core.rig_table(r0, R0, hw, alpha, crown, span, reach, rows)
    if status < 0:
        where = f"at y_ws = {bad_y!r}: " if math.isfinite(bad_y) else ""
        raise RollerRigError(f"rig_table: {where}{status_message(status)}")
    data.setflags(write=False)
    return ContactTable(g, y0, dy, rows, data)


#: the keyword options of simulate / build_rig / replay that go to the creep-force
#: method: every option of the registry's methods (nx, ny are arguments of their own)
CREEP_OPTIONS = tuple(dict.fromkeys(o for m in METHODS.values() for o in m.options
                                    if o not in ("nx", "ny")))


def _creep_options(func, P, method, nx, ny, creep, in_rig=True):
    """The creep-force method and its options: the parameters' contact
    section (the keys of _FILE_OPTIONS the method has), overridden by the
    caller's (method, nx, ny, and `creep`: the method's options); checked
    by the registry.  in_rig: a method the rig steps with (RIG_METHODS),
    else one its contact model takes (replay).  Returns the keywords for
    the binding (method=...)."""
    C = P["contact"]
    method = method if method is not None else C["creep_method"]
    if not (isinstance(method, str) and method in METHODS):
        raise RollerRigError(f"{func}: method must be one of {', '.join(map(repr, METHODS))}, "
                             f"got {method!r:.60}")
    info = rig_method(func, method) if in_rig else loop_method(func, method)
    if info.coulomb_only and C["friction_law"] != "coulomb":
        raise RollerRigError(f"{func}: method {method!r} is built for Coulomb friction; the "
                             f"parameters' contact.friction_law is {C['friction_law']!r} "
                             f"(set it to 'coulomb')")
    unknown = set(creep) - set(CREEP_OPTIONS)
    if unknown:
        raise RollerRigError(f"{func}: unknown option(s) {sorted(unknown)}; the creep "
                             f"options are {list(CREEP_OPTIONS)}")
    has = METHODS[method].options
    opts = {o: C[key] for key, o in _FILE_OPTIONS.items() if o in has and key in C}
    # nx, ny are arguments of their own, like the file's keys: the grid of a
    # method that has one (a method without one takes no grid)
    opts.update({k: v for k, v in (("nx", nx), ("ny", ny)) if v is not None and k in has})
    opts.update(creep)
    return check_creep_options(func, method, opts)


def schedule(P, duration, dt, targets, target_times, roller_speed, first=0, stop=None):
    """The references of samples first <= k < stop (default: all of the
    duration): roller speed [rad/s] and creepage target (NaN before the
    first target's start).  Sample k starts at k dt.  The rule is the C
    side's (rr_rig_schedule), which a C program of the rig follows too."""
    n = int(round(duration / dt))
    stop = n if stop is None else min(stop, n)
    return _core.rig_schedule(float(roller_speed), float(P["roller"]["radius_m"]),
                              [float(x) for x in targets], [float(t) for t in target_times],
                              float(dt), int(first), max(int(stop), int(first)))


def _real_arg(func, name, v, lo=-math.inf, hi=math.inf, lo_open=False, unit=""):
    need = _real(lo, hi, lo_open=lo_open)(v)
    if need:
        raise RollerRigError(f"{func}: {name} {need}{' ' + unit if unit else ''}, "
                             f"got {_short(v)}")
    return float(v)


def _check_dt(func, dt):
    return _real_arg(func, "dt", dt, MIN_DT, MAX_DT, unit="s")


class Rig:
    """The rig stepped by hand (build_rig): the C rig of csrc/rig/rr_rig.h, its
    arguments checked here (RollerRigError naming them).

    sample(roller_ref, xi_ref) -> status: the sampling instant (encoders,
        creepage controller, PI controllers); roller_ref the roller speed
        reference [rad/s], xi_ref the creepage target (NaN: no creepage
        control, the wheelset held at free rolling); the same as
    read() -> (signals, status): the sampling instant's measurement (the
        fields of rollerrig.control.RigSignals from t to xi_est), then
    write(roller_mode, roller_ref, wheelset_mode, wheelset_ref, mu0=nan)
        -> status: the references held over the sample; modes
        _core.CMD_BUILTIN (the rig's controllers: roller speed, creepage
        target), CMD_SPEED [rad/s], CMD_TORQUE [N m]; mu0 the friction
        coefficient over the sample (NaN: the adhesion section's);
        csrc/rig/rr_rig.h, rr_rig_read, rr_rig_write
    info: the controllers' settings (rollerrig.control.RigInfo)
    advance() -> (record, status): the plant over one sample
    run(roller_ref, xi_ref, out=None) -> (records, status): one sample per
        element of the two 1-D arrays, records of shape (n,
        len(RECORD_FIELDS)) (written into `out` if given: a writable
        C-contiguous float64 array of that shape); stops at the first error
        (the rest NaN); status the worst of the run
    record() -> (record, status); rhs(t, y) -> (dydt, status); jac(t, y)
        -> (J, status); set_state(t, y) -> status: the plant's right-hand
        side, its approximate Jacobian and its state y (RIG_STATE, 12 values)
    t [s], y, status: the rig's time, state (a copy) and last status
    Statuses: 0 ok, 1 a warning, < 0 an error (rollerrig.STATUS); after an
    error the rig keeps its last good state and refuses to step on.  One
    thread at a time: a second thread gets RuntimeError.
    """

    __slots__ = ("_core",)

    def __init__(self, core):
        self._core = core

    def __repr__(self):
        return f"Rig(t = {self.t:g} s, status {self.status})"

    @staticmethod
    def _scalar(func, name, v):
        """A real number (NaN and infinities pass: the C rig answers them
        with a status, as it does for a NaN state)."""
        if isinstance(v, numbers.Real) and not isinstance(v, bool):
            try:
                return float(v)
            except OverflowError:                      # an int beyond a double
                pass
        raise RollerRigError(f"{func}: {name} must be a real number, got {_short(v)}")

    @staticmethod
    def _array(func, name, v, n=None):
        a = _as_float(func, name, v) if not (np.ndim(v) == 1 and np.size(v) == 0) \
            else np.zeros(0)
        if a.ndim != 1 or (n is not None and a.size != n):
            want = f"{n} values" if n is not None else "a 1-D array"
            raise RollerRigError(f"{func}: {name} must be {want}, got shape {a.shape}")
        return np.ascontiguousarray(a)

    def run(self, roller_ref, xi_ref, out=None):
        r = self._array("Rig.run", "roller_ref", roller_ref)
        x = self._array("Rig.run", "xi_ref", xi_ref, r.size)
        return self._core.run(r, x) if out is None else self._core.run(r, x, out)

    def sample(self, roller_ref, xi_ref):
        return self._core.sample(self._scalar("Rig.sample", "roller_ref", roller_ref),
                                 self._scalar("Rig.sample", "xi_ref", xi_ref))

    def read(self):
        return self._core.read()

    def write(self, roller_mode, roller_ref, wheelset_mode, wheelset_ref, mu0=math.nan):
        modes = (_core.CMD_BUILTIN, _core.CMD_SPEED, _core.CMD_TORQUE)
        for name, mode in (("roller_mode", roller_mode), ("wheelset_mode", wheelset_mode)):
            if mode not in modes or isinstance(mode, bool):
                raise RollerRigError(f"Rig.write: {name} must be one of {modes} (builtin, "
                                     f"speed, torque), got {_short(mode)}")
        return self._core.write(int(roller_mode), self._scalar("Rig.write", "roller_ref",
                                                               roller_ref),
                                int(wheelset_mode), self._scalar("Rig.write", "wheelset_ref",
                                                                 wheelset_ref),
                                self._scalar("Rig.write", "mu0", mu0))

    def advance(self):
        return self._core.advance()

    def record(self):
        return self._core.record()

    def _t_y(self, func, t, y):
        return (self._scalar(func, "t", t),
                self._array(func, "y", y, _core.RIG_NSTATE))

    def rhs(self, t, y):
        return self._core.rhs(*self._t_y("Rig.rhs", t, y))

    def jac(self, t, y):
        return self._core.jac(*self._t_y("Rig.jac", t, y))

    def set_state(self, t, y):
        return self._core.set_state(*self._t_y("Rig.set_state", t, y))

    @property
    def t(self):
        return self._core.t

    @property
    def y(self):
        return self._core.y

    @property
    def status(self):
        return self._core.status

    @property
    def info(self):
        return _control.rig_info(self._core.info)


def _build(func, P, *, dt, method, substeps, ode, nx, ny, roller_speed, start, creep,
           given_dt=None):
    """(the C rig, dt, roller speed [m/s], creep options) of checked parameters P;
    given_dt: whether the caller gave dt (default: dt not None), for messages."""
    S, I = P["scenario"], P["integration"]
    given_dt = dt is not None if given_dt is None else given_dt
    dt = _check_dt(func, dt if dt is not None else S["control_sample_time_s"])
    substeps = substeps if substeps is not None else I["substeps"]
    if _integer(1, 1000)(substeps):
        raise RollerRigError(f"{func}: substeps must be an integer from 1 to 1000, "
                             f"got {substeps!r}")
    ode = ode if ode is not None else I["method"]
    if ode not in ODE_METHODS:
        raise RollerRigError(f"{func}: ode must be one of {sorted(ODE_METHODS)}, got {ode!r}")
    _check_loops(func, P, _c_params(P, dt, int(substeps), ode),
                 "dt" if given_dt else "scenario.control_sample_time_s")
    opts = _creep_options(func, P, method, nx, ny, creep)
    c_opts = opts
    V = _real_arg(func, "roller_speed", roller_speed if roller_speed is not None
                  else S["roller_speed_m_s"], unit="m/s")
    if start not in ("rolling", "rest"):
        raise RollerRigError(f"{func}: start must be 'rolling' or 'rest', got {start!r}")

    def make(P, V):
        V = P["scenario"]["roller_speed_m_s"] if V is None else V
        table = _geometry(P)
        cp = _c_params(P, dt, int(substeps), ode)
        # the C side (rr_rig_params_set_table) takes eq. 15-16's radii at the
        # centred wheelset's rolling radii, as a rig is calibrated: the
        # profiles' nominal radii would bias the creepage by
        # (r - r0)/r0 + (R0 - R)/R0, about 0.2 % of creepage here
        return table, core(_core.Rig, table.data, table.y0, table.dy, cp, c_opts,
                           V / float(P["roller"]["radius_m"]) if start == "rolling"
                           else 0.0)
    given_V = None if roller_speed is None else V      # None: the scenario's own
    try:
        table, rig = make(P, given_V)
    except (ValueError, RollerRigError) as e:
        culprits = _culprits(P, given_V, make)
        named = f"the rig cannot start with {', '.join(culprits)}: " if culprits else ""
        raise RollerRigError(f"{func}: {named}{e}") from None
    return Rig(rig), table, dt, V, opts["method"]


def _check_loops(func, P, cp, name):
    """Refuse a sample time at which a drive's sampled speed loop is
    unstable (csrc/rig/rr_rig.h, rr_rig_speed_loops; the C rig refuses it
    too): the message names the drive, the settings its loop depends on and
    the sample times at which it is stable (rr_speed_loop_range)."""
    R, W = P["roller_drive"], P["wheelset_drive"]
    settings = (
        f"roller_drive.kp_N_m_s_per_rad = {R['kp_N_m_s_per_rad']:g}, ki_N_m_s_per_rad = "
        f"{R['ki_N_m_s_per_rad']:g} and lag_time_constant_s = {R['lag_time_constant_s']:g} on "
        f"roller.inertia_kg_m2 = {P['roller']['inertia_kg_m2']:g}",
        f"wheelset_drive.kp_N_m_s_per_rad = {W['kp_N_m_s_per_rad']:g}, ki_N_m_s_per_rad = "
        f"{W['ki_N_m_s_per_rad']:g} and lag_time_constant_s = {W['lag_time_constant_s']:g} on "
        f"wheelset.spin_inertia_kg_m2 + wheelset_drive.drive_inertia_kg_m2 = "
        f"{P['wheelset']['spin_inertia_kg_m2'] + W['drive_inertia_kg_m2']:g}, within eq. 13's "
        f"creepage_controller.alpha = {P['creepage_controller']['alpha']:g}")
    dt = cp["scenario.control_sample_time_s"]
    for drive, text, (stable, rho, lo, hi) in zip(("roller", "wheelset"), settings,
                                                  core(_core.rig_speed_loops, cp)):
        if stable:
            continue
        where = (f"it is stable for sample times from {lo:.3g} to {hi:.3g} s"
                 if not math.isnan(lo) else
                 f"it is stable at no sample time from {MIN_DT:g} to {MAX_DT:g} s")
        raise RollerRigError(
            f"{func}: {name} = {dt:g} s: the {drive} drive's sampled speed loop ({text}) is "
            f"unstable at this sample time (its largest closed-loop pole |z| = {rho:.4g}); "
            f"{where}")


def _culprits(P, given_V, make):
    """The changed values the rig cannot start with: each parameter that
    differs from its default, and a given roller speed, is put back to its
    default alone; those whose default lets the rig start are named (the
    core's status cannot say which of 44 numbers overflowed)."""
    D = _defaults()

    def starts(Q, V):
        try:
            make(Q, V)
        except (ValueError, RollerRigError):
            return False
        return True
    found = []
    for section, values in P.items():
        for key, v in values.items():
            if v == D[section][key]:
                continue
            Q = {k: dict(s) for k, s in P.items()}
            Q[section][key] = D[section][key]
            if starts(Q, given_V):
                found.append(f"params {section}.{key} = {v!r}")
    if given_V is not None and starts(P, D["scenario"]["roller_speed_m_s"]):
        found.append(f"roller_speed = {given_V!r}")
    return found


def build_rig(params=None, *, dt=None, method=None, substeps=None, ode=None, nx=None, ny=None,
              roller_speed=None, start="rolling", **creep):
    """The rig (rollerrig.Rig, over the C rig) and the merged parameters,
    for stepping by hand (rig.sample / rig.advance / rig.rhs, e.g. to verify
    the integrator against another solver).  Returns (rig, params, table).

    params:  None (the defaults), a nested dict overriding rig_default.toml
             or the path of a TOML file doing so; checked by
             check_parameters (one RollerRigError listing every problem)
    dt:      control sample time [s], 1e-6 to 0.1 where the drives'
             sampled speed loops are stable (as simulate; default
             scenario.control_sample_time_s, 4 ms)
    method, nx, ny, **creep: the creep-force method, its FASTSIM grid and
             options (CREEP_OPTIONS: bound, grid, slip_speed, blend_rule, k0,
             alpha_inf, beta, kA, kS; see rollerrig.creep_forces); default
             the parameters' contact section
    substeps, ode: plant steps per sample (1 to 1000) and the integrator
             ("trbdf2", "ros2", "lineuler"); default the integration section
    roller_speed: roller surface speed [m/s] of the initial state
    start:   "rolling" (the wheelset rolling freely at roller_speed) or
             "rest"
    table:   the contact table (rollerrig.ContactTable) of the conical wheel
             on its crowned roller
    """
    P = _parameters("build_rig", params)
    rig, table, *_ = _build("build_rig", P, dt=dt, method=method, substeps=substeps, ode=ode,
                            nx=nx, ny=ny, roller_speed=roller_speed, start=start, creep=creep)
    return rig, P, table


# ------------------------------------------------------------------ the result

@dataclass(repr=False)
class RigResult:
    """Time histories of a rig run, with its schedule and parameters.

    records:      float array (samples kept, len(RECORD_FIELDS)), one row
                  per kept control sample, recorded at the sample's end;
                  each column is also an attribute: res.time [s],
                  res.creepage [-], res.fx [N], ... (RECORD_FIELDS, units in
                  RECORD_UNITS; res.sample_status as int8), and
                  res.normal_load = left + right [N]
    params:       the merged parameters (nested dict of rig_default.toml)
    targets:      the creepage targets [-] (magnitudes, in the drive's sense)
    target_times: their start times [s]
    dt:           control sample time [s]
    status:       0 the run finished; > 0 it finished but some samples
                  warned (1: an inner iteration, e.g. the integrator's Newton
                  iteration, ended above its tolerance; the samples'
                  sample_status say which); -19 (ERR_UNTRUSTED) it finished
                  but more than one sample in 20 warned (20 samples at
                  least): its records are all there, not to be trusted;
                  other < 0: it stopped at a sample whose state could not
                  be computed (-1 NaN, -2 a normal load not positive:
                  lift-off, -3 a wheel off its roller, -11 a singular
                  system, -18 a creep force beyond mu N;
                  rollerrig.status_message(status)), and the records end at
                  the last good sample
    message:      "ok", "ok with warnings: ..." (how many samples), "not to
                  be trusted: ..." (how many), or when and why the run
                  stopped
    wall:         wall-clock seconds: "setup" (parameters, contact table: a
                  one-off, as the paper's offline database) and "run" (the
                  stepping loop)
    record_every: the records keep every record_every-th sample (1: all);
                  the kept samples are k record_every dt apart
    method:       the creep-force method of the run
    samples:      control samples stepped (default: len(records) * record_every)
    """

    records: np.ndarray
    params: dict
    targets: tuple
    target_times: tuple
    dt: float
    status: int
    message: str
    wall: dict = None
    record_every: int = 1
    method: str = None
    samples: int = None

    def __getattr__(self, name):
        if name in RECORD_FIELDS:
            col = self.records[:, RECORD_FIELDS.index(name)]
            return col.astype(np.int8) if name == "sample_status" else col
        raise AttributeError(name)

    def __repr__(self):
        method = self.method or self.params.get("contact", {}).get("creep_method")
        return (f"RigResult(samples={self.samples_run}, duration={self.duration:g} s, "
                f"dt={self.dt:g} s, record_every={self.record_every}, method={method!r}, "
                f"status={self.status}, message={self.message!r})")

    @property
    def samples_run(self):
        """Control samples stepped."""
        return self.samples if self.samples is not None else len(self) * self.record_every

    @property
    def duration(self):
        """Simulated time [s]: samples stepped times dt."""
        return self.samples_run * self.dt

    @property
    def record_dt(self):
        """Time between two kept records [s]: record_every dt."""
        return self.record_every * self.dt

    @property
    def normal_load(self):
        """Sum of both wheels' normal loads [N]."""
        return self.normal_load_left + self.normal_load_right

    def __len__(self):
        return self.records.shape[0]

    def to_dataframe(self):
        """The records as a pandas DataFrame, one column per RECORD_FIELDS
        entry (units in RECORD_UNITS).  Needs pandas (extra "sweep")."""
        pd = require("pandas", "RigResult.to_dataframe", "sweep")
        return pd.DataFrame({name: getattr(self, name) for name in RECORD_FIELDS})

    def to_xarray(self):
        """The records as an xarray.Dataset: dimension "time" [s], one
        variable per record field with its unit and meaning in attrs
        ("units", "long_name"); the Dataset's attrs hold the targets, their
        start times, dt, record_every, method, status, message and the
        parameters (as JSON, key "params").  Needs xarray (extra "sweep")."""
        xr = require("xarray", "RigResult.to_xarray", "sweep")

        def attrs(name):
            return {"units": RECORD_UNITS[name], "long_name": _RECORD_MEANING[name]}
        method = self.method or self.params.get("contact", {}).get("creep_method")
        return xr.Dataset(
            {name: ("time", getattr(self, name), attrs(name)) for name in RECORD_FIELDS[1:]},
            coords={"time": ("time", self.time, attrs("time"))},
            attrs={"targets": np.asarray(self.targets, dtype=float),
                   "target_times": np.asarray(self.target_times, dtype=float),
                   "target_times_units": "s", "dt": float(self.dt), "dt_units": "s",
                   "record_every": int(self.record_every), "method": str(method),
                   "status": int(self.status), "message": str(self.message),
                   "params": json.dumps(self.params)})

    def to_csv(self, path):
        """Write the records as CSV (a header of RECORD_FIELDS, one row per
        kept sample) to `path`: a new path or a regular file, replaced
        whole (never a symbolic link, a device or a FIFO: RollerRigError
        naming the path).  Returns the path."""
        import csv
        from ._files import write_file

        def write(fh):
            w = csv.writer(fh)
            w.writerow(RECORD_FIELDS)
            w.writerows(self.records.tolist())
        return write_file(path, write, what="RigResult.to_csv: path")

    def summary(self, tol=0.05, window=0.25):
        """Per target, a dict: "target"; "reached", the creepage held (mean
        over the last 80 % of its interval) [-]; "settling_s", the settling
        time [s] (when the creepage's running mean over `window` seconds
        first comes within tol of the target; eq. 14's recovery steps then
        make a small sawtooth about it; NaN if it never does); "adhesion",
        the adhesion coefficient held [-]; "peak_force_over_muN", the peak
        |fx| / (mu0 N) over the interval.  The creepage is taken in the
        drive's sense (braking cx, traction -cx).  Windows are in seconds,
        so decimated records (record_every > 1) give the same rows to within
        their spacing.  NaN where an interval holds fewer records than the
        window (table() says so, and why)."""
        return [row for row, _ in self._summary(tol, window)]

    def _summary(self, tol, window):
        """summary()'s rows, each with the reason its numbers are NaN ("" if
        none is)."""
        mu0 = self.params["scenario"]["mu0"]
        sense = -1.0 if self.params["scenario"].get("drive_mode") == "traction" else 1.0
        rows = []
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

    def table(self, tol=0.05):
        """summary() as aligned text; a value that is NaN shows as "-", with
        the reason at the end of its row."""
        def cell(v, width, fmt):
            return f"{v:{width}{fmt}}" if np.isfinite(v) else f"{'-':>{width}}"
        lines = [f"{'target':>8} {'reached':>9} {'settling s':>10} {'adhesion':>9} "
                 f"{'peak F/muN':>10}"]
        for r, why in self._summary(tol, 0.25):
            lines.append(f"{r['target']:8.3f} {cell(r['reached'], 9, '.5f')} "
                         f"{cell(r['settling_s'], 10, '.3f')} {cell(r['adhesion'], 9, '.4f')} "
                         f"{cell(r['peak_force_over_muN'], 10, '.4f')}"
                         f"{'  ' + why if why else ''}")
        return "\n".join(lines)


# ------------------------------------------------------------------ simulate

def _target_schedule(S, duration, targets, target_times):
    """(targets, start times) of a run; the rules are simulate's."""
    def listed(v):
        return isinstance(v, (list, tuple, np.ndarray)) and np.ndim(v) == 1 \
            and 0 < len(v) <= _core.RIG_MAX_LIST
    if targets is not None and (not listed(targets)
                                or any(_real(0.0, 1.0, hi_open=True)(x) for x in targets)):
        raise RollerRigError(f"simulate: targets must be a non-empty list of at most "
                             f"{_core.RIG_MAX_LIST} creepages in [0, 1), got "
                             f"{_short(targets)}")
    if targets is None:
        targets = S["targets"]
        if target_times is None:
            starts = [float(x) for x in S["target_start_s"]]
            target_times = starts
            if starts[-1] >= duration:
                scale = duration / float(S["duration_s"])
                target_times = [x * scale for x in starts]
                warnings.warn(
                    f"simulate: the scenario's target start times {starts} s "
                    f"(scenario.target_start_s, for scenario.duration_s = "
                    f"{S['duration_s']:g} s) do not all fall inside duration = "
                    f"{duration:g} s: scaled by {scale:g} to "
                    f"{[float(f'{x:.6g}') for x in target_times]} s", RollerRigWarning,
                    stacklevel=3)
    elif target_times is None:
        target_times = [duration * k / len(targets) for k in range(len(targets))]
    targets = tuple(float(x) for x in targets)
    if not listed(target_times) or len(target_times) != len(targets) \
            or any(_real(0.0)(x) for x in target_times):
        raise RollerRigError(f"simulate: target_times must be start times >= 0 s, one per "
                             f"target ({len(targets)}), got {_short(target_times)}")
    target_times = tuple(float(x) for x in target_times)
    if any(b <= a for a, b in zip(target_times, target_times[1:])):
        raise RollerRigError(f"simulate: target_times must increase, got "
                             f"{_short(target_times)}")
    if target_times[-1] >= duration:
        raise RollerRigError(f"simulate: target_times must fall inside duration = "
                             f"{duration:g} s, got {_short(target_times)}")
    return targets, target_times


def _first_sample(t, dt):
    """The first sample k whose start k dt (as the C schedule computes it,
    rr_rig_schedule) is at or after t."""
    k = max(0, math.ceil(t / dt))
    while k > 0 and (k - 1) * dt >= t:
        k -= 1
    while k * dt < t:
        k += 1
    return k


def _check_targets_applied(targets, target_times, dt, n):
    """Refuse targets no sample would apply: the schedule gives each sample
    the target of the last start time at or before its start (k dt), so a
    target whose interval holds no sample start (it starts within one sample
    of the next, or after the last sample starts) never reaches the
    controller, and its row of the summary would be empty."""
    firsts = [_first_sample(t, dt) for t in target_times] + [n]
    never = [f"{x:g} from {t:g} s" for x, t, a, b in zip(targets, target_times, firsts,
                                                          firsts[1:]) if a >= min(b, n)]
    if never:
        raise RollerRigError(
            f"simulate: {len(never)} of the {len(targets)} targets would never be applied "
            f"({', '.join(never[:5])}{', ...' if len(never) > 5 else ''}): no sample starts "
            f"between such a target's start and the next's (dt = {dt:g} s, {n} sample"
            f"{'s' if n > 1 else ''}); lengthen the duration or space the target_times")


def _record_plan(n, dt, record_every, max_record_bytes):
    """(record_every, records kept) of a run of n samples, within the cap."""
    if _integer(1, max(1, n))(record_every):
        raise RollerRigError(f"simulate: record_every must be an integer from 1 to the "
                             f"number of samples ({n}), got {record_every!r}")
    cap = _real_arg("simulate", "max_record_bytes", max_record_bytes, 0.0, lo_open=True)
    kept = n // record_every
    need = kept * _BYTES_PER_SAMPLE
    if need > cap:
        fit = -(-n * _BYTES_PER_SAMPLE // int(cap)) if cap >= _BYTES_PER_SAMPLE else None
        advice = (f"keep one sample in {fit} (record_every={fit}; on the command line "
                  f"--record-every {fit})" if fit and fit <= n else "shorten the run")
        raise RollerRigError(
            f"simulate: the records of {kept} samples"
            f"{f' (one in {record_every} of {n})' if record_every > 1 else ''} would take "
            f"{need / 2**30:.3g} GiB, over max_record_bytes = {cap / 2**30:.3g} GiB; "
            f"{advice}, or raise max_record_bytes")
    return int(record_every), kept


def simulate(duration=None, dt=None, method=None, params=None, targets=None,
             target_times=None, *, roller_speed=None, start="rolling", nx=None, ny=None,
             substeps=None, ode=None, record_every=1, max_record_bytes=RECORD_BYTES_CAP,
             progress=False, controller=None, **creep):
    """Run the rig: by default the seed paper's scenario on the default parameters.

    duration:  simulated time [s], at least one sample and at most 1e5 s
               (default scenario.duration_s); the run has round(duration /
               dt) samples (a RollerRigWarning says so where that is not
               the duration)
    dt:        control sample time and integration step [s], 1e-6 to 0.1
               (default scenario.control_sample_time_s, the paper's 4 ms),
               at which both drives' sampled speed loops are stable (their
               PI gains on their inertias through their lags, eq. 10-13;
               with the default parameters 6.7e-5 to 8.3e-3 s): another is
               refused before the run, naming the drive and the range
    method:    creep-force method, one of RIG_METHODS ("fastsim",
               "fastsim_blended", "modified_fastsim", "polach", "fastrip",
               "exact_table"; not "linear", which has no friction limit, nor
               "exact", solved at each step); nx, ny the FASTSIM grid
               (default: the parameters' contact section)
    params:    None, a nested dict overriding rig_default.toml, e.g.
               {"scenario": {"mu0": 0.3}, "wheelset": {"mass_kg": 15.0}}, or
               the path of a TOML file of the same layout; every problem is
               reported at once (check_parameters).  Its [adhesion] section
               changes the friction: a schedule of mu0 (and the falling
               law's A, B) in time, a contaminated patch on the roller
               circumference; res.mu_left, res.mu_right record it
    targets:   creepage targets in sequence, magnitudes in [0, 1) in the
               drive's sense (default scenario.targets, the paper's 0.04,
               0.015, 0.02, 0.03); target_times their start times [s],
               increasing, inside the duration.  Without target_times:
               targets given here start at equal intervals over the
               duration; the scenario's own targets start at
               scenario.target_start_s when those all fall inside the
               duration, otherwise at those times scaled by duration /
               scenario.duration_s, with a RollerRigWarning saying so (the
               rule of a scenario.duration_s given without start times:
               check_parameters).  A target no sample would apply (its
               interval holds no sample's start) is refused
    roller_speed: roller surface speed [m/s] held by its controller
               (default scenario.roller_speed_m_s)
    start:     "rolling" (wheelset rolling freely at roller_speed) or "rest"
               (everything at standstill; the roller drive spins the rig up)
    substeps, ode: plant steps per sample and the integrator ("ros2",
               "trbdf2", "lineuler")
    record_every: keep the record of every record_every-th sample only (the
               run still takes every sample): for long runs
    max_record_bytes: cap on the records' memory (default RECORD_BYTES_CAP,
               1 GiB: 232 bytes per kept sample); a run over it is refused
               before it starts, with the record_every that would fit
    progress:  print a progress bar on stderr
    controller: None (the rig's own controllers), or a callable called at
               each control sample with what a real controller sees
               (rollerrig.control.RigSignals: time, encoder counts, angles
               and speeds, drive torques, eq. 16's estimate, the scenario's
               references) and returning the references held over the
               sample: a dict with any of roller_speed [rad/s] or
               roller_torque [N m], wheelset_speed, wheelset_torque or
               xi_ref (a creepage target for the rig's own controller); a
               drive left out (or None returned) keeps the rig's own
               controller.  Its method start(info), if any, is called first
               (rollerrig.control.RigInfo).  A controller that raises or
               returns NaN ends the run with a RollerRigError naming the
               sample, whose .result holds the history so far
    **creep:   the creep-force method's options: bound, grid, slip_speed,
               blend_rule (blended FASTSIM), k0, alpha_inf, beta (modified
               FASTSIM), kA, kS (Polach); see
               rollerrig.creep_forces
    Returns RigResult (its fields, units and status codes are in its
    docstring).  A run that fails (a wheel off its roller, lift-off, NaN, a
    creep force beyond mu N) stops cleanly: the result holds the history so
    far, its status and message say why.  A run whose samples did not
    converge more often than UNTRUSTED_SHARE (one in 20), in UNTRUSTED_MIN
    (20) samples or more, ends with status ERR_UNTRUSTED (-19), its message
    saying how many.
    """
    t0 = time.perf_counter()
    if controller is not None and not callable(controller):
        raise RollerRigError(f"simulate: controller must be a callable (signals -> dict of "
                             f"references), got {_short(controller)}")
    P = _parameters("simulate", params)
    S = P["scenario"]
    given_dt = dt is not None
    dt = _check_dt("simulate", dt if dt is not None else S["control_sample_time_s"])
    duration_name = "duration" if duration is not None else "scenario.duration_s"
    duration = _real_arg("simulate", "duration", duration if duration is not None
                         else S["duration_s"], 0.0, MAX_DURATION, lo_open=True, unit="s")
    dt_name = "dt" if given_dt else "scenario.control_sample_time_s"
    if duration < dt * (1.0 - 1e-9):
        raise RollerRigError(f"simulate: {duration_name} = {duration:g} s is shorter than one "
                             f"sample ({dt_name} = {dt:g} s)")
    n = max(1, int(round(duration / dt)))
    # a run of whole samples: say so where that changes the duration (by more
    # than the rounding of a dt given in single precision, 5e-8)
    if abs(n * dt - duration) > 1e-6 * duration:
        warnings.warn(f"simulate: {duration_name} = {duration:g} s is not a whole number of "
                      f"samples of "
                      f"{dt_name} = {dt:g} s: the run takes {n} samples, {n * dt:.9g} s",
                      RollerRigWarning, stacklevel=2)
    targets, target_times = _target_schedule(S, duration, targets, target_times)
    _check_targets_applied(targets, target_times, dt, n)
    record_every, kept = _record_plan(n, dt, record_every, max_record_bytes)
    rig, _, dt, V, used = _build("simulate", P, dt=dt, method=method, substeps=substeps,
                                 ode=ode, nx=nx, ny=ny, roller_speed=roller_speed,
                                 start=start, creep=creep, given_dt=given_dt)

    out = np.full((kept, len(RECORD_FIELDS)), np.nan)
    t1 = time.perf_counter()

    def result(out, status, message, stepped):
        wall = {"setup": t1 - t0, "run": time.perf_counter() - t1}
        return RigResult(out, P, targets, target_times, dt, int(status), message, wall,
                         record_every=record_every, method=used, samples=stepped)
    if controller is not None:
        out, stepped, status, worst, warned = _run_controlled(
            rig, controller, P, duration, dt, targets, target_times, V, n, record_every, out,
            progress, result)
    else:
        out, stepped, status, worst, warned = _run_builtin(
            rig, P, duration, dt, targets, target_times, V, n, record_every, out, progress)
    if progress:
        sys.stderr.write("\n")
    status = status if status < 0 else worst
    if status == 0:
        message = "ok"
    elif status > 0 and warned > UNTRUSTED_SHARE * stepped and warned >= UNTRUSTED_MIN:
        message = (f"not to be trusted: {warned} of {stepped} samples did not converge "
                   f"(sample_status {status}: {status_message(status)}), more than one in "
                   f"{round(1 / UNTRUSTED_SHARE)}; more integration.substeps or "
                   f"newton_iterations (or a shorter dt) converge it")
        status = _core.ERR_UNTRUSTED
    elif status > 0:
        message = (f"ok with warnings: {warned} of {stepped} samples warned "
                   f"(sample_status {status}: {status_message(status)})")
    else:
        message = f"stopped at t = {rig.t:.4f} s: {status_message(status)}"
    return result(out, status, message, stepped)


def _progress(done):
    sys.stderr.write(f"\rsimulate [{'#' * int(40 * done):<40}] {100 * done:5.1f} %")
    sys.stderr.flush()


def _run_builtin(rig, P, duration, dt, targets, target_times, V, n, record_every, out,
                 progress):
    """simulate's samples on the rig's own controllers, in chunks through
    the C loop.  Returns (records kept, samples stepped, the run's status,
    the worst sample status, samples warned)."""
    # about 50 steps of the progress bar; without one, as few calls as the bound allows
    chunk = max(1, min(n // 50 if progress else n, _CHUNK_SAMPLES))
    stepped, worst, warned, status = 0, 0, 0, 0
    for first in range(0, n, chunk):
        stop = min(n, first + chunk)
        roller_ref, xi_ref = schedule(P, duration, dt, targets, target_times, V, first, stop)
        # every sample kept: the records straight into the result's rows
        rec, status = rig.run(roller_ref, xi_ref, out[first:stop] if record_every == 1
                              else None)
        if status < 0:
            good = np.isfinite(rec[:, 0]) & (rec[:, -1] >= 0)
            rec = rec[:int(np.argmin(good)) if not good.all() else len(rec)]
        # keep samples k = record_every - 1, 2 record_every - 1, ...: the
        # records every record_every dt, ending at the duration
        if record_every > 1:
            offset = (record_every - 1 - first) % record_every
            keep = rec[offset::record_every]
            at = (first + offset) // record_every
            out[at:at + len(keep)] = keep
        stepped = first + len(rec)
        # the worst warning of the chunk from its samples' own statuses: the
        # binding's run() may report only that of its last block of samples
        if len(rec):
            worst = max(worst, status, int(np.max(rec[:, -1])))
            warned += int(np.count_nonzero(rec[:, -1] > 0))
        if progress:
            _progress(stop / n)
        if status < 0:
            out = out[:stepped // record_every]
            break
    return out, stepped, status, worst, warned


_XI_REF = RECORD_FIELDS.index("xi_ref")


def _run_controlled(rig, controller, P, duration, dt, targets, target_times, V, n,
                    record_every, out, progress, result):
    """simulate's samples with a controller of the user's
    (rollerrig.control): read, call, write, advance, sample by sample; the
    records' xi_ref is the scenario's target the controller was given.
    Returns as _run_builtin; a controller that raises, or returns what is
    not a command (reading it raises, whatever the exception) or a command
    the rig refuses (NaN), ends the run with a RollerRigError whose .result
    holds the history so far."""
    core = rig._core
    stepped, worst, warned, status = 0, 0, 0, 0

    def fail(k, t, what, code, cause=None):
        kept = out[:k // record_every]
        text = (f"simulate: the controller failed at sample {k} (t = {t:.4f} s): {what}; "
                f"the history so far is in this error's .result")
        e = RollerRigError(text)
        e.result = result(kept, code, text.split(": ", 1)[1], k)
        raise e from cause

    start = getattr(controller, "start", None)
    if start is not None:
        try:
            start(rig.info)
        except Exception as exc:
            fail(0, 0.0, f"its start(info) raised {type(exc).__name__}: "
                 f"{_control.safe_repr(exc, str)}", _core.ERR_CONTROLLER, exc)
    chunk = max(1, min(n // 50 if progress else n, _CHUNK_SAMPLES))
    for first in range(0, n, chunk):
        stop = min(n, first + chunk)
        roller_ref, xi_ref = schedule(P, duration, dt, targets, target_times, V, first, stop)
        for k in range(first, stop):
            vals, status = core.read()
            if status < 0:
                break
            s = _control.RigSignals(k, *vals, float(roller_ref[k - first]),
                                    float(xi_ref[k - first]))
            try:
                cmd = controller(s)
            except Exception as exc:
                fail(k, s.t, f"it raised {type(exc).__name__}: {_control.safe_repr(exc, str)}",
                     _core.ERR_CONTROLLER, exc)
            try:
                modes = _control.command(cmd, s)
            except ValueError as exc:                   # named by command()
                fail(k, s.t, str(exc), _core.ERR_CONTROLLER, exc.__cause__)
            except Exception as exc:                    # whatever else reading it raised
                fail(k, s.t, f"reading what it returned raised {type(exc).__name__}: "
                     f"{_control.safe_repr(exc, str)}", _core.ERR_CONTROLLER, exc)
            status = core.write(*modes, math.nan)
            if status < 0:
                fail(k, s.t, f"the rig refused its command {_control.safe_repr(cmd):.80}: "
                     f"{status_message(status)}", status)
            rec, status = core.advance()
            rec[_XI_REF] = s.xi_ref
            if status < 0:
                break
            stepped = k + 1
            worst = max(worst, status)
            warned += status > 0
            if stepped % record_every == 0:
                out[stepped // record_every - 1] = rec
        if progress:
            _progress(stop / n)
        if status < 0:
            out = out[:stepped // record_every]
            break
    return out, stepped, status, worst, warned


def replay(res, *, method=None, nx=None, ny=None, **creep):
    """The seed paper's Fig. 9 procedure: the kinematics recorded in a run
    (a RigResult, e.g. an offline high-accuracy run kept as a database) fed
    sample by sample through a contact model (the real-time one by default:
    the parameters' method and grid) with the recorded normal loads.
    Returns rollerrig.RigContact for every sample; compare its
    left.fx + right.fx with res.fx."""
    from .rig_contact import rig_contact
    from .contact import FallingFriction

    P = res.params
    C, A = P["contact"], P["adhesion"]
    mu0 = P["scenario"]["mu0"]
    patch = (A["patch_mu0"], A["patch_polach_A"], A["patch_polach_B_s_per_m"])
    if (np.any(res.mu_left != mu0) or np.any(res.mu_right != mu0)
            or A["schedule_polach_A"] or A["schedule_polach_B_s_per_m"]
            or (A["patch_length_m"] > 0 and patch != (mu0, C["polach_A"], C["polach_B_s_per_m"]))):
        raise RollerRigError("replay: the run's adhesion changed (its [adhesion] section: "
                             "mu_left, mu_right vary, or A, B do); replay takes one friction "
                             "law, scenario.mu0 with the contact section's")
    friction = (FallingFriction(A=C["polach_A"], B=C["polach_B_s_per_m"])
                if C["friction_law"] == "polach_falling" else None)
    opts = _creep_options("replay", P, method, nx, ny, creep, in_rig=False)
    return rig_contact(_geometry(P), x=res.x, y=res.y, yaw=res.yaw, vx=res.vx, vy=res.vy,
                       yaw_rate=res.yaw_rate, spin=res.spin, roller_spin=res.roller_spin,
                       N_left=res.normal_load_left, N_right=res.normal_load_right,
                       mu=P["scenario"]["mu0"], friction=friction,
                       E=C["youngs_modulus_Pa"], nu=C["poisson_ratio"],
                       vmin=C["min_rolling_speed_m_s"], **opts)



def write_defaults(path=DEFAULTS_PATH):
    """Rewrite rig_default.toml from the C declaration (defaults_toml), as
    every file is written (rollerrig._files.write_file)."""
    from ._files import write_file
    text = defaults_toml()
    return write_file(path, lambda fh: fh.write(text), what="write_defaults: path")
