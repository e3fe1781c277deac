#!/usr/bin/python3
"""The scale-down's threshold on fed drums, thermally (docs/validity_threshold.md "Rechecked on
fed drums"): coupled runs of the same receiver on films from drums of different D/d, compared
along the flow.

usage (from the repository root):
  /usr/bin/python3 docs/studies/drum_dd80_dd100_thermal.py OUT.png LABEL=RUN_DIR [LABEL=RUN_DIR ...]

Each RUN_DIR is a `centrec run` folder (summary.json, along_z.csv) of the same receiver. Prints
each run's T_out, efficiency, k_eff with its parts and the mapped film's thickness, then the
largest differences against the first run along z (mixing-cup and surface temperature, film
thickness in d); draws the mixing-cup and surface temperature and the mapped film along z / L.
"""
import json
import sys

import numpy as np
import pandas as pd
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(run):
    s = json.load(open(run + "/summary.json"))
    a = pd.read_csv(run + "/along_z.csv", comment="#")
    return s, a


def main(out, specs):
    runs = []
    for spec in specs:
        label, run = spec.split("=", 1)
        runs.append((label, *load(run)))
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    ref = None
    for n, (label, s, a) in enumerate(runs):
        c = f"C{n}"
        d = s["film"]["mean_thickness_m"] / s["film"]["mean_thickness_d"]  # the particle diameter
        k = s["k_eff"]["film_mean"]
        print(f"{label}: T_out {s['T_out_K']:.2f} K, efficiency {s['efficiency']:.4f}, k_eff {k['k_eff']:.3f} = "
              f"{k['bed_conduction']:.3f} + {k['radiation']:.3f} + {k['mixing']:.3f} W/(m K), "
              f"surface max {s['T_surface_max_K']:.1f} K, mapped film {s['film']['min_thickness_d']:.2f}-"
              f"{s['film']['max_thickness_d']:.2f} d")
        zl = a["z_m"] / a["z_m"].max()
        ax[0].plot(zl, a["T_mixing_cup_K"], color=c, label=f"{label}, mixing cup")
        ax[0].plot(zl, a["T_surface_K"], "--", color=c, label=f"{label}, surface")
        ax[1].plot(zl, a["thickness_m"] / d, color=c, label=label)
        if ref is None:
            ref = (label, a, d)
        else:
            for col, unit, scale in (("T_mixing_cup_K", "K", 1.0), ("T_surface_K", "K", 1.0), ("thickness_m", "d", 1 / d)):
                diff = (a[col].values - ref[1][col].values) * scale
                i = int(np.argmax(np.abs(diff)))
                print(f"  {label} - {ref[0]}: {col} largest {diff[i]:+.2f} {unit} at z/L {zl[i]:.2f}")
    ax[0].set_xlabel("z / L")
    ax[0].set_ylabel("K")
    ax[0].set_title("temperature along the flow")
    ax[0].legend(fontsize=8)
    ax[1].set_xlabel("z / L")
    ax[1].set_ylabel("mapped film thickness (d)")
    ax[1].set_title("the thermal model's film")
    ax[1].legend(fontsize=8)
    for a_ in ax:
        a_.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
