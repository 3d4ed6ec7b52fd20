"""The C core for C programs: where the installed package keeps its headers,
static library, sources and pkg-config file, as numpy.get_include() does for
numpy's headers.

    import rollerrig
    rollerrig.get_include()        # pass to -I: it holds rollerrig.h
    rollerrig.get_library_dir()    # holds librollerrig.a (position-independent)
    rollerrig.get_source_dir()     # the core: its .c and .h files in their layer folders
    rollerrig.get_pkgconfig_dir()  # holds rollerrig.pc (relocatable: ${pcfiledir})

From a shell, the command ``rollerrig-config`` prints the same, as
numpy-config does:

    cc prog.c -o prog $(rollerrig-config --cflags --libs)
    PKG_CONFIG_PATH=$(rollerrig-config --pkgconfigdir) pkg-config --cflags --libs rollerrig

A program includes "rollerrig.h" (the headers include each other by layer,
"rig/rr_rig.h", from that folder) and links the static library and the math
library: -L DIR -lrollerrig -lm.  docs/c_api.md lists the functions.

A wheel carries these under rollerrig/_c/ (include/, lib/, src/).  An
in-place build of a checkout (``pip install -e .``) keeps the headers and
sources where they are, in csrc/, and builds the library into
rollerrig/_c/lib/: the functions then give those folders.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Callable, List, Optional, Sequence, Tuple

__all__ = ["get_include", "get_library_dir", "get_source_dir", "get_pkgconfig_dir", "main"]

_PACKAGE = Path(__file__).resolve().parent
_C = _PACKAGE / "_c"
_CHECKOUT_CSRC = _PACKAGE.parent / "csrc"      # the package in a checkout (pip install -e .)


def _folder(what: str, candidates: Sequence[Tuple[Path, str]]) -> str:
    """The first folder of candidates ((folder, a file it must hold), ...)
    that holds its file; FileNotFoundError naming what is missing if none."""
    for folder, probe in candidates:
        if (folder / probe).is_file():
            return str(folder)
    looked = ", ".join(str(folder / probe) for folder, probe in candidates)
    raise FileNotFoundError(
        f"rollerrig: no {what} in this installation (looked for {looked}); a wheel or "
        "`pip install .` ships it, `pip install -e .` builds it in the checkout")


def get_include() -> str:
    """The folder holding rollerrig.h and its layer folders.

    Compile with ``-I`` it and ``#include "rollerrig.h"``.

    Returns
    -------
    str
        The folder: rollerrig/_c/include in an installed wheel, csrc/ in an
        editable checkout.

    Raises
    ------
    FileNotFoundError
        Naming the paths looked at, when the installation has no headers.

    See Also
    --------
    get_library_dir, get_source_dir, get_pkgconfig_dir

    Examples
    --------
    >>> import os
    >>> import rollerrig as rr
    >>> os.path.isfile(os.path.join(rr.get_include(), "rollerrig.h"))
    True
    """
    return _folder("C headers", [(_C / "include", "rollerrig.h"),
                                 (_CHECKOUT_CSRC, "rollerrig.h")])


def get_library_dir() -> str:
    """The folder holding librollerrig.a, the core as compiled for the extension.

    The library is position-independent: link with ``-L`` it
    ``-lrollerrig -lm``.

    Returns
    -------
    str
        The folder (rollerrig/_c/lib).

    Raises
    ------
    FileNotFoundError
        Naming the path looked at, when the library was not built or
        shipped.

    See Also
    --------
    get_include
    """
    return _folder("C library", [(_C / "lib", "librollerrig.a")])


def get_source_dir() -> str:
    """The folder holding the core's sources and headers in their layer folders.

    The layer folders are util/, contact/, geometry/, rig/ (every
    ``*/rr_*.c``); compile with ``-I`` it (a source may include another:
    rr_fft_avx2.c includes util/rr_fft.c).

    Returns
    -------
    str
        The folder: rollerrig/_c/src in a wheel, csrc/ in a checkout.

    Raises
    ------
    FileNotFoundError
        Naming the paths looked at, when the installation has no sources.
    """
    return _folder("C sources", [(_C / "src", "rig/rr_rig.c"),
                                 (_CHECKOUT_CSRC, "rig/rr_rig.c")])


def get_pkgconfig_dir() -> str:
    """The folder holding rollerrig.pc, for PKG_CONFIG_PATH.

    The file names its folders relative to itself (``${pcfiledir}``).

    Returns
    -------
    str
        The folder (rollerrig/_c/lib/pkgconfig).

    Raises
    ------
    FileNotFoundError
        Naming the path looked at, when the file was not built or shipped.
    """
    return _folder("pkg-config file", [(_C / "lib" / "pkgconfig", "rollerrig.pc")])


def cflags() -> str:
    """The compiler flags for the headers, ``-I<get_include()>``."""
    return f"-I{get_include()}"


def libs() -> str:
    """The linker flags for the library, ``-L<get_library_dir()> -lrollerrig -lm``."""
    return f"-L{get_library_dir()} -lrollerrig -lm"


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The ``rollerrig-config`` command: print the asked flags or folders on one line.

    Parameters
    ----------
    argv : list of str, optional
        The command's arguments (default: ``sys.argv[1:]``): any of
        --cflags, --libs, --includedir, --libdir, --srcdir, --pkgconfigdir,
        --version.

    Returns
    -------
    int
        The exit status: 0 printed, 1 a folder missing (the message on
        stderr), 2 nothing asked (the help printed).
    """
    parser = argparse.ArgumentParser(
        prog="rollerrig-config",
        description="Flags and folders to build a C program against the installed "
                    "rollerrig C library, e.g. cc prog.c $(rollerrig-config --cflags --libs)")
    options: List[Tuple[str, Callable[[], str], str]] = [
        ("--cflags", cflags, "the compiler flags (-I...)"),
        ("--libs", libs, "the linker flags (-L... -lrollerrig -lm)"),
        ("--includedir", get_include, "the folder holding rollerrig.h"),
        ("--libdir", get_library_dir, "the folder holding librollerrig.a"),
        ("--srcdir", get_source_dir, "the folder holding the core's sources"),
        ("--pkgconfigdir", get_pkgconfig_dir, "the folder holding rollerrig.pc"),
    ]
    for flag, _, text in options:
        parser.add_argument(flag, action="store_true", help=text)
    parser.add_argument("--version", action="store_true", help="the version of rollerrig")
    args = parser.parse_args(argv)
    asked = [fn for flag, fn, _ in options if getattr(args, flag[2:])]
    if args.version:
        from ._version import __version__
        asked.append(lambda: __version__)
    if not asked:
        parser.print_help()
        return 2
    try:
        print(" ".join(fn() for fn in asked))
    except FileNotFoundError as exc:
        print(exc, file=sys.stderr)
        return 1
    return 0
