"""Domain errors the services raise when they refuse a request; the message is one sentence
for the operator. Only api/ turns them into HTTP statuses (api/app.py `HTTP_STATUS`)."""

from __future__ import annotations


class StationError(Exception):
    """A request a service refuses; nothing changed."""


class NotFound(StationError):
    """No such plan, mission, re-plan or alert."""


class Conflict(StationError):
    """The request does not fit the state the station or the boat is in."""


class MissionMismatch(Conflict):
    """The boat holds no mission, or another one than the request names."""


class BoatRefused(Conflict):
    """The boat answered the command with a refusal."""


class LinkUnavailable(StationError):
    """The boat link is down, or the boat's clock is not known yet."""


class NoAnswer(StationError):
    """The boat did not answer after the bounded retries."""


class QueueFull(StationError):
    """Too many requests already wait; try again later."""
