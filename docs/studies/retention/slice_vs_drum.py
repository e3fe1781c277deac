#!/usr/bin/python3
"""Slice vs drum (issues 3 and 7): periodic slices of the retention study's drum, with one
setting, against the drum's mid-section (z/L 0.3-0.7): film thickness, the u(eta)
profiles at 45/90/135 deg and the flux per holdup, with wall times. The first points of
the speed-vs-accuracy chart.

usage (from the repository root, after the study ran the setting's drum):
  /usr/bin/python3 docs/studies/retention/slice_vs_drum.py --setting NAME [--lengths 6,12,24] [--jobs 2]

Writes cases/retention/slice_<NAME>_<L>d.yaml (free particles per length = the drum's
mid-section), runs them (`centrec dem --threads 1`), and writes
docs/retention/slice_vs_drum.{png,md,json}.
"""
import argparse
import concurrent.futures
import json
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import retention_cases as rc  # noqa: E402
import retention_metrics as rm  # noqa: E402
from retention_study import run_case  # noqa: E402

MID = (0.3, 0.7)  # z/L of the drum's mid-section


def section_flow(out_dir, z_lo, z_hi):
    """Free mass per length (kg/m) and mass-weighted mean axial velocity (m/s) of the
    particles with z in [z_lo, z_hi), averaged over the run's stored snapshots."""
    f = h5py.File(os.path.join(out_dir, "dem.h5"), "r")
    per_len, vz = [], []
    for snap in f["snapshots"].values():
        x, v, r = snap["position"][:], snap["velocity"][:], snap["radius"][:]
        sel = (x[:, 2] >= z_lo) & (x[:, 2] < z_hi)
        m = rc.DENSITY * 4.0 / 3.0 * np.pi * r[sel] ** 3
        per_len.append(m.sum() / (z_hi - z_lo))
        vz.append(np.dot(m, v[sel, 2]) / m.sum())
    return float(np.mean(per_len)), float(np.mean(vz)), float(np.std(vz))


def profiles_by_angle(m, z_pick=None):
    """Nine-arc profiles -> one per angle: the drum's arcs at z_pick, or the slice's three
    axial positions averaged (all equivalent in a periodic slice)."""
    out = {}
    for a in m["arcs"]:
        if z_pick is not None and abs(a["z_over_length"] - z_pick) > 1e-6:
            continue
        out.setdefault(round(a["theta_deg"]), []).append(np.array(a["u"]))
    return {th: np.mean(us, axis=0) for th, us in out.items()}


def profile_error(u_slice, u_drum, w, t_drum):
    """RMS difference over the film (1 d <= eta <= t + 0.5 d, as retention_metrics.in_film),
    over the drum's surface velocity there."""
    sel = (w >= 1.0) & (w <= t_drum + 0.5) & np.isfinite(u_slice) & np.isfinite(u_drum)
    return float(np.sqrt(np.mean((u_slice[sel] - u_drum[sel]) ** 2)) / np.nanmax(u_drum[sel]))


def slice_dem(drum_dem, length_d, mass_per_length):
    dem = json.loads(json.dumps(drum_dem))
    dem["slice"] = {"enabled": True, "length_d": length_d}
    dem["feeder"] = {"enabled": False}
    dem["drum"]["outlet_lip_height_d"] = 0  # a slice has no outlet
    dem["initial_film"]["particles"] = int(round(mass_per_length * length_d * rc.PARTICLE_D / rc.sphere_mass()))
    return dem


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--setting", required=True)
    ap.add_argument("--lengths", default="6,12,24", help="slice lengths in d")
    ap.add_argument("--centrec", default="build/centrec")
    ap.add_argument("--cases", default="cases/retention")
    ap.add_argument("--out", default="out/retention")
    ap.add_argument("--docs", default="docs/retention")
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()

    drum = rc.scaled_drum(a.centrec)
    name, _g, label, overrides = next(s for s in rc.SETTINGS if s[0] == a.setting)
    drum_dem = rc.setting_dem(drum, overrides)
    drum_out = os.path.join(a.out, name)
    L = drum["length"]
    per_len, vz_drum, vz_drum_sd = section_flow(drum_out, MID[0] * L, MID[1] * L)
    dm = rm.measure(drum_out, drum, drum_dem)
    lengths = [float(x) for x in a.lengths.split(",")]
    jobs = {}
    for ls in lengths:
        dem = slice_dem(drum_dem, ls, per_len)
        path = os.path.join(a.cases, f"slice_{name}_{ls:g}d.yaml")
        comment = (f"Slice vs drum (docs/studies/retention/slice_vs_drum.py writes this file): a {ls:g} d periodic slice\n"
                   f"of the retention study's drum with '{label}', holding the drum's mid-section free mass\n"
                   f"per length ({per_len * 1e3:.4f} g/m); same settle time and sampled turns as the drum.")
        text = rc.case_yaml(f"slice_{name}_{ls:g}d", comment, dem)
        if not os.path.exists(path) or open(path).read() != text:
            with open(path, "w") as f:
                f.write(text)
        jobs[ls] = (path, os.path.join(a.out, f"slice_{name}_{ls:g}d"), dem)
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        for r in pool.map(lambda j: run_case(a.centrec, j[0], j[1]), jobs.values()):
            print(r, flush=True)

    w = np.array(dm["wall_distance_d"])
    t_drum = float(np.mean([t for z, t in zip(dm["z_over_length"], dm["thickness_d"]) if MID[0] <= z <= MID[1]]))
    u_drum = profiles_by_angle(dm, 0.5)
    rows = [{"case": f"drum ({name})", "length_d": L / rc.PARTICLE_D, "thickness_d": t_drum,
             "flux_per_holdup_m_s": dm["outlet_mdot_g_s"] * 1e-3 / per_len, "mean_vz_m_s": vz_drum,
             "mean_vz_std_m_s": vz_drum_sd, "wall_time_s": dm["wall_time_s"], "profile_error": {},
             "u": {str(k): v.tolist() for k, v in u_drum.items()}}]
    for ls, (_p, out, dem) in jobs.items():
        sm = rm.measure(out, drum, dem)
        sp, vz, vz_sd = section_flow(out, 0.0, ls * rc.PARTICLE_D)
        u_sl = profiles_by_angle(sm)
        rows.append({"case": f"slice {ls:g} d", "length_d": ls, "thickness_d": float(np.mean(sm["thickness_d"])),
                     "flux_per_holdup_m_s": vz, "mean_vz_m_s": vz, "mean_vz_std_m_s": vz_sd,
                     "mass_per_length_ratio": sp / per_len, "wall_time_s": sm["wall_time_s"],
                     "profile_error": {str(th): profile_error(u_sl[th], u_drum[th], w, t_drum) for th in u_drum},
                     "u": {str(k): v.tolist() for k, v in u_sl.items()}})
    os.makedirs(a.docs, exist_ok=True)
    with open(os.path.join(a.docs, "slice_vs_drum.json"), "w") as f:
        json.dump({"setting": name, "wall_distance_d": w.tolist(), "drum_mid_mass_per_length_kg_m": per_len,
                   "rows": rows}, f, indent=1)
    md = ["| case | thickness [d] | error [d] | flux / holdup [m/s] | error | profile rms error / u_s "
          "(45/90/135 deg) | wall s |", "|---|---|---|---|---|---|---|"]
    ref = rows[0]
    for r in rows:
        pe = " / ".join(f"{100 * r['profile_error'][k]:.0f} %" for k in sorted(r["profile_error"], key=float))
        md.append(f"| {r['case']} | {r['thickness_d']:.2f} | {r['thickness_d'] - ref['thickness_d']:+.2f} | "
                  f"{r['flux_per_holdup_m_s']:.4f} | "
                  f"{100 * (r['flux_per_holdup_m_s'] / ref['flux_per_holdup_m_s'] - 1):+.0f} % | {pe or '-'} | "
                  f"{r['wall_time_s']:.0f} |")
    md.append(f"\nDrum: mid-section z/L {MID[0]}-{MID[1]}, flux = its outlet mass flow over the sampled turns "
              f"(steady: = inlet) / mid-section mass per length ({per_len * 1e3:.3f} g/m); its snapshot mean "
              f"axial velocity is {vz_drum:.4f} +- {vz_drum_sd:.4f} m/s. Slices: mean axial velocity of all "
              "particles (2 snapshots). Wall times: one thread each, shared 2-core machine.")
    text = "\n".join(md) + "\n"
    with open(os.path.join(a.docs, "slice_vs_drum.md"), "w") as f:
        f.write(text)
    print(text)
    draw(rows, w, t_drum, os.path.join(a.docs, "slice_vs_drum.png"), label)


def draw(rows, w, t_drum, path, label):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ref = rows[0]
    fig, axes = plt.subplots(1, 4, figsize=(15, 3.8))
    for k, th in enumerate(sorted(ref["u"], key=float)):
        ax = axes[k]
        for i, r in enumerate(rows):
            u = np.array(r["u"][th])
            ax.plot(w, u, marker="o", ms=2.5, lw=1.2 if i == 0 else 0.8, color="k" if i == 0 else f"C{i}",
                    label=r["case"])
        ax.axvline(t_drum, color="grey", lw=0.5, ls=":")
        ax.set_title(f"theta {float(th):.0f} deg (drum at z/L 0.5)", fontsize=9)
        ax.set_xlabel("wall distance of centres [d]")
    axes[0].set_ylabel("axial velocity [m/s]")
    axes[0].legend(fontsize=7)
    ax = axes[3]
    slices = rows[1:]
    wt = [r["wall_time_s"] for r in slices]
    ax.plot(wt, [abs(r["thickness_d"] - ref["thickness_d"]) for r in slices], "o-", label="|thickness error| [d]")
    ax.plot(wt, [abs(r["flux_per_holdup_m_s"] / ref["flux_per_holdup_m_s"] - 1) for r in slices], "s-",
            label="|flux per holdup error| [1]")
    ax.plot(wt, [max(r["profile_error"].values()) for r in slices], "^-", label="worst profile rms / u_s")
    for r in slices:
        ax.annotate(f"{r['length_d']:g} d", (r["wall_time_s"], abs(r["thickness_d"] - ref["thickness_d"])),
                    fontsize=7)
    ax.axvline(ref["wall_time_s"], color="k", lw=0.8, ls="--", label="drum wall time")
    ax.set_xlabel("wall time [s] (1 thread, shared machine)")
    ax.set_title("error vs cost", fontsize=9)
    ax.legend(fontsize=6)
    fig.suptitle(f"Periodic slice vs the drum's mid-section, {label}", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
