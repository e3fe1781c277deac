"""``centrec.load(path)``: what kind of centrec output folder a path is, read as its type."""
from __future__ import annotations

import os
from pathlib import Path
from typing import Union

from ._common import read_json
from .dem import DemRun
from .operate import Operate
from .replicas import Replicas
from .run import RESULT_FILES, Run
from .sweep import Sweep


def load(path: Union[str, os.PathLike]) -> Union[Run, DemRun, Sweep, Replicas, Operate]:
    """Read a centrec output folder as the object of its kind.

    * ``sweep.csv``                              -> :class:`Sweep` (``centrec sweep``)
    * ``operate.json``                           -> :class:`Operate` (``centrec operate``)
    * ``summary.json`` with a ``replicas`` block -> :class:`Replicas` (``centrec run --replicas``)
    * ``summary.json`` + ``results.h5``          -> :class:`Run` (``centrec run``)
    * ``summary.json`` + ``thermal.h5``          -> :class:`Run` (``centrec thermal``)
    * ``summary.json`` + ``dem.h5``              -> :class:`DemRun` (``centrec dem``, a DEM cache entry)

    Anything else raises ValueError naming the folder and what it lacks.
    """
    p = Path(path)
    if not p.is_dir():
        raise ValueError(f"{p}: no such folder" if not p.exists() else f"{p} is a file, not a centrec output folder")
    has = lambda name: (p / name).is_file()  # noqa: E731
    if has("sweep.csv"):
        return Sweep(p)
    if has("operate.json"):
        return Operate(p)
    if not has("summary.json"):
        if has("checkpoint.h5"):
            raise ValueError(f"{p} holds an interrupted DEM run (checkpoint.h5 without summary.json): "
                             f"finish it with `centrec dem --resume {p}`")
        if (p / ".centrec-run.lock").is_file():
            raise ValueError(f"{p} has no summary.json yet: a centrec run is writing into it (.centrec-run.lock)")
        raise ValueError(f"{p} is not a centrec output folder: it has no summary.json (a run, thermal, DEM or "
                         "replicas folder) and no sweep.csv (a sweep folder)")
    if "replicas" in read_json(p / "summary.json"):
        return Replicas(p)
    if any(has(n) for n in RESULT_FILES):
        return Run(p)
    if has("dem.h5"):
        return DemRun(p)
    raise ValueError(f"{p} has a summary.json but none of results.h5 (a `centrec run` folder), thermal.h5 "
                     "(`centrec thermal`) or dem.h5 (`centrec dem`, a DEM cache entry)")
