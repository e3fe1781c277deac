"""The retention study's drum and its settings: one drum scaled from the paper's
D12 by eqs 1-3 (`centrec scale`), the same for every setting, pre-filled with the paper's
scaled holdup, and the settings that differ only in the retention hardware, the size
spread and the wall rolling model.
"""
import math
import re
import subprocess

D_OVER_D = 25  # study drum: D12 scaled to D/d = 25 (the quickstart's size)
PARTICLE_D = 1.2e-3  # m, paper Table 1
DENSITY = 3560.0  # kg/m^3, paper Table 1
SOLID_FRACTION = 0.5  # paper section 4, used by eqs 4-7 and for the holdup <-> thickness link
PAPER = {"diameter": 0.12, "length": 0.171, "speed_rpm": 160.08, "mdot": 0.0357, "particles": 1.6e5}

SETTLE_S = 1.5  # s before sampling: the packed start relaxes in ~0.5 s, then hold or drain shows
SAMPLE_TURNS = 3
SNAPSHOTS_PER_TURN = 16


def sphere_mass(d=PARTICLE_D):
    return DENSITY * math.pi / 6.0 * d**3


def film_thickness_d(particles, diameter_d, length_d, solid_fraction=SOLID_FRACTION):
    """Thickness (in d) of an annular film holding `particles` spheres at `solid_fraction`."""
    area = particles * math.pi / 6.0 / solid_fraction / length_d  # annulus area, d^2
    r = 0.5 * diameter_d
    return r - math.sqrt(r * r - area / math.pi)


def scaled_drum(centrec):
    """The study drum from `centrec scale` (eqs 1-3), keeping the paper's film thickness:
    the paper's 1.6e5 particles in D12 are a film of t_paper d at f_s = 0.5; the scaled
    holdup is that film in the scaled drum (curvature kept, so not simply (D/d)^2 times)."""
    t_paper = film_thickness_d(PAPER["particles"], PAPER["diameter"] / PARTICLE_D, PAPER["length"] / PARTICLE_D)
    out = subprocess.run(
        [centrec, "scale", "--diameter", str(PAPER["diameter"]), "--length", str(PAPER["length"]),
         "--speed-rpm", str(PAPER["speed_rpm"]), "--mdot", str(PAPER["mdot"]),
         "--target-d-over-d", str(D_OVER_D), "--film-thickness-d", f"{t_paper:.6f}"],
        check=True, capture_output=True, text=True).stdout

    def scaled(label):
        m = re.search(re.escape(label) + r"\s*\[[^\]]*\]\s+(\S+)\s+(\S+)", out)
        if not m:
            raise RuntimeError(f"`centrec scale` printed no '{label}' row:\n{out}")
        return float(m.group(2))

    return {"diameter": scaled("cavity diameter D"), "length": scaled("cavity length L"),
            "speed_rpm": scaled("rotational speed"), "mdot": scaled("mass flow"),
            "particles": scaled("particles in the film"), "thickness_d": t_paper,
            "naive_particles": PAPER["particles"] * (D_OVER_D * PARTICLE_D / PAPER["diameter"]) ** 2}


def glued_count(drum, rough):
    """Spheres in the rough wall's lattice (same counting as dem/scene/wall_lattice.cpp;
    the study checks it against the run's summary.json)."""
    if not rough.get("enabled"):
        return 0
    dg = rough.get("sphere_diameter_d", 1.0) * PARTICLE_D
    a = rough["spacing_d"] * PARTICLE_D
    rc = 0.5 * drum["diameter"] - 0.5 * dg
    n_theta = math.floor(math.pi / math.asin(min(1.0, a / (2.0 * rc))))
    row = a * math.sqrt(3.0) / 2.0 if rough["lattice"] == "hexagonal" else a
    n_rows = math.floor((drum["length"] - dg) / row) + 1
    return n_theta * n_rows


# Each setting: name, group (for the charts), a label and what differs from the smooth
# open-outlet monodisperse relative-rolling drum.
def _lip(h):
    return {"drum": {"outlet_lip_height_d": h}}


def _rough(lattice, spacing):
    return {"rough_wall": {"enabled": True, "lattice": lattice, "spacing_d": spacing, "sphere_diameter_d": 1.0}}


def _spread(s):
    return {"particles": {"size_distribution": "uniform", "relative_spread": s}}


_LIGGGHTS = {"contacts": {"wall_rolling_model": "liggghts"}}


def _merge(*parts):
    out = {}
    for p in parts:
        for k, v in p.items():
            out.setdefault(k, {}).update(v)
    return out


SETTINGS = [
    ("lip0", "lip", "open outlet, smooth wall", _lip(0)),
    ("lip1", "lip", "lip 1 d", _lip(1)),
    ("lip2", "lip", "lip 2 d", _lip(2)),
    ("lip3", "lip", "lip 3 d", _lip(3)),
    ("rough_sq1.0", "rough", "rough square 1.0 d", _rough("square", 1.0)),
    ("rough_sq1.3", "rough", "rough square 1.3 d", _rough("square", 1.3)),
    ("rough_hex1.0", "rough", "rough hexagonal 1.0 d", _rough("hexagonal", 1.0)),
    ("rough_hex1.3", "rough", "rough hexagonal 1.3 d", _rough("hexagonal", 1.3)),
    ("rough_sq1.0_spread5", "spread", "rough square 1.0 d, sizes +-5 %", _merge(_rough("square", 1.0), _spread(0.05))),
    ("rough_sq1.0_spread10", "spread", "rough square 1.0 d, sizes +-10 %",
     _merge(_rough("square", 1.0), _spread(0.10))),
    # A rough wall keeps free particles off the wall (they nest >= 0.4 d above it), so the
    # wall rolling model only matters on the smooth wall: compare it there, on the lip
    # that holds the most.
    ("lip3_liggghts", "rolling", "lip 3 d, LIGGGHTS wall rolling", _merge(_lip(3), _LIGGGHTS)),
    # Second round, between the first round's neighbours: square 1.0 d holds ~0.76 of the
    # paper's film steadily, square 1.3 d over-holds and locks two layers; a size spread
    # is the suspect for the locking (docs/centrec_scene.md).
    ("rough_sq1.15", "combined", "rough square 1.15 d", _rough("square", 1.15)),
    ("rough_sq1.3_spread10", "combined", "rough square 1.3 d, sizes +-10 %",
     _merge(_rough("square", 1.3), _spread(0.10))),
]


def base_dem(drum):
    return {
        "drum": {"diameter": drum["diameter"], "length": drum["length"], "tilt_deg": 45,
                 "speed_rpm": drum["speed_rpm"], "outlet_lip_height_d": 0},
        "particles": {"diameter": PARTICLE_D, "size_distribution": "mono", "relative_spread": 0.0},
        "contacts": {"particle_particle": {"restitution": 0.46, "friction": 0.81, "rolling_friction": 0.26},
                     "particle_wall": {"restitution": 0.46, "friction": 10000, "rolling_friction": 0.26},
                     "wall_rolling_model": "relative"},
        "rough_wall": {"enabled": False},
        "feeder": {"mass_flow": round(drum["mdot"], 7), "radial_offset_d": 10},
        "initial_film": {"particles": 0},
        "run": {"duration": SETTLE_S, "dt": 2.0e-5, "skin_d": 0.4, "flow_window_turns": 3, "threads": 1},
        "sampling": {"turns": SAMPLE_TURNS, "snapshots_per_turn": SNAPSHOTS_PER_TURN},
    }


def setting_dem(drum, overrides):
    """The case's dem: section: the base drum with the setting's overrides, pre-filled so the
    free particles plus the glued layer (the paper's stuck wall layer) hold the paper's
    scaled holdup."""
    dem = base_dem(drum)
    for k, v in overrides.items():
        dem[k].update(v)
    dem["initial_film"]["particles"] = int(round(drum["particles"])) - glued_count(dem["drum"], dem["rough_wall"])
    return dem


def _flow(v):
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {_flow(x)}" for k, x in v.items()) + "}"
    if isinstance(v, bool):
        return "true" if v else "false"
    return str(v)


def case_yaml(title, comment, dem):
    lines = [f"# {line}" for line in comment.splitlines()]
    lines += [f"title: {title}", "dem:"]
    lines += [f"  {k}: {_flow(v)}" for k, v in dem.items()]
    return "\n".join(lines) + "\n"
