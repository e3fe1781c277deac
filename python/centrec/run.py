"""A coupled run folder (``centrec run``) or a thermal-only one (``centrec thermal``).

``centrec run CASE --out DIR`` writes ``summary.json``, ``results.h5``, ``film.h5`` and
``along_z.csv``; ``centrec thermal CASE --out DIR`` writes ``summary.json``, ``thermal.h5`` and
``along_z.csv`` (docs/outputs.md). results.h5 is thermal.h5's groups plus ``/coupling``.
"""
from __future__ import annotations

from functools import cached_property
from pathlib import Path
from typing import List, Optional

import h5py
import pandas as pd
import xarray as xr

from . import _h5
from ._common import Folder, HeadlineFigures, csv_unit, read_csv

# The results file of each command (apps/runs/coupled_output.cpp, apps/runs/thermal_output.cpp).
RESULT_FILES = ("results.h5", "thermal.h5")
# Groups of results.h5 that are not the thermal field: the film used (apps/io/film_field_h5.cpp),
# the coupling records (apps/runs/coupled_output.cpp) and the flat copies for XDMF readers
# (apps/runs/thermal_output.cpp, /xdmf).
_NOT_FIELD = ("film", "coupling", "xdmf")


class Run(HeadlineFigures, Folder):
    """A ``centrec run`` or ``centrec thermal`` folder.

    Attributes (read on first use):

    * ``summary``: summary.json (dict); keys carry units (``T_out_K``, ``mass_flow_kg_s``).
    * ``T_out`` (K), ``efficiency`` (1, carried / aperture power; None without sunlight),
      ``k_eff`` (W/(m K), the film mean): summary.json's ``/T_out_K``, ``/efficiency``,
      ``/k_eff/film_mean/k_eff`` (the pointers of apps/runs/headline_figures.cpp).
    * ``along_z``: along_z.csv (DataFrame, one row per thermal column from feed to outlet;
      ``attrs["units"]`` maps each column to its unit, matched to results.h5's ``units``), or
      None if the folder has no along_z.csv.
    * ``field``: the thermal solution (xarray Dataset): every group of results.h5 / thermal.h5
      but ``/film``, ``/coupling`` and ``/xdmf``: ``/grid`` (``eta``, ``u``, ``phi``, ``D``,
      ``thickness`` on ``z`` x ``xi``), ``/steady`` (``T``, ``k_n``, ... [z, xi]; per column
      ``T_mixing_cup``, ``T_surface``, ``q_*``; ``keff_*`` over ``keff_z``; ``cavity_*``) and
      ``/transient`` if the case had one; each variable's ``attrs["units"]`` as in the file.
    * ``film``: the film field (xarray Dataset: ``u``, ``phi``, ``D`` [z, eta], ``t`` [z];
      attrs ``drum_diameter``, ``omega``, ... each with ``<name>_units``) from film.h5, or
      from the results file's ``/film`` (the film the thermal model used) without film.h5.
    * ``coupling``: results.h5's ``/coupling`` (flux closure per section, the DEM's
      thickness, ...; attrs: the coupling's figures), None for a thermal-only run.
    * ``kind``: ``"run"`` (results.h5) or ``"thermal"`` (thermal.h5).
    """

    def __init__(self, path):
        super().__init__(path)
        found = [n for n in RESULT_FILES if (self.path / n).is_file()]
        if not (self.path / "summary.json").is_file() or not found:
            missing = "summary.json" if not (self.path / "summary.json").is_file() else " or ".join(RESULT_FILES)
            raise ValueError(f"{self.path} is not a centrec run or thermal folder: it has no {missing}")
        self.results_file: Path = self.path / found[0]
        self.kind = "run" if found[0] == "results.h5" else "thermal"

    # Tables and fields.
    def groups(self) -> List[str]:
        """The top-level groups of the results file (``grid``, ``steady``, ``film``, ...)."""
        with h5py.File(self.results_file, "r") as f:
            return _h5.top_groups(f)

    def group(self, name: str) -> xr.Dataset:
        """Any group of the results file as an xarray Dataset (e.g. ``"transient"``)."""
        with h5py.File(self.results_file, "r") as f:
            return _h5.read_groups(f, [name])

    @cached_property
    def field(self) -> xr.Dataset:
        with h5py.File(self.results_file, "r") as f:
            return _h5.read_groups(f, [g for g in _h5.top_groups(f) if g not in _NOT_FIELD])

    @cached_property
    def film(self) -> Optional[xr.Dataset]:
        film_h5 = self.path / "film.h5"
        source = film_h5 if film_h5.is_file() else self.results_file
        with h5py.File(source, "r") as f:
            if "film" not in f:
                return None
            ds = _h5.read_groups(f, ["film"])
        ds.attrs["source_file"] = str(source)
        return ds

    @cached_property
    def coupling(self) -> Optional[xr.Dataset]:
        with h5py.File(self.results_file, "r") as f:
            return _h5.read_groups(f, ["coupling"]) if "coupling" in f else None

    @cached_property
    def along_z(self) -> Optional[pd.DataFrame]:
        path = self.path / "along_z.csv"
        if not path.is_file():
            return None
        # Each column is <dataset>_<unit> of a field variable (apps/runs/thermal_output.cpp,
        # along_z_csv): its unit is that variable's units attribute.
        known = {}
        for name, var in self.field.variables.items():
            u = var.attrs.get("units")
            if isinstance(u, str):
                known[f"{name}_{csv_unit(u)}"] = u
        return read_csv(path, known)

    @property
    def dem(self):
        """The DEM run this coupled run used (:class:`centrec.DemRun`), None for a thermal-only
        run. Looked for at summary.json's ``dem.dir`` (absolute, or relative to the current
        folder), then in the default cache next to the run (``../dem-cache/<cache_key>``)."""
        from .dem import DemRun

        d = self.value("/dem")
        if not isinstance(d, dict) or not d.get("dir"):
            return None
        tried = []
        key = d.get("cache_key") or Path(d["dir"]).name
        for cand in (Path(d["dir"]), self.path.parent / "dem-cache" / key, self.path.parent.parent / "dem-cache" / key):
            tried.append(str(cand))
            if (cand / "dem.h5").is_file() and (cand / "summary.json").is_file():
                return DemRun(cand)
        raise ValueError(f"{self.path}: its DEM run (summary.json dem.dir {d['dir']!r}) is not found; looked in "
                         + ", ".join(tried))
