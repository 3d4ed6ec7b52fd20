"""Unit strings as the library writes them: CF / UDUNITS-2 spellings that
pint parses too ("1" dimensionless, "N m" a product, "m/s^2" a power).

The C core's tables (csrc/rig/rr_rig_params.c: the rig's record, its
parameters, the per-wheel block) write a dimensionless quantity "-", which
neither CF nor pint reads; every unit the package hands out (a history's
fields, its CSV header, DataFrame and Dataset attributes, the sweeps'
attributes) passes through cf_unit, so the C tables stay as they are and
their "-" never leaves the package.  read_unit takes either spelling back
(a CSV written before the change says "-").
"""

#: the CF / UDUNITS spelling of a dimensionless quantity
DIMENSIONLESS = "1"

# the C tables' spellings that CF does not read, and what it reads instead
_CF = {"-": DIMENSIONLESS, "": ""}


def cf_unit(unit: object) -> str:
    """The CF / UDUNITS spelling of a unit of the C tables: "-" becomes "1";
    "" (a name, a flag or a choice: no unit) stays ""; the others ("m",
    "N m", "kg m^2", "m/s^2", "N m s/rad", ...) are CF's already."""
    unit = str(unit).strip()
    return _CF.get(unit, unit)


def read_unit(text: str) -> str:
    """A unit read back from a file the package wrote, older files included
    (their "-" is "1")."""
    return cf_unit(text)


def is_dimensionless(unit: object) -> bool:
    """Whether `unit` (either spelling) is dimensionless."""
    return cf_unit(unit) == DIMENSIONLESS
