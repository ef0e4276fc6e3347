"""cyclic_triax.run against `dem run`: the same result file bit for bit, the same errors, and the
engine's column table behind the DataFrame.

A short run: Test 1 (scenes/tests/test1.yaml, from the shipped loose sample) cut to its first leg,
A -> TC1."""
import re
import subprocess
import threading
import time

import h5py
import numpy
import pytest

import cyclic_triax as ct

SHORT = {"stages[0].path": "[TC1]"}
# The one value of a result that two runs of the same scene may differ in: the run's wall time.
WALL_CLOCK = {("/", "wall_time_s")}


def dem_run(dem, scene, out, sets):
    args = [dem, "run", str(scene), "--out", str(out), "--quiet"]
    for key, value in sets.items():
        args += ["--set", f"{key}={value}"]
    return subprocess.run(args, capture_output=True, text=True)


def h5_contents(path):
    """{(object path, attribute or ''): bytes} of every dataset and attribute of an HDF5 file."""
    contents = {}

    def add(name, obj):
        where = "/" + name if name else "/"
        for key, value in obj.attrs.items():
            contents[(where, key)] = numpy.asarray(value).tobytes()
        if isinstance(obj, h5py.Dataset):
            data = obj[()]
            if obj.dtype.kind == "O":  # variable-length strings: their text
                data = numpy.asarray([x if isinstance(x, bytes) else str(x).encode() for x in numpy.ravel(data)])
            contents[(where, "")] = numpy.asarray(data).tobytes() + str(obj.shape).encode() + str(obj.dtype).encode()

    with h5py.File(path, "r") as f:
        add("", f)
        f.visititems(add)
    return contents


def test_run_equals_dem_run_bit_for_bit(dem, source, tmp_path):
    scene = source / "scenes/tests/test1.yaml"
    by_dem = tmp_path / "dem.h5"
    done = dem_run(dem, scene, by_dem, SHORT)
    assert done.returncode == 0, done.stderr
    result = ct.run(str(scene), set=SHORT, out=tmp_path / "python.h5")
    assert result.complete and result.status == "complete"
    a, b = h5_contents(by_dem), h5_contents(result.path)
    assert a.keys() == b.keys()
    differ = sorted(k for k in a if a[k] != b[k])
    assert set(differ) == WALL_CLOCK, f"differ beyond the wall time: {differ}"
    assert len(result.table()) > 5  # rows were written: the comparison compared something


def test_set_values_as_dem_reads_them(source, tmp_path):
    # A str is YAML as typed after --set KEY=; a list is written as JSON: both set the same path.
    scene = source / "scenes/tests/test1.yaml"
    a = ct.run(scene, set={"stages[0].path": "[TC1]"}, out=tmp_path / "a.h5")
    b = ct.run(scene, set={"stages[0].path": ["TC1"]}, out=tmp_path / "b.h5")
    assert numpy.array_equal(a.series("q_over_p")["q_over_p"], b.series("q_over_p")["q_over_p"])


@pytest.mark.parametrize("key, value", [("material.friction", "-0.2"), ("material.fricton", "0.5"),
                                        ("stages[0].path[7]", "TC2")])
def test_bad_key_raises_what_dem_prints(dem, source, tmp_path, key, value):
    scene = source / "scenes/tests/test1.yaml"
    done = dem_run(dem, scene, tmp_path / "dem.h5", {key: value})
    assert done.returncode == 2
    printed = done.stderr.strip()
    assert printed.startswith("error: ") and key.split("[")[0].split(".")[0] in printed
    with pytest.raises(ct.ConfigError) as raised:
        ct.run(scene, set={key: value}, out=tmp_path / "python.h5")
    assert "error: " + str(raised.value) == printed
    assert not list(tmp_path.glob("python.h5*")), "bad input must leave nothing behind"


def test_range_in_message(source, tmp_path):
    with pytest.raises(ct.ConfigError, match=r"material\.friction.*\[0, .*got -0\.2"):
        ct.run(source / "scenes/tests/test1.yaml", set={"material.friction": -0.2}, out=tmp_path / "x.h5")


def test_bad_output_name(source, tmp_path):
    with pytest.raises(ct.OutputPathError, match=r"\.h5 or \.hdf5.*nothing was run"):
        ct.run(source / "scenes/tests/test1.yaml", set=SHORT, out=tmp_path / "x.csv")


def dem_columns(dem):
    """{name: unit} in the order of `dem columns`' Markdown table (a row may name several columns)."""
    table = subprocess.run([dem, "columns"], capture_output=True, text=True, check=True).stdout
    units = {}
    for line in table.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        names = re.findall(r"`([^`]+)`", cells[0]) if len(cells) >= 3 else []
        for name in names:
            units[name] = cells[1]
    assert len(units) > 50, f"dem columns parsed into only {len(units)} columns"
    return units


def test_dataframe_columns_and_units_are_dem_columns(dem, source, tmp_path):
    result = ct.run(source / "scenes/tests/test1.yaml", set=SHORT, out=tmp_path / "r.h5")
    frame = result.table()
    expected = dem_columns(dem)
    assert list(frame.columns) == list(expected)
    assert frame.attrs["units"] == expected
    assert result.units == expected
    assert list(ct.columns()["name"]) == list(expected)
    with h5py.File(result.path) as f:  # and each column is the file's dataset, bit for bit
        for name in frame.columns:
            assert frame[name].to_numpy().tobytes() == f["timeseries"][name][()].tobytes()


def test_done_when_line(source, tmp_path, monkeypatch):
    # The line of the README: a scene file, an override, the table's last rows.
    monkeypatch.chdir(source)
    r = ct.run("scenes/tests/test1.yaml", set={"stages[0].path": "[TC1]"}, out=tmp_path / "t1.h5")
    tail = r.table(["time", "q_over_p"]).tail()
    assert list(tail.columns) == ["time", "q_over_p"] and len(tail) == 5


def test_scene_as_dict(source, tmp_path):
    import yaml
    scene = yaml.safe_load((source / "scenes/tests/test1.yaml").read_text())
    scene["particles"]["state"] = str(source / "scenes/samples/loose_1k.h5")  # a dict's paths resolve from the current folder
    scene["stages"][0]["path"] = ["TC1"]
    from_dict = ct.run(scene, out=tmp_path / "dict.h5")
    from_file = ct.run(source / "scenes/tests/test1.yaml", set=SHORT, out=tmp_path / "file.h5")
    for name in ("time", "q_over_p", "volumetric_strain"):
        assert numpy.array_equal(from_dict.series(name)[name], from_file.series(name)[name])


def test_progress_and_gil_released(source, tmp_path):
    # While the run steps in a thread, this (main) thread keeps running Python: the GIL is let go.
    seen = []
    done = {}
    worker = threading.Thread(target=lambda: done.setdefault("r", ct.run(
        source / "scenes/tests/test1.yaml", set={"stages[0].path": "[TC1, TC2]"}, out=tmp_path / "r.h5",
        progress=seen.append)))
    worker.start()
    spins, start = 0, time.monotonic()
    while time.monotonic() - start < 0.3:
        spins += 1
    alive = worker.is_alive()
    worker.join()
    assert alive, "the run ended within 0.3 s or held the GIL: this thread could not run meanwhile"
    assert spins > 1000
    assert done["r"].complete
    assert seen and seen[-1]["stage_name"] == "shear" and seen[-1]["step"] > seen[0]["step"]


def test_progress_callback_error_stops_the_run(source, tmp_path):
    def fail(p):
        if p["step"] > 1000:
            raise ValueError("enough")
    out = tmp_path / "r.h5"
    with pytest.raises(ValueError, match="enough"):
        ct.run(source / "scenes/tests/test1.yaml", out=out, progress=fail)
    partial = ct.Result(str(out) + ".partial")
    assert partial.status.startswith("failed: stopped by the progress callback: ValueError: enough")
