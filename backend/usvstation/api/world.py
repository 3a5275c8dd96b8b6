"""`GET /api/world`: the own ship, the ramp pose and the targets (shared/DESIGN.md "HTTP API")."""

from __future__ import annotations

from fastapi import APIRouter, Request

from usvstation.records import WorldScenario, WorldSnapshot

router = APIRouter(tags=["world"])


@router.get("/api/world")
async def get_world(request: Request) -> WorldSnapshot:
    """Own ship {lat, lon, heading_deg, course_deg, speed, age_s}; the ramp's pose; targets
    [{id, source, mmsi, name, lat, lon, x, y, vx, vy, rvx, rvy, radius, age_s, ...}] predicted
    to now in the ramp frame (vx, vy over ground, rvx, rvy relative to the ramp, m/s);
    stats {sentences, bad, ignored, bad_reasons, sources}."""
    return request.app.state.station.world.snapshot()


@router.get("/api/world/scenario")
async def get_world_scenario(request: Request) -> WorldScenario:
    """The working scenario against the world as it is now: {scenario, dropped}; its
    obstacles are the world's targets in the ramp frame with their velocities relative to
    the ramp, the ship's motion an apparent current. POST it to /api/plans to plan for the
    live world; `dropped` names targets already too close to the start or the ramp."""
    from usvstation.world.monitor import TargetState
    from usvstation.world.replan import world_scenario

    station = request.app.state.station
    base = await station.working_scenario()
    world = station.world
    t = world.clock.now()
    pose = world.world.ramp(t)
    frame_v = (0.0, 0.0)
    if pose is not None:
        vx, vy = pose.frame.vector_to_ramp(pose.ve, pose.vn)
        frame_v = (float(vx), float(vy))
    targets = [TargetState(v["id"], v["x"], v["y"], v["rvx"], v["rvy"], v["radius"])
               for v in world.world.targets(t)]
    scenario, dropped = world_scenario(base, targets, frame_v)
    return {"scenario": scenario.model_dump(mode="json"), "dropped": dropped}
