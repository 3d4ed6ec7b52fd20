"""Two RESULTS.md files side by side: every goal of every section, and the
contact section's per-method times, before and after a change.

    python benchmarks/compare_results.py BEFORE.md [AFTER.md] [--label TEXT]

AFTER defaults to benchmarks/RESULTS.md, which gets the comparison as its
section `before_after`.  Run the benchmark scripts of both trees one after
the other in one session (the figures' dates and loads are quoted), so that
the ratios compare like with like.
"""
import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import _bench_common as bc                                  # noqa: E402

NUMBER = re.compile(r"^(-?[0-9.]+(?:e[+-]?[0-9]+)?)\s*(.*)$")


def sections(path):
    with open(path) as fh:
        text = fh.read()
    return {m.group(1): m.group(2) for m in
            re.finditer(r"<!-- begin (\w+) -->\n(.*?)<!-- end \1 -->", text, re.S)}


def table(text, heading):
    """Rows (lists of cells) of the first Markdown table after `heading`."""
    i = text.find(heading)
    if i < 0:
        return [], []
    lines = [ln for ln in text[i:].split("\n")[1:]]
    rows = []
    for ln in lines:
        if ln.startswith("|"):
            rows.append([c.strip() for c in ln.strip().strip("|").split("|")])
        elif rows:
            break
    return (rows[0], rows[2:]) if len(rows) > 2 else ([], [])


def ratio(before, after):
    mb, ma = NUMBER.match(before), NUMBER.match(after)
    if not (mb and ma) or mb.group(2) != ma.group(2) or float(mb.group(1)) == 0.0:
        return "-"
    return f"{float(ma.group(1)) / float(mb.group(1)):.3f}"


def line(text, key):
    return next((ln for ln in text.split("\n") if ln.startswith(key)), f"{key} ?")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("before")
    parser.add_argument("after", nargs="?", default=os.path.join(HERE, "RESULTS.md"))
    parser.add_argument("--label", default="")
    args = parser.parse_args(argv)
    old, new = sections(args.before), sections(args.after)
    L = ["# Before and after" + (f": {args.label}" if args.label else ""), "",
         "Each section's goals as measured by the code before (left) and after (right); "
         "ratio = after / before (below 1: faster, for times). The two runs of a section "
         "were made one after the other on the same machine:", ""]
    for name in new:
        if name not in old or name == "before_after":
            continue
        L.append(f"- {name}: before {line(old[name], '- date')[2:]}, "
                 f"{line(old[name], '- code')[2:].split(';')[0]}; after "
                 f"{line(new[name], '- date')[2:]}, {line(new[name], '- code')[2:].split(';')[0]}")
    for name in new:
        if name not in old or name == "before_after":
            continue
        _, rows_new = table(new[name], "## Goals")
        _, rows_old = table(old[name], "## Goals")
        before = {r[0]: r[1] for r in rows_old}
        if not rows_new:
            continue
        L += ["", f"## {name}: goals", "", "| goal | before | after | ratio | target |",
              "| --- | ---: | ---: | ---: | --- |"]
        for r in rows_new:
            b = before.get(r[0], "n/a")
            L.append(f"| {r[0]} | {b} | {r[1]} | {ratio(b, r[1])} | {r[2]} |")
    if "contact" in new and "contact" in old:
        head, rows_new = table(new["contact"], "## One thread")
        _, rows_old = table(old["contact"], "## One thread")
        before = {r[0]: r for r in rows_old}
        cols = [head.index(c) for c in ("batched us/case", "one call per case us")]
        L += ["", "## contact: per case, batched and one call per case", "",
              "| method | batched us before | after | ratio | one call us before | after | "
              "ratio |", "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"]
        for r in rows_new:
            o = before.get(r[0])
            if not o:
                continue
            cells = []
            for c in cols:
                b, a = o[c].split(" (")[0], r[c].split(" (")[0]
                cells += [b, a, ratio(b, a)]
            L.append(f"| {r[0]} | " + " | ".join(cells) + " |")
    bc.write_section(args.after, "before_after", "\n".join(L))
    print("\n".join(L))
    return 0


if __name__ == "__main__":
    sys.exit(main())
