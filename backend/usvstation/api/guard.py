"""The station's front door: a pure ASGI middleware that refuses before it works.

In this order, for every HTTP request and websocket handshake:

1. the Host header must name this station (an IP address, `localhost`, the bound
   host or one of `--allowed-hosts`): a DNS-rebinding page never gets an answer;
2. `/api` (but `/api/health`), `/ws` and `/3d` need a token: 401 without one,
   403 for the viewer token on anything but GET/HEAD/OPTIONS, decided from the
   headers alone, before one byte of the body is read;
3. a change (any method but GET/HEAD/OPTIONS) that a browser sends with an Origin, or
   else a Referer, must come from the station's own origin or one of `--allowed-origins`
   / `--cors-origins` (403): a page on another port of the same host gets the operator's
   SameSite cookie, but not a body-less POST through;
4. a request to a route that takes no body (every GET, the body-less POSTs, any unknown
   path) that announces one (beyond a token 16 bytes with a declared length: the `{}` a
   client sends with every POST) is refused with 413 at once, and none of it is read;
5. a body is read only for a route that takes one, up to `max_body_bytes` (413 as soon
   as it is exceeded, whatever Content-Length says) and within `body_timeout_s` (408);
6. a JSON body is parsed once here: not UTF-8 is 400, nested deeper than
   `MAX_JSON_DEPTH` is 400, NaN, Infinity, a number that overflows to infinity or a lone
   surrogate (text that is no Unicode) is 422 naming the field, so no route ever sees one;
7. a websocket must come from the same origin or one of `--allowed-origins`, and
   finds room under `max_ws_clients` (`/ws` and `/3d` together; else 503).

`GET /?token=T` trades the token for an HttpOnly, SameSite=Strict cookie and
redirects to `/`, so the token leaves the address bar; `RedactTokens` keeps it
out of the access log.
"""

from __future__ import annotations

import asyncio
import ipaddress
import json
import logging
import math
import re
from collections.abc import Awaitable, Callable
from dataclasses import dataclass, field
from typing import Any
from urllib.parse import parse_qsl, urlencode, urlsplit

from starlette.types import Message, Receive, Scope, Send

from usvstation.api.auth import COOKIE, Role, Tokens, token_from_headers

ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]

SAFE_METHODS = frozenset({"GET", "HEAD", "OPTIONS"})
PARSE_OFF_LOOP_BYTES = 64 * 1024
MAX_JSON_DEPTH = 32  # a scenario nests 4 levels; deeper is an attack on a recursive encoder
TOKEN_BODY_BYTES = 16  # a route without a body tolerates this much (`{}`), unread
_COOKIE_SAFE = re.compile(r"^[A-Za-z0-9._~+/=-]+$")


@dataclass
class GuardConfig:
    tokens: Tokens
    max_body_bytes: int = 1 << 20
    body_timeout_s: float = 30.0
    bound_host: str = "127.0.0.1"
    allowed_hosts: frozenset[str] = frozenset()
    allowed_origins: frozenset[str] = frozenset()  # websockets and changes
    cors_origins: frozenset[str] = frozenset()  # changes (the HTTP API's CORS origins)
    max_ws_clients: int = 64
    ws_clients: Callable[[], int] = field(default=lambda: 0)  # /ws and /3d connections
    # (method, path) -> whether a route takes a request body (default: every change does)
    takes_body: Callable[[str, str], bool] = field(
        default=lambda method, _path: method not in SAFE_METHODS)


def needed_role(path: str, method: str) -> Role | None:
    """The role a request needs from its path and method alone (None: open)."""
    if path == "/api/health" or method == "OPTIONS":
        return None  # OPTIONS: CORS preflights carry no token and return no data
    if path.startswith(("/api/", "/ws/", "/3d")) or path in ("/api", "/ws"):
        return Role.VIEWER if method in SAFE_METHODS else Role.OPERATOR
    return None


def host_allowed(host_header: str | None, cfg: GuardConfig) -> bool:
    """IP literals (which DNS rebinding cannot produce), localhost, the bound and allowed names."""
    if host_header is None:
        return True  # HTTP/1.0 without Host: no browser sends that
    host = host_header.strip().lower()
    if host.startswith("["):
        host = host[1:].partition("]")[0]
    elif host.count(":") == 1:
        host = host.partition(":")[0]
    if "*" in cfg.allowed_hosts or host in cfg.allowed_hosts:
        return True
    if host in ("localhost", cfg.bound_host.lower()):
        return True
    try:
        ipaddress.ip_address(host)
    except ValueError:
        return False
    return True


def origin_allowed(origin: str | None, host_header: str | None, cfg: GuardConfig) -> bool:
    """No Origin (not a browser), the station's own origin, or one of --allowed-origins."""
    if origin is None:
        return True
    if origin in cfg.allowed_origins or "*" in cfg.allowed_origins:
        return True
    return host_header is not None and urlsplit(origin).netloc.lower() == host_header.lower()


def first_non_finite(value: Any, path: tuple = ()) -> tuple | None:
    """The path of the first NaN or infinite number in parsed JSON, None when all are finite."""
    found = first_problem(value, path)
    return found[1] if found is not None and found[0] == "finite_number" else None


def first_problem(value: Any, path: tuple = (), max_depth: int = MAX_JSON_DEPTH
                  ) -> tuple[str, tuple] | None:
    """(kind, path) of the first thing in parsed JSON no route may see, None when it is
    clean: "depth" (nested deeper than `max_depth`), "finite_number" (NaN, infinity) or
    "unicode" (a lone surrogate, in a value or a key). Iterative: any depth is safe here."""
    stack = [(value, path)]
    while stack:
        v, p = stack.pop()
        if len(p) - len(path) > max_depth:
            return "depth", p
        if isinstance(v, float):
            if not math.isfinite(v):
                return "finite_number", p
        elif isinstance(v, str):
            if not _is_unicode(v):
                return "unicode", p
        elif isinstance(v, dict):
            for k in v:
                if not _is_unicode(k):
                    return "unicode", (*p, k)
            stack.extend((x, (*p, k)) for k, x in reversed(list(v.items())))
        elif isinstance(v, list):
            stack.extend((x, (*p, i)) for i, x in reversed(list(enumerate(v))))
    return None


def _is_unicode(text: str) -> bool:
    """False for text holding a lone surrogate (JSON allows "\\ud800"; UTF-8 does not)."""
    if text.isascii():
        return True
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


@dataclass(frozen=True)
class BodyRefusal:
    status: int
    payload: Any


def check_json_body(body: bytes) -> BodyRefusal | None:
    """Why a JSON body is refused (400 or 422 with FastAPI's shape), None when it may pass
    (invalid JSON passes: the route's own validation names the error)."""
    try:
        parsed = json.loads(body)
    except RecursionError:
        return BodyRefusal(400, {"detail": f"JSON body nested deeper than {MAX_JSON_DEPTH} "
                                           "levels"})
    except UnicodeDecodeError as exc:
        return BodyRefusal(400, {"detail": f"request body is not UTF-8: {exc.reason} at byte "
                                           f"{exc.start}"})
    except ValueError:
        return None
    found = first_problem(parsed)
    if found is None:
        return None
    kind, where = found
    name = ".".join(str(p) for p in where) or "body"
    if kind == "depth":
        return BodyRefusal(400, {"detail": f"JSON body nested deeper than {MAX_JSON_DEPTH} "
                                           f"levels (at {name})"})
    msg = (f"{name}: must be a finite number (NaN and Infinity are not)" if kind ==
           "finite_number" else f"{name}: must be Unicode text (a lone surrogate is not)")
    return BodyRefusal(422, {"detail": [{"type": kind, "loc": ["body", *where], "msg": msg,
                                         "input": None}]})


def _json_content(content_type: str) -> bool:
    """Whether FastAPI would parse a body of this type as JSON (it does when none is given)."""
    if not content_type:
        return True
    main = content_type.partition(";")[0].strip().lower()
    return main == "application/json" or (main.startswith("application/")
                                          and main.endswith("+json"))


def _origin_of(url: str) -> str | None:
    parts = urlsplit(url)
    return f"{parts.scheme}://{parts.netloc}" if parts.scheme and parts.netloc else None


def change_origin_allowed(headers: dict[str, str], cfg: GuardConfig) -> bool:
    """A change from a browser must come from the station's own origin or an allowed one:
    judged by Origin, else Referer; a client that sends neither is no browser."""
    origin = headers.get("origin")
    if origin is None and "referer" in headers:
        origin = _origin_of(headers["referer"]) or "null"
    if origin is None:
        return True
    if origin in cfg.cors_origins or "*" in cfg.cors_origins:
        return True
    return origin_allowed(origin, headers.get("host"), cfg)


class Guard:
    """The middleware; see the module docstring."""

    def __init__(self, app: ASGIApp, config: GuardConfig) -> None:
        self.app, self.cfg = app, config

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        kind = scope["type"]
        if kind not in ("http", "websocket"):
            await self.app(scope, receive, send)
            return
        headers = _headers(scope)
        host = headers.get("host")
        if kind == "websocket":
            await self._websocket(scope, receive, send, headers)
            return
        if not host_allowed(host, self.cfg):
            await _respond(send, 400, f"Host {host!r} is not allowed (see --allowed-hosts)")
            return
        method, path = scope["method"], scope["path"]
        if path == "/" and method == "GET" and b"token=" in scope.get("query_string", b""):
            await self._exchange_token(scope, send)
            return
        need = needed_role(path, method)
        if need is not None:
            role = self.cfg.tokens.role(token_from_headers(headers))
            if role is None:
                await _respond(send, 401, "missing or wrong bearer token (Authorization: "
                               "Bearer <token>, or the cookie of the console URL that "
                               "usv-station serve prints)",
                               [(b"www-authenticate", b"Bearer")])
                return
            if role < need:
                await _respond(send, 403, "the viewer token is read only: this needs the "
                               "operator token")
                return
        if method not in SAFE_METHODS and not change_origin_allowed(headers, self.cfg):
            await _respond(send, 403, "a change from another origin is refused (the "
                           "console's own origin, or --allowed-origins / --cors-origins)")
            return
        if not _announces_body(headers):
            await self.app(scope, receive, send)
            return
        if not self.cfg.takes_body(method, path):
            if not _token_body(headers):
                await _respond(send, 413, f"{method} {path} takes no request body")
                return
            await self.app(scope, receive, send)  # the route never reads it
            return
        await self._with_body(scope, receive, send, headers)

    async def _with_body(self, scope: Scope, receive: Receive, send: Send,
                         headers: dict[str, str]) -> None:
        limit = self.cfg.max_body_bytes
        declared = headers.get("content-length", "")
        if declared.isdigit() and int(declared) > limit:
            await _respond(send, 413, f"request body of {declared} bytes is over the limit of "
                           f"{limit} bytes (--max-body-bytes)")
            return
        chunks, size = [], 0
        try:
            async with asyncio.timeout(self.cfg.body_timeout_s):
                while True:
                    message = await receive()
                    if message["type"] != "http.request":
                        return  # the client went away
                    piece = message.get("body", b"")
                    size += len(piece)
                    if size > limit:
                        await _respond(send, 413, f"request body is over the limit of {limit} "
                                       "bytes (--max-body-bytes)")
                        return
                    chunks.append(piece)
                    if not message.get("more_body", False):
                        break
        except TimeoutError:
            await _respond(send, 408, f"request body not received within "
                           f"{self.cfg.body_timeout_s:g} s")
            return
        body = b"".join(chunks)
        if body and _json_content(headers.get("content-type", "")):
            refusal = (await asyncio.to_thread(check_json_body, body)
                       if len(body) > PARSE_OFF_LOOP_BYTES else check_json_body(body))
            if refusal is not None:
                await _respond_json(send, refusal.status, refusal.payload)
                return
        sent = False

        async def replay() -> Message:
            nonlocal sent
            if not sent:
                sent = True
                return {"type": "http.request", "body": body, "more_body": False}
            return await receive()

        await self.app(scope, replay, send)

    async def _exchange_token(self, scope: Scope, send: Send) -> None:
        query = parse_qsl(scope.get("query_string", b"").decode("latin-1"),
                          keep_blank_values=True)
        token = next((v for k, v in query if k == "token"), "")
        rest = urlencode([(k, v) for k, v in query if k != "token"])
        location = "/" + (f"?{rest}" if rest else "")
        tokens = self.cfg.tokens
        if not tokens.operator:
            await _respond(send, 303, "", [(b"location", location.encode())])
            return
        if tokens.role(token) is None:
            await _respond(send, 401, "wrong token in the console URL")
            return
        if not _COOKIE_SAFE.match(token):
            await _respond(send, 400, "this token cannot be kept in a cookie; use the "
                           "Authorization header")
            return
        secure = "; Secure" if scope.get("scheme") == "https" else ""
        cookie = f"{COOKIE}={token}; Path=/; HttpOnly; SameSite=Strict{secure}"
        await _respond(send, 303, "", [(b"location", location.encode()),
                                       (b"set-cookie", cookie.encode()),
                                       (b"cache-control", b"no-store")])

    async def _websocket(self, scope: Scope, receive: Receive, send: Send,
                         headers: dict[str, str]) -> None:
        host = headers.get("host")
        need = needed_role(scope["path"], "GET")
        refused = None
        if not host_allowed(host, self.cfg):
            refused = "host"
        elif need is not None and self.cfg.tokens.role(token_from_headers(headers)) is None:
            refused = "token"
        elif not origin_allowed(headers.get("origin"), host, self.cfg):
            refused = "origin"
        if refused is None and scope["path"].startswith(("/ws/", "/3d")) \
                and self.cfg.ws_clients() >= self.cfg.max_ws_clients:
            message = await receive()
            if message["type"] != "websocket.connect":
                return
            if "websocket.http.response" in scope.get("extensions", {}):
                body = f"{self.cfg.max_ws_clients} live clients already connected".encode()
                await send({"type": "websocket.http.response.start", "status": 503,
                            "headers": [(b"content-type", b"text/plain; charset=utf-8"),
                                        (b"content-length", str(len(body)).encode())]})
                await send({"type": "websocket.http.response.body", "body": body})
            else:
                await send({"type": "websocket.close", "code": 1013})
            return
        if refused is not None:
            message = await receive()
            if message["type"] == "websocket.connect":
                await send({"type": "websocket.close", "code": 1008})
            return
        await self.app(scope, receive, send)


def _token_body(headers: dict[str, str]) -> bool:
    """A body of at most TOKEN_BODY_BYTES with its length declared: the `{}` a client sends
    with every POST (the console does), which a route without a body never reads."""
    declared = headers.get("content-length", "").strip()
    return "transfer-encoding" not in headers and declared.isdigit() \
        and int(declared) <= TOKEN_BODY_BYTES


def _announces_body(headers: dict[str, str]) -> bool:
    """Whether the request says a body follows (a Content-Length above 0, or chunked)."""
    if "transfer-encoding" in headers:
        return True
    declared = headers.get("content-length", "").strip()
    return bool(declared) and (not declared.isdigit() or int(declared) > 0)


def _headers(scope: Scope) -> dict[str, str]:
    out: dict[str, str] = {}
    for k, v in scope.get("headers", []):
        name, value = k.decode("latin-1").lower(), v.decode("latin-1")
        out[name] = f"{out[name]}; {value}" if name == "cookie" and name in out else value
    return out


async def _respond(send: Send, status: int, text: str,
                   extra: list[tuple[bytes, bytes]] | None = None) -> None:
    """A FastAPI-shaped error, `{"detail": text}` (an empty body when `text` is empty)."""
    body = json.dumps({"detail": text}).encode() if text else b""
    await send({"type": "http.response.start", "status": status,
                "headers": [(b"content-type", b"application/json"),
                            (b"content-length", str(len(body)).encode()), *(extra or [])]})
    await send({"type": "http.response.body", "body": body})


async def _respond_json(send: Send, status: int, payload: Any) -> None:
    body = json.dumps(payload).encode()
    await send({"type": "http.response.start", "status": status,
                "headers": [(b"content-type", b"application/json"),
                            (b"content-length", str(len(body)).encode())]})
    await send({"type": "http.response.body", "body": body})


_TOKEN_IN_URL = re.compile(r"(token=)[^&\s\"']*")


class RedactTokens(logging.Filter):
    """Replaces `token=...` in a log record (uvicorn's access and error logs) by `token=***`."""

    def filter(self, record: logging.LogRecord) -> bool:
        if isinstance(record.args, tuple):
            record.args = tuple(_TOKEN_IN_URL.sub(r"\1***", a) if isinstance(a, str) else a
                                for a in record.args)
        if isinstance(record.msg, str) and "token=" in record.msg:
            record.msg = _TOKEN_IN_URL.sub(r"\1***", record.msg)
        return True


def install_log_redaction() -> None:
    for name in ("uvicorn.access", "uvicorn.error"):
        logger = logging.getLogger(name)
        if not any(isinstance(f, RedactTokens) for f in logger.filters):
            logger.addFilter(RedactTokens())
