"""Anderson acceleration of a fixed-point iteration: exact on small linear maps, and faster."""

import numpy as np

from asperity.ehl.anderson import AndersonMixer


def _linear_map(n, radius, seed=0):
    """g(x) = M x + b with M symmetric, eigenvalues in [0, radius]; returns (g, fixed point)."""
    rng = np.random.default_rng(seed)
    q, _ = np.linalg.qr(rng.normal(size=(n, n)))
    m = q @ np.diag(np.linspace(0.0, radius, n)) @ q.T
    b = rng.normal(size=n)
    return (lambda x: m @ x + b), np.linalg.solve(np.eye(n) - m, b)


def _iterate(g, x, steps, mixer=None):
    for _ in range(steps):
        x = g(x) if mixer is None else mixer.mix(x, g(x))
    return x


def test_first_mix_is_the_plain_step():
    g, _ = _linear_map(4, 0.9)
    x = np.ones(4)
    assert np.array_equal(AndersonMixer(3).mix(x, g(x)), g(x))


def test_exact_on_a_linear_map_of_dimension_memory():
    """Type II Anderson on a linear map is GMRES-like: memory m >= n gives the fixed point
    after n + 1 mixes (Walker & Ni 2011, Theorem 2.2)."""
    g, x_star = _linear_map(3, 0.99)
    x = _iterate(g, np.zeros(3), 4, AndersonMixer(3))
    assert np.allclose(x, x_star, rtol=0, atol=1e-9)


def test_slow_contraction_converges_much_faster():
    """Eigenvalues spread over [0, 0.95]: after 20 steps the plain iteration keeps 15 % of the
    error, Anderson(3) 0.5 %."""
    g, x_star = _linear_map(40, 0.95)
    x0 = np.zeros(40)
    e0 = np.linalg.norm(x0 - x_star)
    plain = np.linalg.norm(_iterate(g, x0, 20) - x_star) / e0
    mixed = np.linalg.norm(_iterate(g, x0, 20, AndersonMixer(3)) - x_star) / e0
    assert plain > 0.1
    assert mixed < 0.01


def test_reset_forgets_the_history():
    g, _ = _linear_map(4, 0.9)
    mixer = AndersonMixer(2)
    x = np.zeros(4)
    x = mixer.mix(x, g(x))
    mixer.reset()
    assert np.array_equal(mixer.mix(x, g(x)), g(x))


def _reference_mix(xs, gs, memory):
    """Walker & Ni Eq. 2.2 from the last memory + 1 pairs, by a direct least-squares solve."""
    xs, gs = np.array(xs[-memory - 1:]), np.array(gs[-memory - 1:])
    f = gs - xs
    if len(f) < 2:
        return gs[-1]
    gamma = np.linalg.lstsq(np.diff(f, axis=0).T, f[-1], rcond=None)[0]
    return gs[-1] - np.diff(gs, axis=0).T @ gamma


def test_incremental_gram_matrix_equals_the_direct_least_squares():
    """Past the memory (oldest pair dropped) every proposal equals the direct solve."""
    g, _ = _linear_map(12, 0.9, seed=3)
    mixer = AndersonMixer(3)
    xs, gs, x = [], [], np.zeros(12)
    for _ in range(8):
        xs.append(x)
        gs.append(np.tanh(g(x)))
        x = mixer.mix(xs[-1], gs[-1])
        np.testing.assert_allclose(x, _reference_mix(xs, gs, 3), rtol=1e-9, atol=1e-12)


def test_a_dot_product_of_another_array_library_gives_the_same_iterates():
    """The mixer with a caller's dot product (as a GPU's vectors need) proposes the same
    iterates as with its compiled one: a linear contraction, 6 mixes."""
    rng = np.random.default_rng(3)
    a = 0.5 * rng.standard_normal((8, 8)) / np.sqrt(8)
    b = rng.standard_normal(8)

    def g(x):
        return a @ x + b

    calls = []

    def dot(u, v):
        calls.append(1)
        return float(np.dot(u, v))

    default = _iterate(g, np.zeros(8), 6, AndersonMixer(3))
    given = _iterate(g, np.zeros(8), 6, AndersonMixer(3, dot=dot))
    np.testing.assert_allclose(given, default, rtol=1e-12, atol=1e-14)
    # mixes 2..6 each add a Gram row (1, 2, 3, 3, 3 products) and a right-hand side (same)
    assert len(calls) == 2 * (1 + 2 + 3 + 3 + 3)
