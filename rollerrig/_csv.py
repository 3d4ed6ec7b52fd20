"""The package's CSV tables: one line of column names, a header of '#'
lines (units, the run's record), then the rows.

    time,creepage,xi_est,...
    # units: s,1,1,...            <- one per column, CF / UDUNITS ("1": dimensionless)
    # rollerrig: 0.1.0
    # method: fastsim
    0.004,0.0001,...

The names come first so that every usual reader still reads the table:
`pandas.read_csv(path, comment="#")`, `numpy.genfromtxt(path,
delimiter=",", names=True)` (which takes its names from the first line,
commented or not), `numpy.loadtxt(path, delimiter=",", skiprows=1)` and
`csv.reader` over the lines not starting with '#'; read_table gives the
header's entries back too.  Each value is
written as Python's repr of the double, the shortest text that reads back
as the same double.
"""
import csv
import math
import os
from typing import Dict, Iterable, List, Mapping, Sequence, TextIO, Tuple, Union

from ._units import cf_unit, read_unit

UNITS_KEY = "units"


def _cell(v: float) -> str:
    v = float(v)
    return repr(v) if math.isfinite(v) else ("nan" if math.isnan(v) else
                                             ("inf" if v > 0 else "-inf"))


def write_table(fh: TextIO, names: Sequence[str], rows: Iterable[Iterable[float]],
                units: Mapping[str, str], meta: Iterable[Tuple[str, object]] = ()) -> None:
    """Write the table to text file `fh`: the names, the units line, `meta`
    ((key, value) pairs, each a "# key: value" line; a value's newlines are
    flattened), the rows (sequences of numbers)."""
    w = csv.writer(fh, lineterminator="\n")
    w.writerow(names)
    fh.write(f"# {UNITS_KEY}: {','.join(cf_unit(units.get(n, '')) for n in names)}\n")
    for key, value in meta:
        fh.write(f"# {key}: {' '.join(str(value).split())}\n")
    for row in rows:
        w.writerow([_cell(v) for v in row])


def read_table(path: Union[str, "os.PathLike[str]"]) -> Tuple[
        List[str], Dict[str, str], Dict[str, str], List[List[float]]]:
    """A table the package wrote (or one written before its header carried
    units: no '#' lines): (names, {name: unit}, {key: value} of the header,
    rows as lists of floats).  Units read in either spelling ("-" is "1")."""
    meta: Dict[str, str] = {}
    lines: List[str] = []
    with open(path, encoding="utf-8", newline="") as fh:
        for line in fh:
            if line.startswith("#"):
                key, sep, value = line[1:].strip().partition(": ")
                if sep:
                    meta[key] = value.strip()
            else:
                lines.append(line)
    reader = csv.reader(lines)
    names = next(reader, [])
    rows = [[float(v) for v in row] for row in reader if row]
    units_text = meta.pop(UNITS_KEY, None)
    units: Dict[str, str] = {}
    if units_text is not None:
        units = dict(zip(names, (read_unit(u) for u in units_text.split(","))))
    return names, units, meta, rows
