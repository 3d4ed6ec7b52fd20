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

See rollerrig.contact and rollerrig.profiles for the conventions.

The C core for C programs (rollerrig.capi; docs/c_api.md):

    rr.get_include(), rr.get_library_dir()     # -I ..., -L ... -lrollerrig -lm
    rr.get_source_dir(), rr.get_pkgconfig_dir()
"""
from ._version import __version__
from ._errors import STATUS, RollerRigError, RollerRigWarning, status_message
from .contact import (BOUNDS, METHODS, CreepForces, FallingFriction, HertzContact,
                      KalkerCoefficients, TractionField, creep_forces, fastsim_field, hertz,
                      kalker_coefficients)
from . import profiles
from .profiles import Profile, read_profile
from .geometry import (ContactSide, ContactTable, RigGeometry, WheelsetContact, contact_table,
                       wheelset_contact)
from .conicity import equivalent_conicity, rolling_radius_difference
from .rig import (Rig, RigResult, build_rig, default_parameters, load_parameters, replay,
                  simulate)
from . import control
from .control import CreepageController, RigInfo, RigSignals
from .fit import FitResult, fit_modified_fastsim, fit_polach
from .sweep import sweep, sweep_rig
from .exact import ExactSolution, exact_field, exact_richardson, exact_solve
from .patch import Patch, PatchShape, RigExact, patch_shape, rig_exact, undeformed_distance
from . import reference
from . import exact_table
from .exact_table import ExactTable, build_exact_table
from .rig_contact import (LinearCreepages, RigContact, RigPose, WheelContact, linear_creepages,
                          rig_contact)
from .capi import get_include, get_library_dir, get_pkgconfig_dir, get_source_dir

__all__ = [
    "__version__", "RollerRigError", "RollerRigWarning", "status_message", "STATUS", "METHODS",
    "BOUNDS", "FallingFriction", "HertzContact", "KalkerCoefficients", "CreepForces",
    "TractionField", "hertz", "kalker_coefficients", "creep_forces", "fastsim_field",
    "profiles", "Profile", "read_profile", "RigGeometry", "ContactSide", "WheelsetContact",
    "wheelset_contact", "ContactTable", "contact_table", "RigPose", "WheelContact",
    "RigContact", "rig_contact", "LinearCreepages", "linear_creepages",
    "equivalent_conicity", "rolling_radius_difference", "simulate", "RigResult",
    "default_parameters", "load_parameters", "build_rig", "Rig", "replay", "fit_polach",
    "fit_modified_fastsim", "FitResult", "sweep", "sweep_rig", "reference", "ExactSolution",
    "exact_field", "exact_solve", "exact_richardson", "Patch", "undeformed_distance",
    "PatchShape", "patch_shape", "RigExact", "rig_exact", "exact_table", "ExactTable",
    "build_exact_table", "control", "RigSignals", "RigInfo", "CreepageController",
    "get_include", "get_library_dir", "get_source_dir", "get_pkgconfig_dir",
]
