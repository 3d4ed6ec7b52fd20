"""The Examples sections of the public docstrings run as written (doctest).

The API reference (docs/api, numpydoc) shows these examples; each is a
doctest whose printed output is compared with what the call gives now, so an
example that stops working, or a number that changes, fails here.  Every
module whose docstrings were converted to numpydoc is listed; a module
listed must hold at least one example (a test that cannot silently check
nothing).  The examples are small cases: about a second a module at most
(the first xarray import, a 320-node table).
"""
import doctest
import importlib
import inspect
import sys
import warnings

import numpy as np
import pytest

MODULES = [
    "rollerrig.contact.creep",
    "rollerrig.contact.exact",
    "rollerrig._binding",
    "rollerrig._errors",
    "rollerrig.capi",
    "rollerrig.analysis.fit",
    "rollerrig.analysis.sweep",
    "rollerrig.analysis.exact_table",
    "rollerrig.analysis.reference",
    "rollerrig.geometry.profiles",
    "rollerrig.geometry.profiles._profile",
    "rollerrig.geometry.wheelset",
    "rollerrig.geometry.patch",
    "rollerrig.geometry.conicity",
    "rollerrig.geometry.nonhertz",
    "rollerrig.rig.contact",
    "rollerrig.rig.build",
    "rollerrig.rig.run",
    "rollerrig.rig.result",
    "rollerrig.rig.control",
    "rollerrig.rig.params",
    "rollerrig.rig.exact",
    "rollerrig.plot._curves",
    "rollerrig.plot._rig",
    "rollerrig.plot._maps",
]

# the optional packages (the extras "fit", "sweep": the test extra installs
# them) a module's examples need
NEEDS = {"rollerrig.analysis.fit": "scipy", "rollerrig.analysis.sweep": "xarray"}

# the output as a reader sees it: spacing of numpy's reprs free, "..." for the
# parts an example leaves out
FLAGS = doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS
PRINT_DEFAULTS = dict(precision=8, threshold=1000, edgeitems=3, linewidth=75, suppress=False,
                      nanstr="nan", infstr="inf", sign="-", floatmode="maxprec", legacy=False)


def _examples(name):
    """The doctests of the module's own objects, their methods included (a
    re-exported name is tested in its own module).  doctest's own search
    skips the methods of a class whose __module__ names the package that
    re-exports it (Profile), so each class and function is searched too."""
    module = importlib.import_module(name)
    finder = doctest.DocTestFinder(exclude_empty=True)
    tests = {t.name: t for t in finder.find(module, name)}
    for attr, obj in vars(module).items():
        if attr.startswith("_") or not (inspect.isclass(obj) or callable(obj)):
            continue
        try:
            source = inspect.getsourcefile(obj)
        except TypeError:
            continue
        if getattr(obj, "__module__", None) != name and source != module.__file__:
            continue
        for test in finder.find(obj, f"{name}.{attr}", module=False, globs={}):
            tests.setdefault(test.name, test)
    return [t for t in tests.values() if t.examples]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name, tmp_path, monkeypatch):
    if name in NEEDS:
        pytest.importorskip(NEEDS[name])
    tests = _examples(name)
    assert tests, f"{name}: no docstring example found"
    monkeypatch.chdir(tmp_path)                  # an example that writes a file writes here
    monkeypatch.setenv("MPLBACKEND", "Agg")
    if "matplotlib.pyplot" in sys.modules:   # another test's figures: not counted here
        sys.modules["matplotlib.pyplot"].close("all")
    runner = doctest.DocTestRunner(optionflags=FLAGS)
    failures = []
    # numpy's default printing (another test may have changed it in this process)
    with warnings.catch_warnings(), np.printoptions(**PRINT_DEFAULTS):
        # an example shows the warning-free call; one that warns fails
        warnings.simplefilter("error")
        for test in tests:
            runner.run(test, out=lambda text: failures.append(text))
    pyplot = sys.modules.get("matplotlib.pyplot")
    if pyplot is not None:
        pyplot.close("all")                     # the figures the examples drew
    summary = runner.summarize(verbose=False)
    assert summary.attempted > 0
    assert summary.failed == 0, "".join(failures)
