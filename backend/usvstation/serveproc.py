"""`usv-station serve` as a subprocess on ephemeral ports (benchmarks and end-to-end tests)."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
from pathlib import Path

from usvstation.clock import REAL_CLOCK, Stopwatch, pause

SCRIPT = Path(sys.executable).parent / "usv-station"


class ServeProcess:
    """Starts `usv-station serve --port 0 --viser-port 0` and reads the URLs it prints."""

    def __init__(self, data_dir: Path, *args: str, token: str,
                 env: dict[str, str] | None = None) -> None:
        self.data_dir, self.token = data_dir, token
        self.log = data_dir.parent / f"{data_dir.name}-serve.log"
        cmd = [str(SCRIPT), "serve", "--port", "0", "--viser-port", "0", "--data-dir",
               str(data_dir), "--token", token, *args]
        self._log = self.log.open("w")
        self.proc = subprocess.Popen(cmd, stdout=self._log, stderr=subprocess.STDOUT,
                                     env={**os.environ, "PYTHONUNBUFFERED": "1", **(env or {})})
        try:
            self.url = self._wait_for("console", r"console (http://[^/]+)/")
            self.viser_url = self._wait_for("3D view", r"3D view (http://\S+)/")
        except BaseException:  # never leave a station behind that nobody will stop
            self.stop(signal.SIGKILL)
            raise

    def _wait_for(self, what: str, pattern: str, timeout: float = 60.0) -> str:
        deadline = REAL_CLOCK.now() + timeout
        while REAL_CLOCK.now() < deadline:
            found = re.search(pattern, self.log.read_text())
            if found:
                return found.group(1)
            if self.proc.poll() is not None:
                raise RuntimeError(f"serve exited: {self.log.read_text()[-2000:]}")
            pause(0.05)
        raise RuntimeError(f"no {what} URL from serve: {self.log.read_text()[-2000:]}")

    def stop(self, sig: int = signal.SIGTERM, timeout: float = 10.0) -> float:
        """Send `sig`; returns the seconds until the process exited (killed after `timeout`)."""
        watch = Stopwatch()
        if self.proc.poll() is None:
            self.proc.send_signal(sig)
            try:
                self.proc.wait(timeout)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        self._log.close()
        return watch.elapsed()
