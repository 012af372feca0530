"""A generated rough surface through a point contact is an areal topography, on a mesh that
resolves it.

A user's ball-on-disc case (3/4 in steel ball, 30 N, 0.3 m/s, slide/roll 0.5, a disc with a
gaussian finish of Sq 0.05 um and correlation length 15 um) ran with the disc's roughness as a
profile extruded across y, the same heights on every row (transverse ridges), and a
``correlation_length_y`` was taken and ignored; its default mesh had cells 12.4 um across y,
0.8 of a correlation length. Now a gaussian (or self-affine) surface of a point contact is a
topography on the mesh's rows, the default mesh gives a gaussian one
``ROUGHNESS_CELLS`` = 4 cells per correlation length across y, and a coarser mesh of the
user's own is reported (docs/references.md, "Roughness on the mesh").

The reference is the definition of the correlation length: the lag at which the surface's
autocorrelation falls to 0.2.
"""

import numpy as np
import pytest
import tomllib

from asperity import diagnostics
from asperity.cases import load_case
from asperity.ehl.transient import ROUGHNESS_CELLS
from asperity.errors import InputError
from asperity.runners import run_case
from asperity.surfaces import Profile, Topography

DISC = """
analysis = "ehl-transient"
title = "Ball on a rough disc"
[body1]
youngs_modulus = "207 GPa"
poisson_ratio = 0.29
[body2]
youngs_modulus = "207 GPa"
poisson_ratio = 0.29
[contact]
type = "point"
rx = "9.525 mm"
ry = "9.525 mm"
load = "30 N"
[speeds]
u = "0.3 m/s"
xi = 0.5
[lubricant]
eta0 = "0.03 Pa s"
alpha = "18 1/GPa"
tau0 = "5 MPa"
[surface2]
kind = "gaussian"
rms = "0.05 um"
correlation_length = "15 um"
"""


def _case(**surface2):
    data = tomllib.loads(DISC)
    data["surface2"].update(surface2)
    return load_case(data)


def _setup(case, grid=None):
    """The mesh and the two surfaces of a run, as the runner makes them."""
    problem = case.problem()
    if grid is None:
        nx, ny, domain = case.mesh(problem)
    else:
        nx, ny = grid
        domain = problem.default_domain()
    x, y = problem.grid(nx, ny, domain)
    dt = 0.5 * (x[1] - x[0]) / max(problem.u1, problem.u2)
    warmup, counting = case.steps(problem, x, dt)
    return x, y, case.surfaces(problem, x, y, warmup, warmup + counting, dt)


def _autocorrelation(z, lag: int, axis: int) -> float:
    """Normalised autocorrelation of the heights at ``lag`` samples along ``axis``
    (periodic)."""
    z = z - z.mean()
    return float(np.mean(z * np.roll(z, -lag, axis=axis)) / np.mean(z * z))


def test_the_default_mesh_resolves_a_gaussian_correlation_length():
    x, y, _ = _setup(_case())
    dx, dy = x[1] - x[0], y[1] - y[0]
    assert dy <= 15e-6 / ROUGHNESS_CELLS * (1 + 1e-9)  # was 12.4 um (41 rows)
    assert dx <= 15e-6 / ROUGHNESS_CELLS
    assert dy >= 3 * dx * (1 - 1e-9)                   # the cell shape the relaxation needs


@pytest.mark.parametrize("ell_y", [None, 60e-6])
def test_a_gaussian_surface_of_a_point_contact_is_a_topography_on_the_mesh_rows(ell_y):
    keys = {} if ell_y is None else {"correlation_length_y": "60 um"}
    x, y, (smooth, disc) = _setup(_case(**keys))
    assert smooth is None
    assert isinstance(disc, Topography)
    np.testing.assert_allclose(disc.y, y)
    z = np.asarray(disc.z)
    hx = disc.x[1] - disc.x[0]
    dy = y[1] - y[0]
    assert np.sqrt(np.mean((z - z.mean()) ** 2)) == pytest.approx(0.05e-6, rel=0.1)
    # along x: the autocorrelation falls to 0.2 at the correlation length
    assert _autocorrelation(z, round(15e-6 / hx), axis=0) == pytest.approx(0.2, abs=0.05)
    # across y: at the correlation length across (rows are dy apart; interpolated between the
    # two rows either side of it)
    ell = 15e-6 if ell_y is None else ell_y
    lo = int(ell // dy)
    w = ell / dy - lo
    acf = (1 - w) * _autocorrelation(z, lo, axis=1) + w * _autocorrelation(z, lo + 1, axis=1)
    assert acf == pytest.approx(0.2, abs=0.08)
    if ell_y is not None:  # elongated across: still well correlated at the x length
        assert _autocorrelation(z, round(15e-6 / dy), axis=1) > 0.6


def test_a_line_contact_keeps_a_gaussian_profile():
    data = tomllib.loads(DISC)
    data["contact"] = {"type": "line", "radius": "19.1 mm", "load_per_length": "527 kN/m"}
    data["grid"] = {"nx": 161, "x_min": -2.5, "x_max": 1.5}
    _, _, (_, disc) = _setup(load_case(data))
    assert isinstance(disc, Profile)


def test_lowpass_filters_each_row_of_a_topography_along_x():
    """``lowpass`` (wavelengths shorter than that many mesh spacings) acts on every row of a
    topography along x as on a profile: the ratio of each row's Fourier amplitudes after and
    before is the ISO 16610-21 Gaussian transmission ``exp(-pi (alpha lc / lambda)^2)``,
    ``alpha = sqrt(ln 2 / pi)`` (50 % at the cut-off), and nothing is smoothed across."""
    x, y, (_, rough) = _setup(_case(), grid=(257, 81))
    _, _, (_, smooth) = _setup(_case(lowpass=8.0), grid=(257, 81))
    z, zs = np.asarray(rough.z), np.asarray(smooth.z)
    assert isinstance(smooth, Topography) and zs.shape == z.shape
    cutoff = 8.0 * (x[1] - x[0])
    period = z.shape[0] * (rough.x[1] - rough.x[0])
    before, after = np.fft.rfft(z, axis=0), np.fft.rfft(zs, axis=0)
    alpha = np.sqrt(np.log(2.0) / np.pi)
    for wavelength in (4.0 * cutoff, cutoff, 0.5 * cutoff):
        k = round(period / wavelength)
        expected = np.exp(-np.pi * (alpha * cutoff * k / period) ** 2)
        np.testing.assert_allclose(np.abs(after[k]) / np.abs(before[k]), expected, rtol=1e-6)


def test_a_mesh_coarse_across_a_gaussian_topography_is_reported():
    """The check judges the cells across y on their own (a transient run's surface is sampled
    finer than the mesh along x): 12.4 um rows against 15 um are reported with the key to
    change, rows of 3.7 um are not; the x cells, finer than the surface sampling along x, are
    left to the check of unresolved wavelengths."""
    x = np.linspace(0.0, 500e-6, 513)
    for rows, reported in ((41, True), (137, False)):
        y = np.linspace(-247.6e-6, 247.6e-6, rows)
        lines = diagnostics.roughness_resolution("surface2", 15e-6, x, y, along_x=False,
                                                 correlation_length_y=15e-6)
        assert bool(lines) is reported
    assert lines == []
    coarse = diagnostics.roughness_resolution("surface2", 15e-6, x,
                                              np.linspace(-247.6e-6, 247.6e-6, 41),
                                              along_x=False, correlation_length_y=15e-6)
    assert coarse[0].startswith("surface2: correlation_length_y = 15 um is 1.2 cells of "
                                "12.4 um across y (limit 2 cells)")
    # along x alone the same coarse cells would be reported against the x length
    x_coarse = np.linspace(0.0, 500e-6, 41)
    assert diagnostics.roughness_resolution("surface2", 15e-6, x_coarse, np.zeros(1),
                                            correlation_length_y=15e-6)


def test_a_run_with_a_topography_on_rows_too_coarse_says_so():
    """The user's case on a grid of its own with rows b/5 apart (a few steps): the disc that
    has entered the domain is a topography (its heights vary across y) and the run names the
    correlation length (the case's key) that its rows cannot resolve across y."""
    data = tomllib.loads(DISC)
    data["grid"] = {"nx": 65, "ny": 21}
    data["time"] = {"warmup_steps": 0, "counting_steps": 6}
    outcome = run_case(load_case(data))
    lines = [w for w in outcome.warnings if "across y (limit 2 cells)" in w]
    # the key the case set: correlation_length (isotropic), not correlation_length_y
    assert len(lines) == 1 and lines[0].startswith("surface2: correlation_length = 15 um")
    disc = outcome.dataset["surface2"].values  # at the last step, entered at the inlet
    entered = disc[np.abs(disc).max(axis=1) > 0.0]
    assert len(entered) >= 2
    assert entered.std(axis=1).mean() > 0.5 * entered.std() > 0.0


def test_a_self_affine_topography_gets_rows_for_its_shortest_wavelength():
    """A self-affine disc (H = 0.8, Sq 0.05 um, roll-off 50 um, short cut-off 10 um) is
    generated on the mesh's rows, which must be at most half its shortest wavelength apart:
    the default mesh gives it four rows per short cut-off, and a grid of the user's own with
    rows 12.4 um apart is refused in one line that names the key and the rows."""
    keys = {"kind": "self-affine", "hurst": 0.8, "rms": "0.05 um",
            "rolloff_wavelength": "50 um", "short_cutoff": "10 um"}
    data = tomllib.loads(DISC)
    data["surface2"] = keys
    x, y, (_, disc) = _setup(load_case(data))
    assert y[1] - y[0] <= 10e-6 / ROUGHNESS_CELLS * (1 + 1e-9)
    assert isinstance(disc, Topography)
    with pytest.raises(InputError, match=r"short_cutoff: expected at least two of the mesh's "
                                         r"row spacings across y \(2\.476e-05 m\).*grid\.ny"):
        _setup(load_case(data), grid=(129, 41))
