"""The comparison figure of a failed regression (rollerrig.testing): per differing field (the
first MAX_PANELS), the data over the reference, and below it the
difference with the band the tolerance allows.  matplotlib is optional:
without it figure() says why instead of drawing."""
from __future__ import annotations

from typing import Any, Mapping, Optional, Protocol, Sequence, Tuple

import numpy as np
import numpy.typing as npt

from .._files import write_file


class _Deviation(Protocol):
    """What the figure reads of a rollerrig.testing.FieldDeviation (the
    testing package imports this module, not the other way round)."""

    @property
    def name(self) -> str: ...
    @property
    def unit(self) -> str: ...
    @property
    def rtol(self) -> float: ...
    @property
    def atol(self) -> float: ...
    @property
    def problem(self) -> Optional[str]: ...
    @property
    def bad(self) -> int: ...
    @property
    def size(self) -> int: ...
    @property
    def worst(self) -> Tuple[int, ...]: ...

MAX_PANELS = 6


def figure(path: str, deviations: Sequence[_Deviation], got: Mapping[str, npt.NDArray[Any]],
           ref: Mapping[str, npt.NDArray[Any]], x: Optional[npt.NDArray[Any]] = None,
           x_name: Optional[str] = None, x_unit: Optional[str] = None,
           title: str = "") -> Tuple[Optional[str], Optional[str]]:
    """Draw the figure into `path` (PNG).  Returns (path, None), or (None,
    why not) when matplotlib does not import or no field can be drawn."""
    try:
        from matplotlib.figure import Figure    # no pyplot: no backend, no window
    except ImportError as e:
        return None, (f"no comparison figure: matplotlib does not import ({e}); "
                      f"pip install matplotlib")
    drawn = [d for d in deviations if not d.problem][:MAX_PANELS]
    if not drawn:
        return None, "no comparison figure: no field could be compared value by value"
    fig = Figure(figsize=(7.5, 2.6 * len(drawn)), layout="constrained")
    axes = fig.subplots(2 * len(drawn), 1, squeeze=False,
                        gridspec_kw={"height_ratios": [2, 1] * len(drawn)})[:, 0]
    for k, d in enumerate(drawn):
        g, r = (np.asarray(a, dtype=float) for a in (got[d.name], ref[d.name]))
        if g.ndim > 1:                                  # a 2-D field: flat index
            g, r = g.ravel(), r.ravel()
        use_x = x is not None and len(x) == len(g) and got[d.name].ndim == 1
        xs = np.asarray(x, dtype=float) if use_x else np.arange(len(g))
        label = (f"{x_name} [{x_unit}]" if x_unit not in ("", "1", None) else x_name
                 ) if use_x else "index"
        unit = f" [{d.unit}]" if d.unit not in ("", "1") else ""
        top, bottom = axes[2 * k], axes[2 * k + 1]
        top.plot(xs, r, color="0.55", lw=2.2, label="reference")
        top.plot(xs, g, color="C3", lw=0.9, label="this run")
        top.set_ylabel(f"{d.name}{unit}")
        top.legend(loc="best", fontsize="small")
        top.set_title(f"{d.name}: {d.bad} of {d.size} values outside rtol = {d.rtol:g}, "
                      f"atol = {d.atol:g}", fontsize="medium")
        with np.errstate(invalid="ignore"):
            bottom.plot(xs, g - r, color="C3", lw=0.9)
            band = d.atol + d.rtol * np.abs(r)
        bottom.fill_between(xs, -band, band, color="C2", alpha=0.3, lw=0, label="allowed")
        i = d.worst[0] if len(d.worst) == 1 else int(np.ravel_multi_index(d.worst,
                                                                          got[d.name].shape))
        bottom.axvline(xs[i], color="k", lw=0.6, ls=":")
        bottom.set_ylabel(f"this run - ref{unit}", fontsize="small")
        bottom.set_xlabel(label)
        bottom.legend(loc="best", fontsize="small")
    if title:
        fig.suptitle(title, fontsize="medium")
    write_file(path, lambda fh: fig.savefig(fh, format="png", dpi=90),
               what="rollerrig.testing: figure", binary=True)
    return path, None
