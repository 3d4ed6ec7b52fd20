"""The rig's parameters: the declaration of every parameter (in C,
csrc/rig/rr_rig_params.c: names, units, defaults, ranges, origins), the
parameter files, the defaults (rollerrig/data/rig_default.toml is generated
from the declaration) and the checks of a parameter set.

Parameters are checked as a whole (check_parameters): every unknown key,
every bad value and every documentation-only key given a new value is
reported at once, in one RollerRigError that names the file or `params`.
The values of the rig's rows and the rules between them are judged in C,
once (rr_rig_config_report, through _core.rig_config_report): this module
words each problem it reports (_report_problems), and checks what is the
file's own (unknown and retired keys, sections) and the creep rows (the
registry's, rollerrig.contact).
"""
from __future__ import annotations

import copy
import difflib
import functools
import math
import numbers
import os
import sys
import warnings
from typing import (Any, Callable, Collection, Dict, List, Mapping, NamedTuple, Optional, Tuple,
                    Union)

from .. import _core
from .._errors import RollerRigError, RollerRigWarning
from .._binding import METHODS, creep_options
from . import real_profiles as _real_profiles
# the file's reading, in a room of its own (fmu, analysis read these names here)
from ._param_file import MAX_PARAMETER_FILE_BYTES as MAX_PARAMETER_FILE_BYTES
from ._param_file import _Problems as _Problems, _error as _error, _short as _short
from ._param_file import _read_parameter_file as _read_parameter_file

if sys.version_info >= (3, 11):
    import tomllib
else:                                                   # Python < 3.11
    import tomli as tomllib

DEFAULTS_PATH = os.path.join(os.path.dirname(os.path.dirname(__file__)), "data",
                             "rig_default.toml")

#: the merged parameters: {section: {key: value}}
_Merged = Dict[str, Dict[str, Any]]
#: a value's check: None where it is good, else what it must be, in words
_Check = Callable[[object], Optional[str]]


class RigParameter(NamedTuple):
    """A row of the rig's parameter declaration (csrc/rig/rr_rig_params.c)."""
    name: str           #: "section.key" of rig_default.toml
    unit: str           #: "-" dimensionless, "" a name or a flag
    type: str           #: "real", "int", "flag", "choice" or "list"
    #: float, int, bool, str or tuple of floats (None: a creep row)
    default: Union[None, float, int, bool, str, Tuple[float, ...]]
    lo: float           #: lower bound of a real, an int or each entry of a list
    hi: float           #: upper bound (as lo)
    lo_open: bool       #: whether the lower bound is excluded
    hi_open: bool       #: whether the upper bound is excluded
    choices: Tuple[str, ...]  #: the names of a choice
    text: Optional[str]  #: the default as TOML text (None: a choice, its name)
    creep: bool         #: the creep-force method or an option of it (rollerrig.contact.creep)
    origin: str         #: where the default comes from
    option: Optional[str]  #: a creep row's option of the method ("nx"; None: not one)


#: every parameter of the rig, declared once in C: name, unit, type,
#: default, range, origin (rig_default.toml is generated from it)
PARAMETERS = tuple(RigParameter(*row) for row in _core.RIG_PARAMETERS)
_PARAMETER = {p.name: p for p in PARAMETERS}

#: the integrators of integration.method
ODE_METHODS = _PARAMETER["integration.method"].choices
#: control sample time [s], simulated time [s] (27.8 h)
MIN_DT, MAX_DT = _PARAMETER["scenario.control_sample_time_s"][4:6]
MAX_DURATION = _PARAMETER["scenario.duration_s"].hi


# ------------------------------------------------------------------ reading files
# (the reading itself: rollerrig.rig._param_file)

def load_parameters(path: Union[str, os.PathLike[str]]) -> Dict[str, Dict[str, Any]]:
    """A parameter file as a nested dict, not yet checked.

    Parameters
    ----------
    path : str or path-like
        A TOML file of the layout of rig_default.toml, any subset of it.

    Returns
    -------
    dict
        The nested dict as read (:func:`check_parameters` checks it).

    Raises
    ------
    RollerRigError
        Naming the file and why: missing, a directory or FIFO, over 1 MiB,
        not UTF-8, not TOML, nested too deeply.

    See Also
    --------
    check_parameters : the values checked and merged with the defaults.
    """
    try:
        return _read_parameter_file(path)
    except _Problems as p:
        raise _error(f"load_parameters: {os.fspath(path)}", p.problems) from None


def _default_value(p: RigParameter) -> Any:
    if p.default is None:                        # a creep row: its TOML text
        return tomllib.loads(f"v = {p.text}")["v"]
    return list(p.default) if p.type == "list" and isinstance(p.default, tuple) else p.default


@functools.lru_cache(maxsize=1)
def _defaults() -> _Merged:
    """The defaults as a nested dict, from the C declaration (PARAMETERS)."""
    D: _Merged = {}
    for p in PARAMETERS:
        section, key = p.name.split(".")
        D.setdefault(section, {})[key] = _default_value(p)
    return D


def defaults_toml() -> str:
    """The text of rollerrig/data/rig_default.toml.

    Returns
    -------
    str
        The declaration of PARAMETERS (csrc/rig/rr_rig_params.c) with every
        origin as a comment.

    Notes
    -----
    tests/test_rig_params.py checks that the shipped file equals it;
    :func:`write_defaults` rewrites it.
    """
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


def _wrap(text: str, width: int) -> List[str]:
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


def default_parameters() -> Dict[str, Dict[str, Any]]:
    """The default parameter set.

    Returns
    -------
    dict
        A fresh nested dict (change it freely), the layout of
        rig_default.toml.

    See Also
    --------
    check_parameters : these overridden by a nested dict, checked.
    """
    return copy.deepcopy(_defaults())


# ------------------------------------------------------------------ checking parameters

def _range_text(lo: float, hi: float, lo_open: bool, hi_open: bool) -> str:
    """" >= 0", " in (0, 1]" or "" (no bound): a range as the messages write it."""
    if lo == -math.inf and hi == math.inf:
        return ""
    if hi == math.inf:
        return f" {'>' if lo_open else '>='} {lo:g}"
    return f" in {'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}"


def _real(lo: float = -math.inf, hi: float = math.inf, lo_open: bool = False,
          hi_open: bool = False) -> _Check:
    """A check: a finite real number in the interval (for an argument that
    is no parameter of the rig; a parameter's range is checked in C, by
    rig_config_report)."""
    need = _range_text(lo, hi, lo_open, hi_open)

    def check(v: object) -> Optional[str]:
        ok = isinstance(v, numbers.Real) and not isinstance(v, bool)
        if isinstance(v, numbers.Real) and ok:
            try:
                x = float(v)
            except OverflowError:                        # an int beyond a double
                ok = False
            else:
                ok = (math.isfinite(x) and (x > lo if lo_open else x >= lo)
                      and (x < hi if hi_open else x <= hi))
        return None if ok else f"must be a finite number{need}"
    return check


def _integer(lo: float, hi: float) -> _Check:
    def check(v: object) -> Optional[str]:
        # (numbers.Real's stub declares no comparison with a float on the left)
        ok = (isinstance(v, numbers.Integral) and not isinstance(v, bool)
              and lo <= v <= hi)                            # type: ignore[operator]
        return None if ok else f"must be an integer from {lo} to {hi}"
    return check


def _choice(*values: str) -> _Check:
    shown = " or ".join(repr(v) for v in values)

    def check(v: object) -> Optional[str]:
        return None if isinstance(v, str) and v in values else f"must be {shown}"
    return check


def _need(p: RigParameter) -> str:
    """What a value of row p must be, in words: its declared type and range
    (the message of rig_config_report's "range" problem, which checks it)."""
    within = _range_text(p.lo, p.hi, p.lo_open, p.hi_open)
    if p.type == "real":
        return f"must be a finite number{within}"
    if p.type == "int":
        return f"must be an integer from {int(p.lo)} to {int(p.hi)}"
    if p.type == "flag":
        return "must be true or false"
    if p.type == "choice":
        return "must be " + " or ".join(map(repr, p.choices))
    # a list whose default is empty may be empty (rr_rig_params.h)
    return (f"must be a {'' if not p.default else 'non-empty '}list of at most "
            f"{_core.RIG_MAX_LIST} numbers{within}")


#: the parameter file's keys (contact section) that set a creep-force option:
#: key -> the option's name in the registry (rollerrig.METHODS), as each
#: creep row declares it (its option column, csrc/rig/rr_rig_params.c, which
#: the C rig and the FMU read too); each is given to the chosen method where
#: it has that option, and checked as the registry says
_FILE_OPTIONS = {p.name.split(".", 1)[1]: p.option for p in PARAMETERS if p.option}


def _option_rule(name: str) -> _Check:
    """A parameter check from the registry's option `name` (its range or names)."""
    op = next(m.options[name] for m in METHODS.values() if name in m.options)
    if op.type == "choice":
        return _choice(*op.choices)
    assert op.lo is not None and op.hi is not None      # a number's range (not a choice's)
    if op.type == "int":
        return _integer(op.lo + op.lo_open, op.hi - op.hi_open)
    return _real(op.lo, op.hi, lo_open=op.lo_open, hi_open=op.hi_open)


#: the checks of the creep rows (the creep-force method and its options,
#: from the registry: rollerrig.contact's, not the rig's configuration); every
#: other row is checked by the C report (_report_problems)
_CREEP_RULES = {"contact.creep_method": _choice(*METHODS),
                **{f"contact.{key}": _option_rule(o) for key, o in _FILE_OPTIONS.items()}}

_SAMPLE_TIME = "scenario.control_sample_time_s"
#: the report's rules that read the sample time: judged for a run, at its dt
#: (build._build, simulate), not in a parameter set, whose sample time a
#: run's dt replaces
_RUN_RULES = ("loop", "sample")
#: a count rule's request, by the list the row must match
_ONE_PER = {"scenario.targets": "one start time per target",
            "adhesion.schedule_times_s": "one per time",
            "disturbance.lateral_force_times_s": "one per time"}


def _c_values(P: Mapping[str, Mapping[str, Any]]) -> Dict[str, Any]:
    """{"section.key": value} of the merged parameters' rig rows (not the
    creep rows): the C configuration (rr_rig_config) they make."""
    out = {p.name: P[p.name.split(".")[0]][p.name.split(".")[1]] for p in PARAMETERS
           if not p.creep}
    for section, keys in _real_profiles.PROFILE_ROWS.items():
        for key in keys:
            name = f"{section}.{key}"
            out[name] = _real_profiles.c_value(section, key, out[name])
    # a table file's path is the C rig's "file" (rollerrig reads it: nonhertz_rig)
    v = out[_NH_TABLE]
    if isinstance(v, str) and v:
        out[_NH_TABLE] = "file"
    return out


_NH_TABLE = "contact.nonhertz_table"


def _nonhertz_problems(P: Mapping[str, Mapping[str, Any]]) -> List[str]:
    """contact.nonhertz_table: "" (built) or a file's path (read at the run)."""
    v = P["contact"]["nonhertz_table"]
    if not isinstance(v, str):
        return [f"{_NH_TABLE} must be '' (built from the rig's profiles) or a table file's "
                f"path (rollerrig.rig_nonhertz_table), got {_short(v)}"]
    return []


def _loop_sentence(name: Optional[str], values: Mapping[str, Any], drive: int, rho: float,
                   lo: float, hi: float) -> str:
    """A drive's sampled speed loop unstable at the sample time: the drive,
    the settings its loop depends on, its pole and the sample times at
    which it is stable (rr_speed_loop_range)."""
    v: Callable[[str], Any] = values.get
    if drive == 0:
        text = (f"roller_drive.kp_N_m_s_per_rad = {v('roller_drive.kp_N_m_s_per_rad'):g}, "
                f"ki_N_m_s_per_rad = {v('roller_drive.ki_N_m_s_per_rad'):g} and "
                f"lag_time_constant_s = {v('roller_drive.lag_time_constant_s'):g} on "
                f"roller.inertia_kg_m2 = {v('roller.inertia_kg_m2'):g}")
    else:
        text = (f"wheelset_drive.kp_N_m_s_per_rad = {v('wheelset_drive.kp_N_m_s_per_rad'):g}, "
                f"ki_N_m_s_per_rad = {v('wheelset_drive.ki_N_m_s_per_rad'):g} and "
                f"lag_time_constant_s = {v('wheelset_drive.lag_time_constant_s'):g} on "
                f"wheelset.spin_inertia_kg_m2 + wheelset_drive.drive_inertia_kg_m2 = "
                f"{v('wheelset.spin_inertia_kg_m2') + v('wheelset_drive.drive_inertia_kg_m2'):g}"
                f", within eq. 13's creepage_controller.alpha = "
                f"{v('creepage_controller.alpha'):g}")
    where = (f"it is stable for sample times from {lo:.3g} to {hi:.3g} s" if not math.isnan(lo)
             else f"it is stable at no sample time from {MIN_DT:g} to {MAX_DT:g} s")
    return (f"{name} = {v(_SAMPLE_TIME):g} s: the {('roller', 'wheelset')[drive]} drive's "
            f"sampled speed loop ({text}) is unstable at this sample time (its largest "
            f"closed-loop pole |z| = {rho:.4g}); {where}")


def _report_problems(values: Dict[str, Any], names: Optional[Mapping[str, str]] = None,
                     skip: Collection[str] = (),
                     about: Optional[Collection[str]] = None) -> List[str]:
    """Sentences for the problems of the C configuration `values`
    ({"section.key": value}, rig rows only; the rest at their defaults), as
    rr_rig_config_report finds them (csrc/rig/rr_rig_params.h: every rule of
    a configuration is there, and only there), each naming its keys.

    names: {"section.key": the argument that gave it} (simulate's dt, ...):
        the message names that instead, with the row's unit after its range;
    skip:  rules not judged here (_RUN_RULES in a parameter set);
    about: only problems wholly about these keys (the key, and the other
        row if any), where the rest of `values` is not yet the run's."""
    given = names or {}

    def name(key: Optional[str]) -> Optional[str]:
        return key if key is None else given.get(key, key)
    out = []
    for key, _, rule, other, entry, value, lo, hi in _core.rig_config_report(values):
        if rule in skip or (about is not None and not {key, other} - {None} <= set(about)):
            continue
        v, p = values.get(key), _PARAMETER[key]
        if rule == "range":
            unit = f" {p.unit}" if key in given and p.unit not in ("", "-") else ""
            out.append(f"{name(key)} {_need(p)}{unit}, got {_short(v)}")
        elif rule == "count":
            empty = ", or none" if lo == 0 else ""     # lo 0: none is allowed too
            out.append(f"{name(key)} has {value:g} entries but {name(other)} has {hi:g}: give "
                       f"{_ONE_PER.get(other or '', f'one per entry of {name(other)}')}{empty}")
        elif rule == "increasing":
            out.append(f"{name(key)} must increase, got {_short(v)}")
        elif rule == "nondecreasing":
            out.append(f"{name(key)} must not decrease (two equal times make a step), got "
                       f"{_short(v)}")
        elif rule == "before":
            out.append(f"{name(key)} must fall inside {name(other)} = {hi:g} s, got "
                       f"{_short(v)}")
        elif rule == "sample":
            out.append(f"{name(key)} = {value:g} s is shorter than one sample ({name(other)} = "
                       f"{lo:g} s)")
        elif rule == "circumference":
            out.append(f"{name(key)} must be at most the roller's circumference 2 pi "
                       f"{name(other)} = {hi:.6g} m, got {_short(v)}")
        elif rule == "loop":
            out.append(_loop_sentence(name(key), values, entry, value, lo, hi))
        elif rule == "sum":
            out.append(f"{name(key)} + {name(other)} must be a finite number (the wheelset's "
                       f"inertia with its drive's), got {_short(v)} + "
                       f"{_short(values.get(other) if other else None)}")
        else:                                   # a rule this module has no words for yet
            out.append(f"{name(key)} = {_short(v)} breaks the rig's rule {rule!r}"
                       f"{f' with {name(other)}' if other else ''}")
    return out


def _creep_problems(C: Mapping[str, Any]) -> List[str]:
    """Sentences for the creep rows of the contact section C: each value as
    the registry declares it, then, where those are good, each method's own
    rule between its options (the registry's check: Polach's kS <= kA) for
    the options the file sets."""
    problems = []
    for name, rule in _CREEP_RULES.items():
        need = rule(C[name.split(".")[1]])
        if need:
            problems.append(f"{name} {need}, got {_short(C[name.split('.')[1]])}")
    if problems:
        return problems
    for method, info in METHODS.items():
        given = {key: o for key, o in _FILE_OPTIONS.items() if o in info.options}
        if len(given) < 2:
            continue                             # no rule between options
        try:
            creep_options("", method, {o: C[key] for key, o in given.items()})
        except RollerRigError as e:
            # the registry's words ("kS must satisfy 0 < kS <= kA <= 1
            # (method 'polach'), got ...") with the file's keys
            words = str(e).split(": ", 1)[-1].split(", got ", 1)[0]
            option, _, rest = words.partition(" ")
            key = next((f"contact.{k}" for k, o in given.items() if o == option), option)
            values = ", ".join(f"contact.{k} = {C[k]!r}" for k in given)
            problems.append(f"{key} {rest}, got {values}")
    return problems


#: keys (or whole sections) the parameters no longer have, since they acted
#: on nothing, with what sets the quantity instead (csrc/rig/rr_rig_params.c):
#: giving one is refused with that reason
RETIRED = dict(_core.RIG_RETIRED)


def _retired(name: str) -> Optional[str]:
    return RETIRED.get(name) or RETIRED.get(name.split(".", 1)[0])


def _merge(base: Dict[str, Any], over: Mapping[Any, Any], problems: List[str],
           where: str = "") -> None:
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


def _check_values(P: _Merged) -> List[str]:
    """Sentences for every value of the merged parameters that breaks its
    rule, then for the rules between keys: the rig rows by the C report
    (but for the rules a run judges at its dt), the creep rows by the
    registry."""
    profiles = _real_profiles.problems(P) + _nonhertz_problems(P)
    values = _c_values(P)
    if profiles:                       # the C rows of a bad one judged at their default
        for section, keys in _real_profiles.PROFILE_ROWS.items():
            for key in keys:
                values[f"{section}.{key}"] = _defaults()[section][key]
        values[_NH_TABLE] = _defaults()["contact"]["nonhertz_table"]
    return profiles + _report_problems(values, skip=_RUN_RULES) + _creep_problems(P["contact"])


def check_parameters(params: Optional[Mapping[str, Any]] = None, *,
                     source: str = "check_parameters: params") -> Dict[str, Dict[str, Any]]:
    """The default parameters overridden by `params`, every value checked.

    Parameters
    ----------
    params : dict, optional
        A nested dict as the layout of rig_default.toml, any subset of it
        (None: the defaults).
    source : str, optional
        The prefix of the error's message.

    Returns
    -------
    dict
        The merged nested dict.

    Raises
    ------
    RollerRigError
        One error, prefixed by `source`, that lists every problem at once:
        params not a nested dict, unknown keys, values out of range (the
        message names the key, the range and the value), a section given a
        value or the reverse, the lengths and order of scenario.targets /
        target_start_s, and a key the parameters no longer have (RETIRED:
        the similarity law, the full-scale reference, the gear ratios,
        ...): such a key acted on nothing.

    Warns
    -----
    RollerRigWarning
        The default target start times scaled to fit a
        scenario.duration_s given without scenario.target_start_s.

    See Also
    --------
    load_parameters : a parameter file as a nested dict.
    default_parameters : the defaults.

    Examples
    --------
    >>> from rollerrig.rig import check_parameters
    >>> P = check_parameters({"scenario": {"mu0": 0.3}})
    >>> P["scenario"]["mu0"], P["roller"]["radius_m"]
    (0.3, 0.16)
    >>> check_parameters({"scenario": {"mu0": -1}})
    Traceback (most recent call last):
    ...
    rollerrig._errors.RollerRigError: ...: scenario.mu0 must be a finite number in (0, ...], got -1
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


def _parameter_problems(params: Optional[Mapping[str, Any]]) -> Tuple[_Merged, List[str]]:
    """(the merged parameters, the list of their problems) of a nested dict."""
    P = default_parameters()
    problems: List[str] = []
    if params:
        _merge(P, copy.deepcopy(params), problems)
        _scale_starts(params, P)
    return P, problems + _check_values(P)


def _default_starts_scaled(params: object, P: _Merged) -> Optional[List[float]]:
    """The default start times scaled to scenario.duration_s where params
    set that duration (valid) but not scenario.target_start_s, and the
    defaults do not all fall inside it; else None.  Also None where the
    scaled times would no longer increase (a duration so short that they
    round to equal times): the defaults are then kept, and the check that
    start times fall inside the duration names scenario.duration_s."""
    S = params.get("scenario") if isinstance(params, dict) else None
    if not (isinstance(S, dict) and "duration_s" in S and "target_start_s" not in S):
        return None
    duration = P["scenario"]["duration_s"]
    if not _in_range("scenario.duration_s", duration):
        return None
    D = _defaults()["scenario"]
    if D["target_start_s"][-1] < duration:
        return None
    scale = duration / D["duration_s"]
    scaled = [x * scale for x in D["target_start_s"]]
    return scaled if all(b > a for a, b in zip(scaled, scaled[1:])) else None


def _scale_starts(params: object, P: _Merged) -> None:
    """One rule for a duration too short for the target start times, whether
    scenario.duration_s or simulate's duration gives it: start times the
    caller did not give (the defaults, written for the default duration)
    are scaled to the duration, as simulate(duration=...) scales the
    scenario's (_target_schedule); start times given with a duration they do
    not fit are refused (_check_values)."""
    scaled = _default_starts_scaled(params, P)
    if scaled is not None:
        P["scenario"]["target_start_s"] = scaled


def _scaled_starts(params: object, P: _Merged) -> str:
    """The warning's text where _scale_starts scaled the start times, else ""."""
    if _default_starts_scaled(params, P) is None:
        return ""
    D = _defaults()["scenario"]
    return (f"the default target start times {D['target_start_s']} s (for the default "
            f"scenario.duration_s = {D['duration_s']:g} s; scenario.target_start_s not given) "
            f"do not all fall inside scenario.duration_s = {P['scenario']['duration_s']:g} s: "
            f"scaled by {P['scenario']['duration_s'] / D['duration_s']:g} to "
            f"{[float(f'{x:.6g}') for x in P['scenario']['target_start_s']]} s")


def _parameters(func: str, params: object) -> _Merged:
    """The checked parameters of a call: params None, a dict, or a file path."""
    if params is None:
        return default_parameters()
    if isinstance(params, (str, os.PathLike)):
        source = f"{func}: params {os.fspath(params)}"
        params_path = os.fspath(params)
        try:
            params = _read_parameter_file(params)
        except _Problems as p:
            raise _error(source, p.problems) from None
        # profile files named relative to the scenario file
        _real_profiles.relative_to(params, os.path.dirname(os.path.abspath(params_path)))
        return check_parameters(params, source=source)
    if not isinstance(params, dict):
        raise RollerRigError(f"{func}: params must be a nested dict or the path of a TOML "
                             f"file, got {type(params).__name__}")
    return check_parameters(params, source=f"{func}: params")


def _real_arg(func: str, name: str, v: object, lo: float = -math.inf, hi: float = math.inf,
              lo_open: bool = False, unit: str = "") -> float:
    need = _real(lo, hi, lo_open=lo_open)(v)
    if need or not isinstance(v, numbers.Real):        # (no need: v is a real number)
        raise RollerRigError(f"{func}: {name} {need}{' ' + unit if unit else ''}, "
                             f"got {_short(v)}")
    return float(v)


def _in_range(key: str, value: object) -> bool:
    """Whether rig row `key` takes `value` (its declared type and range, as
    the C report's "range" rule judges them)."""
    return not any(k == key and rule == "range"
                   for k, _, rule, *_ in _core.rig_config_report({key: value}))


def _check_run(func: str, P: Mapping[str, Mapping[str, Any]], run: Mapping[str, Any],
               names: Optional[Mapping[str, str]] = None,
               about: Optional[Collection[str]] = None,
               skip: Collection[str] = ()) -> Dict[str, Any]:
    """The C configuration of a run: the checked parameters' rig rows with
    the run's own values in their place (run: {"section.key": value}, its
    sample time, duration, targets, ...).  Raises one RollerRigError,
    prefixed by func, for all its problems (_report_problems; names: the
    arguments that gave run's values), or only those wholly `about` some
    keys, and not of the rules `skip`, where the rest of the run is not yet
    known."""
    values = {**_c_values(P), **run}
    problems = _report_problems(values, names, skip=skip, about=about)
    if problems:
        raise _error(func, problems)
    return values


def write_defaults(path: Union[str, os.PathLike[str]] = DEFAULTS_PATH
                   ) -> Union[str, os.PathLike[str]]:
    """Rewrite rig_default.toml from the C declaration (:func:`defaults_toml`).

    Written as every file is (rollerrig._files.write_file).

    Parameters
    ----------
    path : str or path-like, optional
        The file (default the shipped rig_default.toml, DEFAULTS_PATH).

    Returns
    -------
    str or path-like
        The path written.
    """
    from .._files import write_file
    text = defaults_toml()
    return write_file(path, lambda fh: fh.write(text), what="write_defaults: path")


# ------------------------------------------------------------ track mode
# (issue 25, docs/lateral_dynamics.md)

#: the radius [m] that stands for the rail's infinite one in track mode:
#: csrc/rig/rr_rig.h's RR_RIG_TRACK_RADIUS (tests/test_lateral_track.py
#: reads the header); the rollers' effects on the lateral dynamics scale as
#: r0/R, 9.2e-5 for the scaled wheelset
TRACK_RADIUS_M = 1000.0
_ENCODER_MAX = 2147483647


def _with_track(func: str, P: _Merged, track: Optional[bool] = None) -> _Merged:
    """The checked parameters P on track (track True, or None and
    scenario.track true) or on the rig (track False): on track the rollers
    become the rail, a roller of radius TRACK_RADIUS_M whose speed the plant
    holds (csrc/rig/rr_rig.h, track), with its encoder's counts scaled by the
    radius (at most 2^31 - 1) so that it resolves the same surface speed.
    A new dict where anything changes; P itself otherwise."""
    if track is None:
        track = bool(P["scenario"].get("track", False))
    elif not isinstance(track, bool):
        raise RollerRigError(f"{func}: track must be True or False, got {_short(track)}")
    if not track:
        if P["scenario"].get("track", False):
            P = copy.deepcopy(P)
            P["scenario"]["track"] = False
        return P
    if P["scenario"].get("track", False) and float(P["roller"]["radius_m"]) == TRACK_RADIUS_M:
        return P
    Q = copy.deepcopy(P)
    R0 = float(Q["roller"]["radius_m"])
    Q["scenario"]["track"] = True
    Q["roller"]["radius_m"] = TRACK_RADIUS_M
    counts = int(Q["roller_drive"]["encoder_counts_per_rev"])
    Q["roller_drive"]["encoder_counts_per_rev"] = int(min(_ENCODER_MAX,
                                                          round(counts * TRACK_RADIUS_M / R0)))
    return Q
