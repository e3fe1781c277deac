#!/usr/bin/python3
"""PNG plots of a DEM run's dem.h5, like the paper's figures.

usage: /usr/bin/python3 apps/plot_dem.py OUT_DIR   (reads OUT_DIR/dem.h5, writes OUT_DIR/*.png)

  mass_flow.png         outlet (and inlet) mass flow vs time        (paper Fig 2)
  film_thickness.png    eqs 4-7 thickness along z/L, +- std over turns (paper Fig 3)
  velocity_profiles.png axial velocity vs wall distance, nine arcs    (paper Fig 6)
  solid_fraction.png    solid fraction vs wall distance by zone
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def rate(t, cum, window):
    """Mass flow over a trailing window (s) from a cumulative mass series."""
    out = np.full_like(t, np.nan)
    j = 0
    for i in range(len(t)):
        while t[i] - t[j] > window:
            j += 1
        if t[i] > t[j]:
            out[i] = (cum[i] - cum[j]) / (t[i] - t[j])
    return out


def main(out_dir):
    f = h5py.File(f"{out_dir}/dem.h5", "r")
    d = f.attrs["particle_diameter_m"]
    turn = f.attrs["turn_period_s"]
    mf = f["mass_flow"]
    t = mf["time"][:]
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(t, 1e3 * rate(t, mf["out"][:], turn), label="outlet (1-turn average)")
    ax.plot(t, 1e3 * rate(t, mf["fed"][:], turn), label="inlet (1-turn average)", ls="--")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("mass flow [g/s]")
    ax.legend()
    ax.set_title("Outlet mass flow (cf. paper Fig 2)")
    fig.tight_layout()
    fig.savefig(f"{out_dir}/mass_flow.png", dpi=120)

    if "film" not in f:
        print("no /film group (run with sampling.turns > 0): only mass_flow.png written")
        return
    fl = f["film"]
    z = fl["section_z"][:]
    length = z[-1] + z[0]  # equal sections from 0 to L
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.errorbar(z / length, fl["thickness_mean"][:] / d, yerr=fl["thickness_std"][:] / d, marker="o", capsize=3)
    ax.set_xlabel("z / L  (0 inlet, 1 outlet)")
    ax.set_ylabel("film thickness [d]")
    ax.set_title(f"Tangentially averaged film thickness, {fl.attrs['sampled_turns']:.0f} turns (cf. Fig 3)")
    fig.tight_layout()
    fig.savefig(f"{out_dir}/film_thickness.png", dpi=120)

    w = fl["wall_distance_d"][:]
    um, us = fl["axial_velocity_mean"][:], fl["axial_velocity_std"][:]
    th, zl = np.degrees(fl["arc_theta"][:]), fl["arc_z_over_length"][:]
    n = um.shape[0]
    cols = 3
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(10, 3 * rows), squeeze=False, sharex=True)
    for k in range(n):
        ax = axes[k // cols][k % cols]
        ax.errorbar(w, um[k], yerr=us[k], marker="o", ms=3, capsize=2)
        ax.set_title(f"theta {th[k]:.0f} deg, z/L {zl[k]:.1f}", fontsize=9)
        ax.axvline(1.0, color="grey", lw=0.5)
        ax.set_xlabel("wall distance [d]")
        ax.set_ylabel("axial velocity [m/s]")
    fig.suptitle("Axial velocity profiles (cf. paper Fig 6)")
    fig.tight_layout()
    fig.savefig(f"{out_dir}/velocity_profiles.png", dpi=120)

    sm, ss = fl["solid_fraction_mean"][:], fl["solid_fraction_std"][:]
    fig, ax = plt.subplots(figsize=(6, 3.5))
    for k, name in enumerate(["stationary zone", "moving zone"]):
        ax.errorbar(w, sm[k], yerr=ss[k], marker="o", ms=3, capsize=2, label=name)
    ax.set_xlabel("wall distance [d]")
    ax.set_ylabel("solid fraction")
    ax.legend()
    fig.tight_layout()
    fig.savefig(f"{out_dir}/solid_fraction.png", dpi=120)
    print(f"wrote {out_dir}/{{mass_flow,film_thickness,velocity_profiles,solid_fraction}}.png")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
