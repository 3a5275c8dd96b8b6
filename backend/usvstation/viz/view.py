"""The 3D (x, y, t) view of paper 000 Fig. 5b, served by viser.

Ramp-frame x and y are the horizontal axes; time goes up at `time_scale`
metres per second. Obstacles are cylinders over the plan's duration: upright
when static, leaning along their velocity when moving (eq. 8's oblique
cylinders). The planned path and the boat's real path (growing live from
telemetry) are lines in the same space.

The viser GUI toggles each layer and scrubs a time plane through the scene:
at the chosen t it shows the obstacles' circles, the planned position and
the boat's real position. While a run is live the time follows the boat
unless the operator moves the slider. The mother ship's hull, the world's
targets and the day, dusk and night palettes come from viz/scene.py.

viser's server listens on a loopback port and answers only requests that carry this
start's secret (`PROXY_SECRET_HEADER`, `ThreeDView.secret`), which only the station's own
proxy (api/view3d.py, behind the token) sends: another local process, a page in a browser
or a forged Host header gets 403 and no byte of the scene.
"""

from __future__ import annotations

import bisect
import contextlib
import hmac
import http
import math
import secrets
import threading
from collections.abc import Callable, Iterator
from types import SimpleNamespace
from typing import Any

import numpy as np

from usvstation.clock import REAL_CLOCK
from usvstation.geometry import inflated_radius, position_at
from usvstation.scenario import Scenario
from usvstation.viz.scene import (
    PALETTES,
    Palette,
    background_image,
    hull_outline,
    hull_prism,
    palette,
    target_sweeps,
)

CIRCLE_SIDES = 32
TRACK_REDRAW_S = 0.5  # redraw the real path at most this often
DEFAULT_HORIZON_S = 120.0
HORIZON_MARGIN = 1.2  # obstacles are drawn to this multiple of the plan's duration
DISC_HEIGHT_M = 0.15
GRID_LENGTH_M = 200.0
GRID_WIDTH_M = 120.0
LAYERS = {"obstacles": "Obstacles", "plan": "Planned path", "track": "Real path",
          "ramp": "Ramp and grid", "time": "Time plane", "ship": "Mother ship",
          "targets": "Targets"}


PROXY_SECRET_HEADER = "X-USV-Proxy-Secret"
_SERVE_LOCK = threading.Lock()  # one viser server put behind its secret at a time


def _serve_with_secret(real_serve: Callable[..., Any], secret: str, started: list[bool],
                       handler: Any, *args: Any, process_request: Any = None,
                       **kwargs: Any) -> Any:
    """websockets' `serve` as viser calls it, with a first check of every HTTP request and
    websocket handshake: without `secret` in PROXY_SECRET_HEADER, 403 and nothing else."""

    def check(connection: Any, request: Any) -> Any:
        given = request.headers.get(PROXY_SECRET_HEADER, "")
        if not hmac.compare_digest(given.encode(), secret.encode()):
            return connection.respond(http.HTTPStatus.FORBIDDEN, "")
        return process_request(connection, request) if process_request is not None else None

    started.append(True)
    return real_serve(handler, *args, process_request=check, **kwargs)


@contextlib.contextmanager
def _viser_behind_secret(secret: str) -> Iterator[list[bool]]:
    """While a ViserServer starts, its websockets `serve` checks `secret` first (viser has
    no hook for it: its module's `websockets` is swapped for one whose `serve` does). The
    list yielded holds True once viser's server was started that way."""
    from functools import partial

    from viser.infra import _infra

    started: list[bool] = []
    with _SERVE_LOCK:
        real = _infra.websockets
        server = SimpleNamespace(
            serve=partial(_serve_with_secret, real.asyncio.server.serve, secret, started),
            ServerConnection=real.asyncio.server.ServerConnection)
        _infra.websockets = SimpleNamespace(
            asyncio=SimpleNamespace(server=server), datastructures=real.datastructures,
            exceptions=real.exceptions)
        try:
            yield started
        finally:
            _infra.websockets = real


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


def track_position_at(track: list[tuple[float, float, float]], t_scaled: float
                      ) -> tuple[float, float] | None:
    """The real (x, y) last reported at or before scaled time t_scaled, or None."""
    if not track or t_scaled < track[0][2]:
        return None
    i = bisect.bisect_right([p[2] for p in track], t_scaled) - 1
    return track[i][0], track[i][1]


class ThreeDView:
    """The viser server, its scene and GUI; every method is safe to call from any thread."""

    def __init__(self, host: str = "127.0.0.1", port: int = 8080, time_scale: float = 1.0) -> None:
        self.host, self.requested_port, self.time_scale = host, port, time_scale
        self.server: Any = None
        self.horizon_s = DEFAULT_HORIZON_S
        self.scenario: Scenario | None = None
        self.waypoints: list[dict[str, Any]] | None = None
        self.time_s = 0.0
        self.follow_live = True
        self.layers: dict[str, Any] = {}
        self.gui: dict[str, Any] = {}
        self._plane: Any = None
        self._plane_centre = (60.0, 0.0)
        self._planned_marker: Any = None
        self._real_marker: Any = None
        self._obstacle_nodes: list[Any] = []
        self._discs: list[tuple[Any, float, float]] = []  # (handle, vx, vy)
        self._track: list[tuple[float, float, float]] = []
        self._track_drawn_at = 0.0
        self._slider_from_code = False
        self._lock = threading.RLock()
        self.palette: Palette = PALETTES["day"]
        self.targets: list[dict[str, Any]] = []
        self._target_time = 0.0
        self._dangerous: frozenset[str] = frozenset()
        self._target_nodes: dict[str, list[Any]] = {}
        self._ship_nodes: list[Any] = []
        self._axis_labels: list[Any] = []
        self._plane_bounds = (-10.0, 130.0, -40.0, 40.0)
        self.secret = secrets.token_urlsafe(32)  # the proxy's, for this start

    @property
    def port(self) -> int | None:
        return None if self.server is None else int(self.server.get_port())

    def start(self) -> None:
        """Start viser's server on the loopback port, answering only the proxy's secret."""
        import viser

        self.secret = secrets.token_urlsafe(32)
        with _viser_behind_secret(self.secret) as guarded:
            server = viser.ViserServer(host=self.host, port=self.requested_port,
                                       verbose=False, label="USV recovery: x, y, t")
        if not guarded:  # fail closed: a viser whose server no longer starts as expected
            server.stop()
            raise RuntimeError("the 3D view's server could not be put behind the proxy's "
                               f"secret (viser {viser.__version__})")
        self.server = server
        scene = self.server.scene
        scene.set_up_direction("+z")
        camera = self.server.initial_camera
        camera.position = (100.0, -60.0, 38.0)
        camera.look_at = (40.0, 0.0, 12.0)
        self.layers = {key: scene.add_frame(f"/{key}", show_axes=False) for key in LAYERS}
        self._axis_labels = [
            scene.add_label("/ramp/x_label", "x (m), out to sea", position=(150.0, 0.0, 0.0)),
            scene.add_label("/ramp/t_label", f"t (s) up, {self.time_scale:g} m per s",
                            position=(0.0, 0.0, 40.0 * self.time_scale))]
        self._draw_ramp()
        self._draw_plane(-10.0, 130.0, -40.0, 40.0)
        self._planned_marker = scene.add_icosphere("/time/planned", radius=1.0,
                                                   color=self.palette.plan, visible=False)
        self._real_marker = scene.add_icosphere("/time/real", radius=1.0,
                                                color=self.palette.track, visible=False)
        self._build_gui()
        self._apply_theme()

    def _draw_ramp(self) -> None:
        """The grid, the ramp (a slab behind the ramp end) and its axis out to sea, and the
        time axis, in the palette's colours."""
        scene, p = self.server.scene, self.palette
        scene.add_grid("/ramp/grid", width=GRID_LENGTH_M, height=GRID_WIDTH_M, cell_size=10.0,
                       section_size=50.0, position=(60.0, 0.0, 0.0), cell_color=p.grid,
                       section_color=p.grid)
        scene.add_box("/ramp/slab", dimensions=(6.0, 3.0, 0.4), color=p.ramp,
                      position=(-3.0, 0.0, 0.0))
        scene.add_line_segments("/ramp/axis", np.array([[[0, 0, 0], [150, 0, 0]]], np.float32),
                                colors=p.grid, thickness=0.1)
        scene.add_line_segments("/ramp/t_axis", np.array(
            [[[0, 0, 0], [0, 0, 40.0 * self.time_scale]]], np.float32),
            colors=p.grid, thickness=0.1)

    def _apply_theme(self) -> None:
        p = self.palette
        self.server.gui.configure_theme(dark_mode=p.dark, brand_color=p.brand,
                                        show_share_button=False)
        self.server.scene.set_background_image(background_image(p), format="png")
        labels = self._axis_labels + [nodes[2] for nodes in self._target_nodes.values()]
        for label in labels:  # viser draws labels on white: none at night
            label.visible = p.labels

    def _build_gui(self) -> None:
        gui = self.server.gui
        gui.add_markdown("**USV recovery in (x, y, t)**: ramp-frame x, y in metres; time "
                         f"upwards, {self.time_scale:g} m per second. Blue: planned path; "
                         "red: real path; orange: obstacles swept over time (eq. 8).")
        with gui.add_folder("Layers"):
            for key, label in LAYERS.items():
                box = gui.add_checkbox(label, True)
                box.on_update(lambda _, key=key, box=box: self.set_layer(key, box.value))
                self.gui[f"layer:{key}"] = box
        with gui.add_folder("Time"):
            slider = gui.add_slider("t (s)", min=0.0, max=self.horizon_s, step=0.1,
                                    initial_value=0.0)
            slider.on_update(lambda _: self._slider_moved(slider.value))
            follow = gui.add_checkbox("Follow the live run", True)
            follow.on_update(lambda _: self._set_follow(follow.value))
            self.gui.update(time=slider, follow=follow,
                            readout=gui.add_markdown("t = 0.0 s"))
        with gui.add_folder("View"):
            choice = gui.add_dropdown("Palette", tuple(PALETTES), initial_value=self.palette.name)
            choice.on_update(lambda _: self.set_palette(choice.value))
            self.gui["palette"] = choice

    def stop(self) -> None:
        if self.server is not None:
            self.server.stop()
            self.server = None

    # --- layers and time --------------------------------------------------------------------
    def set_layer(self, key: str, visible: bool) -> None:
        """Show or hide one layer (a key of LAYERS)."""
        if key not in LAYERS:
            raise ValueError(f"unknown layer {key!r}; layers: {', '.join(LAYERS)}")
        if self.server is None:
            return
        self.layers[key].visible = visible
        box = self.gui.get(f"layer:{key}")
        if box is not None and box.value != visible:
            box.value = visible

    def _slider_moved(self, t: float) -> None:
        if not self._slider_from_code:
            self._set_follow(False)
        self.set_time(t)

    def _set_follow(self, follow: bool) -> None:
        self.follow_live = follow
        box = self.gui.get("follow")
        if box is not None and box.value != follow:
            box.value = follow

    def set_time(self, t: float) -> None:
        """Move the time plane to t s: obstacles, planned and real positions at that time."""
        if self.server is None:
            return
        with self._lock:
            t = min(max(float(t), 0.0), self.horizon_s)
            self.time_s = t
            z = t * self.time_scale
            lines = [f"t = {t:.1f} s"]
            self._plane.position = (*self._plane_centre, z)
            for handle, vx, vy in self._discs:
                handle.position = (vx * t, vy * t, z)
            if self.waypoints:
                w = self.waypoints
                x, y = position_at([p["t"] for p in w], [p["x"] for p in w], [p["y"] for p in w], t)
                self._planned_marker.position = (x, y, z)
                self._planned_marker.visible = True
                lines.append(f"planned: x {x:.1f} m, y {y:.1f} m")
            real = track_position_at(self._track, z)
            self._real_marker.visible = real is not None
            if real is not None:
                self._real_marker.position = (real[0], real[1], z)
                lines.append(f"real: x {real[0]:.1f} m, y {real[1]:.1f} m")
            slider = self.gui.get("time")
            if slider is not None and abs(slider.value - t) > 1e-9:
                self._slider_from_code = True
                try:
                    slider.value = t
                finally:
                    self._slider_from_code = False
            readout = self.gui.get("readout")
            if readout is not None:
                readout.content = "  \n".join(lines)

    def _draw_plane(self, x0: float, x1: float, y0: float, y1: float) -> None:
        """The time plane over the scene's extent (x0..x1, y0..y1), at the current time."""
        self._plane_bounds = (x0, x1, y0, y1)
        self._plane_centre = ((x0 + x1) / 2, (y0 + y1) / 2)
        self._plane = self.server.scene.add_box(
            "/time/plane", dimensions=(x1 - x0, y1 - y0, 0.02), color=self.palette.plane,
            opacity=0.15, position=(*self._plane_centre, self.time_s * self.time_scale))

    def _set_horizon(self, horizon_s: float) -> None:
        self.horizon_s = horizon_s
        slider = self.gui.get("time")
        if slider is not None:
            slider.max = horizon_s

    # --- scene content ------------------------------------------------------------------------
    def show_scenario(self, scenario: Scenario, horizon_s: float | None = None) -> None:
        """Obstacles (inflated circles as swept cylinders) and the start of a scenario."""
        if self.server is None:
            return
        with self._lock:
            self.scenario = scenario
            if horizon_s is not None:
                self._set_horizon(horizon_s)
            self._draw_obstacles()
            xs = [0.0, scenario.start.x, *(o.x for o in scenario.obstacles)]
            ys = [0.0, scenario.start.y, *(o.y for o in scenario.obstacles)]
            self._draw_plane(min(xs) - 15.0, max(xs) + 15.0, min(ys) - 15.0, max(ys) + 15.0)
            self.server.scene.add_icosphere("/start", radius=1.0, color=self.palette.start,
                                            position=(scenario.start.x, scenario.start.y, 0.0))
        self.set_time(self.time_s)

    def _draw_obstacles(self) -> None:
        scene = self.server.scene
        for node in self._obstacle_nodes:
            node.remove()
        self._obstacle_nodes, self._discs = [], []
        for i, o in enumerate(self.scenario.obstacles):
            r = inflated_radius(o.radius, self.scenario.vessel.length,
                                self.scenario.vessel.compensation_radius)
            v, f = oblique_cylinder(o.x, o.y, r, o.vx, o.vy, self.horizon_s, self.time_scale)
            color = self.palette.obstacle_moving if o.moving else self.palette.obstacle
            self._obstacle_nodes.append(scene.add_mesh_simple(
                f"/obstacles/{i}", v, f, color=color, opacity=0.45, side="double"))
            dv, df = oblique_cylinder(o.x, o.y, r, 0.0, 0.0, DISC_HEIGHT_M, 1.0)
            disc = scene.add_mesh_simple(f"/time/obstacle_{i}", dv, df, color=color,
                                         opacity=0.9, side="double")
            self._obstacle_nodes.append(disc)
            self._discs.append((disc, o.vx, o.vy))
        self._draw_ship()

    def _draw_ship(self) -> None:
        """The mother ship's hull: its outline at t = 0 and a prism over the horizon (it
        stands still in the ship-fixed frame); nothing without a mother ship."""
        scene, p = self.server.scene, self.palette
        ship = self.scenario.mother_ship if self.scenario is not None else None
        outline = hull_outline(ship)
        prism = hull_prism(ship, self.horizon_s * self.time_scale)
        for node in self._ship_nodes:
            node.remove()
        self._ship_nodes = []
        if outline is not None:
            self._ship_nodes.append(scene.add_line_segments(
                "/ship/outline", outline, colors=p.hull, thickness=0.25))
        if prism is not None:
            self._ship_nodes.append(scene.add_mesh_simple(
                "/ship/hull", *prism, color=p.hull, opacity=0.25, side="double"))

    def show_targets(self, targets: list[dict[str, Any]], t_now: float,
                     dangerous: frozenset[str] = frozenset()) -> None:
        """The world's targets (`records.Target`s, ramp frame of now) at mission time t_now,
        each with its predicted track along its velocity relative to the ramp; `dangerous`
        ids are drawn in the palette's danger colour."""
        with self._lock:
            self.targets, self._target_time, self._dangerous = targets, t_now, dangerous
            if self.server is None:
                return
            scene = self.server.scene
            sweeps = target_sweeps(targets, t_now, self.horizon_s, self.time_scale,
                                   self.palette, dangerous)
            for gone in set(self._target_nodes) - {s.id for s in sweeps}:
                for node in self._target_nodes.pop(gone):
                    node.remove()
            for i, sweep in enumerate(sweeps):
                key = f"/targets/{i}_{sweep.id.replace(':', '_')}"
                self._target_nodes[sweep.id] = [
                    scene.add_line_segments(f"{key}/track", sweep.segments, colors=sweep.color,
                                            thickness=0.3),
                    scene.add_icosphere(f"{key}/now", radius=1.5, color=sweep.color,
                                        position=sweep.position),
                    scene.add_label(f"{key}/label", sweep.label, position=sweep.position,
                                    visible=self.palette.labels)]

    def set_palette(self, name: str) -> None:
        """Day, dusk or night: the GUI's theme, the background and every drawn colour."""
        new = palette(name)
        with self._lock:
            self.palette = new
            if self.server is None:
                return
            self._apply_theme()
            self._draw_ramp()
            self._draw_plane(*self._plane_bounds)
            self._planned_marker.color = new.plan
            self._real_marker.color = new.track
            if self.scenario is not None:
                self.show_scenario(self.scenario)
            if self.waypoints:
                self.show_plan({"waypoints": self.waypoints})
            if len(self._track) > 1:
                self.server.scene.add_line_segments(
                    "/track/path", polyline_segments(np.array(self._track)),
                    colors=new.track, thickness=0.3)
            for nodes in self._target_nodes.values():
                for node in nodes:
                    node.remove()
            self._target_nodes = {}
            self.show_targets(self.targets, self._target_time, self._dangerous)
            choice = self.gui.get("palette")
            if choice is not None and choice.value != name:
                choice.value = name

    def show_plan(self, plan: dict[str, Any]) -> None:
        """The planned path in (x, y, t); obstacles are redrawn over the plan's duration."""
        if self.server is None:
            return
        wps = plan["waypoints"]
        pts = np.array([[w["x"], w["y"], w["t"] * self.time_scale] for w in wps])
        with self._lock:
            self.waypoints = wps
            self.server.scene.add_line_segments("/plan/path", polyline_segments(pts),
                                                colors=self.palette.plan, thickness=0.3)
            self._set_horizon(max(math.ceil(wps[-1]["t"] * HORIZON_MARGIN), 10))
            if self.scenario is not None:
                self._draw_obstacles()
        self.set_time(min(self.time_s, self.horizon_s))

    def clear_track(self) -> None:
        """A new run: no real path yet, and the time follows the run again."""
        with self._lock:
            self._track = []
            if self.server is not None:
                self.server.scene.add_frame("/track/path", show_axes=False)
        self._set_follow(True)
        self.set_time(0.0)

    def add_track_point(self, x: float, y: float, t: float) -> None:
        """One real position at mission time t; the line is redrawn at most twice a second."""
        with self._lock:
            self._track.append((x, y, t * self.time_scale))
            now = REAL_CLOCK.now()  # redraw pacing: a browser's frame rate, real time
            if self.server is None or len(self._track) < 2 or \
                    now - self._track_drawn_at < TRACK_REDRAW_S:
                return
            self._track_drawn_at = now
            pts = np.array(self._track)
            self.server.scene.add_line_segments("/track/path", polyline_segments(pts),
                                                colors=self.palette.track, thickness=0.3)
            if t > self.horizon_s:  # a run longer than the plan: slider and obstacles reach it
                self._set_horizon(math.ceil(t * HORIZON_MARGIN))
                if self.scenario is not None:
                    self._draw_obstacles()
            follow = self.follow_live
        if follow:
            self.set_time(min(t, self.horizon_s))
