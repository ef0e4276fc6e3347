"""A real client of the result files: h5py (Debian's python3-h5py) reads a result written by
`dem run` and every column it reads must equal what `dem table` prints of the same result.

    python3 tests/clients/h5py_client.py DEM RESULT.h5

Checked: the status attribute, the resolved scene and the warnings (datasets), the units attribute
of each column read (and the `name [unit]` header of `dem table`), several /timeseries columns and
a /legs column against `dem table` (and `dem table --legs`), and the particle count of
the H5MD frames against `dem state`. `dem table` prints 10 significant digits (%.10g), so a value
read by h5py may differ from its printed form by at most half a unit in the 10th digit:
|h5py - table| <= 5e-10 |h5py|. (Python is a client here only: the project's code is C++.)
"""
import subprocess
import sys

import h5py

SERIES = {"time": "s", "p": "Pa", "q_over_p": "1", "void_ratio": "1", "coordination_number": "1", "volumetric_strain": "1"}
LEGS = {"target_1": "Pa", "max_inertial_number": "1"}


def text(x):
    return x.decode() if isinstance(x, bytes) else str(x)


def unit_of(dataset):
    """A dataset's unit: `unit` (since 2026-11-27, as in the H5MD groups), or an older file's `units`."""
    return dataset.attrs["unit"] if "unit" in dataset.attrs else dataset.attrs["units"]


def table(dem, result, columns, legs=False):
    args = [dem, "table", result] + (["--legs"] if legs else []) + list(columns)
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    lines = out.splitlines()
    header = [f"{name} [{unit}]" for name, unit in columns.items()]  # '# ' then 'name [unit]', tab-separated
    assert lines[0].startswith("# ") and lines[0][2:].split("\t") == header, f"dem table header {lines[0]!r}"
    return [[float(v) for v in line.split("\t")] for line in lines[1:]]


def compare(group, dem, result, columns, legs=False):
    rows = table(dem, result, columns, legs)
    for k, (name, unit) in enumerate(columns.items()):
        data = group[name][()]
        assert text(unit_of(group[name])) == unit, f"{name}: unit {unit_of(group[name])!r}, expected {unit!r}"
        assert len(data) == len(rows), f"{name}: h5py reads {len(data)} rows, dem table prints {len(rows)}"
        for i, v in enumerate(data):
            t = rows[i][k]
            assert abs(v - t) <= 5e-10 * abs(v), f"{name} row {i}: h5py {v!r}, dem table {t!r}"
    return len(rows)


def main():
    dem, result = sys.argv[1], sys.argv[2]
    with h5py.File(result, "r") as f:
        assert text(f.attrs["status"]) == "complete", f"status {f.attrs['status']!r}"
        # The resolved scene is a dataset (schema 3), a string of any length; the warnings, if any,
        # a list of strings.
        scene = text(f["scene_yaml"][()])
        assert scene.startswith("name: ") and "\nstages:" in scene, f"scene_yaml {scene[:80]!r}"
        warnings = [text(w) for w in f["warnings"][()]] if "warnings" in f else []
        assert all(w for w in warnings), "an empty warning"
        n_rows = compare(f["timeseries"], dem, result, SERIES)
        n_legs = compare(f["legs"], dem, result, LEGS, legs=True)
        assert n_rows > 2 and n_legs > 0, "the result should have rows and legs"
        spheres = f["particles/all/radius"].shape[0]
    state = subprocess.run([dem, "state", result], capture_output=True, text=True, check=True).stdout
    assert spheres == len(state.splitlines()) - 1, f"H5MD frames hold {spheres} spheres, dem state prints {len(state.splitlines()) - 1}"
    print(f"h5py client: {n_rows} rows x {len(SERIES)} time-series columns, {n_legs} legs x {len(LEGS)} leg columns "
          f"and {spheres} spheres read with h5py {h5py.__version__} equal dem table / dem state")


if __name__ == "__main__":
    main()
