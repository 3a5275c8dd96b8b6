"""`StandardLink`: a stock MAVLink autopilot on the event loop (`serve --boat-protocol
standard`): usv-link's `BoatLink` (reconnects, events, requests that end within a bounded
time) around the sans-IO `StandardProtocol` (link/standard.py) instead of usv-link 2's
`StationProtocol`.

    link = StandardLink("udpin://0.0.0.0:14550", config=StandardConfig(profile=PROFILES["px4"]))
    async with link:
        await link.wait_link_up(10)
        result = await link.upload_mission(mission)        # standard upload + read-back
        outcome = await link.command("start", mission.mission_id, mission.crc)
"""

from __future__ import annotations

from usvstation.clock import REAL_CLOCK, Clock
from usvstation.link.standard import StandardConfig, StandardProtocol
from usvstation.link.station import BoatLink, StreamFactory


class StandardLink(BoatLink):
    """BoatLink whose protocol is `StandardProtocol`: the same events and requests."""

    protocol: StandardProtocol  # type: ignore[assignment]

    def __init__(self, url: str | None = None, *, baud: int = 57600,
                 stream_factory: StreamFactory | None = None,
                 config: StandardConfig | None = None, reconnect_s: float = 1.0,
                 key: bytes | None = None, session: int | None = None,
                 clock: Clock = REAL_CLOCK) -> None:
        config = config or StandardConfig(baud=baud)
        super().__init__(url, baud=baud, stream_factory=stream_factory, config=config,
                         reconnect_s=reconnect_s, key=key, session=session, clock=clock)
        self.protocol = StandardProtocol(config, self._now(), key=key, unix_time=clock.unix(),
                                         session=session)

    @property
    def signed(self) -> bool:
        """Signed both ways: the vehicle's frames arrive signed (SETUP_SIGNING took)."""
        return self.protocol.signed
