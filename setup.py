"""Build script: declares the C extension ``rollerrig._core`` only.

All package metadata lives in setup.cfg; build requirements in pyproject.toml.
"""
from glob import glob

import numpy
from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

# GCC/Clang-style flags; not applied when the compiler is MSVC.  Python's own
# CFLAGS bring -fwrapv, which slows the FASTSIM march by ~15 %; the core never
# relies on signed overflow (UndefinedBehaviorSanitizer checks it), so undo it.
# No fused multiply-adds: FASTSIM's vector kernels must round as its scalar
# march does (ISO C mode already implies this; the flag keeps it so).
UNIX_COMPILE_ARGS = ["-std=c99", "-O3", "-fno-wrapv", "-ffp-contract=off", "-Wall", "-Wextra"]


class BuildExt(build_ext):
    def build_extensions(self):
        if self.compiler.compiler_type != "msvc":
            for ext in self.extensions:
                ext.extra_compile_args = list(ext.extra_compile_args or []) + UNIX_COMPILE_ARGS
        super().build_extensions()


core = Extension(
    "rollerrig._core",
    sources=sorted(glob("csrc/*/rr_*.c")) + ["rollerrig/_core.c"],
    # headers: trigger rebuilds when they change and get shipped in the sdist
    depends=sorted(glob("csrc/*/rr_*.h") + ["csrc/rollerrig.h"]),
    include_dirs=["csrc", numpy.get_include()],
    define_macros=[("NPY_NO_DEPRECATED_API", "NPY_1_7_API_VERSION")],
)

setup(ext_modules=[core], cmdclass={"build_ext": BuildExt})
