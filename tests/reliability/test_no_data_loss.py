"""Issue 25, item 1: no data loss. Files are replaced atomically (a kill leaves the old or the new file),
`train language` never writes into the installed package and the loader prefers its output, and
`--batch-out` never overwrites a file."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.errors import DataError
from nl2hltl2plan.io import atomic_path, read_json, save_figure, write_json
from nl2hltl2plan.language.learned import slot_model
from nl2hltl2plan.language.learned.inference import load_model
from nl2hltl2plan.language.llm.batch import BatchCollector

SRC = str(Path(slot_model.__file__).parents[3])


def test_a_failed_write_leaves_the_old_file_and_no_temporary(tmp_path: Path) -> None:
    target = tmp_path / "result.json"
    write_json(target, {"old": True})
    with pytest.raises(RuntimeError), atomic_path(target) as tmp:
        tmp.write_text('{"new": tr')  # torn
        raise RuntimeError("killed half-way")
    assert read_json(target) == {"old": True}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["result.json"]


def test_a_process_killed_while_writing_leaves_a_whole_file(tmp_path: Path) -> None:
    """A child rewrites a 2 MB JSON file in a loop; SIGKILL at any moment leaves valid JSON."""
    target = tmp_path / "big.json"
    write_json(target, {"round": -1, "rows": []})
    code = (
        "import sys; from nl2hltl2plan.io import write_json\n"
        "k = 0\n"
        "while True:\n"
        "    write_json(sys.argv[1], {'round': k, 'rows': list(range(300000))}); k += 1\n"
    )
    env = {**os.environ, "PYTHONPATH": SRC}
    for delay in (0.3, 0.45, 0.6):
        child = subprocess.Popen([sys.executable, "-c", code, str(target)], env=env)
        time.sleep(delay)
        child.send_signal(signal.SIGKILL)
        child.wait()
        data = json.loads(target.read_text())  # never torn
        assert data["rows"] in ([], list(range(300000)))


def test_pictures_are_written_atomically(tmp_path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure()
    out = save_figure(fig, tmp_path / "p.svg")
    plt.close(fig)
    assert out.read_text().lstrip().startswith("<?xml")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.svg"]


def test_train_writes_to_the_user_cache_by_default(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    written: list[Path] = []
    from nl2hltl2plan.language.learned import request_units, structure_train, train

    def record(out: Path, seed: int = 0) -> str:  # stands in for minutes of training
        written.append(out)
        return "trained"

    monkeypatch.setattr(train, "train_and_report", record)
    monkeypatch.setattr(structure_train, "train_and_report", record)
    monkeypatch.setattr(request_units, "train_and_report", record)
    assert main(["train", "language"]) == 0
    models = tmp_path / "nl2hltl2plan" / "models"
    # the structure first (the slot model's ranker reads with it)
    assert written == [models / f"{m}_model.npz" for m in ("structure", "slot", "request")]
    assert slot_model.packaged_model_path() not in written
    written.clear()
    assert main(["train", "language", "--only", "structure"]) == 0
    assert written == [models / "structure_model.npz"]


def test_the_loader_prefers_the_user_model_and_names_a_damaged_one(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    user = slot_model.user_model_path()
    assert slot_model.default_model_path() == slot_model.packaged_model_path()
    user.parent.mkdir(parents=True)
    shutil.copy(slot_model.packaged_model_path(), user)
    assert slot_model.default_model_path() == user
    slot_model.SlotModel.load()  # the copy loads
    user.write_bytes(b"")  # what a kill during the old in-place write left behind
    with pytest.raises(DataError, match=r"cannot read the learned language model .*slot_model\.npz"):
        slot_model.SlotModel.load()
    load_model.cache_clear()
    try:
        assert main(["plan", "put the plates in the lower rack", "--llm", "offline"]) == 2
        err = capsys.readouterr().err
        assert str(user) in err and "Traceback" not in err
    finally:
        load_model.cache_clear()


def test_model_save_is_atomic(tmp_path: Path) -> None:
    model = slot_model.SlotModel.load(slot_model.packaged_model_path())
    out = tmp_path / "m.npz"
    model.save(out)
    assert out.read_bytes() == slot_model.packaged_model_path().read_bytes()  # deterministic bytes
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.npz"]


def test_batch_out_never_overwrites(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    existing = tmp_path / "batch.jsonl"
    existing.write_text("precious\n")
    argv = ["plan", "put the plates in the lower rack", "--llm", "openai", "--batch-out", str(existing)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "exists already" in err and str(existing) in err
    assert existing.read_text() == "precious\n"


def test_batch_file_is_complete_or_absent(tmp_path: Path) -> None:
    batch = BatchCollector()
    batch.add("k1", {"model": "m", "messages": []})
    out = tmp_path / "b.jsonl"
    assert batch.write(out) == 1
    assert json.loads(out.read_text())["custom_id"] == "k1"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["b.jsonl"]
