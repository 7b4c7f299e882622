"""Latencies of the web app under load: long plans hold every worker while short plans queue and a
client keeps asking for light things (world geometry, status). Writes results/web_load/report.md.

    python scripts/bench_web_load.py [--clients 12] [--slow 2] [--slow-s 5] [--workers 2]

The load driver is `nl2hltl2plan.web.load.run_load` (the suite's load test uses it too).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import uvicorn

from nl2hltl2plan.web.app import create_app
from nl2hltl2plan.web.load import run_load


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--clients", type=int, default=12, help="short plans sent at once (default 12)")
    ap.add_argument("--slow", type=int, default=2, help="long plans sent first (default 2)")
    ap.add_argument("--slow-s", type=float, default=5.0, help="deadline of each long plan (default 5 s)")
    ap.add_argument("--workers", type=int, default=2, help="worker processes (default 2)")
    ap.add_argument("--out", type=Path, default=Path("results/web_load/report.md"))
    args = ap.parse_args()
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    app = create_app(workers=args.workers, queue=args.clients + args.slow)
    srv = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning"))
    thread = threading.Thread(target=srv.run, daemon=True)
    thread.start()
    while not srv.started:
        time.sleep(0.05)
    started = time.perf_counter()
    report = run_load(f"http://127.0.0.1:{port}", args.clients, args.slow, args.slow_s)
    wall = time.perf_counter() - started
    srv.should_exit = True
    thread.join(10)
    summary = report.summary()
    commit = subprocess.run(
        ["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True
    ).stdout.strip()
    load = ", ".join(f"{v:.1f}" for v in os.getloadavg())
    machine = f"{platform.machine()}, {os.cpu_count()} CPUs, Python {platform.python_version()}, load {load}"
    lines = [
        "# Web app under load",
        "",
        f"Command: `python scripts/bench_web_load.py --clients {args.clients} --slow {args.slow} "
        f"--slow-s {args.slow_s:g} --workers {args.workers}`  ",
        f"Commit: {commit}  ",
        f"Machine: {machine} (at the end; the machine was shared with other jobs)",
        "",
        f"{args.slow} long plans (5 robots, exact mode, deadline {args.slow_s:g} s) hold the {args.workers} "
        f"workers; {args.clients} short plans queue behind them; one client asks for world geometry "
        "and status in a loop meanwhile. Wall time "
        f"{wall:.1f} s.",
        "",
        "| | count | median (s) | p95 (s) | max (s) |",
        "|---|---|---|---|---|",
        f"| light requests | {summary['light_requests']} | {summary['light_s']['median']:.3f} | "
        f"{summary['light_s']['p95']:.3f} | {summary['light_s']['max']:.3f} |",
        f"| short plans (queued) | {summary['plans']} | {summary['plan_s']['median']:.2f} | | "
        f"{summary['plan_s']['max']:.2f} |",
        "",
        f"Long plans' HTTP status: {summary['slow_status']} (504: past its deadline, in one sentence).  ",
        f"Answers checked against their own request (instruction, team, objects): "
        f"{'all right' if not summary['problems'] else json.dumps(summary['problems'])}.",
    ]
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    sys.exit(1 if summary["problems"] else 0)


if __name__ == "__main__":
    main()
