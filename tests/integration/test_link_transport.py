"""Transports on a real pty pair: FdStream <-> pyserial-asyncio, and the fault injector."""

from __future__ import annotations

import asyncio
import time

from usvstation.link import wire
from usvstation.link.transport import FaultInjectingStream, PtyPair, SerialStream

KEY = bytes(range(32))


async def _collect(stream, n_bytes: int, timeout: float) -> bytes:
    buf = b""
    end = time.monotonic() + timeout
    while len(buf) < n_bytes and time.monotonic() < end:
        try:
            buf += await asyncio.wait_for(stream.read(), max(0.01, end - time.monotonic()))
        except TimeoutError:
            break
    return buf


def _heartbeats(n: int) -> tuple[list[bytes], wire.Codec]:
    tx = wire.Codec(1, 1, KEY, timestamp=wire.signing_time(1.7e9))
    return [tx.encode(tx.mav.heartbeat_encode(11, 0, 0, i, 4)) for i in range(n)], tx


def test_bytes_cross_the_pty_both_ways_and_pacing_follows_the_baud_rate():
    async def main():
        pair = PtyPair()
        station = await SerialStream.open(pair.slave_path, 9600)
        boat = FaultInjectingStream(pair.master_stream(), baud=9600)
        frames = b"".join(_heartbeats(96)[0])
        t0 = time.monotonic()
        await boat.write(frames)
        got = await _collect(station, len(frames), 10.0)
        elapsed = time.monotonic() - t0
        assert got == frames
        assert elapsed >= len(frames) * 10 / 9600 * 0.95  # paced: a lower bound only
        await station.write(b"hello")
        assert await _collect(boat, 5, 2.0) == b"hello"
        await station.close()
        await boat.close()
        pair.close()

    asyncio.run(main())


def test_fault_injector_drops_whole_frames_and_corrupted_ones_never_decode():
    async def main():
        pair = PtyPair()
        station = await SerialStream.open(pair.slave_path, 57600)
        lossy = FaultInjectingStream(pair.master_stream(), loss=0.3, seed=5)
        frames, _ = _heartbeats(1000)
        got = b""
        size = len(frames[0])
        for chunk in range(0, 1000, 50):  # no faster than the reader: the pty keeps 4 kB
            await lossy.write(b"".join(frames[chunk:chunk + 50]))
            got += await _collect(station, lossy.frames_sent * size - len(got), 5.0)
        assert lossy.inner.dropped == 0
        rx = wire.Codec(255, 190, KEY)
        out, refused = rx.feed(got)
        assert len(out) == lossy.frames_sent == 1000 - lossy.frames_dropped
        assert 250 <= lossy.frames_dropped <= 350
        assert refused == [] and rx.refused == {}
        kept = [m.custom_mode for m in out]
        assert kept == sorted(kept)  # whole frames dropped, the rest in order
        noisy = FaultInjectingStream(lossy.inner, ber=1e-3, seed=6)
        more, _ = _heartbeats(1000)
        got = b""
        for chunk in range(0, 1000, 50):
            await noisy.write(b"".join(more[chunk:chunk + 50]))
            got += await _collect(station, 50 * size, 2.0)
        rx = wire.Codec(255, 190, KEY)
        out, _ = rx.feed(got)
        assert noisy.bits_flipped > 100
        assert sum(rx.refused.values()) > 50
        assert all(m.get_type() == "HEARTBEAT" and m.type == 11 for m in out)
        await station.close()
        await noisy.close()
        pair.close()

    asyncio.run(main())


def test_udp_frames_cross_one_per_datagram_and_udpin_answers_its_peer():
    """udpin://HOST:PORT listens and answers whoever spoke last; udp://HOST:PORT sends to
    it from an ephemeral port; a write of several frames is one datagram per frame."""
    import socket

    from usvstation.link.transport import open_stream

    async def main():
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
            s.bind(("127.0.0.1", 0))
            port = s.getsockname()[1]
        server = await open_stream(f"udpin://127.0.0.1:{port}")
        client = await open_stream(f"udp://127.0.0.1:{port}")
        try:
            await server.write(b"lost")  # nobody has spoken yet: dropped, no error
            frames = _heartbeats(3)[0]
            await client.write(b"".join(frames))
            got = [await asyncio.wait_for(server.read(), 5.0) for _ in frames]
            assert got == frames  # one datagram each
            await server.write(frames[0])
            assert await asyncio.wait_for(client.read(), 5.0) == frames[0]
        finally:
            await client.close()
            await server.close()
        assert await server.read() == b""

    asyncio.run(main())
