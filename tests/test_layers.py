"""The C core's layers (docs/architecture.md): a module includes only its own
layer and those below it, and no modules include each other in a circle."""
import pathlib
import re

import pytest

CSRC = pathlib.Path(__file__).resolve().parents[1] / "csrc"
LAYERS = ("util", "contact", "geometry", "rig", "fmu")   # bottom to top
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z]+)/(rr_[a-z0-9_]+)\.(?:h|def)"', re.M)

if not (CSRC / "util").is_dir():
    pytest.skip("needs the source tree (csrc/)", allow_module_level=True)


def _modules():
    """module name -> (layer, the modules its .c, .h and .def include)."""
    mods = {}
    for layer in LAYERS:
        for f in sorted((CSRC / layer).glob("rr_*.[ch]")) + sorted((CSRC / layer).glob("*.def")):
            layer_of, uses = mods.setdefault(f.stem, (layer, set()))
            assert layer_of == layer, f"{f.stem} in two layers"
            for inc_layer, name in INCLUDE.findall(f.read_text()):
                uses.add((inc_layer, name))
    return mods


def test_every_include_goes_down_or_across():
    for name, (layer, uses) in _modules().items():
        for inc_layer, inc in uses:
            assert inc_layer in LAYERS, (name, inc_layer)
            assert LAYERS.index(inc_layer) <= LAYERS.index(layer), \
                f"{layer}/{name} includes {inc_layer}/{inc}, a layer above it"
            assert (CSRC / inc_layer / f"{inc}.h").exists() \
                or (CSRC / inc_layer / f"{inc}.def").exists(), (name, inc)


def test_no_include_circle():
    mods = _modules()
    graph = {n: {i for _, i in uses if i != n} for n, (_, uses) in mods.items()}
    state = {}

    def visit(n, path):
        state[n] = "open"
        for m in graph.get(n, ()):
            assert state.get(m) != "open", "include circle: " + " -> ".join(path + [n, m])
            if m not in state:
                visit(m, path + [n])
        state[n] = "done"

    for n in graph:
        if n not in state:
            visit(n, [])
    assert len(graph) > 20                     # the walk saw the core
