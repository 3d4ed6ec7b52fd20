"""The one progress mechanism of every long call (simulate, sweep, sweep_rig,
the table builds): a tqdm bar on stderr, shown only once the work has run
for about a second, so quick calls print nothing.

progress=None (the default of every call): that delayed bar; True: shown
from the start; False: none.
"""
import sys
from typing import Any, Optional

from ._errors import RollerRigError

#: seconds of work before the default bar appears
DELAY_S = 1.0


def check(func: str, progress: object) -> Optional[bool]:
    """progress must be None, True or False (named in the error)."""
    if progress is not None and not isinstance(progress, bool):
        raise RollerRigError(f"{func}: progress must be None (a bar once the work passes "
                             f"about {DELAY_S:g} s), True or False, got {progress!r}")
    return progress


class _Silent:
    def update(self, n: float = 1) -> None:
        pass

    def close(self) -> None:
        pass

    def __enter__(self) -> "_Silent":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def bar(progress: Optional[bool], total: Optional[float], desc: str, unit: str) -> Any:
    """A tqdm bar for `total` units of work (update(n) as they finish; close()
    at the end), or a silent stand-in for progress=False.  tqdm is a
    dependency of the package; should it be missing the work runs without a
    bar, since losing the bar is no reason to fail the work."""
    if progress is False:
        return _Silent()
    try:
        from tqdm import tqdm  # type: ignore[import-untyped]  # (no stubs; types-tqdm)
    except ImportError:
        return _Silent()
    return tqdm(total=total, desc=desc, unit=unit, dynamic_ncols=True, leave=False,
                file=sys.stderr, delay=0.0 if progress else DELAY_S)
