"""Studies from Python: `Study` (plan, run, validate, verdicts) on the pipeline's and validate's own
library calls, and where the `dem` they run is."""
import dataclasses
import os
import pathlib

from . import _engine


def dem_binary(dem=None):
    """The engine a study's runs are made by: `dem` if given, else the `dem` installed beside this
    package (PREFIX/bin/dem for PREFIX/lib/python3.X/dist-packages/cyclic_triax), else the build
    tree's the module was built with."""
    if dem is not None:
        return os.fspath(dem)
    package = pathlib.Path(__file__).resolve().parent
    if package.parents[2].name == "lib":
        installed = package.parents[3] / "bin" / "dem"
        if installed.exists():
            return str(installed)
    return _engine.build_dem


@dataclasses.dataclass
class Plan:
    """What `pipeline STUDY --plan` prints, as data.

    runs            every planned run, one row each (name, action: run, reuse, copy or stopped,
                    particle_steps, cost_basis, to_run: the particle-steps it still costs, ...)
    to_run          the runs still to run
    particle_steps  what they cost, in particle-steps
    critical_path   the longest chain of runs still to run, each starting from the one before
    throughput      the particle-steps per second of one run on one core the estimates assume,
                    and throughput_from, where that figure is from
    wall_time_s     {cores: estimated seconds} on 1, 2, 16 and 64 cores (one run per core);
                    minutes: the same in minutes
    """
    study: str
    profile: str
    results: str
    runs: "object"
    to_run: int
    particle_steps: float
    critical_path: list
    critical_path_particle_steps: float
    throughput: float
    throughput_from: str
    wall_time_s: dict

    @property
    def minutes(self):
        return {cores: seconds / 60 for cores, seconds in self.wall_time_s.items()}


class Validation:
    """A study's results judged against a reference file (`Study.validate`): `rows` (one dict per
    reference row), the counts, and the samples and results it read or missed."""

    def __init__(self, data, results, references, profile):
        self.results, self.references, self.profile = results, references, profile
        self.rows = data["rows"]
        self.label = data["label"]
        self.consistent, self.inconsistent = data["consistent"], data["inconsistent"]
        self.not_judged, self.must_pass_inconsistent = data["not_judged"], data["must_pass_inconsistent"]
        self.samples, self.missing_results, self.missing_samples = data["samples"], data["missing_results"], data["missing_samples"]

    @property
    def complete(self):
        """Every result the rows need read, every row judged (validate's exit status 0 but for must-pass rows)."""
        return not self.missing_results and not self.missing_samples and self.not_judged == 0

    def __repr__(self):
        return (f"<cyclic_triax.Validation {self.results} against {self.references} (profile {self.profile}): "
                f"{self.consistent} consistent, {self.inconsistent} inconsistent, {self.not_judged} not judged>")

    def verdicts(self):
        """One row per reference row: name, verdict, value (the mean over the samples), sd, interval
        (the 95 % prediction interval of one sample, (low, high)), reference, tolerance, statement,
        weak (the verdict cannot mean much: warnings say why), warnings, must_pass, samples."""
        import pandas
        frame = pandas.DataFrame([{
            "name": r["name"], "verdict": r["verdict"], "value": r["mean"], "sd": r["sd"],
            "interval": (r["low"], r["high"]), "reference": r["reference"], "tolerance": r["tolerance"],
            "statement": r["statement"], "weak": bool(r["warnings"]), "warnings": list(r["warnings"]),
            "must_pass": r["must_pass"], "samples": r["samples"]} for r in self.rows],
            columns=["name", "verdict", "value", "sd", "interval", "reference", "tolerance", "statement", "weak",
                     "warnings", "must_pass", "samples"])
        frame.attrs["label"] = self.label
        return frame


class Study:
    """A study file (pipeline/studies/*.yaml, or one of your own), planned and run by the
    pipeline's library and judged by validate's, as `pipeline` and `validate` do.

        s = ct.Study("examples/own_references/study.yaml")
        s.plan(profile="tiny").minutes        # {1: ..., 2: ..., 16: ..., 64: ...}
        s.run(profile="tiny", jobs=2)
        s.validate("examples/own_references/references.yaml")
        s.verdicts()                          # a DataFrame, one row per reference row

    name, profiles, default_profile, densities, tests, variants, output: the file's.
    dem: the engine its runs are made by (default: `dem_binary()`).
    """

    def __init__(self, path, dem=None):
        self.path = os.path.abspath(os.fspath(path))
        info = _engine.study_info(self.path)
        self.name, self.output, self.default_profile = info["name"], info["output"], info["default_profile"]
        self.profiles, self.densities = list(info["profiles"]), list(info["densities"])
        self.tests, self.variants = list(info["tests"]), list(info["variants"])
        self.dem = dem_binary(dem)
        self.validation = None
        self._profile = None  # the last profile planned or run

    def __repr__(self):
        return f"<cyclic_triax.Study {self.name} ({self.path}): profiles {', '.join(self.profiles)}>"

    def _profile_name(self, profile):
        return profile if profile is not None else (self._profile or self.default_profile)

    def results(self, profile=None):
        """The results folder of a profile: the study's output/PROFILE."""
        return os.path.join(self.output, self._profile_name(profile))

    def plan(self, profile=None, variants=None, out=None, throughput=None):
        """The cost `pipeline STUDY --plan` prints, as a `Plan`. Like --plan, it writes the resolved
        scenes and runs.tsv into the results folder and runs nothing. `variants`: only those (its
        --variant); `out`: its --out; `throughput`: its --throughput (particle-steps/s)."""
        import pandas
        profile = self._profile_name(profile)
        data = _engine.study_plan(self.path, profile, list(variants or []), os.fspath(out or ""), self.dem,
                                  None if throughput is None else float(throughput))
        self._profile = data["profile"]
        runs = pandas.DataFrame(data["runs"])
        return Plan(study=data["study"], profile=data["profile"], results=data["results"], runs=runs,
                    to_run=data["to_run"], particle_steps=data["particle_steps"], critical_path=list(data["critical_path"]),
                    critical_path_particle_steps=data["critical_path_particle_steps"], throughput=data["throughput"],
                    throughput_from=data["throughput_from"], wall_time_s=dict(data["wall_time_s"]))

    def run(self, profile=None, jobs=1, threads=1, variants=None, out=None):
        """Runs the study as `pipeline STUDY -j jobs --threads threads` (finished runs reused), with
        the GIL released; returns {results, ran, reused, failed, blocked, copied, stopped, skipped,
        wall_time}. Raises RunError when a run failed or was blocked (its log says why)."""
        profile = self._profile_name(profile)
        outcome = _engine.study_run(self.path, profile, list(variants or []), os.fspath(out or ""), self.dem, int(jobs),
                                    int(threads))
        self._profile = outcome["profile"]
        if outcome["failed"] + outcome["blocked"] > 0:
            raise _engine.RunError(f"{self.path}: {outcome['failed']} run(s) failed and {outcome['blocked']} blocked "
                                   f"(results and logs in {outcome['results']})")
        return dict(outcome)

    def validate(self, reference, profile=None, results=None):
        """Judges the results (default: this study's folder of the profile last planned or run)
        against a reference file, as `validate --results DIR --references FILE --profile P` does
        (the same functions; nothing written); returns a `Validation` and keeps it for `verdicts()`."""
        profile = self._profile_name(profile)
        results = os.path.abspath(os.fspath(results)) if results is not None else self.results(profile)
        reference = os.path.abspath(os.fspath(reference))
        self.validation = Validation(_engine.study_validate(results, reference, profile), results, reference, profile)
        return self.validation

    def verdicts(self):
        """The last validation's verdicts as a DataFrame (`Validation.verdicts`)."""
        if self.validation is None:
            raise RuntimeError(f"{self.name}: no validation yet: call validate(reference) first")
        return self.validation.verdicts()
