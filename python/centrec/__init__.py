"""Read centrec's output folders into pandas and xarray.

    import centrec
    run = centrec.load("out/quickstart")        # a Run
    run.T_out, run.efficiency, run.k_eff          # K, 1, W/(m K)
    run.along_z                                   # DataFrame, attrs["units"]
    run.field["T"]                                # DataArray [z, xi], attrs["units"] == "K"

``load`` returns a :class:`Run` (``centrec run`` / ``centrec thermal``), a :class:`DemRun`
(``centrec dem``, a DEM cache entry), a :class:`Sweep` (``centrec sweep``) or a
:class:`Replicas` (``centrec run --replicas``) or an :class:`Operate` (``centrec operate``). docs/python.md has a worked example;
docs/outputs.md describes every file.
"""
from ._detect import load
from .dem import DemRun
from .operate import Operate
from .replicas import Replicas
from .run import Run
from .sweep import Sweep

__version__ = "0.1.0"
__all__ = ["load", "Run", "DemRun", "Sweep", "Replicas", "Operate", "__version__"]
