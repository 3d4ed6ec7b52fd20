"""Type aliases of the public API (annotations only: nothing here runs in a
call).  Python 3.9 is supported: the modules that use them write
``from __future__ import annotations`` or quote them."""
import os
from typing import Any, Callable, Mapping, Optional, Union

import numpy as np
import numpy.typing as npt

#: a float64 array of any shape
F64Array = npt.NDArray[np.float64]
#: a result field: a float for a call on scalars, else a float64 array
FloatResult = Union[float, F64Array]
#: a status field: an int for a call on scalars, else an int8 array
StatusResult = Union[int, npt.NDArray[np.int8]]
#: the rig's parameters as the functions take them: None (the defaults), a
#: nested dict {section: {key: value}} over rig_default.toml, or the path of
#: a TOML file of that layout
Params = Optional[Union[Mapping[str, Mapping[str, Any]], str, "os.PathLike[str]"]]
#: a controller in simulate's loop: RigSignals -> a dict of references, or None
Controller = Callable[..., Optional[Mapping[str, float]]]
