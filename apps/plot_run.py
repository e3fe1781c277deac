#!/usr/bin/python3
"""Figures of a coupled `centrec run` output folder (DIR/results.h5, DIR/summary.json):

  fig2_mass_flow.png, fig3_film_thickness.png, fig6_velocity_profiles.png, solid_fraction.png
                        the DEM's figures (apps/plot_dem.py) from its dem.h5 in the DEM cache
  thermal_T_map.png     the steady film temperature field over (z, wall distance)
  losses.png            the receiver's power balance: aperture power -> carried + each loss
  thermal_keff.png      k_eff along z and its parts
  run_film.png          film thickness along z (DEM sections +- std, in d), phi and D profiles
  run_velocity.png      the coupled axial velocity u(eta/d) at a few sections, +- std

The DEM folder comes from --dem, else from summary.json (dem.dir). `centrec run` calls this
script; run it by hand with the system python: /usr/bin/python3 apps/plot_run.py DIR
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_common as pc  # noqa: E402
import plot_dem  # noqa: E402
import plot_thermal  # noqa: E402
from plot_common import plt, save, style  # noqa: E402

import h5py  # noqa: E402
import numpy as np  # noqa: E402


def film(f, out, written):
    fl = f["film"]
    d = fl.attrs["particle_diameter"]
    z, t, L = fl["z"][()], fl["t"][()], fl.attrs["length"]
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.8))
    mapping = pc.text(f["coupling"].attrs.get("film_mapping", "")) if "coupling" in f else ""
    top = float(max(t)) / d
    if "coupling/dem_thickness" in f:
        c = f["coupling"]
        # DEM section centres sit symmetrically in the DEM drum (a slice's one at mid-length),
        # so first + last centre = the DEM drum's length: carried to the receiver's z by L.
        zs = c["dem_section_z"][()]
        td, sd = c["dem_thickness"][()] / d, c["dem_thickness_std"][()] / d
        top = max(top, float(max(td + sd)))
        label = "DEM, eqs 4-7 (paper), +- std over turns"
        if len(zs) == 1:  # a periodic slice: one section, the same film all along the receiver
            ax.axhline(td[0], color="C0", label=label + "; a slice: uniform in z")
            ax.axhspan(td[0] - sd[0], td[0] + sd[0], color="C0", alpha=0.2)
        else:
            ax.errorbar(zs * L / (zs[0] + zs[-1]), td, yerr=sd, fmt="o", ms=3, capsize=2, label=label)
    label = "thermal film" + (" (mapping %s)" % mapping if mapping else "")
    if len(z) == 1:
        ax.axhline(t[0] / d, color="C1", label=label + "; uniform in z")
    else:
        ax.plot(z, t / d, "s-", ms=3, color="C1", label=label)
    ax.set_xlim(0, L)
    ax.set_title("Film thickness on the receiver, L = %.3g m" % L)
    ax.set_ylim(0, 1.15 * top)
    style(ax, "axial position z (m)", "film thickness (d)", legend=False)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), fontsize=8)
    eta = fl["eta"][()] / d
    i = len(z) // 2
    ne = len(eta)
    phi, D = fl["phi"][()].reshape(-1, ne)[i], fl["D"][()].reshape(-1, ne)[i]
    ax2.plot(eta, phi, "o-", ms=3, label="solid fraction phi")
    ax2.axvline(t[i] / d, color="k", ls=":", label="film surface t")
    ax2.set_title("Across the film at z = %.3g m (mid-length)" % z[i])
    style(ax2, "wall distance eta (d)", "solid fraction phi", legend=False)
    ax3 = ax2.twinx()
    ax3.plot(eta, D * 1e6, "s--", ms=3, color="C3", label="dispersion D (right axis)")
    ax3.set_ylabel("dispersion D (mm2/s)", color="C3")
    h2, l2 = ax2.get_legend_handles_labels()
    h3, l3 = ax3.get_legend_handles_labels()
    ax2.legend(h2 + h3, l2 + l3, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=3, fontsize=8)
    save(fig, out, "run_film.png", written)


def velocity(f, out, written):
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
    ax.set_title("Coupled axial velocity on the receiver (turn average, %.4g kg/s)" % fl.attrs["mdot"])
    style(ax, "wall distance eta (d)", "axial velocity u (m/s)")
    save(fig, out, "run_velocity.png", written)


def losses(summary, out, written):
    """Where the aperture power goes (summary.json `receiver`), as a horizontal bar chart."""
    r = summary.get("receiver")
    if not r or not r.get("aperture_power_W"):
        return
    parts = [("carried by the particles", r["carried_W"]),
             ("reflected", r["reflected_loss_W"]),
             ("emitted (thermal radiation)", r["emitted_loss_W"]),
             ("convection", r["convective_loss_W"]),
             ("through the wall", r["wall_loss_W"])]
    for key, name in (("storage_rate_W", "stored (not steady)"), ("inlet_conduction_W", "inlet conduction"),
                      ("balance_residual_W", "balance residual")):
        if abs(r.get(key, 0.0)) > 1e-3 * r["aperture_power_W"]:
            parts.append((name, r[key]))
    P = r["aperture_power_W"]
    names = [n for n, _ in parts][::-1]
    vals = [v / 1e3 for _, v in parts][::-1]
    fig, ax = plt.subplots(figsize=(8, 0.45 * len(parts) + 1.6))
    bars = ax.barh(names, vals, color=["C2" if n.startswith("carried") else "C3" for n in names])
    for b, v in zip(bars, vals):
        ax.text(b.get_width(), b.get_y() + b.get_height() / 2, "  %.3g kW (%.1f %%)" % (v, 100 * v * 1e3 / P),
                va="center", fontsize=9)
    ax.set_xlim(0, 1.3 * max(vals))
    ax.set_title("Receiver power balance: %.3g kW through the aperture, efficiency %.1f %%"
                 % (P / 1e3, 100 * r["efficiency"]))
    style(ax, "power (kW)", "", legend=False)
    save(fig, out, "losses.png", written)


def dem_folder(args, summary):
    """--dem, else summary.json's dem.dir (relative to where the run was started), else the
    default cache beside the run folder (DIR/../dem-cache/<key>)."""
    if args.dem:
        return args.dem
    d = summary.get("dem", {}).get("dir")
    if not d:
        return None  # the film did not come from a DEM
    for cand in (d, os.path.join(args.folder, os.pardir, "dem-cache", os.path.basename(d))):
        if os.path.isfile(os.path.join(cand, "dem.h5")):
            return cand
    print(f"no dem.h5 in {d} (summary.json dem.dir): Figs 2, 3 and 6 not drawn; give --dem DEM_DIR")
    return None


def main(argv=None):
    p = pc.parser(__doc__, "output folder of `centrec run` (holds results.h5 and summary.json)")
    p.add_argument("--dem", metavar="DEM_DIR", help="the DEM's output folder (holds dem.h5); default: summary.json dem.dir")
    args = p.parse_args(argv)
    path = pc.input_file(p, args.folder, "results.h5", "`centrec run`")
    with open(pc.input_file(p, args.folder, "summary.json", "`centrec run`")) as fh:
        summary = json.load(fh)
    dem = dem_folder(args, summary)
    dem_h5 = pc.input_file(p, dem, "dem.h5", "`centrec dem`") if dem else None
    out = pc.out_dir(args)
    written = plot_dem.plot_dem_h5(dem_h5, out) if dem_h5 else []
    with h5py.File(path, "r") as f:
        plot_thermal.temperature_map(f, out, written)
        losses(summary, out, written)
        plot_thermal.keff(f, out, written)
        film(f, out, written)
        velocity(f, out, written)
    pc.report(written)


if __name__ == "__main__":
    main()
