"""Hypothesis profiles of the property-based suite (tests/test_properties_*.py).

    python -m pytest tests/test_properties_*.py              # "ci", the default
    HYPOTHESIS_PROFILE=long python -m pytest tests/test_properties_*.py
    HYPOTHESIS_PROFILE=quick python -m pytest tests/test_properties_*.py
    HYPOTHESIS_PROFILE=search python -m pytest tests/test_properties_*.py
    ... --hypothesis-show-statistics                        # examples run per test

"ci" (what `python -m pytest` and CI run) is derandomized: every run of the
same code tries the same examples, so CI passes or fails on the code alone,
never on the luck of the draw.  (Hypothesis also draws literal constants
from the project's loaded modules, so a change to the code, or running a
file alone instead of the whole suite, may change the examples drawn.)  "long" draws fresh random examples, ten times as many:
it is the one that finds new failures.  "quick" is a tenth of "ci" for
editing; "search" is "ci" freshly random and without the explicit @example cases (a failing
explicit example stops a test before any example is generated, so while the
known defects are open, "search" is how to look past them).  No example database is kept in
either (nothing is written into the checkout); a failure found by "long"
becomes an explicit @example(...) regression case in the test itself.

deadline is a hang detector only, generous enough (5 s per example) that no
call of a sane size comes near it on a loaded machine; it never measures
speed.  A call that never returns is not caught by a deadline (it is checked
after the call), so the known hangs run in a child process with a timeout
(_properties.run_isolated), and every test of the suite is watched by
faulthandler (_properties.watchdog).
"""
import os

from hypothesis import HealthCheck, Phase, settings

#: examples per test in "ci"; tests ask for a multiple of it (_properties.examples)
CI_EXAMPLES = 100

_COMMON = dict(deadline=5000, database=None, print_blob=True,
               suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])

settings.register_profile("ci", max_examples=CI_EXAMPLES, derandomize=True, **_COMMON)
settings.register_profile("long", max_examples=10 * CI_EXAMPLES, derandomize=False, **_COMMON)
settings.register_profile("quick", max_examples=CI_EXAMPLES // 10, derandomize=True, **_COMMON)
settings.register_profile("search", max_examples=CI_EXAMPLES, derandomize=False,
                          phases=[Phase.generate, Phase.shrink], **_COMMON)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))
