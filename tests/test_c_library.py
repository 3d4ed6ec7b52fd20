"""The C core as a library for C programs outside the tree.

(a) `make -C csrc install PREFIX=...` (and DESTDIR, uninstall):
    examples/rig_paper.c, copied outside the tree and built with `pkg-config --cflags --libs rollerrig` against the shared and
    against the static library, gives rr.simulate()'s records bit for bit.
(b) The installed Python package's C library (rollerrig.get_include(),
    get_library_dir(), its rollerrig.pc, rollerrig-config): the same
    program, built against it, gives them too; the shipped sources compile.
(c) docs/c_api.md is what docs/c_api.py writes from the headers, and every
    public function there has its comment block.

Builds need `make` and a C compiler, the pkg-config builds `pkg-config`
(pkgconf): skipped, saying which, where one is missing.
"""
import importlib.util
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import _core, capi

from conftest import ROOT
from test_c_core import _compiler

pytestmark = pytest.mark.slow     # C programs built against the installed library

REPO = Path(ROOT)
CSRC = REPO / "csrc"
CFLAGS = ["-std=c99", "-Wall", "-Wextra", "-pedantic", "-Werror", "-O2"]

# The paper's scenario from C alone, every sample's record as raw doubles on
# stdout: examples/rig_paper.c itself, compiled outside the tree.
PAPER_C = (REPO / "examples" / "rig_paper.c").read_text()


# ------------------------------------------------------------------ helpers

def _cc():
    cc = _compiler()
    if cc is None:
        pytest.skip("no C compiler found ($CC or `cc`)")
    return cc


def _pkg_config():
    exe = shutil.which("pkg-config") or shutil.which("pkgconf")
    if exe is None:
        pytest.skip("pkg-config (or pkgconf) not found on PATH: apt-get install pkg-config")
    return exe


def _run(cmd, env=None, **kw):
    proc = subprocess.run([str(c) for c in cmd], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          env=env, timeout=300, **kw)
    assert proc.returncode == 0, (f"{' '.join(map(str, cmd))} failed ({proc.returncode}):\n"
                                  f"{proc.stderr.decode(errors='replace')}")
    return proc.stdout


def _pkg(pc_dir, *args):
    env = dict(os.environ, PKG_CONFIG_PATH=str(pc_dir))
    env.pop("PKG_CONFIG_LIBDIR", None)
    return _run([_pkg_config(), *args, "rollerrig"], env=env).decode().split()


def _build(tmp, name, source, flags):
    """Compile source (text) in tmp into tmp/name with flags after it."""
    src = tmp / f"{name}.c"
    src.write_text(source)
    exe = tmp / name
    _run(_cc() + CFLAGS + [src, "-o", exe] + list(flags))
    return exe


def _assert_paper_records(out, simulated):
    c = np.frombuffer(out, dtype=np.float64).reshape(-1, _core.REC_COUNT)
    assert c.shape == simulated.shape
    assert np.array_equal(np.isnan(c), np.isnan(simulated))
    assert np.array_equal(c.view(np.uint64)[~np.isnan(c)],
                          simulated.view(np.uint64)[~np.isnan(simulated)])


def _needed(exe):
    """The DT_NEEDED libraries of an ELF file (readelf), or None."""
    readelf = shutil.which("readelf")
    if readelf is None:
        return None
    out = _run([readelf, "-d", exe]).decode()
    return re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", out)


def _files(folder):
    return sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*")
                  if p.is_file() or p.is_symlink())


def _version_macros(header):
    text = header.read_text(encoding="utf-8")
    return ".".join(re.search(rf"#define RR_VERSION_{part} (\d+)", text).group(1)
                    for part in ("MAJOR", "MINOR", "PATCH"))


@pytest.fixture(scope="module")
def simulated():
    return rr.simulate().records


@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    """An install by `make -C csrc install PREFIX=...` (its -fPIC objects
    built once in csrc/build/pic/)."""
    if not (CSRC / "Makefile").is_file():
        pytest.skip(f"needs the source tree ({CSRC / 'Makefile'} not found)")
    if shutil.which("make") is None:
        pytest.skip("`make` not found on PATH")
    _cc()
    where = tmp_path_factory.mktemp("prefix")
    _run(["make", "-C", CSRC, "-j", str(os.cpu_count() or 1), "install", f"PREFIX={where}"])
    return where


# ------------------------------------------------------ (a) make install

def _public_headers():
    layers = sorted({p.parent.name for p in CSRC.glob("*/rr_*.c")})
    return ["rollerrig.h"] + sorted(p.relative_to(CSRC).as_posix() for layer in layers
                                    for pattern in ("rr_*.h", "*.def")
                                    for p in (CSRC / layer).glob(pattern))


def test_install_puts_libraries_headers_and_pc_file_under_the_prefix(prefix):
    version = _version_macros(CSRC / "util" / "rr_common.h")
    assert version == rr.__version__, "RR_VERSION_* of rr_common.h differ from _version.py"
    major, minor, _ = version.split(".")
    soname = f"librollerrig.so.{major}.{minor}" if major == "0" else f"librollerrig.so.{major}"
    lib = prefix / "lib"
    assert (lib / "librollerrig.a").is_file()
    assert (lib / f"librollerrig.so.{version}").is_file()
    assert os.readlink(lib / soname) == f"librollerrig.so.{version}"
    assert os.readlink(lib / "librollerrig.so") == soname
    headers = _files(prefix / "include" / "rollerrig")
    assert headers == sorted(_public_headers())
    for name in headers:
        assert (prefix / "include" / "rollerrig" / name).read_bytes() == (CSRC / name).read_bytes()
    readelf = shutil.which("readelf")
    if readelf:
        dyn = _run([readelf, "-d", lib / f"librollerrig.so.{version}"]).decode()
        assert f"Library soname: [{soname}]" in dyn
        assert "libm.so" in dyn
    pc = (lib / "pkgconfig" / "rollerrig.pc").read_text()
    assert f"prefix={prefix}\n" in pc and f"Version: {version}\n" in pc
    assert "Libs.private: -lm" in pc


def test_pkg_config_names_the_install(prefix):
    pc_dir = prefix / "lib" / "pkgconfig"
    assert _pkg(pc_dir, "--modversion") == [rr.__version__]
    assert _pkg(pc_dir, "--cflags") == [f"-I{prefix}/include/rollerrig"]
    assert _pkg(pc_dir, "--libs") == [f"-L{prefix}/lib", "-lrollerrig"]
    assert _pkg(pc_dir, "--static", "--libs") == [f"-L{prefix}/lib", "-lrollerrig", "-lm"]


def test_program_outside_the_tree_against_the_shared_library(prefix, tmp_path, simulated):
    pc_dir = prefix / "lib" / "pkgconfig"
    exe = _build(tmp_path, "paper_shared", PAPER_C, _pkg(pc_dir, "--cflags", "--libs"))
    needed = _needed(exe)
    if needed is not None:
        assert any(n.startswith("librollerrig.so.") for n in needed), needed
    env = dict(os.environ, LD_LIBRARY_PATH=str(prefix / "lib"))
    _assert_paper_records(_run([exe], env=env), simulated)


def test_program_outside_the_tree_against_the_static_library(prefix, tmp_path, simulated):
    pc_dir = prefix / "lib" / "pkgconfig"
    (libdir,) = _pkg(pc_dir, "--variable=libdir")
    exe = _build(tmp_path, "paper_static", PAPER_C,
                 _pkg(pc_dir, "--cflags") + [f"{libdir}/librollerrig.a", "-lm"])
    needed = _needed(exe)
    if needed is not None:
        assert not any("rollerrig" in n for n in needed), needed
    _assert_paper_records(_run([exe]), simulated)


def test_include_with_the_folder_name_works_too(prefix, tmp_path):
    """#include <rollerrig/rollerrig.h> where PREFIX/include is searched
    (as /usr/local/include is by default), with pkg-config's flags: the
    headers' own includes ("contact/rr_contact.h") need -I PREFIX/include/rollerrig."""
    source = ('#include <rollerrig/rollerrig.h>\n'
              'int main(void) { return rr_status_message(RR_OK)[0] == 0; }\n')
    flags = _pkg(prefix / "lib" / "pkgconfig", "--cflags", "--libs")
    exe = _build(tmp_path, "folder", source, [f"-I{prefix}/include"] + flags)
    _run([exe], env=dict(os.environ, LD_LIBRARY_PATH=str(prefix / "lib")))


def test_destdir_stages_the_install_and_uninstall_removes_it(prefix, tmp_path):
    stage = tmp_path / "stage"
    args = ["make", "-C", CSRC, f"DESTDIR={stage}", "PREFIX=/opt/rr"]
    _run(args + ["install"])
    files = _files(stage / "opt" / "rr")
    assert "lib/librollerrig.a" in files and "include/rollerrig/rig/rr_rig.h" in files
    pc = (stage / "opt" / "rr" / "lib" / "pkgconfig" / "rollerrig.pc").read_text()
    assert "prefix=/opt/rr\n" in pc            # the final prefix, not the staging one
    _run(args + ["uninstall"])
    assert _files(stage) == []
    assert not (stage / "opt" / "rr" / "include" / "rollerrig").exists()


@pytest.mark.parametrize("bad", ["relative/folder", ""])
def test_install_refuses_a_prefix_that_is_not_absolute(bad):
    if shutil.which("make") is None or not (CSRC / "Makefile").is_file():
        pytest.skip("needs make and the source tree")
    proc = subprocess.run(["make", "-C", str(CSRC), "install", f"PREFIX={bad}"],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          timeout=60)
    assert proc.returncode != 0
    assert f"PREFIX='{bad}' is not an absolute folder" in proc.stdout
    assert not (CSRC / "relative").exists()


# ------------------------------------------------- (b) the Python package

def test_package_paths_hold_the_headers_library_sources_and_pc_file():
    include = Path(rr.get_include())
    assert (include / "rollerrig.h").is_file()
    for name in _public_headers() if CSRC.is_dir() else ["rig/rr_rig.h"]:
        assert (include / name).is_file(), name
    assert _version_macros(include / "util" / "rr_common.h") == rr.__version__
    assert (Path(rr.get_library_dir()) / "librollerrig.a").is_file()
    sources = Path(rr.get_source_dir())
    shipped = sorted(p.relative_to(sources).as_posix() for p in sources.glob("*/rr_*.c"))
    assert "rig/rr_rig.c" in shipped and "contact/rr_exact_table_data.c" in shipped
    if CSRC.is_dir():
        assert shipped == sorted(p.relative_to(CSRC).as_posix() for p in CSRC.glob("*/rr_*.c"))
    pc = (Path(rr.get_pkgconfig_dir()) / "rollerrig.pc").read_text()
    assert f"Version: {rr.__version__}\n" in pc and "${pcfiledir}" in pc


def test_config_command_prints_the_flags_and_folders(capsys):
    assert capi.main(["--cflags", "--libs"]) == 0
    assert capsys.readouterr().out.split() == [
        f"-I{rr.get_include()}", f"-L{rr.get_library_dir()}", "-lrollerrig", "-lm"]
    # in the order of the options' list, whatever the order asked
    assert capi.main(["--version", "--pkgconfigdir", "--srcdir"]) == 0
    assert capsys.readouterr().out.split() == [rr.get_source_dir(), rr.get_pkgconfig_dir(),
                                               rr.__version__]
    assert capi.main([]) == 2                 # nothing asked: the help
    assert "rollerrig-config" in capsys.readouterr().out


def test_program_against_the_package_headers_and_static_library(tmp_path, simulated):
    """The flags rollerrig-config prints (-I get_include(), -L
    get_library_dir() -lrollerrig -lm): the extension's own objects."""
    flags = [f"-I{rr.get_include()}", f"-L{rr.get_library_dir()}", "-lrollerrig", "-lm"]
    exe = _build(tmp_path, "paper_package", PAPER_C, flags)
    _assert_paper_records(_run([exe]), simulated)


def test_program_against_the_package_through_its_pc_file(tmp_path):
    """The minimal program of docs/c_api.md, built with the package's
    rollerrig.pc (relocatable: ${pcfiledir})."""
    flags = _pkg(rr.get_pkgconfig_dir(), "--cflags", "--libs")
    assert Path(flags[0][2:]).resolve() == Path(rr.get_include()).resolve()
    exe = _build(tmp_path, "minimal", _page_example(), flags)
    out = _run([exe]).decode()
    assert re.fullmatch(r"t = 2\.000 s: creepage 0\.0\d+, adhesion 0\.\d+\n", out), out


def test_package_sources_compile_on_their_own(tmp_path):
    """get_source_dir() holds what the core's sources include: -I it alone."""
    source_dir = Path(rr.get_source_dir())
    sources = sorted(source_dir.glob("*/rr_*.c"))
    _run(_cc() + CFLAGS + ["-fsyntax-only", f"-I{source_dir}"] + sources, cwd=tmp_path)
    for header in Path(rr.get_include()).rglob("*.h"):
        relative = header.relative_to(rr.get_include())
        assert (source_dir / relative).read_bytes() == header.read_bytes(), relative


# ------------------------------------------------------ (c) the C API page

def _c_api():
    script = REPO / "docs" / "c_api.py"
    if not script.is_file() or not CSRC.is_dir():
        pytest.skip("needs the source tree (docs/c_api.py, csrc/)")
    spec = importlib.util.spec_from_file_location("c_api", script)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _page_example():
    page = (REPO / "docs" / "c_api.md")
    if not page.is_file():
        pytest.skip("needs docs/c_api.md")
    match = re.search(r"## A minimal program.*?```c\n(.*?)```", page.read_text(), re.S)
    return match.group(1)


def test_the_c_api_page_is_generated_from_the_headers():
    c_api = _c_api()
    assert c_api.PAGE.read_text(encoding="utf-8") == c_api.render(), \
        "docs/c_api.md is stale: run python docs/c_api.py"


def test_every_public_function_has_its_comment_block():
    assert _c_api().undocumented() == []


def test_the_page_lists_every_function_the_headers_declare():
    """The page's parser against a plain search of the headers: every
    rr_ function declared at the start of a line is on the page, but for
    those after a comment that begins "Not API" (up to the next comment)."""
    c_api = _c_api()
    headings = re.findall(r"^#### (.*)$", c_api.PAGE.read_text(encoding="utf-8"), re.M)
    on_page = {name for line in headings for name in re.findall(r"`(rr_\w+)`", line)}
    declared = set()
    for _, _, paths in c_api.headers():
        for path in paths:
            # each comment becomes a marker on its first line, its lines kept
            text = re.sub(r"/\*.*?\*/", lambda m: ("@internal" if re.match(r"/\*\s*Not API", m.group())
                                               else "@comment") + "\n" * m.group().count("\n"),
                          path.read_text(encoding="utf-8"), flags=re.S)
            internal = False
            for line in text.splitlines():
                if "@internal" in line or "@comment" in line:
                    internal = "@internal" in line
                m = re.match(r"(?:static inline )?(?:const )?\w+(?:[\s*]+const)?[\s*]+(rr_\w+)\(",
                                 line)     # a const pointer too: const char *const *rr_..(
                if m and not internal:
                    declared.add(m.group(1))
    assert len(declared) > 100
    assert declared == on_page, (declared ^ on_page)
