"""Transports on a real pty pair: FdStream <-> pyserial-asyncio, and the fault injector."""

from __future__ import annotations

import asyncio
import time

from usvstation.link import messages as m
from usvstation.link.codec import Encoder, FrameDecoder
from usvstation.link.transport import FaultInjectingStream, PtyPair, SerialStream


async def _collect(stream, n_bytes: int, timeout: float) -> bytes:
    buf = b""
    end = time.monotonic() + timeout
    while len(buf) < n_bytes and time.monotonic() < end:
        try:
            buf += await asyncio.wait_for(stream.read(), max(0.01, end - time.monotonic()))
        except TimeoutError:
            break
    return buf


def test_bytes_cross_the_pty_both_ways_and_pacing_follows_the_baud_rate():
    async def main():
        pair = PtyPair()
        station = await SerialStream.open(pair.slave_path, 9600)
        boat = FaultInjectingStream(pair.master_stream(), baud=9600)
        frames = Encoder().encode_many(m.GuidanceSetpoint(i, i, i) for i in range(96))
        t0 = time.monotonic()
        await boat.write(frames)
        got = await _collect(station, len(frames), 5.0)
        elapsed = time.monotonic() - t0
        assert got == frames
        assert elapsed >= len(frames) * 10 / 9600 * 0.95  # paced at 960 bytes/s
        await station.write(b"\x00hello\x00")
        assert await _collect(boat, 7, 2.0) == b"\x00hello\x00"
        await station.close()
        await boat.close()
        pair.close()

    asyncio.run(main())


def test_fault_injector_drops_whole_frames_and_flips_bits():
    async def main():
        pair = PtyPair()
        station = await SerialStream.open(pair.slave_path, 57600)
        lossy = FaultInjectingStream(pair.master_stream(), loss=0.3, seed=5)
        msgs = [m.Heartbeat(m.DEFINITION_CRC, 1, 2, 0, 0, 0, i, i) for i in range(1000)]
        for chunk in range(0, 1000, 50):
            await lossy.write(Encoder(chunk).encode_many(msgs[chunk : chunk + 50]))
        got = await _collect(station, lossy.frames_sent * 23, 5.0)
        dec = FrameDecoder()
        out = dec.feed(got)
        assert len(out) == lossy.frames_sent == 1000 - lossy.frames_dropped
        assert 250 <= lossy.frames_dropped <= 350
        assert dec.stats.errors == 0 and out == [x for x in msgs if x in out]
        noisy = FaultInjectingStream(lossy.inner, ber=1e-3, seed=6)
        await noisy.write(Encoder().encode_many(msgs))
        got = await _collect(station, 23000, 5.0)
        dec = FrameDecoder()
        out = dec.feed(got)
        assert noisy.bits_flipped > 100
        assert dec.stats.errors > 50 and len(out) + dec.stats.errors >= 900
        assert all(x in msgs for x in out)  # corrupted frames are dropped, never delivered
        await station.close()
        await noisy.close()
        pair.close()

    asyncio.run(main())
