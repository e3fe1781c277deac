#!/usr/bin/python3
"""The paper's DEM figures from a `centrec dem` output folder (DIR/dem.h5):

  fig2_mass_flow.png          outlet and inlet mass flow vs time (a slice: its axial flow), one-turn averages  (paper Fig 2)
  fig3_film_thickness.png     eqs 4-7 film thickness along z/L, +- std over snapshots (paper Fig 3)
  fig6_velocity_profiles.png  axial velocity vs wall distance at the nine arcs         (paper Fig 6)
  solid_fraction.png          solid fraction vs wall distance, stationary and moving zone

Figs 3 and 6 need sampled turns (dem.sampling.turns > 0). `centrec dem` and `centrec run`
call this script; run it by hand with the system python: /usr/bin/python3 apps/plot_dem.py DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_common as pc  # noqa: E402
from plot_common import plt  # noqa: E402

import h5py  # noqa: E402
import numpy as np  # noqa: E402


def rate(t, cum, window):
    """Mass flow over a trailing window (s) from a cumulative mass series."""
    out = np.full_like(t, np.nan)
    j = 0
    for i in range(len(t)):
        while t[i] - t[j] > window:
            j += 1
        if t[i] - t[j] > 0.5 * window:
            out[i] = (cum[i] - cum[j]) / (t[i] - t[j])
    return out


def cumulative(t, q):
    """Running integral of a rate q(t) (trapezoid), so rate() can average it like the masses."""
    return np.concatenate(([0.0], np.cumsum(0.5 * (q[1:] + q[:-1]) * np.diff(t))))


def sampling_window(f):
    times = [g.attrs["time"] for g in f["snapshots"].values()] if "snapshots" in f else []
    return (min(times), max(times)) if len(times) > 1 else None


def fig2_mass_flow(f, out, written):
    turn = float(f.attrs["turn_period_s"])
    mf = f["mass_flow"]
    t = mf["time"][()]
    fig, ax = plt.subplots(figsize=(7, 4))
    axial = mf["slice_axial_flow"][()] if "slice_axial_flow" in mf else np.zeros_like(t)
    if np.any(axial != 0.0) and not np.any(mf["out"][()] != 0.0):
        # A periodic slice has no outlet: its axial flow (an instantaneous rate), turn-averaged.
        ax.plot(t, 1e3 * rate(t, cumulative(t, axial), turn), lw=1.8, label="slice axial flow")
    else:
        ax.plot(t, 1e3 * rate(t, mf["out"][()], turn), lw=1.8, label="outlet")
        ax.plot(t, 1e3 * rate(t, mf["fed"][()], turn), lw=1.2, ls="--", label="inlet (feeder)")
    window = sampling_window(f)
    if window:
        ax.axvspan(*window, color="C2", alpha=0.12, label="sampled turns")
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)
    ax.set_title("Mass flow, trailing one-turn average (paper Fig 2)")
    pc.style(ax, "time (s)", "mass flow (g/s)")
    pc.save(fig, out, "fig2_mass_flow.png", written)


def fig3_thickness(f, out, written):
    d = float(f.attrs["particle_diameter_m"])
    fl = f["film"]
    z = fl["section_z"][()]
    length = z[-1] + z[0]  # equal sections from 0 to L
    fig, ax = plt.subplots(figsize=(7, 4))
    t, s = fl["thickness_mean"][()] / d, fl["thickness_std"][()] / d
    label = "tangential average, +- std over snapshots"
    if len(z) == 1:  # a periodic slice: one section, no axial profile to show
        ax.axhline(t[0], color="C0", label=label + "\n(periodic slice: one section, uniform along z)")
        ax.axhspan(t[0] - s[0], t[0] + s[0], color="C0", alpha=0.2)
    else:
        ax.errorbar(z / length, t, yerr=s, marker="o", ms=4, capsize=3, label=label)
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1.35 * float(max(t + s)))
    ax.set_title("Film thickness along the drum, %d sampled turns (paper Fig 3)" % round(float(fl.attrs["sampled_turns"])))
    pc.style(ax, "z / L   (0 = inlet / back plate, 1 = outlet)", "film thickness (particle diameters)")
    pc.save(fig, out, "fig3_film_thickness.png", written)


def fig6_profiles(f, out, written):
    fl = f["film"]
    w = fl["wall_distance_d"][()]
    um, us = fl["axial_velocity_mean"][()], fl["axial_velocity_std"][()]
    th, zl = np.degrees(fl["arc_theta"][()]), fl["arc_z_over_length"][()]
    n = um.shape[0]
    cols = 3
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(10, 2.8 * rows + 0.6), squeeze=False, sharex=True, sharey=True)
    for k in range(n):
        ax = axes[k // cols][k % cols]
        ok = np.isfinite(um[k])
        ax.errorbar(w[ok], um[k][ok], yerr=us[k][ok], marker="o", ms=3, capsize=2)
        ax.axhline(0.0, color="grey", lw=0.5)
        ax.set_title("theta = %.0f deg, z/L = %.1f" % (th[k], zl[k]), fontsize=9)
        ax.grid(alpha=0.3)
        if k // cols == rows - 1:
            ax.set_xlabel("wall distance (d)")
        if k % cols == 0:
            ax.set_ylabel("axial velocity (m/s)")
    for k in range(n, rows * cols):
        axes[k // cols][k % cols].set_visible(False)
    one_section = len(set(np.round(zl, 6))) == 1 and n < 9
    fig.suptitle("Axial velocity profiles, mean +- std over turns (paper Fig 6%s)"
                 % (": a periodic slice has one axial section, so its three arcs" if one_section else ""))
    pc.save(fig, out, "fig6_velocity_profiles.png", written)


def solid_fraction(f, out, written):
    fl = f["film"]
    w = fl["wall_distance_d"][()]
    sm, ss = fl["solid_fraction_mean"][()], fl["solid_fraction_std"][()]
    fig, ax = plt.subplots(figsize=(7, 4))
    empty = []
    for k, name in enumerate(["stationary zone", "moving zone"]):
        ok = np.isfinite(sm[k])
        if ok.any():
            ax.errorbar(w[ok], sm[k][ok], yerr=ss[k][ok], marker="o", ms=3, capsize=2, color="C%d" % k, label=name)
        else:
            empty.append(name)
    ax.set_ylim(0, 0.75)
    ax.set_title("Solid fraction across the film" + ("" if not empty else " (no %s detected)" % " or ".join(empty)))
    pc.style(ax, "wall distance (d)", "solid fraction")
    pc.save(fig, out, "solid_fraction.png", written)


def plot_dem_h5(path, out):
    """Draws every figure the file supports into out; returns the paths written."""
    written = []
    with h5py.File(path, "r") as f:
        fig2_mass_flow(f, out, written)
        if "film" in f:
            fig3_thickness(f, out, written)
            fig6_profiles(f, out, written)
            solid_fraction(f, out, written)
        else:
            print(f"{path}: no /film group (dem.sampling.turns = 0): Figs 3 and 6 not drawn")
    return written


def main(argv=None):
    p = pc.parser(__doc__, "output folder of `centrec dem` (holds dem.h5)")
    args = p.parse_args(argv)
    path = pc.input_file(p, args.folder, "dem.h5", "`centrec dem`")
    pc.report(plot_dem_h5(path, pc.out_dir(args)))


if __name__ == "__main__":
    main()
