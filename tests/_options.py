"""Tests that run every method with one set of options: the registry refuses an
option the method lacks (before, linear and polach ignored the FASTSIM grid),
so such tests give each method only the options it has."""
import rollerrig as rr


def own(method, **options):
    """The options the method has, with method=."""
    return dict({k: v for k, v in options.items() if k in rr.METHODS[method].options},
                method=method)
