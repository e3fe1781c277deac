#!/usr/bin/python3
"""Scale-down evidence (docs/scale_down.md): compares the film of periodic slices of paper
case D12 scaled to several D/d by eqs 1-3 (cases/scale_down/slice_dd*.yaml).

usage: /usr/bin/python3 docs/scale_down/compare_slices.py REF_DIR DIR [DIR ...]

For each run DIR (a `centrec dem --out DIR`): mean film thickness (eqs 4-7) in d, its
difference to REF_DIR's, and for each of the three arcs (45/90/135 deg) the axial velocity
profile against REF_DIR's: max over wall-distance bins sampled in both of
|u - u_ref| / max(u_ref), i.e. the largest difference as a fraction of the reference
profile's peak (bins of 0.5 d; a ratio of raw profiles would blow up at the wall where
u -> 0). The same two figures inside the film (bins whose centre lies below the reference
film's eqs 4-7 thickness, where the profile carries the flux; above it a few loose
particles give noisy speeds): largest and RMS difference over the peak, and the noise
floor (the combined standard error of the two turn means, over the peak). And the
flux-weighted difference over all bins: sum |u - u_ref| phi / sum |u_ref| phi, with phi the
reference's solid fraction per bin (mean of its two zones): the share of the axial mass flux
that the two profiles disagree on, which weighs the loose top bins by how little they carry.
Also prints wall time, CPU time (user, from DIR/../NAME.time of /usr/bin/time -v when present)
and particle-steps/s. Also the slice's axial mass flow
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
    s["cpu_s"] = float("nan")
    tfile = d.rstrip("/") + ".time"
    if os.path.exists(tfile):
        for line in open(tfile):
            if "User time (seconds)" in line:
                s["cpu_s"] = float(line.split(":")[1])
    with h5py.File(os.path.join(d, "dem.h5"), "r") as f:
        u = f["film/axial_velocity_mean"][:]
        su = f["film/axial_velocity_std"][:]
        y = f["film/wall_distance_d"][:]
        theta = f["film/arc_theta"][:]
        s["phi"] = np.nanmean(f["film/solid_fraction_mean"][:], axis=0)
    return s, y, u, su, theta


def flux_weighted_difference(u, u_ref, phi_ref):
    """sum |u - u_ref| phi / sum |u_ref| phi over the bins sampled in both profiles of one
    arc, phi the reference's solid fraction per bin: the share of the axial mass flux the
    two profiles disagree on."""
    w = np.where(np.isfinite(u) & np.isfinite(u_ref), np.nan_to_num(phi_ref), 0.0)
    return float(np.sum(np.abs(np.nan_to_num(u - u_ref)) * w) / np.sum(np.abs(np.nan_to_num(u_ref)) * w))


def main(ref, dirs):
    sr, yr, ur, sur, theta = load(ref)
    rows, film_rows = [], []
    print("| run | D/d | free particles | film thickness d | vs ref d | max dU/Umax 45 deg | 90 deg | 135 deg "
          "| slice mdot g/s | x 100/(D/d) g/s | wall time s | CPU s | particle-steps/s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for d in [ref] + dirs:
        s, y, u, su, _ = load(d)
        dev, film_dev = [], []
        n_turns, n_ref = max(1, int(s.get("sampled_turns", 1))), max(1, int(sr.get("sampled_turns", 1)))
        for a in range(u.shape[0]):
            both = np.isfinite(u[a]) & np.isfinite(ur[a])
            peak = np.nanmax(ur[a])
            dev.append(np.max(np.abs(u[a][both] - ur[a][both])) / peak if both.any() else float("nan"))
            infilm = both & (yr < sr["mean_film_thickness_d"])
            diff = (u[a] - ur[a])[infilm]
            noise = np.sqrt(su[a][infilm] ** 2 / n_turns + sur[a][infilm] ** 2 / n_ref)
            flux = flux_weighted_difference(u[a], ur[a], sr["phi"])
            film_dev.append((np.max(np.abs(diff)) / peak, np.sqrt(np.mean(diff ** 2)) / peak,
                             np.max(noise) / peak, flux) if infilm.any() else (np.nan,) * 4)
        film_rows.append((os.path.basename(d.rstrip("/")), film_dev))
        t = s["mean_film_thickness_d"]
        cfg = yaml.safe_load(s["resolved_config"])["dem"]
        # a receiver-derived drum is in summary.json only (the resolved case leaves it out)
        dd = s.get("drum_diameter_m", cfg["drum"].get("diameter")) / cfg["particles"]["diameter"]
        # eq 2 keeps mdot / R: the slice's flux scaled back to D12 (D/d = 100), paper 35.7 g/s
        mdot = s.get("slice_mdot_kg_s")
        flow = f"{1e3 * mdot:.2f} | {1e3 * mdot * 100 / dd:.1f}" if mdot else "- | -"
        rows.append((d, u))
        print(f"| {os.path.basename(d.rstrip('/'))} | {dd:.0f} | {s['free_particles']} | {t:.2f} +- {s['mean_film_thickness_std_d']:.2f} "
              f"| {t - sr['mean_film_thickness_d']:+.2f} | {100*dev[0]:.1f} % | {100*dev[1]:.1f} % | {100*dev[2]:.1f} % "
              f"| {flow} | {s['wall_time_s']:.0f} | {s['cpu_s']:.0f} | {s['particle_steps_per_s']:.3g} |")
    print()
    print("Inside the reference film (wall distance < %.2f d): largest / RMS difference over the peak, "
          "and the largest standard error of the difference over the peak" % sr["mean_film_thickness_d"])
    print()
    print("| run | 45 deg max / RMS / noise | 90 deg | 135 deg | flux-weighted 45 / 90 / 135 deg |")
    print("|---|---|---|---|---|")
    for name, fd in film_rows:
        print(f"| {name} | " + " | ".join(f"{100*m:.1f} % / {100*r:.1f} % / {100*n:.1f} %" for m, r, n, _ in fd)
              + " | " + " / ".join(f"{100*x[3]:.1f} %" for x in fd) + " |")
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
