"""Optional dependencies: import one where a feature needs it, or say which
extra of the package installs it.

The base install is numpy and matplotlib; the extras (setup.cfg) add
xarray, pandas, tqdm ("sweep"), scipy ("fit"), dask.distributed
("distributed").
"""
import importlib
from types import ModuleType
from typing import Optional

__all__ = ["OptionalDependencyError", "require"]


class OptionalDependencyError(ImportError):
    """A feature needs a package that is not installed (or does not import);
    the message names the feature, the package and the extra to install."""


def require(module: str, feature: str, extra: str, package: Optional[str] = None,
            instead: Optional[str] = None) -> ModuleType:
    """Import and return `module` (e.g. "scipy.optimize") for `feature`
    (e.g. "fit_polach"), or raise OptionalDependencyError saying
    "<feature> needs <package>: pip install 'rollerrig[<extra>]'".

    package: the distribution's name when it differs from the module's top
    level (default: the top level of `module`); instead: what else the
    caller can do, appended to the message (e.g. "or pass output='dict'")."""
    try:
        return importlib.import_module(module)
    except ImportError as e:
        top = module.split(".")[0]
        package = package or top
        # absent, or present but broken (a missing dependency of its own, a
        # version clash): say which, so the fix offered is the right one
        why = ("is not installed" if e.name in (top, module)
               else f"does not import ({type(e).__name__}: {e})")
        raise OptionalDependencyError(
            f"{feature} needs {package}, which {why}: pip install 'rollerrig[{extra}]' "
            f"(from a checkout: pip install '.[{extra}]')"
            + (f"; {instead}" if instead else ""), name=top) from e
