"""Ship-input sources: URL parsing, and real UDP, TCP and pty (serial) sources."""

from __future__ import annotations

import asyncio
import os
import socket

import pytest

from usvstation.link.transport import PtyPair
from usvstation.shipinputs.readers import Source, open_udp, parse_source, run_stream_source

HDT = b"$HEHDT,271.5,T*2E\r\n"


@pytest.mark.parametrize(("url", "source"), [
    ("udp://0.0.0.0:10110", Source("udp", host="0.0.0.0", port=10110)),
    ("tcp://192.168.1.5:2000", Source("tcp", host="192.168.1.5", port=2000)),
    ("/dev/ttyUSB0", Source("serial", device="/dev/ttyUSB0", baud=4800)),
    ("serial:///dev/ttyS1?baud=38400", Source("serial", device="/dev/ttyS1", baud=38400)),
])
def test_parse_source(url: str, source: Source) -> None:
    assert parse_source(url) == source


@pytest.mark.parametrize(("url", "message"), [
    ("http://x:1", "expected udp://HOST:PORT, tcp://HOST:PORT or a serial device, "
                   "got 'http://x:1'"),
    ("udp://0.0.0.0", "'udp://0.0.0.0' needs a host and a port"),
    ("tcp://host:99999", "'tcp://host:99999' needs a host and a port"),
    ("serial:///dev/ttyS1?baud=fast", "bad baud rate in 'serial:///dev/ttyS1?baud=fast'"),
])
def test_parse_source_errors(url: str, message: str) -> None:
    with pytest.raises(ValueError) as exc:
        parse_source(url)
    assert str(exc.value) == message


def test_udp_datagram_with_two_sentences() -> None:
    async def main() -> list[bytes]:
        got: list[bytes] = []
        transport, port = await open_udp(Source("udp", "127.0.0.1", 0), got.append)
        tx = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        tx.sendto(HDT + b"\r\n" + HDT, ("127.0.0.1", port))
        tx.close()
        for _ in range(500):
            if len(got) == 2:
                break
            await asyncio.sleep(0.01)
        transport.close()
        return got

    assert asyncio.run(main()) == [HDT.strip()] * 2


def test_tcp_source_reads_lines_split_across_packets_and_reconnects() -> None:
    async def main() -> tuple[list[bytes], list[str]]:
        got: list[bytes] = []
        states: list[str] = []
        connections = 0

        async def serve(reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
            nonlocal connections
            connections += 1
            writer.write(HDT[:7])
            await writer.drain()
            await asyncio.sleep(0.05)
            writer.write(HDT[7:] + HDT)
            await writer.drain()
            writer.close()

        server = await asyncio.start_server(serve, "127.0.0.1", 0)
        port = server.sockets[0].getsockname()[1]
        task = asyncio.create_task(run_stream_source(Source("tcp", "127.0.0.1", port),
                                                     got.append, states.append))
        for _ in range(1000):
            if connections >= 2 and len(got) >= 4:
                break
            await asyncio.sleep(0.01)
        task.cancel()
        server.close()
        await server.wait_closed()
        return got, states

    import usvstation.shipinputs.readers as readers

    old, readers.RETRY_S = readers.RETRY_S, 0.05
    try:
        got, states = asyncio.run(main())
    finally:
        readers.RETRY_S = old
    assert got[:4] == [HDT.strip()] * 4
    assert states[:3] == ["open", "closed", "open"]


def test_serial_source_on_a_pty() -> None:
    async def main() -> list[bytes]:
        pair = PtyPair()
        got: list[bytes] = []
        task = asyncio.create_task(run_stream_source(
            Source("serial", device=pair.slave_path, baud=4800), got.append))
        await asyncio.sleep(0.2)
        os.write(pair.master_fd, HDT * 3)
        for _ in range(500):
            if len(got) >= 3:
                break
            await asyncio.sleep(0.01)
        task.cancel()
        with pytest.raises(asyncio.CancelledError):
            await task
        pair.close()
        return got

    assert asyncio.run(main()) == [HDT.strip()] * 3
