"""A DEM folder: ``centrec dem CASE --out DIR`` or a DEM cache entry ``out/dem-cache/<key>/``.

Both hold ``summary.json``, ``dem.h5`` and ``mass_flow.csv`` (docs/outputs.md; dem.h5 written
by apps/io/dem_output_h5.cpp).
"""
from __future__ import annotations

from functools import cached_property
from typing import List, Optional

import h5py
import numpy as np
import pandas as pd
import xarray as xr

from . import _h5
from ._common import Folder, number, read_csv


class DemRun(Folder):
    """A DEM run's folder.

    Attributes (read on first use):

    * ``summary``: the DEM's summary.json (dict): ``mode`` (drum / slice), ``drum_diameter_m``,
      ``holdup_kg``, ``outlet_mdot_kg_s``, ``slice_mdot_kg_s``, ``mean_film_thickness_d``, ...
    * ``film``: dem.h5's ``/film`` (xarray Dataset; empty if the run sampled no turns): the
      eqs 4-7 thickness ``thickness_mean``/``_std`` (m) over ``section_z`` (m), the surface
      velocity (m/s) and ``moving_zone_of_bin`` over ``bin_theta`` (rad), the velocity profiles
      ``axial_velocity_mean``/``_std`` (m/s) over ``arc_theta`` (rad; ``arc_z_over_length``
      along it) x ``wall_distance_d`` (d, particle diameters), the solid fraction by zone
      (``solid_fraction_mean`` [film_dim0, wall_distance_d], the zone labelled), the
      dispersion series (m2/s, over ``wall_distance_d`` and ``dispersion_lags`` in s) and the
      per-ring profiles over ``ring_z``; attrs ``mean_thickness_m``, ``sampled_turns``,
      ``snapshots``, and the root's ``particle_diameter_m``, ``drum_radius_m``,
      ``turn_period_s`` and provenance. Every variable's ``attrs["units"]`` is the file's.
    * ``mass_flow``: mass_flow.csv (DataFrame, one row per feeder batch: cumulative masses in
      kg since t = 0, ``holdup_kg``, ``free_particles``, ``slice_axial_flow_kg_s``), units in
      ``attrs["units"]``.
    * ``particle_diameter``: the particle diameter (m), to turn ``_d`` figures into metres.
    """

    def __init__(self, path):
        super().__init__(path)
        missing = [n for n in ("summary.json", "dem.h5") if not (self.path / n).is_file()]
        if missing:
            raise ValueError(f"{self.path} is not a centrec DEM folder: it has no {' and no '.join(missing)}")
        self.dem_file = self.path / "dem.h5"

    @property
    def particle_diameter(self) -> float:
        """Particle diameter (m), dem.h5's root attribute ``particle_diameter_m``."""
        with h5py.File(self.dem_file, "r") as f:
            return float(f.attrs["particle_diameter_m"])

    @property
    def film_thickness_d(self) -> Optional[float]:
        """Mean film thickness over the sampled turns (particle diameters), summary.json
        ``mean_film_thickness_d``; None if the run sampled no film."""
        return number(self.summary, "/mean_film_thickness_d")

    def groups(self) -> List[str]:
        """The top-level groups of dem.h5 (``mass_flow``, ``film``, ``snapshots``, ``drum``)."""
        with h5py.File(self.dem_file, "r") as f:
            return _h5.top_groups(f)

    def group(self, name: str) -> xr.Dataset:
        """Any group of dem.h5 as an xarray Dataset (``"mass_flow"``: the series over ``time``
        in s; ``"drum"``: the drum surface)."""
        with h5py.File(self.dem_file, "r") as f:
            return _h5.read_groups(f, [name])

    @cached_property
    def film(self) -> xr.Dataset:
        with h5py.File(self.dem_file, "r") as f:
            if "film" not in f:
                ds = xr.Dataset()
                ds.attrs.update(_h5.attrs_of(f))
                return ds
            return _h5.read_groups(f, ["film"])

    @cached_property
    def mass_flow(self) -> pd.DataFrame:
        path = self.path / "mass_flow.csv"
        if not path.is_file():
            raise ValueError(f"{self.path} has no mass_flow.csv")
        return read_csv(path)

    @cached_property
    def snapshot_times(self) -> List[float]:
        """The simulated times (s) of the particle snapshots in dem.h5's ``/snapshots``, in order."""
        with h5py.File(self.dem_file, "r") as f:
            if "snapshots" not in f:
                return []
            return sorted(float(g.attrs["time"]) for g in f["snapshots"].values() if isinstance(g, h5py.Group))

    def snapshot(self, k: int) -> pd.DataFrame:
        """Snapshot ``k`` (in time order) as one row per particle: each dataset of its group
        as a column, an [n, 3] one as ``<name>_x``, ``_y``, ``_z`` (scene frame, drum axis on
        z); units in ``attrs["units"]`` (position m, velocity m/s, radius m), the group's
        attributes (``time`` s, ``free_particles``, ``glued_particles``) in ``attrs``."""
        with h5py.File(self.dem_file, "r") as f:
            groups = [g for g in f["snapshots"].values() if isinstance(g, h5py.Group)] if "snapshots" in f else []
            if not groups:
                raise ValueError(f"{self.dem_file} holds no snapshots")
            groups.sort(key=lambda g: float(g.attrs["time"]))
            g = groups[k]
            cols, units = {}, {}
            for name, ds in g.items():
                data = ds[()]
                u = _h5.attr_value(ds.attrs.get("units", ""))
                parts = [(name, data)] if data.ndim == 1 else [
                    (f"{name}_{'xyz'[j] if data.shape[1] == 3 else j}", data[:, j]) for j in range(data.shape[1])]
                for col, values in parts:
                    cols[col] = np.asarray(values)
                    if u:
                        units[col] = u
            df = pd.DataFrame(cols)
            df.attrs.update(_h5.attrs_of(g))
            df.attrs["units"] = units
            df.attrs["group"] = g.name
            return df
