"""The image (Dockerfile, .dockerignore) and the README's docker lines.

Without a Docker engine the Dockerfile is checked by reading it and by running what it runs:
the build context .dockerignore leaves, the stages' COPY sources in it, and the healthcheck's
own command against a station that is ok and one that is degraded. Where an engine runs, the
README's lines build the image and run it (skipped, with the reason, where none does).
"""

from __future__ import annotations

import http.server
import json
import re
import shlex
import shutil
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCKERFILE = (ROOT / "Dockerfile").read_text()


def _instructions() -> list[tuple[str, str]]:
    """(INSTRUCTION, arguments) of the Dockerfile, continuation lines joined."""
    text = re.sub(r"\\\n", " ", DOCKERFILE)
    out = []
    for line in text.splitlines():
        line = line.strip()
        if line and not line.startswith("#"):
            word, _, rest = line.partition(" ")
            out.append((word.upper(), rest.strip()))
    return out


def _pattern(p: str) -> re.Pattern[str]:
    out, i, p = "", 0, p.strip("/")
    while i < len(p):
        if p.startswith("**", i):
            out, i = out + ".*", i + 2
        elif p[i] == "*":
            out, i = out + "[^/]*", i + 1
        elif p[i] == "?":
            out, i = out + "[^/]", i + 1
        else:
            out, i = out + re.escape(p[i]), i + 1
    return re.compile(out + r"\Z")


def build_context() -> list[str]:
    """The tracked files Docker sends as the build context: .dockerignore's patterns in
    order, the last that matches a path or one of its parents decides, `!` keeps."""
    rules = [(line.startswith("!"), _pattern(line.lstrip("!")))
             for line in (ROOT / ".dockerignore").read_text().splitlines()
             if line.strip() and not line.startswith("#")]
    files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                           check=True).stdout.split()
    kept = []
    for f in files:
        parts = f.split("/")
        paths = ["/".join(parts[:i]) for i in range(1, len(parts) + 1)]
        excluded = False
        for keep, rule in rules:
            if any(rule.match(p) for p in paths):
                excluded = not keep
        if not excluded:
            kept.append(f)
    return kept


def test_the_bases_are_pinned_by_digest_and_the_station_runs_as_a_user():
    steps = _instructions()
    bases = [args.split()[0] for word, args in steps if word == "FROM"]
    assert len(bases) == 3
    for base in bases:
        assert re.fullmatch(r"[a-z0-9./-]+:[\w.-]+@sha256:[0-9a-f]{64}", base), base
    runtime = steps[max(i for i, (w, _) in enumerate(steps) if w == "FROM"):]
    users = [args for word, args in runtime if word == "USER"]
    assert users and users[-1] not in ("root", "0")
    assert [args for word, args in steps if word == "EXPOSE"] == ["8000"]  # no viser port
    assert [args for word, args in runtime if word == "ENTRYPOINT"] == [
        '["usv-station", "serve"]']


def test_the_build_context_holds_what_the_stages_copy_and_nothing_else():
    context = build_context()
    tops = {f.split("/")[0] for f in context}
    assert tops == {"pyproject.toml", "README.md", "backend", "frontend"}, tops
    assert not [f for f in context if "__pycache__" in f or f.startswith(("tests/", ".git"))]
    for word, args in _instructions():
        if word != "COPY" or args.startswith("--from"):
            continue
        *sources, _ = args.split()
        for src in sources:
            assert any(f == src or f.startswith(src.rstrip("/") + "/") for f in context), src


def _healthcheck() -> list[str]:
    (args,) = [args for word, args in _instructions() if word == "HEALTHCHECK"]
    return json.loads(args[args.index("CMD") + 3:].strip())


class _Health(http.server.BaseHTTPRequestHandler):
    status = "ok"

    def do_GET(self) -> None:
        body = json.dumps({"status": type(self).status, "reasons": []}).encode()
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def log_message(self, *args: object) -> None:
        pass


@pytest.mark.parametrize(("status", "code"), [("ok", 0), ("degraded", 1), (None, 1)])
def test_the_healthcheck_fails_on_degraded(status, code):
    cmd = _healthcheck()
    assert cmd[0] == "python"
    if status is None:  # nothing listens: unhealthy too
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            port = s.getsockname()[1]
        server = None
    else:
        handler = type("Health", (_Health,), {"status": status})
        server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        port = server.server_address[1]
        threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        done = subprocess.run([sys.executable, *cmd[1:]], capture_output=True, timeout=60,
                              env={"USV_STATION_PORT": str(port), "PATH": "/usr/bin:/bin"})
    finally:
        if server is not None:
            server.shutdown()
            server.server_close()
    assert done.returncode == code, done.stderr


def readme_docker_lines() -> list[str]:
    text = (ROOT / "README.md").read_text()
    block = text[text.index("## Docker"):]
    block = block[block.index("```sh") + 5:]
    block = block[:block.index("```")]
    return [line.split("  #")[0].strip() for line in re.sub(r"\\\n\s*", " ", block).splitlines()
            if line.strip()]


def test_the_readme_publishes_only_the_stations_port():
    lines = readme_docker_lines()
    assert lines[0] == "docker build -t usv-station ."
    runs = [line for line in lines if line.startswith("docker run")]
    assert runs
    for line in runs:
        ports = re.findall(r"-p (\S+)", line)
        assert all(p.endswith(":8000") for p in ports), line


def _docker_unavailable() -> str | None:
    if shutil.which("docker") is None:
        return "no docker command on this machine"
    info = subprocess.run(["docker", "info"], capture_output=True, text=True)
    if info.returncode != 0:
        return f"no Docker engine answers: {info.stderr.strip()[:200]}"
    return None


def test_the_readme_docker_lines_build_and_run_the_station(tmp_path):
    why = _docker_unavailable()
    if why is not None:
        pytest.skip(why)
    lines = readme_docker_lines()
    subprocess.run(shlex.split(lines[0]), cwd=ROOT, check=True, timeout=3600)
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    name = f"usv-station-test-{port}"
    run = shlex.split(next(line for line in lines if line.startswith("docker run")))
    run = [a.replace("8000:8000", f"{port}:8000").replace("usv-data:", f"usv-test-{port}:")
           for a in run]
    run[2:2] = ["-d", "--name", name]
    run.remove("--rm")
    subprocess.run(run, check=True, timeout=120)
    try:
        deadline = time.monotonic() + 300
        state = ""
        while state != "healthy":
            assert time.monotonic() < deadline, f"container is {state!r}"
            state = subprocess.run(["docker", "inspect", "-f", "{{.State.Health.Status}}",
                                    name], capture_output=True, text=True).stdout.strip()
            time.sleep(1)
        import httpx

        health = httpx.get(f"http://127.0.0.1:{port}/api/health", timeout=30).json()
        assert health["status"] == "ok" and health["link_up"]
        user = subprocess.run(["docker", "exec", name, "id", "-u"], capture_output=True,
                              text=True).stdout.strip()
        assert user != "0"
    finally:
        subprocess.run(["docker", "rm", "-f", name], capture_output=True)
        subprocess.run(["docker", "volume", "rm", f"usv-test-{port}"], capture_output=True)
