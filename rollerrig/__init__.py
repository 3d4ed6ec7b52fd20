"""rollerrig: real-time simulation of a scaled railway roller rig.

The contact core (C99, vectorised, GIL released):

    import rollerrig as rr
    h = rr.hertz(A, B, N)                      # h.a, h.b [m], h.p0 [Pa], h.delta [m]
    k = rr.kalker_coefficients(a_over_b, nu)   # k.c11, k.c22, k.c23, k.c33
    f = rr.creep_forces(cx, cy, cphi, a=..., b=..., N=..., mu=..., method="fastsim")
    t = rr.fastsim_field(cx, cy, cphi, a=..., b=..., N=..., mu=...)

Profiles (numpy only):

    w = rr.Profile.s1002(); r = rr.Profile.uic60()
    p = rr.read_profile("wheel.whl")           # .prw/.prr, .whl/.ban, .txt/.csv/.dat
    p.z_at(y), p.slope(y), p.curvature(y)      # y, z in m; z downward

See rollerrig.contact.creep and rollerrig.geometry.profiles for the conventions.

The C core for C programs (rollerrig.capi; docs/c_api.md):

    rr.get_include(), rr.get_library_dir()     # -I ..., -L ... -lrollerrig -lm
    rr.get_source_dir(), rr.get_pkgconfig_dir()
"""
import importlib as _importlib
import sys as _sys

from ._version import __version__
from ._errors import STATUS, RollerRigError, RollerRigWarning, status_message
# the wings, as the C core's (csrc/): contact < geometry < rig, and the
# studies over them (analysis); each imports only those before it
from .contact import (BOUNDS, METHODS, CreepForces, ExactSolution, FallingFriction, HertzContact,
                      KalkerCoefficients, TractionField, creep_forces, exact_field,
                      exact_richardson, exact_solve, fastsim_field, hertz, kalker_coefficients)
from .geometry import profiles
from .geometry.nonhertz import NonHertzSide, NonHertzTable, nonhertz_table
from .geometry import (ContactSide, ContactTable, Patch, PatchShape, Profile, RigGeometry,
                       WheelsetContact, contact_table, equivalent_conicity, patch_shape,
                       read_profile, rolling_radius_difference, undeformed_distance,
                       wheelset_contact)
from .rig import control
from .rig import (CreepageController, LinearCreepages, Rig, RigContact, RigExact, RigInfo,
                  RigPose, RigResult, RigSignals, WheelContact, build_rig, default_parameters,
                  linear_creepages, load_parameters, replay, rig_contact, rig_exact,
                  rig_nonhertz_table, simulate)
from .analysis import exact_table, reference
from .analysis.exact_table import ExactTable, build_exact_table
from .analysis.fit import FitResult, fit_modified_fastsim, fit_polach
from .analysis.sweep import sweep, sweep_rig
from .capi import get_include, get_library_dir, get_pkgconfig_dir, get_source_dir
# lateral dynamics and stability (issue 25)
from .analysis.stability import (Linearization, Mode, Stability, critical_speed, linearize,
                                 stability)
from .analysis.hunting import Hunting, hunting

#: the modules that moved into a wing, by their old names: `import
#: rollerrig.sweep`, `from rollerrig.profiles import Profile` and the like
#: still give the same module objects (no file stands at the old paths).
#: rollerrig.patch is the undeformed distance alone: rig_exact and RigExact
#: are rollerrig.rig.exact's (rr.rig_exact as before)
_MOVED = {
    "exact": "contact.exact",
    "profiles": "geometry.profiles",
    "conicity": "geometry.conicity",
    "patch": "geometry.patch",
    "rig_contact": "rig.contact",
    "control": "rig.control",
    "sweep": "analysis.sweep",
    "fit": "analysis.fit",
    "reference": "analysis.reference",
    "exact_table": "analysis.exact_table",
}
for _old, _new in _MOVED.items():
    _module = _importlib.import_module(f"{__name__}.{_new}")
    _sys.modules.setdefault(f"{__name__}.{_old}", _module)
    globals().setdefault(_old, _module)      # rr.sweep, rr.rig_contact stay the functions
del _old, _new, _module

__all__ = [
    "__version__", "RollerRigError", "RollerRigWarning", "status_message", "STATUS", "METHODS",
    "BOUNDS", "FallingFriction", "HertzContact", "KalkerCoefficients", "CreepForces",
    "TractionField", "hertz", "kalker_coefficients", "creep_forces", "fastsim_field",
    "profiles", "NonHertzSide", "NonHertzTable", "nonhertz_table", "Profile", "read_profile", "RigGeometry", "ContactSide", "WheelsetContact",
    "wheelset_contact", "ContactTable", "contact_table", "RigPose", "WheelContact",
    "RigContact", "rig_contact", "LinearCreepages", "linear_creepages",
    "equivalent_conicity", "rolling_radius_difference", "simulate", "RigResult",
    "default_parameters", "load_parameters", "build_rig", "Rig", "replay", "fit_polach",
    "fit_modified_fastsim", "FitResult", "sweep", "sweep_rig", "reference", "ExactSolution",
    "exact_field", "exact_solve", "exact_richardson", "Patch", "undeformed_distance",
    "PatchShape", "patch_shape", "RigExact", "rig_exact", "exact_table", "ExactTable",
    "rig_nonhertz_table",
    "build_exact_table", "control", "RigSignals", "RigInfo", "CreepageController",
    "get_include", "get_library_dir", "get_source_dir", "get_pkgconfig_dir",
    # lateral dynamics and stability (issue 25)
    "linearize", "Linearization", "Mode", "stability", "Stability", "critical_speed",
    "hunting", "Hunting",
]
