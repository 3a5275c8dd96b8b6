"""The same encoding and fitness run by pymoo's genetic algorithm, for comparison (issue 12).

pymoo's GA on the IGA's bit strings: binary random sampling (or the IGA's
preheated population), tournament selection, single-point crossover,
bit-flip mutation, duplicates eliminated, pymoo's own survival (which keeps
the best of parents and offspring). The population is evaluated in one
NumPy batch per generation (pymoo's vectorised Problem), as the IGA is. It
runs until it reaches a target fitness (the IGA's) or `max_generations`.
"""

from __future__ import annotations

import numpy as np

from usvstation.bench.deap_baseline import BaselineRun
from usvstation.clock import Stopwatch
from usvstation.planning.encoding import GeneLayout
from usvstation.planning.fitness import Evaluator


def run_pymoo(
    layout: GeneLayout, evaluator: Evaluator, *, population: int, seed: int, target: float,
    max_generations: int = 500, initial_bits: np.ndarray | None = None,
) -> BaselineRun:
    """Run pymoo's GA until the best fitness reaches `target` or `max_generations` pass."""
    from pymoo.algorithms.soo.nonconvex.ga import GA
    from pymoo.core.problem import Problem
    from pymoo.operators.crossover.pntx import SinglePointCrossover
    from pymoo.operators.mutation.bitflip import BitflipMutation
    from pymoo.operators.sampling.rnd import BinaryRandomSampling

    class BitProblem(Problem):
        def __init__(self) -> None:
            super().__init__(n_var=layout.n_bits, n_obj=1, xl=0, xu=1, vtype=bool)

        def _evaluate(self, x, out, *args, **kwargs):
            out["F"] = -evaluator(layout.decode(np.asarray(x, dtype=np.uint8))).fitness

    sampling = BinaryRandomSampling() if initial_bits is None else \
        initial_bits[:population].astype(bool)
    algorithm = GA(pop_size=population, sampling=sampling,
                   crossover=SinglePointCrossover(prob=0.9),
                   mutation=BitflipMutation(prob=1.0, prob_var=min(0.5, 1.5 / layout.n_bits)),
                   eliminate_duplicates=True)
    watch = Stopwatch()
    algorithm.setup(BitProblem(), seed=seed, verbose=False)
    best, gen = -np.inf, -1
    while gen < max_generations:
        algorithm.next()
        gen += 1
        best = max(best, -float(algorithm.opt.get("F").min()))
        if best >= target:
            break
    return BaselineRun(best_fitness=best, generations=gen,
                       evaluations=int(algorithm.evaluator.n_eval),
                       elapsed_s=watch.elapsed(), reached_target=best >= target)
