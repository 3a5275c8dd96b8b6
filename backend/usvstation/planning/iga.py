"""The improved genetic algorithm (IGA) of paper 000 section 3.2, Algorithm 1.

    Foundation()            preheating: collision-free initial population
    while not converged:    (fitness threshold, stall, or 500 generations)
        Elit_Strategy()     the best ~10 % pass unchanged (elite group)
        Tournament()        parents by tournament selection
        TransferBinary(), Variation_binary(), TransferDecimal()
                            single-point binary crossover and bit-flip mutation,
                            then decode-and-map (eq. 10-11)
        TimeReset(), FitnessReset()
                            eq. 11 times and eq. 12 fitness for the whole population
        Intraspecific()     SSIH: fitness-0 individuals die, are re-initialised
                            locally and hybridised (Fig. 8)

The genome is the paper's binary string. It is stored packed, one integer
per gene (`codes`, shape (P, genes)), and the operators act on its bits with
masks: a single-point crossover at bit c takes every bit before c from one
parent and the rest from the other, a mutation flips single bits. Every step
works on the whole population per NumPy call; the only Python loop is over
generations.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from usvstation.planning import kernel_ga
from usvstation.planning.budget import Budget
from usvstation.planning.encoding import GeneLayout, PathBatch
from usvstation.planning.fitness import Evaluation, Evaluator, first_turn_of
from usvstation.planning.kernel import eq12_batch
from usvstation.planning.kernel_ga import LayoutTables
from usvstation.planning.preheat import PreheatReport, preheat, random_levels
from usvstation.planning.problem import Problem
from usvstation.scenario.options import IGAOptions

_BUMP_LOG_M = (float(np.log(0.6)), float(np.log(12.0)))  # local_reinit's bump amplitude, log m
EVAL_CHUNK = 128  # paths per evaluation pass; the budget is checked between passes


@dataclass
class IGAResult:
    """Best path found, its evaluation and how the run went."""

    layout: GeneLayout
    best: PathBatch  # one row
    evaluation: Evaluation  # one row
    generations: int
    stop_reason: str
    elapsed_s: float
    history_best: list[float] = field(default_factory=list)
    history_elite_mean: list[float] = field(default_factory=list)
    preheat: PreheatReport | None = None
    evaluations: int = 0

    @property
    def feasible(self) -> bool:
        return bool(self.evaluation.feasible[0]) and float(self.evaluation.fitness[0]) > 0.0


@dataclass
class _Population:
    codes: np.ndarray  # (P, G) packed binary genes
    fit: np.ndarray  # (P,)


def run_iga(
    problem: Problem, opts: IGAOptions, layout: GeneLayout | None = None,
    budget: Budget | None = None, compiled: bool | None = None,
) -> IGAResult:
    """Plan with the IGA; deterministic for a given `opts.seed`.

    `budget` (default: the options' own) is shared with the plan's other
    attempts. Its evaluation count is checked after every `EVAL_CHUNK` paths
    evaluated and after every generation (stop_reason "max_evaluations"), at
    points that do not depend on time. Its wall deadline, the safety net, is
    checked there too and after every preheating draw (stop_reason
    "time_budget"), so a run overshoots it by at most one such batch.

    `compiled` (default: where numba is available) runs each generation in the compiled
    kernels (planning/kernel_ga.py); False runs the NumPy references, which give the same
    result bit for bit.
    """
    budget = budget or Budget(opts.evaluation_budget, opts.time_budget_s)
    t0 = budget.wall()
    expired = budget.time_expired
    rng = np.random.default_rng(opts.seed)
    layout = layout or GeneLayout.build(problem, opts)
    pop_n, n_elite = opts.population, opts.elite_count
    pm = opts.mutation_rate or min(0.5, 1.5 / layout.n_bits)

    evaluator = Evaluator(problem, opts, layout.segment_x_range())
    engine = _Compiled.of(layout, evaluator, problem, opts) if compiled is not False else None

    def fitness(codes: np.ndarray) -> tuple[np.ndarray, bool]:
        """Eq. 12 of `codes` in chunks, the budget checked after each; rows left out when
        it runs out keep fitness 0. Returns (fitness, complete)."""
        out = np.zeros(codes.shape[0])
        for k in range(0, codes.shape[0], EVAL_CHUNK):
            part = codes[k:k + EVAL_CHUNK]
            out[k:k + part.shape[0]] = (
                engine.fitness(part) if engine is not None
                else evaluator.fitness(layout.decode_codes(part)))
            budget.spend(part.shape[0])
            if k + EVAL_CHUNK < codes.shape[0] and budget.exhausted():
                return out, False
        return out, True

    evaluations_before = budget.evaluations
    levels, fresh, report = _foundation(layout, problem, opts, rng, expired,
                                        compiled=engine is not None)
    codes = layout.levels_to_codes(levels)
    first_fit, complete = fitness(codes)
    pop = _Population(codes, first_fit)

    best_codes, best_fit = pop.codes[np.argmax(pop.fit)].copy(), float(pop.fit.max())
    hist_best, hist_elite = [best_fit], [_elite_mean(pop.fit, n_elite)]
    stop, gen = "generations_max", 0
    if not complete or budget.exhausted():
        stop = budget.stop_reason() or "time_budget"
    n_newborn = pop_n // 2  # SSIH candidates per generation, sized from the last death toll
    while gen < opts.generations_max and stop not in ("time_budget", "max_evaluations"):
        gen += 1
        n_parents = max(n_elite, 1) if best_fit > 0.0 else 0
        if engine is not None:
            pop, n_dead, fresh, report = engine.generation(
                pop, n_parents, fresh, n_newborn, report, rng, pm, fitness, expired)
        else:
            pop, n_dead, fresh, report = _generation_numpy(
                layout, problem, opts, pop, n_parents, fresh, n_newborn, report, rng, pm,
                fitness, expired)
        if opts.ssih:
            n_newborn = min(pop_n, max(8, (3 * n_dead) // 2))
        i = int(np.argmax(pop.fit))
        if pop.fit[i] > best_fit:
            best_fit, best_codes = float(pop.fit[i]), pop.codes[i].copy()
        hist_best.append(best_fit)
        hist_elite.append(_elite_mean(pop.fit, n_elite))
        reason = _converged(hist_best, opts)
        if reason is None and budget.exhausted():
            reason = budget.stop_reason()
        if reason:
            stop = reason
            break

    best = layout.decode_codes(best_codes[None, :])
    return IGAResult(
        layout=layout, best=best, evaluation=evaluator(best), generations=gen,
        stop_reason=stop, elapsed_s=budget.wall() - t0, history_best=hist_best,
        history_elite_mean=hist_elite, preheat=report,
        evaluations=budget.evaluations - evaluations_before,
    )


def _foundation(
    layout: GeneLayout, problem: Problem, opts: IGAOptions, rng: np.random.Generator,
    expired: Callable[[], bool] | None = None, compiled: bool | None = None,
) -> tuple[np.ndarray, np.ndarray, PreheatReport]:
    """Initial population (levels), a stock of fresh preheated paths for SSIH, the report.

    With preheating (Algorithm 1 lines 2-18) the population is grown
    collision-free, with a surplus kept as fresh stock; EG1 starts from
    random bits instead.
    """
    pop_n = opts.population
    if not opts.preheat:
        empty = np.zeros((0, layout.n_genes), dtype=np.int64)
        return random_levels(layout, rng, pop_n), empty, PreheatReport()
    grown, ok, report = preheat(layout, problem, opts, rng, 2 * pop_n, need=pop_n,
                                expired=expired, compiled=compiled)
    if ok.sum() < max(4, pop_n // 4) and not (expired and expired()):
        # hard problem: one more round with many more candidates and draws per waypoint
        harder = opts.model_copy(update={
            "candidates": 4 * opts.candidates, "preheat_retries": 4 * opts.preheat_retries,
        })
        more, ok_more, rep = preheat(layout, problem, harder, rng, pop_n,
                                     need=max(4, pop_n // 4) - int(ok.sum()), expired=expired,
                                     compiled=compiled)
        report.merge(rep)
        grown, ok = np.concatenate([grown, more]), np.concatenate([ok, ok_more])
    grown = grown[ok]
    levels, fresh = grown[:pop_n], grown[pop_n:]
    if levels.shape[0] < pop_n:
        levels = np.concatenate([levels, random_levels(layout, rng, pop_n - levels.shape[0])])
    return levels, layout.levels_to_codes(fresh), report


Fitness = Callable[[np.ndarray], tuple[np.ndarray, bool]]


def _generation_numpy(
    layout: GeneLayout, problem: Problem, opts: IGAOptions, pop: _Population, n_parents: int,
    fresh: np.ndarray, n_newborn: int, report: PreheatReport, rng: np.random.Generator,
    pm: float, fitness: Fitness, expired: Callable[[], bool] | None,
) -> tuple[_Population, int, np.ndarray, PreheatReport]:
    """One generation with the NumPy operators (the reference of `_Compiled.generation`):
    elite group, offspring, SSIH's newborns and sacrifice. Returns the new population,
    the children that died, the fresh stock left and the preheating report."""
    n_elite = opts.elite_count
    order = np.argsort(-pop.fit, kind="stable")
    elite = order[:n_elite]
    children = _offspring(layout, pop, pop.codes.shape[0] - n_elite, opts, pm, rng)
    newborn = children[:0]
    if opts.ssih:
        parents = pop.codes[order[:n_parents]]
        newborn, fresh, report = _newborns(
            layout, problem, opts, rng, parents, fresh, n_newborn, report, expired
        )
    batch_fit, _ = fitness(np.concatenate([children, newborn]))
    child_fit, born_fit = batch_fit[: children.shape[0]], batch_fit[children.shape[0] :]
    n_dead = int(np.count_nonzero(child_fit <= 0.0))
    if opts.ssih:
        children, child_fit = _sacrifice(children, child_fit, newborn, born_fit)
    pop = _Population(np.concatenate([pop.codes[elite], children]),
                      np.concatenate([pop.fit[elite], child_fit]))
    return pop, n_dead, fresh, report


@dataclass
class _Compiled:
    """One generation and eq. 12 in compiled calls (planning/kernel_ga.py, kernel.py).

    The random numbers are drawn here with NumPy, in the order and shapes the NumPy
    operators draw them, and so are the transcendental functions (arctan2, sin, cos,
    exp); the kernels do the rest. The results equal the NumPy route bit for bit.
    """

    layout: GeneLayout
    problem: Problem
    opts: IGAOptions
    evaluator: Evaluator
    tables: LayoutTables
    eq12_args: tuple[np.ndarray, ...] | None
    first_untabled: bool  # the first-turn gate applies and is computed per path

    @classmethod
    def of(cls, layout: GeneLayout, evaluator: Evaluator, problem: Problem,
           opts: IGAOptions) -> _Compiled | None:
        """The compiled route for this run, or None without numba."""
        if not kernel_ga.AVAILABLE:
            return None
        first = None
        if problem.start_heading is not None:
            def first(dx: np.ndarray, dy: np.ndarray) -> np.ndarray:
                h0 = np.arctan2(dy, dx)
                return first_turn_of(h0, layout.start_speed, problem) > problem.turn_max
        tables = LayoutTables.of(layout, first)
        return cls(layout, problem, opts, evaluator, tables, evaluator._kernel_args(),
                   problem.start_heading is not None and tables.first_table.shape[0] == 0)

    def fitness(self, codes: np.ndarray) -> np.ndarray:
        """`Evaluator.fitness` of the decoded codes (one chunk)."""
        if self.eq12_args is None:  # EG3's linear fitness: the NumPy evaluator
            return self.evaluator.fitness(self.layout.decode_codes(codes))
        x, y, v, t, seg, dx, dy, first_bad = kernel_ga.decode(codes, *self.tables.mapping())
        heading = np.arctan2(dy, dx)
        if self.first_untabled:  # too many first waypoints for a table: per path
            problem = self.problem
            first_bad = first_turn_of(heading[0], v[0], problem) > problem.turn_max
        return eq12_batch(x, y, v, t, seg, heading, first_bad, *self.eq12_args)

    def generation(
        self, pop: _Population, n_parents: int, fresh: np.ndarray, n_newborn: int,
        report: PreheatReport, rng: np.random.Generator, pm: float, fitness: Fitness,
        expired: Callable[[], bool] | None,
    ) -> tuple[_Population, int, np.ndarray, PreheatReport]:
        """`_generation_numpy` with the operators compiled."""
        layout, opts, tab = self.layout, self.opts, self.tables
        pop_n, n_elite = pop.codes.shape[0], opts.elite_count
        n = pop_n - n_elite
        pairs = (n + 1) // 2
        # _offspring's and mutate's draws
        entrants = rng.integers(0, pop_n, size=(2 * pairs, opts.tournament_size))
        cross_u = rng.random(pairs)
        cut_raw = rng.integers(1, max(layout.n_bits, 2), size=pairs)
        total = n * layout.n_bits
        flat = rng.choice(total, size=rng.binomial(total, pm), replace=False)
        # _newborns' draws
        pool, n_local = pop.codes[:0], 0
        if opts.ssih:
            pool, n_local, fresh, report = self._newborn_pool(
                n_parents, fresh, n_newborn, report, rng, expired)
        local = _local_draws(layout, rng, n_parents, n_local)
        order = np.argsort(-pop.fit, kind="stable")
        batch = kernel_ga.breed(
            pop.codes, pop.fit, order, n, entrants, cross_u, opts.crossover_rate, cut_raw, flat,
            pool, n_parents, *local, tab.gene_bits, tab.gene_count, tab.gene_start, tab.gene_of_bit,
            tab.bit_shift, tab.x_count, tab.cone_gene, tab.cone_m, tab.y_res)
        batch_fit, _ = fitness(batch)
        codes, fit, n_dead = kernel_ga.next_population(pop.codes, pop.fit, order, n_elite,
                                                       batch, batch_fit, n, opts.ssih)
        return _Population(codes, fit), n_dead, fresh, report

    def _newborn_pool(
        self, n_parents: int, fresh: np.ndarray, n: int, report: PreheatReport,
        rng: np.random.Generator, expired: Callable[[], bool] | None,
    ) -> tuple[np.ndarray, int, np.ndarray, PreheatReport]:
        """`_newborns` up to its local re-initialisations: (fresh or random newborns,
        how many local re-initialisations follow, fresh stock left, report)."""
        layout, opts = self.layout, self.opts
        if not opts.preheat:
            pool = layout.levels_to_codes(random_levels(layout, rng, max(1, n // 5)))
            if n_parents:
                return pool, n - pool.shape[0], fresh, report
            return layout.levels_to_codes(random_levels(layout, rng, n)), 0, fresh, report
        if n_parents == 0 and fresh.shape[0] == 0:
            grown, ok, rep = preheat(layout, self.problem, opts, rng, n, expired=expired)
            report.merge(rep)
            fresh = layout.levels_to_codes(grown[ok])
        n_fresh = min(fresh.shape[0], n if n_parents == 0 else max(1, n // 5))
        return fresh[:n_fresh], (n - n_fresh) if n_parents else 0, fresh[n_fresh:], report


def _local_draws(layout: GeneLayout, rng: np.random.Generator, n_parents: int,
                 n: int) -> tuple[np.ndarray, ...]:
    """`local_reinit`'s random numbers, drawn in its order: parent, centre, half width,
    sign, exp(log amplitude), the (n, n_mid) uniforms (none for n = 0)."""
    if n == 0:
        empty = np.zeros(0, dtype=np.int64)
        return empty, empty, empty, np.zeros(0), np.zeros(0), np.zeros((0, layout.n_mid))
    pick = rng.integers(0, n_parents, size=n)
    centre = rng.integers(0, layout.n_mid, size=n)
    half = rng.integers(0, 4, size=n)
    sign_u = rng.random(n)
    amp_exp = np.exp(rng.uniform(*_BUMP_LOG_M, size=n))
    return pick, centre, half, sign_u, amp_exp, rng.random((n, layout.n_mid))


def _elite_mean(fit: np.ndarray, n_elite: int) -> float:
    """Mean fitness of the elite group: np.mean of the k largest, without its wrapper."""
    k = max(n_elite, 1)
    top = fit.copy()
    top.partition(fit.shape[0] - k)
    return float(np.add.reduce(top[-k:]) / k)


def _offspring(layout: GeneLayout, pop: _Population, n: int, opts: IGAOptions, pm: float,
               rng: np.random.Generator) -> np.ndarray:
    """Tournament selection, single-point binary crossover and bit-flip mutation."""
    if n <= 0:
        return pop.codes[:0]
    pop_n = pop.codes.shape[0]
    pairs = (n + 1) // 2
    entrants = rng.integers(0, pop_n, size=(2 * pairs, opts.tournament_size))
    winners = entrants[np.arange(2 * pairs), np.argmax(pop.fit[entrants], axis=1)]
    a, b = pop.codes[winners[:pairs]], pop.codes[winners[pairs:]]
    cross = rng.random(pairs) < opts.crossover_rate
    cut = np.where(cross, rng.integers(1, max(layout.n_bits, 2), size=pairs), layout.n_bits)
    children = np.concatenate(single_point_crossover(layout, a, b, cut))[:n]
    return mutate(layout, children, pm, rng)


def single_point_crossover(
    layout: GeneLayout, a: np.ndarray, b: np.ndarray, cut: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Children taking bits [0, cut) from one parent and [cut, n_bits) from the other.

    `cut` = n_bits copies the parents unchanged.
    """
    swap = (a ^ b) & ~layout.prefix_masks(cut)  # the bits from `cut` on, where they differ
    return a ^ swap, b ^ swap


def mutate(
    layout: GeneLayout, codes: np.ndarray, pm: float, rng: np.random.Generator
) -> np.ndarray:
    """Flip every bit independently with probability pm."""
    total = codes.shape[0] * layout.n_bits
    flat = rng.choice(total, size=rng.binomial(total, pm), replace=False)
    row, bit = np.divmod(flat, layout.n_bits)
    out = codes.copy()
    np.bitwise_xor.at(out, (row, layout.gene_of_bit[bit]), np.int64(1) << layout.bit_shift[bit])
    return out


def _newborns(
    layout: GeneLayout, problem: Problem, opts: IGAOptions, rng: np.random.Generator,
    parents: np.ndarray, fresh: np.ndarray, n: int, report: PreheatReport,
    expired: Callable[[], bool] | None = None,
) -> tuple[np.ndarray, np.ndarray, PreheatReport]:
    """SSIH's newborns (codes): mostly local re-initialisations of elite paths, some fresh.

    Without a living elite the newborns are preheated directly; under EG1
    (no preheating at all) they are random instead. Returns (newborns, fresh
    stock left, report).
    """
    if not opts.preheat:
        pool = [layout.levels_to_codes(random_levels(layout, rng, max(1, n // 5)))]
        if parents.shape[0]:
            local = local_reinit(layout, rng, layout.codes_to_levels(parents), n - pool[0].shape[0])
            pool.append(layout.levels_to_codes(local))
        else:
            pool = [layout.levels_to_codes(random_levels(layout, rng, n))]
        return np.concatenate(pool), fresh, report
    if parents.shape[0] == 0 and fresh.shape[0] == 0:
        grown, ok, rep = preheat(layout, problem, opts, rng, n, expired=expired,
                                 compiled=False)
        report.merge(rep)
        fresh = layout.levels_to_codes(grown[ok])
    n_fresh = min(fresh.shape[0], n if parents.shape[0] == 0 else max(1, n // 5))
    pool = [fresh[:n_fresh]]
    if parents.shape[0]:
        local = local_reinit(layout, rng, layout.codes_to_levels(parents), n - n_fresh)
        pool.append(layout.levels_to_codes(local))
    return np.concatenate(pool), fresh[n_fresh:], report


def _sacrifice(
    children: np.ndarray, child_fit: np.ndarray, newborn: np.ndarray, born_fit: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Strategy of Sacrifice and Intraspecific Hybridisation (paper 000 Fig. 8).

    Children with fitness 0 die and their slots go to the fittest feasible
    newborns; the newborns are hybridised with the rest of the population by
    the next generation's crossover.
    """
    dead = np.flatnonzero(child_fit <= 0.0)
    alive = np.flatnonzero(born_fit > 0.0)
    if dead.size == 0 or alive.size == 0:
        return children, child_fit
    alive = alive[np.argsort(-born_fit[alive], kind="stable")][: dead.size]
    slots = dead[: alive.size]
    children, child_fit = children.copy(), child_fit.copy()
    children[slots], child_fit[slots] = newborn[alive], born_fit[alive]
    return children, child_fit


def local_reinit(
    layout: GeneLayout, rng: np.random.Generator, parents: np.ndarray, n: int
) -> np.ndarray:
    """Re-initialise a window of waypoints of random parents (levels), smoothly.

    A window of 0-3 waypoints either side of a random centre is redrawn: y is
    displaced by a tent-shaped bump (so turns stay gentle) whose amplitude is
    log-uniform between 0.6 and 12 m (mostly fine adjustments, some detours),
    x is redrawn inside its D_SL block and speeds move by one level.
    """
    n_mid = layout.n_mid
    lv = parents[rng.integers(0, parents.shape[0], size=n)]
    centre = rng.integers(0, n_mid, size=(n, 1))
    half = rng.integers(0, 4, size=(n, 1))
    weight = np.maximum(1.0 - np.abs(np.arange(n_mid) - centre) / (half + 1.0), 0.0)
    sign = np.where(rng.random((n, 1)) < 0.5, -1.0, 1.0)
    amp = sign * np.exp(rng.uniform(*_BUMP_LOG_M, size=(n, 1))) / layout.y_res
    u = rng.random((n, n_mid))
    window = weight > 0.0
    xs, ys, vs = lv[:, 0 : 3 * n_mid : 3], lv[:, 1 : 3 * n_mid : 3], lv[:, 2 : 3 * n_mid : 3]
    xs[:] = np.where(window & (u < 0.3), (u * (layout.x_count / 0.3)).astype(np.int64), xs)
    ys += np.rint(amp * weight).astype(np.int64)
    vs += window * (np.floor(u * 9.0).astype(np.int64) % 3 - 1)
    return layout.clip_levels(lv)


def _converged(hist: list[float], opts: IGAOptions) -> str | None:
    """Stop at the fitness threshold, on stalled progress, or when nothing feasible appears."""
    best = hist[-1]
    if opts.fitness_target is not None and best >= opts.fitness_target:
        return "fitness_target"
    n = opts.stall_generations
    if len(hist) > n:
        before = hist[-1 - n]
        if best > 0.0 and best <= before * (1.0 + opts.stall_tolerance):
            return "converged"
        if best <= 0.0 and len(hist) > 2 * n:
            return "no_feasible_individual"
    return None
