"""Surface figures: the traces drawn are the data, in mm and um."""

import numpy as np
import pytest

from asperity.errors import InputError
from asperity.plotting.surfaces import plot_profiles, plot_surface, plot_turning_roughness
from asperity.surfaces import builtin_profile, roughness_along, turned_profile_dynamic


def test_profiles_are_stacked_in_um():
    profiles = {name: builtin_profile(name, length=0.2e-3, spacing=1e-6) for name in "ABC"}
    fig = plot_profiles(profiles, offset=2e-6)
    lines = fig.axes[0].get_lines()
    assert len(lines) == 3
    np.testing.assert_allclose(lines[1].get_xdata(), profiles["B"].x * 1e3)
    np.testing.assert_allclose(lines[1].get_ydata(), (profiles["B"].z - 2e-6) * 1e6)
    with pytest.raises(InputError, match="surface"):
        plot_surface(np.zeros(3))


def test_turning_roughness_figure():
    res = turned_profile_dynamic(0.127e-3, 0.794e-3, 0.305e-3, 61 / 60, 0.05, 5e-3, 1e-6, 28.0,
                                 mass=250.0)
    fig = plot_turning_roughness([res], 5 * 0.127e-3, labels=["28 Hz"])
    centres, rt = roughness_along(res.profile, 5 * 0.127e-3)
    line = fig.axes[0].get_lines()[0]
    np.testing.assert_allclose(line.get_ydata(), rt * 1e6)
    np.testing.assert_allclose(line.get_xdata(), centres * 1e3)
