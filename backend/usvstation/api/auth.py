"""Bearer-token authentication for every request that changes state or commands the boat."""

from __future__ import annotations

import secrets

from fastapi import HTTPException, Request
from fastapi.security import HTTPAuthorizationCredentials, HTTPBearer

_bearer = HTTPBearer(auto_error=False, description="the station's access token")


def token_matches(expected: str, given: str | None) -> bool:
    if not expected:
        return True  # authentication off (loopback only, see config.resolve_token)
    return given is not None and secrets.compare_digest(given.encode(), expected.encode())


async def require_token(request: Request) -> None:
    """FastAPI dependency: 401 unless `Authorization: Bearer <token>` matches."""
    creds: HTTPAuthorizationCredentials | None = await _bearer(request)
    if not token_matches(request.app.state.token, creds.credentials if creds else None):
        raise HTTPException(
            status_code=401,
            detail="missing or wrong bearer token (Authorization: Bearer <token>)",
            headers={"WWW-Authenticate": "Bearer"},
        )
