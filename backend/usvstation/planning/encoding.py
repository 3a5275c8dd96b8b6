"""Binary encoding of recovery paths (paper 000 section 3.2.2, eq. 10-11).

A path is start -> n_mid intermediate waypoints -> goal. Waypoints are
stepped along x: waypoint k owns a block of x positions (the interval D_SL
of eq. 10) and carries three binary genes, an x offset inside its block, a
y coordinate and a speed; the goal carries one more speed gene. The start's
speed is the boat's current speed and is not encoded.

Decode-and-map (the paper's overflow fix): a gene of b bits holds a code k
in [0, 2^b); it is mapped onto the n <= 2^b admissible levels of its
variable by level = floor(k n / 2^b), so every code decodes to a valid
value. The inverse, used when preheating writes paths into genes, is
k = ceil(level 2^b / n). Widths start from the paper's 3/7/4 bits and grow
until every level is reachable, so a 400 m transit encodes as well as an
85 m recovery.

For a recovery the last intermediate waypoint's y gene maps into the cone
|y| <= x tan(align_max) around the ramp axis, so the final segment always
arrives along the axis; this is the same decode-and-map step with a range
that depends on the decoded x.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from usvstation.planning.problem import Problem
from usvstation.scenario.options import IGAOptions

PREFIX_TABLE_ELEMENTS = 1 << 18  # crossover mask table: at most 2 MB, else computed per call


class InfeasibleProblem(ValueError):
    """The scenario admits no path of the encoded form; the message says why."""


@dataclass(frozen=True)
class PathBatch:
    """Decoded paths, one per row: waypoints (x, y, v) and eq. 11 times."""

    x: np.ndarray  # (P, N) m
    y: np.ndarray  # (P, N) m
    v: np.ndarray  # (P, N) m/s
    t: np.ndarray  # (P, N) s
    seg_len: np.ndarray  # (P, N-1) m
    seg_dt: np.ndarray  # (P, N-1) s
    seg_dx: np.ndarray  # (P, N-1) m
    seg_dy: np.ndarray  # (P, N-1) m

    def __len__(self) -> int:
        return int(self.x.shape[0])

    def rows(self, sel: slice | np.ndarray) -> PathBatch:
        """The paths of rows `sel` (a slice or an index array)."""
        return PathBatch(*(getattr(self, f)[sel] for f in (
            "x", "y", "v", "t", "seg_len", "seg_dt", "seg_dx", "seg_dy")))


def timed_paths(x: np.ndarray, y: np.ndarray, v: np.ndarray) -> PathBatch:
    """Waypoints (P, N) with eq. 11 segment times dT = 2 L / (v_i + v_i+1) (speeds > 0)."""
    dx, dy = x[:, 1:] - x[:, :-1], y[:, 1:] - y[:, :-1]
    seg_len = np.hypot(dx, dy)
    seg_dt = 2.0 * seg_len / (v[:, :-1] + v[:, 1:])
    t = np.empty_like(x)
    t[:, 0] = 0.0
    np.add.accumulate(seg_dt, axis=1, out=t[:, 1:])  # np.cumsum, without its wrapper
    return PathBatch(x=x, y=y, v=v, t=t, seg_len=seg_len, seg_dt=seg_dt, seg_dx=dx, seg_dy=dy)


def _bits_for(levels: int, minimum: int) -> int:
    return max(minimum, math.ceil(math.log2(max(levels, 1))) if levels > 1 else minimum)


@dataclass(frozen=True)
class GeneLayout:
    """Where each waypoint's genes sit and how codes map to coordinates."""

    start: np.ndarray  # (2,)
    start_speed: float
    goal: np.ndarray  # (2,)
    n_mid: int
    x_min: float  # x of position 0
    x_base: np.ndarray  # (n_mid,) first position index of each waypoint's block
    x_count: np.ndarray  # (n_mid,) positions per block
    x_res: float
    y_lo: float
    y_count: int
    y_res: float
    v_lo: float
    v_count: int
    v_res: float
    cone_tan: float | None  # recovery: last waypoint within |y| <= x tan(align)
    gene_bits: np.ndarray  # (G,) width of every gene
    gene_count: np.ndarray  # (G,) levels of every gene (cone gene: upper bound)
    gene_of_bit: np.ndarray = field(repr=False)  # (B,) gene index of every bit
    bit_shift: np.ndarray = field(repr=False)  # (B,) place value exponent, MSB first
    bit_weight: np.ndarray = field(repr=False)  # (B, G) 2**shift where the bit belongs
    gene_start: np.ndarray = field(repr=False)  # (G,) index of every gene's first bit
    cone_m: np.ndarray = field(repr=False)  # (x_count[-1],) cone half-width per last x level

    # --- construction -------------------------------------------------------
    @classmethod
    def build(cls, problem: Problem, opts: IGAOptions) -> GeneLayout:
        """Choose block sizes and widths that cover the problem (eq. 10)."""
        xs = float(problem.start[0])
        x_res = opts.x_resolution
        x_min = max(opts.approach_length, x_res) if problem.recovery else x_res
        n_pos = math.floor((xs - x_res - x_min) / x_res + 1e-9) + 1
        if n_pos < 1:
            raise InfeasibleProblem(
                f"the start is only {xs:.1f} m out along the approach axis; the run-in "
                f"needs waypoints at least {x_min:g} m out (approach_length)"
            )
        n_mid = max(1, round(xs / opts.d_sl) - 1)
        n_mid = min(n_mid, opts.max_waypoints, n_pos)
        # blocks in path order: block 0 holds the positions nearest the start
        sizes = np.full(n_mid, n_pos // n_mid)
        sizes[: n_pos % n_mid] += 1
        upper = n_pos - np.concatenate([[0], np.cumsum(sizes)[:-1]])  # exclusive top index
        x_base = upper - sizes
        y_lo, y_count = _y_range(problem, opts)
        v_count = math.floor((problem.speed_max - problem.speed_min) / opts.speed_resolution
                             + 1e-9) + 1
        x_bits = _bits_for(int(sizes.max()), opts.x_bits)
        y_bits = _bits_for(y_count, opts.y_bits)
        v_bits = _bits_for(v_count, opts.speed_bits)
        gene_bits = np.array([x_bits, y_bits, v_bits] * n_mid + [v_bits])
        gene_count = np.array(
            [c for k in range(n_mid) for c in (sizes[k], y_count, v_count)] + [v_count]
        )
        cone = math.tan(math.radians(opts.align_max_deg)) if problem.recovery else None
        gene_of_bit, bit_shift, bit_weight = _bit_tables(gene_bits)
        last_x = x_min + (x_base[-1] + np.arange(sizes[-1])) * x_res
        cone_m = (
            np.floor(last_x * cone / opts.y_resolution + 1e-9).astype(np.int64)
            if cone is not None else np.zeros(sizes[-1], dtype=np.int64)
        )
        return cls(
            start=problem.start, start_speed=problem.start_speed, goal=problem.goal,
            n_mid=n_mid, x_min=x_min, x_base=x_base, x_count=sizes, x_res=x_res,
            y_lo=y_lo, y_count=y_count, y_res=opts.y_resolution,
            v_lo=problem.speed_min, v_count=v_count, v_res=opts.speed_resolution,
            cone_tan=cone, gene_bits=gene_bits, gene_count=gene_count,
            gene_of_bit=gene_of_bit, bit_shift=bit_shift, bit_weight=bit_weight,
            gene_start=np.concatenate([[0], np.cumsum(gene_bits)[:-1]]), cone_m=cone_m,
        )

    # --- sizes --------------------------------------------------------------
    @property
    def n_genes(self) -> int:
        return int(self.gene_bits.shape[0])

    @functools.cached_property
    def n_bits(self) -> int:  # cached: the operators ask for it several times a generation
        return int(self.gene_bits.sum())

    @property
    def n_waypoints(self) -> int:
        return self.n_mid + 2

    @property
    def cone_gene(self) -> int | None:
        """Index of the y gene mapped into the arrival cone (recovery only)."""
        return 3 * (self.n_mid - 1) + 1 if self.cone_tan is not None else None

    def segment_x_range(self) -> tuple[np.ndarray, np.ndarray]:
        """(lo, hi) of x over every segment: segment s joins block s-1 (or the start) to s."""
        top = self.x_of(self.x_count - 1, np.arange(self.n_mid))
        bottom = self.x_of(0, np.arange(self.n_mid))
        hi = np.concatenate([[self.start[0]], top])
        lo = np.concatenate([bottom, [self.goal[0]]])
        return lo, hi

    def prefix_masks(self, cut: np.ndarray) -> np.ndarray:
        """(P, G) for cuts (P,) in 0..n_bits: per gene, the mask of its bits whose index is
        below the cut (the part a single-point crossover there takes from the first
        parent). Read from a table of every cut when it has at most
        `PREFIX_TABLE_ELEMENTS` entries, else computed."""
        table = self._prefix_table
        return table[cut] if table is not None else self._prefix_of(cut)

    @functools.cached_property
    def _prefix_table(self) -> np.ndarray | None:
        if (self.n_bits + 1) * self.n_genes > PREFIX_TABLE_ELEMENTS:
            return None
        return self._prefix_of(np.arange(self.n_bits + 1))

    def _prefix_of(self, cut: np.ndarray) -> np.ndarray:
        width = self.gene_bits
        before = np.clip(cut[:, None] - self.gene_start, 0, width)  # leading bits before it
        full = (np.int64(1) << width) - 1
        return full & ~((np.int64(1) << (width - before)) - 1)

    # --- bits <-> codes -----------------------------------------------------
    def bits_to_codes(self, bits: np.ndarray) -> np.ndarray:
        """(P, n_bits) of 0/1 to (P, n_genes) integer codes (eq. 11's binary sums)."""
        return (bits.astype(np.float64) @ self.bit_weight).astype(np.int64)

    def codes_to_bits(self, codes: np.ndarray) -> np.ndarray:
        return ((codes[:, self.gene_of_bit] >> self.bit_shift) & 1).astype(np.uint8)

    # --- codes <-> levels (decode-and-map) ----------------------------------
    def clip_levels(self, levels: np.ndarray) -> np.ndarray:
        """Clip levels (in place) into each gene's admissible range; the cone gene's
        range depends on the waypoint's x."""
        np.maximum(levels, 0, out=levels)  # np.clip, without its wrapper's overhead
        np.minimum(levels, self.gene_count - 1, out=levels)
        if self.cone_tan is not None:
            g = self.cone_gene
            top = 2 * self.cone_half_levels(levels[:, g - 1])
            np.minimum(levels[:, g], top, out=levels[:, g])
        return levels

    def cone_half_levels(self, last_x_level: np.ndarray) -> np.ndarray:
        """m with |y| <= m y_res inside the arrival cone at the last waypoint's x."""
        return self.cone_m[last_x_level]

    def codes_to_levels(self, codes: np.ndarray) -> np.ndarray:
        levels = (codes * self.gene_count) >> self.gene_bits
        if self.cone_tan is not None:
            g = self.cone_gene
            n = self._cone_levels[levels[:, g - 1]]
            levels[:, g] = (codes[:, g] * n) >> self.gene_bits[g]
        return levels

    def levels_to_codes(self, levels: np.ndarray) -> np.ndarray:
        num = levels.astype(np.int64) << self.gene_bits
        codes = -((-num) // self.gene_count)  # ceil division
        if self.cone_tan is not None:
            g = self.cone_gene
            codes[:, g] = -((-num[:, g]) // self._cone_levels[levels[:, g - 1]])
        return codes

    # --- levels -> coordinates ----------------------------------------------
    def x_of(self, level: np.ndarray, k: int | np.ndarray) -> np.ndarray:
        return self.x_min + (self.x_base[k] + level) * self.x_res

    def y_of(self, level: np.ndarray) -> np.ndarray:
        return self.y_lo + level * self.y_res

    def v_of(self, level: np.ndarray) -> np.ndarray:
        return self.v_lo + level * self.v_res

    @functools.cached_property
    def _cone_levels(self) -> np.ndarray:
        """Levels of the cone gene (2 m + 1) per level of the last waypoint's x."""
        return 2 * self.cone_m + 1

    @functools.cached_property
    def _affine(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Per gene (base, res, lo): its coordinate is (level + base) res + lo, the same
        arithmetic as `x_of`, `y_of` and `v_of` (the cone gene's base is -m, per row)."""
        n = self.n_mid
        base = np.zeros(self.n_genes, dtype=np.int64)
        base[0 : 3 * n : 3] = self.x_base
        res = np.array([self.x_res, self.y_res, self.v_res] * n + [self.v_res])
        lo = np.array([self.x_min, self.y_lo, self.v_lo] * n + [self.v_lo])
        if self.cone_tan is not None:
            lo[self.cone_gene] = 0.0
        return base, res, lo

    def levels_to_paths(self, levels: np.ndarray) -> PathBatch:
        """Assemble full waypoint arrays (start, intermediates, goal) and eq. 11 times.

        x, y and v are (P, N) views of one (3, N, P) block: column-major, so the
        evaluator's per-segment gathers read contiguous memory.
        """
        p, n_mid = levels.shape[0], self.n_mid
        base, res, lo = self._affine
        pos = levels + base
        if self.cone_tan is not None:
            pos[:, self.cone_gene] -= self.cone_half_levels(levels[:, self.cone_gene - 1])
        value = pos * res + lo  # (P, G)
        xyv = np.empty((3, self.n_waypoints, p))
        xyv[:, 1:-1, :] = value[:, : 3 * n_mid].reshape(p, n_mid, 3).transpose(2, 1, 0)
        xyv[:, 0, :] = ((self.start[0],), (self.start[1],), (self.start_speed,))
        xyv[:2, -1, :] = self.goal[:, None]
        xyv[2, -1, :] = value[:, -1]
        return timed_paths(xyv[0].T, xyv[1].T, xyv[2].T)

    def decode(self, bits: np.ndarray) -> PathBatch:
        """Bit strings (P, n_bits) to paths: TransferDecimal, decode-and-map, TimeReset."""
        return self.decode_codes(self.bits_to_codes(bits))

    def decode_codes(self, codes: np.ndarray) -> PathBatch:
        """Per-gene packed bit strings (P, n_genes) to paths."""
        return self.levels_to_paths(self.codes_to_levels(codes))

    def encode(self, levels: np.ndarray) -> np.ndarray:
        """Levels to bit strings (P, n_bits): TransferBinary."""
        return self.codes_to_bits(self.levels_to_codes(levels))

    # --- coordinates -> levels (for preheating and tests) -------------------
    def y_level(self, y: np.ndarray) -> np.ndarray:
        cell = np.maximum(np.rint((y - self.y_lo) / self.y_res), 0)
        return np.minimum(cell, self.y_count - 1).astype(np.int64)

    def v_level_range(self, vlo: np.ndarray, vhi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Levels whose speed lies in [vlo, vhi] (may be empty: lo > hi)."""
        lo = np.ceil((vlo - self.v_lo) / self.v_res - 1e-9).astype(np.int64)
        hi = np.floor((vhi - self.v_lo) / self.v_res + 1e-9).astype(np.int64)
        return np.maximum(lo, 0), np.minimum(hi, self.v_count - 1)


def _bit_tables(gene_bits: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    n_genes, n_bits = gene_bits.shape[0], int(gene_bits.sum())
    gene_of_bit = np.repeat(np.arange(n_genes), gene_bits)
    ends = np.cumsum(gene_bits)
    shift = ends[gene_of_bit] - 1 - np.arange(n_bits)  # most significant bit first
    weight = np.zeros((n_bits, n_genes))
    weight[np.arange(n_bits), gene_of_bit] = 2.0**shift
    return gene_of_bit, shift, weight


_Y_LIMIT = 40_000.0  # m: twice the 20 km bound on coordinates
_GAP_M = 4.0  # a free band in y at least this wide lets the range stand as it is


def _gap_in(c_lo: np.ndarray, c_hi: np.ndarray, lo: float, hi: float) -> bool:
    """True if the intervals [c_lo, c_hi] leave a band of _GAP_M free inside [lo, hi]."""
    order = np.argsort(c_lo)
    edge = lo
    for a, b in zip(c_lo[order], c_hi[order], strict=True):
        if a - edge >= _GAP_M:
            return True
        edge = max(edge, b)
        if edge >= hi:
            return False
    return hi - edge >= _GAP_M


def _y_range(problem: Problem, opts: IGAOptions) -> tuple[float, int]:
    """Search range of y: the paper's +-64 m at least, grown to cover start and obstacles."""
    res = opts.y_resolution
    cap = max(opts.y_half_width, problem.distance)
    f = problem.obstacles
    lows = [-opts.y_half_width, problem.start[1] - opts.y_margin]
    highs = [opts.y_half_width - res, problem.start[1] + opts.y_margin]
    near = np.abs(f.centre[:, 1]) <= cap
    if near.any():
        lows.append(float(np.min(f.centre[near, 1] - f.inflated[near])) - opts.y_margin)
        highs.append(float(np.max(f.centre[near, 1] + f.inflated[near])) + opts.y_margin)
    lo = max(min(lows), -cap - opts.y_margin)
    hi = min(max(highs), cap + opts.y_margin)
    # a wall or island chain across the corridor that reaches past the range: grow the range
    # along the chain (static obstacles between start and goal in x) until it ends (issue 12)
    x_lo = min(float(problem.start[0]), float(problem.goal[0]))
    x_hi = max(float(problem.start[0]), float(problem.goal[0]))
    chain = f.static & (f.centre[:, 0] + f.inflated >= x_lo) & (f.centre[:, 0] - f.inflated <= x_hi)
    if chain.any() and not _gap_in(f.centre[chain, 1] - f.inflated[chain],
                                   f.centre[chain, 1] + f.inflated[chain], lo, hi):
        c_lo = f.centre[chain, 1] - f.inflated[chain]
        c_hi = f.centre[chain, 1] + f.inflated[chain]
        for _ in range(64):
            touch = (c_hi >= lo) & (c_lo <= hi)
            new_lo = min(lo, float(c_lo[touch].min()) - opts.y_margin) if touch.any() else lo
            new_hi = max(hi, float(c_hi[touch].max()) + opts.y_margin) if touch.any() else hi
            new_lo, new_hi = max(new_lo, -_Y_LIMIT), min(new_hi, _Y_LIMIT)
            if (new_lo, new_hi) == (lo, hi):
                break
            lo, hi = new_lo, new_hi
    lo = math.floor(lo / res) * res
    count = math.floor((hi - lo) / res + 1e-9) + 1
    return lo, count
