"""`plot`: one column against another, several runs overlaid, drawn by `dem plot`'s own code (gnuplot)."""
import os
import tempfile

from . import _engine
from .result import Result


class Plot:
    """A drawn plot: a PNG (which Jupyter shows inline) or, with term='dumb', text."""

    def __init__(self, path, term):
        self.path, self.term = path, term

    def _repr_png_(self):
        if self.term == "png":
            with open(self.path, "rb") as f:
                return f.read()
        return None

    def __repr__(self):
        if self.term == "dumb":
            with open(self.path, encoding="utf-8") as f:
                return f.read()
        return f"<cyclic_triax.Plot {self.path}>"


def _label(name, frames, legs):
    try:
        return _engine.axis_label(name, legs)
    except ValueError:  # a column of the caller's own (e.g. cycles computed in a notebook)
        units = {u for f in frames for n, u in f.attrs.get("units", {}).items() if n == name and u not in ("", "1")}
        return f"{name} [{units.pop()}]" if len(units) == 1 else name


def plot(data, x, y, out=None, title=None, legs=False, term="png"):
    """Draws column y against column x of one or several runs and returns a `Plot`.

    data   a Result, a pandas DataFrame (e.g. Result.table() with columns of your own), or several:
           a list of them, or {key: Result or DataFrame} (the keys name the lines)
    out    the PNG (default: a temporary file); term='dumb' draws text instead (repr() shows it)
    """
    if isinstance(data, dict):
        items = list(data.items())
    elif isinstance(data, (list, tuple)):
        items = [(None, d) for d in data]
    else:
        items = [(None, data)]
    frames, keys = [], []
    for i, (key, d) in enumerate(items):
        if isinstance(d, Result):
            frames.append(d.table([x, y], legs=legs))
            keys.append(key or os.path.basename(d.path) + ("" if d.complete else " (partial)"))
        else:
            for name in (x, y):
                if name not in d.columns:
                    raise KeyError(f"no column '{name}' in the table of {key or f'series {i + 1}'}")
            frames.append(d)
            keys.append(key or f"series {i + 1}")
    if out is None:
        out = tempfile.mkstemp(prefix="cyclic_triax-plot-", suffix=".png" if term == "png" else ".txt")[1]
    series = [(k, f[x].to_numpy(dtype=float).tolist(), f[y].to_numpy(dtype=float).tolist()) for k, f in zip(keys, frames)]
    _engine.draw_plot(series, _label(x, frames, legs), _label(y, frames, legs), title or f"{y} against {x}",
                      os.fspath(out), term)
    return Plot(os.fspath(out), term)
