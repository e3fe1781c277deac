#!/usr/bin/python3
"""Speed against accuracy for the DEM's fidelity knobs (docs/dem_knobs.md).

Every run is the quickstart's DEM (cases/quickstart.yaml: a periodic slice of D12 scaled to
D/d 80, square 1.0 d wall, holdup controlled towards the scaled 28.56 g/s) with one knob
moved; its accuracy is measured against the finest setting of that knob:

  dt      time step 2.5e-6 (reference), 5e-6, 1e-5, 2e-5 (default), 3e-5 s (stability bound 3.24e-5)
  E       Young's modulus of particles and wall 5 (default), 15, 50 MPa (reference), each with
          dt = 2e-5 s x sqrt(5 MPa / E), the quickstart's steps per contact time
  skin    Verlet skin 0.2, 0.4 (default, reference), 0.8 d: changes the cost, not the physics
  length  slice length 5, 9 (default), 18 d (reference), whole square lattice rows, started at
          the same free particles per length
  seed    the default with another random start: the noise floor every error is read against

Figures per run (the controlled slice's flow is held at the target by its controller, so the
flow is not an accuracy figure; what the knob moves is the film that carries it): film
thickness (eqs 4-7) minus the reference's, in d; the flux-weighted velocity profile
difference over the three arcs (sum |u - u_ref| phi / sum |u_ref| phi, docs/scale_down.md);
free holdup per length against the reference's; the slice's flow against the target; the
answer of the whole chain on that DEM film (`centrec run --dem-from`: film mapped, scaled up to
the receiver, heated by the quickstart's thermal section): T_out and k_eff against the
reference's; and the cost: particle-steps and wall time.

usage:
  dem_knobs.py cases [--out cases/knobs]          write the case files
  dem_knobs.py run [--threads N] RUNS_DIR [NAME..] run the missing ones (resumable: a run with
                                                   a summary.json is skipped, a killed one resumed
                                                   from its checkpoint), then the coupled chain
                                                   on each finished one
  dem_knobs.py compare RUNS_DIR OUT_DIR            table.md, results.json, knobs.png
"""
import argparse
import json
import math
import os
import subprocess
import sys

import numpy as np
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "docs", "scale_down"))
from compare_slices import flux_weighted_difference, load  # noqa: E402  (one reader, one metric)

BASE = os.path.join(ROOT, "cases", "quickstart.yaml")
DT0, E0 = 2.0e-5, 5.0e6


def variants():
    """The points of the study: a list of (knob, value, run name, reference?), and the run
    names with their edit of the quickstart's dem section. A knob's default setting is the
    one run "default", shared by every knob."""
    points, edits = [], {"default": lambda d: None}

    def put(knob, value, default, ref, name, edit):
        name = "default" if value == default else name
        points.append((knob, value, name, ref))
        edits.setdefault(name, edit)

    for dt in (2.5e-6, 5e-6, 1e-5, 2e-5, 3e-5):
        put("dt", dt, DT0, dt == 2.5e-6, f"dt{dt:g}", lambda d, dt=dt: d["run"].update(dt=dt))
    for e in (5e6, 15e6, 50e6):
        def edit(d, e=e):
            d.setdefault("particles", {})["youngs_modulus"] = e
            d.setdefault("wall", {})["youngs_modulus"] = e
            d["run"]["dt"] = float(f"{DT0 * math.sqrt(E0 / e):.4g}")
        put("E", e, E0, e == 50e6, f"E{e / 1e6:.0f}MPa", edit)
    for s in (0.2, 0.4, 0.8):
        put("skin", s, 0.4, s == 0.4, f"skin{s}", lambda d, s=s: d["run"].update(skin_d=s))
    for n in (5, 9, 18):
        def edit(d, n=n):
            per_d = d["initial_film"]["particles"] / d["slice"]["length_d"]
            d["slice"]["length_d"] = n
            d["initial_film"]["particles"] = int(round(per_d * n))
        put("length", n, 9, n == 18, f"length{n}d", edit)
    put("seed", 2, None, False, "seed2", lambda d: d.update(seed=2))
    return points, edits


def write_cases(out):
    os.makedirs(out, exist_ok=True)
    base = yaml.safe_load(open(BASE))
    points, edits = variants()
    for name, edit in edits.items():
        case = {"title": f"knobs_{name}", "receiver": base["receiver"], "dem": json.loads(json.dumps(base["dem"])),
                "thermal": base["thermal"]}
        edit(case["dem"])
        what = ", ".join(f"{k} = {v:g}{' (the reference of this knob)' if r else ''}" for k, v, n, r in points if n == name)
        text = (f"# DEM knob study (docs/dem_knobs.md; written by docs/studies/dem_knobs.py cases):\n"
                f"# the quickstart's DEM with {what}.\n")
        open(os.path.join(out, name + ".yaml"), "w").write(text + yaml.safe_dump(case, sort_keys=False, width=100))
        print("wrote", os.path.join(out, name + ".yaml"))


def run(runs, threads, names, cases):
    os.makedirs(runs, exist_ok=True)
    exe = os.path.join(ROOT, "build", "centrec")
    for name in names or list(variants()[1]):
        out = os.path.join(runs, name)
        if os.path.exists(os.path.join(out, "summary.json")):
            print("done:", name)
            continue
        if os.path.exists(os.path.join(out, "checkpoint.h5")):  # killed: continue it (bitwise the same run)
            cmd = [exe, "dem", "--resume", out, "--threads", str(threads)]
        else:
            cmd = [exe, "dem", os.path.join(cases, name + ".yaml"), "--out", out, "--threads", str(threads), "--no-plots"]
        print(" ".join(cmd), flush=True)
        with open(out + ".log", "a") as log:
            subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, check=True)
    coupled(runs, names, cases)


def coupled(runs, names, cases):
    """The rest of the chain on each finished DEM run: `centrec run --dem-from` maps its film,
    scales it up to the receiver and heats it (the quickstart's thermal section), so every knob
    is also read in the figures a user takes away (T_out, efficiency, k_eff). Seconds each."""
    exe = os.path.join(ROOT, "build", "centrec")
    for name in names or list(variants()[1]):
        dem, out = os.path.join(runs, name), os.path.join(runs, name, "coupled")
        if not os.path.exists(os.path.join(dem, "summary.json")) or os.path.exists(os.path.join(out, "summary.json")):
            continue
        cmd = [exe, "run", os.path.join(cases, name + ".yaml"), "--dem-from", dem, "--out", out, "--no-plots",
               "--allow-unsteady"]
        print(" ".join(cmd), flush=True)
        with open(out + ".log", "w") as log:
            subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, check=True)


def figures(d, ref):
    s, y, u, su, _ = load(d)
    sr, yr, ur, _, _ = load(ref)
    flux = [flux_weighted_difference(u[a], ur[a], sr["phi"]) for a in range(u.shape[0])]
    cfg = yaml.safe_load(s["resolved_config"])["dem"]
    cfg_r = yaml.safe_load(sr["resolved_config"])["dem"]
    per_len = s["free_particles"] / cfg["slice"]["length_d"]
    chain = {}
    c, cr = (os.path.join(x, "coupled", "summary.json") for x in (d, ref))
    if os.path.exists(c) and os.path.exists(cr):  # the rest of the chain (`run` finishes it)
        c, cr = json.load(open(c)), json.load(open(cr))
        chain = {"T_out_K": c["T_out_K"], "T_out_error_K": c["T_out_K"] - cr["T_out_K"],
                 "efficiency": c["efficiency"], "k_eff": c["k_eff"]["film_mean"]["k_eff"],
                 "k_eff_error": c["k_eff"]["film_mean"]["k_eff"] / cr["k_eff"]["film_mean"]["k_eff"] - 1.0,
                 "flow_closure": c["coupling"]["flow_closure_mean"], "chain_warnings": c["warnings"]}
    per_len_r = sr["free_particles"] / cfg_r["slice"]["length_d"]
    return {
        "thickness_d": s["mean_film_thickness_d"],
        "thickness_std_d": s["mean_film_thickness_std_d"],
        "thickness_error_d": s["mean_film_thickness_d"] - sr["mean_film_thickness_d"],
        "profile_error": flux,
        "profile_error_mean": float(np.mean(flux)),
        "free_per_d": per_len,
        "holdup_error": per_len / per_len_r - 1.0,
        "slice_flow_g_s": 1e3 * s.get("slice_mdot_kg_s", float("nan")),
        "target_g_s": 1e3 * s["slice_target_mdot_kg_s"],
        "steady": s["steady_state"],
        "particle_steps": s["particle_steps_per_s"] * s["wall_time_s"],
        "wall_time_s": s["wall_time_s"],
        "dt_s": s["dt_s"],
        "threads": s["threads"],
        **chain,
    }


def compare(runs, out):
    os.makedirs(out, exist_ok=True)
    points, _ = variants()
    refs = {knob: name for knob, _, name, ref in points if ref}
    refs["seed"] = "default"  # the seed replica is read against the default run
    res = {}
    for knob, value, name, _ in points:
        d = os.path.join(runs, name)
        if not os.path.exists(os.path.join(d, "summary.json")) or not os.path.exists(
                os.path.join(runs, refs[knob], "summary.json")):
            print("missing:", name, "or its reference", refs[knob])
            continue
        r = figures(d, os.path.join(runs, refs[knob]))
        r.update(knob=knob, value=value, run=name, reference=refs[knob])
        res[f"{knob}={value:g}"] = r
    json.dump(res, open(os.path.join(out, "results.json"), "w"), indent=1)
    lines = ["| knob = value | run | vs | thickness [d] | error [d] | profile error 45 / 90 / 135 deg | free per d | holdup error "
             "| slice flow [g/s] | T_out [K] (error) | k_eff (error) | dt [s] | particle-steps | wall [s] (threads) |",
             "|" + "---|" * 14]
    for name, r in res.items():
        lines.append(f"| {name} | {r['run']} | {r['reference']} | {r['thickness_d']:.2f} +- {r['thickness_std_d']:.2f} "
                     f"| {r['thickness_error_d']:+.2f} | " + " / ".join(f"{100 * x:.1f}" for x in r["profile_error"])
                     + f" % | {r['free_per_d']:.0f} | {100 * r['holdup_error']:+.1f} % | {r['slice_flow_g_s']:.2f} "
                     + (f"| {r['T_out_K']:.2f} ({r['T_out_error_K']:+.2f}) | {r['k_eff']:.4f} ({100 * r['k_eff_error']:+.1f} %) "
                        if "T_out_K" in r else "| - | - ") +
                     f"| {r['dt_s']:.3g} | {r['particle_steps']:.3g} | {r['wall_time_s']:.0f} ({r['threads']}) |")
    open(os.path.join(out, "table.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, axes = plt.subplots(1, 5, figsize=(23, 4.5))
    marks = {"dt": "o", "E": "s", "skin": "^", "length": "D", "seed": "*"}
    for knob, m in marks.items():
        pts = [(r["particle_steps"], abs(r["thickness_error_d"]), r["profile_error_mean"], abs(r["holdup_error"]),
                abs(r.get("T_out_error_K", float("nan"))), 100 * abs(r.get("k_eff_error", float("nan"))), n)
               for n, r in res.items() if r["knob"] == knob and r["run"] != r["reference"]]
        if not pts:
            continue
        c, t, p, h, T, k, names = zip(*pts)
        for ax, val in zip(axes, (t, [100 * x for x in p], [100 * x for x in h], T, k)):
            ax.scatter(c, val, marker=m, s=60, label=knob)
            for ci, vi, ni in zip(c, val, names):
                ax.annotate(ni, (ci, vi), fontsize=7, xytext=(3, 3), textcoords="offset points")
    noise = res.get("seed=2")
    for ax, key, scale, title in ((axes[0], "thickness_error_d", 1, "|thickness error| [d]"),
                                  (axes[1], "profile_error_mean", 100, "flux-weighted profile error [%]"),
                                  (axes[2], "holdup_error", 100, "|holdup error| at the target flow [%]"),
                                  (axes[3], "T_out_error_K", 1, "|T_out error| of the coupled chain [K]"),
                                  (axes[4], "k_eff_error", 100, "|k_eff error| of the coupled chain [%]")):
        if noise and key in noise:
            ax.axhline(abs(noise[key]) * scale, color="grey", ls="--", lw=1, label="seed noise")
        ax.set_xscale("log")
        ax.set_xlabel("cost: particle-steps of the run")
        ax.set_title(title)
    axes[0].axhline(0.1, color="r", lw=0.8, label="0.1 d")
    axes[1].axhline(10, color="r", lw=0.8, label="10 %")
    axes[0].legend(fontsize=8)
    fig.suptitle("DEM knobs of the quickstart slice: error against each knob's finest setting vs cost")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "knobs.png"), dpi=100)
    print("wrote", os.path.join(out, "knobs.png"))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("cases")
    c.add_argument("--out", default=os.path.join(ROOT, "cases", "knobs"))
    r = sub.add_parser("run")
    r.add_argument("runs")
    r.add_argument("names", nargs="*")
    r.add_argument("--threads", type=int, default=1)
    r.add_argument("--cases", default=os.path.join(ROOT, "cases", "knobs"))
    m = sub.add_parser("compare")
    m.add_argument("runs")
    m.add_argument("out")
    a = p.parse_args()
    if a.cmd == "cases":
        write_cases(a.out)
    elif a.cmd == "run":
        run(a.runs, a.threads, a.names, a.cases)
    else:
        compare(a.runs, a.out)


if __name__ == "__main__":
    main()
