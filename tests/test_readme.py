"""README.md's code, and the documentation site's guide, run as written.

The ```python blocks of each page run in order in one namespace (README.md;
then docs/getting_started.md and the guide's pages, docs/guide/, in the
guide's order, one namespace for them all: the guide continues from page to
page), on the `.[test]` install
the README tells the user to make, from a temporary working folder (nothing is
written into the checkout), with matplotlib's non-interactive backend.  A block
that fails names its README line.

A block that needs what only an extra gives says so in it: run on the base
install (the extras' modules hidden), such a block must name
`pip install ".[extra]"` for extras that make it run.

The two set-up commands of the README's ```sh block are the ones .ci/run runs.
"""
import re
import sys
import traceback
from pathlib import Path

import pytest

from conftest import ROOT

pytestmark = pytest.mark.slow     # the README's code, an FMU build among it

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

README = Path(ROOT) / "README.md"
DOCS = Path(ROOT) / "docs"
CI_SCRIPT = Path(ROOT) / ".ci" / "run"

# Top-level modules that only an extra installs, and the extras that give them
# (setup.cfg; test_extras_table_matches_setup_cfg keeps the two in step).
EXTRA_MODULES = {
    "scipy": {"fit"},
    "xarray": {"sweep"},
    "pandas": {"sweep"},
    "dask": {"distributed"},
    "distributed": {"distributed"},
}
EXTRA_DISTRIBUTIONS = {"scipy": "scipy", "xarray": "xarray", "pandas": "pandas",
                       "dask": "dask[distributed]",
                       "distributed": "dask[distributed]"}
EXTRA_NOTE = re.compile(r'"\.\[([\w,]+)\]"')       # ".[sweep]", ".[fit,sweep]"


class Block:
    def __init__(self, path, kind, first_line, lines, heading):
        self.path = path                # the page
        self.kind = kind                # the fence's language, e.g. "python"
        self.first_line = first_line    # the page's line number of the block's first line
        self.lines = lines
        self.heading = heading          # the section it sits in

    @property
    def source(self):
        return "\n".join(self.lines)

    def __repr__(self):
        return (f"{self.path.relative_to(ROOT)} lines {self.first_line}-"
                f"{self.first_line + len(self.lines) - 1}")


def page_blocks(path, kind):
    blocks, heading, fence = [], "", None
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if fence is None:
            if line.startswith("#"):
                heading = line.lstrip("#").strip()
            elif line.startswith("```"):
                fence = Block(path, line[3:].strip(), number + 1, [], heading)
        elif line.startswith("```"):
            blocks.append(fence)
            fence = None
        else:
            fence.lines.append(line)
    return [b for b in blocks if b.kind == kind]


def readme_blocks(kind):
    return page_blocks(README, kind)


def guide_pages():
    """docs/getting_started.md, then the guide's pages in its toctree's order."""
    toc = (DOCS / "guide" / "index.md").read_text(encoding="utf-8")
    body = toc.split("```{toctree}", 1)[1].split("```", 1)[0]
    names = [line.strip() for line in body.splitlines()
             if line.strip() and not line.strip().startswith(":")]
    return [DOCS / "getting_started.md"] + [DOCS / "guide" / f"{n}.md" for n in names]


#: the chains of blocks, each run in order in one namespace
CHAINS = {"README": readme_blocks("python"),
          "guide": [b for page in guide_pages() for b in page_blocks(page, "python")]}
PYTHON_BLOCKS = [b for chain in CHAINS.values() for b in chain]


def run_block(block, namespace):
    """Execute a block in namespace; on failure, say which page line failed."""
    # padded so that tracebacks count the page's lines
    code = compile("\n" * (block.first_line - 1) + block.source, str(block.path), "exec")
    try:
        exec(code, namespace)
    except Exception as exc:
        lines = [f.lineno for f in traceback.extract_tb(exc.__traceback__)
                 if f.filename == str(block.path)]
        where = lines[-1] if lines else block.first_line
        text = block.lines[where - block.first_line].strip()
        raise AssertionError(f"{block.path.name} line {where} ({block.heading!r} block, "
                             f"{block!r}): {text}\n  {type(exc).__name__}: {exc}") from exc


@pytest.fixture(scope="module")
def namespaces(tmp_path_factory):
    """Run every chain's blocks in order on the full install: the namespace
    before each block (in PYTHON_BLOCKS' order)."""
    import matplotlib.pyplot as plt

    before = []
    for name, chain in CHAINS.items():
        workdir = tmp_path_factory.mktemp(name)
        namespace = {"__name__": "__readme__"}
        with pytest.MonkeyPatch.context() as mp:
            mp.chdir(workdir)
            for block in chain:
                before.append(dict(namespace))
                run_block(block, namespace)
        plt.close("all")
    return before


def test_readme_has_python_blocks():
    assert len(CHAINS["README"]) >= 2, CHAINS["README"]
    assert len(CHAINS["guide"]) >= 10, CHAINS["guide"]


def test_python_blocks_run_in_order(namespaces):
    assert len(namespaces) == len(PYTHON_BLOCKS)


def _hide(monkeypatch, modules):
    """Make `import m` fail for each module (and its submodules), as when its
    distribution is not installed."""
    for name in list(sys.modules):
        if name.split(".")[0] in modules:
            monkeypatch.setitem(sys.modules, name, None)
    for name in modules:
        monkeypatch.setitem(sys.modules, name, None)


def _extras_named(block):
    return {extra for group in EXTRA_NOTE.findall(block.source) for extra in group.split(",")}


def setup_cfg():
    import configparser

    cfg = configparser.ConfigParser()
    cfg.read(Path(ROOT) / "setup.cfg", encoding="utf-8")
    extras = {name: value.split() for name, value in cfg["options.extras_require"].items()}
    return cfg["options"]["install_requires"].split(), extras


@pytest.mark.parametrize("index", [pytest.param(i, id=f"{b.path.stem}:{b.heading or i}")
                                   for i, b in enumerate(PYTHON_BLOCKS)])
def test_block_names_the_extra_it_needs(index, namespaces, monkeypatch, tmp_path):
    import matplotlib.pyplot as plt

    block = PYTHON_BLOCKS[index]
    monkeypatch.chdir(tmp_path)
    named = _extras_named(block)
    with monkeypatch.context() as base_install:
        _hide(base_install, set(EXTRA_MODULES))
        try:
            run_block(block, dict(namespaces[index]))
            return
        except AssertionError as failure:
            on_base_install = failure
    plt.close("all")
    assert named, (f"{block!r} fails on the base install (`pip install .`) and names no "
                   f'`pip install ".[extra]"`:\n{on_base_install}')
    unknown = named - set(setup_cfg()[1])
    assert not unknown, f"{block!r} names extras setup.cfg lacks: {unknown}"
    still_missing = {m for m, extras in EXTRA_MODULES.items() if not extras & named}
    with monkeypatch.context() as with_extras:
        _hide(with_extras, still_missing)
        run_block(block, dict(namespaces[index]))
    plt.close("all")


def test_extras_table_matches_setup_cfg():
    """EXTRA_MODULES above says what setup.cfg's extras install."""
    base, extras = setup_cfg()
    for module, names in EXTRA_MODULES.items():
        distribution = EXTRA_DISTRIBUTIONS[module]
        assert not any(r.startswith(distribution.split("[")[0]) for r in base), \
            f"{distribution} is a base dependency now: drop {module} from EXTRA_MODULES"
        for extra in names:
            assert any(r.startswith(distribution) for r in extras[extra]), \
                f"setup.cfg's {extra!r} extra no longer lists {distribution}"


def test_shell_commands_are_the_ones_ci_runs():
    """The README's two commands, as written, are lines of .ci/run."""
    blocks = readme_blocks("sh")
    commands = [[line.split("#")[0].strip() for line in b.lines if line.strip()] for b in blocks]
    assert len(commands[0]) == 2, commands[0]      # the first block: the two set-up commands
    ci_lines = {line.strip() for line in CI_SCRIPT.read_text(encoding="utf-8").splitlines()}
    for command in (c for block in commands for c in block):   # the docs' command too
        assert command in ci_lines, f".ci/run does not run the README's `{command}`"
