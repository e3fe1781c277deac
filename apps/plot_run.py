#!/usr/bin/python3
"""Plots of a coupled `centrec run`.

Usage: /usr/bin/python3 apps/plot_run.py OUT_DIR
Reads OUT_DIR/results.h5 and writes
  OUT_DIR/run_film.png        film thickness along z (DEM sections with their std over turns,
                              in d, on the receiver's z) and the solid fraction / dispersion profiles
  OUT_DIR/run_velocity.png    the coupled axial velocity u(eta/d) at a few sections, +- std
  OUT_DIR/thermal_T_map.png   steady temperature over (z, eta)   (apps/plot_thermal.py)
  OUT_DIR/thermal_keff.png    k_eff along z and its parts          (apps/plot_thermal.py)
Uses Debian's python3-matplotlib and python3-h5py (hence /usr/bin/python3).
"""
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_thermal  # noqa: E402
from plot_thermal import plt, save, style  # noqa: E402


def film(f, out):
    fl = f["film"]
    d = fl.attrs["particle_diameter"]
    z, t, L = fl["z"][()], fl["t"][()], fl.attrs["length"]
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4))
    if "coupling/dem_thickness" in f:
        c = f["coupling"]
        ax.errorbar(z, c["dem_thickness"][()] / d, yerr=c["dem_thickness_std"][()] / d, fmt="o", ms=3,
                    capsize=2, label="DEM sections (eqs 4-7), +- std over turns")
    else:
        ax.plot(z, t / d, "o-", ms=3, label="film thickness")
    ax.set_title("film thickness, L = %.3g m" % L)
    style(ax, "z (m)", "t / d")
    eta = fl["eta"][()] / d
    i = len(z) // 2
    ne = len(eta)
    phi, D = fl["phi"][()].reshape(-1, ne)[i], fl["D"][()].reshape(-1, ne)[i]
    ax2.plot(eta, phi, "o-", ms=3, label="solid fraction phi")
    ax2.axvline(t[i] / d, color="k", ls=":", label="film surface t")
    style(ax2, "wall distance eta / d", "phi")
    ax3 = ax2.twinx()
    ax3.plot(eta, D * 1e6, "s--", ms=3, color="C3", label="dispersion D")
    ax3.set_ylabel("D (mm2/s)", color="C3")
    save(fig, out, "run_film.png")


def velocity(f, out):
    fl = f["film"]
    d = fl.attrs["particle_diameter"]
    z, t = fl["z"][()], fl["t"][()]
    eta = fl["eta"][()] / d
    ne = len(eta)
    u = fl["u"][()].reshape(-1, ne)
    us = fl["u_std"][()].reshape(-1, ne) if "u_std" in fl else np.zeros_like(u)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for i in sorted({0, len(z) // 4, len(z) // 2, 3 * len(z) // 4, len(z) - 1}):
        m = eta <= t[i] / d + 1e-9
        ax.plot(eta[m], u[i, m], "o-", ms=3, label="z = %.3g m" % z[i])
        ax.fill_between(eta[m], u[i, m] - us[i, m], u[i, m] + us[i, m], alpha=0.15)
    ax.set_title("coupled axial velocity (turn average, mass flux %.4g kg/s)" % fl.attrs["mdot"])
    style(ax, "wall distance eta / d", "u (m/s)")
    save(fig, out, "run_velocity.png")


def main(out):
    with h5py.File(os.path.join(out, "results.h5"), "r") as f:
        film(f, out)
        velocity(f, out)
        plot_thermal.temperature_map(f, out)
        plot_thermal.keff(f, out)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
