"""Reading a result file: `Result`, and `columns`, the engine's table of columns."""
import os
import warnings

from . import _engine


class PartialResultWarning(UserWarning):
    """Data read from RESULT.h5.partial: a run that has not finished (failed, interrupted, or still going)."""


def columns(legs=False):
    """The engine's columns of /timeseries (or /legs) as a pandas DataFrame: name, unit, meaning,
    in the file's order (the table `dem columns` prints)."""
    import pandas
    return pandas.DataFrame(_engine.columns(legs), columns=["name", "unit", "meaning"])


class Result:
    """A result file of a run (RESULT.h5), or the partial result of one that did not finish
    (RESULT.h5.partial), read with the engine's own readers.

    status     'complete', 'running', or 'failed: <reason>' (a partial result)
    partial    True for a .partial file: its data stop where the run stopped
    scene      the resolved scene (YAML text: every key with the value the run used)
    units      {column: unit} of the time series, from the engine's column table
    table(columns=None, legs=False)   the time series (or the legs' rows) as a pandas DataFrame
    series(columns=None, legs=False)  the same as {column: NumPy array}
    final_state()  the particles at the end of a complete run (positions, radii, ...)
    frames         the number of particle frames the run wrote (output.frames)
    frame(i)       frame i's arrays (positions, velocities, radii, masses, the cell; the contacts
                   if the run wrote them); particles(i), contacts(i): the same as DataFrames
    """

    def __init__(self, path):
        path = os.fspath(path)
        if not os.path.exists(path) and os.path.exists(path + ".partial"):
            info = _engine.result_info(path + ".partial")
            raise FileNotFoundError(f"{path}: no such result; its run left {path}.partial (status "
                                    f"'{info.get('status', 'missing')}'): Result('{path}.partial') reads it")
        self.path = path
        self.info = _engine.result_info(path)
        self.status = self.info.get("status", "missing")
        self.partial = path.endswith(".partial") or self.status != "complete"

    def __repr__(self):
        kind = f"partial result (status '{self.status}')" if self.partial else "complete result"
        return f"<cyclic_triax.Result {self.path}: {kind}>"

    @property
    def complete(self):
        return self.status == "complete" and not self.path.endswith(".partial")

    @property
    def scene(self):
        return self.info.get("scene_yaml", "")

    @property
    def scene_dict(self):
        import yaml
        return yaml.safe_load(self.scene)

    @property
    def warnings(self):
        return list(self.info["warnings"])

    def _units(self, legs):
        return {name: unit for name, unit, _ in _engine.columns(legs)}

    @property
    def units(self):
        return self._units(False)

    @property
    def leg_units(self):
        return self._units(True)

    def series(self, columns=None, legs=False):
        """{column: NumPy array} of /timeseries (or /legs); every column of the engine's table by default."""
        if self.partial:
            warnings.warn(f"{self.path} is a partial result (status '{self.status}'): its rows stop where its run "
                          "stopped", PartialResultWarning, stacklevel=3)
        if isinstance(columns, str):
            columns = [columns]
        if columns is None:
            columns = [name for name, _, _ in _engine.columns(legs)]
        return _engine.read_columns(self.path, "legs" if legs else "timeseries", list(columns))

    def table(self, columns=None, legs=False):
        """The time series (or the legs) as a pandas DataFrame, one column per name; the units are
        in `frame.attrs["units"]` (and `Result.units`)."""
        import pandas
        data = self.series(columns, legs)
        frame = pandas.DataFrame(data)
        units = self._units(legs)
        frame.attrs["units"] = {name: units.get(name, "") for name in frame.columns}
        return frame

    def legs(self, columns=None):
        """The rows of /legs (one per leg of a stress path) as a pandas DataFrame."""
        return self.table(columns, legs=True)

    def final_state(self):
        """The particles at the end of a complete run: {position (N x 3, m), velocity (m/s),
        angular_velocity (rad/s), radius (m), mass (kg), cell (lengths, m), step}."""
        return _engine.read_final_state(self.path)

    @property
    def frames(self):
        """The number of particle frames in the file (0 without output.frames)."""
        return _engine.frame_count(self.path)

    def frame(self, index=-1):
        """Frame `index` (negative: from the last) as NumPy arrays, read with the engine's reader
        of its H5MD frames (docs/results.md): {step, time (s), position (N x 3, m), velocity (N x 3,
        m/s, the fluctuating part), angular_velocity (N x 3, rad/s), radius (m), mass (kg), cell
        (edges, m)} and, if the run wrote contacts (output.frames.contacts), pairs (M x 2 particle
        indices), normal_force and tangential_force (N), branch (M x 3, m)."""
        count = self.frames
        if not -count <= index < count:
            raise IndexError(f"{self.path}: frame {index} asked for; it has {count} frame(s)"
                             + ("" if count else " (a scene writes them with output.frames: {interval: STEPS})"))
        return _engine.read_frame(self.path, index % count)

    def particles(self, frame=-1):
        """A frame's particles as a pandas DataFrame, one row each: x, y, z (m), vx, vy, vz (m/s),
        wx, wy, wz (rad/s), radius (m), mass (kg); attrs: units, step, time, cell."""
        import pandas
        f = self.frame(frame)
        columns = {}
        for key, names in (("position", "xyz"), ("velocity", ("vx", "vy", "vz")), ("angular_velocity", ("wx", "wy", "wz"))):
            for k, name in enumerate(names):
                columns[name] = f[key][:, k]
        columns["radius"], columns["mass"] = f["radius"], f["mass"]
        frame_ = pandas.DataFrame(columns)
        frame_.attrs.update(step=f["step"], time=f["time"], cell=f["cell"],
                            units={"x": "m", "y": "m", "z": "m", "vx": "m/s", "vy": "m/s", "vz": "m/s", "wx": "rad/s",
                                   "wy": "rad/s", "wz": "rad/s", "radius": "m", "mass": "kg"})
        return frame_

    def contacts(self, frame=-1):
        """A frame's contacts as a pandas DataFrame, one row each: i, j (particle indices),
        normal_force, tangential_force (N), branch_x, branch_y, branch_z (m, from i's centre to the
        nearest image of j's); attrs: units, step, time. Needs a run with output.frames.contacts."""
        import pandas
        f = self.frame(frame)
        if "pairs" not in f:
            raise KeyError(f"{self.path}: its frames have no contacts (a scene writes them with "
                           "output.frames: {interval: STEPS, contacts: true})")
        frame_ = pandas.DataFrame({"i": f["pairs"][:, 0], "j": f["pairs"][:, 1], "normal_force": f["normal_force"],
                                   "tangential_force": f["tangential_force"], "branch_x": f["branch"][:, 0],
                                   "branch_y": f["branch"][:, 1], "branch_z": f["branch"][:, 2]})
        frame_.attrs.update(step=f["step"], time=f["time"],
                            units={"i": "", "j": "", "normal_force": "N", "tangential_force": "N", "branch_x": "m",
                                   "branch_y": "m", "branch_z": "m"})
        return frame_
