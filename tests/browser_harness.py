"""Headless Chromium for the report tests: load a page, report what went wrong.

``chromium_load(url)`` starts Debian's ``/usr/bin/chromium`` headless, drives it over the DevTools
protocol on a pipe (fds 3 and 4, no port opened), loads ``url`` and returns the page's problems:
console errors and warnings, uncaught exceptions, log errors and every failed request. With
``offline=True`` the browser has no network (DNS resolves nothing and DevTools' network emulation
is offline), and ``requests`` (a list) receives the URL of every request the page made, so a test
can assert that a page asks for nothing but ``file:`` and ``data:`` URLs.

Chromium is installed by ``make system-deps``. Without it, ``needs_chromium`` skips a test with the
reason shown in pytest's summary, except under ``REQUIRE_SYSTEM_DEPS=1`` (CI), where the test runs
and fails on the missing browser.
"""

from __future__ import annotations

import base64
import fcntl
import json
import os
import select
import subprocess
import tempfile
import time
from pathlib import Path

import pytest

from tests.hang_guard import HANG_GUARD_S

CHROMIUM = Path("/usr/bin/chromium")
REQUIRED = os.environ.get("REQUIRE_SYSTEM_DEPS") == "1"

needs_chromium = pytest.mark.skipif(
    not CHROMIUM.exists() and not REQUIRED,
    reason="/usr/bin/chromium not installed (make system-deps installs Debian's chromium)",
)


def _child_fds(read_fd: int, write_fd: int) -> None:
    hi_r = fcntl.fcntl(read_fd, fcntl.F_DUPFD, 10)
    hi_w = fcntl.fcntl(write_fd, fcntl.F_DUPFD, 10)
    os.dup2(hi_r, 3)
    os.dup2(hi_w, 4)


def chromium_load(
    url: str,
    screenshot: Path | None = None,
    timeout: float = HANG_GUARD_S,
    offline: bool = False,
    requests: list[str] | None = None,
) -> list[str]:
    """Load ``url`` in headless Chromium driven over the DevTools pipe (fds 3 and 4);
    return its console errors/warnings, uncaught exceptions and failed loads, and save a
    PNG of the top of the page down to the end of ``#scoreboard`` to ``screenshot``.
    ``offline``: no network at all; ``requests``: gets the URL of every request made."""
    if not CHROMIUM.exists():
        raise FileNotFoundError(
            f"{CHROMIUM} is not installed: run `make system-deps` (Debian's chromium)"
        )
    to_chrome_r, to_chrome_w = os.pipe()
    from_chrome_r, from_chrome_w = os.pipe()
    no_network = ["--host-resolver-rules=MAP * ~NOTFOUND"] if offline else []
    with tempfile.TemporaryDirectory() as profile:
        proc = subprocess.Popen(
            [
                str(CHROMIUM),
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--disable-quic",
                "--no-first-run",
                "--disable-background-networking",
                "--disable-component-update",
                "--disable-sync",
                *no_network,
                f"--user-data-dir={profile}",
                "--hide-scrollbars",
                "--remote-debugging-pipe",
                "about:blank",
            ],  # fmt: skip
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            close_fds=False,
            preexec_fn=lambda: _child_fds(to_chrome_r, from_chrome_w),
        )
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        buf = b""
        next_id = 0
        events: list[dict] = []
        deadline = time.monotonic() + timeout

        def send(method: str, params: dict | None = None, session: str | None = None) -> int:
            nonlocal next_id
            next_id += 1
            msg = {"id": next_id, "method": method, "params": params or {}}
            if session:
                msg["sessionId"] = session
            os.write(to_chrome_w, json.dumps(msg).encode() + b"\0")
            return next_id

        def wait(pred, until: float) -> dict:
            nonlocal buf
            while True:
                while b"\0" in buf:
                    raw, buf = buf.split(b"\0", 1)
                    msg = json.loads(raw)
                    if "method" in msg:
                        events.append(msg)
                    if pred(msg):
                        return msg
                if time.monotonic() > until:
                    raise TimeoutError("no answer from chromium")
                ready, _, _ = select.select([from_chrome_r], [], [], 0.2)
                if ready:
                    chunk = os.read(from_chrome_r, 1 << 22)
                    if not chunk:
                        raise RuntimeError("chromium closed the DevTools pipe")
                    buf += chunk

        def call(method: str, params: dict | None = None, session: str | None = None) -> dict:
            i = send(method, params, session)
            reply = wait(lambda m: m.get("id") == i, deadline)
            assert "error" not in reply, reply
            return reply.get("result", {})

        try:
            target = call("Target.createTarget", {"url": "about:blank"})["targetId"]
            sid = call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
            for method in ("Runtime.enable", "Log.enable", "Page.enable", "Network.enable"):
                call(method, session=sid)
            if offline:
                call(
                    "Network.emulateNetworkConditions",
                    {"offline": True, "latency": 0, "downloadThroughput": -1,
                     "uploadThroughput": -1},
                    session=sid,
                )  # fmt: skip
            call(
                "Emulation.setDeviceMetricsOverride",
                {"width": 1400, "height": 1000, "deviceScaleFactor": 1, "mobile": False},
                session=sid,
            )
            call("Page.navigate", {"url": url}, session=sid)
            wait(lambda m: m.get("method") == "Page.loadEventFired", deadline)
            try:  # late messages
                wait(lambda m: False, time.monotonic() + 1.0)
            except TimeoutError:
                pass
            if screenshot is not None:
                bottom = call(
                    "Runtime.evaluate",
                    {
                        "expression": "(() => { const e = document.querySelector("
                        "'#scoreboard'); const l = document.querySelector('p.legend'); "
                        "const r = (l || e).getBoundingClientRect(); "
                        "return Math.ceil(r.bottom + window.scrollY + 16); })()",
                        "returnByValue": True,
                    },
                    session=sid,
                )["result"]["value"]
                shot = call(
                    "Page.captureScreenshot",
                    {
                        "format": "png",
                        "captureBeyondViewport": True,
                        "clip": {"x": 0, "y": 0, "width": 1400, "height": bottom, "scale": 1},
                    },
                    session=sid,
                )
                screenshot.parent.mkdir(parents=True, exist_ok=True)
                screenshot.write_bytes(base64.b64decode(shot["data"]))
            send("Browser.close")
        finally:
            try:
                proc.wait(timeout=15)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
            os.close(to_chrome_w)
            os.close(from_chrome_r)
    problems = []
    urls: dict[str, str] = {}  # request id -> URL
    for e in events:
        p = e["params"]
        if e["method"] == "Runtime.consoleAPICalled" and p["type"] in (
            "error",
            "warning",
            "assert",
        ):
            problems.append(f"console.{p['type']}: " + " ".join(str(a.get("value", a.get(
                "description", ""))) for a in p["args"]))  # fmt: skip
        elif e["method"] == "Runtime.exceptionThrown":
            d = p["exceptionDetails"]
            problems.append(f"exception: {d.get('exception', {}).get('description', d['text'])}")
        elif e["method"] == "Log.entryAdded" and p["entry"]["level"] in ("error", "warning"):
            problems.append(f"log.{p['entry']['level']}: {p['entry']['text']}")
        elif e["method"] == "Network.requestWillBeSent":
            urls[p["requestId"]] = p["request"]["url"]
            if requests is not None:
                requests.append(p["request"]["url"])
        elif e["method"] == "Network.loadingFailed" and not p.get("canceled"):
            where = urls.get(p["requestId"], p["requestId"])[:120]
            problems.append(f"failed request: {where}: {p['errorText']}")
    return problems
