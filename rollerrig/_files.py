"""Output files: the one rule of every file rollerrig writes (the command
line's outputs, RigResult.to_csv, plot_run's figures, the FMU, the exact
table, Profile.write_text).

A file goes only where the caller pointed: to a regular file or a new path,
never through a symbolic link, never over a directory, a device, a FIFO or a
socket.  check_output says so, naming the caller's path, before any long
work; write_file checks again, writes into a new file created exclusively
beside the path and renames it over the path, so that a reader never sees
half a file and no temporary is left behind.
"""
from __future__ import annotations

import os
import secrets
import stat
from typing import (IO, Any, BinaryIO, Callable, Literal, Optional, TextIO, Tuple, TypeVar, Union,
                    overload)

from ._errors import RollerRigError

#: a path as the writers take it (anything else is refused at run time, naming it)
PathArg = Union[str, bytes, "os.PathLike[str]", "os.PathLike[bytes]"]
_P = TypeVar("_P", bound=PathArg)

_KINDS = ((stat.S_ISDIR, "a directory"), (stat.S_ISLNK, "a symbolic link"),
          (stat.S_ISFIFO, "a FIFO"), (stat.S_ISCHR, "a character device"),
          (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket"))


class OutputPathError(RollerRigError):
    """A path no file may be written at: "<what> <path>: <reason>" (.path,
    .reason: the command line names its option instead of `what`)."""

    def __init__(self, what: str, path: str, reason: str) -> None:
        super().__init__(f"{what} {path}: {reason}" if what else f"{path}: {reason}")
        self.path, self.reason = path, reason


def _text(path: PathArg, what: str, folder: bool = False) -> str:
    try:
        text = os.fspath(path)
    except TypeError:
        raise OutputPathError(what, repr(path), "not a path") from None
    if isinstance(text, bytes):
        text = os.fsdecode(text)
    if not text:
        raise OutputPathError(what, "''", "an empty path")
    if "\0" in text:
        raise OutputPathError(what, repr(text), "not a path (a NUL character)")
    if folder:
        return text
    if text.endswith(("/", os.sep)) or os.path.basename(text) in (os.curdir, os.pardir):
        raise OutputPathError(what, text, "not a file name")
    return text


def _exclusive(folder: str, name: str, mode: int = 0o666) -> Tuple[int, str]:
    """A new file beside `name` in folder, created exclusively (never an
    existing file, never through a link): (descriptor, its path).  The
    umask applies, as for open()."""
    flags = (os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0)
             | getattr(os, "O_NOFOLLOW", 0))
    while True:
        tmp = os.path.join(folder, f".{name}.{secrets.token_hex(6)}.tmp")
        try:
            return os.open(tmp, flags, mode), tmp
        except FileExistsError:                      # a clash of random names: draw again
            continue


def _replaceable(text: str, what: str) -> None:
    """What is at the path may be replaced: nothing, or a regular file."""
    try:
        mode = os.lstat(text).st_mode
    except FileNotFoundError:
        return
    except OSError as e:
        raise OutputPathError(what, text, e.strerror or str(e)) from None
    if stat.S_ISREG(mode):
        return
    if stat.S_ISDIR(mode):
        why = "is a directory; give the name of a file in it"
    elif stat.S_ISLNK(mode):
        why = ("is a symbolic link; a file is written only to a regular file or a new "
               "path, never through a link")
    else:
        kind = next((name for test, name in _KINDS if test(mode)), "something")
        why = f"is {kind}, not a regular file; give a regular file or a new path"
    raise OutputPathError(what, text, why)


def check_output(path: PathArg, *, what: str, suffix: Optional[str] = None) -> str:
    """Check, before any work, that a file may be written at `path`: its
    folder exists, is a directory and takes a new file (one is made and
    removed there); what is at `path` is nothing or a regular file (not a
    symbolic link, a directory, a device, a FIFO or a socket); its name
    ends in `suffix` if given.  Otherwise OutputPathError (a
    RollerRigError) "<what> <path>: <why>".  Returns the path as text."""
    text = _text(path, what)
    folder = os.path.dirname(text) or os.curdir
    try:
        # the folder may be reached through a link: it is the one the caller named
        is_dir = stat.S_ISDIR(os.stat(folder).st_mode)
    except FileNotFoundError:
        raise OutputPathError(what, text, f"the folder {folder} does not exist") from None
    except NotADirectoryError:
        is_dir = False
    except OSError as e:
        raise OutputPathError(what, text, f"the folder {folder}: {e.strerror or e}") from None
    if not is_dir:
        raise OutputPathError(what, text, f"{folder} is not a directory")
    _replaceable(text, what)
    if suffix is not None and not text.lower().endswith(suffix):
        raise OutputPathError(what, text, f"the file name must end in {suffix}")
    try:
        fd, probe = _exclusive(folder, os.path.basename(text), 0o600)
        os.close(fd)
        os.remove(probe)
    except OSError as e:
        raise OutputPathError(what, text, f"cannot write in the folder {folder}: "
                                          f"{e.strerror or e}") from None
    return text


def make_folder(path: PathArg, *, what: str) -> str:
    """The folder `path`, created if needed (with its parents), for files
    to be written in: OutputPathError "<what> <path>: why" if it is not a
    directory or cannot be made.  Returns the path as text."""
    text = _text(path, what, folder=True)
    if os.path.exists(text) and not os.path.isdir(text):
        raise OutputPathError(what, text, "not a directory")
    try:
        os.makedirs(text, exist_ok=True)
    except OSError as e:
        raise OutputPathError(what, text, f"cannot create the folder: "
                                          f"{e.strerror or e}") from None
    if not os.path.isdir(text):
        raise OutputPathError(what, text, "not a directory")
    return text


@overload
def write_file(path: _P, write: Callable[[TextIO], object], *, what: str,
               binary: Literal[False] = False, suffix: Optional[str] = None) -> _P: ...


@overload
def write_file(path: _P, write: Callable[[BinaryIO], object], *, what: str,
               binary: Literal[True], suffix: Optional[str] = None) -> _P: ...


def write_file(path: _P, write: Callable[[Any], object], *, what: str,
               binary: bool = False, suffix: Optional[str] = None) -> _P:
    """Write a file through `write(file object)` by check_output's rule:
    checked, written into a new file created exclusively beside `path`,
    what is at `path` checked again (still nothing or a regular file), then
    renamed over it.  A failure names `path` (an OSError of the writing, an
    OutputPathError of the checks) and leaves no temporary file.  Returns
    `path`."""
    text = check_output(path, what=what, suffix=suffix)
    folder, name = os.path.split(os.path.abspath(text))
    try:
        fd, tmp = _exclusive(folder, name)
    except OSError as e:
        raise OSError(e.errno, e.strerror, text) from None
    try:
        fh: IO[Any] = (os.fdopen(fd, "wb") if binary
                       else os.fdopen(fd, "w", newline="", encoding="utf-8"))
        with fh:
            write(fh)
        _replaceable(text, what)                     # nothing put there meanwhile
        os.replace(tmp, text)
    except BaseException as e:
        try:
            os.remove(tmp)
        except OSError:
            pass
        if isinstance(e, OSError) and e.errno is not None and e.filename in (None, tmp):
            raise OSError(e.errno, e.strerror, text) from None     # the caller's path
        raise
    return path
