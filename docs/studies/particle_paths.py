#!/usr/bin/python3
"""Figures of `centrec paths` (docs/particle_paths.md): the residence-time distribution of a
fed drum's particles and the outlet temperatures of the particles heated along their paths.

usage (from the repository root):
  /usr/bin/python3 docs/studies/particle_paths.py PATHS_DIR [OUT.png]

PATHS_DIR holds summary.json and paths.csv of `centrec paths`. Left: the weighted histogram
of the residence times in the receiver (each path weighted W / (W - tau) for the window),
with the mean, holdup / feed and the continuum film's mean residence scaled to the receiver.
Right: the particles' outlet temperatures (relaxing towards the film, and reading the film
at every point, tau = 0), with the continuum's mixing-cup T_out. Default OUT:
PATHS_DIR/paths.png.
"""
import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    src = argv[1]
    out = argv[2] if len(argv) > 2 else src + "/paths.png"
    with open(src + "/summary.json") as f:
        s = json.load(f)
    with open(src + "/paths.csv") as f:
        rows = list(csv.DictReader(f))
    tau = np.array([float(r["residence_receiver_s"]) for r in rows])
    w = np.array([float(r["weight"]) for r in rows])
    T = np.array([float(r["T_out_K"]) for r in rows])
    T0 = np.array([float(r["T_out_tau0_K"]) for r in rows])
    scale = s["scale_receiver_over_drum"]

    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2), dpi=150)
    a.hist(tau, bins=60, weights=w / w.sum(), color="#4477aa")
    a.axvline(s["residence_drum_s"]["mean"] * scale, color="k", label="mean of the paths")
    a.axvline(s["mean_residence_little_s"] * scale, color="#cc6677", ls="--", label="holdup / feed")
    a.axvline(s["mean_residence_film_implies_receiver_s"], color="#228833", ls=":", label="continuum film")
    a.set_xlabel("residence time in the receiver (s)")
    a.set_ylabel("share of the feed")
    a.set_title("residence times (%d paths, window %.1f s in the drum)" % (len(rows), s["window_s"]), fontsize=10)
    a.legend(fontsize=8)
    lo, hi = min(T.min(), T0.min()), max(T.max(), T0.max())
    bins = np.linspace(lo, hi, 60)
    b.hist(T0, bins=bins, weights=w / w.sum(), color="#bbbbbb", label="film read at every point (tau = 0)")
    b.hist(T, bins=bins, weights=w / w.sum(), histtype="step", lw=1.5, color="#ee6677", label="relaxing (tau ~ 1 s)")
    b.axvline(s["T_out_mixing_cup_K"], color="k", label="continuum mixing cup %.1f K" % s["T_out_mixing_cup_K"])
    b.set_xlabel("particle outlet temperature (K)")
    b.set_ylabel("share of the feed")
    b.set_title("outlet temperatures: mean %.1f K, 5-95 %% %.0f-%.0f K" % (
        s["T_out_paths_K"]["mean"], s["T_out_paths_K"]["q05"], s["T_out_paths_K"]["q95"]), fontsize=10)
    b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out)
    print("wrote", out)


if __name__ == "__main__":
    main(sys.argv)
