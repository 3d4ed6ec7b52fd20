"""Contact mechanics, over arrays (the wing of csrc/contact/): Hertz,
Kalker's coefficients, the creep-force methods of the C registry and their
traction fields (creep), Kalker's exact theory on any undeformed distance
(exact).  This face hands on the public names of its rooms."""
from .creep import (BOUNDS, METHODS, CreepForces, FallingFriction, HertzContact,
                    KalkerCoefficients, MethodInfo, OptionInfo, TractionField, creep_forces,
                    fastsim_field, hertz, kalker_coefficients)
from .exact import ExactSolution, exact_field, exact_richardson, exact_solve

__all__ = ["METHODS", "BOUNDS", "MethodInfo", "OptionInfo", "FallingFriction", "HertzContact",
           "KalkerCoefficients", "CreepForces", "TractionField", "hertz", "kalker_coefficients",
           "creep_forces", "fastsim_field", "ExactSolution", "exact_field", "exact_solve",
           "exact_richardson"]
