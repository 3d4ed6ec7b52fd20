"""Wheel-roller geometry (the wing of csrc/geometry/): profiles (profiles),
the wheelset on its rollers or rails, its contact points and tables
(wheelset), equivalent conicity (conicity), the undeformed distance of a
wheel on its roller for the exact theory (patch).  This face hands on the
public names of its rooms."""
from .profiles import DATA_DIR, Profile, read_profile
from .wheelset import (MAX_ROWS, ContactSide, ContactTable, RigGeometry, WheelsetContact,
                       contact_table, wheelset_contact)
from .conicity import CONICITY_METHODS, equivalent_conicity, rolling_radius_difference
from .patch import Patch, PatchShape, patch_shape, undeformed_distance

__all__ = ["Profile", "read_profile", "RigGeometry", "ContactSide", "WheelsetContact",
           "wheelset_contact", "ContactTable", "contact_table", "equivalent_conicity",
           "rolling_radius_difference", "Patch", "undeformed_distance", "PatchShape",
           "patch_shape"]
