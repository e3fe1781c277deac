"""HDF5 groups of centrec's outputs as xarray Datasets.

centrec writes every HDF5 dataset with a ``units`` attribute (docs/outputs.md: ``m``, ``m/s``,
``m2/s``, ``kg``, ``K``, ``W/m2``, ``W/(m K)``, ``rad``, ``s``, ``"1"`` for dimensionless, ``"d"``
for particle diameters) and its 1D axes as HDF5 dimension scales. This module walks a file's
groups rather than naming datasets, so a dataset the C++ writers add later is read too:

* a dimension scale becomes a coordinate; the first scale on an axis names that dimension,
  further scales on the same axis (``/film/arc_z_over_length`` next to ``/film/arc_theta``)
  become non-index coordinates along it;
* an axis without a scale gets a dimension named ``<group>_dim<k>`` (the group's path with
  ``/`` as ``_``); axes of one length in one group share it (h5netcdf's "phony" dimensions);
  a ``rows`` attribute of the form ``"0 = a, 1 = b"`` labels such a dimension;
* a variable is named by its path below the group read, subgroups joined by ``_``
  (``/steady/keff/k_eff`` read from ``/steady`` is ``keff_k_eff``, as along_z.csv names it);
* every attribute is carried over: the dataset's into the variable's ``attrs`` (``units``
  among them), the root's (provenance) and the groups' into the Dataset's ``attrs``.
"""
from __future__ import annotations

import re
from typing import Dict, Iterable, List, Optional, Tuple

import h5py
import numpy as np
import xarray as xr

# Attributes the HDF5 dimension-scale API keeps for itself.
_SCALE_ATTRS = {"CLASS", "NAME", "DIMENSION_LIST", "REFERENCE_LIST", "_Netcdf4Dimid"}


def attr_value(v):
    """An HDF5 attribute as a plain Python value (str for text, float/int for a number)."""
    if isinstance(v, bytes):
        return v.decode("utf-8", "replace")
    if isinstance(v, np.generic):
        return v.item()
    if isinstance(v, np.ndarray) and v.dtype.kind in "SO":
        return [attr_value(x) for x in v.tolist()]
    return v


def attrs_of(obj, skip=_SCALE_ATTRS) -> Dict[str, object]:
    """The attributes of an HDF5 object, less the dimension-scale bookkeeping."""
    return {k: attr_value(obj.attrs[k]) for k in obj.attrs if k not in skip}


def units_of(f: h5py.File) -> Dict[str, str]:
    """Every dataset's ``units`` attribute, by its absolute path ('/steady/T' -> 'K')."""
    out: Dict[str, str] = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset) and "units" in obj.attrs:
            out["/" + name] = attr_value(obj.attrs["units"])

    f.visititems(visit)
    return out


def _label(path: str) -> str:
    """'/steady/cavity' -> 'steady_cavity' (the root is 'root')."""
    return path.strip("/").replace("/", "_") or "root"


def _is_scale(ds: h5py.Dataset) -> bool:
    return attr_value(ds.attrs.get("CLASS", b"")) == "DIMENSION_SCALE"


def _datasets_under(group: h5py.Group, skip: Iterable[str]) -> List[h5py.Dataset]:
    skip = {"/" + s.strip("/") for s in skip}
    found: List[h5py.Dataset] = []

    def visit(name, obj):
        path = obj.name
        if any(path == s or path.startswith(s + "/") for s in skip):
            return
        if isinstance(obj, h5py.Dataset):
            found.append(obj)

    group.visititems(visit)
    return sorted(found, key=lambda d: d.name)


def _scales(ds: h5py.Dataset) -> List[List[str]]:
    """Per axis, the paths of the dimension scales attached to it (first = the dimension)."""
    out = []
    for axis in ds.dims:
        out.append([axis[i].name for i in range(len(axis))])
    return out


def _row_labels(text: str, n: int) -> Optional[List[str]]:
    """'0 = stationary zone, 1 = moving zone' -> ['stationary zone', 'moving zone'] (n rows)."""
    found = dict((int(k), v.strip()) for k, v in re.findall(r"(\d+)\s*=\s*([^,;]+)", text))
    if sorted(found) != list(range(n)):
        return None
    return [found[k] for k in range(n)]


def read_groups(f: h5py.File, groups: Iterable[str], skip: Iterable[str] = ()) -> xr.Dataset:
    """The datasets under ``groups`` (recursively, less the paths in ``skip``) as one Dataset.

    Coordinates come from the files' dimension scales, each variable's ``attrs["units"]`` from
    its ``units`` attribute; the Dataset's attrs hold the root's attributes (provenance:
    ``code_version``, ``case``, ``resolved_config``, ...) and the groups' (e.g. ``/steady``'s
    ``T_out_K``), a group attribute clashing with an earlier one prefixed by its group's label.
    A scale outside ``groups`` that a dataset uses (``/grid/z`` under ``/steady/T``) is read
    as a coordinate too.
    """
    groups = ["/" + g.strip("/") if g.strip("/") else "/" for g in groups]
    for g in groups:
        if g not in f or not isinstance(f[g], h5py.Group):
            raise KeyError(f"{f.filename} has no group {g}")
    # Every dataset read, with the group it was found under.
    owner: Dict[str, str] = {}
    for g in groups:
        for ds in _datasets_under(f[g], skip):
            owner.setdefault(ds.name, g)
    # Scales used from outside the groups read.
    for path in list(owner):
        for axis in _scales(f[path]):
            for s in axis:
                owner.setdefault(s, "")
    # Variable names: the path below its group, '/' as '_'; a clash gets the full path.
    def rel(path: str, g: str) -> str:
        if not g:  # a scale from outside the groups read: its own name
            return path.rsplit("/", 1)[-1]
        below = path if g == "/" else path[len(g):]
        return below.strip("/").replace("/", "_")

    names: Dict[str, str] = {p: rel(p, g) for p, g in owner.items()}
    by_name: Dict[str, List[str]] = {}
    for p, n in names.items():
        by_name.setdefault(n, []).append(p)
    for n, paths in by_name.items():
        if len(paths) > 1:
            for p in paths:
                names[p] = _label(p)

    # Which dimension each scale lies along: its own when it is the first scale of some axis,
    # else that of the first scale sharing its axis.
    scale_dim: Dict[str, str] = {}
    for path in owner:
        for axis in _scales(f[path]):
            if axis:
                scale_dim[axis[0]] = names[axis[0]]
    for path in owner:
        for axis in _scales(f[path]):
            for s in axis[1:]:
                scale_dim.setdefault(s, names[axis[0]])
    for path in owner:
        if _is_scale(f[path]):
            scale_dim.setdefault(path, names[path])

    # Axes without a scale: one dimension per length per HDF5 group, shared by its datasets.
    phony: Dict[str, List[Tuple[int, str]]] = {}

    def phony_dims(ds: h5py.Dataset, axes: List[List[str]]) -> List[str]:
        label = _label(ds.parent.name)
        pool = phony.setdefault(label, [])
        used: List[str] = []
        dims = []
        for i, axis in enumerate(axes):
            if axis:
                dims.append(scale_dim[axis[0]])
                continue
            n = ds.shape[i]
            name = next((d for (m, d) in pool if m == n and d not in used), None)
            if name is None:
                name = f"{label}_dim{len(pool)}"
                pool.append((n, name))
            used.append(name)
            dims.append(name)
        return dims

    coords: Dict[str, xr.Variable] = {}
    data_vars: Dict[str, xr.Variable] = {}
    labels: Dict[str, List[str]] = {}
    for path in sorted(owner):
        ds = f[path]
        name = names[path]
        attrs = attrs_of(ds)
        if _is_scale(ds):
            long_name = attr_value(ds.attrs.get("NAME", b""))
            if long_name and long_name != name and not long_name.startswith("This is a netCDF"):
                attrs.setdefault("long_name", long_name)
            coords[name] = xr.Variable((scale_dim[path],), ds[()], attrs)
            continue
        axes = _scales(ds)
        dims = phony_dims(ds, axes)
        data_vars[name] = xr.Variable(tuple(dims), ds[()], attrs)
        rows = attrs.get("rows")
        if isinstance(rows, str) and ds.ndim >= 1 and not axes[0]:
            found = _row_labels(rows, ds.shape[0])
            if found:
                labels.setdefault(dims[0], found)
    for dim, found in labels.items():
        coords.setdefault(dim, xr.Variable((dim,), np.array(found, dtype=object)))

    out = xr.Dataset(data_vars=data_vars, coords=coords)
    out.attrs.update(attrs_of(f))
    seen_groups = set()
    skipped = {"/" + s.strip("/") for s in skip}
    for g in groups:
        def visit_group(name, obj):
            if any(obj.name == s or obj.name.startswith(s + "/") for s in skipped):
                return
            if isinstance(obj, h5py.Group) and obj.name not in seen_groups:
                seen_groups.add(obj.name)
                for k, v in attrs_of(obj).items():
                    if k in out.attrs and out.attrs[k] == v:
                        continue
                    key = k if k not in out.attrs else f"{_label(obj.name)}_{k}"
                    out.attrs[key] = v

        visit_group(g, f[g])
        f[g].visititems(visit_group)
    return out


def top_groups(f: h5py.File) -> List[str]:
    """The names of the file's top-level groups."""
    return [k for k in f if isinstance(f[k], h5py.Group)]
