#!/usr/bin/env python3
"""Generate the usv-link 2 codecs from protocol/usv_recovery.xml with pymavlink's mavgen.

Writes (never edit them by hand):
  backend/usvstation/link/mavlink/usv_recovery.py   Python codec (MAVLink 2, signing)
  protocol/c/mavlink/                               C headers (mavgen's C generator)

mavgen resolves `<include>common.xml</include>` next to the dialect, so the run copies
the dialect together with common.xml, standard.xml and minimal.xml of the installed
(pinned, see pyproject.toml) pymavlink into a temporary directory. The C generator stamps
the build date into version.h; it is replaced by a fixed text so the output depends on the
definitions and the pymavlink version only.

`python protocol/generate.py` rewrites the output; `--check` exits 1 naming every stale
file (tests/unit/test_protocol_generated.py runs it).
"""

from __future__ import annotations

import argparse
import contextlib
import filecmp
import io
import re
import shutil
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DIALECT = ROOT / "protocol" / "usv_recovery.xml"
PY_OUT = ROOT / "backend" / "usvstation" / "link" / "mavlink" / "usv_recovery.py"
C_OUT = ROOT / "protocol" / "c" / "mavlink"
INCLUDES = ("common.xml", "standard.xml", "minimal.xml")
PYMAVLINK_VERSION = "2.4.50"
BUILD_DATE = re.compile(r'#define MAVLINK_BUILD_DATE "[^"]*"')


def _generate(out: Path) -> tuple[Path, Path]:
    """Run mavgen for Python and C into `out`; return (python module, C directory)."""
    import pymavlink
    from pymavlink.generator import mavgen

    version = getattr(pymavlink, "__version__", None)
    if version is None:
        from importlib.metadata import version as dist_version

        version = dist_version("pymavlink")
    if version != PYMAVLINK_VERSION:
        raise SystemExit(f"generate.py: pymavlink {version} installed, the codecs are pinned to "
                         f"{PYMAVLINK_VERSION} (pip install -e '.[dev]')")
    dialects = Path(pymavlink.__file__).parent / "dialects" / "v20"
    src = out / "xml"
    src.mkdir()
    for name in INCLUDES:
        shutil.copy(dialects / name, src / name)
    xml = src / DIALECT.name
    shutil.copy(DIALECT, xml)
    py = out / "py" / "usv_recovery.py"
    py.parent.mkdir()
    c_dir = out / "c"
    for lang, target in (("Python3", py.with_suffix("")), ("C", c_dir)):
        opts = mavgen.Opts(str(target), wire_protocol="2.0", language=lang, validate=True,
                           strict_units=False)
        with contextlib.redirect_stdout(io.StringIO()) as log:
            ok = mavgen.mavgen(opts, [str(xml)])
        if not ok:
            sys.stderr.write(log.getvalue())
            raise SystemExit(f"generate.py: mavgen ({lang}) failed on {DIALECT}")
    for header in c_dir.rglob("version.h"):
        text = header.read_text()
        header.write_text(BUILD_DATE.sub(
            f'#define MAVLINK_BUILD_DATE "pymavlink {PYMAVLINK_VERSION}"', text))
    return py, c_dir


def _tree(root: Path) -> dict[str, Path]:
    return {p.relative_to(root).as_posix(): p for p in sorted(root.rglob("*")) if p.is_file()}


def stale_files() -> list[str]:
    """Every generated file that differs from a fresh run (or is missing or extra)."""
    with tempfile.TemporaryDirectory() as tmp:
        py, c_dir = _generate(Path(tmp))
        stale = []
        if not PY_OUT.exists() or not filecmp.cmp(py, PY_OUT, shallow=False):
            stale.append(str(PY_OUT.relative_to(ROOT)))
        fresh, have = _tree(c_dir), _tree(C_OUT) if C_OUT.exists() else {}
        for rel in sorted(set(fresh) | set(have)):
            if rel not in fresh or rel not in have or \
                    not filecmp.cmp(fresh[rel], have[rel], shallow=False):
                stale.append(str((C_OUT / rel).relative_to(ROOT)))
        return stale


def write() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        py, c_dir = _generate(Path(tmp))
        PY_OUT.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(py, PY_OUT)
        init = PY_OUT.parent / "__init__.py"
        if not init.exists():
            init.write_text('"""Generated MAVLink codec of usv-link 2 (protocol/generate.py)."""\n')
        if C_OUT.exists():
            shutil.rmtree(C_OUT)
        shutil.copytree(c_dir, C_OUT)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="exit 1 if any output is stale")
    args = ap.parse_args(argv)
    if args.check:
        stale = stale_files()
        for rel in stale:
            print(f"stale: {rel} (run python protocol/generate.py)", file=sys.stderr)
        return 1 if stale else 0
    write()
    return 0


if __name__ == "__main__":
    sys.exit(main())
