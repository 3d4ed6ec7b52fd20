"""The rig in time (the wing of csrc/rig/): its parameters (params), the C
rig built from them (build), a run and its record (run, result), the rig's
contact model over arrays (contact), a controller of the caller's in the
loop (control), one wheel solved by the exact theory (exact), the
non-Hertzian contact's table of the rig's pair (nonhertz_rig).  This face
hands on the public names of its rooms; a private name comes from its room
(rollerrig.rig.params._report_problems, say)."""
from .params import (DEFAULTS_PATH, MAX_DT, MAX_DURATION, MAX_PARAMETER_FILE_BYTES, MIN_DT,
                     ODE_METHODS, PARAMETERS, RETIRED, RigParameter, check_parameters,
                     default_parameters, defaults_toml, load_parameters, write_defaults)
from .result import RECORD, RECORD_FIELDS, RECORD_UNITS, RigResult
from .build import CREEP_OPTIONS, GEOMETRY_KEYS, RIG_METHODS, Rig, build_rig, rig_nonhertz_table
from .run import RECORD_BYTES_CAP, UNTRUSTED_MIN, UNTRUSTED_SHARE, replay, schedule, simulate
from .contact import (LinearCreepages, RigContact, RigPose, WheelContact, linear_creepages,
                      rig_contact)
from .control import CreepageController, RigInfo, RigSignals
from .exact import RigExact, rig_exact

__all__ = ["PARAMETERS", "default_parameters", "load_parameters", "check_parameters", "build_rig",
           "Rig", "simulate", "replay", "RigResult", "RECORD_FIELDS", "RECORD_UNITS",
           "RECORD_BYTES_CAP", "RIG_METHODS",
           # re-exported by rollerrig (rr.rig_contact, ...): public here too
           "LinearCreepages", "RigContact", "RigPose", "WheelContact", "linear_creepages",
           "rig_contact", "CreepageController", "RigInfo", "RigSignals", "RigExact", "rig_exact",
           "rig_nonhertz_table"]
