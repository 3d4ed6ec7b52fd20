"""FMI co-simulation units (FMUs) of the rig: ``rollerrig fmu OUT.fmu``.

    from rollerrig.fmu import build_fmu
    build_fmu("rig.fmu")                                   # FMI 2.0, the paper's scenario
    build_fmu("rig3.fmu", scenario="my.toml", fmi_version=3)

An FMU is a zip of
  modelDescription.xml        the variables, written by the C side
                              (csrc/fmu/rr_fmu_xml.h) from the rig's declarations
                              at the FMU's start values
  binaries/<platform>/<id>.so the rig's C core, the FMU layer (csrc/fmu/rr_fmu.h)
                              and the FMI adapter, compiled here with the system C
                              compiler ($CC, cc, gcc or clang); only the fmi2* or
                              fmi3* functions are exported
  sources/                    the same C sources in their layer folders (FMI 3:
                              and buildDescription.xml), the FMU's start values
                              in sources/fmu_start.c
  documentation/licenses/     the licence
Its start values are the default parameters overridden by the scenario file
(the layout of rollerrig/data/rig_default.toml); with the default inputs and
control modes an FMU run is rollerrig.simulate()'s of the same parameters,
bit for bit.  The variables are listed in docs/fmu.md.

Where the C sources come from: the core's (with the FMU layer, csrc/fmu/)
from rollerrig.get_source_dir() and get_include() (core_c_dirs, the one
place that asks), the FMU adapters' (fmi2_cs.c, fmi3_cs.c, fmi_glue.c,
their headers and fmu_describe.c, the build's description program) from the
package's data/fmi/.
"""
from __future__ import annotations

import concurrent.futures
import hashlib
import json
import os
import platform
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import uuid
import zipfile
from pathlib import Path
from typing import (Any, BinaryIO, Callable, Dict, Iterable, List, Mapping, Optional, Sequence,
                    Tuple, TypedDict, Union)

from ._errors import RollerRigError
from ._files import check_output, write_file
from ._typing import F64Array, Params
from ._version import __version__

__all__ = ["build_fmu", "FmuBuildError", "core_c_dirs", "find_compiler", "model_identifier",
           "FMI_VERSIONS"]

FMI_VERSIONS = (2, 3)

#: the flags of every FMU compile: no fused multiply-adds (the extension's
#: -ffp-contract=off: the FMU must round as rollerrig.simulate() does),
#: position-independent, nothing exported but the fmi functions
CFLAGS = ("-std=c99", "-O2", "-ffp-contract=off", "-fPIC", "-fvisibility=hidden")

FMI_DATA = Path(__file__).resolve().parent / "data" / "fmi"


LICENSE_TEXT = """\
This FMU's sources and binary are rollerrig {version} (Copyright 2026 the
rollerrig authors), licensed under the Apache License, Version 2.0
(https://www.apache.org/licenses/LICENSE-2.0).  sources/fmi2_api.h and
fmi3_api.h declare the FMI 2.0 and 3.0 interfaces as written for rollerrig
from the FMI standard of the Modelica Association (https://fmi-standard.org),
whose headers are under the 2-Clause BSD License.
"""


#: checked parameters {section: {key: value}} (rollerrig.rig.params.check_parameters)
_Checked = Mapping[str, Mapping[str, Any]]
#: a real profile's points as rollerrig.rig.real_profiles gives them: (y, z, end: 1 natural)
_ProfilePoints = Tuple[F64Array, F64Array, int]


class FmuBuildError(RollerRigError):
    """The FMU could not be built: no C compiler, a compiler error, an
    unsupported platform."""


def core_c_dirs() -> Tuple[Path, Path]:
    """(sources, headers): the folders holding the C core's sources
    (``*/rr_*.c`` in their layer folders: util, contact, geometry, rig, fmu)
    and its headers (``*/rr_*.h``, ``*/*.def``): rollerrig.get_source_dir()
    and rollerrig.get_include(), the wheel's copies or an editable
    install's csrc/."""
    from .capi import get_include, get_source_dir
    try:
        return Path(get_source_dir()), Path(get_include())
    except FileNotFoundError as e:
        raise FmuBuildError(f"rollerrig fmu: {e}") from None


def find_compiler(cc: Optional[str] = None) -> List[str]:
    """The C compiler command (a list): cc if given, else $CC, else the
    first of cc, gcc, clang on PATH.  FmuBuildError if there is none."""
    looked: List[str] = []
    for text, origin in ((cc, "cc="), (os.environ.get("CC"), "$CC"), ("cc", None),
                         ("gcc", None), ("clang", None)):
        if not text or not text.strip():
            continue
        cmd = shlex.split(text)
        looked.append(f"{origin}{text!r}" if origin else repr(text))
        if shutil.which(cmd[0]):
            return cmd
        if origin:
            raise FmuBuildError(f"rollerrig fmu: the C compiler {origin} {text!r} is not "
                                f"found: set CC to a C compiler (gcc, clang)")
    raise FmuBuildError(f"rollerrig fmu: no C compiler found (looked for "
                        f"{', '.join(looked)} on PATH): install one (e.g. apt install gcc) "
                        f"or set CC")


def _platform_dir(fmi_version: int) -> Tuple[str, str]:
    """binaries/<this> of an FMU of this platform, and the binary's extension."""
    machine = platform.machine().lower()
    arch = {"x86_64": "x86_64", "amd64": "x86_64", "aarch64": "aarch64",
            "arm64": "aarch64"}.get(machine)
    system: Optional[str]
    ext: Optional[str]
    if sys.platform.startswith("linux"):
        system, ext = "linux", ".so"
    elif sys.platform == "darwin":
        system, ext = "darwin", ".dylib"
    else:
        system = ext = None
    if arch is None or system is None or ext is None or sys.maxsize <= 2 ** 32:
        raise FmuBuildError(f"rollerrig fmu: builds for 64-bit Linux and macOS only, not "
                            f"{sys.platform} {platform.machine()}")
    if fmi_version == 2:
        return f"{system}64", ext               # FMI 2.0 names the system and word size only
    return f"{arch}-{system}", ext


def model_identifier(path: Union[str, "os.PathLike[str]"]) -> str:
    """The FMU's modelIdentifier from its file name: a C identifier."""
    stem = Path(path).name
    stem = stem[:-4] if stem.lower().endswith(".fmu") else stem
    ident = re.sub(r"[^A-Za-z0-9_]", "_", stem)
    if not ident or not (ident[0].isalpha() or ident[0] == "_"):
        ident = "rig_" + ident
    return ident


# ------------------------------------------------------------------ the start values

def _c_string(text: object) -> str:
    return json.dumps(str(text))


def _start_config_c(P: _Checked, source: str) -> str:
    """sources/fmu_start.c: the default configuration overridden by every
    value of the checked parameters P that differs from its default, exact
    (hexadecimal floating constants)."""
    from .rig import params, real_profiles
    D = params.default_parameters()
    calls: List[str] = []
    arrays: List[str] = []
    C = params._c_values(P)                 # a profile row: "points" for a real one
    for p in params.PARAMETERS:
        section, key = p.name.split(".")
        v, d = P[section][key], D[section][key]
        if not p.creep:
            v = C[p.name]
        if v == d and type(v) is type(d):
            continue
        name = _c_string(p.name)
        if p.type == "list":
            if v:
                arrays.append(f"    static const double list{len(arrays)}[] = "
                              f"{{{', '.join(float(x).hex() for x in v)}}};")
                calls.append(f"rr_fmu_config_set_list(f, {name}, {len(v)}, "
                             f"list{len(arrays) - 1})")
            else:
                calls.append(f"rr_fmu_config_set_list(f, {name}, 0, NULL)")
        elif isinstance(v, str):                      # a choice, or a creep row's name
            calls.append(f"rr_fmu_config_set_choice(f, {name}, {_c_string(v)})")
        elif isinstance(v, bool):
            calls.append(f"rr_fmu_config_set(f, {name}, {1.0 if v else 0.0})")
        elif isinstance(v, int):
            calls.append(f"rr_fmu_config_set(f, {name}, {float(v)!r})")
        else:
            calls.append(f"rr_fmu_config_set(f, {name}, {float(v).hex()})")
    lines = ["/* fmu_start.c - generated by rollerrig fmu " + __version__ + ": the FMU's start",
             f" * values, the defaults overridden by {source} (the scenario's",
             " * values exact, as hexadecimal floating constants). */",
             "#include <stddef.h>",
             '#include "fmu_build.h"', "",
             "const char rr_fmu_token[] = @TOKEN@;", "",
             "int rr_fmu_start_config(rr_fmu_config *f)", "{"]
    lines += arrays
    lines.append("    int st = rr_fmu_config_default(f);")
    for call in calls:
        lines.append(f"    if (st == 0)\n        st = {call};")
    lines += ["    return st;", "}", ""]
    lines += _start_profiles_c(real_profiles.profile_points(P))
    lines += _start_nonhertz_c(P)
    return "\n".join(lines)


def _start_nonhertz_c(P: _Checked) -> List[str]:
    """rr_fmu_start_nonhertz of fmu_start.c: on contact.patch = "nonhertz"
    the tables simulate() runs on (rollerrig.rig.nonhertz_rig: built from
    the rig's pair or read from contact.nonhertz_table), their rows exact
    hexadecimal constants; else none."""
    head = ["", "int rr_fmu_start_nonhertz(rr_nh_table t[2])", "{"]
    if P["contact"]["patch"] != "nonhertz":
        return head + ["    (void)t;", "    return 0;", "}", ""]
    from .rig import build, nonhertz_rig
    nh = nonhertz_rig.table_for(P, build._geometry(P))
    lines: List[str] = []
    sets = head[:]
    for k, side in enumerate((nh.left, nh.right)):
        assert side is not None             # the rig's table has both (table_for checks)
        flat = side.rows.reshape(-1)
        body = ",\n    ".join(", ".join(float(x).hex() for x in flat[i:i + 4])
                              for i in range(0, flat.size, 4))
        lines.append(f"static const double nonhertz_rows{k}[{flat.size}] = {{\n    {body}}};")
        sigma, R0, G, nu, mu_ref = side.head
        sets += [f"    t[{k}].nrows = {side.rows.shape[0]};",
                 f"    t[{k}].rows = nonhertz_rows{k};",
                 f"    t[{k}].sigma = {float(sigma).hex()};", f"    t[{k}].R0 = {float(R0).hex()};",
                 f"    t[{k}].G = {float(G).hex()};", f"    t[{k}].nu = {float(nu).hex()};",
                 f"    t[{k}].mu_ref = {float(mu_ref).hex()};"]
    return [""] + lines + sets + ["    return 1;", "}", ""]


def _start_profiles_c(points: Optional[Sequence[Optional[_ProfilePoints]]]) -> List[str]:
    """rr_fmu_start_profiles of fmu_start.c: the real profiles' points as
    rollerrig.rig.real_profiles gives them to the C table build (so the FMU
    builds simulate()'s table, bit for bit), exact hexadecimal constants."""
    slots = ("wheel", "roller", "wheel_right", "roller_right")
    lines: List[str] = []
    sets = ["    memset(pr, 0, sizeof *pr);"]
    for k, name in enumerate(slots):
        s = None if points is None else points[k]
        if s is None:
            continue
        y, z, end = s
        for axis, a in (("y", y), ("z", z)):
            body = ",\n    ".join(", ".join(float(x).hex() for x in a[i:i + 4])
                                  for i in range(0, len(a), 4))
            lines.append(f"static const double {name}_{axis}[{len(a)}] = {{\n    {body}}};")
        sets += [f"    pr->{name}.n = {len(y)};", f"    pr->{name}.y = {name}_y;",
                 f"    pr->{name}.z = {name}_z;",
                 f"    pr->{name}.end = {'RR_SPLINE_NATURAL' if end else 'RR_SPLINE_NOT_A_KNOT'};"]
    return (["#include <string.h>", ""] + lines
            + ["", "void rr_fmu_start_profiles(rr_rig_profiles *pr)", "{"] + sets + ["}", ""])


def check_scenario(scenario: Params, *, source: str, method: Optional[str] = None,
                   patch: Optional[str] = None) -> Tuple[Dict[str, Dict[str, Any]], str]:
    """(checked parameters, what they come from) of a scenario: None (the
    defaults), a nested dict or the path of a TOML file, checked as simulate
    checks it: every value (one RollerRigError listing every problem), then
    the rig built from them with `method` (default their
    contact.creep_method), so that one it cannot start from (a value that
    overflows the C rig, a method that does not suit the friction law) is
    refused before any work.  Messages begin with `source` and the path.
    patch: contact.patch for the run (None: the scenario's)."""
    from .rig import build, params as rig_params
    if scenario is None and patch is None:
        return rig_params.default_parameters(), "nothing (the defaults)"
    params: Optional[Mapping[str, Any]]
    if isinstance(scenario, (str, os.PathLike)):
        source = f"{source} {os.fspath(scenario)}"
        try:
            params = rig_params._read_parameter_file(scenario)
        except rig_params._Problems as p:
            raise rig_params._error(source, p.problems) from None
        from .rig import real_profiles
        real_profiles.relative_to(params, os.path.dirname(os.path.abspath(scenario)))
        what = f"the scenario {Path(scenario).name}"
    else:
        params, what = scenario, "the scenario given" if scenario else "the defaults"
    if patch is not None:
        patched = {k: dict(v) if isinstance(v, dict) else v for k, v in (params or {}).items()}
        patched["contact"] = {**patched.get("contact", {}), "patch": patch}
        params = patched
    P = rig_params.check_parameters(params, source=source)
    build._build(source, P, dt=None, method=method, substeps=None, ode=None, nx=None,
                 ny=None, roller_speed=None, start="rolling", creep={})
    return P, what


# ------------------------------------------------------------------ compiling

def _run(cmd: Sequence[str], what: str, cwd: Optional[Path] = None) -> str:
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          cwd=cwd)
    if proc.returncode != 0:
        raise FmuBuildError(f"rollerrig fmu: {what} failed (exit status {proc.returncode}):\n"
                            f"{' '.join(map(str, cmd))}\n{proc.stdout[-4000:]}")
    return proc.stdout


def _stage_sources(src: Path, fmi_version: int) -> Tuple[List[str], List[str]]:
    """Copy the core's sources and headers and the adapter into src/;
    return (the core's .c files, the FMU's own .c files), relative to src."""
    sources, headers = core_c_dirs()
    core: List[str] = []
    for path in sorted(Path(sources).glob("*/rr_*.c")):
        rel = path.relative_to(sources)
        (src / rel.parent).mkdir(parents=True, exist_ok=True)
        shutil.copyfile(path, src / rel)
        core.append(rel.as_posix())
    # the headers of the layers (the folders holding the core's sources)
    layers = sorted({c.split("/")[0] for c in core})
    for layer in layers:
        for pattern in ("rr_*.h", "*.def"):
            for path in sorted((Path(headers) / layer).glob(pattern)):
                shutil.copyfile(path, src / layer / path.name)
    if not any(c == "fmu/rr_fmu.c" for c in core):
        raise FmuBuildError(f"rollerrig fmu: the C core in {sources} has no FMU layer "
                            f"(fmu/rr_fmu.c): it is older than this rollerrig")
    own = [f"fmi{fmi_version}_cs.c", "fmi_glue.c"]
    for name in own + [f"fmi{fmi_version}_api.h", "fmi_glue.h", "fmu_build.h"]:
        shutil.copyfile(FMI_DATA / name, src / name)
    return core, own


def _compile_all(cc: List[str], files: Sequence[str], src: Path, obj_dir: Path,
                 jobs: int) -> Dict[str, Path]:
    """Compile src/<file> into obj_dir, largest first, `jobs` at a time;
    return {file: object path}."""
    obj_dir.mkdir(parents=True, exist_ok=True)
    objects = {f: obj_dir / (f.replace("/", "__")[:-2] + ".o") for f in files}

    def one(f: str) -> None:
        _run(cc + list(CFLAGS) + [f"-I{src}", "-c", str(src / f), "-o", str(objects[f])],
             f"compiling {f}")
    order = sorted(files, key=lambda f: -(src / f).stat().st_size)
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        for future in [pool.submit(one, f) for f in order]:
            future.result()
    return objects


def _core_objects(cc: List[str], core: Sequence[str], src: Path, work: Path, jobs: int,
                  cache_dir: Optional[Union[str, "os.PathLike[str]"]]) -> Dict[str, Path]:
    """The core's objects: compiled in work/, or taken from cache_dir when
    it holds those of the same compiler, flags and sources (the tests build
    several FMUs)."""
    if cache_dir is None:
        return _compile_all(cc, core, src, work / "core", jobs)
    h = hashlib.sha256(json.dumps([cc, CFLAGS]).encode())
    for path in sorted(p for p in src.rglob("*") if p.is_file()):
        rel = path.relative_to(src).as_posix()
        if rel.startswith("fmi") or rel.startswith("fmu_"):
            continue                                  # the adapter's, compiled each time
        h.update(rel.encode() + b"\0" + path.read_bytes())
    cached = Path(cache_dir) / ("core-" + h.hexdigest()[:20])
    if not (cached / "done").is_file():
        tmp = Path(tempfile.mkdtemp(prefix="core-", dir=cache_dir))
        _compile_all(cc, core, src, tmp, jobs)
        (tmp / "done").write_text("")
        try:
            os.replace(tmp, cached)
        except OSError:                               # another build put it there first
            shutil.rmtree(tmp, ignore_errors=True)
    return {f: cached / (f.replace("/", "__")[:-2] + ".o") for f in core}


def _build_description(identifier: str, files: Iterable[str]) -> str:
    lines = ['<?xml version="1.0" encoding="UTF-8"?>', '<fmiBuildDescription fmiVersion="3.0">',
             f'  <BuildConfiguration modelIdentifier="{identifier}" description="the rig\'s C '
             f'core, its FMU layer and the FMI 3.0 adapter: compile every file with the '
             f'sources folder on the include path, C99 without fused multiply-adds '
             f'(-ffp-contract=off), and link the math library">',
             '    <SourceFileSet language="C99" compilerOptions="-ffp-contract=off">']
    lines += [f'      <SourceFile name="{f}"/>' for f in files]
    lines += ['    </SourceFileSet>', '    <Library name="m" external="true" description="the C '
              'math library (-lm)"/>', '  </BuildConfiguration>', '</fmiBuildDescription>', '']
    return "\n".join(lines)


def build_fmu(out: Union[str, "os.PathLike[str]"], scenario: Params = None, fmi_version: int = 2,
              *, cc: Optional[str] = None, jobs: Optional[int] = None,
              cache_dir: Optional[Union[str, "os.PathLike[str]"]] = None,
              quiet: bool = True) -> Path:
    """Write a co-simulation FMU of the rig to `out`, a name ending in .fmu:
    a new path or a regular file, replaced whole (never a symbolic link, a
    directory, a device or a FIFO; its folder must exist), checked before
    the compile.

    scenario:    None (the default parameters), a nested dict as simulate's
                 params, or the path of a TOML parameter file: the FMU's start
                 values (the scenario's schedule, adhesion, method, ...)
    fmi_version: 2 (FMI 2.0) or 3 (FMI 3.0)
    cc:          the C compiler command (default $CC, then cc, gcc, clang)
    jobs:        parallel compiles (default: the cores)
    cache_dir:   a folder where the compiled core is kept between builds
                 (the same compiler, flags and sources: taken from there);
                 default $ROLLERRIG_FMU_CACHE if set, else none
    Returns the path.  Raises RollerRigError for a bad output path or a bad
    scenario (every problem named; one the rig cannot start from, as
    simulate refuses it), FmuBuildError (a RollerRigError) without a compiler, on
    an unsupported platform or a failed compile.
    """
    if fmi_version not in FMI_VERSIONS:
        raise RollerRigError(f"rollerrig fmu: fmi_version must be 2 or 3, got {fmi_version!r}")
    out = Path(check_output(out, what="rollerrig fmu:", suffix=".fmu"))   # before the work
    P, source = check_scenario(scenario, source="rollerrig fmu: scenario")
    identifier = model_identifier(out)
    plat, ext = _platform_dir(fmi_version)
    cc_cmd = find_compiler(cc)
    jobs = max(1, int(jobs or os.cpu_count() or 1))
    if cache_dir is None and os.environ.get("ROLLERRIG_FMU_CACHE"):
        cache_dir = os.environ["ROLLERRIG_FMU_CACHE"]
    if cache_dir is not None:
        Path(cache_dir).mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="rollerrig-fmu-") as tmp_name:
        tmp = Path(tmp_name)
        stage = tmp / "fmu"
        src = stage / "sources"
        src.mkdir(parents=True)
        core, own = _stage_sources(src, fmi_version)
        start_c = _start_config_c(P, source)
        digest = hashlib.sha256(start_c.encode())
        for f in sorted(p for p in src.rglob("*") if p.is_file()):
            digest.update(f.read_bytes())
        token = "{" + str(uuid.uuid5(uuid.NAMESPACE_URL, f"rollerrig:{__version__}:"
                                     f"{fmi_version}:{identifier}:{digest.hexdigest()}")) + "}"
        (src / "fmu_start.c").write_text(start_c.replace("@TOKEN@", _c_string(token)))
        own.append("fmu_start.c")
        objects = _core_objects(cc_cmd, core, src, tmp, jobs, cache_dir)
        objects.update(_compile_all(cc_cmd, own, src, tmp / "own", jobs))
        binary_dir = stage / "binaries" / plat
        binary_dir.mkdir(parents=True)
        binary = binary_dir / (identifier + ext)
        all_files = core + own
        _run(cc_cmd + ["-shared", "-o", str(binary)] + [str(objects[f]) for f in all_files]
             + ["-lm"], "linking the FMU's binary")
        # the description, from the C side at the FMU's start values
        shutil.copyfile(FMI_DATA / "fmu_describe.c", tmp / "fmu_describe.c")
        describe = tmp / "fmu_describe"
        _run(cc_cmd + list(CFLAGS) + [f"-I{src}", str(tmp / "fmu_describe.c"), "-o", str(describe)]
             + [str(objects[f]) for f in core] + [str(objects["fmu_start.c"]), "-lm"],
             "building the description program")
        description = (f"The Politecnico di Torino 1/5 roller rig (a wheelset on driven "
                       f"rollers: wheel-roller contact, drives, encoders, controllers), "
                       f"stepped every control sample; start values from {source}")
        xml = _run([str(describe), str(fmi_version), identifier, identifier,
                    f"rollerrig {__version__}", description]
                   + (all_files if fmi_version == 2 else []), "describing the FMU")
        (stage / "modelDescription.xml").write_text(xml, encoding="utf-8")
        licenses = stage / "documentation" / "licenses"
        licenses.mkdir(parents=True)
        (licenses / "license.txt").write_text(LICENSE_TEXT.format(version=__version__))
        if fmi_version == 3:
            (src / "buildDescription.xml").write_text(_build_description(identifier,
                                                                         all_files))

        def pack(fh: BinaryIO) -> None:
            with zipfile.ZipFile(fh, "w", zipfile.ZIP_DEFLATED) as z:
                for path in sorted(p for p in stage.rglob("*") if p.is_file()):
                    z.write(path, path.relative_to(stage).as_posix())
        write_file(out, pack, what="rollerrig fmu:", binary=True, suffix=".fmu")
    if not quiet:
        print(f"wrote {out}: FMI {fmi_version}.0 co-simulation, modelIdentifier {identifier}, "
              f"binaries/{plat}, start values from {source}")
    return out


# ------------------------------------------------------------------ the variable list

class _Row(TypedDict):
    """One variable of a modelDescription.xml, as the tables show it."""
    name: str
    vr: Optional[str]
    causality: Optional[str]
    variability: Optional[str]
    type: str
    unit: str
    start: str
    range: str
    description: str


#: a table's column: (its heading, a row's cell)
_Column = Tuple[str, Callable[[_Row], object]]

DOCS_PATH = Path(__file__).resolve().parent.parent / "docs" / "fmu.md"
_DOCS_BEGIN, _DOCS_END = "<!-- begin variables -->", "<!-- end variables -->"


def variables_markdown(xml: str) -> str:
    """The variables of an FMI 2.0 modelDescription.xml (text) as Markdown
    tables: control parameters, inputs, outputs (the record, the encoders,
    each wheel's contact block), the rig's parameters."""
    import xml.etree.ElementTree as ET
    root = ET.fromstring(xml)
    items = {t.get("name"): {i.get("value"): i.get("name") for i in t.iter("Item")}
             for t in root.iter("SimpleType")}
    rows: List[_Row] = []
    for sv in root.iter("ScalarVariable"):
        kind = next(iter(sv))
        start = kind.get("start")
        if kind.tag == "Enumeration" and start is not None:
            start = f'"{items[kind.get("declaredType")][start]}"'
        lo, hi = kind.get("min"), kind.get("max")
        rng = "" if lo is None and hi is None else f"{lo if lo is not None else ''} .. " \
                                                    f"{hi if hi is not None else ''}"
        if kind.tag == "Enumeration":
            rng = ", ".join(f'"{n}"' for n in items[kind.get("declaredType")].values())
        rows.append(_Row(name=sv.attrib["name"], vr=sv.get("valueReference"),
                         causality=sv.get("causality"), variability=sv.get("variability"),
                         type=kind.tag, unit=kind.get("unit", ""), start=start or "",
                         range=rng, description=sv.get("description", "")))

    def esc(text: str) -> str:
        return text.replace("|", "\\|")

    def table(selected: Iterable[_Row], columns: Sequence[_Column]) -> List[str]:
        out = ["| " + " | ".join(c for c, _ in columns) + " |",
               "| " + " | ".join("---" for _ in columns) + " |"]
        for r in selected:
            out.append("| " + " | ".join(esc(str(f(r))) for _, f in columns) + " |")
        return out

    name: _Column = ("name", lambda r: f"`{r['name']}`")
    vr: _Column = ("vr", lambda r: r["vr"])
    unit: _Column = ("unit", lambda r: r["unit"])
    desc: _Column = ("description", lambda r: r["description"])
    control = [r for r in rows if r["name"].startswith("control.")]
    inputs = [r for r in rows if r["causality"] == "input"]
    outputs = [r for r in rows if r["causality"] == "output"]
    record = [r for r in outputs if "." not in r["name"]]
    encoders = [r for r in outputs if r["name"].startswith("encoder.")]
    left = [r for r in outputs if r["name"].startswith("left.")]
    params = [r for r in rows if r["causality"] == "parameter" and r not in control]
    L = ["### Control parameters", ""]
    L += table(control, [name, vr, ("variability", lambda r: r["variability"]),
                         ("values", lambda r: r["range"]), ("start", lambda r: r["start"]),
                         desc])
    L += ["", "### Inputs (discrete: sampled at each control sample)", ""]
    L += table(inputs, [name, vr, unit, ("start", lambda r: r["start"]), desc])
    L += ["", "### Outputs: the record of the last sample (rollerrig.simulate's fields)", ""]
    L += table(record, [name, vr, ("type", lambda r: r["type"]), unit, desc])
    L += ["", "### Outputs: the encoders at the present time", ""]
    L += table(encoders, [name, vr, unit, desc])
    L += ["", "### Outputs: each wheel's contact block",
          "", "`left.` (value references 400 + i) and `right.` (500 + i); a vector's "
          "components [1], [2], [3] are x, y, z of the rig's frame.", ""]
    L += table(left, [("name", lambda r: f"`{r['name'][len('left.'):]}`"),
                      ("vr (left)", lambda r: r["vr"]), unit, desc])
    L += ["", "### Parameters (the rig's declaration; origins in docs/parameters.md)", "",
          "Tunable ones may change between steps (the rig reads them at every sample); a "
          "list of the scenario file is one parameter per entry, `name[1]`, ...", ""]
    L += table(params, [name, vr, ("variability", lambda r: r["variability"]),
                        ("type", lambda r: r["type"]), unit, ("start", lambda r: r["start"]),
                        ("range", lambda r: r["range"])])
    return "\n".join(L) + "\n"


def docs_text(xml: str, path: Union[str, "os.PathLike[str]"] = DOCS_PATH) -> str:
    """docs/fmu.md with its generated variable list replaced by that of xml."""
    text = Path(path).read_text(encoding="utf-8")
    head, rest = text.split(_DOCS_BEGIN, 1)
    _, tail = rest.split(_DOCS_END, 1)
    return head + _DOCS_BEGIN + "\n" + variables_markdown(xml) + _DOCS_END + tail


def write_docs(fmu_path: Union[str, "os.PathLike[str]"],
               path: Union[str, "os.PathLike[str]"] = DOCS_PATH) -> Union[str, "os.PathLike[str]"]:
    """Rewrite docs/fmu.md's variable list from an FMI 2.0 FMU (built from
    the defaults: rollerrig fmu rig.fmu)."""
    with zipfile.ZipFile(fmu_path) as z:
        xml = z.read("modelDescription.xml").decode("utf-8")
    text = docs_text(xml, path)
    return write_file(path, lambda fh: fh.write(text), what="write_docs: path")
