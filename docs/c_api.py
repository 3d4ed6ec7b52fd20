"""Write docs/c_api.md, the C API page, from the headers' doc blocks.

    python docs/c_api.py            # rewrite docs/c_api.md from csrc/
    python docs/c_api.py --check    # exit status 1 if docs/c_api.md is stale

The page documents the headers csrc/rollerrig.h includes, grouped by layer
(top down, as docs/architecture.md) and header (in rollerrig.h's order): each
header's opening comment, then every public function's declaration with its
comment block (given, returns, status, reference: the house style's fixed
block).  A comment block documents the declarations that follow it with no
blank line between; a comment on a declaration's last line documents that
one; a function with neither takes the first comment of its header that
names it (a type's comment naming its size query).  A comment that begins
"Not API" leaves the declarations after it, up to the next comment, out of
the page.  tests/test_c_library.py holds the committed page equal to this
script's output and every public function to a comment.
"""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CSRC = ROOT / "csrc"
PAGE = ROOT / "docs" / "c_api.md"

# top down, as docs/architecture.md; (folder, title)
LAYERS = [
    ("fmu", "5. The rig as a co-simulation unit"),
    ("rig", "4. The rig in time"),
    ("geometry", "3. Wheel-roller geometry and creepage"),
    ("contact", "2. Contact mechanics"),
    ("util", "1. Utilities"),
]

INTRO = r'''# The C API

The rollerrig C core is plain C99 with no Python: `csrc/` in the repository,
installed by `make -C csrc install` or shipped in the wheel.  This page lists
every public function of the headers `rollerrig.h` includes, with the
comment block of its header.  It is generated from the headers by
`python docs/c_api.py` (tests/test_c_library.py checks that it is current):
edit the headers, not this page.

## Building against the library

The headers include each other by layer (`"rig/rr_rig.h"`), from the folder
that holds `rollerrig.h`: that folder is the one to pass to `-I` (pkg-config's
`Cflags` and `rollerrig-config --cflags` give it), and a program writes
`#include "rollerrig.h"` (or includes one header, as
`#include "contact/rr_hertz.h"`).  After `make install`,
`#include <rollerrig/rollerrig.h>` works too where `PREFIX/include` is
searched (`/usr/local/include` is by default), with the same `-I`.  Every
build links the math library.

From a checkout, installed under a prefix (a static and a shared library,
both position-independent, the headers in `PREFIX/include/rollerrig/`, and
`PREFIX/lib/pkgconfig/rollerrig.pc`; `make -C csrc uninstall PREFIX=...`
removes them):

```console
$ make -C csrc install PREFIX=$HOME/.local          # DESTDIR=... for staging
$ export PKG_CONFIG_PATH=$HOME/.local/lib/pkgconfig
$ cc -std=c99 prog.c -o prog $(pkg-config --cflags --libs rollerrig)   # shared
$ LD_LIBRARY_PATH=$HOME/.local/lib ./prog
$ cc -std=c99 prog.c -o prog $(pkg-config --cflags rollerrig) \
      "$(pkg-config --variable=libdir rollerrig)/librollerrig.a" -lm    # static
```

The shared library's soname is `librollerrig.so.MAJOR.MINOR` while the major
version is 0 (a minor release may change the structs a caller allocates),
from the version macros `RR_VERSION_MAJOR`, `_MINOR`, `_PATCH` of
`util/rr_common.h`.

From the Python package (`pip install .`, a wheel, or `pip install -e .` in
a checkout): it ships the headers, a static library of the core as
compiled for the extension (position-independent, so that it links into a
shared object such as an FMU) and the sources, and says where they are, as
numpy does for its headers:

```console
$ cc -std=c99 prog.c -o prog $(rollerrig-config --cflags --libs)
$ PKG_CONFIG_PATH=$(rollerrig-config --pkgconfigdir) pkg-config --cflags --libs rollerrig
$ python -c "import rollerrig; print(rollerrig.get_include())"
```

| Python | `rollerrig-config` | the folder holding |
| --- | --- | --- |
| `rollerrig.get_include()` | `--includedir` (`--cflags`: `-I` it) | `rollerrig.h` and the layer folders of headers |
| `rollerrig.get_library_dir()` | `--libdir` (`--libs`: `-L` it `-lrollerrig -lm`) | `librollerrig.a` |
| `rollerrig.get_source_dir()` | `--srcdir` | the core's sources (`*/rr_*.c`) and headers in their layer folders: compile them with `-I` it |
| `rollerrig.get_pkgconfig_dir()` | `--pkgconfigdir` | `rollerrig.pc`, relocatable (`${pcfiledir}`) |

A wheel keeps them in `rollerrig/_c/` (`include/`, `lib/`, `src/`); an
editable install gives the checkout's `csrc/` for the headers and sources
and builds the library into `rollerrig/_c/lib/` there.

## Conventions

- **Status.** Every public function that can fail returns an `int` status:
  0 (`RR_OK`) for success, > 0 a warning (the outputs are valid, e.g.
  `RR_WARN_NOT_CONVERGED`), < 0 an error (`RR_ERR_*` of `util/rr_common.h`),
  and then its outputs are NaN.  `rr_status_message(status)` gives the
  message (a fixed string).  A NULL pointer gives `RR_ERR_NULL`; finite
  inputs so extreme that a result would not be a finite double give
  `RR_ERR_RANGE`: a success never comes with a NaN or an infinity.  No
  function prints, aborts or touches `errno`.  The codes (`enum
  rr_status`):

@STATUS_TABLE@

- **Workspace.** Nothing allocates: the caller owns every buffer.  A
  function that needs scratch memory takes `double *work` and its length,
  sized by a query (`rr_creep_workspace_len` of a method for a problem's
  size, `rr_exact_workspace_len`, `rr_rig_workspace_len` for the rig,
  given once to `rr_rig_init`, `rr_profile_table_work_len`,
  `RR_RIG_TABLE_WORK_LEN`, `rr_rig_table_data_len` for a table's data), and
  returns `RR_ERR_WORKSPACE` when it is missing or too short.  One workspace
  per thread; there is no global state that changes.
- **The contact problem.** Every creep-force method takes one
  `rr_contact_problem` (`contact/rr_contact.h`): the Hertz ellipse or an
  undeformed distance on a grid, with the load, material, friction law and
  creepages; `rr_contact_problem_check` checks one and names the member at
  fault (docs/architecture.md, "The contact problem").
- **Structs.** Parameters come in `const` structs, evolving state in a
  separate struct the caller allocates (an `rr_rig` may be `static`) and
  the library initialises (`rr_rig_init`).  Units are SI (m, s, N, Pa,
  rad), given for every field; x is the rolling direction, y lateral, z
  normal.
- **C++.** The headers are C: include them inside `extern "C" { ... }`.

## A minimal program

The seed paper's rig at its defaults, one second of free rolling then a
braking creepage target, printing the creepage and the adhesion:

```c
#include <stdio.h>
#include <stdlib.h>

#include "rollerrig.h"

int main(void)
{
    static double work[RR_RIG_TABLE_WORK_LEN];
    static rr_rig rig;                   /* large: static, or on the heap */
    rr_rig_config c;
    rr_rig_geometry g;
    rr_contact_table t;
    rr_rig_params p;
    double rec[RR_REC_COUNT], *data;
    long k;
    int st;

    rr_rig_config_default(&c);           /* the paper's rig and scenario */
    rr_rig_geometry_from(&c, &g);
    data = malloc((size_t)rr_rig_table_data_len(&g) * sizeof *data);
    if (!data)
        return 1;
    if ((st = rr_rig_table_build(&g, data, rr_rig_table_data_len(&g), work,
                                 RR_RIG_TABLE_WORK_LEN, &t, NULL)) < 0
        || (st = rr_rig_params_from(&c, &t, &p)) < 0
        /* no workspace: the rig's default method needs none
         * (rr_rig_workspace_len(&p) doubles, for one that does) */
        || (st = rr_rig_init(&p, c.roller_speed / c.roller_radius, NULL, 0, &rig)) < 0) {
        fprintf(stderr, "%s\n", rr_status_message(st));
        free(data);
        return 1;
    }
    for (k = 0; k < 500; k++) {          /* 2 s at the 4 ms sample */
        double xi_ref = k < 250 ? 0.0 : 0.02;
        if ((st = rr_rig_step(&rig, c.roller_speed / c.roller_radius, xi_ref, rec)) < 0) {
            fprintf(stderr, "sample %ld: %s\n", k, rr_status_message(st));
            free(data);
            return 1;
        }
    }
    printf("t = %.3f s: creepage %.5f, adhesion %.4f\n",
           rec[RR_REC_T], rec[RR_REC_CREEPAGE], rec[RR_REC_ADHESION]);
    free(data);
    return 0;
}
```

`examples/rig_paper.c` runs the paper's whole scenario with
`rr_rig_schedule` (its records are `rollerrig.simulate()`'s, bit for bit);
`examples/rig_realtime.c` steps the rig at a fixed rate.
'''

COMMENT = re.compile(r"/\*.*?\*/", re.S)
FUNCTION = re.compile(r"\b(rr_\w+)\s*\(")


def _items(text):
    """The header's file-scope items in order: ("comment", text, first line,
    last line) and ("decl", text, first line, last line); preprocessor lines
    and the bodies of structs, enums and inline functions are skipped over."""
    items, i, n = [], 0, len(text)
    line_at = lambda pos: text.count("\n", 0, pos) + 1          # noqa: E731
    while i < n:
        c = text[i]
        if c.isspace():
            i += 1
        elif text.startswith("/*", i):
            j = text.index("*/", i) + 2
            items.append(("comment", text[i:j], line_at(i), line_at(j)))
            i = j
        elif text.startswith("//", i):
            i = text.index("\n", i)
        elif c == "#":                                  # a directive, with continuations
            j = i
            while True:
                j = text.find("\n", j)
                if j < 0 or text[j - 1] != "\\":
                    break
                j += 1
            i = n if j < 0 else j
        else:                                           # a declaration or definition
            j, depth = i, 0
            while j < n:
                if text.startswith("/*", j):
                    j = text.index("*/", j) + 2
                    continue
                ch = text[j]
                if ch == "{":
                    depth += 1
                elif ch == "}":
                    depth -= 1
                    if depth == 0 and not re.match(r"[ \t]*[\w*;]", text[j + 1:]):
                        j += 1                           # a function's body ends it
                        break
                elif ch == ";" and depth == 0:
                    j += 1
                    break
                j += 1
            items.append(("decl", text[i:j], line_at(i), line_at(j)))
            i = j
    return items


def _function(decl):
    """The name of the function a declaration declares, or None (a type,
    a variable, a function pointer)."""
    head = COMMENT.sub(" ", decl).split("{")[0]
    if re.match(r"\s*typedef\b", head):
        return None
    if "{" in decl and re.match(r"\s*(struct|enum|union)\b", head):
        return None                                     # a type's definition
    m = FUNCTION.search(head)
    if not m or "(*" in head[:m.start()]:
        return None
    return m.group(1)


def _prototype(decl):
    """A declaration as one statement: an inline function's body dropped,
    comments dropped, the original line breaks kept."""
    text = COMMENT.sub("", decl)
    if "{" in text:
        text = text[:text.index("{")].rstrip() + ";"
    lines = [line.rstrip() for line in text.strip().splitlines()]
    return "\n".join(lines)


def _comment_text(comment):
    """A comment's text without its /*, */ and leading stars, dedented."""
    out = []
    for k, line in enumerate(comment[2:-2].split("\n")):
        if k == 0:
            line = line.strip()
        elif line.strip().startswith("*"):
            line = re.sub(r"^\s*\* ?", "", line)
        else:
            line = line.strip()
        out.append(line.rstrip())
    while out and not out[0]:
        out.pop(0)
    while out and not out[-1]:
        out.pop()
    indent = min((len(s) - len(s.lstrip()) for s in out if s), default=0)
    return "\n".join(s[indent:] for s in out)


def parse_header(path):
    """(the header's opening comment, [([(name, prototype)], comment text or
    None)]) for its public functions."""
    items = _items(path.read_text(encoding="utf-8"))
    intro = _comment_text(items[0][1]) if items and items[0][0] == "comment" else ""
    comments = [_comment_text(it[1]) for it in items[1:] if it[0] == "comment"]
    entries, k, internal = [], 0, False
    while k < len(items):
        kind, text, first, _ = items[k]
        if kind == "comment":
            internal = _comment_text(text).startswith("Not API")
        if kind != "decl" or _function(text) is None:
            k += 1
            continue
        # a group: this declaration and the function declarations on the lines below
        start = k
        while (k + 1 < len(items) and items[k + 1][0] == "decl"
               and items[k + 1][2] == items[k][3] + 1 and _function(items[k + 1][1])):
            k += 1
        group = items[start:k + 1]
        docs = []
        if start > 0 and items[start - 1][0] == "comment" and items[start - 1][3] == first - 1:
            docs.append(_comment_text(items[start - 1][1]))
        if k + 1 < len(items) and items[k + 1][0] == "comment" \
                and items[k + 1][2] == group[-1][3]:
            docs.append(_comment_text(items[k + 1][1]))     # on the last line
            k += 1
        names = [_function(t) for _, t, _, _ in group]
        if not docs:
            docs = [c for c in comments if re.search(rf"\b{names[0]}\b", c)][:1]
        if not internal:
            entries.append((list(zip(names, (_prototype(t) for _, t, _, _ in group))),
                            "\n".join(docs) or None))
        k += 1
    return intro, entries


def headers():
    """[(layer folder, title, [header paths in rollerrig.h's order])]."""
    umbrella = (CSRC / "rollerrig.h").read_text(encoding="utf-8")
    order = re.findall(r'^#include "(\w+/rr_\w+\.h)"', umbrella, re.M)
    return [(folder, title, [CSRC / h for h in order if h.startswith(folder + "/")])
            for folder, title in LAYERS]


def undocumented():
    """'header: function' for every public function without a comment, and
    every layer header with public functions that rollerrig.h leaves out."""
    missing = []
    listed = {p for _, _, paths in headers() for p in paths}
    for folder, _ in LAYERS:
        for path in sorted((CSRC / folder).glob("rr_*.h")):
            _, entries = parse_header(path)
            if entries and path not in listed:
                missing.append(f"{path.relative_to(CSRC)}: not included by rollerrig.h")
            for protos, doc in entries:
                if doc is None:
                    missing += [f"{path.relative_to(CSRC)}: {name}" for name, _ in protos]
    return missing


def _anchor(name):
    return re.sub(r"[^a-z0-9_-]", "", name.lower().replace(" ", "-").replace(".", ""))


def status_table():
    """The status codes of util/rr_common.h's enum rr_status as a table."""
    text = (CSRC / "util" / "rr_common.h").read_text(encoding="utf-8")
    body = re.search(r"enum rr_status \{(.*?)\};", text, re.S).group(1)
    rows = ["  | code | value | meaning |", "  | --- | --- | --- |"]
    pattern = r"(RR_\w+)\s*=\s*(-?\d+),?[ \t]*(?:/\*(.*?)\*/)?"
    for name, value, comment in re.findall(pattern, body, re.S):
        meaning = " ".join(comment.split()) or ("success" if value == "0" else "")
        rows.append(f"  | `{name}` | {value} | {meaning} |")
    return "\n".join(rows)


def render():
    intro = INTRO.replace("@STATUS_TABLE@", status_table())
    parts = [intro.rstrip("\n"), "", "## Contents", ""]
    layers = headers()
    for folder, title, paths in layers:
        links = ", ".join(f"[`{p.name}`](#{_anchor(p.relative_to(CSRC).as_posix())})"
                          for p in paths)
        parts.append(f"- [{title}](#{_anchor(title)}) (`{folder}/`): {links}")
    for folder, title, paths in layers:
        parts += ["", f"## {title}"]
        for path in paths:
            intro, entries = parse_header(path)
            name = path.relative_to(CSRC).as_posix()
            parts += ["", f"### {name}", ""]
            if intro:
                # the opening comment: "rr_x.h - what it is." and the rest
                first, _, rest = intro.partition("\n")
                first = re.sub(rf"^{re.escape(path.name)}\s*-\s*", "", first)
                text = (first + ("\n" + rest if rest else "")).strip("\n")
                parts += ["```text", text, "```"]
            if not entries:
                parts += ["", "(types and constants only)"]
            for protos, doc in entries:
                names = ", ".join(f"`{n}`" for n, _ in protos)
                parts += ["", f"#### {names}", "", "```c"]
                parts += [p for _, p in protos]
                parts.append("```")
                if doc:
                    parts += ["", "```text", doc, "```"]
    return "\n".join(parts) + "\n"


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    text = render()
    missing = undocumented()
    if missing:
        print("public functions without a comment block:\n  " + "\n  ".join(missing),
              file=sys.stderr)
    if argv == ["--check"]:
        current = PAGE.read_text(encoding="utf-8") if PAGE.exists() else ""
        if current != text:
            print(f"{PAGE} is stale: run python docs/c_api.py", file=sys.stderr)
            return 1
        return 1 if missing else 0
    if argv:
        print(__doc__, file=sys.stderr)
        return 2
    PAGE.write_text(text, encoding="utf-8")
    print(f"wrote {PAGE}")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
