"""A real browser on the page (Playwright + Debian's Chromium): progress in order, cancel, every
control in the request, an ambiguity choice that re-plans, downloads, and a shared link.

Runs where `playwright` (pip) and Chromium (`apt-get install chromium`) are installed; skipped with
a message elsewhere. No browser is downloaded.
"""

from __future__ import annotations

import json
import shutil
import time

import pytest

pytest.importorskip("fastapi", reason="the web app needs the [web] extra (fastapi); it is not installed")
uvicorn = pytest.importorskip("uvicorn", reason="the web app needs uvicorn; it is not installed")
sync_api = pytest.importorskip(
    "playwright.sync_api", reason="playwright is not installed (pip install playwright)"
)
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
if CHROMIUM is None:
    pytest.skip("Chromium is not installed (apt-get install chromium)", allow_module_level=True)

from serving import served  # noqa: E402

from nl2hltl2plan.web.app import create_app  # noqa: E402

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync"]  # fmt: skip
INSTRUCTION = "Put the apple in the fridge. Then put the mug in the cabinet."
HARD = (
    "Put the plates, mugs and utensils in the lower rack in any order; after that, first the saucers, "
    "then the cups, in the upper rack."
)


@pytest.fixture(scope="module")
def server():
    with served(create_app(workers=1)) as base:
        yield base


@pytest.fixture(scope="module")
def browser():
    with sync_api.sync_playwright() as pw:
        b = pw.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        yield b
        b.close()


@pytest.fixture
def page(browser, server):
    p = browser.new_page(viewport={"width": 1200, "height": 900}, accept_downloads=True)
    errors: list[str] = []
    p.on("pageerror", lambda e: errors.append(str(e)))
    p.goto(server)
    p.wait_for_selector("#examples button")
    yield p
    p.close()
    assert errors == [], errors


def plan(page, instruction: str | None = None, click: str = "#go") -> None:
    """Plan and wait for the plan (not for its pictures: the next plan cancels their drawing)."""
    if instruction is not None:
        page.fill("#instruction", instruction)
    before = page.evaluate("() => document.body.dataset.job || ''")
    page.click(click)
    shown = (
        "(old) => { const d = document.body.dataset; return d.job && d.job !== old && d.result === d.job; }"
    )
    page.wait_for_function(shown, arg=before)


def test_progress_in_order_pictures_and_downloads(page):
    page.fill("#robots", "2")
    plan(page, INSTRUCTION)
    page.wait_for_function("() => document.getElementById('message').textContent.startsWith('done')")
    stages = page.eval_on_selector_all("#stages li", "lis => lis.map(li => li.dataset.stage)")
    assert stages == ["language", "specification", "planning", "execution"]
    assert "expansions" in page.inner_text("#stages li[data-stage=planning]")
    assert "travel" in page.inner_text("#summary")
    page.wait_for_selector("#downloads a")
    loaded = (
        "(id) => { const i = document.getElementById(id); return i && i.complete && i.naturalWidth > 0; }"
    )
    page.wait_for_function(loaded, arg="ganttimg")
    page.wait_for_function(loaded, arg="httimg")
    links = page.eval_on_selector_all("#downloads a", "as => as.map(a => a.href)")
    assert len(links) == 12  # result, spec json and HOA, four pictures in two formats, the zip
    for href in links:
        res = page.request.get(href)
        assert res.ok and len(res.body()) > 100, href
    with page.expect_download() as download:
        page.click("#downloads a:text('all (zip)')")
    assert download.value.suggested_filename.endswith(".zip")
    inked = page.evaluate(
        "() => { const c = document.getElementById('map'); const d = c.getContext('2d')"
        ".getImageData(0, 0, c.width, c.height).data; let n = 0;"
        " for (let k = 3; k < d.length; k += 4) if (d[k]) n++; return n; }"
    )
    assert inked > 100  # the robots and their paths are drawn over the world picture


# the server's cancel has an in-process twin (test_api.py::test_deadline_and_cancel_end_the_worker); the
# default run keeps one browser test per page flow that has none (docs/reliability.md, rule 3)
@pytest.mark.sweep
def test_cancel_stops_the_work_on_the_server(page, server):
    page.fill("#robots", "5")
    page.select_option("#mode", "exact")
    page.fill("#instruction", HARD)
    page.click("#go")
    page.wait_for_selector("#stages li[data-stage=planning]")
    page.click("#cancel")
    page.wait_for_function("() => document.getElementById('message').textContent.startsWith('cancelled')")
    deadline = time.time() + 10
    while page.request.get(f"{server}/api/status").json()["running"]:
        assert time.time() < deadline, "the worker still runs after cancel"
        time.sleep(0.1)
    page.fill("#instruction", "put the statue in the fridge")  # a refusal is one red sentence
    page.click("#go")
    page.wait_for_selector("#message.error")
    assert "no Statue in demo" in page.inner_text("#message")


def test_every_control_changes_the_request(page, tmp_path):
    bodies: list[dict] = []

    def capture(route):
        bodies.append(json.loads(route.request.post_data))
        route.fulfill(status=503, content_type="application/json", body='{"error": "captured"}')

    page.route("**/api/plan/stream", capture)

    def sent() -> dict:
        page.click("#go")
        page.wait_for_function("() => document.getElementById('message').textContent.includes('captured')")
        page.evaluate("() => { document.getElementById('message').textContent = ''; }")
        return bodies[-1]

    base = sent()
    changes = {
        "#world": ("select", "tabletop", "world", "tabletop"),
        "#robots": ("fill", "3", "robots", 3),
        "#objective": ("select", "minmax", "objective", "minmax"),
        "#mode": ("select", "exact", "mode", "exact"),
        "#backend": ("select", "grammar", "backend", "grammar"),
        "#timeout": ("fill", "17", "timeout_s", 17),
        "#instruction": ("fill", "Put the mug in the sink.", "instruction", "Put the mug in the sink."),
    }
    for selector, (how, value, key, expected) in changes.items():
        assert base[key] != expected
        (page.select_option if how == "select" else page.fill)(selector, value)
        assert sent()[key] == expected, selector
    assert base["partial"] is False
    page.check("#partial")
    assert sent()["partial"] is True
    page.select_option("#teamkind", "profiles")
    page.fill("#profiles", "robot1, robot5")
    body = sent()
    assert body["profiles"] == ["robot1", "robot5"] and "robots" not in body
    team = [{"name": "arm", "skills": ["PickupObject", "PutObject"], "mass_capacity": 2}]
    (tmp_path / "team.json").write_text(json.dumps(team))
    page.select_option("#teamkind", "file")
    page.set_input_files("#teamfile", str(tmp_path / "team.json"))
    page.wait_for_function("() => document.getElementById('message').textContent.includes('read')")
    assert sent()["team"] == team


# twin: test_api.py::test_an_ambiguity_choice_replans (the same choice re-planned, in process)
@pytest.mark.sweep
def test_an_ambiguity_choice_replans(page):
    plan(page, "Put the utensils in the lower rack.")
    first = json.loads(page.text_content("#json"))
    candidates = page.eval_on_selector_all("#choice0 option", "os => os.map(o => o.value)")
    assert candidates[0] == "" and len(candidates) >= 3  # "any of them", then the scene types
    pick = candidates[2]  # not the top-ranked type
    page.select_option("#choice0", pick)
    plan(page, click="#replan")
    second = json.loads(page.text_content("#json"))
    assert second["tasks"][0]["object"] == [pick] != first["tasks"][0]["object"]
    assert "choices=" in page.url


def test_a_shared_link_reproduces_the_plan(page, browser):
    page.fill("#robots", "2")
    page.select_option("#objective", "minmax")
    plan(page, INSTRUCTION)
    link, first = page.url, json.loads(page.text_content("#json"))
    other = browser.new_page()
    try:
        other.goto(link)  # the link alone: it fills the form and plans
        other.wait_for_function("() => document.body.dataset.result")
        second = json.loads(other.text_content("#json"))
        assert other.input_value("#robots") == "2" and other.input_value("#objective") == "minmax"
    finally:
        other.close()
    assert second["plan"] == first["plan"] and second["planner"]["objective"] == "minmax"
    recent = page.eval_on_selector_all("#recent a", "as => as.map(a => a.href)")
    assert recent[0] == link  # the page keeps the links of the last plans
