"""Standard errors of a transient run's counting-period statistics.

The contact-time fraction, the count rate Q and the pressure maxima are time averages (or
extremes) of an autocorrelated process over a finite counting period: another period of the
same length gives other values. Two standard estimators give their spread from the one run:

- **Batch means** for a statistic that is the mean of a per-step series (the contact-time
  fraction: the mean of the per-step contact flag; the mean count rate over the Hertz zone):
  the counting period is cut into ``B`` non-overlapping blocks of consecutive steps, and the
  standard error of the mean is ``s_B / sqrt(B)``, ``s_B`` the standard deviation of the block
  means. It holds when the blocks are longer than the correlation time of the series, so that
  the block means are nearly independent (Flyvbjerg & Petersen, J. Chem. Phys. 91 (1989) 461,
  "blocking"; Geyer, Stat. Sci. 7 (1992) 473, sec. 3.2). The rule here: :data:`BLOCKS`
  blocks (fewer, one step each, when the period is shorter); when the lag-1 autocorrelation
  of the block means exceeds ``-1/B + 2/sqrt(B)`` (its mean for independent means plus twice
  its standard deviation, :func:`lag1_limit`) neighbouring blocks are merged in pairs, down
  to :data:`MIN_BLOCKS`; if they are still correlated there the estimate is flagged
  (:attr:`StandardError.correlated`): it then understates the spread. Blocks of about 4-5
  correlation times, as the default example's, still understate it by about 10 % (a Markov
  chain of 2.8 steps in blocks of 12: the variance by 23 %, tests/test_ehl_uncertainty.py).
- **Block bootstrap** for the largest count rate, a maximum over nodes of means, which no
  formula in the block means gives: the blocks' count maps are resampled with replacement
  (:data:`BOOTSTRAP_RESAMPLES` resamples, a fixed seed), and the standard deviation of the
  resampled maxima is the standard error (the non-overlapping block bootstrap, Carlstein,
  Ann. Stat. 14 (1986) 1171; Lahiri, Resampling Methods for Dependent Data (2003) sec. 2.5).
  The mean of the resampled maxima less the observed one estimates the maximum's bias: the
  largest rate of a short period lies above the long-run one.

Measured on the default example (holmes-rough-CC with 3200 and 1600 counting steps, cut into
24 windows of 200 steps; docs/ehl-transient.md, "Standard errors of the statistics"): the
real spread between the windows of the contact-time fraction 0.056, the batch-means
estimate on one window 0.055 (root mean square over the windows); of the Hertz-zone mean
rate 6.9 against 8.6 per ms; of the largest rate 56 against 88 per ms (the bootstrap
overstates it by half), its bias +108 per ms estimated against +76 measured.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..formatting import format_number

__all__ = ["BLOCKS", "BOOTSTRAP_NODES", "BOOTSTRAP_RESAMPLES", "DEFAULT_STEPS", "MIN_BLOCKS",
           "RELATIVE_ERROR_LIMIT", "StandardError", "batch_means", "block_bootstrap_max",
           "block_edges", "counting_period_warning", "lag1_correlation", "lag1_limit",
           "steps_for_error"]

#: Blocks the counting period is cut into (and whose count maps a run keeps): twice
#: :data:`MIN_BLOCKS`, so that one merging of neighbours is left when they are correlated.
BLOCKS = 16
#: Fewest blocks a standard error rests on (the standard deviation of 8 block means is known
#: to about 27 %, ``1/sqrt(2 (B - 1))``).
MIN_BLOCKS = 8
#: Resamples of the block bootstrap (its standard error then known to about 4 %).
BOOTSTRAP_RESAMPLES = 400
#: Nodes with the most contacts that the bootstrap's maximum is taken over (a node further
#: down cannot overtake them in a resample of 16 blocks but by a freak).
BOOTSTRAP_NODES = 512
#: Counting steps the warning of a period too short for any estimate advises: the default
#: example's (16 blocks of 12.5 steps, 5 times the integrated autocorrelation time, 2.4 steps,
#: of its per-step contact flag).
DEFAULT_STEPS = 200
#: Standard error, as a share of the value, above which a statistic warns that the counting
#: period is too short: two standard errors, about the 95 % interval, then span more than a
#: fifth of the value either way. The default example (200 steps) is just above it for the
#: contact-time fraction (11 %; 7 % is typical of 24 other 200-step periods of the same case,
#: one of them above 10 %) and well above it for the largest count rate (27 %) and the
#: Hertz-zone mean rate (32 %).
RELATIVE_ERROR_LIMIT = 0.10


@dataclass(frozen=True)
class StandardError:
    """A statistic with its standard error.

    Attributes
    ----------
    value : float
        The statistic over the counting period.
    standard_error : float
        Its standard error, in its own unit; NaN when fewer than :data:`MIN_BLOCKS` blocks
        exist.
    blocks : int
        Blocks it rests on (after merging correlated neighbours).
    block_steps : float
        Mean steps per block.
    lag1 : float
        Lag-1 autocorrelation of the block means it rests on (for the largest count rate:
        of the block rates at its node).
    correlated : bool
        Whether that correlation stayed above :func:`lag1_limit` at :data:`MIN_BLOCKS`
        blocks: the blocks are not longer than the correlation time and the standard error
        understates the spread.
    method : str
        ``"batch means"`` or ``"block bootstrap"``.
    bias : float
        The block bootstrap's estimate of the statistic's bias (NaN for batch means).
    """

    value: float
    standard_error: float
    blocks: int
    block_steps: float
    lag1: float
    correlated: bool
    method: str
    bias: float = float("nan")

    @property
    def relative_error(self) -> float:
        """Standard error over ``|value|`` (0 for a zero statistic known exactly, NaN when
        there is no estimate)."""
        if not np.isfinite(self.standard_error):
            return float("nan")
        if self.value == 0.0:
            return 0.0 if self.standard_error == 0.0 else float("inf")
        return self.standard_error / abs(self.value)


def block_edges(steps: int, blocks: int = BLOCKS) -> np.ndarray:
    """Edges (step indices, 0-based) of ``min(blocks, steps)`` consecutive blocks of
    ``steps`` steps whose lengths differ by at most one: ``floor(i steps / B)``."""
    count = max(1, min(blocks, steps))
    return (np.arange(count + 1) * steps) // count


def lag1_correlation(values) -> float:
    """Lag-1 autocorrelation ``sum c_i c_{i+1} / sum c_i^2`` of a sequence about its mean (0
    for a constant one)."""
    c = np.asarray(values, dtype=float)
    c = c - c.mean()
    total = float(np.sum(c * c))
    return float(np.sum(c[1:] * c[:-1]) / total) if total > 0.0 else 0.0


def lag1_limit(blocks: int) -> float:
    """Lag-1 autocorrelation above which ``blocks`` block means count as correlated: its mean
    for independent means, ``-1/B``, plus twice its standard deviation, ``1/sqrt(B)``
    (Bartlett's approximation): 0.44 for 16 blocks, 0.58 for 8."""
    return -1.0 / blocks + 2.0 / math.sqrt(blocks)


def _pair_sums(values):
    """Neighbouring blocks (rows) summed in pairs; an odd last block stays alone."""
    n = values.shape[0] // 2 * 2
    return np.concatenate([values[:n:2] + values[1:n:2], values[n:]])


def _merged(means, sizes):
    """Neighbouring blocks merged in pairs (an odd last block stays alone)."""
    merged_sizes = _pair_sums(sizes)
    return _pair_sums(means * sizes) / merged_sizes, merged_sizes


def _block_level(means, sizes, min_blocks):
    """The block means and sizes the estimate rests on: merged in pairs while their lag-1
    autocorrelation exceeds :func:`lag1_limit` and ``B/2 >= min_blocks``; and whether they
    are still correlated."""
    while True:
        r1 = lag1_correlation(means)
        correlated = r1 > lag1_limit(means.size)
        if not correlated or means.size // 2 < min_blocks:
            return means, sizes, r1, correlated
        means, sizes = _merged(means, sizes)


def batch_means(series, *, blocks: int = BLOCKS, min_blocks: int = MIN_BLOCKS) -> StandardError:
    """Mean of a per-step series and its batch-means standard error (module docstring).

    Parameters
    ----------
    series : array_like
        One value per counting step (e.g. 1 where the step had contact, 0 where not).
    blocks : int
        Blocks to start from (:func:`block_edges`).
    min_blocks : int
        Fewest blocks merging may leave, and fewest an estimate needs.

    Returns
    -------
    StandardError
        Standard error NaN when the series has fewer than ``min_blocks`` steps.
    """
    x = np.asarray(series, dtype=float)
    if x.size == 0:
        return StandardError(float("nan"), float("nan"), 0, 0.0, float("nan"), False,
                             "batch means")
    edges = block_edges(x.size, blocks)
    sizes = np.diff(edges).astype(float)
    means = np.add.reduceat(x, edges[:-1]) / sizes
    value = float(x.mean())
    if means.size < min_blocks:
        return StandardError(value, float("nan"), int(means.size), float(sizes.mean()),
                             float("nan"), False, "batch means")
    means, sizes, r1, correlated = _block_level(means, sizes, min_blocks)
    se = float(np.std(means, ddof=1) / math.sqrt(means.size))
    return StandardError(value, se, int(means.size), float(sizes.mean()), r1, correlated,
                         "batch means")


def block_bootstrap_max(block_counts, block_steps, *, scale: float = 1.0,
                        min_blocks: int = MIN_BLOCKS, resamples: int = BOOTSTRAP_RESAMPLES,
                        seed: int = 0) -> StandardError:
    """Largest per-node rate ``scale * count / steps`` over the counting period and its block
    bootstrap standard error (module docstring).

    Parameters
    ----------
    block_counts : array_like of int, shape (B, ...)
        Per block, the count map (steps with contact at each node).
    block_steps : array_like of int, shape (B,)
        Steps per block.
    scale : float
        Factor from a count per step to the rate reported (``1 / (dt / 1 ms)`` for Q per ms).
    min_blocks : int
        Fewest blocks an estimate needs; blocks whose rates at the node of the maximum have a
        lag-1 autocorrelation above :func:`lag1_limit` are merged in pairs down to it.
    resamples : int
        Bootstrap resamples.
    seed : int
        Seed of the resampling (the same data give the same standard error).

    Returns
    -------
    StandardError
        With the bootstrap's bias estimate; standard error NaN below ``min_blocks`` blocks.
    """
    counts = np.asarray(block_counts, dtype=float)
    sizes = np.asarray(block_steps, dtype=float)
    counts = counts.reshape(counts.shape[0], -1)
    steps = sizes.sum()
    if counts.shape[0] == 0 or steps == 0:
        return StandardError(float("nan"), float("nan"), 0, 0.0, float("nan"), False,
                             "block bootstrap")
    total = counts.sum(axis=0)
    top = int(np.argmax(total))
    value = float(scale * total[top] / steps)
    if counts.shape[0] < min_blocks or total[top] == 0:
        se = 0.0 if total[top] == 0 and counts.shape[0] >= min_blocks else float("nan")
        return StandardError(value, se, counts.shape[0], float(sizes.mean()), float("nan"),
                             False, "block bootstrap")
    nodes = np.argsort(total)[::-1][:BOOTSTRAP_NODES]
    counts = counts[:, nodes]
    means, _, r1, correlated = _block_level(counts[:, 0] / sizes, sizes, min_blocks)
    while counts.shape[0] > means.size:  # the maps merged as the series at the top node was
        counts, sizes = _pair_sums(counts), _pair_sums(sizes)
    rng = np.random.default_rng(seed)
    picks = rng.integers(0, counts.shape[0], size=(resamples, counts.shape[0]))
    weights = np.zeros((resamples, counts.shape[0]))
    np.add.at(weights, (np.arange(resamples)[:, None], picks), 1.0)
    maxima = scale * (weights @ counts).max(axis=1) / (weights @ sizes)
    return StandardError(value, float(np.std(maxima, ddof=1)), int(counts.shape[0]),
                         float(sizes.mean()), r1, correlated, "block bootstrap",
                         bias=float(maxima.mean() - value))


def steps_for_error(relative_error: float, steps: int,
                    limit: float = RELATIVE_ERROR_LIMIT) -> int:
    """Counting steps that bring a relative standard error of ``relative_error`` over
    ``steps`` steps to ``limit``: the error falls as ``1/sqrt(steps)``, so
    ``steps (relative_error / limit)^2``, rounded up to two significant digits."""
    need = steps * (relative_error / limit) ** 2
    digits = 10 ** max(0, int(math.floor(math.log10(need))) - 1)
    return int(math.ceil(need / digits) * digits)


def counting_period_warning(estimates: dict, counting_steps: int,
                            limit: float = RELATIVE_ERROR_LIMIT) -> list[str]:
    """One line when the counting period is too short for a statistic: fewer than
    :data:`MIN_BLOCKS` counting steps (no estimate), a standard error above ``limit`` times
    the value, or block means still correlated at :data:`MIN_BLOCKS` blocks; none when no
    contact was counted (every statistic zero).

    Parameters
    ----------
    estimates : dict
        Words naming the statistic (``"the contact-time fraction"``) -> (:class:`StandardError`,
        its unit as printed, ``""`` or ``"per ms"``; a fraction is printed in percent).
    counting_steps : int
        Steps the estimates rest on.
    limit : float
        The largest standard error, as a share of the value, that does not warn.

    Returns
    -------
    list of str
        At most one line, naming ``time.counting_steps`` and the steps that would do.
    """
    if not estimates or not any(e.value > 0 for e, _ in estimates.values()):
        return []  # no contact counted: nothing to be uncertain about
    if all(not np.isfinite(e.standard_error) and e.blocks < MIN_BLOCKS
           for e, _ in estimates.values()):
        return [f"time.counting_steps: {counting_steps} counting steps are too few to tell "
                "how far the statistics would move over another period (their standard error "
                f"needs at least {MIN_BLOCKS} blocks of steps (limit), each longer than the "
                "time contacts stay correlated: the default example's 200 steps make 16 "
                "blocks of 12 steps, 5 times its contact flag's correlation time); count at "
                f"least {DEFAULT_STEPS} steps"]
    parts, need = [], 0
    for words, (e, unit) in estimates.items():
        rel = e.relative_error
        if not np.isfinite(rel) and not e.correlated:
            continue
        if rel > limit or e.correlated:
            percent = unit == "%"
            scale = 100.0 if percent else 1.0
            shown = (f"{format_number(scale * e.value, 3)} ± "
                     f"{format_number(scale * e.standard_error, 2)} {unit}").rstrip()
            text = f"{words} is {shown} ({e.method}"
            if np.isfinite(rel) and math.isfinite(rel):
                text += f", {rel:.0%} of the value"
            if e.correlated:
                text += (f"; its {e.blocks} block means of {e.block_steps:.3g} steps are still "
                         f"correlated, lag-1 {e.lag1:.2f}, so the error is understated")
            if np.isfinite(e.bias) and e.bias > e.standard_error:
                text += (f"; a short period's maximum also lies above the long-run one, here "
                         f"by about {format_number(e.bias, 2)} {unit}".rstrip())
            parts.append(text + ")")
            wanted = 2 * counting_steps if e.correlated else 0
            if math.isfinite(rel) and rel > limit:
                wanted = max(wanted, steps_for_error(rel, counting_steps, limit))
            need = max(need, wanted)
    if not parts:
        return []
    return [f"time.counting_steps: over its {counting_steps} counting steps "
            + "; ".join(parts) + f" (limit: a standard error of {limit:.0%} of the value): "
            f"these time averages have not settled; count at least {need} steps "
            "(time.counting_steps; the error falls as 1/sqrt(steps))"]
