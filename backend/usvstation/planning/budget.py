"""The one budget every planner honours (issues 23 and 27).

Two limits, of different kinds:

- `max_evaluations`, deterministic: candidate paths evaluated (the IGA's
  fitness evaluations, a tree's iterations, a GA's individuals, a DE's
  trials; each planner counts its own unit, docs/planners.md). It decides
  where a run stops, so the same scenario and seed give the same plan on a
  quiet and on a busy machine.
- `time_budget_s`, the safety net against inputs whose evaluations are slow.
  It counts the CPU time of the planning process (`time.process_time`): what
  the planner actually got, so other work on the machine does not fire it,
  and on an idle machine the same as wall time. A wall-clock deadline at
  `WALL_FACTOR` x time_budget_s stays as the last net, for a machine so busy
  that the planner hardly runs. When either fires the plan is the best so
  far and says so in `warnings` (or there is none: CLI exit 3).

This module is the planner's documented deadline: the one place in the
planning core that reads a clock (`time.process_time`, `time.perf_counter`,
or the clock a test injects); nothing else in planning/ does.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field

Clock = Callable[[], float]
WALL_FACTOR = 4.0  # the wall-clock deadline, in multiples of time_budget_s


class BudgetExhausted(Exception):
    """Raised inside a planner's loop when its budget is spent (caught by the planner)."""


def cpu_clock() -> float:
    """CPU seconds of this process (all its threads): the budget's clock."""
    return time.process_time()


def wall_clock() -> float:
    """Seconds of wall time (monotonic): the last safety net and the plan's `elapsed_s`."""
    return time.perf_counter()


@dataclass
class Budget:
    """Evaluations left and the deadlines of one plan (shared by all its attempts)."""

    max_evaluations: int | None
    time_budget_s: float
    clock: Clock = cpu_clock
    started: float | None = None  # clock value the budget counts from (default: now)
    evaluations: int = 0
    wall: Clock = wall_clock
    time_fired: bool = field(default=False, init=False)

    def __post_init__(self) -> None:
        if self.started is None:
            self.started = self.clock()
        self.deadline = self.started + self.time_budget_s
        self.wall_started = self.wall()
        self.wall_deadline = self.wall_started + WALL_FACTOR * self.time_budget_s

    def excluding(self, work: Callable[[], object], when: Callable[[], bool]) -> None:
        """Run `work`, outside the budget when `when()` says so afterwards: both deadlines
        move on by the time it took (the compiled kernels' compilation, planning/warm.py,
        is not planning; their load from the cache counts like an import)."""
        cpu, wall = self.clock(), self.wall()
        work()
        if when():
            self.deadline += self.clock() - cpu
            self.wall_deadline += self.wall() - wall

    def spend(self, n: int = 1) -> None:
        self.evaluations += int(n)

    @property
    def out_of_evaluations(self) -> bool:
        return self.max_evaluations is not None and self.evaluations >= self.max_evaluations

    def left(self) -> int | None:
        """Evaluations left (None: no count limit)."""
        if self.max_evaluations is None:
            return None
        return max(self.max_evaluations - self.evaluations, 0)

    def time_expired(self) -> bool:
        """True once the time budget (or the wall deadline) has passed, and from then on."""
        if not self.time_fired and (self.clock() > self.deadline
                                    or self.wall() > self.wall_deadline):
            self.time_fired = True
        return self.time_fired

    def exhausted(self) -> bool:
        """Evaluations spent, or the wall deadline passed."""
        return self.out_of_evaluations or self.time_expired()

    def check(self) -> None:
        """Raise BudgetExhausted once more evaluations than allowed were spent or the wall
        deadline passed (a loop that stops at `exhausted()` never meets it)."""
        over = self.max_evaluations is not None and self.evaluations > self.max_evaluations
        if over or self.time_expired():
            raise BudgetExhausted

    def elapsed_s(self) -> float:
        """Wall seconds since the budget was made."""
        return self.wall() - self.wall_started

    def stop_reason(self) -> str | None:
        """'time_budget' (the wall net fired), 'max_evaluations', or None."""
        if self.time_fired:
            return "time_budget"
        if self.out_of_evaluations:
            return "max_evaluations"
        return None

    def warning(self) -> str:
        """The plan's warning when the wall-clock safety net fired."""
        return (f"time budget of {self.time_budget_s:g} s reached (safety net): best plan so "
                "far, which a faster machine may not repeat")

    def failure(self) -> str:
        """What a NoFeasiblePlan message says about the budget ('' when it was not spent)."""
        if self.time_fired:
            return f" within the time budget of {self.time_budget_s:g} s"
        if self.out_of_evaluations:
            return f" within {self.max_evaluations} evaluations"
        return ""
