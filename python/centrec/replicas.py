"""A replicas folder: ``centrec run CASE --out DIR --replicas N``.

DIR holds ``summary.json`` (replica 0's, its headline figures replaced by their means over the
seeds, plus a ``replicas`` block) and one run folder per seed, ``replica_<k>/``
(apps/cli/cmd_run.cpp, apps/runs/replica_summary.cpp).
"""
from __future__ import annotations

from functools import cached_property
from typing import List

import pandas as pd

from ._common import Folder, HeadlineFigures, LazyFolders, resolve_child


class Replicas(HeadlineFigures, Folder):
    """A ``centrec run --replicas N`` folder.

    * ``summary``: summary.json (dict); its headline figures are the means over the seeds.
    * ``T_out`` (K), ``efficiency`` (1), ``k_eff`` (W/(m K)): those means.
    * ``seeds``: the DEM seeds, replica k's at k.
    * ``table``: one row per replica (index: replica number, column ``seed``), one column per
      figure, named by its JSON pointer into a summary.json (``/T_out_K``,
      ``/k_eff/film_mean/k_eff``, ``/film/mean_thickness_d``, ...; units as the pointer's last
      part names them).
    * ``spread``: one row per figure (index: the pointer), columns ``mean`` and ``std`` (the
      sample standard deviation, N - 1) as centrec computed them.
    * ``dirs`` and ``points``: each replica's folder and its :class:`centrec.Run`, read when
      first indexed.
    """

    def __init__(self, path):
        super().__init__(path)
        if not (self.path / "summary.json").is_file():
            raise ValueError(f"{self.path} is not a centrec replicas folder: it has no summary.json")
        if "replicas" not in self.summary:
            raise ValueError(f"{self.path} is not a centrec replicas folder: its summary.json has no 'replicas'")


    @property
    def seeds(self) -> List[int]:
        return list(self.summary["replicas"]["seeds"])

    @cached_property
    def table(self) -> pd.DataFrame:
        block = self.summary["replicas"]
        cols = {"seed": block["seeds"]}
        for ptr, fig in block["figures"].items():
            cols[ptr] = fig["values"]
        df = pd.DataFrame(cols)
        df.index.name = "replica"
        return df

    @cached_property
    def spread(self) -> pd.DataFrame:
        figs = self.summary["replicas"]["figures"]
        df = pd.DataFrame({"mean": {p: f["mean"] for p, f in figs.items()},
                           "std": {p: f["std"] for p, f in figs.items()}})
        df.index.name = "figure"
        return df

    @cached_property
    def dirs(self):
        return [resolve_child(self.path, d) for d in self.summary["replicas"]["dirs"]]

    @cached_property
    def points(self) -> LazyFolders:
        return LazyFolders(self.dirs)
