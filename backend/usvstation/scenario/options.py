"""Options of the improved genetic algorithm (IGA) of paper 000, section 3.2.

Defaults reproduce the paper where it gives a figure (3/7/4 bits, 1 m and
0.2 m/s resolution, about 10 % elite group, at most 500 generations); the
rest are documented choices (docs/planner.md).
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

EVALUATIONS_PER_INDIVIDUAL = 500  # default max_evaluations per member of the population


class IGAOptions(BaseModel):
    """Tunable parameters of the IGA; every field can be set in a scenario's `planner`."""

    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False)

    seed: int = Field(
        1, ge=0, le=2**32 - 1, description="random seed; the same seed gives the same plan"
    )

    # population and genetic operators
    population: int = Field(60, ge=4, le=1000)
    elite_fraction: float = Field(0.1, ge=0.0, le=0.5, description="share kept as elite group")
    tournament_size: int = Field(3, ge=2, le=16)
    crossover_rate: float = Field(0.9, ge=0.0, le=1.0)
    mutation_rate: float | None = Field(
        None, gt=0.0, le=0.5, description="per-bit flip probability; default 1.5 / bits"
    )

    # stopping (Algorithm 1 lines 20 and 30)
    generations_max: int = Field(500, ge=1, le=5000)
    fitness_target: float | None = Field(
        None, gt=0.0, le=1e9, description="stop once the best fitness reaches this value"
    )
    stall_generations: int = Field(
        8, ge=1, le=5000,
        description="converged when the best fitness stalls this many generations",
    )
    stall_tolerance: float = Field(
        5e-3, ge=0.0, le=1.0, description="relative gain counted as progress"
    )

    # encoding (eq. 10-11): widths grow to cover the scenario
    d_sl: float = Field(
        8.0, ge=0.5, le=10_000.0, description="nominal waypoint interval D_SL along x, m"
    )
    max_waypoints: int = Field(20, ge=1, le=200, description="cap on intermediate waypoints")
    x_resolution: float = Field(1.0, ge=0.05, le=1000.0, description="m")
    y_resolution: float = Field(1.0, ge=0.05, le=1000.0, description="m")
    speed_resolution: float = Field(0.2, ge=0.01, le=30.0, description="m/s")
    x_bits: int = Field(3, ge=1, le=24)
    y_bits: int = Field(7, ge=1, le=24)
    speed_bits: int = Field(4, ge=1, le=24)
    y_half_width: float = Field(
        64.0, gt=0.0, le=20_000.0, description="least |y| range searched, m"
    )
    y_margin: float = Field(
        15.0, ge=0.0, le=20_000.0, description="search beyond the start and obstacles in y, m"
    )

    # recovery approach
    approach_length: float = Field(
        5.0, ge=0.0, le=1000.0, description="straight run-in before the ramp end, m"
    )
    align_max_deg: float = Field(
        10.0, gt=0.0, le=45.0, description="last segment within this of the ramp axis"
    )
    final_straight: bool = Field(
        False, description="recovery (an extension of paper 000, issue 24): the last leg "
        "runs along the ramp axis (within 1 deg) from at least the first approach gate "
        "(vessel.gates_m[0]) in, so the boat is on the axis before its gates; a start off "
        "the axis runs out first if it needs the room; without such a plan the paper's "
        "run-in (approach_length, align_max_deg) with a warning")

    # fitness eq. 12: A / (a Fit_d + b Fit_T + c Fit_ang + d Fit_mal)
    weight_a: float = Field(4.0, ge=0.0, le=1e6, description="a, on Fit_d")
    weight_b: float = Field(
        1.4, ge=0.0, le=1e6, description="b, on Fit_T (normalised; 0.5 on the paper's seconds)"
    )
    weight_c: float = Field(2.0, ge=0.0, le=1e6, description="c, on Fit_ang")
    weight_d: float = Field(
        40.0, ge=0.0, le=1e6,
        description="d, on Fit_mal (recovery only; normalised; 0.5 on the paper's metres)",
    )
    terms: Literal["normalised", "paper"] = Field(
        "normalised",
        description="Fit_T and Fit_mal without units (t_end v_max / D, Fit_mal / D), or in the "
        "paper's seconds and metres (then weights b and d of about 0.5)",
    )
    scale_A: float = Field(10.0, gt=0.0, le=1e9, description="A, numerator of eq. 12")

    # preheating (Algorithm 1 lines 2-18)
    preheat_retries: int = Field(2, ge=1, le=64, description="N_max draws per waypoint")
    preheat_restarts: int = Field(
        3, ge=0, le=64, description="fresh starts of a blocked individual"
    )
    candidates: int = Field(10, ge=1, le=64, description="candidate points per draw")

    # ablations of section 4.2
    preheat: bool = Field(True, description="False = EG1: random initial population")
    ssih: bool = Field(True, description="False = EG2: no sacrifice and hybridisation")
    fitness: Literal["eq12", "linear"] = Field("eq12", description="'linear' = EG3")
    elitism: bool = Field(True, description="False = EG4: no elite group")

    time_budget_s: float = Field(
        5.0, gt=0.0, le=600.0,
        description="wall-clock safety net of one plan: past it the best feasible plan so far "
        "is returned with a warning, or none",
    )
    max_evaluations: int | None = Field(
        None, ge=1, le=50_000_000,
        description="deterministic budget of one plan: candidate paths evaluated, over all "
        "its attempts (default 500 x population); the plan does not depend on the machine's "
        "speed or load unless the wall-clock safety net fires first",
    )

    smoothing: bool = Field(True, description="add a B-spline smoothed path to the plan")
    clearance_fallback: bool = Field(
        True,
        description="when no plan keeps eq. 7's full margin, retry with R_c = 0 and then with "
        "half the hull length (the plan carries a warning)",
    )

    @model_validator(mode="after")
    def _weights_not_all_zero(self) -> IGAOptions:
        if self.weight_a + self.weight_b <= 0.0:
            raise ValueError(
                "planner.weight_a: weight_a or weight_b must be positive "
                "(Fit_d and Fit_T are the only terms that never vanish)"
            )
        return self

    @property
    def evaluation_budget(self) -> int:
        """`max_evaluations`, or 500 x population when it is not set."""
        return self.max_evaluations or EVALUATIONS_PER_INDIVIDUAL * self.population

    @property
    def elite_count(self) -> int:
        """Size of the elite group (0 when elitism is off)."""
        if not self.elitism or self.elite_fraction == 0.0:
            return 0
        return max(1, round(self.population * self.elite_fraction))

    @classmethod
    def ablation(cls, name: str, **overrides: object) -> IGAOptions:
        """Options for 'IGA' or one of the paper's ablations EG1..EG4 (section 4.2)."""
        switches = {
            "IGA": {},
            "EG1": {"preheat": False},
            "EG2": {"ssih": False},
            "EG3": {"fitness": "linear"},
            "EG4": {"elitism": False},
        }
        if name not in switches:
            raise ValueError(f"unknown ablation {name!r}; expected one of {sorted(switches)}")
        return cls(**{**switches[name], **overrides})
