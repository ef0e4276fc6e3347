"""cyclic_triax: the cyclic-triax DEM engine from Python.

    import cyclic_triax as ct
    r = ct.run("scenes/tests/test1.yaml", set={"stages[0].path[1].repeat": 1})
    r.table(["time", "q_over_p"])          # a pandas DataFrame; r.units gives each column's unit

`run` makes a run exactly as `dem run` does (the same library function, bit for bit the same
result file); `Result` reads a result (or a `.partial` one, and says so); `columns` is the
engine's table of time-series columns with units, as `dem columns` prints it; `plot` draws
columns of runs against each other with `dem plot`'s own code (gnuplot); `Study` plans, runs and
validates a study with the pipeline's and validate's library calls; `calibrate` runs a calibration.
"""
import os

# OpenMP threads that wait for work spin by default; a run on several threads waits passively
# instead, as `dem run` makes sure by starting itself again with this set (libgomp reads it when it
# is loaded, which is when the engine's module is imported). A value the caller set stays.
if "OMP_WAIT_POLICY" not in os.environ and "GOMP_SPINCOUNT" not in os.environ:
    os.environ["OMP_WAIT_POLICY"] = "PASSIVE"

from ._engine import ConfigError, OutputPathError, RunError, engine_source_hash, schema_version, software_version  # noqa: E402
from .result import PartialResultWarning, Result, columns  # noqa: E402
from .run import RunWarning, run  # noqa: E402
from .plot import Plot, plot  # noqa: E402
from .study import Plan, Study, Validation, dem_binary  # noqa: E402
from .calibrate import Calibration, calibrate  # noqa: E402

__version__ = software_version
__all__ = ["run", "Result", "columns", "plot", "Plot", "Study", "Plan", "Validation", "calibrate", "Calibration", "dem_binary", "ConfigError", "OutputPathError", "RunError", "RunWarning",
           "PartialResultWarning", "software_version", "schema_version", "engine_source_hash"]
