"""The non-Hertzian study (issue 24, item 3): fast methods against the exact
reference, their tables' cost and their continuity.

    python benchmarks/nonhertz_cases.py            # the exact reference (cached)
    python benchmarks/study_nonhertz.py rows --spacing 0.1     # tables (cached)
    python benchmarks/study_nonhertz.py evaluate   # every method on every case
    python benchmarks/study_nonhertz.py continuity # force against y at 0.01 mm
    python benchmarks/study_nonhertz.py report     # the Markdown tables

Caches and results in benchmarks/out/nonhertz/ (gitignored); the findings
in benchmarks/NONHERTZ_STUDY.md.  One process (the machine is shared).
"""
import argparse
import os
import pickle
import sys
import time
import warnings

import numpy as np

import rollerrig as rr
import nonhertz_cases as nc
import nonhertz_fast as nf
import nonhertz_geom as ng

OUT = nc.OUT
SIDES = (("miniprof", "left"), ("miniprof", "right"), ("s1002", "left"))
FZ_MAX = 1.6 * nc.FZ0          # the tables' largest vertical load


def log(msg):
    print(msg, file=sys.stderr, flush=True)


# ------------------------------------------------------------------ tables

def row_path(pair, side, tag):
    return os.path.join(OUT, f"rows_{pair}_{side}_{tag}{nc.SUFFIX}.pkl")


def base_tag(tag):
    """The shifts' tag of a table's tag ("cases+c": cases, corrected)."""
    return tag.split("+")[0].split(":")[0]


def row_shifts(tag, pair, side):
    """The rows' shifts [m]: "cases" (each shift of the reference's cases) or
    a spacing in mm over -8.5 ... 8.5 mm."""
    if tag == "cases":
        ys = set()
        for name in ("csv", "sweep"):
            for r in nc.load(name):
                if r["pair"] == pair and r["side"] == side:
                    ys.add(round(r["y"], 9))
        return sorted(ys)
    d = float(tag[1:])
    if tag[0] == "o":       # offset by half a spacing: the sweep's shifts fall between rows
        return list(np.round(np.arange(-8.5 - d / 2, 8.5 + d / 2 + 1e-9, d) * 1e-3, 9))
    return list(np.round(np.arange(-8.5, 8.5 + 1e-9, d) * 1e-3, 9))


def build_rows(tag, only=None, corrected=False, **kw):
    geo = nc.geometries()
    for pair, side in SIDES:
        if only and pair != only:
            continue
        path = row_path(pair, side, tag)
        rows = {}
        if os.path.exists(path):
            with open(path, "rb") as f:
                rows = pickle.load(f)
        ys = [y for y in row_shifts(base_tag(tag), pair, side) if y not in rows]
        log(f"{pair} {side} {tag}: {len(ys)} rows to build")
        w = ng.Wheel(geo[pair], side)
        tab = nc.table(pair, geo)
        t0 = time.perf_counter()
        for k, y in enumerate(ys):
            t = time.perf_counter()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", rr.RollerRigWarning)
                kw_ = dict(kw)
                if corrected:
                    # the rig's kinematics at free rolling at this shift
                    spin, _ = nc.kinematics(tab, y, side, 0.0, 0.0)
                    kw_["correct"] = ng.Kinematics(tab, y, spin, nc.ROLLER_SPIN)
                row = nf.build_row(w, y, FZ_MAX, **kw_)
            row.seconds = time.perf_counter() - t
            rows[y] = row
            if (k + 1) % 20 == 0 or k + 1 == len(ys):
                with open(path + ".tmp", "wb") as f:
                    pickle.dump(rows, f)
                os.replace(path + ".tmp", path)
                log(f"  {k + 1}/{len(ys)} {time.perf_counter() - t0:.0f} s")


def load_rows(pair, side, tag):
    with open(row_path(pair, side, tag), "rb") as f:
        rows = pickle.load(f)
    return [rows[y] for y in sorted(rows)]


# ------------------------------------------------------------------ methods

class Context:
    """Geometry, tables and table methods, built on demand."""

    def __init__(self):
        self.geo = nc.geometries()
        self._rows = {}
        self._wheels = {}

    def wheel(self, pair, side):
        if (pair, side) not in self._wheels:
            self._wheels[(pair, side)] = ng.Wheel(self.geo[pair], side)
        return self._wheels[(pair, side)]

    def rows(self, pair, side, tag):
        """A table's rows; tag "o0.1+c:2": every 2nd row of o0.1+c."""
        if (pair, side, tag) not in self._rows:
            base, _, stride = tag.partition(":")
            rows = load_rows(pair, side, base)
            self._rows[(pair, side, tag)] = rows[::int(stride)] if stride else rows
        return self._rows[(pair, side, tag)]

    def table_method(self, pair, side, tag, tangential, y=None, mu=nc.MU):
        rows = self.rows(pair, side, tag)
        if base_tag(tag) == "cases":       # the row at the case's own shift
            rows = [r for r in rows if abs(r.y - y) < 1e-9]
        return nf.TableMethod(rows, self.wheel(pair, side), tangential=tangential, mu=mu,
                              G=nc.G, nu=nc.NU)


def run_method(ctx, name, rec):
    pair, side, y = rec["pair"], rec["side"], rec["y"]
    tab = nc.table(pair, ctx.geo)
    kw = dict(spin=rec["spin"], roller_spin=rec["roller_spin"], vy=rec["vy"])
    Fz = rec["Fz"]
    mu = rec.get("mu", nc.MU)
    if name == "hertz_fastsim":
        return nf.hertz(tab, y, Fz, side, method="fastsim", mu=mu, G=nc.G, nu=nc.NU, **kw)
    if name == "hertz_exact_table":
        return nf.hertz(tab, y, Fz, side, method="exact_table", mu=mu, G=nc.G, nu=nc.NU,
                        **kw)
    if name == "multi_hertz":
        return nf.multi_hertz(ctx.wheel(pair, side), tab, y, Fz, mu=mu, G=nc.G, nu=nc.NU,
                              **kw)
    if name == "exact40":        # the reference's construction, 40 elements, no Richardson
        m = ng.exact_multi(ctx.wheel(pair, side), tab, y, Fz, mu=mu, G=nc.G, nu=nc.NU, n=40,
                           n_short=16, richardson=False, **kw)
        return nf.Result(force=m.force, N=m.N, area=m.area, pmax=m.pmax, centre=m.centre,
                         normal=sum((p.N * p.grid.n for p in m.patches), np.zeros(3)))
    if name.startswith("table_"):
        _, tangential, tag = name.split("_", 2)
        return ctx.table_method(pair, side, tag, tangential, y, mu)(tab, y, Fz, **kw)
    raise ValueError(name)


def errors(rec, res):
    """The errors of one result against the reference record."""
    muN = rec.get("mu", nc.MU) * rec["N"]
    creep_ref = rec["force"] - sum(p["N"] * p["n"] for p in rec["patches"])
    return dict(
        dF=float(np.linalg.norm(res.force - rec["force"]) / muN),
        dC=float(np.linalg.norm(res.creep - creep_ref) / muN),
        dN=float(res.N / rec["N"] - 1.0),
        dA=float(res.area / rec["area"] - 1.0),
        dP=float(res.pmax / rec["pmax"] - 1.0),
        dX=float(np.linalg.norm(res.centre - rec["centre"]) * 1e3),
        npatch=len(res.patches), npatch_ref=len(rec["patches"]))


def evaluate(methods, sets=("csv", "sweep")):
    ctx = Context()
    path = os.path.join(OUT, f"errors{nc.SUFFIX}.pkl")
    done = {}
    if os.path.exists(path):
        with open(path, "rb") as f:
            done = pickle.load(f)
    for name in methods:
        for s in sets:
            recs = nc.load(s)
            key = (name, s)
            t0 = time.perf_counter()
            out = []
            for rec in recs:
                if "error" in rec:
                    continue
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", rr.RollerRigWarning)
                    try:
                        res = run_method(ctx, name, rec)
                        e = errors(rec, res)
                    except (rr.RollerRigError, ValueError, IndexError) as err:
                        e = dict(error=str(err)[:200])
                e.update(pair=rec["pair"], side=rec["side"], y=rec["y"], load=rec["load"],
                         cx_t=rec.get("cx_t"), cy_t=rec.get("cy_t"), key=rec.get("key"))
                out.append(e)
            done[key] = out
            log(f"{name} {s}: {len(out)} cases, {time.perf_counter() - t0:.0f} s")
            with open(path + ".tmp", "wb") as f:
                pickle.dump(done, f)
            os.replace(path + ".tmp", path)


# ------------------------------------------------------------------ continuity

def continuity(methods, step=1e-5, half=0.5e-3, only=None):
    """Force against y at `step` through every two-point zone (the contact
    point's jumps, +-half around them), at the nominal load and a mid
    creepage: the largest change between neighbours over mu N."""
    ctx = Context()
    jumps = {("miniprof", "left"): [3.93, 5.52, 7.44], ("miniprof", "right"): [-1.01, 6.55],
             ("s1002", "left"): [0.20, 4.84, 6.25]}
    out = {}
    for name in methods:
        for (pair, side), js in jumps.items():
            if only and pair != only:
                continue
            tab = nc.table(pair, ctx.geo)
            for yj in js:
                yj *= 1e-3
                spin, vy = nc.kinematics(tab, yj - half, side, 0.002, 0.001)
                ys = np.arange(yj - half, yj + half + 1e-12, step)
                F, N = [], []
                for y in ys:
                    rec = dict(pair=pair, side=side, y=float(y), spin=spin,
                               roller_spin=nc.ROLLER_SPIN, vy=vy, Fz=nc.FZ0)
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore", rr.RollerRigWarning)
                        try:
                            r = run_method(ctx, name, rec)
                            F.append(r.force)
                            N.append(r.N)
                        except (rr.RollerRigError, ValueError, IndexError):
                            F.append(np.full(3, np.nan))
                            N.append(np.nan)
                F = np.array(F)
                d = np.linalg.norm(np.diff(F, axis=0), axis=1) / (nc.MU * np.array(N[:-1]))
                failed = int(np.sum(~np.isfinite(N)))
                k = int(np.nanargmax(d)) if np.isfinite(d).any() else 0
                out[(name, pair, side, round(yj * 1e3, 2))] = dict(
                    max_jump=float(d[k]), at=float(ys[k]), ys=ys, F=F, N=np.array(N),
                    failed=failed)
                log(f"{name} {pair} {side} {yj * 1e3:.2f} mm: largest step {d[k]:.4f} mu N "
                    f"at {ys[k] * 1e3:.3f} mm ({failed} failed)")
    path = os.path.join(OUT, f"continuity{nc.SUFFIX}.pkl")
    old = {}
    if os.path.exists(path):
        with open(path, "rb") as f:
            old = pickle.load(f)
    old.update(out)
    with open(path, "wb") as f:
        pickle.dump(old, f)


# ------------------------------------------------------------------ export for the C prototype

def export(tag, pair, side, path_table, path_cases, tangential="corrected"):
    """The table of one side and the sweep's cases of it, as flat doubles
    for benchmarks/bench_nonhertz_runtime.c (its header describes the
    layout), with the Python prototype's results to compare."""
    ctx = Context()
    rows = ctx.rows(pair, side, tag)
    w = ctx.wheel(pair, side)
    K = len(nf.NODES)
    nu_, nth = len(nf.CORR_U), len(nf.CORR_TH)
    ncn = len(nf.CORR_NODES)
    out = [0x4e48, len(rows), K, nu_, nth, ncn, w.sigma, float(w.g.roller_radius)]
    out += list(nf.CORR_U)
    for r in rows:
        out += [r.y, len(r.patches)]
        for p in r.patches:
            sig = w.sigma
            PY = sig * (w.roller_y + p.s_roller)
            PZ = -w.roller.z_at(p.s_roller)
            ab = np.clip(p.a5 / p.b5, nf.AB_LO, nf.AB_HI)
            out += [p.g]
            for arr in (p.e, p.N / p.e ** 1.5, PY, PZ, p.delta, p.xc, p.yc,
                        p.area / p.N ** (2 / 3), p.pmax / p.N ** (1 / 3), ab,
                        -p.K[:, 0, 0], -p.K[:, 1, 1], -p.K[:, 1, 2]):
                out += list(np.asarray(arr, dtype=float))
            cs = [c for c in p.corr if c is not None]
            ks = [k for k, c in enumerate(p.corr) if c is not None]
            assert len(cs) == ncn
            for k, c in zip(ks, cs):
                out += [p.e[k]] + list(c["R0"]) + list(np.asarray(c["R"]).ravel())
    np.asarray(out, dtype="<f8").tofile(path_table)
    tab = nc.table(pair, ctx.geo)
    recs = [r for r in nc.load("sweep") if r["pair"] == pair and r["side"] == side]
    ys = np.array([r.y for r in rows])
    cases = []
    for rec in recs:
        y = rec["y"]
        i = int(np.clip(np.searchsorted(ys, y) - 1, 0, len(ys) - 2))
        tt = (y - ys[i]) / (ys[i + 1] - ys[i])
        m = nf.TableMethod(rows, w, tangential=tangential, mu=nc.MU, G=nc.G, nu=nc.NU)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", rr.RollerRigWarning)
            res = m(tab, y, rec["Fz"], spin=rec["spin"], roller_spin=rec["roller_spin"],
                    vy=rec["vy"])
        c = [y, rec["Fz"], nc.MU, rec["roller_spin"], i, tt]
        for k in (i, i + 1):
            kin = ng.Kinematics(tab, rows[k].y, rec["spin"], rec["roller_spin"], vy=rec["vy"])
            c += list(kin.c) + list(kin.v) + list(kin.w)
        c += list(res.force) + [res.N]
        cases.append(c)
    np.asarray(cases, dtype="<f8").tofile(path_cases)
    log(f"{len(rows)} rows, {len(cases)} cases written")


# ------------------------------------------------------------------ report

def _stats(v):
    v = np.asarray(v, dtype=float)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return "-", "-", "-"
    return f"{np.median(v):.4f}", f"{np.percentile(v, 95):.4f}", f"{np.max(v):.4f}"


def report(methods=None):
    with open(os.path.join(OUT, f"errors{nc.SUFFIX}.pkl"), "rb") as f:
        done = pickle.load(f)
    names = methods or sorted({k[0] for k in done})
    lines = ["| method | set | cases | |dF|/(mu N) median | p95 | max | creep only p95 | max "
             "| load p95 | area p95 | peak p95 | centre p95 [mm] | failed |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for name in names:
        for s in ("csv", "sweep", "mu"):
            if (name, s) not in done:
                continue
            es = done[(name, s)]
            for pair in (None, "miniprof", "s1002"):
                sel = [e for e in es if (pair is None or e["pair"] == pair)]
                ok = [e for e in sel if "error" not in e]
                if not ok:
                    continue
                med, p95, mx = _stats([e["dF"] for e in ok])
                _, c95, cmx = _stats([e["dC"] for e in ok])
                pct = lambda k: f"{np.percentile(np.abs([e[k] for e in ok]), 95):.3f}"
                lines.append(f"| {name} | {s}{'' if pair is None else ' ' + pair} | {len(ok)} "
                             f"| {med} | {p95} | {mx} | {c95} | {cmx} | {pct('dN')} "
                             f"| {pct('dA')} | {pct('dP')} | {pct('dX')} "
                             f"| {len(sel) - len(ok)} |")
    print("\n".join(lines))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("what", choices=("rows", "evaluate", "continuity", "report", "export"))
    ap.add_argument("--side", default="left")
    ap.add_argument("--tag", default="cases", help="rows: 'cases' or 'd<mm>' (d0.1)")
    ap.add_argument("--pair", default=None)
    ap.add_argument("--methods", default="hertz_fastsim,hertz_exact_table,multi_hertz,"
                    "table_area_cases,table_calibrated_cases,table_fastsim_cases")
    ap.add_argument("--sets", default="csv,sweep")
    ap.add_argument("--split", type=float, default=None,
                    help="the reference and tables with patches split by angle [rad]")
    args = ap.parse_args()
    nc.set_split(args.split)
    methods = args.methods.split(",")
    if args.what == "rows":
        build_rows(args.tag, args.pair, corrected=args.tag.endswith("+c"))
    elif args.what == "evaluate":
        evaluate(methods, args.sets.split(","))
    elif args.what == "continuity":
        continuity(methods, only=args.pair)
    elif args.what == "export":
        export(args.tag, args.pair, args.side,
               os.path.join(OUT, f"table_{args.pair}_{args.side}.bin"),
               os.path.join(OUT, f"cases_{args.pair}_{args.side}.bin"))
    else:
        report(None if args.methods == "all" else methods)


if __name__ == "__main__":
    main()
