"""The documentation site's sources (docs/conf.py): every public object of
the package is in the API reference, every guide page in the guide's table
of contents, the docs extra carries what conf.py loads.  The build itself
(Sphinx, warnings as errors, every example and notebook run: the gallery
lists examples/ by running it) is CI's docs step."""
import inspect
import os
import re

import rollerrig as rr

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOCS = os.path.join(ROOT, "docs")


def _read(*parts):
    with open(os.path.join(DOCS, *parts), encoding="utf-8") as f:
        return f.read()


def test_every_public_function_and_class_is_in_the_api_reference():
    listed = set(re.findall(r"^   (\w+)$", _read("api", "index.rst"), flags=re.M))
    public = {name for name in dir(rr) if not name.startswith("_")
              and (inspect.isfunction(getattr(rr, name)) or inspect.isclass(getattr(rr, name)))}
    assert public - listed == set(), "add them to docs/api/index.rst"
    assert listed - public == set(), "docs/api/index.rst lists names rollerrig does not have"


def test_every_guide_page_is_in_the_guide():
    toc = _read("guide", "index.md")
    pages = {f[:-3] for f in os.listdir(os.path.join(DOCS, "guide"))
             if f.endswith(".md") and f != "index.md"}
    missing = {p for p in pages if not re.search(rf"^{re.escape(p)}$", toc, flags=re.M)}
    assert missing == set()


def test_the_site_builds_from_the_docs_extra():
    # the extra names what conf.py loads: a build in a fresh environment
    # (CI's docs step) cannot miss one
    with open(os.path.join(DOCS, "conf.py"), encoding="utf-8") as f:
        conf = f.read()
    import configparser
    cfg = configparser.ConfigParser()
    cfg.read(os.path.join(ROOT, "setup.cfg"), encoding="utf-8")   # as setuptools reads it
    extra = cfg["options.extras_require"]["docs"]
    for module, package in (("numpydoc", "numpydoc"), ("myst_nb", "myst-nb"),
                            ("pydata_sphinx_theme", "pydata-sphinx-theme")):
        assert module in conf and package in extra
