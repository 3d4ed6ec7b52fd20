"""Reference files: NAME.npz (what the comparison reads: every field as
stored, bit for bit, with the units and the writer's record as JSON under
the key "__rollerrig__") and NAME.csv beside it (for a person: the same
numbers as text, read by pandas and numpy too; rollerrig._csv)."""
from __future__ import annotations

import json
import os
from typing import Any, BinaryIO, Dict, Iterable, List, Mapping, Optional, TextIO, Tuple

import numpy as np
import numpy.typing as npt

from .._csv import write_table
from .._errors import RollerRigError
from .._files import write_file
from .._units import cf_unit
from .._version import __version__

META_KEY = "__rollerrig__"
FORMAT = 1


def write_reference(base: str, fields: Mapping[str, npt.NDArray[Any]],
                    units: Optional[Mapping[str, str]] = None, x: Optional[str] = None,
                    meta: Optional[Iterable[Tuple[str, object]]] = None) -> Tuple[str, str]:
    """Write base + ".npz" and base + ".csv" (folders made as needed);
    returns both paths.  fields: {name: ndarray}; units {name: unit}; x the
    field that is the abscissa (time, creepage) if any; meta: more (key,
    value) lines for the CSV's header."""
    written = {n: cf_unit(units.get(n, "")) for n in fields} if units else {n: "" for n in fields}
    record = {"format": FORMAT, "rollerrig": __version__, "fields": list(fields),
              "units": written, "x": x}
    os.makedirs(os.path.dirname(os.path.abspath(base)), exist_ok=True)
    npz, csv_path = base + ".npz", base + ".csv"

    # (Any: numpy's stubs take **kwds beside a keyword allow_pickle: bool)
    arrays: Mapping[str, Any] = fields
    meta_array: Dict[str, Any] = {META_KEY: np.array(json.dumps(record))}

    def write_npz(fh: BinaryIO) -> None:
        np.savez_compressed(fh, **arrays, **meta_array)
    write_file(npz, write_npz, what="rollerrig.testing: reference", binary=True)
    header: List[Tuple[str, object]] = [("written by", f"rollerrig {__version__} (rollerrig.testing); the comparison "
                             f"reads {os.path.basename(npz)}, this file is for reading")]
    header += list(meta or ())
    write_file(csv_path, lambda fh: _write_csv(fh, fields, written, header),
               what="rollerrig.testing: reference")
    return npz, csv_path


def _write_csv(fh: TextIO, fields: Mapping[str, npt.NDArray[Any]], units: Mapping[str, str],
               header: List[Tuple[str, object]]) -> None:
    """One column per field when every field is 1-D of one length (a
    history, a curve); else long form: field, index, value."""
    arrays = list(fields.values())
    if all(a.ndim == 1 for a in arrays) and len({a.shape for a in arrays}) == 1:
        write_table(fh, list(fields), zip(*arrays), units, header)
        return
    rows = ([k, *np.unravel_index(i, a.shape), v] if a.ndim > 1 else [k, i, v]
            for k, (name, a) in enumerate(fields.items()) for i, v in enumerate(a.ravel()))
    header = header + [("long form", "field_number is the position in: "
                        + ", ".join(f"{k} {n} [{units[n]}]" for k, n in enumerate(fields))
                        + "; index (the flat index, or one column per axis), value")]
    width = max(a.ndim for a in arrays)
    names = ["field_number"] + [f"index_{d}" for d in range(max(width, 1))] + ["value"]
    padded = ([r[0], *r[1:-1], *([-1] * (width - len(r) + 2)), r[-1]] for r in rows)
    write_table(fh, names, padded, {}, header)


def read_reference(base: str) -> Optional[Tuple[Dict[str, npt.NDArray[Any]], Dict[str, Any]]]:
    """(fields {name: ndarray}, record {"units", "x", "rollerrig", ...}) of
    base + ".npz"; None when there is none."""
    path = base + ".npz"
    if not os.path.exists(path):
        return None
    try:
        with np.load(path, allow_pickle=False) as z:
            record = json.loads(str(z[META_KEY])) if META_KEY in z.files else {}
            order = record.get("fields") or [n for n in z.files if n != META_KEY]
            fields = {n: z[n] for n in order}
    except (OSError, ValueError, KeyError) as e:
        raise RollerRigError(f"rollerrig.testing: reference {path} does not read "
                             f"({type(e).__name__}: {e}); rewrite it with --rr-regen") from None
    return fields, record
