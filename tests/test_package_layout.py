"""The package's rooms (docs/architecture.md, "The Python rooms"): its modules
stand in the C core's wings, each importing only its own wing and those
below it (contact < geometry < rig < analysis, the package-wide rooms below
and above them), no modules import each other in a circle (imports inside
functions included), no module is over 800 lines, and the old module paths
still import (rollerrig._MOVED)."""
import ast
import importlib
import pathlib
import sys

import pytest

PKG = pathlib.Path(__file__).resolve().parents[1] / "rollerrig"

# bottom to top: the package-wide helpers (and the compiled binding), the
# wings as csrc/'s layers, then the rooms that use the whole package
FLOORS = {
    "rollerrig._core": 0, "rollerrig._version": 0, "rollerrig._optional": 0,
    "rollerrig._errors": 0, "rollerrig._binding": 0, "rollerrig._files": 0,
    "rollerrig._progress": 0,
    "rollerrig._units": 0, "rollerrig._csv": 0,
    # the public API's type aliases (annotations only)
    "rollerrig._typing": 0,
    # the regression helpers for users' tests, above the whole package
    **{f"rollerrig.testing{m}": 5 for m in ("", "._compare", "._store", "._assert",
                                             "._fixtures")},
    "rollerrig.contact": 1, "rollerrig.geometry": 2, "rollerrig.rig": 3, "rollerrig.analysis": 4,
    "rollerrig.capi": 5, "rollerrig.fmu": 5, "rollerrig.plot": 5, "rollerrig.cli": 5,
    # the pictures' package: its files are one room (rollerrig.plot)
    "rollerrig.plot._base": 5, "rollerrig.plot._curves": 5, "rollerrig.plot._maps": 5,
    "rollerrig.plot._rig": 5, "rollerrig.plot._regression": 5,
    "rollerrig.__main__": 5, "rollerrig": 5,
}
MAX_LINES = 800


def _name(path):
    parts = path.relative_to(PKG.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {_name(p): p for p in sorted(PKG.rglob("*.py")) if "data" not in p.parts}


WINGS = ("rollerrig.contact", "rollerrig.geometry", "rollerrig.rig", "rollerrig.analysis")


def _floor(module):
    """The floor of a module: its own entry, else its wing's (a new room at
    the package's top has none until it is placed in FLOORS or in a wing)."""
    if module in FLOORS:
        return FLOORS[module]
    wing = ".".join(module.split(".")[:2])
    assert wing in WINGS, f"{module}: in no wing and not one of the package's own rooms (FLOORS)"
    return FLOORS[wing]


def _is_package(module):
    return MODULES[module].name == "__init__.py"


def _imports(module):
    """The package's modules that `module` imports, anywhere in it (a function's
    lazy import too), with the faces (__init__) they run on the way, other than
    the importer's own packages (already running) and the root."""
    path = MODULES[module]
    package = module if _is_package(module) else module.rsplit(".", 1)[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.rsplit(".", node.level - 1)[0] if node.level > 1 else package
                base = f"{base}.{node.module}" if node.module else base
            else:
                base = node.module
            if not base.startswith("rollerrig"):
                continue
            for alias in node.names:
                sub = f"{base}.{alias.name}"
                found.add(sub if sub in MODULES or sub == "rollerrig._core" else base)
        elif isinstance(node, ast.Import):
            found |= {a.name for a in node.names if a.name.startswith("rollerrig")}
    targets = set()
    for target in found:
        parts = target.split(".")
        for i in range(2, len(parts) + 1):       # the target and the faces it runs
            name = ".".join(parts[:i])
            if not (module == name or module.startswith(name + ".")):
                targets.add(name)
        if target == "rollerrig":
            targets.add(target)
    return targets - {module}


GRAPH = {m: _imports(m) for m in MODULES}


def test_every_module_stands_in_a_wing_or_is_a_room_of_the_package():
    for module in MODULES:
        _floor(module)
    for wing in WINGS:
        assert (PKG / wing.split(".")[1] / "__init__.py").is_file(), wing


@pytest.mark.parametrize("module", sorted(MODULES))
def test_imports_go_down_or_across(module):
    for target in sorted(GRAPH[module]):
        if target == "rollerrig":
            pytest.fail(f"{module} imports the package itself (its __init__ imports everything)")
        assert _floor(target) <= _floor(module), \
            f"{module} (floor {_floor(module)}) imports {target} (floor {_floor(target)})"


def test_no_import_circle():
    seen, path = {}, []

    def visit(m):
        seen[m] = "open"
        path.append(m)
        for n in sorted(GRAPH.get(m, ())):
            if seen.get(n) == "open":
                pytest.fail("import circle: " + " -> ".join(path[path.index(n):] + [n]))
            if n not in seen:
                visit(n)
        path.pop()
        seen[m] = "done"
    for m in sorted(GRAPH):
        if m not in seen:
            visit(m)


@pytest.mark.parametrize("module", sorted(MODULES))
def test_no_module_over_800_lines(module):
    lines = len(MODULES[module].read_text().splitlines())
    assert lines <= MAX_LINES, f"{MODULES[module]}: {lines} lines; split it along its seams"


def test_old_module_paths_import_the_wings_modules():
    import rollerrig
    assert rollerrig._MOVED
    for old, new in rollerrig._MOVED.items():
        assert not (PKG / f"{old}.py").exists() and not (PKG / old).exists(), old
        moved = importlib.import_module(f"rollerrig.{new}")
        assert importlib.import_module(f"rollerrig.{old}") is moved, old
        assert sys.modules[f"rollerrig.{old}"] is moved
    from rollerrig.profiles import Profile
    from rollerrig.sweep import sweep_rig
    from rollerrig.rig_contact import WheelContact
    assert Profile is rollerrig.Profile and sweep_rig is rollerrig.sweep_rig
    assert WheelContact is rollerrig.WheelContact
    # the package's attributes as before: rr.sweep and rr.rig_contact the functions
    assert callable(rollerrig.sweep) and callable(rollerrig.rig_contact)
    assert rollerrig.profiles is sys.modules["rollerrig.geometry.profiles"]
