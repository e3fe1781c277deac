#!/usr/bin/python3
"""Retention at a valid size (docs/retention_dd80.md): periodic slices of the paper's D12
scaled to D/d = 80 (cases/retention_dd80/*.yaml), each holding the paper's holdup per length
as the paper counts it (stuck wall layer included), one wall setting each.

usage: /usr/bin/python3 docs/studies/retention/dd80_scan.py RUN_DIR [RUN_DIR ...]

Per run (`centrec dem --out RUN_DIR`): the slice's axial mass flow over the sampled window
and its ratio to the paper's flow scaled by eq 2 (35.7 g/s x 80/100 = 28.56 g/s), the
flow's change between the two halves of the window (steadiness), eqs 4-7 thickness, the
standing-layer height (u below 2 % of the surface velocity) and the RMS distance of the
profile from the paper's line (u = 0 below 1 d, linear from 1 d to the surface; Fig 6a) at
the three arcs, the solid fraction by zone, the moving-zone arcs, particle-steps and CPU
time. Writes profiles.png and table.md next to docs/retention_dd80/ (or OUT=dir).
"""
import csv
import json
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from retention_metrics import in_film, line_from_one_d, standing_height, surface_velocity  # noqa: E402

PAPER_FLOW_DD80 = 35.7e-3 * 80 / 100  # eq 2: mdot / R kept


def flow_halves(run_dir, t0):
    """Mean slice axial flow over the first and second half of the sampled window."""
    t, q = [], []
    with open(os.path.join(run_dir, "mass_flow.csv")) as f:
        for row in csv.DictReader(f):
            t.append(float(row["time_s"]))
            q.append(float(row["slice_axial_flow_kg_s"]))
    t, q = np.array(t), np.array(q)
    sel = t > t0
    t, q = t[sel], q[sel]
    mid = 0.5 * (t[0] + t[-1])
    return float(np.mean(q[t <= mid])), float(np.mean(q[t > mid]))


def measure(run_dir):
    s = json.load(open(os.path.join(run_dir, "summary.json")))
    import yaml
    cfg = yaml.safe_load(s["resolved_config"])["dem"]
    r = {"name": os.path.basename(run_dir.rstrip("/")), "free": s["free_particles"], "glued": s["glued_particles"],
         "flow": s["slice_mdot_kg_s"], "thickness": s["mean_film_thickness_d"],
         "thickness_std": s["mean_film_thickness_std_d"], "zones": s.get("moving_zones", []),
         "psteps": s["particle_steps_per_s"] * s["wall_time_s"], "wall": s["wall_time_s"]}
    r["first_half"], r["second_half"] = flow_halves(run_dir, cfg["run"]["duration"])
    r["cpu"] = float("nan")
    tfile = run_dir.rstrip("/") + ".time"
    if os.path.exists(tfile):
        for line in open(tfile):
            if "User time (seconds)" in line:
                r["cpu"] = float(line.split(":")[1])
    with h5py.File(os.path.join(run_dir, "dem.h5"), "r") as f:
        fl = f["film"]
        w = fl["wall_distance_d"][:]
        bw = float(w[1] - w[0])
        um, ut = fl["axial_velocity_mean"][:], fl["axial_velocity_turns"][:]
        sm = fl["solid_fraction_mean"][:]
        r["theta"] = np.degrees(fl["arc_theta"][:])
        r["w"], r["u"] = w, um
        t = r["thickness"]
        stand, rms = [], []
        for k in range(um.shape[0]):
            film = in_film(w, t)
            us = surface_velocity(um[k], ut[k], film)
            stand.append(standing_height(w, um[k], ut[k], us, bw))
            slope, e = line_from_one_d(w, um[k], ut[k], t)
            rms.append(e / us if us > 0 else float("nan"))
        r["standing"], r["line_rms"] = stand, rms
        core = (w >= 1.0) & (w <= t - 1.0)
        r["phi"] = [float(np.nanmean(sm[z][core])) if np.any(core) else float("nan") for z in range(sm.shape[0])]
    return r


def main(dirs):
    rows = [measure(d) for d in dirs]
    out = os.environ.get("OUT", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "retention_dd80"))
    head = ("| wall | glued + free | slice flow g/s | / paper 28.56 | halves g/s | thickness d | standing height d "
            "45/90/135 | rms off paper line / u_s | phi stationary / moving | moving arcs deg | particle-steps | CPU s |\n"
            "|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    lines = []
    for r in rows:
        arcs = ", ".join(f"{z['start_deg']:.0f}-{z['end_deg']:.0f}" for z in r["zones"]) or "none"
        lines.append(
            f"| {r['name']} | {r['glued']} + {r['free']} | {1e3 * r['flow']:.2f} | {r['flow'] / PAPER_FLOW_DD80:.2f} | "
            f"{1e3 * r['first_half']:.2f} / {1e3 * r['second_half']:.2f} | {r['thickness']:.2f} +- {r['thickness_std']:.2f} | "
            + " / ".join(f"{x:.2f}" for x in r["standing"]) + " | "
            + " / ".join(f"{x:.2f}" for x in r["line_rms"]) + " | "
            + " / ".join(f"{x:.3f}" for x in r["phi"]) + f" | {arcs} | {r['psteps']:.2g} | {r['cpu']:.0f} |")
    table = head + "\n".join(lines) + "\n"
    print(table)
    os.makedirs(out, exist_ok=True)
    open(os.path.join(out, "table.md"), "w").write(table)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 3, figsize=(13, 4.2), sharey=True)
        for r in rows:
            for a, ax in enumerate(axes):
                ax.plot(r["w"], r["u"][a], marker="o", ms=2.5, label=f"{r['name']} ({1e3 * r['flow']:.1f} g/s)")
        for a, ax in enumerate(axes):
            ax.set_title(f"arc {rows[0]['theta'][a]:.0f} deg")
            ax.set_xlabel("wall distance / d")
            ax.set_xlim(0, 8)
            ax.grid(alpha=0.3)
        axes[0].set_ylabel("axial velocity, m/s")
        axes[0].legend(fontsize=7)
        fig.suptitle("D/d 80 slices at the paper's holdup per length: wall settings (paper flow 28.56 g/s)")
        fig.tight_layout()
        fig.savefig(os.path.join(out, "profiles.png"), dpi=100)
        print("wrote", os.path.join(out, "profiles.png"))
    except ImportError:
        pass


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
