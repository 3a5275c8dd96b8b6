"""The 3D (x, y, t) view of paper 000 Fig. 5b, served by viser.

Ramp-frame x and y are the horizontal axes; time goes up at `time_scale`
metres per second. Obstacles are cylinders over the plan's duration: upright
when static, leaning along their velocity when moving (eq. 8's oblique
cylinders). The planned path and the boat's real path (growing live from
telemetry) are lines in the same space.
"""

from __future__ import annotations

import math
import threading
import time
from typing import Any

import numpy as np

from usvstation.scenario import Scenario

CIRCLE_SIDES = 32
TRACK_REDRAW_S = 0.5  # redraw the real path at most this often


def oblique_cylinder(cx: float, cy: float, r: float, vx: float, vy: float, t_end: float,
                     time_scale: float) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and faces of a circle of radius r swept from t = 0 to t_end (eq. 8)."""
    a = np.linspace(0.0, 2.0 * math.pi, CIRCLE_SIDES, endpoint=False)
    ring = np.column_stack([r * np.cos(a), r * np.sin(a)])
    start, end = np.array([cx, cy]), np.array([cx + vx * t_end, cy + vy * t_end])
    bottom = np.column_stack([ring + start, np.zeros(CIRCLE_SIDES)])
    top = np.column_stack([ring + end, np.full(CIRCLE_SIDES, t_end * time_scale)])
    vertices = np.vstack([bottom, top, [[cx, cy, 0.0]],
                          [[cx + vx * t_end, cy + vy * t_end, t_end * time_scale]]])
    i = np.arange(CIRCLE_SIDES)
    j = (i + 1) % CIRCLE_SIDES
    n = CIRCLE_SIDES
    sides = np.concatenate([np.column_stack([i, j, n + j]), np.column_stack([i, n + j, n + i])])
    caps = np.concatenate([np.column_stack([np.full(n, 2 * n), j, i]),
                           np.column_stack([np.full(n, 2 * n + 1), n + i, n + j])])
    return vertices.astype(np.float32), np.vstack([sides, caps]).astype(np.uint32)


def polyline_segments(points: np.ndarray) -> np.ndarray:
    """(N, 3) points to (N - 1, 2, 3) line segments."""
    return np.stack([points[:-1], points[1:]], axis=1).astype(np.float32)


class ThreeDView:
    """The viser server and its scene; every method is safe to call from any thread."""

    def __init__(self, host: str = "127.0.0.1", port: int = 8080, time_scale: float = 1.0) -> None:
        self.host, self.requested_port, self.time_scale = host, port, time_scale
        self.server: Any = None
        self.horizon_s = 120.0
        self._track: list[tuple[float, float, float]] = []
        self._track_drawn_at = 0.0
        self._lock = threading.Lock()

    @property
    def port(self) -> int | None:
        return None if self.server is None else int(self.server.get_port())

    def start(self) -> None:
        import viser

        self.server = viser.ViserServer(host=self.host, port=self.requested_port, verbose=False,
                                        label="USV recovery: x, y, t")
        scene = self.server.scene
        scene.set_up_direction("+z")
        scene.add_grid("/grid", width=200.0, height=200.0, cell_size=10.0,
                       position=(60.0, 0.0, 0.0))
        # the ramp: a slab behind the ramp end, and its axis out to sea
        scene.add_box("/ramp", dimensions=(6.0, 3.0, 0.4), color=(120, 120, 120),
                      position=(-3.0, 0.0, 0.0))
        scene.add_line_segments("/ramp_axis", np.array([[[0, 0, 0], [150, 0, 0]]], np.float32),
                                colors=(200, 200, 200), thickness=0.1)

    def stop(self) -> None:
        if self.server is not None:
            self.server.stop()
            self.server = None

    def show_scenario(self, scenario: Scenario, horizon_s: float | None = None) -> None:
        """Obstacles (inflated circles as swept cylinders) and the start of a scenario."""
        if self.server is None:
            return
        if horizon_s is not None:
            self.horizon_s = horizon_s
        scene = self.server.scene
        with self._lock:
            scene.add_frame("/obstacles", show_axes=False)
            for i, o in enumerate(scenario.obstacles):
                v, f = oblique_cylinder(o.x, o.y, o.radius, o.vx, o.vy, self.horizon_s,
                                        self.time_scale)
                color = (230, 120, 60) if o.moving else (150, 90, 60)
                scene.add_mesh_simple(f"/obstacles/{i}", v, f, color=color, opacity=0.6,
                                      side="double")
            scene.add_icosphere("/start", radius=1.0, color=(40, 160, 60),
                                position=(scenario.start.x, scenario.start.y, 0.0))

    def show_plan(self, plan: dict[str, Any]) -> None:
        """The planned path in (x, y, t)."""
        if self.server is None:
            return
        pts = np.array([[w["x"], w["y"], w["t"] * self.time_scale] for w in plan["waypoints"]])
        with self._lock:
            self.server.scene.add_line_segments("/plan", polyline_segments(pts),
                                                colors=(40, 90, 220), thickness=0.3)

    def clear_track(self) -> None:
        with self._lock:
            self._track = []
            if self.server is not None:
                self.server.scene.add_frame("/track", show_axes=False)

    def add_track_point(self, x: float, y: float, t: float) -> None:
        """One real position at mission time t; the line is redrawn at most twice a second."""
        with self._lock:
            self._track.append((x, y, t * self.time_scale))
            now = time.monotonic()
            if self.server is None or len(self._track) < 2 or \
                    now - self._track_drawn_at < TRACK_REDRAW_S:
                return
            self._track_drawn_at = now
            pts = np.array(self._track)
        self.server.scene.add_line_segments("/track", polyline_segments(pts),
                                            colors=(220, 40, 40), thickness=0.3)
