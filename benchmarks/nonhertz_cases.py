"""The cases and the exact reference of the non-Hertzian study (issue 24, item 3).

    python benchmarks/nonhertz_cases.py [--quick]

Two sets of cases, one wheel each, solved by the library's exact
non-Hertzian solver (rr.rig_exact: the vertical load Fz given, the normal
load iterated; creepages from the rig's kinematics at its own reference
point) and cached in benchmarks/out/nonhertz/ (gitignored):

- "csv": CONTACT's 72 roller cases (tests/data/roller_nonhertz_cases.csv),
  on rollerrig's own geometry as tests/test_nonhertz.py's chain(), on
  CONTACT's 0.4 mm grid;
- "sweep": both pairs (the measured MiniProf pair, left and right wheel;
  S1002 on the UIC60-headed roller, the left wheel: its right one is the
  mirror image) at lateral shifts -8 to +8 mm every 0.5 mm and in the
  two-point zones every 0.1 mm, the vertical load 61.16 kN (CONTACT's
  13750 lbf) and 0.5 and 1.5 times it, creepages from small to full
  sliding: the wheelset's spin and lateral velocity set so that the
  creepages at rig_contact's (rigid) contact point are the targets (cx, cy);
  the spin creepage is the contact angle's (0.04 to 3.8 rad/m).

The reference is nonhertz_geom.exact_multi: rig_exact's construction
(CONTACT's weighted reference, the loaded pose, the vertical balance
N n_z + fy t2_z = Fz) extended to patches farther apart than 4 mm (each its
own plane, one pose), on grids of 60 elements across a patch's longer side
and at least 24 across its shorter one (rig_exact's default n = 40 puts 4
to 7 across the flange's patches), the forces extrapolated to the
continuum by Richardson from elements half that size, each patch's plane
(CONTACT's weighted reference) set at the final approach, as rig_exact's
rebuild does (see nonhertz_geom.exact_multi) (the steady-rolling
upwind difference is first order in the element size, as
rollerrig.exact_table's nodes are extrapolated), the normal solution the
fine grid's.  rig_exact on its default grid is kept beside it.
"""
import argparse
import os
import pickle
import sys
import time
import warnings

import numpy as np

import rollerrig as rr

import nonhertz_geom as ng

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "out", "nonhertz")
sys.path.insert(0, os.path.join(HERE, "..", "tests"))

FZ0 = 61163.04721          # CONTACT's FZ, 13750 lbf [N]
MU = 0.52
G = 8.2e10
NU = 0.28
E = 2.0 * G * (1.0 + NU)
ROLLER_SPIN = 5.587302     # 10 mph on the 0.8 m roller [rad/s]

#: creepage targets (cx, cy) at rig_contact's contact point, nominal load
CREEP = [(0.0005, 0.0), (0.002, 0.0), (0.006, 0.0), (0.02, 0.0),
         (0.001, 0.001), (0.003, -0.002), (-0.001, 0.003), (0.0, 0.008)]
#: and at 0.5 and 1.5 times the load
CREEP_LOADS = [(0.001, 0.0), (0.004, 0.002)]
LOADS = (0.5, 1.5)

#: shifts [mm] where the rigid contact point jumps between two gap minima
#: (rig_contact's table at 0.01 mm: MiniProf left 3.93, 5.52, 7.44, right
#: -1.01, 6.55; S1002 0.20, 4.84, 6.25): swept every 0.1 mm around them
TWO_POINT = {("miniprof", "left"): [(3.6, 4.3), (5.2, 5.9), (7.1, 7.8)],
             ("miniprof", "right"): [(-1.4, -0.7), (6.2, 6.9)],
             ("s1002", "left"): [(-0.1, 0.6), (4.5, 5.2), (5.9, 6.6)]}
#: the reference's grids: n elements across a patch's longer side, at least
#: n_short across its shorter one, and Richardson from elements half as large
REF_GRID = dict(n=60, n_short=24)


def geometries():
    return {"miniprof": rr.RigGeometry.measured_pair(),
            "s1002": rr.RigGeometry.standard(roller_radius=0.8001)}


_TABLES = {}


def table(pair, geo=None):
    """The rig's contact table of a pair, 0.01 mm rows over +-9.5 mm."""
    if pair not in _TABLES:
        geo = geo or geometries()
        _TABLES[pair] = rr.contact_table(geo[pair], -0.0095, 0.0095, 1901)
    return _TABLES[pair]


def kinematics(tab, y, side, cx, cy):
    """(spin, vy) giving creepages (cx, cy) at rig_contact's contact point
    of `side` (linear in both: three evaluations)."""
    R0 = float(tab.geometry.roller_radius)
    r0 = float(tab.geometry.wheel_radius)
    s0 = ROLLER_SPIN * R0 / r0

    def at(spin, vy):
        w = getattr(rr.rig_contact(tab, y=y, spin=spin, roller_spin=ROLLER_SPIN, vy=vy,
                                   N_left=1.0, N_right=1.0, kinematics_only=True), side)
        return np.array([float(w.cx), float(w.cy)])
    c0 = at(s0, 0.0)
    J = np.stack([(at(s0 * 1.001, 0.0) - c0) / (s0 * 1e-3), (at(s0, 0.01) - c0) / 0.01], 1)
    d = np.linalg.solve(J, np.array([cx, cy]) - c0)
    return s0 + d[0], d[1]


def sweep_cases(quick=False):
    cases = []
    for pair, side in (("miniprof", "left"), ("miniprof", "right"), ("s1002", "left")):
        ys = set(np.round(np.arange(-8.0, 8.001, 0.5), 3))
        for lo, hi in TWO_POINT[(pair, side)]:
            ys |= set(np.round(np.arange(lo, hi + 1e-9, 0.1), 3))
        ys = sorted(ys)
        if quick:
            ys = ys[::4]
        for y in ys:
            for cx, cy in CREEP:
                cases.append(dict(set="sweep", pair=pair, side=side, y=y * 1e-3, load=1.0,
                                  cx_t=cx, cy_t=cy))
            for f in LOADS:
                for cx, cy in CREEP_LOADS:
                    cases.append(dict(set="sweep", pair=pair, side=side, y=y * 1e-3, load=f,
                                      cx_t=cx, cy_t=cy))
    return cases


#: friction of the "mu" set (the tables' corrections are built at MU)
MU_OTHER = 0.3
CREEP_MU = [(0.0005, 0.0), (0.002, 0.0), (0.003, -0.002), (0.0, 0.004)]


def mu_cases():
    """The sweep's shifts every 0.5 mm at friction MU_OTHER, four creepages."""
    cases = []
    for pair, side in (("miniprof", "left"), ("miniprof", "right"), ("s1002", "left")):
        for y in np.round(np.arange(-8.0, 8.001, 0.5), 3):
            for cx, cy in CREEP_MU:
                cases.append(dict(set="mu", pair=pair, side=side, y=y * 1e-3, load=1.0,
                                  cx_t=cx, cy_t=cy, mu=MU_OTHER))
    return cases


def csv_cases():
    from reference_cases import read_columns
    C = read_columns("roller_nonhertz_cases.csv")
    out = []
    for i in range(C["key"].size):
        pair = "miniprof" if C["pair"][i] == "miniprof" else "s1002"
        out.append(dict(set="csv", key=str(C["key"][i]), pair=pair, side="left",
                        y=float(C["y_ws"][i]), load=float(C["FZ"][i]) / FZ0,
                        spin=float(C["spin"][i]), roller_spin=float(C["roller_spin"][i]),
                        vy=0.0, dx=float(C["dx"][i]),
                        contact={k: float(C[k][i]) for k in ("fx", "fy", "mz", "FN", "area",
                                                             "pmax", "cx", "cphi", "delta")}))
    return out


def solve_case(case, geo):
    """The exact reference of one case: nonhertz_geom.exact_multi (every
    patch, Richardson) and rig_exact on its default grid (one patch)."""
    g = geo[case["pair"]]
    tab = table(case["pair"], geo)
    if "spin" not in case:
        case["spin"], case["vy"] = kinematics(tab, case["y"], case["side"], case["cx_t"],
                                              case["cy_t"])
        case["roller_spin"] = ROLLER_SPIN
    Fz = FZ0 * case["load"]
    rec = dict(case, Fz=Fz)
    t0 = time.perf_counter()
    m = ng.exact_multi(ng.Wheel(g, case["side"]), tab, case["y"], Fz, spin=case["spin"],
                       roller_spin=case["roller_spin"], vy=case["vy"], mu=case.get("mu", MU),
                       G=G, nu=NU,
                       **REF_GRID)
    rec["t_multi"] = time.perf_counter() - t0
    rec.update(N=m.N, force=m.force, area=m.area, pmax=m.pmax, centre=m.centre, dz=m.dz,
               patches=[dict(N=p.N, fx=p.fx, fy=p.fy, mz=p.mz, cx=p.cx, cy=p.cy, cphi=p.cphi,
                             area=p.area, pmax=p.pmax, centre=p.centre, point=p.grid.point,
                             t1=p.grid.t1, t2=p.grid.t2, n=p.grid.n, delta=p.grid.delta,
                             s_roller=p.grid.s_roller, dx=p.grid.dx, shape=p.grid.h.shape,
                             regions=rr.patch_shape(p.solution.contact, p.solution.x[0, 1]
                                                    - p.solution.x[0, 0],
                                                    p.grid.dy / 2).regions)
                        for p in m.patches])
    t0 = time.perf_counter()
    with warnings.catch_warnings(record=True) as wl:
        warnings.simplefilter("always")
        try:
            e = rr.rig_exact(g, case["y"], Fz=Fz, mu=case.get("mu", MU), side=case["side"],
                             spin=case["spin"],
                             roller_spin=case["roller_spin"], vy=case["vy"], E=E, nu=NU,
                             table=tab)
            rec["rig_exact"] = dict(N=e.N, force=e.force, fx=e.solution.fx, fy=e.solution.fy,
                                    area=e.solution.contact_area, pmax=e.solution.pmax,
                                    delta=e.patch.delta, excluded=len(e.patch.excluded))
        except rr.RollerRigError as err:
            rec["rig_exact"] = dict(error=str(err))
    rec["rig_exact"]["warnings"] = [str(w.message)[:200] for w in wl]
    rec["t_rig_exact"] = time.perf_counter() - t0
    return rec


def run(cases, path, geo):
    done = {}
    if os.path.exists(path):
        with open(path, "rb") as f:
            done = pickle.load(f)

    def key(c):
        return (c["set"], c["pair"], c["side"], round(c["y"] * 1e6), c["load"],
                c.get("cx_t"), c.get("cy_t"), c.get("key"))
    todo = [c for c in cases if key(c) not in done]
    print(f"{len(cases)} cases, {len(todo)} to solve", file=sys.stderr)
    t0 = time.perf_counter()
    for i, c in enumerate(todo):
        try:
            done[key(c)] = solve_case(dict(c), geo)
        except rr.RollerRigError as err:
            done[key(c)] = dict(c, error=str(err))
            print(f"  {key(c)}: {err}", file=sys.stderr)
        if (i + 1) % 50 == 0 or i + 1 == len(todo):
            with open(path + ".tmp", "wb") as f:
                pickle.dump(done, f)
            os.replace(path + ".tmp", path)
            print(f"  {i + 1}/{len(todo)} {time.perf_counter() - t0:.0f} s", file=sys.stderr)
    return [done[key(c)] for c in cases]


#: "" or "_split" (patches split by angle, nonhertz_geom.A_SEP): the files' suffix
SUFFIX = ""


def set_split(a_sep):
    """Use (and write) the reference with patches split by angle a_sep [rad]."""
    global SUFFIX
    ng.A_SEP = a_sep
    SUFFIX = "" if a_sep is None else "_split"


def load(name):
    """The cached records of a set ("csv", "sweep", "mu"), in the cases' order."""
    with open(os.path.join(OUT, f"{name}{SUFFIX}.pkl"), "rb") as f:
        done = pickle.load(f)
    return list(done.values())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="every 4th shift of the sweep")
    ap.add_argument("--set", choices=("csv", "sweep", "both", "mu"), default="both")
    ap.add_argument("--split", type=float, default=None,
                    help="split patches whose gap minima's angles differ by more [rad]")
    ap.add_argument("--pair", default=None)
    args = ap.parse_args()
    set_split(args.split)
    os.makedirs(OUT, exist_ok=True)
    geo = geometries()
    if args.set in ("csv", "both"):
        run([k for k in csv_cases() if args.pair in (None, k["pair"])],
            os.path.join(OUT, f"csv{SUFFIX}.pkl"), geo)
    if args.set in ("sweep", "both"):
        run([k for k in sweep_cases(args.quick) if args.pair in (None, k["pair"])],
            os.path.join(OUT, f"sweep{SUFFIX}.pkl"), geo)
    if args.set == "mu":
        run([k for k in mu_cases() if args.pair in (None, k["pair"])],
            os.path.join(OUT, f"mu{SUFFIX}.pkl"), geo)


if __name__ == "__main__":
    main()
