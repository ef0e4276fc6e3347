"""cyclic_triax.calibrate: the example calibration (examples/calibration/: the friction that makes a
drained triaxial compression match a lab curve of q/p) on a smaller study, through the same library
call as `calibrate`: its plan, and one iteration of 3 sets on 64-sphere samples."""
import json

import pytest

import cyclic_triax as ct


def tiny_calibration(source, folder, batch=3):
    """The example's calibration, its study at 64 spheres (lattice 4, one sample), one iteration of
    `batch` sets; everything written under `folder`."""
    example = source / "examples" / "calibration"
    (folder / "study.yaml").write_text(
        "name: calibration_tiny\n"
        f"output: {folder / 'results'}\n"
        f"preparation: {source / 'scenes/prepare_dense.yaml'}\n"
        "densities:\n  - {name: dense, friction: 0.0}\n"
        f"tests:\n  - {{name: triaxial, scene: {source / 'scenes/tests/triaxial_drained.yaml'}}}\n"
        "profiles:\n  tiny: {lattice: 4, seeds: 1}\n")
    (folder / "calibration.yaml").write_text(
        "name: tiny\nstudy: study.yaml\n"
        f"references: {example / 'references.yaml'}\n"
        f"report: {folder / 'report'}\n"
        "parameters:\n  - {name: friction, keys: material.friction, applies_to: test, uniform: [0.05, 0.8]}\n"
        f"batch: {batch}\nmin_iterations: 1\nmax_iterations: 1\n")
    return folder / "calibration.yaml"


def test_plan_prints_and_runs_nothing(source, tmp_path, capfd):
    file = tiny_calibration(source, tmp_path)
    assert ct.calibrate(file, plan=True) is None
    printed = capfd.readouterr().out
    assert "friction" in printed or "set" in printed, printed
    assert not list(tmp_path.glob("results/**/*.h5")), "a plan runs nothing"
    assert not (tmp_path / "report" / "posterior.json").exists()


def test_one_iteration_posterior(source, tmp_path):
    c = ct.calibrate(tiny_calibration(source, tmp_path), jobs=1)
    assert c.iterations == 1 and c.sets == 3 and not c.converged  # max_iterations 1: stopped there
    p = c.posterior
    assert list(p.columns) == ["parameter", "mean", "sd", "median", "lower_95", "upper_95", "identified"]
    assert p["parameter"].tolist() == ["friction"]
    row = p.iloc[0]
    # A weighted mean of sets drawn from the prior lies in the prior's range, its quantiles in order.
    assert 0.05 <= row["lower_95"] <= row["median"] <= row["upper_95"] <= 0.8
    assert 0.05 <= row["mean"] <= 0.8 and row["sd"] >= 0
    # The report calibrate writes is there, with the same posterior.
    written = json.loads((tmp_path / "report" / "posterior.json").read_text())["parameters"]
    assert [w["name"] for w in written] == ["friction"]
    for column in ("mean", "sd", "median", "lower_95", "upper_95", "identified"):
        assert row[column] == written[0][column], column


def test_bad_file(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: bad\nbatch: 1\n")
    with pytest.raises(ct.ConfigError, match="bad.yaml"):
        ct.calibrate(bad, plan=True)
