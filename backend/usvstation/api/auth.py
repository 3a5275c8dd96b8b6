"""Access control: two roles, operator (changes and commands) and viewer (read only).

A client proves its role with `Authorization: Bearer <token>` or with the
`usv_token` cookie, which the console receives by opening the printed
`/?token=...` URL (see `api.guard`). `api.guard.Guard` checks the token of
every `/api`, `/ws` and `/3d` request before any body is read; the
dependencies here declare the role a route needs (OpenAPI security) and
check it again, so routers of other modules reuse them:

    router = APIRouter(dependencies=[Depends(require_viewer)])
    @router.post("/x", dependencies=[Depends(require_operator)])
"""

from __future__ import annotations

from collections.abc import Mapping

from fastapi import HTTPException, Request
from fastapi.security import HTTPBearer

from usvstation.config import Role, Tokens

COOKIE = "usv_token"
_bearer = HTTPBearer(auto_error=False, description="the operator or viewer token")


def token_from_headers(headers: Mapping[str, str]) -> str | None:
    """The bearer token of the Authorization header, else the `usv_token` cookie."""
    auth = headers.get("authorization", "")
    scheme, _, value = auth.partition(" ")
    if scheme.lower() == "bearer" and value.strip():
        return value.strip()
    for part in headers.get("cookie", "").split(";"):
        name, _, value = part.strip().partition("=")
        if name == COOKIE and value:
            return value
    return None


def token_matches(expected: str, given: str | None) -> bool:
    """True when `given` is the operator token (or authentication is off)."""
    return Tokens(expected).role(given) is Role.OPERATOR


def request_role(request: Request) -> Role | None:
    tokens: Tokens = request.app.state.tokens
    return tokens.role(token_from_headers(request.headers))


UNAUTHORIZED = HTTPException(
    status_code=401,
    detail="missing or wrong bearer token (Authorization: Bearer <token>, or the cookie of the "
    "console URL that usv-station serve prints)",
    headers={"WWW-Authenticate": "Bearer"},
)


async def require_viewer(request: Request) -> Role:
    """FastAPI dependency: 401 unless the request carries the viewer or operator token."""
    await _bearer(request)  # declares the scheme in OpenAPI
    role = request_role(request)
    if role is None:
        raise UNAUTHORIZED
    return role


async def require_operator(request: Request) -> Role:
    """FastAPI dependency: 401 without a token, 403 for the viewer token."""
    role = await require_viewer(request)
    if role < Role.OPERATOR:
        raise HTTPException(status_code=403, detail="the viewer token is read only: this "
                            "needs the operator token")
    return role


require_token = require_operator  # the name earlier routes used
