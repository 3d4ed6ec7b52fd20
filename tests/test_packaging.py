"""What the source distribution and the extras carry.

The sdist is the checkout less the README's pictures: unpacked, it must
build, install and pass these tests (.ci/run does that, and checks LICENSE and
NOTICE in the wheel, which needs a compile).  Here the sdist is built without
network or compiler from a copy of the tracked files with build products
planted in it, and its member list is checked.

The `notebooks` extra, with the base install, provides every module the
notebooks import.
"""
import ast
import fnmatch
import glob
import importlib.util
import json
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tarfile
from pathlib import Path

import pytest

from conftest import ROOT

pytestmark = pytest.mark.slow     # builds the sdist and wheels

REPO = Path(ROOT)

# tracked but left out of the sdist: the README's pictures (examples/ remakes them)
NOT_SHIPPED = ["docs/*.png"]
# what a build or a run leaves in the tree; none of it may ship
BUILD_PRODUCTS = [
    "csrc/build/rr_hertz.o",
    "csrc/build/rr_hertz.d",
    "csrc/build/librollerrig.a",
    "csrc/build/tests/test_hertz",
    "csrc/build/san/tests/test_hertz",
    "csrc/rr_hertz.o",
    "rollerrig/_core.cpython-311-x86_64-linux-gnu.so",
    "tests/__pycache__/conftest.cpython-311-pytest-8.0.0.pyc",
    "benchmarks/out/bench.json",
    "notebooks/.ipynb_checkpoints/rig_scenario-checkpoint.ipynb",
    "rollerrig-out/rig_history.csv",
    "build/lib/rollerrig/__init__.py",
    "csrc/build/pic/librollerrig.so.0.1.0",
    "rollerrig/_c/lib/librollerrig.a",
    "rollerrig/_c/lib/pkgconfig/rollerrig.pc",
    "docs/_build/html/index.html",
    "docs/api/generated/rollerrig.hertz.rst",
    "docs/gallery/index.md",
    "docs/notebooks/rig_scenario.ipynb",
    "docs/jupyter_execute/x.ipynb",
]


def _tracked_files():
    if shutil.which("git") is None or not (REPO / ".git").exists():
        pytest.skip("not a git checkout (e.g. an unpacked sdist): nothing to compare with")
    out = subprocess.run(["git", "ls-files", "-z"], cwd=REPO, check=True,
                         stdout=subprocess.PIPE).stdout.decode()
    return [name for name in out.split("\0") if name and (REPO / name).is_file()]


@pytest.fixture(scope="module")
def sdist_members(tmp_path_factory):
    """Member names (relative to the sdist's top folder) of an sdist built
    from a copy of the tracked files plus BUILD_PRODUCTS."""
    pytest.importorskip("build", reason="the test extra installs `build`")
    tracked = _tracked_files()
    src = tmp_path_factory.mktemp("checkout")
    for name in tracked + BUILD_PRODUCTS:
        dest = src / name
        dest.parent.mkdir(parents=True, exist_ok=True)
        if name in BUILD_PRODUCTS:
            dest.write_bytes(b"build product\n")
        else:
            shutil.copy2(REPO / name, dest)
    out = tmp_path_factory.mktemp("dist")
    proc = subprocess.run([sys.executable, "-m", "build", "--sdist", "--no-isolation",
                           "--outdir", str(out), str(src)],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          timeout=300)
    assert proc.returncode == 0, f"building the sdist failed:\n{proc.stdout}"
    (archive,) = glob.glob(str(out / "rollerrig-*.tar.gz"))
    with tarfile.open(archive) as tar:
        names = [m.name for m in tar.getmembers() if m.isfile()]
    top = {n.split("/", 1)[0] for n in names}
    assert len(top) == 1, top
    return tracked, {n.split("/", 1)[1] for n in names}


def test_sdist_has_every_tracked_file(sdist_members):
    tracked, members = sdist_members
    wanted = [n for n in tracked if not any(fnmatch.fnmatch(n, p) for p in NOT_SHIPPED)]
    missing = sorted(set(wanted) - members)
    assert not missing, f"tracked files missing from the sdist (MANIFEST.in): {missing}"
    for folder in ("csrc/", "csrc/tests/", "tests/", "tests/data/", "notebooks/", "examples/"):
        assert any(n.startswith(folder) for n in wanted), f"no tracked file under {folder}"


def test_sdist_has_licence_notice_and_readme(sdist_members):
    _, members = sdist_members
    for name in ("LICENSE", "NOTICE", "README.md", "MANIFEST.in", ".ci/run"):
        assert name in members, name
    # setuptools names them in the metadata too (License-File)
    assert "rollerrig.egg-info/SOURCES.txt" in members


def test_sdist_has_no_build_products(sdist_members):
    _, members = sdist_members
    shipped = sorted(set(BUILD_PRODUCTS) & members)
    assert not shipped, f"build products in the sdist: {shipped}"
    patterns = ["*.o", "*.a", "*.so", "*.so.*", "*.pyc", "*/__pycache__/*", "csrc/build/*",
                "rollerrig/_c/*"]
    products = sorted(n for n in members if any(fnmatch.fnmatch(n, p) for p in patterns))
    assert not products, products


# ------------------------------------------------------------ licence and notice

# MD5 of the Apache License 2.0 as the ASF publishes it (LICENSE-2.0.txt)
APACHE_2_MD5 = "3b83ef96387f14655fc854ddc3c6bd57"


def test_licence_is_the_apache_text_the_metadata_names():
    import configparser
    import hashlib

    text = (REPO / "LICENSE").read_bytes()
    assert hashlib.md5(text).hexdigest() == APACHE_2_MD5, "LICENSE is not the verbatim text"
    cfg = configparser.ConfigParser()
    cfg.read(REPO / "setup.cfg", encoding="utf-8")
    assert cfg["metadata"]["license_expression"] == "Apache-2.0"
    assert cfg["metadata"]["license_files"].split() == ["LICENSE", "NOTICE"]


def _from_contact():
    """Shipped data files that come from CONTACT: the profiles, and every file
    whose first line names CONTACT's repository as its source."""
    profiles = [p for p in (REPO / "rollerrig" / "data" / "profiles").iterdir()
                if p.name != "README.md"]
    tables = []
    for folder in ("rollerrig/data", "tests/data"):
        for path in sorted((REPO / folder).rglob("*.csv")):
            with open(path, encoding="utf-8") as f:
                if "eve70a/CONTACT" in f.readline():
                    tables.append(path)
    return profiles + tables


def test_notice_names_every_file_from_contact():
    notice = (REPO / "NOTICE").read_text(encoding="utf-8")
    assert "Copyright 2026 the rollerrig authors" in notice
    assert "github.com/eve70a/CONTACT" in notice and "Apache License, Version 2.0" in notice
    files = _from_contact()
    assert len(files) >= 12, files
    words = set(re.findall(r"\w[\w.-]*\w", notice))
    unnamed = [str(p.relative_to(REPO)) for p in files
               if p.name not in words or f"{p.parent.relative_to(REPO).as_posix()}/:" not in notice]
    assert not unnamed, f"NOTICE does not attribute these files from CONTACT: {unnamed}"


# ------------------------------------------------------------ the notebooks extra

# top-level (or dotted) module -> the requirements that provide it, any of them
MODULE_PROVIDERS = {
    "numpy": {"numpy"},
    "matplotlib": {"matplotlib"},
    "scipy": {"scipy"},
    "pandas": {"pandas"},
    "xarray": {"xarray"},
    "tqdm": {"tqdm"},
    "dask": {"dask", "dask[distributed]"},
    "dask.distributed": {"dask[distributed]", "distributed"},
    "distributed": {"dask[distributed]", "distributed"},
    "IPython": {"ipykernel", "ipython", "jupyterlab"},
    "ipywidgets": {"ipywidgets"},
}


def _requirements(extra=None):
    """Requirements ("numpy", "dask[distributed]") of the base install, or of an
    extra with the extras it names through rollerrig[...]."""
    import configparser

    from packaging.requirements import Requirement

    cfg = configparser.ConfigParser()
    cfg.read(REPO / "setup.cfg", encoding="utf-8")
    todo = [cfg["options"]["install_requires"] if extra is None
            else cfg["options.extras_require"][extra]]
    seen, out = {extra}, set()
    while todo:
        for line in todo.pop().split("\n"):
            if not line.strip():
                continue
            req = Requirement(line)
            name = req.name.lower()
            if name == "rollerrig":
                todo += [cfg["options.extras_require"][e] for e in req.extras - seen]
                seen |= req.extras
                continue
            out |= {name} | {f"{name}[{e}]" for e in req.extras}
    return out


def _stdlib(module):
    names = getattr(sys, "stdlib_module_names", None)      # Python >= 3.10
    if names is not None:
        return module in names
    spec = importlib.util.find_spec(module)
    if spec is None:
        return False
    origin = spec.origin or ""
    return origin in ("built-in", "frozen") or (
        origin.startswith(sysconfig.get_paths()["stdlib"]) and "site-packages" not in origin)


def notebook_imports(path):
    """Modules imported by a notebook's code cells (dotted, as written)."""
    with open(path, encoding="utf-8") as f:
        nb = json.load(f)
    modules = set()
    for cell in nb["cells"]:
        if cell["cell_type"] != "code":
            continue
        # IPython's magics and shell lines are not Python
        source = "\n".join(line for line in "".join(cell["source"]).splitlines()
                           if not line.lstrip().startswith(("%", "!")))
        for node in ast.walk(ast.parse(source)):
            if isinstance(node, ast.Import):
                modules |= {alias.name for alias in node.names}
            elif isinstance(node, ast.ImportFrom) and node.level == 0:
                modules.add(node.module)
    return modules


NOTEBOOKS = sorted(glob.glob(str(REPO / "notebooks" / "*.ipynb")))


def test_there_are_notebooks():
    assert NOTEBOOKS


@pytest.mark.parametrize("path", NOTEBOOKS, ids=os.path.basename)
def test_notebooks_extra_provides_every_import(path):
    provided = _requirements() | _requirements("notebooks")
    for module in sorted(notebook_imports(path)):
        top = module.split(".")[0]
        if top == "rollerrig" or _stdlib(top):
            continue
        key = max((k for k in MODULE_PROVIDERS if module == k or module.startswith(k + ".")),
                  key=len, default=None)
        assert key is not None, (f"{os.path.basename(path)} imports {module}: add the "
                                 "distribution that provides it to MODULE_PROVIDERS")
        assert MODULE_PROVIDERS[key] & provided, (
            f"{os.path.basename(path)} imports {module}, which neither the base install nor "
            f"the notebooks extra provides (any of {sorted(MODULE_PROVIDERS[key])})")


def test_notebooks_extra_can_open_and_run_notebooks():
    provided = _requirements("notebooks")
    assert {"nbclient", "nbformat", "ipykernel"} <= provided, provided
    assert provided & {"jupyterlab", "notebook"}, "nothing to open the notebooks with"


def test_requirement_parser_expands_self_references():
    assert {"pytest", "scipy", "xarray", "pandas", "dask[distributed]"} <= _requirements("test")
    assert "numpy" in _requirements()


# ------------------------------------------------------------ the checkout

def test_gitignore_covers_what_runs_leave():
    """`rollerrig simulate` from the checkout (the README's first command),
    the C builds and the test runs leave nothing for `git status` to show."""
    _tracked_files()                                  # skips outside a git checkout
    from rollerrig.cli import build_parser

    out = build_parser().parse_args(["simulate"]).out
    left = [f"{out}/rig_history.csv", "csrc/build/rr_hertz.o", ".pytest_cache/README.md",
            ".hypothesis/examples/0", "tests/__pycache__/conftest.pyc", "build/lib/x.py",
            "dist/rollerrig-0.1.0.tar.gz", "rollerrig.egg-info/PKG-INFO",
            "rollerrig/_c/lib/librollerrig.a", "rollerrig/_c/lib/pkgconfig/rollerrig.pc",
            "csrc/build/pic/librollerrig.so.0.1.0"]
    for path in left:
        proc = subprocess.run(["git", "check-ignore", "-q", path], cwd=REPO)
        assert proc.returncode == 0, f".gitignore does not cover {path}"
