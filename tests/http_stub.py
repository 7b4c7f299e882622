"""The tests' fake LLM servers run here: a handler class served on a free port of this machine, in a
background thread, so each test writes only what its server answers (`from http_stub import ...`:
tests/ is on the path, as the folder of the top conftest)."""

from __future__ import annotations

import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer


def start_server(handler: type[BaseHTTPRequestHandler]) -> ThreadingHTTPServer:
    """`handler` served on 127.0.0.1 (its port: `server.server_address[1]`) until `stop_server`; a
    request still running does not keep the test process alive."""
    server = ThreadingHTTPServer(("127.0.0.1", 0), handler)
    server.daemon_threads = True
    threading.Thread(target=server.serve_forever, args=(0.05,), daemon=True).start()
    return server


def stop_server(server: ThreadingHTTPServer) -> None:
    server.shutdown()
    server.server_close()
