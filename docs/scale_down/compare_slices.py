#!/usr/bin/python3
"""Scale-down evidence (docs/scale_down.md): compares the film of periodic slices of paper
case D12 scaled to several D/d by eqs 1-3 (cases/scale_down/slice_dd*.yaml).

usage: /usr/bin/python3 docs/scale_down/compare_slices.py REF_DIR DIR [DIR ...]

For each run DIR (a `centrec dem --out DIR`): mean film thickness (eqs 4-7) in d, its
difference to REF_DIR's, and for each of the three arcs (45/90/135 deg) the axial velocity
profile against REF_DIR's: max over wall-distance bins sampled in both of
|u - u_ref| / max(u_ref), i.e. the largest difference as a fraction of the reference
profile's peak (bins of 0.5 d; a ratio of raw profiles would blow up at the wall where
u -> 0). Also prints wall time and particle-steps/s. Also the slice's axial mass flow
(summary.json slice_mdot_kg_s, when the run wrote it) and that flow scaled back to D12 by
eq 2 (mdot / R kept). Writes profiles.png next to this script (or PNG=path) if matplotlib
is available.
"""
import json
import os
import sys

import h5py
import numpy as np
import yaml


def load(d):
    s = json.load(open(os.path.join(d, "summary.json")))
    with h5py.File(os.path.join(d, "dem.h5"), "r") as f:
        u = f["film/axial_velocity_mean"][:]
        su = f["film/axial_velocity_std"][:]
        y = f["film/wall_distance_d"][:]
        theta = f["film/arc_theta"][:]
    return s, y, u, su, theta


def main(ref, dirs):
    sr, yr, ur, _, theta = load(ref)
    rows = []
    print("| run | D/d | free particles | film thickness d | vs ref d | max dU/Umax 45 deg | 90 deg | 135 deg "
          "| slice mdot g/s | x 100/(D/d) g/s | wall time s | particle-steps/s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for d in [ref] + dirs:
        s, y, u, su, _ = load(d)
        dev = []
        for a in range(u.shape[0]):
            both = np.isfinite(u[a]) & np.isfinite(ur[a])
            peak = np.nanmax(ur[a])
            dev.append(np.max(np.abs(u[a][both] - ur[a][both])) / peak if both.any() else float("nan"))
        t = s["mean_film_thickness_d"]
        cfg = yaml.safe_load(s["resolved_config"])["dem"]
        dd = cfg["drum"]["diameter"] / cfg["particles"]["diameter"]
        # eq 2 keeps mdot / R: the slice's flux scaled back to D12 (D/d = 100), paper 35.7 g/s
        mdot = s.get("slice_mdot_kg_s")
        flow = f"{1e3 * mdot:.2f} | {1e3 * mdot * 100 / dd:.1f}" if mdot else "- | -"
        rows.append((d, u))
        print(f"| {os.path.basename(d.rstrip('/'))} | {dd:.0f} | {s['free_particles']} | {t:.2f} +- {s['mean_film_thickness_std_d']:.2f} "
              f"| {t - sr['mean_film_thickness_d']:+.2f} | {100*dev[0]:.1f} % | {100*dev[1]:.1f} % | {100*dev[2]:.1f} % "
              f"| {flow} | {s['wall_time_s']:.0f} | {s['particle_steps_per_s']:.3g} |")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 3, figsize=(12, 4), sharey=True)
        for d, u in rows:
            for a, ax in enumerate(axes):
                ax.plot(yr, u[a], marker="o", ms=3, label=os.path.basename(d.rstrip("/")))
        for a, ax in enumerate(axes):
            ax.set_title(f"arc {np.degrees(theta[a]):.0f} deg")
            ax.set_xlabel("wall distance / d")
        axes[0].set_ylabel("axial velocity, m/s")
        axes[0].legend()
        out = os.environ.get("PNG", os.path.join(os.path.dirname(os.path.abspath(__file__)), "profiles.png"))
        fig.tight_layout()
        fig.savefig(out, dpi=100)
        print("wrote", out)
    except ImportError:
        pass


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
