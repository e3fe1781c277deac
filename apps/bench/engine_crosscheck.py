#!/usr/bin/python3
"""Cross-check of the two DEM engines: reads two `centrec dem` output
directories of the same case (native and --engine liggghts) and writes a Markdown table
and a PNG: holdup, inlet/outlet mass flow, eqs 4-7 film thickness (whole film and along z)
and the nine axial-velocity profiles (paper Fig 6), each with its spread over the sampled
turns (std over turns; sigma = sqrt(s_a^2 + s_b^2) for a difference).

usage: /usr/bin/python3 apps/bench/engine_crosscheck.py NATIVE_DIR LIGGGHTS_DIR --png OUT.png --table OUT.md
"""
import argparse
import json
import math

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("a")
ap.add_argument("b")
ap.add_argument("--png", required=True)
ap.add_argument("--table", required=True)
ap.add_argument("--title", default="")
args = ap.parse_args()


def load(d):
    s = json.load(open(d + "/summary.json"))
    f = h5py.File(d + "/dem.h5", "r")
    period = f.attrs["turn_period_s"]
    diam = f.attrs["particle_diameter_m"]
    mf = {k: f["mass_flow/" + k][()] for k in ("time", "fed", "out", "holdup", "particles")}
    # Sampling window: the last `sampled_turns` turns of the run.
    turns = int(s["sampled_turns"])
    t_end = mf["time"][-1]
    t0 = t_end - turns * period
    win = mf["time"] >= t0 - 1e-9
    hold = mf["holdup"][win]
    # Outlet and inlet mass flow per sampled turn.
    per_turn_out, per_turn_in = [], []
    for k in range(turns):
        a, b = t0 + k * period, t0 + (k + 1) * period
        out_a, out_b = np.interp([a, b], mf["time"], mf["out"])
        in_a, in_b = np.interp([a, b], mf["time"], mf["fed"])
        per_turn_out.append((out_b - out_a) / period)
        per_turn_in.append((in_b - in_a) / period)
    film = f["film"]
    r = dict(
        name="%s (%s)" % (s["engine"], s.get("engine_version", "")[:22]),
        engine=s["engine"],
        d=diam,
        turns=turns,
        holdup=(hold.mean(), hold.std()),
        particles=(mf["particles"][win].mean(), mf["particles"][win].std()),
        mdot_out=(np.mean(per_turn_out), np.std(per_turn_out)),
        mdot_in=(np.mean(per_turn_in), np.std(per_turn_in)),
        thick=(film.attrs["mean_thickness_m"] / diam, film.attrs["mean_thickness_std_m"] / diam),
        z=film["section_z"][()],
        tz=film["thickness_mean"][()] / diam,
        tz_std=film["thickness_std"][()] / diam,
        arc_theta=np.degrees(film["arc_theta"][()]),
        arc_z=film["arc_z_over_length"][()],
        wd=film["wall_distance_d"][()],
        v=film["axial_velocity_mean"][()],
        v_std=film["axial_velocity_std"][()],
        wall=s["wall_time_s"],
        pss=s["particle_steps_per_s"],
        ranks=s.get("ranks", 1),
        threads=s["threads"],
    )
    return r


A, B = load(args.a), load(args.b)


def row(label, a, b, scale=1.0, unit="", rel=False):
    diff = (b[0] - a[0]) * scale
    sig = math.hypot(a[1], b[1]) * scale
    extra = " (%+.1f %%)" % (100 * (b[0] - a[0]) / a[0]) if rel and a[0] else ""
    return "| %s | %.4g +- %.2g | %.4g +- %.2g | %+.3g%s | %.2g | %.1f |" % (
        label + (" " + unit if unit else ""), a[0] * scale, a[1] * scale, b[0] * scale, b[1] * scale, diff, extra,
        sig, abs(diff) / sig if sig > 0 else float("inf"))


lines = [
    "| quantity | %s | %s | difference (L - c) | sigma | abs(diff)/sigma |" % (A["name"], B["name"]),
    "|---|---|---|---|---|---|",
    row("holdup", A["holdup"], B["holdup"], 1e3, "g", rel=True),
    row("free particles", A["particles"], B["particles"], 1.0, "", rel=True),
    row("inlet mass flow", A["mdot_in"], B["mdot_in"], 1e3, "g/s", rel=True),
    row("outlet mass flow", A["mdot_out"], B["mdot_out"], 1e3, "g/s", rel=True),
    row("film thickness eqs 4-7", A["thick"], B["thick"], 1.0, "d"),
]
# Thickness along z: mean and worst section differences.
dz = B["tz"] - A["tz"]
sz = np.hypot(A["tz_std"], B["tz_std"])
ok = np.isfinite(dz)
lines.append("| thickness along z, %d sections | | | mean %+.3g d, max abs %.3g d | median %.2g d | max %.1f |" %
             (ok.sum(), dz[ok].mean(), np.abs(dz[ok]).max(), np.median(sz[ok]), np.max(np.abs(dz[ok]) / sz[ok])))
prof = []
for k in range(len(A["arc_theta"])):
    va, vb, sa, sb = A["v"][k], B["v"][k], A["v_std"][k], B["v_std"][k]
    m = np.isfinite(va) & np.isfinite(vb)
    dv = vb[m] - va[m]
    sg = np.hypot(sa[m], sb[m])
    sg = np.where(sg > 0, sg, np.nan)
    prof.append("| theta %.0f deg, z/L %.1f | %d | %.3g | %.3g | %.3g | %.2f | %.0f %% |" %
                (A["arc_theta"][k], A["arc_z"][k], m.sum(), np.abs(va[m]).max() if m.any() else float("nan"),
                 np.sqrt(np.mean(dv ** 2)) if m.any() else float("nan"), np.abs(dv).max() if m.any() else float("nan"),
                 np.nanmedian(np.abs(dv) / sg) if m.any() else float("nan"),
                 100 * np.nanmean(np.abs(dv) <= 2 * sg) if m.any() else float("nan")))
md = ["# DEM engine cross-check%s\n" % (": " + args.title if args.title else ""),
      "`%s` vs `%s`; %d and %d sampled turns; spreads are standard deviations over turns "
      "(holdup and particles: over the sampled records); sigma = sqrt(s_c^2 + s_L^2).\n" %
      (args.a, args.b, A["turns"], B["turns"]),
      "\n".join(lines), "",
      "Axial-velocity profiles (paper Fig 6), per arc: bins with data in both, largest |v| (m/s), "
      "RMS and largest difference (m/s), median |diff|/sigma per bin, bins within 2 sigma.\n",
      "| profile | bins | max abs v c | RMS diff | max abs diff | median abs(diff)/sigma | within 2 sigma |",
      "|---|---|---|---|---|---|---|"] + prof + [
      "", "Speeds: %s %.3g particle-steps/s (%d thread(s), %d rank(s), %.0f s wall); %s %.3g particle-steps/s "
      "(%d thread(s), %d rank(s), %.0f s wall); machine shared with other jobs." %
      (A["engine"], A["pss"], A["threads"], A["ranks"], A["wall"], B["engine"], B["pss"], B["threads"], B["ranks"],
       B["wall"]), ""]
open(args.table, "w").write("\n".join(md))
print("\n".join(md))

fig = plt.figure(figsize=(13, 12))
gs = fig.add_gridspec(4, 3)
ax = fig.add_subplot(gs[0, :2])
for R, c in ((A, "C0"), (B, "C3")):
    ax.errorbar(R["z"] * 1e3, R["tz"], yerr=R["tz_std"], color=c, marker="o", ms=3, capsize=2, label=R["name"])
ax.set_xlabel("z (mm)")
ax.set_ylabel("film thickness (d), eqs 4-7")
ax.legend()
ax.set_title("film thickness along the drum" + (" - " + args.title if args.title else ""))
ax = fig.add_subplot(gs[0, 2])
labels = ["holdup g", "out g/s", "in g/s"]
for i, (R, c) in enumerate(((A, "C0"), (B, "C3"))):
    vals = [R["holdup"][0] * 1e3, R["mdot_out"][0] * 1e3, R["mdot_in"][0] * 1e3]
    errs = [R["holdup"][1] * 1e3, R["mdot_out"][1] * 1e3, R["mdot_in"][1] * 1e3]
    ax.bar(np.arange(3) + 0.38 * i, vals, 0.36, yerr=errs, color=c, capsize=3, label=R["engine"])
ax.set_xticks(np.arange(3) + 0.19)
ax.set_xticklabels(labels)
ax.legend()
for k in range(len(A["arc_theta"])):
    ax = fig.add_subplot(gs[1 + k // 3, k % 3])
    for R, c in ((A, "C0"), (B, "C3")):
        ax.errorbar(R["wd"], R["v"][k], yerr=R["v_std"][k], color=c, marker=".", capsize=2, label=R["engine"])
    ax.set_title("theta %.0f deg, z/L %.1f" % (A["arc_theta"][k], A["arc_z"][k]), fontsize=9)
    if k // 3 == 2:
        ax.set_xlabel("wall distance (d)")
    if k % 3 == 0:
        ax.set_ylabel("axial velocity (m/s)")
    if k == 0:
        ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(args.png, dpi=90)
print("wrote", args.png, args.table)
