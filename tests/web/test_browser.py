"""A browser types an instruction into the page and sees the pictures (Playwright + Debian's Chromium).

Runs where `playwright` (pip) and Chromium (`apt-get install chromium`, /usr/bin/chromium) are
installed; skipped with a message elsewhere. No browser is downloaded.
"""

from __future__ import annotations

import shutil
import socket
import threading
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

from nl2hltl2plan.web.app import create_app  # noqa: E402


@pytest.fixture(scope="module")
def server():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    srv = uvicorn.Server(uvicorn.Config(create_app(), host="127.0.0.1", port=port, log_level="warning"))
    thread = threading.Thread(target=srv.run, daemon=True)
    thread.start()
    deadline = time.time() + 20
    while not srv.started and time.time() < deadline:
        time.sleep(0.05)
    assert srv.started, "the server did not start"
    yield f"http://127.0.0.1:{port}"
    srv.should_exit = True
    thread.join(timeout=10)


def test_type_an_instruction_and_see_the_pictures(server):
    with sync_api.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, headless=True, args=["--no-sandbox"])
        try:
            page = browser.new_page()
            page.goto(server)
            page.wait_for_selector(
                "#world option[value='demo'], #world option:text('demo')", state="attached"
            )
            page.fill("#instruction", "Put the apple in the fridge. Then put the mug in the cabinet.")
            page.fill("#robots", "2")
            page.click("#go")
            loaded = (
                "(id) => { const i = document.getElementById(id); return i.complete && i.naturalWidth > 0; }"
            )
            page.wait_for_function(loaded, arg="gantt", timeout=30000)
            page.wait_for_function(loaded, arg="htt", timeout=30000)
            assert "travel cost" in page.inner_text("#summary")
            assert "task1 =" in page.inner_text("#spec")
            # the map canvas has been drawn on: some pixels are not blank
            inked = page.evaluate(
                "() => { const c = document.getElementById('map'); const d = c.getContext('2d')"
                ".getImageData(0, 0, c.width, c.height).data; let n = 0;"
                " for (let k = 3; k < d.length; k += 4) if (d[k]) n++; return n; }"
            )
            assert inked > 1000
            page.wait_for_function("() => document.getElementById('now').textContent.startsWith('t = ')")
            # a word several scene types fit is said, with its candidates
            page.fill("#instruction", "Put the utensils in the lower rack.")
            page.click("#go")
            page.wait_for_function("() => document.getElementById('status').textContent.includes('could be')")
            assert "'utensils' (object of A) could be" in page.inner_text("#status")
            # a bad request shows its message
            page.fill("#instruction", "put the statue in the fridge")
            page.click("#go")
            page.wait_for_selector("#status.error")
            assert "no Statue in demo" in page.inner_text("#status")
        finally:
            browser.close()
