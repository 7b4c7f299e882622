"""A load driver for the web app: a bounded number of concurrent plan clients, and light requests
(world geometry, status) timed meanwhile. It checks that every plan answer is the answer to its own
request (nothing lost, nothing mixed up between clients). Used by the suite's load test
(tests/web/test_load.py) and by scripts/bench_web_load.py (results/web_load/report.md).
"""

from __future__ import annotations

import http.client
import json
import statistics
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Any
from urllib.parse import urlsplit

# (instruction, robots, the object types its plan must handle): each client asks something different
CLIENT_REQUESTS = [
    ("Put the apple in the fridge.", 1, {"Apple", "Fridge"}),
    ("Put the mug in the cabinet.", 2, {"Mug", "Cabinet"}),
    ("Put the bread on the dining table.", 3, {"Bread", "DiningTable"}),
    ("Put the tomato in the fridge.", 1, {"Tomato", "Fridge"}),
    ("Put the bowl in the sink.", 2, {"Bowl", "SinkBasin"}),
    (
        "Put the apple in the fridge. Then put the mug in the cabinet.",
        2,
        {"Apple", "Fridge", "Mug", "Cabinet"},
    ),
]
SLOW = (
    "Put the plates, mugs and utensils in the lower rack in any order; after that, first the saucers, "
    "then the cups, in the upper rack."
)


@dataclass
class Answer:
    status_code: int
    text: str

    def json(self) -> Any:
        return json.loads(self.text)


class Client:
    """One client's keep-alive HTTP connection (the standard library's: no extra dependency)."""

    def __init__(self, base_url: str, timeout: float) -> None:
        url = urlsplit(base_url)
        self.conn = http.client.HTTPConnection(url.hostname or "127.0.0.1", url.port, timeout=timeout)

    def request(self, method: str, path: str, body: dict[str, Any] | None = None) -> Answer:
        data = None if body is None else json.dumps(body)
        headers = {} if body is None else {"Content-Type": "application/json"}
        self.conn.request(method, path, body=data, headers=headers)
        res = self.conn.getresponse()
        return Answer(res.status, res.read().decode())

    def get(self, path: str) -> Answer:
        return self.request("GET", path)

    def post(self, path: str, json: dict[str, Any]) -> Answer:
        return self.request("POST", path, json)

    def __enter__(self) -> Client:
        return self

    def __exit__(self, *exc: object) -> None:
        self.conn.close()


@dataclass
class LoadReport:
    plans: int = 0
    plan_s: list[float] = field(default_factory=list)
    light_s: list[float] = field(default_factory=list)
    slow_status: list[int] = field(default_factory=list)  # HTTP status of each long plan
    problems: list[str] = field(default_factory=list)

    def summary(self) -> dict[str, Any]:
        light = sorted(self.light_s)
        return {
            "plans": self.plans,
            "plan_s": {"median": statistics.median(self.plan_s), "max": max(self.plan_s)}
            if self.plan_s
            else {},
            "light_requests": len(light),
            "light_s": {
                "median": statistics.median(light),
                "p95": light[int(0.95 * (len(light) - 1))],
                "max": light[-1],
            }
            if light
            else {},  # fmt: skip
            "slow_status": sorted(self.slow_status),
            "problems": self.problems,
        }


def _plan(client: Any, k: int, report: LoadReport, lock: threading.Lock) -> None:
    instruction, robots, needed = CLIENT_REQUESTS[k % len(CLIENT_REQUESTS)]
    started = time.perf_counter()
    res = client.post("/api/plan", json={"instruction": instruction, "robots": robots, "pictures": False})
    took = time.perf_counter() - started
    with lock:
        report.plan_s.append(took)
        if res.status_code != 200:
            report.problems.append(f"client {k}: HTTP {res.status_code}: {res.text[:200]}")
            return
        out = res.json()
        steps = [s for r in (out["plan"] or {}).get("robots", []) for s in r["steps"]]
        handled = {o.rsplit("_", 1)[0] for s in steps for o in s["objects"]}
        if out["instruction"] != instruction or out["robots"] != robots or handled != needed:
            report.problems.append(
                f"client {k}: got the answer to {out['instruction']!r} for {out['robots']} robots"
            )
        report.plans += 1


def _slow(client: Any, seconds: float, report: LoadReport, lock: threading.Lock) -> None:
    body = {"instruction": SLOW, "robots": 5, "mode": "exact", "pictures": False, "timeout_s": seconds}
    res = client.post("/api/plan", json=body)
    with lock:  # a plan, or the documented answer for a request past its deadline
        report.slow_status.append(res.status_code)
        if res.status_code == 504 and "deadline" in res.json()["error"]:
            return
        if res.status_code != 200 or res.json()["instruction"] != SLOW:
            report.problems.append(f"slow client: HTTP {res.status_code}: {res.text[:200]}")


def run_load(base_url: str, clients: int = 6, slow: int = 2, slow_s: float = 3.0) -> LoadReport:
    """`slow` long plans and `clients` short ones at once (each its own connection), and light
    requests in a loop until they are all answered."""
    report, lock = LoadReport(), threading.Lock()
    done = threading.Event()

    def light() -> None:
        with Client(base_url, timeout=30) as c:
            while not done.is_set():
                for path in ("/api/worlds/demo", "/api/status"):
                    started = time.perf_counter()
                    res = c.get(path)
                    with lock:
                        report.light_s.append(time.perf_counter() - started)
                        if res.status_code != 200:
                            report.problems.append(f"light {path}: HTTP {res.status_code}")

    def client_job(fn: Any, *args: Any) -> None:
        with Client(base_url, timeout=120) as c:
            fn(c, *args, report, lock)

    watcher = threading.Thread(target=light)
    with ThreadPoolExecutor(max_workers=clients + slow) as pool:
        futures = [pool.submit(client_job, _slow, slow_s) for _ in range(slow)]
        time.sleep(0.2)  # the long plans hold the workers first
        watcher.start()
        futures += [pool.submit(client_job, _plan, k) for k in range(clients)]
        for f in futures:
            f.result()
    done.set()
    watcher.join()
    return report
