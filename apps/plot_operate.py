#!/usr/bin/python3
"""The operating map of a `centrec operate` output folder (DIR/operate.json, operate_map.csv).

  operate_map.png   outlet temperature and efficiency contours over speed x mass flow
                    (the case's thermal model on the film surrogate), the map's points
                    (usable: dots; not usable: crosses, outside the stable window: shaded),
                    the target's contour, the mass flow found at each speed tried and the
                    operating point (star)
  operate_transient.png  with --transient: flux factor, mass flow, outlet and peak surface
                    temperature against time, the mass flow held, the PI on T_out and the PI
                    with the flux fed forward (the +-15 K band around the target shaded)

`centrec operate` calls this script; by hand: /usr/bin/python3 apps/plot_operate.py DIR
"""
import csv
import json
import os
import sys

import numpy as np
from matplotlib.patches import Rectangle

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_common as pc  # noqa: E402
from plot_common import plt  # noqa: E402


def hatch_outside_window(ax, points):
    """Hatches every cell of the map's grid that is not inside the window (a cell is inside
    when its four corner points are usable: apps/runs/operating_map.hpp), drawn from the map's
    own points so that a window narrower than the figure's grid is shown as it is."""
    usable = {(q["speed_rpm"], q["mass_flow_kg_s"]): q["usable"] for q in points}
    vs = sorted({q["speed_rpm"] for q in points})
    ms = sorted({q["mass_flow_kg_s"] for q in points})
    for i in range(len(vs) - 1):
        for j in range(len(ms) - 1):
            corners = [(vs[a], ms[b]) for a in (i, i + 1) for b in (j, j + 1)]
            if not all(usable.get(c, False) for c in corners):
                ax.add_patch(Rectangle((vs[i], ms[j]), vs[i + 1] - vs[i], ms[j + 1] - ms[j], fill=False,
                                       hatch="//", lw=0, zorder=3))


def main(argv=None):
    p = pc.parser(__doc__, "output folder of `centrec operate` (holds operate.json)")
    args = p.parse_args(argv)
    path = pc.input_file(p, args.folder, "operate.json", "`centrec operate`")
    grid_path = pc.input_file(p, args.folder, "operate_map.csv", "`centrec operate`")
    out = pc.out_dir(args)
    with open(path) as fh:
        op = json.load(fh)
    with open(grid_path) as fh:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(fh)]
    speeds = sorted({r["speed_rpm"] for r in rows})
    flows = sorted({r["mass_flow_kg_s"] for r in rows})
    cell = {(r["speed_rpm"], r["mass_flow_kg_s"]): r for r in rows}

    def field(name):  # nan where the surrogate had no film (off the window): left blank
        return np.ma.masked_invalid([[cell[(v, m)][name] for v in speeds] for m in flows])

    target = op["target_T_out_K"]
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    panels = [("outlet temperature (K)", "T_out_K", "inferno"), ("thermal efficiency", "efficiency", "viridis")]
    for ax, (title, name, cmap) in zip(axes, panels):
        cs = ax.contourf(speeds, flows, field(name), levels=14, cmap=cmap)
        fig.colorbar(cs, ax=ax, label=title)
        tc = ax.contour(speeds, flows, field("T_out_K"), levels=[target], colors="w", linewidths=2)
        ax.clabel(tc, fmt={target: "target %.0f K" % target}, fontsize=8)
        hatch_outside_window(ax, op["map_points"])
        good = [q for q in op["map_points"] if q["usable"]]
        bad = [q for q in op["map_points"] if not q["usable"]]
        ax.plot([q["speed_rpm"] for q in good], [q["mass_flow_kg_s"] for q in good], "o", color="c",
                mec="k", label="map point, usable", clip_on=False, zorder=5)
        if bad:
            ax.plot([q["speed_rpm"] for q in bad], [q["mass_flow_kg_s"] for q in bad], "x", color="r", ms=9,
                    mew=2, label="map point, not usable", clip_on=False, zorder=5)
        found = [c for c in op["candidates"] if c["found"]]
        ax.plot([c["speed_rpm"] for c in found], [c["mass_flow_kg_s"] for c in found], "s", color="w", mec="k",
                ms=5, label="mass flow for the target, per speed tried", clip_on=False, zorder=5)
        if op.get("operating_point"):
            b = op["operating_point"]
            ax.plot(b["speed_rpm"], b["mass_flow_kg_s"], "*", color="gold", mec="k", ms=16,
                    label="operating point (%.2f rpm, %.4f kg/s)" % (b["speed_rpm"], b["mass_flow_kg_s"]), clip_on=False,
                    zorder=6)
        if op.get("checked_operating_point"):
            k = op["checked_operating_point"]
            ax.plot(k["speed_rpm"], k["mass_flow_kg_s"], "D", color="lime", mec="k", ms=8, zorder=7,
                    label="checked by %d full run(s): %.2f K" % (k["full_runs"], k["T_out_K"]), clip_on=False)
        ax.set_yscale("log")
        ax.set_title(title + " (hatched: outside the stable window)", fontsize=9)
        pc.style(ax, "speed (rpm)", "receiver mass flow (kg/s)", legend=False)
    axes[0].legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, fontsize=8)
    if op.get("map_scaling"):
        sc = op["map_scaling"]
        fig.suptitle("the map of another receiver of the same scaled film (%s), read as this one's by eqs 1-2: "
                     "speeds x %.4g, mass flows x %.4g" % (op["map"], sc["speed"], sc["mass_flow"]), fontsize=9)
    written = []
    pc.save(fig, out, "operate_map.png", written)
    transient = os.path.join(args.folder, "operate_transient.csv")
    if os.path.isfile(transient):
        plot_transient(op, transient, out, written)
    pc.report(written)


def plot_transient(op, path, out, written):
    with open(path) as fh:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(fh)]
    t = [r["t_s"] for r in rows]
    target = op["target_T_out_K"]
    modes = [("fixed", "mass flow held", "0.5"), ("pi", "PI on T_out", "C0"),
             ("feedforward", "PI + flux feedforward", "C3")]
    fig, axes = plt.subplots(4, 1, figsize=(9, 10), sharex=True)
    axes[0].plot(t, [r["flux_factor"] for r in rows], "k-")
    pc.style(axes[0], "", "flux factor", legend=False)
    for key, label, color in modes:
        axes[1].plot(t, [r[key + "_mass_flow_kg_s"] for r in rows], color=color, label=label)
        axes[2].plot(t, [r[key + "_T_out_K"] for r in rows], color=color, label=label)
        axes[3].plot(t, [r[key + "_T_surface_max_K"] for r in rows], color=color, label=label)
    axes[2].axhspan(target - 15.0, target + 15.0, color="g", alpha=0.15, label="target +-15 K")
    pc.style(axes[1], "", "mass flow (kg/s)", legend=False)
    pc.style(axes[2], "", "outlet T (K)")
    pc.style(axes[3], "time (s)", "peak surface T (K)", legend=False)
    tr = op.get("transient", {})
    axes[0].set_title("%s at %.2f rpm; film response %.2f s%s, turndown %.2f; %s" % (
        os.path.basename(tr.get("flux_file", "")), op["operating_point"]["speed_rpm"], tr.get("film_response_s", 0),
        " (%s)" % tr["film_response_source"] if "film_response_source" in tr else "", tr.get("turndown", 0),
        "the film follows the surrogate" if tr.get("film_follows_surrogate") else "the film's geometry held"),
        fontsize=9)
    pc.save(fig, out, "operate_transient.png", written)


if __name__ == "__main__":
    main()
