"""Campaign SPEC.toml (docs/planners.md "Campaigns").

Required: `planners = [...]` (registry names), `families = [...]`
(recovery, transit, dense, colregs, traps), `seeds = N` (seeds 1..N).
Optional: `name` (default the file stem), `disturbances = [0.0, 0.2]`
(current speeds in m/s, direction `current_dir_deg`, default [0.0]),
`current_dir_deg = 0.0`, `hidden = 6` (seeded hidden scenarios per family
beside the public ones, as in `bench compare`), `dense_maps = 2` (seeded maps
per 004 start/goal pair),
`options = { "rrt-star" = { iterations = 800 } }` (per-planner options),
`time_budget_s = 5.0` and `max_evaluations = 20000` (the budget every planner gets, unless
its own options set it: docs/planners.md "Budget").
"""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any, TypeVar

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from usvstation.bench.compare import FAMILIES
from usvstation.planning.registry import planner_names

M = TypeVar("M", bound=BaseModel)


class CampaignError(ValueError):
    """A campaign could not be read or run; one line naming the field."""


class CampaignSpec(BaseModel):
    model_config = ConfigDict(extra="forbid")
    name: str = "campaign"
    planners: list[str] = Field(min_length=1)
    families: list[str] = Field(min_length=1)
    seeds: int = Field(ge=1, le=100_000)
    disturbances: list[float] = Field(default_factory=lambda: [0.0])
    current_dir_deg: float = 0.0
    hidden: int = Field(6, ge=0, le=10_000)
    dense_maps: int = Field(2, ge=1, le=1000)
    options: dict[str, dict[str, Any]] = Field(default_factory=dict)
    time_budget_s: float | None = Field(None, gt=0.0, le=600.0)
    max_evaluations: int | None = Field(None, ge=1, le=50_000_000)

    def planner_options(self, planner: str) -> dict[str, Any]:
        """The options of one planner: the common budget, then the planner's own options."""
        budget = {k: v for k, v in (("time_budget_s", self.time_budget_s),
                                    ("max_evaluations", self.max_evaluations)) if v is not None}
        return {**budget, **self.options.get(planner, {})}

    @field_validator("planners")
    @classmethod
    def _planners(cls, v: list[str]) -> list[str]:
        for p in v:
            if p not in planner_names():
                raise ValueError(f"unknown planner {p!r}; available: {', '.join(planner_names())}")
        return v

    @field_validator("families")
    @classmethod
    def _families(cls, v: list[str]) -> list[str]:
        for f in v:
            if f not in FAMILIES:
                raise ValueError(f"unknown family {f!r}; available: {', '.join(FAMILIES)}")
        return v

    @field_validator("disturbances")
    @classmethod
    def _dist(cls, v: list[float]) -> list[float]:
        if any(x < 0 for x in v):
            raise ValueError("current speeds must be >= 0 m/s")
        return v


def load_toml(path: Path, model: type[M], error: type[ValueError], what: str) -> M:
    """A TOML file read into `model` (its `name` defaults to the file's stem); `error` with one
    line naming the field when it cannot be read or is wrong."""
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise error(f"{path}: no such {what} file") from None
    except (OSError, tomllib.TOMLDecodeError) as exc:
        raise error(f"{path}: {exc}") from None
    data.setdefault("name", path.stem)
    try:
        return model(**data)
    except ValidationError as exc:
        err = exc.errors(include_url=False)[0]
        loc = ".".join(str(p) for p in err["loc"])
        raise error(f"{path}: {loc}: {err['msg'].removeprefix('Value error, ')}") from None


def load_spec(path: Path) -> CampaignSpec:
    return load_toml(path, CampaignSpec, CampaignError, "campaign")
