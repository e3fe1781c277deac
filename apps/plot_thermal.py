#!/usr/bin/python3
"""Figures of a `centrec thermal` output folder (DIR/thermal.h5, docs/outputs.md):

  thermal_T_map.png     steady film temperature over (z, wall distance), surface and wall temperature
  thermal_keff.png      k_eff per axial section and its bed / radiation / mixing parts
  thermal_T_out.png     T_out(t) and the powers over time (transient runs only)

Run with the system python: /usr/bin/python3 apps/plot_thermal.py DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_common as pc  # noqa: E402
from plot_common import plt, save, style  # noqa: E402,F401

import h5py  # noqa: E402
import numpy as np  # noqa: E402


def units(ds):
    u = ds.attrs.get("units", "")
    return u.decode() if isinstance(u, bytes) else u


def temperature_map(f, out, written=None):
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
    save(fig, out, "thermal_T_map.png", written)


def keff(f, out, written=None):
    k = f["steady/keff"]
    z = k["z"][()]
    fig, ax = plt.subplots(figsize=(8, 4))
    top = 0.0
    for name, label, lw in (("k_eff", "k_eff (series value)", 2.2), ("bed_conduction", "bed conduction", 1.3),
                            ("radiation", "radiation", 1.3), ("mixing", "mixing", 1.3)):
        ax.plot(z, k[name][()], label=label, lw=lw)
        top = max(top, float(np.nanmax(k[name][()])))
    ax.set_ylim(0, 1.3 * top)
    ax.set_title("Effective wall-normal conductivity of the moving film and its parts")
    style(ax, "axial position z (m)", "conductivity (W/(m K))", legend=False)
    ax.legend(loc="upper center", ncol=4)
    save(fig, out, "thermal_keff.png", written)


def transient(f, out, written=None):
    tr = f["transient"]
    t = tr["t"][()]
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    ax.plot(t, tr["T_out"][()] - 273.15, label="T_out (mixing cup)")
    ax.plot(t, tr["T_surface_max"][()] - 273.15, label="max surface T", alpha=0.7)
    style(ax, "", "T (C)")
    for name in ("absorbed", "emitted", "carried", "storage_rate"):
        ax2.plot(t, tr[name][()] / 1e6, label=name)
    style(ax2, "t (s)", "power (MW)")
    save(fig, out, "thermal_T_out.png", written)


def main(argv=None):
    p = pc.parser(__doc__, "output folder of `centrec thermal` (holds thermal.h5)")
    args = p.parse_args(argv)
    path = pc.input_file(p, args.folder, "thermal.h5", "`centrec thermal`")
    out = pc.out_dir(args)
    written = []
    with h5py.File(path, "r") as f:
        temperature_map(f, out, written)
        keff(f, out, written)
        if "transient" in f:
            transient(f, out, written)
    pc.report(written)


if __name__ == "__main__":
    main()
