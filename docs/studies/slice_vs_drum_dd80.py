#!/usr/bin/python3
"""Slice vs drum at a valid size (docs/slice_vs_drum_dd80.md): the D/d 80 drum's mid-section
(z/L 0.3-0.7) against a controlled periodic slice whose target flow is the drum's measured
flow.

usage (from the repository root):
  /usr/bin/python3 docs/studies/slice_vs_drum_dd80.py slice-case DRUM_DIR [TIMES] > cases/slice_vs_drum_dd80/slice.yaml
  /usr/bin/python3 docs/studies/slice_vs_drum_dd80.py compare DRUM_DIR SLICE_DIR [OUT_DIR]

`slice-case` writes the slice's case: the drum's geometry, contacts and wall, a whole number
of lattice rows (10 hexagonal, 8.66 d at 1.0 d; 9 square, 9 d; TIMES as many), started with the drum's mid-section free mass per length and its
holdup controlled towards the drum's outlet flow over its sampled turns.

`compare` measures both runs with the same code on their dem.h5 / summary.json (OUT_DIR,
default docs/slice_vs_drum_dd80: table.md, results.json, slice_vs_drum.png):
- flow: the drum's inlet and outlet over its sampled turns, its holdup drift; the slice's
  axial flow over its sampled turns; flux per holdup (flow / free mass per length);
- thickness (eqs 4-7): the drum's sections with z/L in [0.3, 0.7] averaged, against the
  slice's one section; bound 0.15 d;
- axial velocity profiles at 45 / 90 / 135 deg: the drum's arcs at z/L 0.5 against the slice's
  arcs; flux-weighted difference sum |u - u_drum| phi / sum |u_drum| phi over the bins both
  sampled (phi: the drum's solid fraction per bin, mean of its two zones); bound 10 %;
- solid fraction by zone (stationary / moving) in the film's core (1 d to t - 1 d); bound 0.02;
- the ring profiles the coupling maps onto the thermal film (docs/coupling.md "Film as
  measured"): solid fraction and axial volume flux density phi u over the whole
  circumference, drum sections in [0.3, 0.7] averaged, as a relative L1 difference.
"""
import json
import os
import sys

import h5py
import numpy as np
import yaml

MID = (0.3, 0.7)
BOUNDS = {"thickness_d": 0.15, "profile": 0.10, "solid_fraction": 0.02}


def slice_length_d(rough_wall, times=1):
    """A whole number of lattice rows close to times x 8.7 d, so the slice's wall is the lattice
    asked for: 10 hexagonal rows (0.866 x spacing apart) or 9 square rows, times `times`."""
    a = rough_wall["spacing_d"]
    if rough_wall["lattice"] == "hexagonal":
        return round(10 * times * a * 3 ** 0.5 / 2, 5)
    return round(9 * times * a, 5)


def sampled_window(f, summary):
    """Start and end time of the sampled turns."""
    period = float(f.attrs["turn_period_s"])
    t_end = float(summary["simulated_time_s"])
    return t_end - summary["sampled_turns"] * period, t_end


def rate(t, series, t0, t1):
    k0, k1 = np.searchsorted(t, t0), np.searchsorted(t, t1, side="right") - 1
    return float((series[k1] - series[k0]) / (t[k1] - t[k0]))


def free_mass_per_length(f, z_lo, z_hi, density):
    """Free particles' mass per length (kg/m) with centres in [z_lo, z_hi), mean over the
    stored snapshots (which hold the glued layer too, flagged `glued`)."""
    per = []
    for snap in f["snapshots"].values():
        z, r = snap["position"][:, 2], snap["radius"][:]
        sel = (z >= z_lo) & (z < z_hi) & (snap["glued"][:] == 0)
        per.append(density * 4.0 / 3.0 * np.pi * np.sum(r[sel] ** 3) / (z_hi - z_lo))
    return float(np.mean(per))


def load(run_dir):
    s = json.load(open(os.path.join(run_dir, "summary.json")))
    cfg = yaml.safe_load(s["resolved_config"])["dem"]
    return s, cfg, h5py.File(os.path.join(run_dir, "dem.h5"), "r")


def slice_case(drum_dir, times=1):
    s, cfg, f = load(drum_dir)
    d = float(f.attrs["particle_diameter_m"])
    L = cfg["drum"]["length"]
    t0, t1 = sampled_window(f, s)
    mf = f["mass_flow"]
    outlet = rate(mf["time"][:], mf["out"][:], t0, t1)
    per_len = free_mass_per_length(f, MID[0] * L, MID[1] * L, cfg["particles"]["density"])
    m = cfg["particles"]["density"] * np.pi / 6.0 * cfg["particles"]["diameter"] ** 3
    length_d = slice_length_d(cfg["rough_wall"], times)
    n = int(round(per_len * length_d * d / m))
    dem = {k: cfg[k] for k in ("drum", "particles", "contacts", "rough_wall")}
    dem["drum"] = dict(dem["drum"], outlet_lip_height_d=0)
    dem["slice"] = {"enabled": True, "length_d": length_d, "target_mass_flow": round(outlet, 7),
                    "controller_window_turns": 2, "controller_gain": 0.2}
    dem["initial_film"] = {"particles": n}
    run = cfg["run"]
    period = float(f.attrs["turn_period_s"])
    dem["run"] = {"duration": round(6 * period, 5), "dt": run["dt"], "skin_d": run["skin_d"], "flow_window_turns": 6}
    dem["sampling"] = {"turns": 6, "snapshots_per_turn": 8}
    head = (f"# Slice vs drum at D/d 80 (docs/slice_vs_drum_dd80.md; written by\n"
            f"# docs/studies/slice_vs_drum_dd80.py slice-case {drum_dir}): a periodic slice of the drum\n"
            f"# {s['case']}, {length_d:g} d ({cfg['rough_wall']['lattice']} lattice rows), started with the drum's\n"
            f"# mid-section (z/L 0.3-0.7) free mass per length ({per_len * 1e3:.3f} g/m) and its holdup\n"
            f"# controlled every 2 turns towards the drum's outlet flow over its {s['sampled_turns']} sampled\n"
            f"# turns ({outlet * 1e3:.3f} g/s); 6 turns of spin-up (extended up to 6 more until the flow over\n"
            f"# the last 6 turns is within 5 % of the target), 6 sampled turns of 8 snapshots.\n")
    sys.stdout.write(head + yaml.safe_dump({"title": "slice_dd80_vs_drum", "dem": dem}, sort_keys=False,
                                           default_flow_style=None))


def measure(run_dir):
    s, cfg, f = load(run_dir)
    d = float(f.attrs["particle_diameter_m"])
    is_slice = bool(cfg.get("slice", {}).get("enabled"))
    length = cfg["slice"]["length_d"] * d if is_slice else cfg["drum"]["length"]
    t0, t1 = sampled_window(f, s)
    mf = f["mass_flow"]
    t = mf["time"][:]
    fl = f["film"]
    rw = cfg["rough_wall"]
    r = {"dir": run_dir, "mode": "slice" if is_slice else "drum", "wall_time_s": s["wall_time_s"],
         "wall": f"{rw['lattice']} {rw['spacing_d']:g} d", "length_d": length / d,
         "particle_steps": s["particle_steps_per_s"] * s["wall_time_s"], "free_particles": s["free_particles"],
         "glued_particles": s["glued_particles"], "sampled_turns": s["sampled_turns"], "steady": s["steady_state"],
         "steady_text": s["steady_state_text"]}
    if is_slice:
        r["flow_kg_s"] = float(np.mean(mf["slice_axial_flow"][:][(t >= t0) & (t <= t1)]))
        r["target_kg_s"] = s["slice_target_mdot_kg_s"]
        z_lo, z_hi = 0.0, length
        sec = np.ones(len(fl["section_z"]), bool)
        rings = np.ones(len(fl["ring_z"]), bool)
        arcs = np.arange(len(fl["arc_theta"]))
    else:
        r["inlet_kg_s"] = rate(t, mf["fed"][:], t0, t1)
        r["flow_kg_s"] = rate(t, mf["out"][:], t0, t1)
        hold = mf["holdup"][:]
        sel = (t >= t0) & (t <= t1)
        r["holdup_drift_per_turn"] = float(np.polyfit(t[sel], hold[sel], 1)[0] / np.mean(hold[sel])
                                           * f.attrs["turn_period_s"])
        z_lo, z_hi = MID[0] * length, MID[1] * length
        zs = fl["section_z"][:] / length
        sec = (zs >= MID[0]) & (zs <= MID[1])
        zr = fl["ring_z"][:] / length
        rings = (zr >= MID[0]) & (zr <= MID[1])
        arcs = np.flatnonzero(np.isclose(fl["arc_z_over_length"][:], 0.5))
        r["z_over_length"] = zs.tolist()
        r["thickness_along_z_d"] = (fl["thickness_mean"][:] / d).tolist()
    r["mass_per_length_kg_m"] = free_mass_per_length(f, z_lo, z_hi, cfg["particles"]["density"])
    r["flux_per_holdup_m_s"] = r["flow_kg_s"] / r["mass_per_length_kg_m"]
    r["thickness_d"] = float(np.mean(fl["thickness_mean"][:][sec]) / d)
    w = fl["wall_distance_d"][:]
    r["w"] = w.tolist()
    r["theta_deg"] = np.degrees(fl["arc_theta"][:][arcs]).tolist()
    r["u"] = fl["axial_velocity_mean"][:][arcs].tolist()
    r["u_turns"] = fl["axial_velocity_turns"][:][arcs].tolist()
    sf = fl["solid_fraction_mean"][:]
    r["phi_zones"] = sf.tolist()
    core = (w >= 1.0) & (w <= r["thickness_d"] - 1.0)
    r["phi_core"] = [float(np.nanmean(sf[z][core])) for z in range(sf.shape[0])]
    r["ring_phi"] = np.nanmean(fl["ring_solid_fraction_mean"][:][rings], axis=0).tolist()
    r["ring_flux"] = np.nanmean(fl["ring_volume_flux_mean"][:][rings], axis=0).tolist()
    return r


def compare(drum_dir, slice_dir, out_dir):
    dr, sl = measure(drum_dir), measure(slice_dir)
    w = np.array(dr["w"])
    phi_w = np.nan_to_num(np.nanmean(np.array(dr["phi_zones"]), axis=0))
    prof = []
    for k in range(len(dr["u"])):
        ud, us = np.array(dr["u"][k]), np.array(sl["u"][k])
        both = (np.array(dr["u_turns"][k]) > 0) & (np.array(sl["u_turns"][k]) > 0)
        num = np.sum(np.abs(us - ud)[both] * phi_w[both])
        prof.append(float(num / np.sum(np.abs(ud)[both] * phi_w[both])))
    ring_phi = float(np.nansum(np.abs(np.array(sl["ring_phi"]) - dr["ring_phi"])) / np.nansum(dr["ring_phi"]))
    ring_flux = float(np.nansum(np.abs(np.array(sl["ring_flux"]) - dr["ring_flux"])) / np.nansum(np.abs(dr["ring_flux"])))
    res = {
        "thickness_d": {"drum": dr["thickness_d"], "slice": sl["thickness_d"],
                        "difference": sl["thickness_d"] - dr["thickness_d"]},
        "profile_flux_weighted": dict(zip([f"{t:.0f}" for t in dr["theta_deg"]], prof)),
        "phi_core": {"drum": dr["phi_core"], "slice": sl["phi_core"],
                     "difference": [a - b for a, b in zip(sl["phi_core"], dr["phi_core"])]},
        "ring_solid_fraction_l1": ring_phi, "ring_volume_flux_l1": ring_flux,
        "flow_g_s": {"drum_outlet": dr["flow_kg_s"] * 1e3, "drum_inlet": dr.get("inlet_kg_s", 0) * 1e3,
                     "slice": sl["flow_kg_s"] * 1e3, "slice_target": sl["target_kg_s"] * 1e3},
        "flux_per_holdup_m_s": {"drum": dr["flux_per_holdup_m_s"], "slice": sl["flux_per_holdup_m_s"]},
        "mass_per_length_g_m": {"drum_mid": dr["mass_per_length_kg_m"] * 1e3,
                                "slice": sl["mass_per_length_kg_m"] * 1e3},
        "bounds": BOUNDS,
    }
    res["within"] = {
        "thickness": abs(res["thickness_d"]["difference"]) <= BOUNDS["thickness_d"],
        "profile": max(prof) <= BOUNDS["profile"],
        "solid_fraction": max(abs(x) for x in res["phi_core"]["difference"]) <= BOUNDS["solid_fraction"],
    }
    cost = {k: {"wall_time_s": v["wall_time_s"], "particle_steps": v["particle_steps"],
                "particles": v["free_particles"] + v["glued_particles"], "steady": v["steady_text"]}
            for k, v in (("drum", dr), ("slice", sl))}
    res["cost"] = cost
    res["drum_holdup_drift_per_turn"] = dr["holdup_drift_per_turn"]
    os.makedirs(out_dir, exist_ok=True)
    json.dump({"result": res, "drum": dr, "slice": sl}, open(os.path.join(out_dir, "results.json"), "w"), indent=1)
    ok = lambda b: "within" if b else "OUTSIDE"  # noqa: E731
    lines = [
        "| figure | drum mid-section (z/L 0.3-0.7) | slice | difference | bound |",
        "|---|---|---|---|---|",
        f"| thickness eqs 4-7 [d] | {dr['thickness_d']:.2f} | {sl['thickness_d']:.2f} | "
        f"{res['thickness_d']['difference']:+.2f} | 0.15 d: {ok(res['within']['thickness'])} |",
        "| flux-weighted profile difference 45 / 90 / 135 deg | (z/L 0.5) | | "
        + " / ".join(f"{100 * x:.1f} %" for x in prof) + f" | 10 %: {ok(res['within']['profile'])} |",
        f"| solid fraction, core, stationary / moving | {dr['phi_core'][0]:.3f} / {dr['phi_core'][1]:.3f} | "
        f"{sl['phi_core'][0]:.3f} / {sl['phi_core'][1]:.3f} | "
        + " / ".join(f"{x:+.3f}" for x in res["phi_core"]["difference"])
        + f" | 0.02: {ok(res['within']['solid_fraction'])} |",
        f"| ring solid fraction / axial volume flux (coupling input), relative L1 | | | "
        f"{100 * ring_phi:.1f} % / {100 * ring_flux:.1f} % | - |",
        f"| flow [g/s] | outlet {dr['flow_kg_s'] * 1e3:.2f} (inlet {dr.get('inlet_kg_s', 0) * 1e3:.2f}) | "
        f"{sl['flow_kg_s'] * 1e3:.2f} (target {sl['target_kg_s'] * 1e3:.2f}) | "
        f"{100 * (sl['flow_kg_s'] / dr['flow_kg_s'] - 1):+.1f} % | - |",
        f"| free mass per length [g/m] | {dr['mass_per_length_kg_m'] * 1e3:.2f} | "
        f"{sl['mass_per_length_kg_m'] * 1e3:.2f} | "
        f"{100 * (sl['mass_per_length_kg_m'] / dr['mass_per_length_kg_m'] - 1):+.1f} % | - |",
        f"| flux per holdup [m/s] | {dr['flux_per_holdup_m_s']:.4f} | {sl['flux_per_holdup_m_s']:.4f} | "
        f"{100 * (sl['flux_per_holdup_m_s'] / dr['flux_per_holdup_m_s'] - 1):+.1f} % | - |",
        f"| particles (glued + free), wall time, particle-steps | {dr['glued_particles']} + {dr['free_particles']}, "
        f"{dr['wall_time_s']:.0f} s, {dr['particle_steps']:.2g} | {sl['glued_particles']} + {sl['free_particles']}, "
        f"{sl['wall_time_s']:.0f} s, {sl['particle_steps']:.2g} | cost x {dr['particle_steps'] / sl['particle_steps']:.0f} | - |",
        "",
        f"Drum: {dr['steady_text']}; holdup drift over the sampled turns {100 * dr['holdup_drift_per_turn']:+.2f} % per turn. "
        f"Slice: {sl['steady_text']}.",
    ]
    table = "\n".join(lines) + "\n"
    open(os.path.join(out_dir, "table.md"), "w").write(table)
    print(table)
    draw(dr, sl, prof, os.path.join(out_dir, "slice_vs_drum.png"))


def draw(dr, sl, prof, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    w = np.array(dr["w"])
    fig, axes = plt.subplots(1, 5, figsize=(19, 3.9))
    for k in range(3):
        ax = axes[k]
        for r, style, lab in ((dr, "k-o", "drum, z/L 0.5"), (sl, "C1-s", "slice")):
            u = np.where(np.array(r["u_turns"][k]) > 0, np.array(r["u"][k]), np.nan)
            ax.plot(w, u, style, ms=3, lw=1.0, label=lab)
        ax.axvline(dr["thickness_d"], color="grey", lw=0.6, ls=":")
        ax.set_title(f"theta {dr['theta_deg'][k]:.0f} deg: flux-weighted diff {100 * prof[k]:.1f} %", fontsize=9)
        ax.set_xlabel("wall distance of centres [d]")
        ax.set_xlim(0, 8)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("axial velocity [m/s]")
    axes[0].legend(fontsize=8)
    ax = axes[3]
    for r, style, lab in ((dr, "k-o", "drum z/L 0.3-0.7"), (sl, "C1-s", "slice")):
        ax.plot(w, r["ring_phi"], style, ms=3, lw=1.0, label=f"{lab}: solid fraction")
        ax.plot(w, np.array(r["ring_flux"]) * 10, style.replace("-", "--"), ms=3, lw=0.8,
                label=f"{lab}: volume flux x 10 [m/s]")
    ax.set_xlabel("wall distance [d]")
    ax.set_xlim(0, 8)
    ax.set_title("ring profiles (the coupling's input)", fontsize=9)
    ax.legend(fontsize=6)
    ax.grid(alpha=0.3)
    ax = axes[4]
    ax.plot(dr["z_over_length"], dr["thickness_along_z_d"], "k-o", ms=3, label="drum")
    ax.axhline(sl["thickness_d"], color="C1", label="slice")
    ax.axvspan(*MID, color="grey", alpha=0.15, label="mid-section")
    ax.set_xlabel("z / L")
    ax.set_ylabel("thickness eqs 4-7 [d]")
    ax.set_title("thickness along the drum", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.suptitle(f"D/d 80, glued {dr['wall']} wall: a controlled periodic slice ({sl['length_d']:g} d) against the "
                 f"drum's mid-section ({dr['length_d']:.0f} d drum), both at {dr['flow_kg_s'] * 1e3:.2f} g/s", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print("wrote", path)


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "slice-case":
        slice_case(sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 1)
    elif len(sys.argv) >= 4 and sys.argv[1] == "compare":
        compare(sys.argv[2], sys.argv[3], sys.argv[4] if len(sys.argv) > 4 else "docs/slice_vs_drum_dd80")
    else:
        sys.exit(__doc__)
