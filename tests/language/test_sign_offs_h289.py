"""A closing sign-off with its writer's name is frame (h289, issues 23 and 28): the frame rule drops it whole
("Night, Bo", "Night, Mr Okafor"; `handover_discourse.unsigned`, every reader's) and the assumptions say
so, or the courtesy list does ("Thanks! - Priya", `courtesy.greeted`), so the unknown-word check never
sees the name alone. A name alone as a sentence mid-message may be an unread command's object, and a
sign-off's name that is a scene thing may be one more item: neither is frame."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.language.translate import translate

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))

REQUEST = "Put the egg in the fridge, then put the mug in the sink."
READ = ["place Egg -> Fridge", "place Mug -> SinkBasin"]


def read(text: str) -> tuple[list[str], list[str], list[str]]:
    """(the tasks' summaries, what is left unread, the assumptions)."""
    from trust_sets import world_of

    res = translate(text, world_of("FloorPlan28"), build=False, actions="none")
    return [t.summary() for t in res.tasks], res.unparsed, res.assumptions


@pytest.mark.data
@pytest.mark.parametrize("sign_off", ["Night, Bo.", "Night, Mr Okafor"])
def test_a_sign_off_with_its_name_is_dropped_and_said(sign_off):
    tasks, unread, assumed = read(f"{REQUEST} {sign_off}")
    assert tasks == READ and unread == []
    assert f"'{sign_off.rstrip('.')}'" in " ".join(assumed)  # the name is dropped with it, and said


@pytest.mark.data
def test_a_listed_sign_off_with_its_name_is_dropped():
    assert read(f"{REQUEST} Thanks! - Priya")[:2] == (READ, [])


@pytest.mark.data
def test_a_name_alone_mid_message_is_never_dropped_unsaid_and_one_closing_the_message_is_frame(monkeypatch):
    from nl2hltl2plan.config.reading_settings import REQUEST_UNITS_ENV

    mid = "Put the egg in the fridge. Bo. Put the mug in the sink."
    monkeypatch.setenv(REQUEST_UNITS_ENV, "0")  # the rules alone: refused (it may be an object)
    assert any("'Bo' (words)" in u for u in read(mid)[1])
    monkeypatch.delenv(REQUEST_UNITS_ENV)  # the request-unit classifier (h287) drops it as frame, said
    tasks, unread, assumed = read(mid)
    assert unread == [] and "'Bo'" in " ".join(assumed)
    tasks, unread, assumed = read(f"{REQUEST} Bo")
    assert tasks == READ and unread == [] and "'Bo'" in " ".join(assumed)


@pytest.mark.data
def test_a_sign_off_naming_a_scene_thing_is_no_frame():
    _, unread, assumed = read("Put the egg in the fridge. Thanks, Mug")
    assert any("'Thanks, Mug' (object)" in u for u in unread) and not assumed
