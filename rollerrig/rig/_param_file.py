"""Reading a parameter file (rollerrig.rig.params' first half): only a
regular file of at most MAX_PARAMETER_FILE_BYTES of UTF-8 TOML, its problems
as sentences (_Problems) that the public functions turn into one
RollerRigError (_error)."""
from __future__ import annotations

import os
import stat
import sys
from typing import Any, Dict, Iterable, Optional, Sequence, Union

from .._errors import RollerRigError

if sys.version_info >= (3, 11):
    import tomllib
else:                                                   # Python < 3.11
    import tomli as tomllib

MAX_PARAMETER_FILE_BYTES = 1 << 20  # the default file is 12 kB


class _Problems(Exception):
    """What is wrong with a parameter set or file: a list of sentences, each
    naming its key; the public functions turn it into one RollerRigError."""

    def __init__(self, problems: Iterable[str]) -> None:
        super().__init__(problems)
        self.problems = list(problems)


_SHOWN_PROBLEMS = 30     # a file of thousands of bad keys gives a readable message


def _error(source: str, problems: Sequence[str]) -> RollerRigError:
    if len(problems) == 1:
        return RollerRigError(f"{source}: {problems[0]}")
    shown = [f"  {p}" for p in problems[:_SHOWN_PROBLEMS]]
    if len(problems) > _SHOWN_PROBLEMS:
        shown.append(f"  ... and {len(problems) - _SHOWN_PROBLEMS} more")
    return RollerRigError(f"{source}: {len(problems)} problems:\n" + "\n".join(shown))


def _short(value: object, width: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= width else text[:width - 3] + "..."


def _read_parameter_file(path: Union[str, os.PathLike[str]]) -> Dict[str, Any]:
    """The parsed TOML of `path`, or _Problems saying why not.  Only a
    regular file of at most MAX_PARAMETER_FILE_BYTES of UTF-8 is read (a
    FIFO is never waited on, a device never read from)."""
    fd: Optional[int]
    try:
        # O_NONBLOCK: opening a FIFO for reading must not wait for a writer;
        # the type is then checked on the open descriptor, so it cannot change
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0)
                     | getattr(os, "O_BINARY", 0))
    except IsADirectoryError:
        raise _Problems(["is a directory, not a parameter file"]) from None
    except OSError as e:
        raise _Problems([f"cannot open it: {e.strerror or e}"]) from None
    try:
        info = os.fstat(fd)
        if stat.S_ISDIR(info.st_mode):
            raise _Problems(["is a directory, not a parameter file"])
        if not stat.S_ISREG(info.st_mode):
            raise _Problems(["is not a regular file (a FIFO, a device or a socket); give a "
                             "TOML parameter file"])
        if info.st_size > MAX_PARAMETER_FILE_BYTES:
            raise _Problems([f"is {info.st_size} bytes; a parameter file is at most "
                             f"{MAX_PARAMETER_FILE_BYTES} bytes (rig_default.toml: 12 kB)"])
        with os.fdopen(fd, "rb") as fh:
            fd = None
            data = fh.read(MAX_PARAMETER_FILE_BYTES + 1)
    except OSError as e:
        raise _Problems([f"cannot read it: {e.strerror or e}"]) from None
    finally:
        if fd is not None:
            os.close(fd)
    if len(data) > MAX_PARAMETER_FILE_BYTES:             # grew while being read
        raise _Problems([f"is more than {MAX_PARAMETER_FILE_BYTES} bytes"])
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise _Problems([f"is not UTF-8 text (byte {e.start}); a parameter file is TOML "
                         f"text"]) from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise _Problems([f"is not valid TOML: {e}"]) from None
    except RecursionError:
        raise _Problems(["is nested too deeply or malformed (TOML arrays or tables inside "
                         "each other beyond Python's recursion limit)"]) from None
