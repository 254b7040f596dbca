"""Each problem with the output path or the study file has its own, true message (one line from
the command line, exit code 2) and leaves no temporary file behind."""
import os

import h5py
import pytest

from viscocontact.cli import main
from viscocontact.studies import StudyFileError, Sweep, load_study, run, storage
from viscocontact.testing.scenes import WAVY

SCENE = WAVY


@pytest.fixture
def scene(tmp_path):
    path = tmp_path / "wavy.toml"
    path.write_text(SCENE)
    return path


def one_line_error(capsys, code):
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and "Traceback" not in err[0], err
    return err[0]


def no_leftovers(folder):
    return not [p.name for p in folder.rglob("*") if p.name.endswith((".tmp", ".lock"))]


@pytest.mark.parametrize("extra", [[], ["--force"], ["--resume"]])
def test_output_is_a_folder(tmp_path, scene, capsys, extra):
    folder = tmp_path / "results"
    folder.mkdir()
    code = main(["sweep", str(scene), "--zetas", "1", "--quiet", "--out", str(folder), *extra])
    err = one_line_error(capsys, code)
    assert "results is a folder: the study file needs a file name" in err
    assert "wavy.toml" not in err and "exists" not in err
    assert no_leftovers(tmp_path) and list(folder.iterdir()) == []


def test_output_in_a_missing_folder(tmp_path, scene, capsys):
    out = tmp_path / "nowhere" / "s.h5"
    err = one_line_error(capsys, main(["sweep", str(scene), "--zetas", "1", "--quiet",
                                       "--out", str(out)]))
    assert f"the folder {out.parent} does not exist" in err and "None" not in err


def test_output_below_a_file(tmp_path, scene, capsys):
    (tmp_path / "afile").write_text("x")
    out = tmp_path / "afile" / "s.h5"
    err = one_line_error(capsys, main(["sweep", str(scene), "--zetas", "1", "--quiet",
                                       "--out", str(out)]))
    assert "afile is not a folder" in err


def test_output_in_a_folder_without_write_permission(tmp_path, adhesionless, monkeypatch):
    real = os.access
    monkeypatch.setattr(os, "access", lambda p, mode: False if str(p) == str(tmp_path)
                        else real(p, mode))
    with pytest.raises(StudyFileError, match=f"no permission to create files in {tmp_path}"):
        run(Sweep(scene=adhesionless, zetas=[1.0]), tmp_path / "s.h5", progress=None)


def test_a_failed_header_write_leaves_no_temporary_file(tmp_path, adhesionless, monkeypatch):
    def fail(*args, **kwargs):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(storage, "_layout", fail)
    with pytest.raises(StudyFileError, match="cannot write .*s.h5: No space left on device"):
        storage.create(tmp_path / "s.h5", Sweep(scene=adhesionless, zetas=[1.0]))
    assert list(tmp_path.iterdir()) == []


def test_resume_of_a_missing_file_names_it(tmp_path, capsys):
    err = one_line_error(capsys, main(["sweep", "--resume", "--out",
                                       str(tmp_path / "gone.h5"), "--quiet"]))
    assert err.endswith(f"no such file: {tmp_path / 'gone.h5'}")


@pytest.mark.parametrize("command", [["plot"], ["sweep", "--resume", "--quiet", "--out"]])
def test_a_truncated_study_file_is_called_truncated(tmp_path, adhesionless, capsys, command):
    path = tmp_path / "s.h5"
    storage.create(path, Sweep(scene=adhesionless, zetas=[1.0]))
    data = path.read_bytes()
    path.write_bytes(data[: len(data) // 2])
    err = one_line_error(capsys, main([*command, str(path)]))
    assert f"s.h5 is truncated: it has {len(data) // 2} of its {len(data)} bytes" in err
    assert "lock" not in err and "another process" not in err


@pytest.mark.parametrize("content,fragment", [
    (b"", "not a readable HDF5 file: it is empty"),
    (b"x" * 100, "not a readable HDF5 file: its 100 bytes have no HDF5 signature"),
])
def test_not_hdf5(tmp_path, capsys, content, fragment):
    path = tmp_path / "s.h5"
    path.write_bytes(content)
    assert fragment in one_line_error(capsys, main(["plot", str(path)]))


@pytest.mark.parametrize("below", ["", "sub"])
def test_study_output_is_a_file(tmp_path, capsys, below):
    (tmp_path / "afile").write_text("x")
    out = tmp_path / "afile" / below
    err = one_line_error(capsys, main(["study", "--out", str(out), "--quiet"]))
    assert "--out" in err and f"({tmp_path / 'afile'} is a file)" in err


@pytest.mark.parametrize("below", ["", "sub"])
def test_plot_output_is_a_file(tmp_path, adhesionless, capsys, below):
    storage.create(tmp_path / "s.h5", Sweep(scene=adhesionless, zetas=[1.0]))
    (tmp_path / "afile").write_text("x")
    err = one_line_error(capsys, main(["plot", str(tmp_path / "s.h5"), "--out",
                                       str(tmp_path / "afile" / below)]))
    assert "a folder for the PNG files" in err and "afile is a file" in err


def test_a_study_file_made_unreadable_mid_read_is_damaged(tmp_path, adhesionless, monkeypatch):
    path = tmp_path / "s.h5"
    storage.create(path, Sweep(scene=adhesionless, zetas=[1.0]))
    real = h5py.Dataset.__getitem__

    def broken(self, key):
        if self.name == "/points/area":
            raise OSError("Can't synchronously read data (len not positive after adjustment "
                          "for EOA)")
        return real(self, key)

    monkeypatch.setattr(h5py.Dataset, "__getitem__", broken)
    with pytest.raises(StudyFileError, match="s.h5 is damaged: Can't synchronously read"):
        load_study(path)
