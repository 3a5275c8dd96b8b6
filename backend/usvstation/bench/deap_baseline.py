"""The same encoding and fitness run by a general GA library (DEAP), for comparison.

DEAP's standard operators on the IGA's bit strings: tournament selection,
one-point crossover, bit-flip mutation, the eaSimple generation scheme
(no elitism, no preheating, no SSIH). The individuals a generation needs
evaluated are decoded and evaluated in one batch, as the IGA does, so the
comparison measures the algorithms rather than Python loops. It runs
until it reaches a target fitness (the IGA's) or 500 generations, so that
times compare at equal or worse fitness.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

import numpy as np

from usvstation.clock import Stopwatch
from usvstation.planning.encoding import GeneLayout
from usvstation.planning.fitness import Evaluator


@dataclass
class BaselineRun:
    best_fitness: float
    generations: int
    evaluations: int
    elapsed_s: float
    reached_target: bool


def _deap_types():
    from deap import base, creator

    if not hasattr(creator, "UsvFitnessMax"):
        creator.create("UsvFitnessMax", base.Fitness, weights=(1.0,))
        creator.create("UsvIndividual", list, fitness=creator.UsvFitnessMax)
    return creator.UsvIndividual


def run_deap(
    layout: GeneLayout, evaluator: Evaluator, *, population: int, seed: int, target: float,
    max_generations: int = 500, initial_bits: np.ndarray | None = None,
    crossover_rate: float = 0.9, tournament_size: int = 3,
) -> BaselineRun:
    """Run DEAP until the best fitness reaches `target` or `max_generations` pass."""
    from deap import algorithms, base, tools

    individual = _deap_types()
    rnd = random.Random(seed)
    random.seed(seed)  # DEAP's operators draw from the module-level generator
    pm = min(0.5, 1.5 / layout.n_bits)

    def evaluate_all(inds: list) -> int:
        """Evaluate every individual of `inds` in one NumPy batch; returns how many."""
        if not inds:
            return 0
        fit = evaluator(layout.decode(np.asarray(inds, dtype=np.uint8))).fitness
        for ind, f in zip(inds, fit, strict=True):
            ind.fitness.values = (float(f),)
        return len(inds)

    toolbox = base.Toolbox()
    toolbox.register("mate", tools.cxOnePoint)
    toolbox.register("mutate", tools.mutFlipBit, indpb=pm)
    toolbox.register("select", tools.selTournament, tournsize=tournament_size)

    watch = Stopwatch()
    if initial_bits is None:
        pop = [individual(rnd.randint(0, 1) for _ in range(layout.n_bits))
               for _ in range(population)]
    else:
        pop = [individual(int(b) for b in row) for row in initial_bits[:population]]
    evaluations = evaluate_all(pop)
    best = max(ind.fitness.values[0] for ind in pop)
    gen = 0
    while best < target and gen < max_generations:
        gen += 1
        offspring = algorithms.varAnd(toolbox.select(pop, len(pop)), toolbox,
                                      cxpb=crossover_rate, mutpb=1.0)
        evaluations += evaluate_all([ind for ind in offspring if not ind.fitness.valid])
        pop[:] = offspring
        best = max(best, max(ind.fitness.values[0] for ind in pop))
    return BaselineRun(best_fitness=best, generations=gen, evaluations=evaluations,
                       elapsed_s=watch.elapsed(), reached_target=best >= target)
