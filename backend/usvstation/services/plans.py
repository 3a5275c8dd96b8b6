"""Plan jobs: the IGA runs in a process pool so the event loop never blocks."""

from __future__ import annotations

import asyncio
import contextlib
import multiprocessing
import os
import uuid
from concurrent.futures import ProcessPoolExecutor
from typing import Any

from usvstation.planning.errors import NoFeasiblePlan
from usvstation.runtime import tune_allocator
from usvstation.scenario import Scenario
from usvstation.services.hub import LiveHub
from usvstation.store.db import Store, utc_now


def plan_in_worker(scenario: dict[str, Any], planner: str, seed: int | None) -> dict[str, Any]:
    """Runs in a worker process: validate and plan; NoFeasiblePlan propagates."""
    from usvstation.planning.registry import plan_with
    from usvstation.scenario import parse_scenario

    return plan_with(parse_scenario(scenario), planner, seed)


WORKER_NICENESS = 19


def init_worker() -> None:
    """Plan workers: tuned allocator, and the CPU only when the server does not want it.

    Planning is background work; the event loop (telemetry, websocket, API)
    must get the CPU first on a 2-core machine running several plans, so the
    workers run under SCHED_IDLE (Linux), else at the lowest nice level.
    """
    tune_allocator()
    try:
        os.sched_setscheduler(0, os.SCHED_IDLE, os.sched_param(0))
    except (AttributeError, OSError):
        with contextlib.suppress(OSError):
            os.nice(WORKER_NICENESS)


def _warm_up() -> bool:
    import usvstation.planning.registry  # noqa: F401  (import numpy/scipy once per worker)

    return True


class PlanService:
    """Queues plan jobs, runs at most `workers` at once, stores every job and its result."""

    def __init__(self, store: Store, hub: LiveHub, workers: int = 2) -> None:
        self.store, self.hub, self.workers = store, hub, workers
        self.jobs: dict[str, dict[str, Any]] = {}
        self._slots = asyncio.Semaphore(workers)
        self._tasks: set[asyncio.Task] = set()
        self._pool: ProcessPoolExecutor | None = None

    async def start(self) -> None:
        ctx = multiprocessing.get_context("forkserver")
        self._pool = ProcessPoolExecutor(self.workers, mp_context=ctx, initializer=init_worker)
        loop = asyncio.get_running_loop()
        for job in await asyncio.to_thread(self.store.plans):
            if job["status"] in ("queued", "running"):  # interrupted by a restart
                job.update(status="failed", error="the station restarted before this plan finished")
                await asyncio.to_thread(self.store.save_plan, job)
            self.jobs[job["id"]] = job
        await asyncio.gather(*(loop.run_in_executor(self._pool, _warm_up)
                               for _ in range(self.workers)))

    async def stop(self) -> None:
        for task in self._tasks:
            task.cancel()
        if self._pool:
            self._pool.shutdown(wait=False, cancel_futures=True)

    async def submit(self, scenario: Scenario, planner: str, seed: int | None) -> dict[str, Any]:
        job = {
            "id": uuid.uuid4().hex[:12], "created_at": utc_now(), "status": "queued",
            "planner": planner, "seed": seed, "scenario": scenario.model_dump(mode="json"),
            "plan": None, "error": None,
        }
        self.jobs[job["id"]] = job
        await self._save(job)
        task = asyncio.create_task(self._run(job))
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)
        return job

    def get(self, job_id: str) -> dict[str, Any] | None:
        return self.jobs.get(job_id)

    def summary(self, job: dict[str, Any]) -> dict[str, Any]:
        return {k: job[k] for k in ("id", "status", "created_at", "planner", "seed", "error")} | {
            "scenario": job["scenario"]["name"],
            "fitness": job["plan"]["metrics"]["fitness"] if job.get("plan") else None,
        }

    async def _run(self, job: dict[str, Any]) -> None:
        async with self._slots:
            job["status"] = "running"
            await self._save(job)
            loop = asyncio.get_running_loop()
            try:
                plan = await loop.run_in_executor(
                    self._pool, plan_in_worker, job["scenario"], job["planner"], job["seed"]
                )
            except NoFeasiblePlan as exc:
                job.update(status="failed", error=str(exc))
            except asyncio.CancelledError:
                job.update(status="failed", error="the station stopped before this plan finished")
                await self._save(job)
                raise
            except Exception as exc:  # a bug in the planner must not take the station down
                job.update(status="failed", error=f"planner error: {type(exc).__name__}: {exc}")
            else:
                job.update(status="done", plan=plan, seed=plan["seed"])
            await self._save(job)

    async def _save(self, job: dict[str, Any]) -> None:
        await asyncio.to_thread(self.store.save_plan, job)
        self.hub.publish("plan", self.summary(job))
