"""`dem table --csv` read by pandas (Debian's python3-pandas): every column equals, bit for bit,
what h5py reads from the result file, and the headers are `name [unit]` with the units attribute
of each dataset.

    python3 tests/clients/pandas_client.py DEM RESULT.h5 docs/results.md

`--csv` prints 17 significant digits, which read back give the same double, so the comparison is
exact (with pandas' round-trip parser; its default fast parser may differ in the last bit). Then the Python one-liners of docs/results.md (its lines with `python3 -c '`) run with RESULT.h5
replaced by this result and build/bin/dem by DEM; each must succeed and print a number.
"""
import io
import re
import subprocess
import sys

import h5py
import pandas


def text(x):
    return x.decode() if isinstance(x, bytes) else str(x)


def unit_of(dataset):
    """A dataset's unit: `unit` (since 2026-11-27, as in the H5MD groups), or an older file's `units`."""
    return dataset.attrs["unit"] if "unit" in dataset.attrs else dataset.attrs["units"]


def main():
    dem, result, readme = sys.argv[1], sys.argv[2], sys.argv[3]
    csv = subprocess.run([dem, "table", result, "--csv"], capture_output=True, text=True, check=True).stdout
    frame = pandas.read_csv(io.StringIO(csv), float_precision="round_trip")
    with h5py.File(result, "r") as f:
        group = f["timeseries"]
        assert len(frame.columns) == len(group), f"--csv has {len(frame.columns)} columns, /timeseries {len(group)}"
        for header in frame.columns:
            m = re.fullmatch(r"(\S+) \[(\S+)\]", header)
            assert m, f"header {header!r} is not 'name [unit]'"
            name, unit = m.groups()
            assert text(unit_of(group[name])) == unit, f"{name}: header unit {unit!r}, file {unit_of(group[name])!r}"
            data = group[name][()]
            assert len(data) == len(frame), f"{name}: {len(data)} rows in the file, {len(frame)} in the CSV"
            assert (frame[header].to_numpy() == data).all(), f"{name}: pandas and h5py differ"
    one_liners = [line for line in open(readme, encoding="utf-8") if "python3 -c '" in line]
    assert one_liners, f"{readme} shows no 'python3 -c' one-liner"
    for line in one_liners:
        # The doc names Debian's /usr/bin/python3; this test runs them with its own interpreter.
        command = re.sub(r"(/usr/bin/)?python3\b", sys.executable, line.strip().replace("RESULT.h5", result).replace("build/bin/dem", dem))
        out = subprocess.run(["bash", "-c", command], capture_output=True, text=True)
        assert out.returncode == 0, f"README one-liner failed: {command}\n{out.stderr}"
        float(out.stdout.split()[-1])  # each prints a number last
    print(f"pandas client: {len(frame)} rows x {len(frame.columns)} columns of dem table --csv equal h5py's reads "
          f"bit for bit (pandas {pandas.__version__}); {len(one_liners)} README one-liners run")


if __name__ == "__main__":
    main()
