"""The IGA's generation in compiled calls (numba, issue 27): breeding and decode-and-map.

At the public cases' sizes (60-120 paths of 6-16 waypoints) the NumPy
operators of `iga.py` and `encoding.py` spend most of their time in the
fixed cost of NumPy calls. These kernels do the same arithmetic element by
element, each expression in the NumPy reference's order, so that they give
the same integers and the same floating-point values bit for bit
(tests/unit/test_plan_kernel_ga.py checks it on random inputs):

- `breed`: Elit_Strategy's ranking, tournament selection, single-point
  crossover, bit-flip mutation and SSIH's newborns (fresh paths and local
  re-initialisations of elite paths, clipped into range): the NumPy
  references are `iga._offspring`, `iga.mutate`, `iga.local_reinit` and
  `GeneLayout.levels_to_codes`.
- `decode`: TransferDecimal, decode-and-map and eq. 11 times
  (`GeneLayout.decode_codes`), waypoints as (N, P) arrays, one path per
  column, as the eq. 12 kernel reads them.
- `next_population`: SSIH's sacrifice (`iga._sacrifice`) and the new
  population (elite group and children).

The random numbers are drawn by the caller with NumPy's generator, in the
same order and shapes as the references draw them, and so are the
transcendental functions (exp), whose NumPy versions are vectorised
differently from libm: the kernels only do arithmetic on them. Compiled with
`cache=True`; without numba the IGA runs the NumPy references.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from usvstation.planning.encoding import GeneLayout
from usvstation.planning.kernel import AVAILABLE, njit


@dataclass(frozen=True)
class LayoutTables:
    """The gene layout as the kernels take it: int64 and float64 arrays and scalars."""

    gene_bits: np.ndarray  # (G,)
    gene_count: np.ndarray  # (G,)
    gene_start: np.ndarray  # (G,)
    gene_of_bit: np.ndarray  # (B,)
    bit_shift: np.ndarray  # (B,)
    x_count: np.ndarray  # (n_mid,)
    cone_gene: int  # -1 without an arrival cone
    cone_m: np.ndarray  # (x levels of the last block,)
    base: np.ndarray  # (G,) decode-and-map: (level + base) res + lo
    res: np.ndarray  # (G,)
    lo: np.ndarray  # (G,)
    ends: np.ndarray  # (start x, start y, start speed, goal x, goal y)
    y_res: float
    first_table: np.ndarray  # (x levels, y levels) of the first waypoint: first turn too wide

    @classmethod
    def of(cls, layout: GeneLayout,
           first_turn: Callable[[np.ndarray, np.ndarray], np.ndarray] | None = None,
           ) -> LayoutTables:
        """The tables of `layout`; with `first_turn` (the first-turn gate of first legs
        (dx, dy)) its value for every first waypoint, when there are at most
        `FIRST_TABLE_MAX` of them."""
        base, res, lo = layout._affine
        i64 = np.int64
        return cls(
            gene_bits=layout.gene_bits.astype(i64), gene_count=layout.gene_count.astype(i64),
            gene_start=layout.gene_start.astype(i64),
            gene_of_bit=layout.gene_of_bit.astype(i64), bit_shift=layout.bit_shift.astype(i64),
            x_count=layout.x_count.astype(i64),
            cone_gene=-1 if layout.cone_gene is None else int(layout.cone_gene),
            cone_m=layout.cone_m.astype(i64), base=base.astype(i64),
            res=res.astype(np.float64), lo=lo.astype(np.float64),
            ends=np.array([layout.start[0], layout.start[1], layout.start_speed,
                           layout.goal[0], layout.goal[1]], dtype=np.float64),
            y_res=float(layout.y_res),
            first_table=_first_table(layout, first_turn),
        )

    def coding(self) -> tuple:
        """The arguments of `_levels_to_codes` and `_codes_to_levels` after the array."""
        return (self.gene_bits, self.gene_count, self.cone_gene, self.cone_m)

    def mapping(self) -> tuple:
        """The arguments of `decode` after the codes."""
        return (*self.coding(), self.base, self.res, self.lo, self.ends, self.first_table)


FIRST_TABLE_MAX = 1 << 16


def _first_table(layout: GeneLayout,
                 first_turn: Callable[[np.ndarray, np.ndarray], np.ndarray] | None,
                 ) -> np.ndarray:
    """first_turn(dx, dy) of the first leg through each (x level, y level) of the first
    waypoint (decode-and-map's arithmetic): the gate depends on the first leg alone. Empty
    without `first_turn` or with more than `FIRST_TABLE_MAX` first waypoints."""
    nx, ny = int(layout.gene_count[0]), int(layout.gene_count[1])
    if first_turn is None or nx * ny > FIRST_TABLE_MAX:
        return np.zeros((0, 0), dtype=np.bool_)
    base, res, lo = layout._affine
    xl, yl = np.divmod(np.arange(nx * ny, dtype=np.int64), ny)
    pos_y = yl + base[1]
    if layout.cone_gene == 1:  # one intermediate waypoint: its y lies in the arrival cone
        pos_y = pos_y - layout.cone_m[xl]
    x1 = (xl + base[0]) * res[0] + lo[0]
    y1 = pos_y * res[1] + lo[1]
    bad = first_turn(x1 - layout.start[0], y1 - layout.start[1])
    return np.ascontiguousarray(bad.reshape(nx, ny))


def _codes_to_levels(codes: np.ndarray, gene_bits: np.ndarray, gene_count: np.ndarray,
                     cone_gene: int, cone_m: np.ndarray) -> np.ndarray:  # pragma: no cover
    """`GeneLayout.codes_to_levels`: (P, G) codes to levels."""
    p, g = codes.shape
    levels = np.empty((p, g), np.int64)
    for i in range(p):
        for j in range(g):
            levels[i, j] = (codes[i, j] * gene_count[j]) >> gene_bits[j]
        if cone_gene >= 0:
            n = 2 * cone_m[levels[i, cone_gene - 1]] + 1
            levels[i, cone_gene] = (codes[i, cone_gene] * n) >> gene_bits[cone_gene]
    return levels


def _clip_and_code(levels: np.ndarray, out: np.ndarray, row: int, gene_bits: np.ndarray,
                   gene_count: np.ndarray, cone_gene: int,
                   cone_m: np.ndarray) -> None:  # pragma: no cover
    """`GeneLayout.clip_levels` then `levels_to_codes` of one row of levels, into out[row]."""
    g = levels.shape[0]
    for j in range(g):
        levels[j] = min(max(levels[j], 0), gene_count[j] - 1)
    if cone_gene >= 0:
        levels[cone_gene] = min(levels[cone_gene], 2 * cone_m[levels[cone_gene - 1]])
    for j in range(g):
        count = gene_count[j]
        if j == cone_gene:
            count = 2 * cone_m[levels[cone_gene - 1]] + 1
        out[row, j] = -((-(levels[j] << gene_bits[j])) // count)


def _levels_to_codes(levels: np.ndarray, gene_bits: np.ndarray, gene_count: np.ndarray,
                     cone_gene: int, cone_m: np.ndarray) -> np.ndarray:  # pragma: no cover
    """`GeneLayout.levels_to_codes` (without clipping: levels in range)."""
    p, g = levels.shape
    out = np.empty((p, g), np.int64)
    for i in range(p):
        for j in range(g):
            count = gene_count[j]
            if j == cone_gene:
                count = 2 * cone_m[levels[i, cone_gene - 1]] + 1
            out[i, j] = -((-(levels[i, j] << gene_bits[j])) // count)
    return out


def _decode(codes: np.ndarray, gene_bits: np.ndarray, gene_count: np.ndarray, cone_gene: int,
            cone_m: np.ndarray, base: np.ndarray, res: np.ndarray, lo: np.ndarray,
            ends: np.ndarray, first_table: np.ndarray) -> tuple:  # pragma: no cover
    """`GeneLayout.decode_codes` as (N, P) arrays: x, y, v, t, then the (N - 1, P) segment
    lengths, dx and dy (eq. 11: dT = 2 L / (v_i + v_i+1), t accumulated in order), and
    each path's first-turn flag looked up in `first_table` (x level, y level of the first
    waypoint; all False when the table is empty)."""
    p, g = codes.shape
    n_mid = (g - 1) // 3
    n = n_mid + 2
    levels = codes_to_levels(codes, gene_bits, gene_count, cone_gene, cone_m)
    first_bad = np.zeros(p, np.bool_)
    if first_table.shape[0] > 0:
        for i in range(p):
            first_bad[i] = first_table[levels[i, 0], levels[i, 1]]
    x = np.empty((n, p))
    y = np.empty((n, p))
    v = np.empty((n, p))
    t = np.empty((n, p))
    seg = np.empty((n - 1, p))
    dx = np.empty((n - 1, p))
    dy = np.empty((n - 1, p))
    for i in range(p):
        x[0, i], y[0, i], v[0, i] = ends[0], ends[1], ends[2]
        x[n - 1, i], y[n - 1, i] = ends[3], ends[4]
        for j in range(g):
            pos = levels[i, j] + base[j]
            if j == cone_gene:
                pos -= cone_m[levels[i, cone_gene - 1]]
            value = pos * res[j] + lo[j]
            k, q = j // 3, j % 3
            if j == g - 1:
                v[n - 1, i] = value
            elif q == 0:
                x[k + 1, i] = value
            elif q == 1:
                y[k + 1, i] = value
            else:
                v[k + 1, i] = value
    for i in range(p):
        t[0, i] = 0.0
    for s in range(n - 1):
        for i in range(p):
            ddx = x[s + 1, i] - x[s, i]
            ddy = y[s + 1, i] - y[s, i]
            length = math.hypot(ddx, ddy)
            dx[s, i], dy[s, i], seg[s, i] = ddx, ddy, length
            t[s + 1, i] = t[s, i] + 2.0 * length / (v[s, i] + v[s + 1, i])
    return x, y, v, t, seg, dx, dy, first_bad


def _breed(codes: np.ndarray, fit: np.ndarray, order: np.ndarray, n_children: int,
           entrants: np.ndarray,
           cross_u: np.ndarray, cross_rate: float, cut_raw: np.ndarray, mut_flat: np.ndarray,
           fresh: np.ndarray, n_parents: int, pick: np.ndarray, centre: np.ndarray,
           half: np.ndarray, sign_u: np.ndarray, amp_exp: np.ndarray, u_local: np.ndarray,
           gene_bits: np.ndarray, gene_count: np.ndarray, gene_start: np.ndarray,
           gene_of_bit: np.ndarray, bit_shift: np.ndarray, x_count: np.ndarray,
           cone_gene: int, cone_m: np.ndarray, y_res: float) -> np.ndarray:  # pragma: no cover
    """Children then newborns (codes) of one generation.

    Children: tournaments (`entrants` (2 pairs, size), the first fittest wins), single-point
    crossover where cross_u < cross_rate at cut_raw (else cut = n_bits), rows [a-children,
    b-children][:n_children], then the bits `mut_flat` (flat row * n_bits + bit) flipped.
    Newborns: `fresh` as they are, then one local re-initialisation per row of `pick` of
    the `n_parents` fittest (`order`: the population ranked, fittest first, ties in index
    order; `iga.local_reinit` with its draws: parent, centre, half width, sign draw,
    exp(log amplitude), the (n, n_mid) uniforms), clipped and coded.
    """
    g = codes.shape[1]
    n_bits = gene_of_bit.shape[0]
    n_mid = x_count.shape[0]
    pairs = (n_children + 1) // 2
    n_fresh, n_local = fresh.shape[0], pick.shape[0]
    out = np.empty((n_children + n_fresh + n_local, g), np.int64)
    winners = np.empty(2 * pairs, np.int64)
    for r in range(2 * pairs):
        best = entrants[r, 0]
        for e in range(1, entrants.shape[1]):
            if fit[entrants[r, e]] > fit[best]:
                best = entrants[r, e]
        winners[r] = best
    for i in range(pairs):
        cut = cut_raw[i] if cross_u[i] < cross_rate else n_bits
        a, b = winners[i], winners[pairs + i]
        for j in range(g):
            width = gene_bits[j]
            before = min(max(cut - gene_start[j], 0), width)
            full = (np.int64(1) << width) - 1
            prefix = full & ~((np.int64(1) << (width - before)) - 1)
            swap = (codes[a, j] ^ codes[b, j]) & ~prefix
            if i < n_children:
                out[i, j] = codes[a, j] ^ swap
            if pairs + i < n_children:
                out[pairs + i, j] = codes[b, j] ^ swap
    for f in mut_flat:
        row, bit = f // n_bits, f % n_bits
        out[row, gene_of_bit[bit]] ^= np.int64(1) << bit_shift[bit]
    for i in range(n_fresh):
        for j in range(g):
            out[n_children + i, j] = fresh[i, j]
    if n_local == 0:
        return out
    elite = np.empty((n_parents, g), np.int64)
    for i in range(n_parents):
        for j in range(g):
            elite[i, j] = codes[order[i], j]
    parents = codes_to_levels(elite, gene_bits, gene_count, cone_gene, cone_m)
    lv = np.empty(g, np.int64)
    for i in range(n_local):
        for j in range(g):
            lv[j] = parents[pick[i], j]
        c, h = centre[i], half[i]
        amp = (-1.0 if sign_u[i] < 0.5 else 1.0) * amp_exp[i] / y_res
        for k in range(n_mid):
            weight = max(1.0 - abs(k - c) / (h + 1.0), 0.0)
            window = weight > 0.0
            u = u_local[i, k]
            if window and u < 0.3:
                lv[3 * k] = np.int64(u * (x_count[k] / 0.3))
            lv[3 * k + 1] += np.int64(round(amp * weight))
            if window:
                lv[3 * k + 2] += np.int64(math.floor(u * 9.0)) % 3 - 1
        clip_and_code(lv, out, n_children + n_fresh + i, gene_bits, gene_count, cone_gene,
                      cone_m)
    return out


def _next_population(codes: np.ndarray, fit: np.ndarray, order: np.ndarray, n_elite: int,
                     batch: np.ndarray, batch_fit: np.ndarray, n_children: int,
                     sacrifice: bool) -> tuple:  # pragma: no cover
    """The elite group (the `n_elite` first of `order`, the population ranked) and the
    children, whose dead (fitness <= 0) give their slots, first to last, to the living
    newborns, fittest first, ties in index order (SSIH, `iga._sacrifice`) when `sacrifice`.
    Returns (codes, fitness, dead children)."""
    g = codes.shape[1]
    out = np.empty((n_elite + n_children, g), np.int64)
    out_fit = np.empty(n_elite + n_children)
    for i in range(n_elite):
        for j in range(g):
            out[i, j] = codes[order[i], j]
        out_fit[i] = fit[order[i]]
    n_dead = 0
    for i in range(n_children):
        for j in range(g):
            out[n_elite + i, j] = batch[i, j]
        out_fit[n_elite + i] = batch_fit[i]
        if batch_fit[i] <= 0.0:
            n_dead += 1
    if not sacrifice or n_dead == 0:
        return out, out_fit, n_dead
    taken = np.zeros(batch_fit.shape[0], np.bool_)
    for i in range(n_children):
        if batch_fit[i] > 0.0:
            continue
        best = -1  # the fittest newborn not yet taken, the first of equals
        for j in range(n_children, batch_fit.shape[0]):
            if batch_fit[j] > 0.0 and not taken[j] and (best < 0 or batch_fit[j] > batch_fit[best]):
                best = j
        if best < 0:
            break
        taken[best] = True
        for j in range(g):
            out[n_elite + i, j] = batch[best, j]
        out_fit[n_elite + i] = batch_fit[best]
    return out, out_fit, n_dead


if AVAILABLE:
    codes_to_levels = njit(cache=True, nogil=True)(_codes_to_levels)
    clip_and_code = njit(cache=True, nogil=True)(_clip_and_code)
    levels_to_codes = njit(cache=True, nogil=True)(_levels_to_codes)
    decode = njit(cache=True, nogil=True)(_decode)
    breed = njit(cache=True, nogil=True)(_breed)
    next_population = njit(cache=True, nogil=True)(_next_population)
else:  # pragma: no cover - numba is a dependency; the IGA then runs the NumPy references
    codes_to_levels = levels_to_codes = decode = breed = next_population = None
