"""The particle frames of a result (output.frames), read back by a real client, h5py, and checked
against what the run itself wrote independently of them.

    python3 tests/clients/frames_client.py RESULT.h5 INTERVAL

Checked: the number of frames (the start, every INTERVAL steps, and the end if it falls between);
for every frame at a time-series row, its contact count and mean normal force equal that row's
`contacts` and `mean_normal_force` (the same contacts summed in the same order: equal to the last
bit, allowed 1e-12 relative for the mean); every contact's branch vector is shorter than the sum of
its two radii (the pair overlaps) and is the difference of the two ends drawn; the cell corners
span the row's cell lengths. (Python is a client here only: the project's code is C++.)
"""
import sys

import h5py
import numpy as np

result, interval = sys.argv[1], int(sys.argv[2])
with h5py.File(result, "r") as f:
    steps = f["particles/all/position/step"][:]
    last = int(f["timeseries/step"][-1])
    expected = [0] + list(range(interval, last + 1, interval))
    if expected[-1] != last:
        expected.append(last)
    assert list(steps) == expected, f"frames at steps {list(steps)}, expected {expected}"
    radius = f["particles/all/radius"][:]
    count = f["frames/contacts/count"][:]
    pairs, fn = f["frames/contacts/pairs"][:], f["frames/contacts/normal_force"][:]
    branch, ends = f["frames/contacts/branch"][:], f["frames/contacts/ends"][:]
    assert len(count) == len(steps) and count.sum() == len(pairs) == len(fn) == len(branch) == len(ends)
    row_of = {int(s): k for k, s in enumerate(f["timeseries/step"][:])}
    first, checked = 0, 0
    for frame, step in enumerate(steps):
        m = int(count[frame])
        rows = slice(first, first + m)
        first += m
        length = np.linalg.norm(branch[rows], axis=1)
        assert np.all(length < radius[pairs[rows, 0]] + radius[pairs[rows, 1]]), f"frame {frame}: a contact without overlap"
        assert np.allclose(ends[rows, 1] - ends[rows, 0], branch[rows], rtol=0, atol=1e-15), f"frame {frame}: ends"
        corners = f["frames/cell_corners"][frame]
        if int(step) in row_of and step > 0:
            r = row_of[int(step)]
            assert m == int(f["timeseries/contacts"][r]), f"frame {frame}: {m} contacts, row says {f['timeseries/contacts'][r]}"
            mean = fn[rows].mean() if m else 0.0
            assert abs(mean - f["timeseries/mean_normal_force"][r]) <= 1e-12 * abs(mean), f"frame {frame}: mean f_n"
            for k in range(3):
                span = corners[1 << k] - corners[0]
                assert abs(span[k] - f[f"timeseries/cell_length_{k + 1}"][r]) <= 1e-15, f"frame {frame}: cell side {k + 1}"
            checked += 1
    assert checked >= len(steps) - 2, f"only {checked} of {len(steps)} frames matched a row"
print(f"frames: {len(steps)} frames, {len(pairs)} contact rows, {checked} frames checked against their rows")
