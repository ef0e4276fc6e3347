"""Result.frame / particles / contacts: a run's particle frames (output.frames) read with the
engine's frame reader, against the scene's sample and the run's own final state."""
import h5py
import numpy
import pytest

import cyclic_triax as ct

# Test 1's first leg, A -> TC1 (from the shipped loose 1,000-sphere sample, 7,407 steps), with a
# frame every 2,000 steps (and at the start and the end) and the contacts of each.
FRAMES = {"stages[0].path": "[TC1]", "output.frames": {"interval": 2000, "contacts": True}}


@pytest.fixture(scope="module")
def with_frames(source, tmp_path_factory):
    return ct.run(source / "scenes/tests/test1.yaml", set=FRAMES, out=tmp_path_factory.mktemp("frames") / "r.h5")


def test_frame_particles_are_the_samples(source, with_frames):
    with h5py.File(source / "scenes/samples/loose_1k.h5") as sample:  # the scene's particles.state
        spheres, radii = sample["state/radius"].shape[0], sample["state/radius"][()]
    r = with_frames
    assert r.frames >= 2
    first, last = r.particles(0), r.particles()
    assert len(first) == len(last) == spheres == 1000  # the loose sample: a 10 x 10 x 10 lattice
    assert list(first.columns) == ["x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz", "radius", "mass"]
    assert first.attrs["step"] < last.attrs["step"] and first.attrs["units"]["x"] == "m"
    assert numpy.array_equal(first["radius"].to_numpy(), radii)  # the sample's spheres, in its order
    # The last frame is written at the run's last step: the final state (/state, read by another
    # reader, io/state_io.hpp) holds the same particles, bit for bit.
    final = r.final_state()
    assert last.attrs["step"] == final["step"]
    for column, key, k in (("x", "position", 0), ("z", "position", 2), ("vy", "velocity", 1), ("wx", "angular_velocity", 0)):
        assert numpy.array_equal(last[column].to_numpy(), final[key][:, k]), column
    assert numpy.array_equal(last["radius"].to_numpy(), final["radius"])
    assert numpy.array_equal(last["mass"].to_numpy(), final["mass"])


def test_frame_arrays_are_the_files(with_frames):
    r = with_frames
    f = r.frame(1)
    with h5py.File(r.path) as h:
        assert f["step"] == h["particles/all/position/step"][1]
        assert numpy.array_equal(f["position"], h["particles/all/position/value"][1])
        assert numpy.array_equal(f["velocity"], h["particles/all/velocity/value"][1])
        count = h["frames/contacts/count"][()]
        first = int(count[:1].sum())
        rows = slice(first, first + int(count[1]))
        assert numpy.array_equal(f["pairs"], h["frames/contacts/pairs"][rows])
        assert numpy.array_equal(f["normal_force"], h["frames/contacts/normal_force"][rows])


def test_contacts(with_frames):
    c = with_frames.contacts()
    assert list(c.columns) == ["i", "j", "normal_force", "tangential_force", "branch_x", "branch_y", "branch_z"]
    assert len(c) > 1000  # a sheared 1,000-sphere packing at 100 kPa: a coordination number above 2
    assert (c["i"] < c["j"]).all() and (c["j"] < 1000).all()
    assert (c["normal_force"] >= 0).all()
    # A branch joins two touching centres: its length is at most the sum of their radii.
    radius = with_frames.particles()["radius"].to_numpy()
    length = numpy.linalg.norm(c[["branch_x", "branch_y", "branch_z"]].to_numpy(), axis=1)
    assert (length <= radius[c["i"]] + radius[c["j"]] + 1e-12).all()


def test_no_such_frame_and_no_contacts(source, with_frames, tmp_path):
    with pytest.raises(IndexError, match="it has"):
        with_frames.frame(with_frames.frames)
    # Without output.frames a run writes a frame at its start and its end, without contacts.
    plain = ct.run(source / "scenes/tests/test1.yaml", set={"stages[0].path": "[TC1]"}, out=tmp_path / "plain.h5")
    assert plain.frames == 2 and plain.particles(0).attrs["step"] == 0
    with pytest.raises(KeyError, match="contacts: true"):
        plain.contacts()
