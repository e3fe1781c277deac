#!/usr/bin/python3
"""Slice vs drum at a valid size (docs/slice_vs_drum_dd80.md): the D/d 80 drum's mid-section
(z/L 0.3-0.7) against a controlled periodic slice whose target flow is the drum's measured
flow.

usage (from the repository root):
  /usr/bin/python3 docs/studies/slice_vs_drum_dd80.py slice-case DRUM_DIR [TIMES] > cases/slice_vs_drum_dd80/slice_sq1.0.yaml
  /usr/bin/python3 docs/studies/slice_vs_drum_dd80.py compare DRUM_DIR SLICE_DIR [OUT_DIR]
  /usr/bin/python3 docs/studies/slice_vs_drum_dd80.py ages DRUM_DIR [SLICE_DIR ...] [--out OUT_DIR]
  any of them with --window LO,HI: the drum's sections z/L in [LO, HI] instead of the
  mid-section 0.3-0.7 (velocity arcs: the drum's arcs nearest the window's centre)

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

`ages` splits the drum's flow by the particles' age (time since the feeder inserted them; the
fed particles' ids follow the glued layer and the initial film in insertion order, so an id
maps to its insertion time through the cumulative fed count): in the mid-section, the share of
mass and axial flux per age class, their wall distance and speed; the outlet's age
distribution (ids that leave between two snapshots); and the ring profiles (solid fraction,
axial velocity, axial volume flux density over the whole circumference, from the snapshots) of
the drum's settled film (particles older than AGE_CUT) against each slice (all its particles).
OUT_DIR (default docs/slice_vs_drum_dd80/ages): table.md, results.json, ages.png.
"""
import json
import os
import sys

import h5py
import numpy as np
import yaml

MID = (0.3, 0.7)
BOUNDS = {"thickness_d": 0.15, "profile": 0.10, "solid_fraction": 0.02}
AGE_CUT = 0.2          # s: a fed particle younger than this is still in the feed stream (see `ages`)
AGE_EDGES = [0.0, 0.1, 0.2, 0.4, 0.8, 1.6, 3.2]
W_EDGES = np.arange(0.0, 10.01, 0.25)   # wall distance of centres [d] for the ring profiles


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
            f"# sections z/L {MID[0]:g}-{MID[1]:g} free mass per length ({per_len * 1e3:.3f} g/m) and its holdup\n"
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
        # the arcs nearest the window's centre
        az = fl["arc_z_over_length"][:]
        arcs = np.flatnonzero(np.isclose(az, az[np.argmin(np.abs(az - 0.5 * (MID[0] + MID[1])))]))
        r["arc_z_over_length"] = float(az[arcs[0]])
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
        f"| figure | drum sections z/L {MID[0]:g}-{MID[1]:g} | slice | difference | bound |",
        "|---|---|---|---|---|",
        f"| thickness eqs 4-7 [d] | {dr['thickness_d']:.2f} | {sl['thickness_d']:.2f} | "
        f"{res['thickness_d']['difference']:+.2f} | 0.15 d: {ok(res['within']['thickness'])} |",
        f"| flux-weighted profile difference 45 / 90 / 135 deg | (z/L {dr['arc_z_over_length']:g}) | | "
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
    for r, style, lab in ((dr, "k-o", f"drum z/L {MID[0]:g}-{MID[1]:g}"), (sl, "C1-s", "slice")):
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


def particle_ages(f, cfg, summary):
    """Per-snapshot age function: insertion time of fed particles from their ids. Ids run
    glued layer, initial film, then fed particles in insertion order (dem/scene/feeder.cpp);
    particles present from the start get age +inf."""
    m = cfg["particles"]["density"] * np.pi / 6.0 * cfg["particles"]["diameter"] ** 3
    mf = f["mass_flow"]
    t, fed_n = mf["time"][:], mf["fed"][:] / m
    if cfg["initial_film"].get("from_run"):
        # A settled start lays another run's film, as many particles as that run left: the
        # first fed id follows the largest id of the earliest snapshot, less what was fed by then.
        g = min(f["snapshots"].values(), key=lambda g: float(g.attrs["time"]))
        fed_then = int(round(np.interp(float(g.attrs["time"]), t, fed_n)))
        first_fed = int(g["id"][:].max()) + 1 - fed_then
    else:
        first_fed = int(summary["glued_particles"]) + int(cfg["initial_film"]["particles"])

    def ages(ids, t_now):
        k = ids - first_fed
        t_in = np.interp(k + 0.5, fed_n, t)
        return np.where(k >= 0, t_now - t_in, np.inf)
    return ages


def snapshots_in(f, t0, t1):
    snaps = sorted(f["snapshots"].values(), key=lambda g: float(g.attrs["time"]))
    return [g for g in snaps if t0 - 1e-9 <= float(g.attrs["time"]) <= t1 + 1e-9]


def ring_profile(snaps, select, d, R, length):
    """Solid fraction, mean axial velocity and axial volume flux density phi u against the wall
    distance of centres, over the whole circumference: particle volume (and volume x u) with
    centres in each annulus over the annulus' volume, mean over the snapshots."""
    vol = np.zeros(len(W_EDGES) - 1)
    flux = np.zeros_like(vol)
    for g in snaps:
        sel = select(g)
        p, v, r = g["position"][:][sel], g["velocity"][:][sel], g["radius"][:][sel]
        w = (R - np.hypot(p[:, 0], p[:, 1])) / d
        V = 4.0 / 3.0 * np.pi * r ** 3
        vol += np.histogram(w, W_EDGES, weights=V)[0]
        flux += np.histogram(w, W_EDGES, weights=V * v[:, 2])[0]
    ro, ri = R - W_EDGES[:-1] * d, R - W_EDGES[1:] * d
    shell = np.pi * (ro ** 2 - ri ** 2) * length * len(snaps)
    phi, q = vol / shell, flux / shell
    u = np.divide(flux, vol, out=np.full_like(vol, np.nan), where=vol > 0)
    return {"w": (0.5 * (W_EDGES[:-1] + W_EDGES[1:])).tolist(), "phi": phi.tolist(), "u": u.tolist(), "q": q.tolist()}


def ages(drum_dir, slice_dirs, out_dir):
    s, cfg, f = load(drum_dir)
    d = float(f.attrs["particle_diameter_m"])
    R = float(f.attrs["drum_radius_m"])
    L = cfg["drum"]["length"]
    rho = cfg["particles"]["density"]
    t0, t1 = sampled_window(f, s)
    snaps = snapshots_in(f, t0, t1)
    age_of = particle_ages(f, cfg, s)
    z_lo, z_hi = MID[0] * L, MID[1] * L
    edges = AGE_EDGES + [np.inf]
    mass = np.zeros(len(edges) - 1)
    flux = np.zeros_like(mass)
    wsum = np.zeros_like(mass)
    for g in snaps:
        p = g["position"][:]
        sel = (g["glued"][:] == 0) & (p[:, 2] >= z_lo) & (p[:, 2] < z_hi)
        a = age_of(g["id"][:][sel], float(g.attrs["time"]))
        V = 4.0 / 3.0 * np.pi * g["radius"][:][sel] ** 3
        w = (R - np.hypot(p[sel, 0], p[sel, 1])) / d
        b = np.digitize(a, AGE_EDGES) - 1   # the last class (> 3.2 s) also holds the initial film (inf)
        mass += np.bincount(b, V, len(mass))
        flux += np.bincount(b, V * g["velocity"][:][sel, 2], len(mass))
        wsum += np.bincount(b, V * w, len(mass))
    n = len(snaps)
    span = (z_hi - z_lo)
    classes = []
    for k in range(len(mass)):
        classes.append({"age_s": [edges[k], edges[k + 1]], "mass_share": mass[k] / mass.sum(),
                        "flux_share": flux[k] / flux.sum(), "wall_distance_d": wsum[k] / mass[k],
                        "u_m_s": flux[k] / mass[k]})
    # whole-section flow through the mid-section from the snapshots (kg/s), total and settled
    settled_from = int(np.searchsorted(AGE_EDGES, AGE_CUT))
    flow_mid = rho * flux.sum() / n / span
    flow_settled = rho * flux[settled_from:].sum() / n / span
    hold_settled = rho * mass[settled_from:].sum() / n / span
    # along the drum: per axial section, free mass per length and the flow carried by the
    # feed stream (age < AGE_CUT) and by the settled film
    zedges = np.linspace(0.0, L, 11)
    zm = np.zeros(10)
    zf_stream = np.zeros(10)
    zf_settled = np.zeros(10)
    for g in snaps:
        p = g["position"][:]
        sel = (g["glued"][:] == 0) & (p[:, 2] >= 0.0) & (p[:, 2] < L)
        a = age_of(g["id"][:][sel], float(g.attrs["time"]))
        V = 4.0 / 3.0 * np.pi * g["radius"][:][sel] ** 3
        k = np.minimum((p[sel, 2] / L * 10).astype(int), 9)
        vz = g["velocity"][:][sel, 2]
        zm += np.bincount(k, V, 10)
        zf_stream += np.bincount(k, V * vz * (a < AGE_CUT), 10)
        zf_settled += np.bincount(k, V * vz * (a >= AGE_CUT), 10)
    dz = L / 10
    along = {"z_over_length": (0.5 * (zedges[:-1] + zedges[1:]) / L).tolist(),
             "mass_per_length_kg_m": (rho * zm / n / dz).tolist(),
             "stream_flow_kg_s": (rho * zf_stream / n / dz).tolist(),
             "settled_flow_kg_s": (rho * zf_settled / n / dz).tolist()}
    # the outlet's age distribution: free ids present in one snapshot and gone from the next
    out_ages = []
    for g, h in zip(snaps[:-1], snaps[1:]):
        ids_g = g["id"][:][g["glued"][:] == 0]
        gone = np.setdiff1d(ids_g, h["id"][:], assume_unique=True)
        out_ages.append(age_of(gone, float(g.attrs["time"])))
    out_ages = np.concatenate(out_ages)
    finite = np.isfinite(out_ages)
    res = {"drum": drum_dir, "age_cut_s": AGE_CUT, "snapshots": n, "classes": classes,
           "mid_flow_kg_s": flow_mid, "settled_flow_kg_s": flow_settled,
           "settled_mass_per_length_kg_m": hold_settled,
           "settled_flux_per_holdup_m_s": flow_settled / hold_settled,
           "outlet_particles": int(len(out_ages)),
           "outlet_age_quantiles_s": {q: float(np.quantile(out_ages[finite], q)) for q in (0.1, 0.25, 0.5, 0.75, 0.9)},
           "outlet_share_younger_than_cut": float(np.mean(out_ages < AGE_CUT)),
           "outlet_share_from_initial_film": float(np.mean(~finite)), "along_z": along}
    prof = {"drum, all free": ring_profile(snaps, lambda g: (g["glued"][:] == 0) & (g["position"][:, 2] >= z_lo)
                                           & (g["position"][:, 2] < z_hi), d, R, span),
            f"drum, settled (age > {AGE_CUT:g} s)":
                ring_profile(snaps, lambda g: (g["glued"][:] == 0) & (g["position"][:, 2] >= z_lo)
                             & (g["position"][:, 2] < z_hi)
                             & (age_of(g["id"][:], float(g.attrs["time"])) > AGE_CUT), d, R, span)}
    slices = []
    for sd in slice_dirs:
        ss, scfg, sf = load(sd)
        sl_len = scfg["slice"]["length_d"] * d
        st0, st1 = sampled_window(sf, ss)
        ssn = snapshots_in(sf, st0, st1)
        pr = ring_profile(ssn, lambda g: g["glued"][:] == 0, d, R, sl_len)
        mft = sf["mass_flow"]["time"][:]
        sel = (mft >= st0) & (mft <= st1)
        flow = float(np.mean(sf["mass_flow"]["slice_axial_flow"][:][sel]))
        hold = free_mass_per_length(sf, 0.0, sl_len, rho)
        ref = prof[f"drum, settled (age > {AGE_CUT:g} s)"]
        qd, qs = np.array(ref["q"]), np.array(pr["q"])
        pd_, ps = np.array(ref["phi"]), np.array(pr["phi"])
        slices.append({"dir": sd, "length_d": scfg["slice"]["length_d"], "flow_kg_s": flow,
                       "target_kg_s": ss.get("slice_target_mdot_kg_s", 0.0),
                       "mass_per_length_kg_m": hold, "flux_per_holdup_m_s": flow / hold,
                       "ring_flux_l1_vs_settled": float(np.sum(np.abs(qs - qd)) / np.sum(np.abs(qd))),
                       "ring_phi_l1_vs_settled": float(np.sum(np.abs(ps - pd_)) / np.sum(pd_)),
                       "steady": ss["steady_state_text"], "wall_time_s": ss["wall_time_s"]})
        prof[f"slice {os.path.basename(sd.rstrip('/'))}"] = pr
    res["slices"] = slices
    res["profiles"] = prof
    os.makedirs(out_dir, exist_ok=True)
    json.dump(res, open(os.path.join(out_dir, "results.json"), "w"), indent=1)
    lines = [f"Drum {drum_dir}, mid-section z/L {MID[0]}-{MID[1]}, {n} snapshots over the sampled turns.", "",
             "| age since fed [s] | share of free mass | share of axial flux | wall distance [d] | mean axial speed [m/s] |",
             "|---|---|---|---|---|"]
    for c in classes:
        a0, a1 = c["age_s"]
        lab = f"{a0:g}-{a1:g}" if np.isfinite(a1) else f"> {a0:g}"
        lines.append(f"| {lab} | {100 * c['mass_share']:.1f} % | {100 * c['flux_share']:.1f} % | "
                     f"{c['wall_distance_d']:.2f} | {c['u_m_s']:.3f} |")
    q = res["outlet_age_quantiles_s"]
    lines += ["",
              f"Mid-section flow from the snapshots {flow_mid * 1e3:.2f} g/s; the settled film (age > {AGE_CUT:g} s) "
              f"carries {flow_settled * 1e3:.2f} g/s ({100 * flow_settled / flow_mid:.0f} %) with "
              f"{hold_settled * 1e3:.0f} g/m: flux per holdup {flow_settled / hold_settled:.4f} m/s.",
              f"Outlet: {len(out_ages)} particles left over the window; {100 * res['outlet_share_younger_than_cut']:.0f} % "
              f"younger than {AGE_CUT:g} s; age quantiles 10/25/50/75/90 %: "
              + " / ".join(f"{q[k]:.2f}" for k in q) + " s.", ""]
    lines += [f"Along the drum ({L / d:.0f} d; sections of {L / d / 10:.1f} d):", "",
              "| z/L | free mass per length [g/m] | flow of the feed stream (age < cut) [g/s] | flow of the settled film [g/s] |",
              "|---|---|---|---|"]
    for k in range(10):
        lines.append(f"| {along['z_over_length'][k]:.2f} | {1e3 * along['mass_per_length_kg_m'][k]:.0f} | "
                     f"{1e3 * along['stream_flow_kg_s'][k]:.2f} | {1e3 * along['settled_flow_kg_s'][k]:.2f} |")
    lines.append("")
    if slices:
        lines += ["| run | length [d] | flow [g/s] | free mass per length [g/m] | flux per holdup [m/s] | "
                  "ring flux / solid fraction vs settled film (rel. L1) |", "|---|---|---|---|---|---|",
                  f"| drum settled film | - | {flow_settled * 1e3:.2f} | {hold_settled * 1e3:.0f} | "
                  f"{flow_settled / hold_settled:.4f} | - |"]
        for sl in slices:
            tgt = f" (target {sl['target_kg_s'] * 1e3:.2f})" if sl["target_kg_s"] else " (fixed holdup)"
            lines.append(f"| {sl['dir']} | {sl['length_d']:g} | {sl['flow_kg_s'] * 1e3:.2f}{tgt} | "
                         f"{sl['mass_per_length_kg_m'] * 1e3:.0f} | {sl['flux_per_holdup_m_s']:.4f} | "
                         f"{100 * sl['ring_flux_l1_vs_settled']:.0f} % / {100 * sl['ring_phi_l1_vs_settled']:.0f} % |")
    table = "\n".join(lines) + "\n"
    open(os.path.join(out_dir, "table.md"), "w").write(table)
    print(table)
    draw_ages(res, os.path.join(out_dir, "ages.png"))


def draw_ages(res, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(15, 4))
    ax = axes[0]
    labs = [f"{c['age_s'][0]:g}-{c['age_s'][1]:g}" if np.isfinite(c["age_s"][1]) else f">{c['age_s'][0]:g}"
            for c in res["classes"]]
    x = np.arange(len(labs))
    ax.bar(x - 0.2, [100 * c["mass_share"] for c in res["classes"]], 0.4, label="share of free mass")
    ax.bar(x + 0.2, [100 * c["flux_share"] for c in res["classes"]], 0.4, label="share of axial flux")
    ax.set_xticks(x, labs)
    ax.set_xlabel("age since fed [s]")
    ax.set_ylabel("%")
    ax.set_title("drum mid-section: who carries the flow", fontsize=9)
    ax.legend(fontsize=8)
    styles = ["k-", "k--", "C1-", "C2-", "C3-", "C4-"]
    for ax, key, lab in ((axes[1], "u", "mean axial velocity [m/s]"), (axes[2], "q", "axial volume flux phi u [m/s]")):
        for (name, pr), st in zip(res["profiles"].items(), styles):
            ax.plot(pr["w"], pr[key], st, lw=1.2, label=name)
        ax.set_xlabel("wall distance of centres [d]")
        ax.set_ylabel(lab)
        ax.set_xlim(0, 8)
        ax.grid(alpha=0.3)
    axes[1].legend(fontsize=7)
    axes[1].set_title("over the whole circumference", fontsize=9)
    axes[2].set_title("the flux the coupling maps", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print("wrote", path)


if __name__ == "__main__":
    if "--window" in sys.argv:   # the drum's sections to measure, z/L LO,HI (default 0.3,0.7)
        k = sys.argv.index("--window")
        MID = tuple(float(v) for v in sys.argv[k + 1].split(","))
        del sys.argv[k:k + 2]
    if len(sys.argv) >= 3 and sys.argv[1] == "ages":
        args = sys.argv[2:]
        out = "docs/slice_vs_drum_dd80/ages"
        if "--out" in args:
            k = args.index("--out")
            out = args[k + 1]
            del args[k:k + 2]
        ages(args[0], args[1:], out)
        sys.exit(0)
    if len(sys.argv) >= 3 and sys.argv[1] == "slice-case":
        slice_case(sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 1)
    elif len(sys.argv) >= 4 and sys.argv[1] == "compare":
        compare(sys.argv[2], sys.argv[3], sys.argv[4] if len(sys.argv) > 4 else "docs/slice_vs_drum_dd80")
    else:
        sys.exit(__doc__)
