"""An operate folder: ``centrec operate CASE --map SWEEP --target-outlet K --out DIR``.

It holds ``operate.json`` (the map's points and states, the film surrogate's leave-one-out
errors, every speed tried, the operating point with its margins, the check and the transient's
figures), ``operate_map.csv`` (T_out and efficiency over the map) and, with ``--transient``,
``operate_transient.csv`` (apps/cli/cmd_operate.cpp; docs/operating.md).
"""
from __future__ import annotations

from functools import cached_property
from pathlib import Path
from typing import Optional

import pandas as pd

from ._common import read_csv, read_json


class Operate:
    """A ``centrec operate`` folder.

    * ``info``: operate.json (dict).
    * ``target_T_out``: the target outlet temperature (K).
    * ``operating_point``: dict (``speed_rpm``, ``mass_flow_kg_s``, ``T_out_K``, ``efficiency``,
      ``film_thickness_d``, ``margin``), or None when no speed of the window reaches the target.
    * ``candidates``: DataFrame, one row per speed tried (``found``, the mass flow and figures).
    * ``map_points``: DataFrame of the map's points (``usable``, ``state``).
    * ``surrogate_errors``: DataFrame of the leave-one-out errors per quantity.
    * ``map``: operate_map.csv (DataFrame, ``attrs["units"]``).
    * ``transient``: operate_transient.csv (DataFrame), or None without ``--transient``.
    """

    def __init__(self, path):
        self.path = Path(path)
        if not (self.path / "operate.json").is_file():
            raise ValueError(f"{self.path} is not a centrec operate folder: it has no operate.json")

    def __repr__(self) -> str:
        return f"Operate({str(self.path)!r})"

    @cached_property
    def info(self) -> dict:
        return read_json(self.path / "operate.json")

    @property
    def target_T_out(self) -> float:
        return self.info["target_T_out_K"]

    @property
    def operating_point(self) -> Optional[dict]:
        return self.info.get("operating_point")

    @cached_property
    def candidates(self) -> pd.DataFrame:
        return pd.DataFrame(self.info.get("candidates", []))

    @cached_property
    def map_points(self) -> pd.DataFrame:
        return pd.DataFrame(self.info.get("map_points", []))

    @cached_property
    def surrogate_errors(self) -> pd.DataFrame:
        return pd.DataFrame(self.info.get("surrogate", {}).get("leave_one_out", []))

    @cached_property
    def map(self) -> pd.DataFrame:
        return read_csv(self.path / "operate_map.csv")

    @cached_property
    def transient(self) -> Optional[pd.DataFrame]:
        path = self.path / "operate_transient.csv"
        return read_csv(path) if path.is_file() else None
