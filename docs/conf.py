"""Sphinx configuration of rollerrig's documentation site.

Build:  pip install ".[docs]" && python -m sphinx -W --keep-going -b html docs docs/_build/html
(RR_DOCS_QUICK=1 for a draft: notebooks not run, the gallery kept as last built)

The pages are Markdown (MyST) beside the existing docs/*.md; the Python API
reference is generated from the docstrings (numpydoc), the C API reference
is docs/c_api.md (generated from the headers by docs/c_api.py), the gallery
runs examples/*.py (docs/_ext/rr_gallery.py) and the notebooks are executed (myst-nb).
"""
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

sys.path.insert(0, os.path.join(HERE, "_ext"))
# the installed package, never the checkout's folder: `python -m sphinx` run
# from the checkout puts it first on sys.path, and a plain `pip install .`
# leaves that folder without the built extension
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != ROOT]

import rollerrig  # noqa: E402  (the installed package: the site documents what users get)

project = "rollerrig"
author = "the rollerrig developers"
copyright = "2026, the rollerrig developers"
release = rollerrig.__version__
version = ".".join(release.split(".")[:2])

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "numpydoc",
    "myst_nb",
    "rr_gallery",
]

# Markdown pages and notebooks (myst-nb registers both)
source_suffix = {".rst": "restructuredtext", ".md": "myst-nb", ".ipynb": "myst-nb"}
myst_enable_extensions = ["dollarmath", "colon_fence"]
myst_heading_anchors = 3
# RR_DOCS_QUICK=1: a draft build for writing pages, the notebooks not run and
# the gallery not rebuilt (CI and releases build everything)
QUICK = os.environ.get("RR_DOCS_QUICK") == "1"
nb_execution_mode = "off" if QUICK else "auto"   # run the notebooks (ours carry no outputs)
nb_execution_timeout = 600
nb_execution_raise_on_error = True  # a notebook that fails fails the build

# The notebooks live at the top of the repository (notebooks/, run by CI and
# the tests); Sphinx reads only its source folder, so they are copied in.
_NB_OUT = os.path.join(HERE, "notebooks")
if os.path.isdir(os.path.join(ROOT, "notebooks")):
    os.makedirs(_NB_OUT, exist_ok=True)
    for name in sorted(os.listdir(os.path.join(ROOT, "notebooks"))):
        if name.endswith(".ipynb"):
            shutil.copyfile(os.path.join(ROOT, "notebooks", name), os.path.join(_NB_OUT, name))

autosummary_generate = True
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False}
autodoc_typehints = "none"          # the numpydoc sections carry the types and units
numpydoc_show_class_members = False
numpydoc_xref_param_type = False
numpydoc_validation_checks = {"GL08"}   # every public object has a docstring
# (a dataclass's __init__ is its fields, documented on the class)
numpydoc_validation_exclude = {r"\.__init__$"}

exclude_patterns = ["_build", "_ext", "Thumbs.db", ".DS_Store", "notebooks/.ipynb_checkpoints"]
templates_path = ["_templates"]
html_theme = "pydata_sphinx_theme"
html_title = f"rollerrig {release}"
html_theme_options = {"show_toc_level": 2, "navigation_with_keys": False}
html_static_path = []
suppress_warnings = ["mystnb.unknown_mime_type"]
