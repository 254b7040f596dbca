"""The study file: layout, point-by-point appends, the loader, foreign and damaged files."""
import json

import h5py
import numpy as np
import pytest

import viscocontact
from viscocontact.errors import ValidationError
from viscocontact.scene import Scene
from viscocontact.studies import StudyFileError, Sweep, load_study, run
from viscocontact.studies import storage
from viscocontact.studies.point import COLUMNS


def fake_record(chain, step, zeta, area, fields=False):
    record = {k: (np.nan if kind == "float" else 0 if kind == "int" else False if kind == "bool"
                  else "" if kind == "str" else np.zeros(0)) for k, kind in COLUMNS.items()}
    record.update(chain=chain, step=step, phase="sweep", started_from="neighbour",
                  variant="adhesionless", seed=-1, gamma=0.0, load=0.1, zeta=zeta,
                  control="mean_pressure", target=0.1, status="converged", converged=True,
                  message="converged", area=area, n_contacts=1,
                  edges=np.array([-area / 2, area / 2]))
    record["fields"] = ({"x": np.linspace(0, 1, 5), "pressure": np.ones(5),
                         "displacement": np.zeros(5), "gap": np.zeros(5)} if fields else None)
    return record


@pytest.fixture
def sweep(adhesionless):
    return Sweep(scene=adhesionless, zetas=[0.1, 1.0, 10.0], loads=[0.1])


def test_layout_and_round_trip(tmp_path, sweep):
    path = tmp_path / "s.h5"
    storage.create(path, sweep)
    for step, zeta in enumerate(sweep.zetas[:2]):
        storage.append(path, fake_record(0, step, zeta, 0.5 + step, fields=step == 1))
    with h5py.File(path, "r") as f:
        assert f.attrs["format"] == "viscocontact.study" and f.attrs["kind"] == "sweep"
        assert f.attrs["viscocontact_version"] == viscocontact.__version__
        assert Scene.from_toml(f["scene"][()].decode()) == sweep.scene
        assert json.loads(f["study"][()])["zetas"] == [0.1, 1.0, 10.0]
        assert f["points"].attrs["count"] == 2 and set(COLUMNS) <= set(f["points"])
        assert list(f["fields"]) == ["000001"]
    data = load_study(path)
    assert data.kind == "sweep" and not data.complete and len(data) == 2
    assert data.scene == sweep.scene and data.study == sweep
    assert data.points["area"].tolist() == [0.5, 1.5]
    assert data.points["status"].tolist() == ["converged"] * 2
    assert np.array_equal(data.points["edges"][1], [-0.75, 0.75])
    assert data.fields(0) is None and np.array_equal(data.fields(1)["pressure"], np.ones(5))
    table = data.table("area")
    assert table.shape == (1, 1, 1, 3)
    assert table[0, 0, 0, :2].tolist() == [0.5, 1.5] and np.isnan(table[0, 0, 0, 2])


def test_rows_beyond_count_are_ignored_and_overwritten(tmp_path, sweep):
    path = tmp_path / "s.h5"
    storage.create(path, sweep)
    storage.append(path, fake_record(0, 0, 0.1, 0.5))
    with h5py.File(path, "r+") as f:          # a write cut short: rows resized, count not raised
        for name in ("chain", "area"):
            f["points"][name].resize((2,))
        f["points"]["area"][1] = 99.0
    assert len(load_study(path)) == 1
    storage.append(path, fake_record(0, 1, 1.0, 1.5))
    assert load_study(path).points["area"].tolist() == [0.5, 1.5]


def test_not_hdf5(tmp_path):
    path = tmp_path / "junk.h5"
    path.write_bytes(b"this is not an HDF5 file" * 10)
    with pytest.raises(StudyFileError, match="not a readable HDF5 file"):
        load_study(path)


def test_truncated(tmp_path, sweep):
    path = tmp_path / "s.h5"
    storage.create(path, sweep)
    storage.append(path, fake_record(0, 0, 0.1, 0.5))
    data = path.read_bytes()
    path.write_bytes(data[: len(data) // 3])
    with pytest.raises(StudyFileError, match=str(path.name)):
        load_study(path)


def test_foreign_hdf5(tmp_path):
    path = tmp_path / "other.h5"
    with h5py.File(path, "w") as f:
        f["x"] = np.arange(3)
        f.attrs["study"] = "wavy-zeta-sweep"
    with pytest.raises(StudyFileError, match="not a viscocontact study file"):
        load_study(path)


def test_damaged_study(tmp_path, sweep):
    path = tmp_path / "s.h5"
    storage.create(path, sweep)
    with h5py.File(path, "r+") as f:
        del f["points"]["area"]
    with pytest.raises(StudyFileError, match="damaged: /points/area is missing"):
        load_study(path)
    with h5py.File(path, "r+") as f:
        f.attrs["format_version"] = 99
    with pytest.raises(StudyFileError, match="format version 99"):
        load_study(path)


def test_missing_file(tmp_path):
    with pytest.raises(FileNotFoundError):
        load_study(tmp_path / "nope.h5")


def test_existing_file_needs_resume_or_overwrite(tmp_path, sweep):
    path = tmp_path / "s.h5"
    storage.create(path, sweep)
    with pytest.raises(StudyFileError, match="exists"):
        run(sweep, path, progress=None)


def test_resume_accepts_a_scene_stored_before_a_parameter_was_added(tmp_path, sweep):
    """A file whose stored scene lacks a parameter a component gained since (its default now
    applies) resumes; a scene that differs in a value does not."""
    path = tmp_path / "s.h5"
    storage.create(path, sweep)
    text = storage.read_header(path)["scene"]
    older = "\n".join(line for line in text.splitlines() if not line.startswith("relaxation"))
    assert older != text and Scene.from_toml(older).to_toml() == text
    with h5py.File(path, "r+") as f:
        del f["scene"]
        f["scene"] = older
    run(sweep, path, resume=True, progress=None)
    assert len(load_study(path)) == 3
    changed = older.replace("zeta = ", "zeta = 2")
    with h5py.File(path, "r+") as f:
        del f["scene"]
        f["scene"] = changed
    with pytest.raises(ValidationError, match="scene"):
        run(sweep, path, resume=True, progress=None)


def test_resume_refuses_another_study(tmp_path, sweep):
    path = tmp_path / "s.h5"
    storage.create(path, sweep)
    other = Sweep(scene=sweep.scene, zetas=[0.1, 1.0], loads=[0.1])
    with pytest.raises(ValidationError, match=r"sweep.zetas = \[0.1, 1.0\].*stored in"):
        run(other, path, resume=True, progress=None)
