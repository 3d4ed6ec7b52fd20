"""The rig in time (csrc/rig/): its parameters (params), the C rig built
from them (build), a run and its record (run, result).

    import rollerrig as rr
    res = rr.simulate()                           # the paper's scenario
    rig, P, table = rr.build_rig()                # the rig stepped by hand

rollerrig.rig hands on the public names of its rooms; a name of its own
comes from its room (rollerrig.rig.params._RULES, say).
"""
from .params import (DEFAULTS_PATH, MAX_DT, MAX_DURATION, MAX_PARAMETER_FILE_BYTES, MIN_DT,
                     ODE_METHODS, PARAMETERS, RETIRED, RigParameter, check_parameters,
                     default_parameters, defaults_toml, load_parameters, write_defaults)
from .result import RECORD, RECORD_FIELDS, RECORD_UNITS, RigResult
from .build import CREEP_OPTIONS, GEOMETRY_KEYS, RIG_METHODS, Rig, build_rig
from .run import RECORD_BYTES_CAP, UNTRUSTED_MIN, UNTRUSTED_SHARE, replay, schedule, simulate

__all__ = ["PARAMETERS", "default_parameters", "load_parameters", "check_parameters", "build_rig", "Rig",
           "simulate", "replay", "RigResult", "RECORD_FIELDS", "RECORD_UNITS",
           "RECORD_BYTES_CAP", "RIG_METHODS"]
