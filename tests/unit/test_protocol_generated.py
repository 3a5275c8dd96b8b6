"""The generated MAVLink codecs (Python and C) match protocol/usv_recovery.xml."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _generate_module():
    spec = importlib.util.spec_from_file_location("usv_generate", ROOT / "protocol" / "generate.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules["usv_generate"] = mod
    spec.loader.exec_module(mod)
    return mod


def test_generated_codecs_are_fresh():
    stale = _generate_module().stale_files()
    assert stale == [], f"run python protocol/generate.py; stale: {stale}"


def test_dialect_ids_in_the_documented_range():
    from usvstation.link.mavlink import usv_recovery as mav

    ours = [cls for cls in mav.mavlink_map.values() if cls.msgname.startswith("USV_")]
    assert sorted(c.msgname for c in ours) == sorted([
        "USV_MISSION_BEGIN", "USV_MISSION_ITEM", "USV_MISSION_ACK", "USV_MISSION_END",
        "USV_MISSION_STATE", "USV_MISSION_READ", "USV_RAMP_POSE", "USV_GUIDANCE", "USV_THRUST"])
    assert all(44000 <= c.id <= 44049 for c in ours)
    cmds = [mav.MAV_CMD_USV_START, mav.MAV_CMD_USV_HOLD, mav.MAV_CMD_USV_RESUME,
            mav.MAV_CMD_USV_ABORT]
    assert all(44100 <= c <= 44149 for c in cmds)
