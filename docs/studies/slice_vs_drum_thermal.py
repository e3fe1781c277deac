#!/usr/bin/python3
"""Slice against drum, thermally (docs/slice_vs_drum_thermal.md): the coupled runs of the
same receiver on a periodic slice's film and on a fed drum's film along z, side by side.

usage (from the repository root):
  /usr/bin/python3 docs/studies/slice_vs_drum_thermal.py OUT.png LABEL=RUN_DIR [LABEL=RUN_DIR ...]

Each RUN_DIR is a `centrec run` folder (summary.json, results.h5). Prints one row per run:
T_out, efficiency, k_eff and its parts, the peak surface temperature, the film's thickness
range (the mean residence the film implies is `centrec paths`'s). Draws, along the receiver (z / L): the mixing-cup temperature of the stream leaving each
thermal column (results.h5 /steady/T_mixing_cup), the film's surface temperature and its
thickness.
"""
import json
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(run):
    with open(run + "/summary.json") as f:
        s = json.load(f)
    with h5py.File(run + "/results.h5", "r") as h:
        g = h["grid"]
        z, t = g["z"][()], g["thickness"][()]
        cup, Ts = h["steady/T_mixing_cup"][()], h["steady/T_surface"][()]
    return dict(s=s, z=z / s["film"]["length_m"], t=t, cup=cup, Ts=Ts)


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    out = argv[1]
    runs = []
    for a in argv[2:]:
        label, run = a.split("=", 1)
        runs.append((label, load(run)))
    d = None
    print("| film | T_out (K) | efficiency | k_eff (W/(m K)) = bed + radiation + mixing | T_surface max (K) | "
          "thickness (d) |")
    print("|---|---|---|---|---|---|")
    for label, r in runs:
        s = r["s"]
        k = s["k_eff"]["film_mean"]
        d = s["film"]["mean_thickness_m"] / s["film"]["mean_thickness_d"]
        print("| %s | %.2f | %.4f | %.3f = %.3f + %.3f + %.3f | %.1f | %.2f-%.2f |" % (
            label, s["T_out_K"], s["efficiency"], k["k_eff"], k["bed_conduction"], k["radiation"], k["mixing"],
            s["T_surface_max_K"], s["film"]["min_thickness_d"], s["film"]["max_thickness_d"]))

    fig, (a, b, c) = plt.subplots(1, 3, figsize=(13, 4.0), dpi=150)
    for label, r in runs:
        a.plot(r["z"], r["cup"], label=label)
        b.plot(r["z"], r["Ts"], label=label)
        c.plot(r["z"], r["t"] / d, label=label)
    a.set_ylabel("mixing-cup temperature (K)")
    b.set_ylabel("film surface temperature (K)")
    c.set_ylabel("film thickness (d)")
    for ax in (a, b, c):
        ax.set_xlabel("z / L (feed end to outlet)")
        ax.grid(alpha=0.3)
    a.legend(fontsize=8)
    fig.suptitle("the same receiver on a slice's film and on a fed drum's film along z", fontsize=10)
    fig.tight_layout()
    fig.savefig(out)
    print("wrote", out)


if __name__ == "__main__":
    main(sys.argv)
