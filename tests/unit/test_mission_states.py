"""The station's mission states come from what the boat reports (services/missions.py): a
mission the boat flies stays active through HOLD, FAILSAFE and a go-around."""

from __future__ import annotations

import pytest

from usvstation.link.protocol import MissionState
from usvstation.services.missions import MissionStatus, Seen, next_status, seen


def report(state: str, active_id: int = 7, crc: int = 99) -> MissionState:
    return MissionState(uptime_ms=1000, boot_id=1, state=state, active_id=active_id,
                        active_crc32=crc, active_count=6, current_seq=2, staging=0,
                        staged_id=0, staged_crc32=0, staged_received=0, staged_count=0,
                        swap_at_ms=0, station_session=1, rejected=0)


@pytest.mark.parametrize("state", ["RUNNING", "HOLD", "FAILSAFE", "GO_AROUND"])
def test_a_mission_under_way_stays_active(state):
    assert seen(report(state), 7, 99) == Seen.HELD_RUNNING
    assert next_status(MissionStatus.ACTIVE, seen(report(state), 7, 99)) == MissionStatus.ACTIVE


def test_done_completes_and_another_mission_makes_it_gone():
    assert next_status(MissionStatus.ACTIVE, seen(report("DONE"), 7, 99)) == \
        MissionStatus.COMPLETED
    assert next_status(MissionStatus.ACTIVE, seen(report("RUNNING", active_id=8), 7, 99)) == \
        MissionStatus.GONE
