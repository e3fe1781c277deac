"""A sweep folder: ``centrec sweep CASE --out DIR``.

It holds ``sweep.csv`` and ``sweep.json`` (one row / entry per point, in the grid's order) and
one ``centrec run`` folder per point (apps/cli/cmd_sweep.cpp; docs/outputs.md "Sweep").
"""
from __future__ import annotations

from functools import cached_property
from pathlib import Path
from typing import List, Optional

import pandas as pd

from ._common import LazyFolders, read_csv, read_json, resolve_child


class Sweep:
    """A ``centrec sweep`` folder.

    * ``table``: sweep.csv (DataFrame, one row per point). Its columns are read as they come:
      the swept keys first, as given (``speed_rpm``, ``mass_flow_kg_s``, or a case key's dotted
      path such as ``thermal.flux.q_film``, in the key's SI unit), then the point's inputs and
      headline figures (``T_out_K``, ``efficiency``, ``k_eff_W_mK``, ...; empty = NaN where a
      point has no such figure), ``dem_flow`` ("steady", "NOT steady", "failed"), and with
      replicas ``<figure>_std`` and ``replicas``. ``attrs["units"]``: the unit each column's
      name carries (``_K``, ``_W_mK``, ``_kg_s``, ``_rpm``, ``_d``, ...).
    * ``info``: sweep.json (dict): the case, the axes (newer sweeps) and per point its folder,
      exit status, figures and warnings; None if the folder has no sweep.json.
    * ``swept``: the swept columns of ``table`` (sweep.json ``axes``; a sweep written before
      the axes were recorded swept its case's ``speed_rpm`` x ``mass_flow_kg_s``).
    * ``dirs``: each point's folder, in the table's order (from sweep.json).
    * ``points``: the points, each read by :func:`centrec.load` when first indexed (a
      :class:`centrec.Run`, or :class:`centrec.Replicas` for a sweep with ``--replicas``).
    """

    def __init__(self, path):
        self.path = Path(path)
        if not (self.path / "sweep.csv").is_file():
            raise ValueError(f"{self.path} is not a centrec sweep folder: it has no sweep.csv")

    def __repr__(self) -> str:
        return f"Sweep({str(self.path)!r})"

    @cached_property
    def table(self) -> pd.DataFrame:
        return read_csv(self.path / "sweep.csv")

    @cached_property
    def info(self) -> Optional[dict]:
        path = self.path / "sweep.json"
        return read_json(path) if path.is_file() else None

    @property
    def swept(self) -> List[str]:
        if self.info and "axes" in self.info:
            return [a["column"] for a in self.info["axes"]]
        return [c for c in ("speed_rpm", "mass_flow_kg_s") if c in self.table.columns]

    @cached_property
    def dirs(self) -> List[Path]:
        if self.info is None:
            raise ValueError(f"{self.path} has no sweep.json: the folder of each row of sweep.csv is recorded there")
        dirs = [resolve_child(self.path, p["dir"]) for p in self.info.get("points", [])]
        if len(dirs) != len(self.table):
            raise ValueError(f"{self.path}: sweep.json lists {len(dirs)} points, sweep.csv {len(self.table)} rows")
        return dirs

    @cached_property
    def points(self) -> LazyFolders:
        return LazyFolders(self.dirs)
