"""Take the README's screenshot of the web page (docs/web.png) in headless Chromium.

    python scripts/web_screenshot.py [--out docs/web.png] [--chromium /usr/bin/chromium]

Serves the app on 127.0.0.1, plans the demo instruction for two robots through the page, moves the
time slider to the middle of the plan, points at the fridge, and saves the top of the page.
"""

from __future__ import annotations

import argparse
import socket
import threading
import time
from pathlib import Path

import uvicorn
from playwright.sync_api import sync_playwright

from nl2hltl2plan.web.app import create_app

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync"]  # fmt: skip
INSTRUCTION = (  # the README's example: both robots work under the completion-time objective
    "Put the plates, mugs and utensils in the lower rack in any order; after that, first the saucers, "
    "then the cups, in the upper rack"
)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", type=Path, default=Path("docs/web.png"))
    ap.add_argument("--chromium", default="/usr/bin/chromium")
    args = ap.parse_args()
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    srv = uvicorn.Server(uvicorn.Config(create_app(), host="127.0.0.1", port=port, log_level="warning"))
    thread = threading.Thread(target=srv.run, daemon=True)
    thread.start()
    while not srv.started:
        time.sleep(0.05)
    try:
        with sync_playwright() as pw:
            browser = pw.chromium.launch(executable_path=args.chromium, args=FLAGS)
            page = browser.new_page(viewport={"width": 1280, "height": 1120})
            page.goto(f"http://127.0.0.1:{port}/")
            page.wait_for_selector("#examples button")
            page.fill("#instruction", INSTRUCTION)
            page.fill("#robots", "2")
            page.select_option("#objective", "minmax")
            page.click("#go")
            page.wait_for_selector("#ganttimg", timeout=120_000)
            # the middle of the plan
            page.eval_on_selector(
                "#time", "s => { s.value = Math.floor(s.max / 2); s.dispatchEvent(new Event('input')); }"
            )
            fridge = page.evaluate(
                "() => { const g = worldCache['demo'], c = document.getElementById('map');"
                " const [px, pz] = projector(g, c); const o = g.objects.find(o => o.id === 'Fridge_0');"
                " const r = c.getBoundingClientRect(); return [r.left + px(o.x), r.top + pz(o.z)]; }"
            )
            page.mouse.move(*fridge)
            page.screenshot(path=str(args.out))
            browser.close()
    finally:
        srv.should_exit = True
        thread.join(10)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
