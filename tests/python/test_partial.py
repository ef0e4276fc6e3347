"""A run that does not finish: reading its .partial says so, and Ctrl-C (SIGINT) stops a run made
from Python as it stops `dem run`, its partial result marked the same way."""
import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

import cyclic_triax as ct


def test_failed_run_keeps_a_partial_that_says_so(dem, source, tmp_path):
    # An energy balance allowed no error: the run stops at its first rows (StageError), as in dem.
    scene = source / "scenes/tests/test1.yaml"
    sets = {"numerics.max_energy_error": "1e-300"}
    out = tmp_path / "r.h5"
    with pytest.raises(ct.RunError, match=r"energy balance no longer closes.*partial result kept in .*r\.h5\.partial"):
        ct.run(scene, set=sets, out=out)
    assert not out.exists() and not (tmp_path / "r.h5.lock").exists()
    with pytest.raises(FileNotFoundError, match=r"r\.h5\.partial.*Result\('.*r\.h5\.partial'\)"):
        ct.Result(out)
    partial = ct.Result(str(out) + ".partial")
    assert partial.partial and not partial.complete
    assert partial.status.startswith("failed: the energy balance no longer closes")
    assert "partial result" in repr(partial)
    with pytest.warns(ct.PartialResultWarning, match="partial result"):
        frame = partial.table(["time", "energy_closure_error"])
    assert len(frame) >= 1 and frame["energy_closure_error"].iloc[-1] > 1e-300
    # dem marks the same run the same way.
    by_dem = tmp_path / "dem.h5"
    args = [dem, "run", str(scene), "--out", str(by_dem), "--quiet", "--set", "numerics.max_energy_error=1e-300"]
    assert subprocess.run(args, capture_output=True).returncode == 1
    assert ct.Result(str(by_dem) + ".partial").status == partial.status


RUN = textwrap.dedent("""
    import sys
    import cyclic_triax as ct
    print("started", flush=True)
    ct.run(sys.argv[1], out=sys.argv[2], progress=lambda p: print(p["step"], flush=True) if p["step"] >= 2048 else None)
""")


def interrupted_status(out):
    return ct.Result(str(out) + ".partial").status


def test_ctrl_c_stops_the_run_as_dem_marks_it(dem, source, tmp_path):
    scene = source / "scenes/tests/test1.yaml"  # whole, it runs for minutes: only SIGINT ends it here
    out = tmp_path / "python.h5"
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    child = subprocess.Popen([sys.executable, "-c", RUN, str(scene), str(out)], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=env)
    assert child.stdout.readline().strip() == "started"
    child.stdout.readline()  # the run has made 2,048 steps
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    _, err = child.communicate(timeout=60)
    took = time.monotonic() - sent
    assert child.returncode != 0 and "KeyboardInterrupt: interrupted by SIGINT" in err, err
    assert took < 10, f"the run took {took:.1f} s to stop"
    assert not out.exists() and not (tmp_path / "python.h5.lock").exists()
    status = interrupted_status(out)
    assert status.startswith("failed: interrupted by SIGINT")
    # dem run under the same signal writes the same status.
    by_dem = tmp_path / "dem.h5"
    run = subprocess.Popen([dem, "run", str(scene), "--out", str(by_dem), "--progress-interval", "0"],
                           stderr=subprocess.PIPE, text=True)
    while "step" not in run.stderr.readline():
        pass
    run.send_signal(signal.SIGINT)
    run.communicate(timeout=60)
    assert run.returncode == -signal.SIGINT
    assert interrupted_status(by_dem) == status
    rows = ct.Result(str(out) + ".partial")
    with pytest.warns(ct.PartialResultWarning):
        assert len(rows.table(["time"])) >= 4  # rows every 500 steps: those of the first 2,048 steps at least
