"""The gallery: every examples/*.py run as a user runs it (`python example.py
<folder>`), its docstring, figures, printed output and code on one page.

Run at each build (builder-inited): an example that fails fails the build,
so the gallery keeps the examples working.  The C examples are shown as
code (the test suite builds and runs them: tests/test_c_core.py,
tests/test_rig_c_program.py).  The pages are written into docs/gallery/
(generated, not tracked).
"""
import ast
import os
import shutil
import subprocess
import sys
import time

from sphinx.errors import ExtensionError
from sphinx.util import logging

log = logging.getLogger(__name__)


def _title_and_body(doc, name):
    """The docstring's first sentence as the title, the rest as the text."""
    doc = (doc or name).strip()
    first, _, rest = doc.partition("\n\n")
    first = " ".join(first.split())
    cut = first.find(". ")
    title, tail = (first, "") if cut < 0 else (first[:cut + 1], first[cut + 2:])
    if len(title) > 70:            # a long sentence: its head as the title, all of it below
        cuts = [i for i in (title.find(": "), title.find(", "), title.find(" (")) if i > 15]
        if cuts:
            tail = " ".join(p for p in (title, tail) if p)
            title = title[:min(cuts)]
    body = "\n\n".join(p for p in (tail, rest) if p.strip())
    return title.rstrip("."), body


def _run(path, outdir, timeout):
    env = dict(os.environ, MPLBACKEND="Agg")
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, path, outdir], cwd=outdir, env=env,
                          capture_output=True, text=True, timeout=timeout)
    if proc.returncode != 0:
        raise ExtensionError(f"gallery: {os.path.basename(path)} failed (exit status "
                             f"{proc.returncode}):\n{proc.stderr[-3000:]}")
    return proc.stdout, time.perf_counter() - start


def _fence(text):
    """A fence longer than any backtick run in text."""
    n = 3
    while "`" * n in text:
        n += 1
    return "`" * n


def build_gallery(app):
    src = app.srcdir
    root = os.path.dirname(str(src))
    examples = os.path.join(root, "examples")
    out = os.path.join(str(src), "gallery")
    if os.environ.get("RR_DOCS_QUICK") == "1" and os.path.isfile(os.path.join(out, "index.md")):
        log.info("gallery: RR_DOCS_QUICK=1, kept as last built")
        return
    if os.path.isdir(out):
        shutil.rmtree(out)
    os.makedirs(out)
    timeout = app.config.rr_gallery_timeout
    entries = []
    for name in sorted(os.listdir(examples)):
        stem, ext = os.path.splitext(name)
        path = os.path.join(examples, name)
        if ext == ".py":
            with open(path, encoding="utf-8") as f:
                doc = ast.get_docstring(ast.parse(f.read()))
            figures = os.path.join(out, "_images", stem)
            os.makedirs(figures)
            stdout, seconds = _run(path, figures, timeout)
            log.info(f"gallery: {name} ran in {seconds:.1f} s")
            pngs = sorted(p for p in os.listdir(figures) if p.endswith(".png"))
            lang = "python"
        elif ext == ".c":
            with open(path, encoding="utf-8") as f:
                text = f.read()
            doc = text[2:text.find("*/")] if text.startswith("/*") else stem
            doc = "\n".join(line.strip().lstrip("*").strip() if line.strip().startswith("*")
                            else line for line in doc.splitlines())
            stdout, pngs, lang = "", [], "c"
        else:
            continue
        title, body = _title_and_body(doc, stem)
        lines = [f"# {title}", "", f"`examples/{name}`", "", body, ""]
        for png in pngs:
            lines += [f"![{png}](_images/{stem}/{png})", ""]
        if stdout.strip():
            fence = _fence(stdout)
            lines += ["What it prints:", "", fence + "text", stdout.rstrip(), fence, ""]
        lines += ["The code:", "", f"```{{literalinclude}} ../../examples/{name}",
                  f":language: {lang}", "```", ""]
        with open(os.path.join(out, stem + ".md"), "w", encoding="utf-8") as f:
            f.write("\n".join(lines))
        entries.append((stem, title, pngs))
    index = ["# Gallery", "",
             "Each example of `examples/` as it runs from a checkout "
             "(`python examples/<name>.py <folder>` writes the figures into the folder); "
             "this page is rebuilt by running them.", "",
             "```{toctree}", ":maxdepth: 1", ""]
    index += [stem for stem, _, _ in entries]
    index += ["```", ""]
    for stem, title, pngs in entries:
        if pngs:
            index += [f"[{title}]({stem}.md)", "",
                      f"![{title}](_images/{stem}/{pngs[0]})", ""]
    with open(os.path.join(out, "index.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(index))


def setup(app):
    app.add_config_value("rr_gallery_timeout", 900, "env")
    app.connect("builder-inited", build_gallery)
    return {"version": "1", "parallel_read_safe": True}
