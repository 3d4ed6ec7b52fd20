"""Property-based test: the elements of one creep_forces batch are independent
(issue 22).  Every element of a random batch, good and bad neighbours
alike, gives bitwise what it gives alone, for every method of the registry:
whatever one element leaves in the batch's workspace (the exact solver's
caches, its starts and search directions, a NaN of a failed case) must not
reach the next.

Run:  python -m pytest tests/test_properties_batch.py     (profile "ci")
      HYPOTHESIS_PROFILE=long python -m pytest tests/test_properties_batch.py
"""
import numpy as np
from hypothesis import example, given, strategies as st

import rollerrig as rr
from _properties import (assert_same, batches, creep_options, examples, log_uniform, signed,
                         subset, uniform, watchdog)

assert watchdog  # the autouse hang detector, imported to take effect here

CREEP = dict(cx=signed(1e-8, 1.0), cy=signed(1e-8, 1.0), cphi=signed(1e-6, 50.0),
             a=log_uniform(1e-4, 3e-2), b=log_uniform(1e-4, 3e-2), N=log_uniform(1.0, 3e5),
             mu=log_uniform(0.01, 1.5), G=log_uniform(1e9, 3e11), nu=uniform(0.0, 0.5),
             speed=log_uniform(0.01, 100.0))

# the reproducer: an element of extreme numbers that fails (RR_ERR_RANGE)
# before a plausible one, which then failed too (status -12 and NaN instead of
# 0 and fy = 8206.9 N: NormCG's first direction read the NaN the failed case
# left, 0 times NaN)
BAD_THEN_GOOD = dict(cx=np.array([1.7976931348623157e308, 1e-200]),
                     cy=np.array([0.08277198570663905, -1000.0]),
                     cphi=np.array([-1e9, -5e-324]),
                     a=np.array([958999.8673731439, 0.006481419441671279]),
                     b=np.array([1e6, 0.0003823545954440463]),
                     N=np.array([1.7976931348623157e308, 13749.97146368838]),
                     mu=np.array([0.238281690811457, 0.5968699418112151]),
                     G=8.2e10, nu=0.28, speed=0.0)


@st.composite
def any_method_options(draw):
    """Valid options of any method of the registry, the exact theory's on
    small grids (a case well under a millisecond)."""
    method = draw(st.sampled_from(tuple(rr.METHODS)))
    if method == "exact":
        return dict(method=method, nx=draw(st.integers(1, 8)), ny=draw(st.integers(1, 8)))
    return draw(creep_options((method,)))


def creep(args, opts, friction):
    kw = {k: v for k, v in args.items() if k not in ("cx", "cy", "cphi")}
    if rr.METHODS[opts["method"]].coulomb_only:
        friction = None
    return rr.creep_forces(args["cx"], args["cy"], args["cphi"], friction=friction,
                           errors="ignore", **kw, **opts)


frictions = st.one_of(st.none(), st.builds(rr.FallingFriction, A=st.floats(0.01, 1.0),
                                           B=st.floats(0.0, 20.0)))


@examples(2)
@given(args=batches(CREEP, wild_share=2), opts=any_method_options(), friction=frictions)
@example(args=BAD_THEN_GOOD, opts=dict(method="exact", nx=5, ny=5), friction=None)
def test_every_element_as_alone(args, opts, friction):
    f = creep(args, opts, friction)
    n = np.size(f.status)
    for i in range(n):
        one = creep(subset(args, [i]), opts, friction)
        assert_same([v[i] for v in f], [v[0] for v in one],
                    f"{opts['method']}: element {i} of {n} in the batch, then alone: ")
