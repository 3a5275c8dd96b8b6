"""Plan jobs: the IGA runs in worker processes so the event loop never blocks.

With `workers=0` the plans run inline on the event loop instead, one at a time: that is for
simulated time (a sea trial, an in-process test), where the virtual clock stands still while
the planner computes, so a plan takes no simulated time and the outcome does not depend on
the machine's speed.

Each of the `workers` slots owns one worker process and a pipe to it. A job
that overruns `timeout_s`, is cancelled (`DELETE /api/plans/{id}`) or whose
worker dies (killed, out of memory) ends `failed` or `cancelled` with the
reason, and the slot starts a fresh worker, so one bad job never breaks
planning. Workers run at nice 10 with an address-space limit of
`memory_mb`, and die with the station (PR_SET_PDEATHSIG, even on kill -9).
At most `queue_max` jobs wait or run at once; beyond that `submit` refuses.
Every job ends in a final state (done, failed, cancelled), even when the
database refuses to store it.
"""

from __future__ import annotations

import asyncio
import contextlib
import ctypes
import ctypes.util
import hashlib
import json
import logging
import multiprocessing
import os
import resource
import signal
import sys
import threading
import uuid
from dataclasses import dataclass
from multiprocessing.connection import Connection
from multiprocessing.process import BaseProcess

from usvstation.clock import REAL_CLOCK, Clock
from usvstation.planning.errors import NoFeasiblePlan
from usvstation.planning.limits import PlanTooLarge
from usvstation.records import (
    JsonObject,
    PlanDocument,
    PlanJob,
    PlansHealth,
    PlanSummary,
    TelemetryRow,
)
from usvstation.runtime import tune_allocator
from usvstation.scenario import Scenario, ScenarioError, scenario_at
from usvstation.services.errors import Conflict, QueueFull
from usvstation.services.hub import LiveHub
from usvstation.store.db import Store, utc_now

log = logging.getLogger("usvstation.plans")

WORKER_NICENESS = 10  # the niceness plan workers run at (the server: its own, usually 0)
WORKER_START_TIMEOUT_S = 120.0
FINAL = ("done", "failed", "cancelled")
PR_SET_PDEATHSIG = 1
WATCHDOG_S = 1.0


class PlanQueueFull(QueueFull):
    """More than `queue_max` jobs waiting or running."""


class PlanNotCancellable(Conflict):
    """The job already ended."""


class WorkerDied(Exception):
    pass


def plan_in_worker(scenario: JsonObject, planner: str, seed: int | None) -> PlanDocument:
    """Runs in a worker process: validate and plan; NoFeasiblePlan propagates. The plan
    leaves the process in the stable plan format, the form the store keeps and the API
    serves."""
    from usvstation.planning.registry import plan_with
    from usvstation.scenario import parse_scenario

    return plan_with(parse_scenario(scenario), planner, seed).to_document()


def die_with_parent(station_pid: int) -> None:
    """End this worker when the station dies, even by SIGKILL.

    The worker's parent is the forkserver, which exits when the station does:
    PR_SET_PDEATHSIG has Linux SIGKILL us then. A watchdog thread also polls the
    station's pid each WATCHDOG_S in case the forkserver outlives it.
    """
    if sys.platform.startswith("linux"):
        with contextlib.suppress(OSError, AttributeError):
            libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
            libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    if os.getppid() == 1:  # the parent already died before prctl
        os._exit(0)

    def watch() -> None:
        never = threading.Event()
        while not never.wait(WATCHDOG_S):  # a blocking wait in this worker's own thread
            try:
                os.kill(station_pid, 0)
            except ProcessLookupError:
                os._exit(0)
            except PermissionError:
                pass

    threading.Thread(target=watch, name="station-watchdog", daemon=True).start()


def scenario_from_boat(scenario: Scenario, row: TelemetryRow | None,
                       run_t0: float | None) -> Scenario:
    """The scenario re-started from the boat's latest telemetry `row` (issue 12, re-plan
    under way).

    Position and hull heading in the ramp frame, speed over ground as the start speed; moving
    obstacles are propagated to the boat's time since its run began at boat time `run_t0`
    (0 outside a run). Raises Conflict (one line) when there is no usable telemetry.
    """
    if not row or row.get("x") is None or row.get("ramp_heading_deg") is None:
        raise Conflict("from_boat: no telemetry with a ramp-frame position yet "
                         "(is the boat connected and the scenario's origin set?)")
    t = row["boat_time"] - run_t0 if row.get("run") is not None and run_t0 is not None else 0.0
    try:
        return scenario_at(scenario, row["x"], row["y"], row["ramp_heading_deg"], row["speed"],
                           max(float(t), 0.0))
    except ScenarioError as exc:  # the boat where no plan can start: inside the ship, ...
        raise Conflict(f"cannot plan from the boat: {exc}") from None


def scenario_digest(scenario: Scenario) -> dict[str, str]:
    """A short digest of each top-level field of a scenario (what `basis` keeps)."""
    doc = scenario.model_dump(mode="json")
    return {k: hashlib.sha256(json.dumps(v, sort_keys=True).encode()).hexdigest()[:16]
            for k, v in doc.items()}


def outdated_by(job: PlanJob, working: Scenario) -> list[str]:
    """The top-level fields of the working scenario that changed since the plan was asked
    against it (its `basis`: a plan from the boat or from the live world differs from the
    working scenario in its start, obstacles or current, and is not outdated by that); a job
    without a basis (stored before bases were kept) compares its own scenario, when it was
    made for the working scenario (same name); else []."""
    basis = job.get("basis")
    if basis is not None:
        now = scenario_digest(working)
        return sorted(k for k in basis.keys() | now.keys() if basis.get(k) != now.get(k))
    planned = job["scenario"]
    current = working.model_dump(mode="json")
    if planned.get("name") != current["name"]:
        return []
    return sorted(k for k in planned.keys() | current.keys() if planned.get(k) != current.get(k))


def init_worker(memory_mb: int | None = None) -> None:
    """Plan workers: tuned allocator, a memory limit, and a lower CPU priority.

    Planning is background work; the event loop (telemetry, websocket, API)
    must get the CPU first on a 2-core machine running several plans, so the
    workers run at nice 10 (about a tenth of the weight of the server). Not
    SCHED_IDLE: beside any busy process such a worker gets no CPU at all, and
    the station could neither start (it waits for its workers) nor plan.
    """
    tune_allocator()
    if memory_mb is not None:
        limit = memory_mb << 20
        _, hard = resource.getrlimit(resource.RLIMIT_AS)
        if hard != resource.RLIM_INFINITY:
            limit = min(limit, hard)
        with contextlib.suppress(ValueError, OSError):
            resource.setrlimit(resource.RLIMIT_AS, (limit, hard))
    with contextlib.suppress(OSError):
        os.nice(max(0, WORKER_NICENESS - os.nice(0)))


def worker_main(conn: Connection, parent_pid: int, memory_mb: int) -> None:
    """A plan worker: ("ready",), then one reply per (scenario, planner, seed) request."""
    die_with_parent(parent_pid)
    init_worker(memory_mb)
    # the planners, scipy and the compiled kernels (planning/warm.py), once, before the first
    # job: already there when the worker forks from the forkserver that preloaded them
    import usvstation.planning.preload  # noqa: F401
    conn.send(("ready", os.getpid()))
    while True:
        try:
            request = conn.recv()
        except (EOFError, OSError):
            return
        if request is None:
            return
        try:
            reply: tuple = ("done", plan_in_worker(*request))
        except (NoFeasiblePlan, PlanTooLarge) as exc:  # PlanTooLarge: the 500 MB bound
            reply = ("failed", str(exc))
        except MemoryError:
            reply = ("failed", f"the plan needed more than the worker's {memory_mb} MB "
                               "(--plan-memory-mb)")
        except Exception as exc:  # a bug in the planner must not take the worker down
            reply = ("failed", f"planner error: {type(exc).__name__}: {exc}")
        conn.send(reply)


@dataclass(eq=False)
class _Worker:
    proc: BaseProcess
    conn: Connection
    waiting: asyncio.Future | None = None  # the reply being awaited


class PlanService:
    """Queues plan jobs, runs at most `workers` at once, stores every job and its result."""

    def __init__(self, store: Store, hub: LiveHub, workers: int = 2, *, timeout_s: float = 10.0,
                 memory_mb: int = 2048, queue_max: int = 32, clock: Clock = REAL_CLOCK) -> None:
        self.store, self.hub, self.workers, self.clock = store, hub, workers, clock
        self.timeout_s, self.memory_mb, self.queue_max = timeout_s, memory_mb, queue_max
        self.jobs: dict[str, PlanJob] = {}
        self.started = False
        self.restarts = 0  # workers replaced after a death, timeout or cancel
        self._queue: asyncio.Queue[str] = asyncio.Queue()
        self._slots: list[_Worker | None] = [None] * workers
        self._running: dict[str, int] = {}  # job id -> slot
        self._runners: list[asyncio.Task] = []
        self._reapers: set[asyncio.Task] = set()
        self._ctx = multiprocessing.get_context("forkserver")
        # before the forkserver starts: it imports the planners and loads the kernels once
        self._ctx.set_forkserver_preload(["__main__", "usvstation.planning.preload"])

    async def start(self) -> None:
        for job in await asyncio.to_thread(self.store.plans):
            if job["status"] not in FINAL:  # interrupted by a restart
                job.update(status="failed", error="the station restarted before this plan finished")
                await self._save(job, publish=False)
            self.jobs[job["id"]] = job
        await asyncio.gather(*(self._ensure_worker(i) for i in range(self.workers)))
        self._runners = [asyncio.create_task(self._slot(i), name=f"plan-slot-{i}")
                         for i in range(self.workers)]
        if self.workers == 0:
            self._runners.append(asyncio.create_task(self._inline(), name="plan-inline"))
        self.started = True

    async def stop(self) -> None:
        for task in self._runners:
            task.cancel()
        for task in self._runners:
            with contextlib.suppress(asyncio.CancelledError, Exception):
                await task
        for job in self.jobs.values():
            if job["status"] not in FINAL:
                job.update(status="failed", error="the station stopped before this plan finished")
                await self._save(job, publish=False)
        for i in range(self.workers):
            self._kill(i)

    # --- requests ------------------------------------------------------------------------
    async def submit(self, scenario: Scenario, planner: str, seed: int | None,
                     basis: Scenario | None = None) -> PlanJob:
        """Queue a job (`basis`: the working scenario it was asked against, when it was);
        PlanQueueFull when `queue_max` jobs already wait or run."""
        active = sum(1 for j in self.jobs.values() if j["status"] not in FINAL)
        if active >= self.queue_max:
            raise PlanQueueFull(f"{active} plans already queued or running (--plan-queue "
                                f"{self.queue_max}); try again later")
        job: PlanJob = {
            "id": uuid.uuid4().hex[:12], "created_at": utc_now(self.clock), "status": "queued",
            "planner": planner, "seed": seed, "scenario": scenario.model_dump(mode="json"),
            "plan": None, "error": None,
            "basis": scenario_digest(basis) if basis is not None else None,
        }
        self.jobs[job["id"]] = job
        await self._save(job)
        self._queue.put_nowait(job["id"])
        return job

    async def cancel(self, job_id: str) -> PlanJob | None:
        """Cancel a queued or running job (its worker is replaced); None if there is no such job."""
        job = self.jobs.get(job_id)
        if job is None:
            return None
        if job["status"] in FINAL:
            raise PlanNotCancellable(f"plan {job_id} already ended: {job['status']}")
        job.update(status="cancelled", error="cancelled by the operator")
        slot = self._running.get(job_id)
        if slot is not None:
            self._kill(slot)
        await self._save(job)
        return job

    def get(self, job_id: str) -> PlanJob | None:
        return self.jobs.get(job_id)

    def summary(self, job: PlanJob) -> PlanSummary:
        plan = job["plan"]
        return {"id": job["id"], "status": job["status"], "created_at": job["created_at"],
                "planner": job["planner"], "seed": job["seed"], "error": job["error"],
                "scenario": str(job["scenario"]["name"]),
                "fitness": plan["metrics"]["fitness"] if plan else None}

    def health(self) -> PlansHealth:
        statuses = [j["status"] for j in self.jobs.values()]
        alive = [w for w in self._slots if w is not None and w.proc.is_alive()]
        return {"queued": statuses.count("queued"), "running": statuses.count("running"),
                "workers": self.workers, "workers_alive": len(alive),
                "worker_pids": [w.proc.pid for w in alive if w.proc.pid is not None],
                "workers_replaced": self.restarts, "queue_max": self.queue_max,
                "timeout_s": self.timeout_s}

    # --- workers -------------------------------------------------------------------------
    async def _ensure_worker(self, i: int) -> _Worker:
        w = self._slots[i]
        if w is not None and w.proc.is_alive():
            return w
        if w is not None:
            self._kill(i)
        parent_end, child_end = self._ctx.Pipe()
        proc = self._ctx.Process(target=worker_main, name=f"usv-plan-worker-{i}", daemon=True,
                                 args=(child_end, os.getpid(), self.memory_mb))
        await asyncio.to_thread(proc.start)
        child_end.close()
        w = _Worker(proc, parent_end)
        self._slots[i] = w
        await asyncio.wait_for(self._recv(w), WORKER_START_TIMEOUT_S)
        return w

    def _kill(self, i: int) -> None:
        w = self._slots[i]
        if w is None:
            return
        self._slots[i] = None
        loop = asyncio.get_running_loop()
        with contextlib.suppress(OSError, ValueError):
            loop.remove_reader(w.conn.fileno())
        if w.waiting is not None and not w.waiting.done():
            w.waiting.set_exception(WorkerDied("stopped by the station"))
        with contextlib.suppress(OSError, ValueError, AttributeError):
            w.proc.kill()
        w.conn.close()
        reaper = loop.create_task(asyncio.to_thread(w.proc.join, 5.0))
        self._reapers.add(reaper)
        reaper.add_done_callback(self._reapers.discard)

    async def _recv(self, w: _Worker) -> tuple:
        """The worker's next message, without blocking the loop; WorkerDied on EOF."""
        loop = asyncio.get_running_loop()
        fut: asyncio.Future[tuple] = loop.create_future()
        fd = w.conn.fileno()
        w.waiting = fut

        def readable() -> None:
            loop.remove_reader(fd)
            if fut.done():
                return
            try:
                fut.set_result(w.conn.recv())
            except (EOFError, OSError) as exc:
                fut.set_exception(WorkerDied(str(exc) or "the pipe closed"))

        loop.add_reader(fd, readable)
        try:
            return await fut
        finally:
            with contextlib.suppress(OSError, ValueError):
                loop.remove_reader(fd)

    # --- jobs ----------------------------------------------------------------------------
    async def _slot(self, i: int) -> None:
        while True:
            job_id = await self._queue.get()
            job = self.jobs.get(job_id)
            if job is None or job["status"] != "queued":
                continue  # cancelled while waiting
            try:
                await self._run(i, job)
            except asyncio.CancelledError:
                raise
            except Exception as exc:  # nothing leaves a job queued or running
                log.exception("plan job %s", job_id)
                if job["status"] not in FINAL:
                    job.update(status="failed", error=f"station error: {type(exc).__name__}: "
                                                      f"{exc}")
                    await self._save(job)

    async def _inline(self) -> None:
        """workers=0: each job planned on the loop itself (simulated time)."""
        while True:
            job = self.jobs.get(await self._queue.get())
            if job is None or job["status"] != "queued":
                continue
            job["status"] = "running"
            await self._save(job)
            try:
                plan = plan_in_worker(job["scenario"], job["planner"], job["seed"])
            except (NoFeasiblePlan, PlanTooLarge) as exc:
                job.update(status="failed", error=str(exc))
            except Exception as exc:  # as in a worker: a planner bug fails the job only
                job.update(status="failed", error=f"planner error: {type(exc).__name__}: {exc}")
            else:
                job.update(status="done", plan=plan, seed=plan["seed"])
            await self._save(job)

    async def _run(self, i: int, job: PlanJob) -> None:
        try:
            w = await self._ensure_worker(i)
        except (OSError, WorkerDied, TimeoutError) as exc:
            job.update(status="failed", error=f"no plan worker could start: {exc}")
            await self._save(job)
            return
        job["status"] = "running"
        await self._save(job)
        self._running[job["id"]] = i
        try:
            w.conn.send((job["scenario"], job["planner"], job["seed"]))
            kind, payload = await asyncio.wait_for(self._recv(w), self.timeout_s)
        except TimeoutError:
            self._kill(i)
            self.restarts += 1
            if job["status"] not in FINAL:
                job.update(status="failed", error=f"the plan took longer than the "
                                                  f"{self.timeout_s:g} s limit (--plan-timeout-s)")
        except (WorkerDied, OSError) as exc:
            await asyncio.to_thread(w.proc.join, 2.0)  # reap it for its exit code
            code = w.proc.exitcode
            self._kill(i)
            self.restarts += 1
            if job["status"] not in FINAL:
                how = (f"killed by signal {-code}" if code is not None and code < 0 else
                       f"exit code {code}" if code is not None else str(exc))
                job.update(status="failed", error=f"the plan worker died ({how})")
        except asyncio.CancelledError:
            self._kill(i)
            raise
        else:
            if job["status"] not in FINAL:
                if kind == "done":
                    job.update(status="done", plan=payload, seed=payload["seed"])
                else:
                    job.update(status="failed", error=payload)
        finally:
            self._running.pop(job["id"], None)
        if job["status"] != "cancelled":
            await self._save(job)
        if self._slots[i] is None:
            with contextlib.suppress(OSError, WorkerDied, TimeoutError):
                await self._ensure_worker(i)

    async def _save(self, job: PlanJob, publish: bool = True) -> None:
        """Store the job; a store error is logged, the job's state stays true in memory."""
        try:
            await asyncio.to_thread(self.store.save_plan, job)
        except Exception as exc:  # the job must still reach a final state
            log.error("cannot store plan %s (%s): %s", job["id"], job["status"], exc)
        if publish:
            self.hub.publish("plan", self.summary(job))

