"""Calibration from Python: `calibrate`, the run `calibrate CALIBRATION.yaml` makes."""
import dataclasses
import os
import sys

from . import _engine
from .study import dem_binary


@dataclasses.dataclass
class Calibration:
    """A finished (or stopped) calibration: where its report is (posterior.json, section.md), why
    it stopped, and the posterior's marginals as a DataFrame (parameter, mean, sd, median,
    lower_95, upper_95, identified)."""
    name: str
    report: str
    results: str
    profile: str
    converged: bool
    stop_reason: str
    iterations: int
    sets: int
    runs: int
    unscored: list
    posterior: "object"


def calibrate(path, plan=False, jobs=1, profile=None, threads=1, dem=None):
    """Runs a calibration file as `calibrate CALIBRATION.yaml -j jobs --threads threads [--profile
    P]` does (the same library call; finished runs reused; the report written to the file's report
    folder after every iteration), the GIL released, and returns a `Calibration`. With plan=True,
    prints what its first iteration would run and what max_iterations would cost (`calibrate
    --plan`, on the process's standard output) and returns None."""
    sys.stdout.flush()
    data = _engine.calibrate(os.path.abspath(os.fspath(path)), profile or "", int(jobs), int(threads), bool(plan), dem_binary(dem))
    if data is None:
        return None
    import pandas
    posterior = pandas.DataFrame(data["posterior"],
                                 columns=["parameter", "mean", "sd", "median", "lower_95", "upper_95", "identified"])
    return Calibration(name=data["name"], report=data["report"], results=data["results"], profile=data["profile"],
                       converged=data["converged"], stop_reason=data["stop_reason"], iterations=data["iterations"],
                       sets=data["sets"], runs=data["runs"], unscored=list(data["unscored"]), posterior=posterior)
