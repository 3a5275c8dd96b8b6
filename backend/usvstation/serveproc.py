"""`usv-station serve` as a subprocess on ephemeral ports (benchmarks and end-to-end tests)."""

from __future__ import annotations

import contextlib
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

from usvstation.clock import REAL_CLOCK, Stopwatch, pause

SCRIPT = Path(sys.executable).parent / "usv-station"
START_TIMEOUT_S = 180.0  # generous: a loaded 2-core machine starts a station slowly


class ServeProcess:
    """Starts `usv-station serve --port 0 --viser-port 0` and reads the URLs it prints."""

    def __init__(self, data_dir: Path, *args: str, token: str,
                 env: dict[str, str] | None = None) -> None:
        self.data_dir, self.token = data_dir, token
        self.log = data_dir.parent / f"{data_dir.name}-serve.log"
        cmd = [str(SCRIPT), "serve", "--port", "0", "--viser-port", "0", "--data-dir",
               str(data_dir), "--token", token, *args]
        self._log = self.log.open("w")
        # its own process group: stop() ends the station with every process it started
        self.proc = subprocess.Popen(cmd, stdout=self._log, stderr=subprocess.STDOUT,
                                     env={**os.environ, "PYTHONUNBUFFERED": "1", **(env or {})},
                                     start_new_session=True)
        try:
            self.url = self._wait_for("console", r"console (http://[^/]+)/")
            self.viser_url = self._wait_for("3D view", r"3D view (http://\S+)/")
        except BaseException:  # never leave a station behind that nobody will stop
            ServeProcess.stop(self, signal.SIGKILL)  # the base's: a subclass may not be ready
            raise

    def _wait_for(self, what: str, pattern: str, timeout: float = START_TIMEOUT_S) -> str:
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
        """Send `sig`; returns the seconds until the process exited (killed after `timeout`).
        Whatever is left of its process group (plan workers, a forkserver) is killed."""
        watch = Stopwatch()
        if self.proc.poll() is None:
            self.proc.send_signal(sig)
            try:
                self.proc.wait(timeout)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        elapsed = watch.elapsed()
        with contextlib.suppress(ProcessLookupError, PermissionError):
            os.killpg(self.proc.pid, signal.SIGKILL)
        self._log.close()
        return elapsed
