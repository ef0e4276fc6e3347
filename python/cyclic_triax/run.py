"""Running a scene: `run`, the same run as `dem run SCENE --out OUT --set KEY=VALUE ...`."""
import json
import os
import sys
import tempfile
import warnings

from . import _engine
from .result import Result


class RunWarning(UserWarning):
    """A warning of the run (e.g. an inertial number above 1e-3); also kept in the result's warnings."""


def _override_text(value):
    """A --set value as YAML text: a str as typed after `--set KEY=`, anything else as JSON (which YAML reads)."""
    return value if isinstance(value, str) else json.dumps(value)


def _progress_call(progress):
    """The callback the engine calls every 256 steps: `progress` itself, or a tqdm-like bar (with
    `update` and `total`) advanced in percent of the stages."""
    if progress is None or not (hasattr(progress, "update") and hasattr(progress, "total")):
        return progress
    bar = progress

    def advance(p):
        if bar.total is None:
            bar.total = 100 * p["stages"]
        done = 100 * (p["stage"] + max(p["stage_fraction"], 0.0))
        if done > bar.n:
            bar.update(done - bar.n)
    return advance


def run(scene, set=None, out=None, threads=1, progress=None, force=False, resume="if_valid", input_hash=""):
    """Runs a scene and returns its `Result`, as `dem run` would (the same library call).

    scene     a scene file (str or path), or a scene as a dict (the YAML's keys; relative paths in it
              resolve from the current folder)
    set       {key path: value}, the overrides of `dem run --set KEY=VALUE`: a str value is YAML text
              as typed after `KEY=`, any other value (number, list, dict) is written as JSON
    out       the result file, RESULT.h5 (default: <scene name>.h5 in a new temporary folder)
    threads   threads inside the run (the result is bit for bit the same on any count)
    progress  None, a callable given a dict (scene, stage, stages, stage_name, step, time, elapsed,
              stage_fraction, status) every 256 steps, or a tqdm-like bar
    force, resume ('if_valid', 'always', 'never'), input_hash: as `dem run`'s --force, --resume /
              --no-resume and --input-hash

    The GIL is released while the run steps. Ctrl-C stops it between two steps as SIGINT stops
    `dem run`: RESULT.h5.partial keeps the rows so far with status "failed: interrupted by SIGINT
    ...", and KeyboardInterrupt is raised. Errors: ConfigError (bad input, naming the file, the key
    and what is allowed; nothing written), OutputPathError (where the result may not go; nothing
    run), RunError (the run failed; its .partial says why). Warnings come as RunWarning.
    """
    if isinstance(scene, dict):
        scene = dict(scene)
        scene.setdefault("name", "scene")
        scene_file, scene_text = "<scene dict>", json.dumps(scene)
        name = str(scene["name"])
    else:
        scene_file, scene_text = os.fspath(scene), ""
        name = os.path.splitext(os.path.basename(scene_file))[0]
    if out is None:
        out = os.path.join(tempfile.mkdtemp(prefix="cyclic_triax-"), name + ".h5")
    out = os.fspath(out)
    overrides = [(str(k), _override_text(v)) for k, v in (set or {}).items()]
    _engine.run(scene_file, scene_text, overrides, out, int(threads), bool(force), resume, input_hash,
                _progress_call(progress), lambda w: warnings.warn(w, RunWarning, stacklevel=3),
                lambda n: print(n, file=sys.stderr))
    return Result(out)
