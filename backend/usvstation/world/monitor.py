"""Plan monitor (pure): where the boat will be, how close it will pass, and when to alert.

At every telemetry frame `assess` takes the running plan (ramp frame, ship-fixed), the
boat's real position and velocity, and the targets (ramp-frame position and velocity
relative to the ramp), and predicts:

- progress: the plan time tau of the point of the plan nearest the boat, the schedule slip
  (elapsed - tau, > 0 behind) and the cross-track distance to that point;
- the boat's path: the rest of the plan from tau, delayed by the slip, starting from the
  boat's real position (the offset fades out over `rejoin_s`);
- per target: the minimum hull clearance over the horizon (centre distance - target
  radius - half the hull, the water the plan's `min_clearance_m` measures) and when;
  DCPA/TCPA of the present motion (vector form of paper 001 eq. 10-11, as corrected in
  shared/notes/seeds-digest.md 2.3) and the COLREGs encounter class.

`AlertTracker` turns values into advisory/caution/warning/alarm levels with hysteresis: a
level is entered as soon as its threshold is crossed and left only once the value is back
past the threshold by the hysteresis band, so a value wobbling at a threshold alerts once.
Each condition (kind, target) is one alert that changes level in place and ends when the
condition clears (IEC 62923 / MSC.302(87): one alert per cause); a rise is announced (it
asks for attention: sound, acknowledgement) unless the same or a higher level of that
condition was announced less than `REPEAT_S` ago.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from usvstation.geometry import position_at

Level = Literal["advisory", "caution", "warning", "alarm"]
LEVELS: tuple[Level, ...] = ("advisory", "caution", "warning", "alarm")
REPEAT_S = 30.0  # a condition's level is not announced again within this time
STATIC_SPEED = 0.2  # m/s over ground: a target slower than this is static (a buoy, a wreck)
Encounter = Literal["head-on", "overtaking-give-way", "overtaking-stand-on",
                    "crossing-give-way", "crossing-stand-on", "none"]


@dataclass(frozen=True)
class MonitorConfig:
    horizon_s: float = 120.0
    dt_s: float = 0.5
    rejoin_s: float = 10.0  # the boat's offset from its plan fades out over this time
    clearance_margin_m: float = 1.6  # hull clearance the plan keeps: L/2 + R_c (eq. 7)
    clearance_warning_m: float = 1.0  # below this a warning: R_c, the tracking allowance
    clearance_hysteresis_m: float = 0.3
    time_margin_s: float = 5.0
    slip_hysteresis_s: float = 0.5
    cross_track_m: tuple[float, float, float] = (2.0, 5.0, 10.0)
    cross_track_hysteresis_m: float = 0.5


@dataclass(frozen=True)
class BoatState:
    """The boat in the ramp frame: position, velocity relative to the ramp, plan time."""

    x: float
    y: float
    vx: float
    vy: float
    elapsed_s: float  # time since the plan started
    heading_deg: float | None = None  # ramp frame; used when the boat is (almost) stopped


@dataclass(frozen=True)
class TargetState:
    id: str
    x: float
    y: float
    vx: float  # relative to the ramp
    vy: float
    radius: float
    known: bool = False  # the running plan was made around it (a scenario obstacle)
    moving: bool = True  # it makes way over ground (faster than STATIC_SPEED)


@dataclass(frozen=True)
class TargetAssessment:
    id: str
    min_clearance_m: float  # predicted over the rest of the plan (within the horizon)
    t_min_s: float  # seconds from now to that minimum
    dcpa_m: float
    tcpa_s: float
    encounter: Encounter
    known: bool = False
    moving: bool = True


@dataclass(frozen=True)
class Assessment:
    plan_time_s: float
    slip_s: float
    cross_track_m: float
    path: np.ndarray  # (S, 3): x, y, seconds from now
    targets: list[TargetAssessment]

    @property
    def min_clearance_m(self) -> float | None:
        return min((t.min_clearance_m for t in self.targets), default=None)


def dcpa_tcpa(p: tuple[float, float], w: tuple[float, float]) -> tuple[float, float]:
    """DCPA (m) and TCPA (s) of a target at relative position p with relative velocity w.

    TCPA = -(p.w)/|w|^2 (> 0 approaching), DCPA = |p x w|/|w|; |w| ~ 0: (|p|, 0).
    """
    w2 = w[0] * w[0] + w[1] * w[1]
    if w2 < 1e-12:
        return math.hypot(*p), 0.0
    tcpa = -(p[0] * w[0] + p[1] * w[1]) / w2
    return abs(p[0] * w[1] - p[1] * w[0]) / math.sqrt(w2), tcpa


def encounter(p: tuple[float, float], own_v: tuple[float, float], tgt_v: tuple[float, float],
              own_heading_deg: float | None = None) -> Encounter:
    """COLREGs situation from the own vessel's view (rules 13-15), in a frame with angles
    counter-clockwise (the ramp frame or ENU); p = target - own, velocities over ground.

    Sectors: head-on within 15 degrees of the bow on a reciprocal course (within 15);
    overtaking from more than 22.5 degrees abaft the beam (112.5..247.5 relative);
    crossing from starboard: give way; from port: stand on.
    """
    own_speed, tgt_speed = math.hypot(*own_v), math.hypot(*tgt_v)
    if own_speed > 0.05:
        psi_o = math.degrees(math.atan2(own_v[1], own_v[0]))
    elif own_heading_deg is not None:
        psi_o = own_heading_deg
    else:
        return "none"
    beta = (psi_o - math.degrees(math.atan2(p[1], p[0]))) % 360.0  # clockwise from the bow
    if tgt_speed > 0.05:
        psi_t = math.degrees(math.atan2(tgt_v[1], tgt_v[0]))
        gamma = (psi_t - psi_o + 180.0) % 360.0 - 180.0
        beta_t = (psi_t - math.degrees(math.atan2(-p[1], -p[0]))) % 360.0  # own from target
        if (beta <= 15.0 or beta >= 345.0) and abs(gamma) >= 165.0:
            return "head-on"
        if 112.5 < beta_t < 247.5 and (beta <= 67.5 or beta >= 292.5) and own_speed > tgt_speed:
            return "overtaking-give-way"
        if 112.5 < beta < 247.5 and tgt_speed > own_speed and (beta_t <= 67.5
                                                               or beta_t >= 292.5):
            return "overtaking-stand-on"
    if 0.0 < beta <= 112.5:
        return "crossing-give-way"
    if 247.5 <= beta < 360.0:
        return "crossing-stand-on"
    return "none"


def plan_progress(wx: np.ndarray, wy: np.ndarray, wt: np.ndarray, x: float, y: float,
                  elapsed: float) -> tuple[float, float]:
    """(tau, cross-track): plan time of the plan point nearest the boat and the distance.

    Ties between passes of a path near itself go to the point nearest the schedule
    (distance + 0.1 m per second off schedule).
    """
    if len(wt) == 1:
        return float(wt[0]), math.hypot(x - wx[0], y - wy[0])
    ax, ay, bx, by = wx[:-1], wy[:-1], wx[1:], wy[1:]
    dx, dy = bx - ax, by - ay
    seg2 = dx * dx + dy * dy
    u = np.where(seg2 > 0, ((x - ax) * dx + (y - ay) * dy) / np.where(seg2 > 0, seg2, 1), 0.0)
    u = np.clip(u, 0.0, 1.0)
    px, py = ax + u * dx, ay + u * dy
    dist = np.hypot(x - px, y - py)
    tau = wt[:-1] + u * (wt[1:] - wt[:-1])
    i = int(np.argmin(dist + 0.1 * np.abs(tau - elapsed)))
    return float(tau[i]), float(dist[i])


def assess(waypoints: np.ndarray, boat: BoatState, targets: list[TargetState],
           vessel_length: float, config: MonitorConfig = MonitorConfig(),
           frame_velocity: tuple[float, float] = (0.0, 0.0)) -> Assessment:
    """Predict the boat's path and its clearance to every target (see the module docstring).

    `waypoints` is (N, 3) x, y, t of the running plan in the ramp frame; `frame_velocity`
    the ramp's own ground velocity in ramp axes (for the encounter class, which is judged
    on velocities over ground).
    """
    wx, wy, wt = waypoints[:, 0], waypoints[:, 1], waypoints[:, 2]
    tau, xte = plan_progress(wx, wy, wt, boat.x, boat.y, boat.elapsed_s)
    slip = boat.elapsed_s - tau
    remaining = max(0.0, min(float(wt[-1]) - tau, config.horizon_s))
    s = np.arange(0.0, remaining + config.dt_s, config.dt_s)
    s[-1] = min(s[-1], remaining)
    px, py = position_at(wt, wx, wy, tau + s)
    fade = np.clip(1.0 - s / config.rejoin_s, 0.0, 1.0) if config.rejoin_s > 0 else s * 0.0
    px = px + (boat.x - px[0]) * fade
    py = py + (boat.y - py[0]) * fade
    out: list[TargetAssessment] = []
    if targets:
        tx = np.array([t.x for t in targets])[:, None] + np.array([t.vx for t in targets])[
            :, None] * s[None, :]
        ty = np.array([t.y for t in targets])[:, None] + np.array([t.vy for t in targets])[
            :, None] * s[None, :]
        radius = np.array([t.radius for t in targets])[:, None]
        clear = np.hypot(tx - px[None, :], ty - py[None, :]) - radius - vessel_length / 2.0
        k = np.argmin(clear, axis=1)
        fvx, fvy = frame_velocity
        for i, t in enumerate(targets):
            p = (t.x - boat.x, t.y - boat.y)
            dcpa, tcpa = dcpa_tcpa(p, (t.vx - boat.vx, t.vy - boat.vy))
            out.append(TargetAssessment(
                id=t.id, min_clearance_m=float(clear[i, k[i]]), t_min_s=float(s[k[i]]),
                dcpa_m=dcpa, tcpa_s=tcpa,
                encounter=encounter(p, (boat.vx + fvx, boat.vy + fvy),
                                    (t.vx + fvx, t.vy + fvy), boat.heading_deg),
                known=t.known, moving=t.moving))
    return Assessment(tau, slip, xte, np.column_stack([px, py, s]), out)


# --- alerts ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class AlertEvent:
    """A condition (kind, target) changed level: `level` None when it ended. `announce`: the
    change asks for attention (a new alert, or a rise not announced within REPEAT_S)."""

    level: Level | None
    kind: str
    message: str
    target_id: str | None = None
    announce: bool = True
    rose: bool = True  # the level went up (False: down, or ended)


def level_of(value: float, thresholds: tuple[float, ...], current: int,
             hysteresis: float) -> int:
    """The new level index (-1 none, 0 advisory, 1 caution, 2 warning, 3 alarm) for `value`,
    where larger is worse and thresholds rise (inf: no such level); going down needs a margin
    of `hysteresis`."""
    up = max((i for i, th in enumerate(thresholds) if value >= th), default=-1)
    down = max((i for i, th in enumerate(thresholds) if value >= th - hysteresis), default=-1)
    return max(up, min(current, down))


@dataclass
class Condition:
    """One alert condition's state: its level (-1: clear) and what was last announced."""

    level: int = -1
    announced: int = -1
    announced_t: float = -math.inf


@dataclass
class AlertTracker:
    """One alert per (kind, target): levels with hysteresis, events on every change."""

    config: MonitorConfig = field(default_factory=MonitorConfig)
    conditions: dict[tuple[str, str | None], Condition] = field(default_factory=dict)

    @property
    def levels(self) -> dict[tuple[str, str | None], int]:
        """The active conditions and their level index."""
        return {k: c.level for k, c in self.conditions.items() if c.level >= 0}

    def step(self, kind: str, target: str | None, value: float,
             thresholds: tuple[float, ...], hysteresis: float, message: str,
             t: float = 0.0) -> AlertEvent | None:
        """One condition's value against its thresholds at station time t; an event if its
        level changed (None when it did not)."""
        key = (kind, target)
        cond = self.conditions.setdefault(key, Condition())
        new = level_of(value, thresholds, cond.level, hysteresis)
        if new == cond.level:
            return None
        rose, cond.level = new > cond.level, new
        if new < 0:
            return AlertEvent(None, kind, message, target, announce=False, rose=False)
        announce = rose and (new > cond.announced or t - cond.announced_t >= REPEAT_S)
        if announce:
            cond.announced, cond.announced_t = new, t
        return AlertEvent(LEVELS[new], kind, message, target, announce=announce, rose=rose)

    def end(self, kind: str, target: str | None, message: str) -> AlertEvent | None:
        """End a condition whatever its value (its target is gone); None if it was clear."""
        cond = self.conditions.get((kind, target))
        if cond is None or cond.level < 0:
            return None
        cond.level = -1
        return AlertEvent(None, kind, message, target, announce=False, rose=False)

    def forget(self, t: float) -> None:
        """Drop clear conditions announced longer than REPEAT_S ago."""
        for key in [k for k, c in self.conditions.items()
                    if c.level < 0 and t - c.announced_t >= REPEAT_S]:
            del self.conditions[key]

    def update(self, a: Assessment, t: float = 0.0) -> list[AlertEvent]:
        """Alert changes from this assessment at station time t (predicted clearance, collision
        course, slip, cross-track); the conditions of targets no longer seen end."""
        c = self.config
        m, w = c.clearance_margin_m, c.clearance_warning_m
        events: list[AlertEvent | None] = []
        seen = set()
        for g in a.targets:
            seen.add(g.id)
            events.append(self.step(
                "clearance", g.id, -g.min_clearance_m, (-2 * m, -m, -w, 0.0),
                c.clearance_hysteresis_m, clearance_message(g, m), t))
            # on the present course: only a target that makes way over ground (a buoy the
            # ship sails past is no collision course) and that the plan was not made around
            # (its own obstacles: the plan turns away from them, `clearance` watches them);
            # a warning only when the plan's predicted path does not clear it either
            on_course = g.moving and not g.known and 0.0 < g.tcpa_s < c.horizon_s
            top = -w if g.min_clearance_m < m else math.inf
            events.append(self.step(
                "collision_course", g.id, -g.dcpa_m if on_course else -math.inf,
                (-2 * m, -m, top), c.clearance_hysteresis_m,
                f"{g.id}: on a collision course, DCPA {g.dcpa_m:.1f} m in {g.tcpa_s:.0f} s "
                f"({g.encounter})", t))
        for kind, target in [k for k, cond in self.conditions.items()
                             if k[1] is not None and k[1] not in seen and cond.level >= 0]:
            events.append(self.end(kind, target, f"{target}: no longer tracked"))
        tm = c.time_margin_s
        events.append(self.step(
            "slip", None, abs(a.slip_s), (0.25 * tm, 0.5 * tm, tm), c.slip_hysteresis_s,
            f"schedule slip {a.slip_s:+.1f} s ({'behind' if a.slip_s > 0 else 'ahead'}; "
            f"time margin {tm:.1f} s)", t))
        events.append(self.step(
            "cross_track", None, a.cross_track_m, c.cross_track_m,
            c.cross_track_hysteresis_m, f"cross-track {a.cross_track_m:.1f} m off the plan", t))
        self.forget(t)
        return [e for e in events if e is not None]


def clearance_message(g: TargetAssessment, margin: float) -> str:
    """`ais:1: predicted clearance 1.2 m in 14 s (plan margin 1.6 m)`; contact, now."""
    what = "contact" if g.min_clearance_m <= 0 else f"{g.min_clearance_m:.1f} m"
    when = "now" if g.t_min_s < 0.5 else f"in {g.t_min_s:.0f} s"
    return f"{g.id}: predicted clearance {what} {when} (plan margin {margin:.1f} m)"
