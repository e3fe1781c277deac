#!/usr/bin/python3
"""Plots of a `centrec thermal` run (docs/outputs.md).

Usage: /usr/bin/python3 apps/plot_thermal.py OUT_DIR
Reads OUT_DIR/thermal.h5 and writes
  OUT_DIR/thermal_T_map.png     steady temperature over (z, eta), with the surface temperature
  OUT_DIR/thermal_keff.png      k_eff per axial section and its bed / radiation / mixing parts
  OUT_DIR/thermal_T_out.png     T_out(t) and the powers over time (transient runs only)
Uses Debian's python3-matplotlib and python3-h5py (hence /usr/bin/python3).
"""
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def units(ds):
    u = ds.attrs.get("units", "")
    return u.decode() if isinstance(u, bytes) else u


def style(ax, xlabel, ylabel):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend()
    ax.grid(alpha=0.3)


def save(fig, out, name):
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=120)
    plt.close(fig)


def temperature_map(f, out):
    z = f["grid/z"][()]
    eta = f["grid/eta"][()]
    T = f["steady/T"][()]
    Ts = f["steady/T_surface"][()]
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(9, 6), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
    Z = np.repeat(z[:, None], eta.shape[1], axis=1)
    pc = ax.pcolormesh(Z, eta * 1e3, T - 273.15, shading="gouraud", cmap="inferno")
    fig.colorbar(pc, ax=ax, label="T (C)")
    ax.set_ylabel("distance from wall eta (mm)")
    ax.set_title("%s: steady film temperature, T_out = %.1f C" % (f.attrs.get("title", ""), f["steady"].attrs["T_out_K"] - 273.15))
    ax2.plot(z, Ts - 273.15, label="surface")
    ax2.plot(z, T[:, 0] - 273.15, label="wall cell")
    style(ax2, "axial position z (%s)" % units(f["grid/z"]), "T (C)")
    save(fig, out, "thermal_T_map.png")


def keff(f, out):
    k = f["steady/keff"]
    z = k["z"][()]
    fig, ax = plt.subplots(figsize=(8, 4))
    for name in ("k_eff", "bed_conduction", "radiation", "mixing"):
        ax.plot(z, k[name][()], label=name)
    ax.set_title("effective wall-normal conductivity of the moving film (series value)")
    style(ax, "z (m)", "W/(m K)")
    save(fig, out, "thermal_keff.png")


def transient(f, out):
    tr = f["transient"]
    t = tr["t"][()]
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    ax.plot(t, tr["T_out"][()] - 273.15, label="T_out (mixing cup)")
    ax.plot(t, tr["T_surface_max"][()] - 273.15, label="max surface T", alpha=0.7)
    style(ax, "", "T (C)")
    for name in ("absorbed", "emitted", "carried", "storage_rate"):
        ax2.plot(t, tr[name][()] / 1e6, label=name)
    style(ax2, "t (s)", "power (MW)")
    save(fig, out, "thermal_T_out.png")


def main(out):
    with h5py.File(os.path.join(out, "thermal.h5"), "r") as f:
        temperature_map(f, out)
        keff(f, out)
        if "transient" in f:
            transient(f, out)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
