"""What every folder kind shares: summary.json, JSON pointers, CSV tables with their units.

centrec's CSV columns and JSON keys carry their unit in the name (docs/outputs.md):
``T_mixing_cup_K``, ``q_absorbed_W_m2``, ``keff_k_eff_W_mK``, ``mass_flow_kg_s``, ``speed_rpm``,
``film_thickness_d``. The suffix is the unit with ``/`` written ``_`` and ``(``, ``)`` and spaces
dropped (apps/runs/thermal_output.cpp, ``csv_unit``); :func:`csv_unit` is that spelling and
:func:`units_from_names` reads it back.
"""
from __future__ import annotations

import json
import os
from collections.abc import Sequence
from pathlib import Path
from typing import Dict, Iterable, List, Mapping, Optional

import pandas as pd

# The unit spellings of centrec's outputs (docs/outputs.md), and the two non-SI ones its keys
# name (speed_rpm, tilt_deg).
KNOWN_UNITS = ("m", "m2", "m/s", "m2/s", "kg", "kg/s", "K", "W", "W/m2", "W/(m K)", "W/(m2 K)",
               "rad", "rad/s", "s", "d", "rpm", "deg", "C")


def csv_unit(units: str) -> str:
    """A unit as centrec writes it into a column name: 'W/(m K)' -> 'W_mK', 'W/m2' -> 'W_m2'."""
    out = []
    for ch in units:
        if ch == "/":
            out.append("_")
        elif ch not in "() ":
            out.append(ch)
    return "".join(out)


def unit_from_name(column: str) -> Optional[str]:
    """The unit a column or key names by its suffix ('T_out_K' -> 'K'), or None.

    A ``_std`` column (a standard deviation over seeds) has its figure's unit.
    """
    if column.endswith("_std"):
        column = column[: -len("_std")]
    best = None
    for u in KNOWN_UNITS:
        suffix = "_" + csv_unit(u)
        if column.endswith(suffix) and len(column) > len(suffix):
            if best is None or len(csv_unit(u)) > len(csv_unit(best)):
                best = u
    return best


def units_from_names(columns: Iterable[str], known: Mapping[str, str] = {}) -> Dict[str, str]:
    """Units of the columns: from ``known`` (column -> unit, e.g. matched to the HDF5's
    ``units`` attributes) where given, else from the name's suffix; columns without either
    (counts, ratios, text) are left out."""
    out = {}
    for c in columns:
        u = known.get(c) or unit_from_name(c)
        if u:
            out[c] = u
    return out


def read_csv(path: Path, known: Mapping[str, str] = {}) -> pd.DataFrame:
    """A centrec CSV (one header line of names) as a DataFrame, its units in ``attrs["units"]``."""
    df = pd.read_csv(path)
    df.attrs["units"] = units_from_names(df.columns, known)
    df.attrs["source"] = str(path)
    return df


def read_json(path: Path) -> dict:
    with open(path) as fh:
        return json.load(fh)


def pointer(doc: Mapping, ptr: str, default=None):
    """The value at a JSON pointer ('/k_eff/film_mean/k_eff'), or ``default`` if absent."""
    node = doc
    for part in ptr.strip("/").split("/"):
        part = part.replace("~1", "/").replace("~0", "~")
        if isinstance(node, Mapping) and part in node:
            node = node[part]
        elif isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        else:
            return default
    return node


def number(doc: Mapping, ptr: str) -> Optional[float]:
    """A number at a JSON pointer as float; None where absent or null (e.g. an efficiency
    without sunlight)."""
    v = pointer(doc, ptr)
    return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else None


def resolve_child(folder: Path, recorded: str) -> Path:
    """A sub-folder a summary recorded (as the path given on the command line, relative to
    where that command ran): the folder of that name inside ``folder``, or the path itself
    when it is absolute and exists."""
    p = Path(recorded)
    if p.is_absolute() and p.is_dir():
        return p
    return folder / p.name


class Folder:
    """A centrec output folder: its path and its ``summary.json`` (dict, loaded once)."""

    def __init__(self, path):
        self.path = Path(path)
        self._summary: Optional[dict] = None

    @property
    def summary(self) -> dict:
        """summary.json as a dict (keys carry units: ``T_out_K``, ``mass_flow_kg_s``, ...)."""
        if self._summary is None:
            self._summary = read_json(self.path / "summary.json")
        return self._summary

    def value(self, ptr: str, default=None):
        """The summary's value at a JSON pointer, e.g. ``value("/receiver/aperture_power_W")``."""
        return pointer(self.summary, ptr, default)

    def __repr__(self) -> str:
        return f"{type(self).__name__}({os.fspath(self.path)!r})"


class HeadlineFigures:
    """The headline figures of a folder's summary.json (apps/runs/headline_figures.cpp): a run's
    own, or a replicas folder's means over its seeds."""

    summary: Mapping

    @property
    def T_out(self) -> Optional[float]:
        """Outlet mixing-cup temperature (K), summary.json ``T_out_K``."""
        return number(self.summary, "/T_out_K")

    @property
    def efficiency(self) -> Optional[float]:
        """Receiver efficiency (1), carried / aperture power, summary.json ``efficiency``."""
        return number(self.summary, "/efficiency")

    @property
    def k_eff(self) -> Optional[float]:
        """Film-mean effective conductivity (W/(m K)), summary.json ``k_eff.film_mean.k_eff``."""
        return number(self.summary, "/k_eff/film_mean/k_eff")


class LazyFolders(Sequence):
    """A list of output folders, each read by :func:`centrec.load` when first indexed."""

    def __init__(self, dirs):
        self.dirs: List[Path] = [Path(d) for d in dirs]
        self._loaded: Dict[int, object] = {}

    def __len__(self) -> int:
        return len(self.dirs)

    def __getitem__(self, k):
        if isinstance(k, slice):
            return [self[i] for i in range(*k.indices(len(self)))]
        if k < 0:
            k += len(self)
        if not 0 <= k < len(self):
            raise IndexError(k)
        if k not in self._loaded:
            from ._detect import load

            self._loaded[k] = load(self.dirs[k])
        return self._loaded[k]

    def __repr__(self) -> str:
        return f"LazyFolders({[str(d) for d in self.dirs]!r})"
