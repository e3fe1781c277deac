#!/usr/bin/python3
"""Charts of a `centrec sweep` output folder (DIR/sweep.json): the study's map.

  sweep_map.png         outlet temperature, efficiency, k_eff and film thickness against
                        the last swept key with more than one value (mass flow for the
                        case's own speed x mass flow grid), one line per value of the others
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

LABELS = {"speed_rpm": "speed (rpm)", "mass_flow_kg_s": "receiver mass flow (kg/s)"}


def label(column):
    return LABELS.get(column, column)


def value_text(v):
    return "%.4g" % v if isinstance(v, (int, float)) else str(v)


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
        p["steady"] = p["dem_flow_steady"] or not p["dem_flow"]  # decided by centrec sweep; no DEM: nothing to settle
    columns = [a["column"] for a in sweep["axes"]]
    varied = [c for a, c in zip(sweep["axes"], columns) if len(set(map(str, a["values"]))) > 1]
    numeric = [c for c in varied if all(isinstance(p[c], (int, float)) for p in pts)]
    x = numeric[-1] if numeric else None
    others = [c for c in varied if c != x]

    def line_name(p):
        return ", ".join("%s %s" % (c, value_text(p[c])) for c in others) or "all points"

    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    panels = [("outlet temperature (C)", lambda p: p["T_out_K"] - 273.15),
              ("thermal efficiency", lambda p: p["efficiency"]),
              ("film k_eff (W/(m K))", lambda p: p["k_eff_W_mK"]),
              ("mean film thickness (d)", lambda p: p["film_thickness_d"])]
    lines = {}
    for p in pts:
        lines.setdefault(line_name(p), []).append(p)
    for ax, (ylabel, get) in zip(axes.flat, panels):
        for name, row in lines.items():
            if x:
                row = sorted(row, key=lambda p: p[x])
                xs = [p[x] for p in row]
            else:
                xs = list(range(len(row)))
            line, = ax.plot(xs, [get(p) for p in row], "-", label=name)
            for xv, p in zip(xs, row):
                ax.plot(xv, get(p), "o", color=line.get_color(), mfc=line.get_color() if p["steady"] else "none")
        ax.set_xlabel(label(x) if x else "point")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        if len(lines) > 1:
            ax.legend(fontsize=8)
    fig.suptitle("%s: %s (hollow: DEM flow not steady within dem.run.steady_tolerance)"
                 % (sweep["case"], " x ".join(columns)), fontsize=10)
    written = []
    pc.save(fig, out, "sweep_map.png", written)

    fig, ax = plt.subplots(figsize=(max(6.0, 1.2 * len(pts) + 2.0), 4.5))
    names = ["\n".join(value_text(p[c]) for c in (varied or columns)) + ("" if p["steady"] else "\n(not steady)")
             for p in pts]
    bottom = [0.0] * len(pts)
    for part, column in (("bed_conduction", "k_bed_W_mK"), ("radiation", "k_rad_W_mK"), ("mixing", "k_mix_W_mK")):
        vals = [p[column] for p in pts]
        ax.bar(names, vals, bottom=bottom, label=part)
        bottom = [b + v for b, v in zip(bottom, vals)]
    ax.plot(names, [p["k_eff_W_mK"] for p in pts], "kD", label="k_eff (series value)")
    ax.set_xlabel(" / ".join(label(c) for c in (varied or columns)))
    ax.set_ylabel("W/(m K), film mean")
    ax.set_title("parts of k_eff over the study")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, axis="y")
    pc.save(fig, out, "sweep_keff_parts.png", written)
    pc.report(written)


if __name__ == "__main__":
    main()
