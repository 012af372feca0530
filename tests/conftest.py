"""Shared test fixtures."""

import matplotlib
import pytest

matplotlib.use("Agg")


@pytest.fixture(autouse=True)
def _close_figures():
    """Close the figures a test drew, so that a file of plotting tests does not hold dozens."""
    yield
    import matplotlib.pyplot as plt

    plt.close("all")
