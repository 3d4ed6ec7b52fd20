"""Build script: declares the C extension ``rollerrig._core``, and ships the
C core beside it for C programs (rollerrig.capi finds it).

All package metadata lives in setup.cfg; build requirements in pyproject.toml.

The package's ``_c/`` folder, made by build_ext:
  lib/librollerrig.a              the core's objects as compiled for the
                                  extension (position-independent: Python
                                  compiles extensions with -fPIC), archived,
                                  not compiled a second time
  lib/pkgconfig/rollerrig.pc      from csrc/rollerrig.pc.in, relocatable
                                  (${pcfiledir})
  include/                        csrc's headers with their layer folders
  src/                            csrc's sources and headers with their layer
                                  folders: the core, compiled with -I src
                                  (rr_fft_avx2.c includes util/rr_fft.c)
An in-place build (``pip install -e .``) writes lib/ only, in the checkout,
and its rollerrig.pc names csrc/ for the headers: rollerrig.capi gives the
checkout's csrc/ for the headers and the sources then.
"""
import os
import re
from glob import glob

import numpy
from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

# GCC/Clang-style flags; not applied when the compiler is MSVC.  Python's own
# CFLAGS bring -fwrapv, which slows the FASTSIM march by ~15 %; the core never
# relies on signed overflow (UndefinedBehaviorSanitizer checks it), so undo it.
# No fused multiply-adds: FASTSIM's vector kernels must round as its scalar
# march does (ISO C mode already implies this; the flag keeps it so).  The
# core's calls into itself need not go through the PLT, as if another
# library could replace its functions (-fPIC's default): binding them
# locally makes the rig's step 4-5 % faster (benchmarks/RESULTS.md).  The
# core never reads errno (csrc/util/rr_common.h), so sqrt need not set it:
# loops with a square root then vectorise (the patch's cross-sections, in
# rr_gap_section.h), with the same doubles.
UNIX_COMPILE_ARGS = ["-std=c99", "-O3", "-fno-wrapv", "-ffp-contract=off",
                     "-fno-math-errno", "-fno-semantic-interposition", "-Wall", "-Wextra"]

CORE_SOURCES = sorted(glob("csrc/*/rr_*.c"))
# the layer folders: those holding the core's sources (util, contact, ...)
LAYERS = sorted({os.path.basename(os.path.dirname(p)) for p in CORE_SOURCES})
# the public headers: the umbrella, each layer's headers and the method registry
HEADERS = ["csrc/rollerrig.h"] + sorted(
    p for layer in LAYERS for p in glob(f"csrc/{layer}/rr_*.h") + glob(f"csrc/{layer}/*.def"))


def core_version():
    """MAJOR.MINOR.PATCH from csrc/util/rr_common.h's RR_VERSION_* macros."""
    with open("csrc/util/rr_common.h", encoding="utf-8") as f:
        text = f.read()
    return ".".join(re.search(rf"^#define RR_VERSION_{part} (\d+)", text, re.M).group(1)
                    for part in ("MAJOR", "MINOR", "PATCH"))


def pkgconfig_text(in_checkout):
    """rollerrig.pc for the package's _c/lib/pkgconfig/: the folders relative
    to the file (${pcfiledir}), the headers in _c/include/ or, for an
    in-place build, in the checkout's csrc/ (rollerrig/_c/lib/pkgconfig/ ->
    four levels up).  Only a static library lies there: -lm in Libs."""
    with open("csrc/rollerrig.pc.in", encoding="utf-8") as f:
        text = f.read()
    values = {
        "prefix": "${pcfiledir}/../..",
        "libdir": "${prefix}/lib",
        "includedir": "${prefix}/../../csrc" if in_checkout else "${prefix}/include",
        "headerdir": "${includedir}",
        "version": core_version(),
        "libs": " -lm",
    }
    return re.sub(r"@(\w+)@", lambda m: values[m.group(1)], text)


class BuildExt(build_ext):
    def build_extensions(self):
        if self.compiler.compiler_type != "msvc":
            for ext in self.extensions:
                ext.extra_compile_args = list(ext.extra_compile_args or []) + UNIX_COMPILE_ARGS
        super().build_extensions()

    def run(self):
        super().run()            # an in-place build copies the extension back here
        self.build_c_library()

    def c_dir(self):
        """The package's _c folder: in the checkout for an in-place build."""
        if self.inplace:
            package_dir = self.get_finalized_command("build_py").get_package_dir("rollerrig")
            return os.path.join(package_dir, "_c")
        return os.path.join(self.build_lib, "rollerrig", "_c")

    def build_c_library(self):
        if self.compiler.compiler_type == "msvc":
            return               # a C library for GCC/Clang platforms only
        ext = core
        objects = self.compiler.object_filenames(CORE_SOURCES, output_dir=self.build_temp)
        inputs = CORE_SOURCES + list(ext.depends)
        newest_input = max(os.path.getmtime(p) for p in inputs)
        if not all(os.path.exists(o) and os.path.getmtime(o) >= newest_input for o in objects):
            # the extension was up to date and its objects are gone (another
            # build folder): compile them as build_extension does
            objects = self.compiler.compile(
                CORE_SOURCES, output_dir=self.build_temp, macros=ext.define_macros,
                include_dirs=ext.include_dirs, debug=self.debug,
                extra_postargs=ext.extra_compile_args, depends=ext.depends)
        c_dir = self.c_dir()
        lib_dir = os.path.join(c_dir, "lib")
        self.mkpath(os.path.join(lib_dir, "pkgconfig"))
        library = os.path.join(lib_dir, "librollerrig.a")
        if self.force or not os.path.exists(library) or os.path.getmtime(library) < max(
                os.path.getmtime(o) for o in objects):
            if os.path.exists(library):
                os.remove(library)          # ar adds to an archive: start afresh
            self.compiler.create_static_lib(objects, "rollerrig", output_dir=lib_dir,
                                            debug=self.debug)
        with open(os.path.join(lib_dir, "pkgconfig", "rollerrig.pc"), "w",
                  encoding="utf-8") as f:
            f.write(pkgconfig_text(in_checkout=self.inplace))
        if not self.inplace:
            for source, dest in self.c_copies():
                self.mkpath(os.path.dirname(dest))
                self.copy_file(source, dest)

    def c_copies(self):
        """(source, destination) of the headers and sources under _c/."""
        c_dir = self.c_dir()
        pairs = []
        for path in HEADERS:
            pairs.append((path, os.path.join(c_dir, "include", os.path.relpath(path, "csrc"))))
        for path in HEADERS + CORE_SOURCES:
            pairs.append((path, os.path.join(c_dir, "src", os.path.relpath(path, "csrc"))))
        return pairs

    def get_outputs(self):
        outputs = super().get_outputs()
        if self.inplace:
            return outputs
        lib_dir = os.path.join(self.c_dir(), "lib")
        return outputs + [os.path.join(lib_dir, "librollerrig.a"),
                          os.path.join(lib_dir, "pkgconfig", "rollerrig.pc")] + [
                              dest for _, dest in self.c_copies()]


# the binding: its files in one folder (rollerrig/_core_c/core.h says what each holds)
BINDING_SOURCES = sorted(glob("rollerrig/_core_c/*.c"))

core = Extension(
    "rollerrig._core",
    sources=CORE_SOURCES + BINDING_SOURCES,
    # headers: trigger rebuilds when they change and get shipped in the sdist
    depends=sorted(glob("csrc/*/rr_*.h") + ["csrc/rollerrig.h"]
                   + glob("rollerrig/_core_c/*.h")),
    include_dirs=["csrc", numpy.get_include()],
    define_macros=[("NPY_NO_DEPRECATED_API", "NPY_1_7_API_VERSION")],
)

setup(ext_modules=[core], cmdclass={"build_ext": BuildExt})
