"""Standard errors of the counting-period statistics (asperity.ehl.uncertainty) against
processes whose answer is known in closed form (docs/references.md#batch-means), the
warning of a counting period too short, and the accumulator's checkpoint round trip."""

import numpy as np
import pytest

from asperity.ehl.statistics import ContactStatistics
from asperity.ehl.uncertainty import (
    RELATIVE_ERROR_LIMIT,
    StandardError,
    batch_means,
    block_bootstrap_max,
    block_edges,
    counting_period_warning,
    lag1_limit,
    steps_for_error,
)


def variance_of_mean(n, variance, rho):
    """Exact variance of the mean of ``n`` consecutive values of a stationary series whose
    autocorrelation at lag k is ``rho^k``: ``variance/n [1 + 2 sum_k (1 - k/n) rho^k]``."""
    k = np.arange(1, n)
    return variance / n * (1.0 + 2.0 * np.sum((1.0 - k / n) * rho**k))


def markov_chains(alpha, beta, steps, count, seed):
    """``count`` stationary two-state Markov chains, P(0 -> 1) = alpha, P(1 -> 0) = beta:
    P(1) = alpha / (alpha + beta), autocorrelation (1 - alpha - beta)^k."""
    rng = np.random.default_rng(seed)
    x = np.empty((count, steps), dtype=bool)
    x[:, 0] = rng.random(count) < alpha / (alpha + beta)
    u = rng.random((count, steps))
    for i in range(1, steps):
        x[:, i] = np.where(x[:, i - 1], u[:, i] >= beta, u[:, i] < alpha)
    return x


ALPHA, BETA = 0.2, 0.1  # P(1) = 2/3, rho = 0.7: tau_int = 0.5 + rho/(1 - rho) = 2.83 steps
P1, RHO = ALPHA / (ALPHA + BETA), 1.0 - ALPHA - BETA


def test_batch_means_of_a_markov_chain_matches_its_exact_variance():
    """A binary Markov chain with the default example's correlation time (2.8 steps; its
    contact flag 2.4) over 192 steps, 2000 chains. With 16 blocks of 12 steps held fixed, the
    mean squared standard error is the exact expectation ``(Var(block mean) - Var(mean)) /
    (B - 1)`` (measured: to 0.9 %; Monte Carlo sd 0.8 %), which is 0.771 of the variance of
    the mean: blocks of 4 correlation times understate it, the known bias of batch means.
    With the rule (merging correlated blocks) the root mean square standard error is 0.88 of
    the exact standard deviation (0.0804), and the sample means scatter by it."""
    steps, blocks, variance = 192, 16, P1 * (1.0 - P1)
    chains = markov_chains(ALPHA, BETA, steps, 2000, seed=1)
    exact = variance_of_mean(steps, variance, RHO)
    expected = (variance_of_mean(steps // blocks, variance, RHO) - exact) / (blocks - 1)
    fixed = np.array([batch_means(c, min_blocks=blocks).standard_error for c in chains])
    assert np.mean(fixed**2) == pytest.approx(expected, rel=0.04)
    assert expected / exact == pytest.approx(0.771, abs=0.001)
    ruled = [batch_means(c) for c in chains]
    se = np.array([e.standard_error for e in ruled])
    assert np.sqrt(np.mean(se**2) / exact) == pytest.approx(np.sqrt(expected / exact), abs=0.03)
    assert np.std(chains.mean(axis=1)) == pytest.approx(np.sqrt(exact), rel=0.05)
    assert ruled[0].value == pytest.approx(chains[0].mean())
    assert np.mean([e.correlated for e in ruled]) < 0.01  # measured: 3 of 2000 chains


def test_batch_means_of_independent_steps_is_the_binomial_error():
    """Independent steps (alpha + beta = 1: rho = 0): the standard error is
    ``sqrt(p (1 - p) / n)`` with no bias, to the 18 % scatter of 16 blocks, 3 % on 1000
    chains."""
    chains = markov_chains(0.4, 0.6, 200, 1000, seed=2)
    se = np.array([batch_means(c).standard_error for c in chains])
    assert np.sqrt(np.mean(se**2)) == pytest.approx(np.sqrt(0.4 * 0.6 / 200), rel=0.03)


def test_correlated_blocks_are_merged_then_flagged():
    """A series that changes once (100 steps without contact, 100 with): block means 0 then 1,
    lag-1 0.8125 over 16 blocks (limit 0.4375), merged to 8 and still 0.625 (limit
    -1/8 + 2/sqrt(8) = 0.582): flagged, and the warning asks for twice the steps at least."""
    assert lag1_limit(16) == pytest.approx(0.4375)
    assert lag1_limit(8) == pytest.approx(0.5821, abs=1e-4)
    e = batch_means(np.repeat([0.0, 1.0], 100))
    assert e.blocks == 8 and e.correlated and e.lag1 == pytest.approx(0.625)
    lines = counting_period_warning({"the contact-time fraction": (e, "%")}, 200)
    assert len(lines) == 1 and lines[0].startswith("time.counting_steps:")
    assert "correlated" in lines[0] and "at least" in lines[0]
    need = int(lines[0].split("count at least ")[1].split()[0])
    assert need >= 400


def test_block_bootstrap_of_one_dominant_node_is_its_binomial_error():
    """One node in contact at each of 192 independent steps with p = 0.3, the others at
    p = 0.02: the largest rate is that node's, and the bootstrap of 16 blocks gives
    ``sqrt(p (1 - p) / n)`` times ``sqrt(15/16)`` (the bootstrap's variance of a mean of B
    blocks, (B - 1)/B of the unbiased one), within 5 % over 100 runs; no bias to speak of."""
    rng = np.random.default_rng(3)
    steps, edges = 192, block_edges(192)
    ratios, biases = [], []
    for _ in range(100):
        rates = np.full(50, 0.02)
        rates[7] = 0.3
        contact = rng.random((steps, 50)) < rates
        counts = np.add.reduceat(contact, edges[:-1], axis=0)
        e = block_bootstrap_max(counts, np.diff(edges), scale=2.0)
        assert e.value == pytest.approx(2.0 * contact[:, 7].mean())
        ratios.append(e.standard_error / (2.0 * np.sqrt(0.3 * 0.7 / steps)))
        biases.append(e.bias / e.standard_error)
    assert np.sqrt(np.mean(np.square(ratios))) == pytest.approx(np.sqrt(15 / 16), rel=0.05)
    assert abs(np.mean(biases)) < 0.2
    # the same data give the same error (fixed seed), as a resumed run must
    again = block_bootstrap_max(counts, np.diff(edges), scale=2.0)
    assert again == e


def _estimate(value, error, blocks=16):
    return StandardError(value, error, blocks, 12.5, 0.0, False, "batch means")


def test_warning_only_above_the_limit_naming_the_steps_that_would_do():
    fraction = _estimate(0.78, 0.05)  # 6.4 %: under 10 %
    assert counting_period_warning({"the contact-time fraction": (fraction, "%")}, 200) == []
    rate = _estimate(300.0, 60.0)  # 20 %: (0.2 / 0.1)^2 = 4 times the steps
    lines = counting_period_warning({"the contact-time fraction": (fraction, "%"),
                                     "the largest contact count rate": (rate, "per ms")}, 200)
    assert len(lines) == 1
    line = lines[0]
    assert line.startswith("time.counting_steps:") and "count at least 800 steps" in line
    assert "the largest contact count rate is 300 ± 60 per ms" in line
    assert "contact-time fraction" not in line  # under the limit: not named
    assert f"{RELATIVE_ERROR_LIMIT:.0%}" in line
    # a statistic that is zero with no spread (no contact in any block) says nothing
    assert counting_period_warning({"x": (_estimate(0.0, 0.0), "")}, 200) == []
    # too few steps for any estimate
    few = batch_means(np.ones(5))
    assert not np.isfinite(few.standard_error) and few.blocks == 5
    lines = counting_period_warning({"the contact-time fraction": (few, "%")}, 5)
    assert len(lines) == 1 and "too few" in lines[0] and "time.counting_steps" in lines[0]
    # ... unless nothing was counted at all (a smooth contact's short run)
    assert counting_period_warning({"x": (batch_means(np.zeros(5)), "%")}, 5) == []


def test_steps_for_error_falls_as_one_over_the_root_of_the_steps():
    assert steps_for_error(0.2, 200) == 800
    assert steps_for_error(0.11, 200) == 250  # 242 rounded up to two digits
    assert steps_for_error(0.32, 200) == 2100  # 2048


def test_accumulator_round_trip_and_an_old_checkpoint():
    """The per-step series and block maps survive arrays()/restore(); a checkpoint written
    before they were kept restores with the steps it had counted unknown (-1)."""
    rng = np.random.default_rng(4)
    region = np.zeros((6, 5), dtype=bool)
    region[2:4, 1:4] = True
    films = rng.random((40, 6, 5)) * 1e-7
    contacts = rng.random((40, 6, 5)) < 0.1

    def accumulate(stats, steps):
        for k in steps:
            stats.add(films[k], contacts[k])

    whole = ContactStatistics((6, 5), np.linspace(0, 1e-7, 6), region, 40)
    accumulate(whole, range(40))
    first = ContactStatistics((6, 5), np.linspace(0, 1e-7, 6), region, 40)
    accumulate(first, range(17))
    resumed = ContactStatistics((6, 5), np.linspace(0, 1e-7, 6), region, 40)
    resumed.restore({k: np.array(v) for k, v in first.arrays().items()})
    accumulate(resumed, range(17, 40))
    for name, value in whole.arrays().items():
        np.testing.assert_array_equal(resumed.arrays()[name], value, err_msg=name)
    np.testing.assert_array_equal(whole.contact_nodes, contacts.sum(axis=(1, 2)))
    np.testing.assert_array_equal(whole.region_contact_nodes, contacts[:, region].sum(axis=1))
    np.testing.assert_array_equal(whole.block_counts.sum(axis=0), whole.count)
    np.testing.assert_array_equal(whole.block_steps, np.diff(block_edges(40)))
    old = {k: v for k, v in first.arrays().items()
           if k not in ("stat_contact_nodes", "stat_region_contact_nodes", "stat_block_counts",
                        "stat_block_steps")}
    restored = ContactStatistics((6, 5), np.linspace(0, 1e-7, 6), region, 40)
    restored.restore(old)
    accumulate(restored, range(17, 40))
    assert np.all(restored.contact_nodes[:17] == -1)
    np.testing.assert_array_equal(restored.contact_nodes[17:], whole.contact_nodes[17:])
    np.testing.assert_array_equal(restored.block_steps, whole.block_steps)
    np.testing.assert_array_equal(restored.count, whole.count)
