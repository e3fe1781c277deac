#!/usr/bin/python3
"""Charts of a `centrec sweep` output folder (DIR/sweep.json): the operating map.

  sweep_map.png         outlet temperature, efficiency, k_eff and film thickness
                        against mass flow, one line per rotational speed
  sweep_keff_parts.png  k_eff split into bed conduction, radiation and mixing per point

Points whose DEM had not reached steady flow over the last window (`dem_flow` in sweep.json
and the status in sweep.csv: `filling`, outlet below 80 % of the feed, or `draining`, above
125 %) are drawn hollow: the flow the thermal model carries is then not the feed.
`centrec sweep` calls this script; by hand: /usr/bin/python3 apps/plot_sweep.py DIR
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_common as pc  # noqa: E402
from plot_common import plt  # noqa: E402


def main(argv=None):
    p = pc.parser(__doc__, "output folder of `centrec sweep` (holds sweep.json)")
    args = p.parse_args(argv)
    path = pc.input_file(p, args.folder, "sweep.json", "`centrec sweep`")
    out = pc.out_dir(args)
    with open(path) as fh:
        sweep = json.load(fh)
    pts = [p for p in sweep["points"] if p.get("status") == 0 and "T_out_K" in p]
    if not pts:
        sys.exit("no successful sweep point in %s" % path)
    for p in pts:
        p["steady"] = p["dem_flow_steady"]  # decided by centrec sweep (cmd_sweep.cpp)
    speeds = sorted({p["speed_rpm"] for p in pts})
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    panels = [("T_out_K", "outlet temperature (C)", lambda p: p["T_out_K"] - 273.15),
              ("efficiency", "thermal efficiency", lambda p: p["efficiency"]),
              ("k_eff_W_mK", "film k_eff (W/(m K))", lambda p: p["k_eff_W_mK"]),
              ("film_thickness_d", "mean film thickness (d)", lambda p: p["film_thickness_d"])]
    for ax, (_, label, get) in zip(axes.flat, panels):
        for n in speeds:
            row = sorted((p for p in pts if p["speed_rpm"] == n), key=lambda p: p["mass_flow_kg_s"])
            line, = ax.plot([p["mass_flow_kg_s"] for p in row], [get(p) for p in row], "-", label="%.4g rpm" % n)
            for p in row:
                ax.plot(p["mass_flow_kg_s"], get(p), "o", color=line.get_color(),
                        mfc=line.get_color() if p["steady"] else "none")
        ax.set_xlabel("receiver mass flow (kg/s)")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        ax.legend()
    fig.suptitle("operating map: %s (hollow: DEM flow not steady within dem.run.steady_tolerance)" % sweep["case"])
    written = []
    pc.save(fig, out, "sweep_map.png", written)

    fig, ax = plt.subplots(figsize=(10, 4.5))
    names = ["%.4g rpm\n%.4g kg/s%s" % (p["speed_rpm"], p["mass_flow_kg_s"], "" if p["steady"] else "\n(not steady)")
             for p in pts]
    bottom = [0.0] * len(pts)
    for part, column in (("bed_conduction", "k_bed_W_mK"), ("radiation", "k_rad_W_mK"), ("mixing", "k_mix_W_mK")):
        vals = [p[column] for p in pts]
        ax.bar(names, vals, bottom=bottom, label=part)
        bottom = [b + v for b, v in zip(bottom, vals)]
    ax.plot(names, [p["k_eff_W_mK"] for p in pts], "kD", label="k_eff (series value)")
    ax.set_ylabel("W/(m K), film mean")
    ax.set_title("parts of k_eff over the operating window")
    ax.legend()
    ax.grid(alpha=0.3, axis="y")
    pc.save(fig, out, "sweep_keff_parts.png", written)
    pc.report(written)


if __name__ == "__main__":
    main()
