"""A headless Chromium driven over the DevTools protocol on a pipe (``--remote-debugging-pipe``, standard
library only), for the tests that look at the browsable report as its reader does."""

from __future__ import annotations

import base64
import json
import os
import select
import shutil
import subprocess
import tempfile
import time

# The Debian package's name of the browser, and the other names it goes by.
NAMES = ("chromium", "chromium-browser", "google-chrome")
MISSING = ("no headless Chromium on this machine: install it (Debian/Ubuntu: apt-get install chromium) "
           "to see the browsable report as its reader does")


def executable() -> str | None:
    """The path of the first Chromium found on the PATH, or None."""
    return next((path for path in map(shutil.which, NAMES) if path), None)


class Browser:
    """One headless Chromium with one page: ``call`` sends a DevTools command and returns its result,
    ``evaluate`` runs JavaScript (awaiting a promise) in the page or in one of its frames."""

    def __init__(self, width: int = 1400, height: int = 900, timeout: float = 60.0):
        path = executable()
        if path is None:
            raise RuntimeError(MISSING)
        self.timeout = timeout
        self._id = 0
        self._buffer = b""
        self._profile = tempfile.mkdtemp(prefix="chromium-")
        to_browser, self._send = os.pipe()
        self._receive, from_browser = os.pipe()
        self._process = subprocess.Popen(
            [path, "--headless", "--no-sandbox", "--disable-gpu", "--remote-debugging-pipe",
             "--allow-file-access-from-files", f"--window-size={width},{height}",
             f"--user-data-dir={self._profile}", "about:blank"],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            pass_fds=(3, 4), preexec_fn=_map_fds(to_browser, from_browser))
        os.close(to_browser)
        os.close(from_browser)
        target = self.call("Target.createTarget", url="about:blank")["targetId"]
        self._session = self.call("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]
        self.call("Page.enable")

    def call(self, method: str, **params):
        self._id += 1
        message = {"id": self._id, "method": method, "params": params}
        if method.split(".")[0] not in ("Target", "Browser"):
            message["sessionId"] = self._session
        os.write(self._send, json.dumps(message).encode() + b"\0")
        while True:
            reply = self._read()
            if reply.get("id") == self._id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply["result"]

    def wait_for(self, event: str) -> dict:
        while True:
            message = self._read()
            if message.get("method") == event:
                return message["params"]

    def open(self, url: str) -> None:
        self.call("Page.navigate", url=url)
        self.wait_for("Page.loadEventFired")

    def evaluate(self, expression: str, frame: str | None = None):
        """The value of ``expression`` (a promise awaited) in the page, or in the frame of id ``frame``."""
        params = {"expression": expression, "awaitPromise": True, "returnByValue": True}
        if frame is not None:
            world = self.call("Page.createIsolatedWorld", frameId=frame, worldName="test")
            params["contextId"] = world["executionContextId"]
        result = self.call("Runtime.evaluate", **params)
        if "exceptionDetails" in result:
            raise RuntimeError(f"{expression[:80]}...: {result['exceptionDetails']}")
        return result["result"].get("value")

    def frames(self) -> list[dict]:
        """The page's child frames (id and url), depth first."""
        found, pending = [], list(self.call("Page.getFrameTree")["frameTree"].get("childFrames", []))
        while pending:
            node = pending.pop(0)
            found.append(node["frame"])
            pending.extend(node.get("childFrames", []))
        return found

    def screenshot(self, path) -> None:
        with open(path, "wb") as file:
            file.write(base64.b64decode(self.call("Page.captureScreenshot", format="png")["data"]))

    def close(self) -> None:
        self._process.kill()
        self._process.wait()
        os.close(self._send)
        os.close(self._receive)
        shutil.rmtree(self._profile, ignore_errors=True)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _read(self) -> dict:
        deadline = time.monotonic() + self.timeout
        while b"\0" not in self._buffer:
            if time.monotonic() > deadline or self._process.poll() is not None:
                raise RuntimeError("Chromium stopped answering")
            if not select.select([self._receive], [], [], 1.0)[0]:
                continue
            chunk = os.read(self._receive, 1 << 16)
            if not chunk:
                raise RuntimeError("Chromium closed its pipe")
            self._buffer += chunk
        message, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(message)


def _map_fds(to_browser: int, from_browser: int):
    """The child's fds 3 (commands in) and 4 (replies out), as ``--remote-debugging-pipe`` expects."""
    def mapping():
        commands, replies = os.dup(to_browser), os.dup(from_browser)  # out of the way of 3 and 4 first
        os.dup2(commands, 3)
        os.dup2(replies, 4)
    return mapping
