"""cyclic_triax.Study against the tools it binds: its plan is `pipeline --plan`'s, its verdicts
`validate`'s, on the worked example of a study of your own (examples/own_references/, profile
tiny: 2 samples of 216 spheres, prepared and sheared to 40 % axial strain, about 15 s of CPU)."""
import json
import re
import subprocess

import pytest

import cyclic_triax as ct


def pipeline_plan(dem, study, out, *args):
    """`pipeline STUDY --plan --out OUT`'s printed numbers: every run's (name, action, particle-steps)
    and the total, runs to do, critical path and wall time on each core count (as printed)."""
    tool = str(ct.dem_binary(dem)).rsplit("/", 1)[0] + "/pipeline"
    text = subprocess.run([tool, str(study), "--plan", "--out", str(out), *args], capture_output=True, text=True,
                          check=True).stdout
    runs = re.findall(r"^(\S+)\s+(run|reuse|copy|stopped)\s+(\S+) particle-steps", text, re.M)
    total = re.search(r"^to run: (\S+) particle-steps in (\d+) of (\d+) runs", text, re.M)
    critical = re.search(r"^critical path .*?: (\S+) particle-steps, (.+?): (.+)$", text, re.M)
    at = re.search(r"at (\S+) particle-steps/s:(.*)$", text, re.M)
    cores = dict(re.findall(r" (\d+) cores? ([^;]+);", at.group(2)))
    return runs, total, critical, at.group(1), cores


def duration_text(s):
    """pipeline's duration_text (pipeline/main.cpp)."""
    return f"{s:.0f} s" if s < 120 else f"{s / 60:.1f} min" if s < 7200 else f"{s / 3600:.1f} h"


@pytest.fixture(scope="module")
def example(source):
    return source / "examples" / "own_references"


def test_plan_is_pipeline_plan(dem, example, tmp_path):
    study = ct.Study(example / "study.yaml", dem=dem)
    assert study.name == "own_references" and "tiny" in study.profiles
    plan = study.plan(profile="tiny", out=tmp_path / "python")
    runs, total, critical, throughput, cores = pipeline_plan(dem, example / "study.yaml", tmp_path / "tool", "--profile", "tiny")
    # The same runs, each with the same action and cost, as printed (%.3g).
    assert [(r.name, r.action, f"{r.particle_steps:.3g}") for r in plan.runs.itertuples()] == runs
    assert len(runs) == 4  # 2 samples x (preparation + compression): the plan planned something
    assert (f"{plan.particle_steps:.3g}", str(plan.to_run), str(len(plan.runs))) == total.groups()
    assert plan.to_run == 4 and plan.particle_steps > 0
    assert f"{plan.critical_path_particle_steps:.3g}" == critical.group(1)
    assert duration_text(plan.critical_path_particle_steps / plan.throughput) == critical.group(2)
    assert " -> ".join(plan.critical_path) == critical.group(3)
    assert f"{plan.throughput:.3g}" == throughput
    assert {str(c): duration_text(s) for c, s in plan.wall_time_s.items()} == cores
    assert sorted(plan.minutes) == [1, 2, 16, 64]
    # One core runs everything in turn: its estimate is the whole cost at the throughput.
    assert plan.wall_time_s[1] == pytest.approx(plan.particle_steps / plan.throughput, rel=1e-12)


def test_plan_of_one_variant_and_bad_profile(dem, source, tmp_path):
    study = ct.Study(source / "pipeline/studies/stability.yaml", dem=dem)
    first = study.variants[0]
    plan = study.plan(profile=study.profiles[0], variants=[first], out=tmp_path / "one")
    assert plan.to_run > 0 and all(first in v for v in plan.runs["variants"])
    with pytest.raises(ct.ConfigError, match="no_such_profile"):
        study.plan(profile="no_such_profile", out=tmp_path / "bad")
    with pytest.raises(ct.ConfigError, match="no_such_variant"):
        study.plan(variants=["no_such_variant"], out=tmp_path / "bad")


def test_run_validate_verdicts_as_validate(dem, example, tmp_path):
    study = ct.Study(example / "study.yaml", dem=dem)
    results = tmp_path / "results"
    outcome = study.run(profile="tiny", jobs=1, threads=1, out=results)
    assert outcome["ran"] == 4 and outcome["failed"] == 0
    references = example / "references.yaml"
    validation = study.validate(references, profile="tiny", results=results)
    verdicts = study.verdicts()
    assert list(verdicts.columns) == ["name", "verdict", "value", "sd", "interval", "reference", "tolerance", "statement",
                                      "weak", "warnings", "must_pass", "samples"]
    # The validate tool on the same results: the same rows, verdicts, values and intervals.
    tool = str(ct.dem_binary(dem)).rsplit("/", 1)[0] + "/validate"
    subprocess.run([tool, "--results", str(results), "--references", str(references), "--out", str(tmp_path / "v"),
                    "--profile", "tiny"], capture_output=True, text=True)
    record = json.loads((tmp_path / "v" / "validation.json").read_text())
    assert len(verdicts) == len(record["rows"]) >= 3
    for ours, theirs in zip(verdicts.itertuples(), record["rows"]):
        assert ours.name == theirs["name"] and ours.verdict == theirs["verdict"]
        assert ours.value == theirs["mean"] and ours.sd == theirs["sd"]
        assert ours.tolerance == theirs["tolerance"] and ours.samples == 2
    assert (validation.consistent, validation.inconsistent, validation.not_judged) == (
        record["consistent"], record["inconsistent"], record["not_judged"])
    assert validation.complete and validation.samples == ["seed1", "seed2"]
    # Two samples give a wide interval: the example's rows carry validate's warning, and say so.
    assert verdicts["weak"].tolist() == [bool(w) for w in verdicts["warnings"]]


def test_validate_missing_results_folder(dem, example, tmp_path):
    study = ct.Study(example / "study.yaml", dem=dem)
    with pytest.raises(ct.ConfigError, match="does not exist"):
        study.validate(example / "references.yaml", profile="tiny", results=tmp_path / "none")
