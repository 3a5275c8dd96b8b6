"""The boat service for a stock MAVLink autopilot (`serve --boat-protocol standard`).

It is the usv-link boat service (services/boat.py: missions derived from the boat's
reports, runs, commands that end within a bounded time, the same `GET /api/boat`, store,
monitor and console) on a `StandardLink` (link/standard_link.py). What differs is what a
stock autopilot can do, docs/link.md "Standard MAVLink":

- an upload is the standard mission protocol followed by a read-back; the mission is
  "verified" only when the vehicle's copy is identical;
- START arms and sets GUIDED (the station streams the timed plan's position targets) or
  AUTO (the uploaded mission at its leg speeds); HOLD, RESUME and ABORT are mode changes
  (ABORT also disarms);
- no timed hot swap (no TIMESYNC-aligned boat clock): a re-plan stays a plan, and an
  upload while the vehicle runs is refused;
- the link is signed only once the vehicle signs its own frames (SETUP_SIGNING); until
  then `GET /api/boat` says plainly that it is unsigned.
"""

from __future__ import annotations

from usvstation.link.standard_link import StandardLink
from usvstation.records import BoatSnapshot, MissionView
from usvstation.services.boat import BoatService
from usvstation.services.errors import Conflict

UNSIGNED = ("unsigned link: the vehicle does not sign its frames, so anyone with a radio "
            "on this link can command the boat")
SIGNING_PENDING = ("unsigned link: SETUP_SIGNING sent, the vehicle does not sign yet; "
                   "until it does anyone with a radio on this link can command the boat")


class StandardBoatService(BoatService):
    """BoatService on a stock autopilot: same interface, standard protocols underneath."""

    swap_mission = None  # type: ignore[assignment]  # no timed hot swap (monitor reads it)

    async def create_mission(self, plan_id: str,
                             swap_at_ms: int | None = None) -> MissionView:
        link = self._require_link()
        report = link.report
        if report is not None and report.state in ("RUNNING", "GO_AROUND"):
            raise Conflict(f"the vehicle is {report.state}: a stock autopilot has no timed "
                           "hot swap; ABORT, then upload")
        if swap_at_ms:
            raise Conflict("a stock autopilot has no timed hot swap")
        return await super().create_mission(plan_id, 0)

    def snapshot(self) -> BoatSnapshot:
        snap = super().snapshot()
        link = self.link
        info = snap["link"]
        info["protocol"] = "standard"
        info["profile"] = self.settings.vehicle_profile
        if isinstance(link, StandardLink):
            p = link.protocol
            info["signed"] = p.signed
            info["warning"] = None if p.signed else (
                SIGNING_PENDING if p.key is not None and p.profile.signing else UNSIGNED)
            info["vehicle_mode"] = p.mode_name
            info["armed"] = p.status.armed
        return snap
