"""Trust checks: each one fires on a field built to break it, at the value an independent
calculation gives (closed-form shares of Hertz and uniform fields, filter transmissions), and
stays silent on a field that respects its limit."""

import math
import re

import numpy as np
import pytest

from asperity import diagnostics as dg
from asperity.materials import Material


def _percent(line: str, after: str) -> float:
    """The first ``N %`` following ``after`` in a warning line, as a fraction."""
    match = re.search(re.escape(after) + r"[^0-9]*([0-9.e+-]+) %", line)
    assert match, line
    return float(match.group(1)) / 100.0


def _cells(n, length):
    dx = length / n
    return -0.5 * length + dx * (np.arange(n) + 0.5)


def _hertz(x, y, a, p0=1e9):
    X, Y = np.meshgrid(x, y, indexing="ij")
    return p0 * np.sqrt(np.clip(1.0 - (X**2 + Y**2) / a**2, 0.0, None))


def _every_line_names_a_limit(lines):
    for line in lines:
        assert "limit" in line and ":" in line.split()[0], line


# ------------------------------------------------------------------------- dry contact edge
def test_edge_share_of_a_uniform_pressure_is_the_edge_cell_count():
    """Uniform pressure on every cell: the edge cells carry (2 nx + 2 ny - 4) / (nx ny)."""
    nx, ny = 20, 12
    lines = dg.contact_at_grid_edge(np.ones((nx, ny)), _cells(nx, 1e-3), _cells(ny, 1e-3))
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and lines[0].startswith("domain:")
    assert "x_min, x_max, y_min, y_max" in lines[0]
    expected = (2 * nx + 2 * ny - 4) / (nx * ny)
    assert _percent(lines[0], "carry") == pytest.approx(expected, rel=2e-3)


def test_edge_advice_uses_the_expected_contact_size():
    x = y = _cells(32, 0.1e-3)  # the 0.1 mm domain, contact 0.67 mm wide
    lines = dg.contact_at_grid_edge(_hertz(x, y, 0.335e-3), x, y, (0.67e-3, 0.67e-3))
    assert "x_extent >= 1.01 mm" in lines[0] and "y_extent >= 1.01 mm" in lines[0]


def test_edge_advice_for_a_contact_wider_than_expected():
    """A contact that reaches x_max on a grid already 1.5 times the expected (smooth) size
    along both axes (a rough contact spreading beyond Hertz): the advice enlarges x, the
    axis it reaches, by half (64 -> 96 um) and leaves y alone (it said y_extent before)."""
    x, y = _cells(128, 64e-6), _cells(96, 48e-6)
    p = _hertz(x - 12e-6, y, 21e-6)  # reaches x = +33 um > +32 um
    lines = dg.contact_at_grid_edge(p, x, y, (30e-6, 30e-6))
    assert "at x_max (" in lines[0] and "reaches beyond it" in lines[0]
    assert "x_extent >= 96 µm" in lines[0] and "y_extent" not in lines[0]


def test_contact_inside_the_grid_is_silent():
    x = y = _cells(64, 2e-3)
    assert dg.contact_at_grid_edge(_hertz(x, y, 0.6e-3), x, y) == []


def test_one_edge_touched_is_named():
    x = y = _cells(64, 2e-3)
    p = _hertz(x + 0.8e-3, y, 0.3e-3)  # centred at x = -0.8 mm: reaches x_min
    lines = dg.contact_at_grid_edge(p, x, y)
    assert len(lines) == 1 and "at x_min (" in lines[0]


# ------------------------------------------------------------------------- periodic contact
def test_periodic_contact_filling_the_cell():
    c = np.ones((32, 32), dtype=bool)
    c[:3, :3] = False  # 99.1 % in contact
    lines = dg.periodic_contact(c, _cells(32, 1.0), _cells(32, 1.0))
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and _percent(lines[0], "fills") == pytest.approx(1 - 9 / 1024,
                                                                            abs=5e-4)


@pytest.mark.parametrize("shift", [0, 16])
def test_periodic_patch_width_also_across_the_boundary(shift):
    """A disc of radius 0.3 L spans 0.6 L (+ one cell) of the period, also when it is split
    across the cell boundary (shift by half the period)."""
    n, L = 64, 1.0
    x = y = _cells(n, L)
    c = _hertz(x, y, 0.3 * L) > 0
    c = np.roll(c, shift, axis=0)
    lines = dg.periodic_contact(c, x, y)
    assert len(lines) == 1 and lines[0].startswith("contact: one contact patch")
    width = _percent(lines[0], "spans")
    assert width == pytest.approx(0.6, abs=2 / n)


def test_periodic_strips_the_same_on_every_row_are_judged_along_x_only():
    """A profile repeated across y on a flat: every patch is a strip across the whole period
    by design, and a wider period would change nothing, so only x is judged (strips 20 % of
    the period wide: silent). The same strips broken on one row do span y by contact and are
    reported."""
    x = y = _cells(64, 1.0)
    strips = np.zeros((64, 64), dtype=bool)
    strips[10:23, :] = strips[40:53, :] = True
    assert dg.periodic_contact(strips, x, y) == []
    broken = strips.copy()
    broken[10:23, 5] = False
    lines = dg.periodic_contact(broken, x, y)
    assert len(lines) == 1 and "along y" in lines[0]


def test_periodic_patch_below_half_the_period_is_silent():
    x = y = _cells(64, 1.0)
    assert dg.periodic_contact(_hertz(x, y, 0.2) > 0, x, y) == []


# ------------------------------------------------------------------------------ resolution
def test_contact_resolved_by_too_few_cells():
    """A disc 2 r = 8 cells wide: 4 cells per semi-axis, against a limit of 10."""
    x = y = _cells(64, 64.0)
    lines = dg.contact_resolution(_hertz(x, y, 4.0) > 0, x, y)
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and lines[0].startswith("mesh:")
    assert "4 cells per semi-axis along x" in lines[0] and "nx >= 160" in lines[0]
    # the size given is the semi-axis those cells make (4 cells of 1 m), not a cell's
    assert "(a semi-axis of about 4 m;" in lines[0]


def test_contact_resolved_by_enough_cells_is_silent():
    x = y = _cells(64, 64.0)
    assert dg.contact_resolution(_hertz(x, y, 12.0) > 0, x, y) == []
    assert dg.contact_resolution(np.zeros((64, 64), bool), x, y) == []


def test_no_cell_in_contact_with_a_contact_narrower_than_a_cell():
    """No contact at all, and the expected (Hertz) contact 0.3 cells wide along x: one mesh
    line naming both sizes; an expected contact wider than the cells, or none given, stays
    silent (no contact can be a correct answer, e.g. a negative approach)."""
    x = y = _cells(64, 64.0)
    none = np.zeros((64, 64), bool)
    lines = dg.contact_resolution(none, x, y, expected_size=(0.3, 5.0))
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and lines[0].startswith("mesh: no cell is in contact")
    assert "300 mm wide along x against cells of 1 m" in lines[0] and "along y" not in lines[0]
    assert dg.contact_resolution(none, x, y, expected_size=(5.0, 5.0)) == []


# -------------------------------------------------------------------------------- hardness
def test_hardness_exceeded_on_the_hertz_share_of_the_area():
    """Hertz pressure p0 sqrt(1 - r^2/a^2) exceeds H on r^2 < a^2 (1 - (H/p0)^2): that share of
    the contact area."""
    x = y = _cells(400, 2.4)
    p0, h = 2e9, 1.5e9
    soft = Material(200e9, 0.3, "soft steel", hardness=h)
    lines = dg.above_hardness(_hertz(x, y, 1.0, p0),
                              [("body1", soft), ("body2", Material(200e9, 0.3))])
    assert len(lines) == 1 and "body1 (soft steel)" in lines[0] and "1.5 GPa" in lines[0]
    assert _percent(lines[0], "body1 (soft steel) on") == pytest.approx(
        1 - (h / p0) ** 2, abs=0.01)


def test_hardness_not_reached_or_not_given_is_silent():
    x = y = _cells(64, 2.4)
    p = _hertz(x, y, 1.0, 1e9)
    assert dg.above_hardness(p, [("body1", Material(200e9, 0.3, hardness=2e9))]) == []
    assert dg.above_hardness(p, [("body1", Material(200e9, 0.3))]) == []


# ------------------------------------------------------------------------------------- EHL
def _hertz_line(x, a, p_h):
    return p_h * np.sqrt(np.clip(1 - (x / a) ** 2, 0, None))


def test_ehl_inlet_inside_the_build_up():
    """Hertz pressure on a domain from -1.05 a: within 0.1 a of the inlet it reaches
    sqrt(1 - 0.95^2) = 31 % of p_h."""
    a, p_h = 1e-4, 1e9
    x = np.linspace(-1.05 * a, 1.5 * a, 256)
    field = np.repeat(_hertz_line(x, a, p_h)[:, None], 5, axis=1)
    lines = dg.ehl_inlet(field, x, a, p_h)
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and lines[0].startswith("inlet: x_min = -1.05 a")
    near = x[x <= x[0] + 0.1 * a]
    assert _percent(lines[0], "leaves pressure") == pytest.approx(
        math.sqrt(1 - (near[-1] / a) ** 2), rel=1e-3)
    assert "use x_min <= -2.5 a" in lines[0]


def test_ehl_inlet_far_upstream_is_silent():
    a = 1e-4
    x = np.linspace(-2.5 * a, 1.5 * a, 256)
    assert dg.ehl_inlet(_hertz_line(x, a, 1e9)[:, None], x, a, 1e9) == []


def test_ehl_sides():
    a, b, p_h = 1e-4, 4e-4, 1e9
    x = np.linspace(-2.5 * a, 1.5 * a, 65)
    for y_max, fires in ((1.05, True), (2.0, False)):
        y = np.linspace(-y_max * b, y_max * b, 81)
        X, Y = np.meshgrid(x, y, indexing="ij")
        field = p_h * np.sqrt(np.clip(1 - (X / a) ** 2 - (Y / b) ** 2, 0, None))
        lines = dg.ehl_sides(field, y, b, p_h)
        assert bool(lines) is fires, lines
        if fires:
            _every_line_names_a_limit(lines)
            assert "y_max >= 2 b" in lines[0]
            band = np.abs(y) >= y_max * b - 0.1 * b - 1e-15
            assert _percent(lines[0], "leave pressure") == pytest.approx(
                field[:, band].max() / p_h, rel=1e-3)


def test_ehl_film_mesh():
    """The central film's discretisation error estimated by the default mesh's rule, 5 dx^2/H_c:
    reported above 5 %, with the nodes that bring it to 2 %; silent below."""
    a = 1e-4
    x = np.linspace(-4.0 * a, 1.5 * a, 129)  # dx = a/23.3
    lines = dg.ehl_film_mesh(x, a, 0.097)
    _every_line_names_a_limit(lines)
    assert len(lines) == 1
    assert _percent(lines[0], "up to") == pytest.approx(5 * (5.5 / 128) ** 2 / 0.097, rel=1e-2)
    cells = int(np.ceil(np.sqrt(5 / (0.02 * 0.097))))  # 51 cells per a for 2 %
    assert f"use nx >= {int(np.ceil(5.5 * cells)) + 1} (cells_per_a >= {cells})" in lines[0]
    assert dg.ehl_film_mesh(np.linspace(-4.0 * a, 1.5 * a, 257), a, 0.097) == []
    assert dg.ehl_film_mesh(x, a, 0.0) == []


def test_ehl_minimum_film_mesh():
    """The minimum film's error estimated from its relative second difference, 0.33 s, in
    each direction: a valley across y whose neighbours are 30 % thicker is reported (9.9 %)
    with the nodes for 2 % by the dy^2 scaling (and the nx that keeps dy >= 3 dx); one 10 %
    thicker (3.3 %) is not; a minimum on a side node is not judged across y; a zero film is
    reported as over 100 %; a line contact is judged along x only."""
    a = b = 1e-4
    x = np.linspace(-2 * a, 1.5 * a, 129)
    y = np.linspace(-2 * b, 2 * b, 41)

    def valley(rise, j=31):  # across y at row j, nearly flat along x (s = 0.001)
        h = np.full((x.size, y.size), 100e-9)
        bottom = 50e-9 * (1 + 1e-3 * (np.arange(x.size) - 60) ** 2)
        h[:, j - 1:j + 2] = np.outer(bottom, [1 + rise, 1, 1 + rise])
        return h

    lines = dg.ehl_minimum_film_mesh(valley(0.3), x, y, a, b)
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and "across y" in lines[0] and "along x" not in lines[0]
    assert _percent(lines[0], "estimated error") == pytest.approx(0.33 * 0.3, rel=1e-3)
    need = 8 * int(np.ceil(40 * np.sqrt(0.099 / 0.02) / 8)) + 1  # 89 cells -> 96
    dy = 4 * b / (need - 1)
    nx = 8 * int(np.ceil(3.5 * a / (dy / 3) / 8)) + 1
    assert f"use ny >= {need} with nx >= {nx} (dy >= 3 dx)" in lines[0]
    assert "y = 1.1 b" in lines[0] and "50 nm" in lines[0]
    assert dg.ehl_minimum_film_mesh(valley(0.1), x, y, a, b) == []
    edge = valley(0.3, j=1)
    edge[:, 0] = 0.5 * edge[:, 1]  # the minimum on the side node, flat along x
    assert dg.ehl_minimum_film_mesh(edge, x, y, a, b) == []
    zero = valley(0.3)
    zero[60, 31] = 0.0
    assert "over 100 %" in dg.ehl_minimum_film_mesh(zero, x, y, a, b)[0]
    line = np.full(x.size, 100e-9)
    line[59:62] = [80e-9, 50e-9, 80e-9]
    lines = dg.ehl_minimum_film_mesh(line, x, np.array([0.0]), a, None)
    assert len(lines) == 1 and "along x" in lines[0] and "y =" not in lines[0]


def test_ehl_minimum_film_mesh_keeps_within_the_nodes_a_case_takes():
    """Where the mesh for 2 % needs more nodes than a case takes, the line says so and names
    the finest mesh within the limits at the same proportions, with the error the dy^2
    scaling leaves on it, instead of a mesh the case refuses (probe case 04, a collapsed
    side lobe at M = 4849, was told 569 x 5993 and 14489 nodes along x). The valley of the
    test above needs 257 x 97 (dy = b/24, dx = dy/3): within 10,000 nodes the finest mesh
    is 161 x 57 (both spacings 1.58 times larger, in blocks of 8 cells), on which the
    0.33 * 0.3 = 9.9 % of the 129 x 41 mesh falls by (40/56)^2 to 5.05 %; within 200
    nodes along x, 193 x 73."""
    a = b = 1e-4
    x = np.linspace(-2 * a, 1.5 * a, 129)
    y = np.linspace(-2 * b, 2 * b, 41)
    h = np.full((x.size, y.size), 100e-9)
    bottom = 50e-9 * (1 + 1e-3 * (np.arange(x.size) - 60) ** 2)
    h[:, 30:33] = np.outer(bottom, [1.3, 1, 1.3])
    free = dg.ehl_minimum_film_mesh(h, x, y, a, b, max_nodes=(10**6, 8193, 4097))
    assert free == dg.ehl_minimum_film_mesh(h, x, y, a, b)
    assert "use ny >= 97 with nx >= 257 (dy >= 3 dx)" in free[0]
    (line,) = dg.ehl_minimum_film_mesh(h, x, y, a, b, max_nodes=(10_000, 8193, 4097))
    _every_line_names_a_limit([line])
    assert "use ny" not in line
    assert "needs nx >= 257, ny >= 97 (24,929 nodes), more than a case takes (10,000" in line
    assert "nx = 161, ny = 57 (9,177 nodes)" in line
    assert _percent(line, "still up to") == pytest.approx(0.099 * (40 / 56) ** 2, rel=1e-3)
    (line,) = dg.ehl_minimum_film_mesh(h, x, y, a, b, max_nodes=(10**6, 200, 4097))
    assert "nx <= 200" in line and "nx = 193, ny = 73 " in line


def test_ehl_minimum_film_mesh_keeps_to_the_nodes_that_converge():
    """With ``max_ny`` (a soft point contact's relaxation converges on at most 129 nodes
    across, on cells dy >= 8 dx) a minimum film that needs more nodes across is told the
    capped mesh and the error the dy^2 scaling leaves on it, not a mesh that does not
    converge; on a mesh already at the cap, that the estimate is its error bar."""
    a = b = 1e-3
    x = np.linspace(-2.5 * a, 1.5 * a, 1025)

    def lobe(ny, rise):  # a valley across y at y = 0.9 b, its neighbours `rise` thicker
        y = np.linspace(-2 * b, 2 * b, ny)
        j = int(np.argmin(abs(y - 0.9 * b)))
        h = np.full((x.size, y.size), 3e-6)
        h[:, j - 1:j + 2] = np.outer(1e-6 * (1 + 1e-4 * (np.arange(x.size) - 700) ** 2),
                                     [1 + rise, 1, 1 + rise])
        return y, h

    y, h = lobe(65, 2.4)  # estimate 0.33 * 2.4 = 79 %: ny >= 409 uncapped
    plain = dg.ehl_minimum_film_mesh(h, x, y, a, b)
    assert "use ny >= 409 with nx >= 1225 (dy >= 3 dx)" in plain[0]
    lines = dg.ehl_minimum_film_mesh(h, x, y, a, b, cell_aspect=8.0, max_ny=129)
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and "needs ny >= 409" in lines[0]
    assert "use ny = 129," in lines[0] and "nx >=" not in lines[0]  # 1025 keeps dy = 8 dx
    assert _percent(lines[0], "still up to") == pytest.approx(0.33 * 2.4 / 4, rel=1e-3)
    assert "refine until" not in lines[0] and "does not converge" in lines[0]
    y, h = lobe(129, 0.32)  # on the cap: 10.6 %
    lines = dg.ehl_minimum_film_mesh(h, x, y, a, b, cell_aspect=8.0, max_ny=129)
    assert "take the estimate as the error bar" in lines[0] and "use ny" not in lines[0]
    narrow = np.linspace(-2.5 * a, 1.5 * a, 513)  # dx = 2 dy / 8 at the cap: nx raised
    y, h = lobe(65, 2.4)
    lines = dg.ehl_minimum_film_mesh(h[::2], narrow, y, a, b, cell_aspect=8.0, max_ny=129)
    assert "use ny = 129 with nx >= 1025 (dy >= 8 dx)" in lines[0]


def test_ehl_side_film():
    """The side probe's film changes are reported above their limits, with the wider sides
    as the advice; within the limits, or when a probe solve did not converge, nothing."""
    from asperity.ehl.sides import SideProbe

    b = 1e-4

    def probe(narrow_min, narrow_centre, converged=True):
        return SideProbe((-1.4 * b, 1.4 * b), (-2.4 * b, 2.4 * b), (narrow_min, 80e-9),
                         (narrow_centre, 150e-9), converged, (65, 29))

    lines = dg.ehl_side_film(probe(76e-9, 149e-9), b)
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and "y_min <= -2.4 b and y_max >= 2.4 b" in lines[0]
    assert "on 65 x 29 nodes" in lines[0]
    assert _percent(lines[0], "minimum film is") == pytest.approx(80 / 76 - 1, rel=1e-3)
    assert _percent(lines[0], "central film") == pytest.approx(150 / 149 - 1, rel=1e-3)
    assert "higher" in lines[0]
    lower = dg.ehl_side_film(probe(84e-9, 150e-9), b)[0]  # the wider sides thin it: no "-4.76"
    assert _percent(lower, "minimum film is") == pytest.approx(1 - 80 / 84, rel=1e-3)
    assert "% lower and the central" in lower and "-" not in lower.split("minimum film is")[1][:3]
    assert dg.ehl_side_film(probe(79e-9, 149e-9), b) == []
    assert len(dg.ehl_side_film(probe(79e-9, 147e-9), b)) == 1  # the central film alone
    assert dg.ehl_side_film(probe(60e-9, 140e-9, converged=False), b) == []


def test_ehl_inlet_film():
    """The inlet probe's central film change is reported above ``STARVED_FILM_LOSS``, with the
    longer inlet as the advice; its minimum film change only where both minima are open;
    within the limit, or when a probe solve did not converge, nothing."""
    from asperity.ehl.sides import InletProbe

    a = 1e-4

    def probe(short_centre, short_min=64e-9, long_min=72e-9, converged=True):
        return InletProbe(-1.3 * a, -2.5 * a, (short_min, long_min), (short_centre, 100e-9),
                          converged, (181, 153))

    lines = dg.ehl_inlet_film(probe(94e-9), a)
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and lines[0].startswith("inlet: the inlet at x = -1.3 a")
    assert "use x_min <= -2.5 a" in lines[0] and "on 181 x 153 nodes" in lines[0]
    assert _percent(lines[0], "central film is") == pytest.approx(100 / 94 - 1, rel=1e-3)
    assert _percent(lines[0], "minimum film is") == pytest.approx(72 / 64 - 1, rel=1e-3)
    assert dg.ehl_inlet_film(probe(99e-9, short_min=71e-9), a) == []
    assert len(dg.ehl_inlet_film(probe(99e-9, short_min=60e-9), a)) == 1  # the minimum alone
    closed = dg.ehl_inlet_film(probe(94e-9, long_min=-1e-12), a)
    assert len(closed) == 1 and "minimum film" not in closed[0]
    assert dg.ehl_inlet_film(probe(80e-9, converged=False), a) == []


def test_ehl_mesh():
    a, b = 1e-4, 4e-4
    coarse = dg.ehl_mesh(np.linspace(-2.5 * a, 1.5 * a, 17), np.linspace(-2 * b, 2 * b, 81),
                         a, b)
    _every_line_names_a_limit(coarse)
    assert len(coarse) == 1 and "a/dx = 4" in coarse[0] and "b/dy" not in coarse[0]
    assert "nx >= 41" in coarse[0]
    assert dg.ehl_mesh(np.linspace(-2.5 * a, 1.5 * a, 41), np.linspace(-2 * b, 2 * b, 41),
                       a, b) == []  # exactly 10 spacings per semi-axis
    assert dg.ehl_mesh(np.linspace(-2.5 * a, 1.5 * a, 41), np.zeros(1), a, None) == []
    # 16 nodes over 58 km across a 1.3 mm contact (found by the case fuzzer): a/dy rounds to
    # 0 at 6 decimals; the line still gives the ratio and a finite node count
    absurd = dg.ehl_mesh(np.linspace(-2.5 * a, 1.5 * a, 41), np.linspace(-5.8e4, 0, 16), a, b)
    assert len(absurd) == 1 and "b/dy = 1.03e-07" in absurd[0], absurd


# ------------------------------------------------------------------------------- roughness
def test_unresolved_roughness_share():
    """A wave of 2 dx (the Gaussian filter at 4 dx passes exp(-pi (0.47 * 2)^2) = 6 % of it)
    beside a wave of 64 dx of the same amplitude: about 0.94 / sqrt(2) of the rms is
    unresolved."""
    dx, s = 8e-6, 1e-6
    xs = s * np.arange(8192)
    long_, short = np.sin(2 * np.pi * xs / (64 * dx)), np.sin(2 * np.pi * xs / (2 * dx))
    lines = dg.unresolved_roughness("surface1", 1e-7 * (long_ + short), s, dx)
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and lines[0].startswith("surface1:")
    alpha = math.sqrt(math.log(2) / math.pi)
    passed = 1 - math.exp(-math.pi * (alpha * 4 / 2) ** 2)
    assert _percent(lines[0], "surface1:") == pytest.approx(passed / math.sqrt(2), abs=0.02)
    assert dg.unresolved_roughness("surface1", 1e-7 * (long_ + 0.05 * short), s, dx) == []


def test_lowpass_removed_share():
    xs = np.linspace(0, 1e-3, 2000)
    long_, short = np.sin(2 * np.pi * xs / 2e-4), 0.5 * np.sin(2 * np.pi * xs / 1e-5)
    lines = dg.lowpass_removed("surface2", long_ + short, long_, 3e-5)
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and "30 um" in lines[0]
    assert _percent(lines[0], "removed") == pytest.approx(0.5 / math.sqrt(1.25), rel=1e-3)
    assert dg.lowpass_removed("surface2", long_, long_ + 1e-4 * short, 3e-5) == []


def test_unconverged_steps():
    flags = np.ones(200, dtype=bool)
    flags[[3, 50, 51]] = False
    lines = dg.unconverged_steps(flags, 1e-4, 400)
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and lines[0].startswith("steps: 3 of 200") and "4, 51, 52" in lines[0]
    assert dg.unconverged_steps(np.ones(5, bool), 1e-4, 400) == []
    assert "raise max_sweeps" in lines[0]


def test_smooth_start_contact():
    # a smooth film that closes on two bands at the edges across y (the side lobes on too
    # coarse a mesh), and on the boundary rows, which the statistics do not count
    a, b = 2e-4, 1e-4
    x, y = np.linspace(-2.5 * a, 1.5 * a, 81), np.linspace(-2 * b, 2 * b, 41)
    film = np.full((81, 41), 3e-7)
    lobes = (np.abs(x) <= 0.5 * a)[:, None] & (np.abs(np.abs(y) - b) < 0.06 * b)[None, :]
    film[lobes] = 0.0
    film[0, :] = film[:, -1] = 0.0
    (line,) = dg.smooth_start_contact(film, x, y, a, b, 1e-11)
    _every_line_names_a_limit([line])
    assert f"at {lobes.sum()} nodes" in line
    xs = x[np.any(lobes, axis=1)] / a
    assert f"x = {xs.min():.2f} a to {xs.max():.2f} a, |y| = 1.00 b;" in line
    film[lobes] = 2e-11                                 # above the contact film: no contact
    assert dg.smooth_start_contact(film, x, y, a, b, 1e-11) == []
    # a line contact: one node across
    line_film = np.full(81, 3e-7)
    line_film[50] = 0.0                                 # x = 0
    (line,) = dg.smooth_start_contact(line_film, x, np.zeros(1), a, None, 1e-11)
    assert "at 1 nodes (x = 0.00 a; limit 0)" in line


def test_unconverged_steps_that_blew_up_are_not_told_to_take_more_sweeps():
    # two steps stalled near the tolerance, one given up with its residual at 0.15 p_h and
    # one diverged (inf): the advice for each kind, with the sizes of the last changes
    flags = np.ones(200, dtype=bool)
    flags[[3, 50, 51, 120]] = False
    residuals = np.full(200, 5e-5)
    residuals[[3, 50, 51, 120]] = [2e-4, 0.15, np.inf, 3e-4]
    (line,) = dg.unconverged_steps(flags, 1e-4, 400, residuals, 0.05)
    _every_line_names_a_limit([line])
    assert line.startswith("steps: 4 of 200") and "4, 51, 52, 121" in line
    assert "2 ran out of 400 sweeps: raise max_sweeps" in line
    assert "2 stayed far from it" in line and "last change per sweep 0.15, at least 0.05" in line
    assert "try a finer grid (grid.nx, grid.ny) or a smaller [time] dt" in line
    residuals[51] = 2.0
    (line,) = dg.unconverged_steps(flags[52:], 1e-4, 400, residuals[52:], 0.05)
    assert "raise max_sweeps" in line and "stayed far" not in line
    (line,) = dg.unconverged_steps(flags[:52], 1e-4, 400, residuals[:52], 0.05)
    assert "1 ran out" in line and "2 stayed far from it" in line and "0.15-2," in line
    (line,) = dg.unconverged_steps(flags[51:52], 1e-4, 400, [np.inf], 0.05)
    assert "1 stayed far from it with every setting the solver falls back on (diverged" in line
    (line,) = dg.unconverged_steps(flags[51:52], 1e-4, 400, [np.inf], 0.05, line=True)
    assert "try a finer grid (grid.nx) or" in line


def test_inlet_length_criterion_against_a_longer_inlet():
    """Hamrock & Dowson's starvation fit against the solver: a thick-film point contact
    (100 m/s, 0.05 Pa s) whose film needs an inlet of about 3.7 a by the fit. With the seed's
    -2.5 a the check predicts the central film some 16 % below the flooded one; the solve with
    the inlet at -8 a (same mesh spacing; no warning there) shows that loss within 5 points
    (19.3 %). The reference inlet was -4.5 a until the inlet probe measured its film 3.7 %
    below that at -7.6 a: the solve at -8 a is 3.8 % thicker than at -4.5 a and 0.25 %
    thinner than at -9 a (docs/ehl-robustness.md, "Inlet boundary")."""
    from pathlib import Path

    from asperity.cases import load_case
    from asperity.runners import run_case

    text = (Path(__file__).parent / "corpus" /
            "warn-ehl-point-inlet-inside-flooded-distance.toml").read_text()
    short = run_case(load_case(text))
    long_ = run_case(load_case(text.replace("x_min = -2.5", "x_min = -8.0")
                               .replace("nx = 65", "nx = 153")))
    assert [w.split(":")[0] for w in short.warnings] == ["inlet"] and long_.warnings == []
    predicted = _percent(short.warnings[0], "central film")
    loss = 1 - short.summary["central_film_thickness_m"] / long_.summary[
        "central_film_thickness_m"]
    assert loss == pytest.approx(predicted, abs=0.05)
    assert dg.ehl_inlet_length(-4.5e-4, 1e-4, 19.1e-3, 0.5e-6) == []


def test_film_collapse():
    """A film at or below zero anywhere in a smooth steady contact; positive films pass."""
    film = np.full((9, 5), 2e-7)
    assert dg.ehl_film_collapse(film, 2e-7) == []
    film[4, 2] = -1.8e-11
    lines = dg.ehl_film_collapse(film, 2.5e-9)
    _every_line_names_a_limit(lines)
    assert len(lines) == 1 and "-0.018 nm" in lines[0] and "<= 0 on 1 nodes" in lines[0]
    assert "about 2.5 nm" in lines[0]


def test_film_collapse_over_part_of_the_hertz_zone():
    """A positive film that has collapsed onto its floor over part of the Hertz zone (side
    lobes of probe case 12 at 3e-5 of the formula's film) is reported with the share of the
    Hertz area below 1 % of the formula's film; a thin lobe at 7 % of it (probe cases 15,
    27) and a collapse outside the zone are not."""
    x = np.linspace(-2.0, 1.5, 36)[:, None] * np.ones((1, 41))
    y = np.ones((36, 1)) * np.linspace(-2.0, 2.0, 41)[None, :]
    zone = x**2 + y**2 < 1.0
    film = np.full(x.shape, 1e-7)
    assert dg.ehl_film_collapse(film, 1e-7, zone) == []
    lobes = film.copy()
    lobes[zone & (np.abs(y) > 0.7)] = 7e-9  # thin lobes, 7 % of the formula's film
    assert dg.ehl_film_collapse(lobes, 1e-7, zone) == []
    collapsed = film.copy()
    sides = zone & (np.abs(y) > 0.7)
    collapsed[sides] = 3e-12
    lines = dg.ehl_film_collapse(collapsed, 1e-7, zone)
    _every_line_names_a_limit(lines)
    share = np.count_nonzero(sides) / np.count_nonzero(zone)
    assert _percent(lines[0], "collapsed on") == pytest.approx(share, abs=5e-4)
    assert "below 1 % of the film formulas' 100 nm" in lines[0]
    assert "0.003 nm at its thinnest" in lines[0]
    assert dg.ehl_film_collapse(collapsed, None, zone) == []
    outside = film.copy()
    outside[~zone & (np.abs(y) > 1.5)] = 3e-12
    assert dg.ehl_film_collapse(outside, 1e-7, zone) == []


def test_roughness_correlation_length_in_cells():
    """15 um on cells of 12.7 um is 15/12.7 = 1.18 cells (below the limit of 2), named with
    the cell size that resolves it (a quarter of the length)."""
    x = y = (np.arange(160) + 0.5) * 12.7e-6
    lines = dg.roughness_resolution("roughness", 15e-6, x, y)
    assert len(lines) == 1 and lines[0].startswith("roughness: correlation_length = 15 um")
    assert "1.2 cells of 12.7 um" in lines[0] and "cells <= 3.8 um" in lines[0]


def test_roughness_of_two_and_a_half_cells_is_silent():
    x = y = (np.arange(64) + 0.5) * 4e-6
    assert dg.roughness_resolution("roughness", 10e-6, x, y) == []


# ---------------------------------------------------------------- measured files on the grid
def test_a_grid_coarser_than_the_file_is_reported_with_the_nodes_it_needs():
    """A 1 um map on 2 um cells (128 over 256 um): the grid takes every other point; the line
    names both spacings, the slopes as given and nx >= 256 (256 um over 1 um). A grid of the
    file's own spacing, or of 1.5 times it, is silent."""
    x = y = _cells(128, 256e-6)
    lines = dg.decimated_roughness_file("roughness", (1e-6, 1e-6), x, y, 0.118, 0.101)
    assert len(lines) == 1 and lines[0].startswith("roughness.path: the grid is coarser")
    assert "dx = 2 um, 2 times the file's 1 um" in lines[0]
    assert "0.101 against the file's 0.118 (-14%)" in lines[0]
    assert "grid.nx >= 256 and grid.ny >= 256" in lines[0]
    fine = _cells(256, 256e-6)
    assert dg.decimated_roughness_file("roughness", (1e-6, 1e-6), fine, fine, 0.1, 0.1) == []
    assert dg.decimated_roughness_file("roughness", (1e-6, 1e-6), _cells(171, 256e-6),
                                       _cells(171, 256e-6), 0.1, 0.1) == []


def test_a_coarse_file_at_exactly_the_limit_is_silent():
    """A 1 um file on 0.5 um cells is twice as coarse: at the limit, not above it (the
    spacing 256 um / 512 came out 4.99999999999985e-7 and the line told the user to use
    the nx the case had)."""
    x = y = _cells(512, 256e-6)
    assert dg.coarse_roughness_file("roughness", (1e-6, 1e-6), x, y) == []
    assert dg.coarse_roughness_file("roughness", (1.01e-6, 1e-6), x, y) != []


def test_a_surface_that_is_not_periodic_on_a_periodic_grid_is_reported():
    """Sines of whole periods over the cell are periodic: the jump across the boundary is
    one of the neighbours' (silent). A window of 7.25 periods ends at a crest and steps by
    about A there, against neighbours' rms 2 pi 7.25 A / (sqrt(2) 256) = 0.126 A (a ratio
    of about 8): reported along x, naming the fix. On a grid 16 times finer than the file
    (each point repeated) the jump between neighbouring cells is mostly 0, so the inner
    jumps are taken over the file's interval, 16 cells."""
    n = 256
    i = np.arange(n)
    whole = np.sin(2 * np.pi * 8 * i / n)[:, None] * np.ones((1, 16))
    assert dg.periodic_seam("roughness", 1e-6 * whole) == []
    window = np.sin(2 * np.pi * 7.25 * i / n)[:, None] * np.ones((1, 16))
    lines = dg.periodic_seam("roughness", 1e-6 * window)
    assert len(lines) == 1 and "across the x boundary" in lines[0]
    assert "across the y boundary" not in lines[0] and "grid.periodic = false" in lines[0]
    ratio = float(lines[0].split("um rms across the x boundary, ")[1].split(" times")[0])
    step = abs(window[0, 0] - window[-1, 0])
    assert step == pytest.approx(1.0, abs=0.02)
    assert ratio == pytest.approx(step / (2 * np.pi * 7.25 / (np.sqrt(2) * n)), rel=0.02)
    fine = np.repeat(whole, 16, axis=0)  # steps of 16 cells: neighbours mostly equal
    assert dg.periodic_seam("roughness", 1e-6 * fine) != []
    assert dg.periodic_seam("roughness", 1e-6 * fine, lags=(16, 1)) == []


def _hertz_sphere(load, radius, e_star):
    """Hertz's closed forms of a sphere: a = (3 P R / 4 E*)^(1/3), p0 = 3 P / (2 pi a^2)."""
    a = (3.0 * load * radius / (4.0 * e_star)) ** (1.0 / 3.0)
    return a, 3.0 * load / (2.0 * math.pi * a * a)


def test_hertz_validity_flags_a_large_soft_contact_and_unchecked_strain():
    """A user's steel ball (R 6 mm, 210 GPa, nu 0.3) on PTFE (0.5 GPa, nu 0.46) at 200 N:
    E* = 0.6325 GPa, a = 1.125 mm (a/R = 0.1875), p0 = 75.5 MPa (p0/E* = 0.119), no
    hardness: both limits passed. The same ball on steel (E* = 115.4 GPa): a/R = 0.033,
    p0/E* = 0.021, silent."""
    e_ptfe = 1.0 / ((1 - 0.3**2) / 210e9 + (1 - 0.46**2) / 0.5e9)
    a, p0 = _hertz_sphere(200.0, 6e-3, e_ptfe)
    assert a / 6e-3 == pytest.approx(0.1875, abs=5e-4)
    lines = dg.hertz_validity(a, 6e-3, p0, e_ptfe, hardness_given=False)
    assert len(lines) == 2 and all(w.startswith("pressure:") for w in lines)
    size, strain = lines
    assert f"is {a / 6e-3:.3g} of the radius" in size and "limit a/R = 0.1" in size
    assert "reduce the load" in size and "too soft for half-space theory" in size
    assert f"p0/E* = {p0 / e_ptfe:.3g}" in strain and "limit 0.05" in strain
    assert "plasticity was not checked" in strain and "body1.hardness" in strain
    # a hardness given: the pressure is checked against it instead (above_hardness)
    assert dg.hertz_validity(a, 6e-3, p0, e_ptfe, hardness_given=True) == [size]
    e_steel = 1.0 / (2 * (1 - 0.3**2) / 210e9)
    a, p0 = _hertz_sphere(200.0, 6e-3, e_steel)
    assert dg.hertz_validity(a, 6e-3, p0, e_steel) == []
    # at the limits exactly: silent
    assert dg.hertz_validity(0.1, 1.0, 0.05, 1.0) == []


def test_a_contact_as_small_as_the_files_points_is_not_told_to_refine_past_them():
    """One spot 10 cells across on 256 cells of a 1 um map (a user's rough flat at 1 MPa):
    5 cells per semi-axis, under the 10 asked for; a grid of 512 cells would be finer than
    the file's points and only interpolate, so the line says that instead of nx >= 512. A
    generated surface (no file) is told nx >= 512."""
    x = y = _cells(256, 256e-6)
    spot = np.zeros((256, 256), dtype=bool)
    spot[100:110, 100:110] = True
    told = dg.contact_resolution(spot, x, y)
    assert len(told) == 1 and "use nx >= 512" in told[0]
    measured = dg.contact_resolution(spot, x, y, file_spacing=(1e-6, 1e-6))
    assert len(measured) == 1 and "use nx" not in measured[0]
    assert "finer grid than the file's points (1 um apart) only interpolates" in measured[0]
    coarse_file = dg.contact_resolution(spot, x, y, file_spacing=(0.25e-6, 0.25e-6))
    assert "use nx >= 512" in coarse_file[0]  # the file holds finer points: refine


def test_a_starved_inlet_is_advised_as_far_as_the_flooded_inlet_distance():
    """An MTM ball (3/4 in steel on glass, 20 N, 0.5 m/s, a = 134.6 um, Rx = 9.525 mm) on a
    user's -1.5 a inlet was told "use x_min <= -2.5 a" by the boundary-pressure line; on
    -2.5 a the inlet-length line then said m* = 2.8 a. Hamrock & Dowson's
    m* = 1 + 3.06 ((Rx/a)^2 hc/Rx)^0.58 with the flooded film hc = 738 nm (Nijenbanning's) is
    worked by hand below; the first line now asks for both at once."""
    a, rx, hc = 134.6e-6, 9.525e-3, 738e-9
    by_hand = 1.0 + 3.06 * ((rx / a) ** 2 * hc / rx) ** 0.58
    m_star = dg.flooded_inlet_distance_of(-1.5 * a, a, rx, hc, solved=False)
    assert m_star == pytest.approx(by_hand, rel=1e-12)
    assert 2.5 < m_star < 3.0
    x = np.linspace(-1.5 * a, 1.2 * a, 109)
    pressure = np.where(np.abs(x) < a, 1.0, 0.05)[:, None] * np.ones((1, 5))
    (plain,) = dg.ehl_inlet(pressure, x, a, 1.0)
    (flooded,) = dg.ehl_inlet(pressure, x, a, 1.0, m_star)
    assert plain.endswith("use x_min <= -2.5 a")
    assert flooded.endswith("use x_min <= -3 a")
    assert dg.advised_domain(x, np.zeros(5), [flooded])[0][0] == pytest.approx(-3 * a)


def test_steps_above_hardness_names_the_step_and_the_counting_share():
    """Largest pressures 1, 2, 8, 3, 9 GPa over five steps, two of warm-up: the hardness of
    7 GPa is exceeded at step 5 (9 GPa) and in 2 of the 3 counting steps; 10 GPa is not, nor
    is 1.5 GPa by warm-up steps alone."""
    from asperity.diagnostics import steps_above_hardness
    from asperity.materials import Material

    p = np.array([1.0, 2.0, 8.0, 3.0, 9.0]) * 1e9
    steel = Material(210e9, 0.3, "steel", 7e9)
    (line,) = steps_above_hardness(p, 2, [("body1", steel), ("body2", steel)])
    assert "9 GPa (step 5)" in line and "body1 and body2 (steel)" in line
    assert "66.7 % of the counting steps" in line and "7 GPa" in line
    assert steps_above_hardness(p, 2, [("body1", Material(210e9, 0.3, "hard", 10e9))]) == []
    assert steps_above_hardness(np.full(3, np.nan), 0, [("body1", steel)]) == []
    soft = Material(210e9, 0.3, "soft", 1.5e9)
    assert steps_above_hardness([1e9, 2e9, 1.2e9], 2, [("body1", soft)]) == []
    # the last step below the hardness, an earlier counting step above it: the run's field
    # check (above_hardness on the last step) passed such a run
    (late,) = steps_above_hardness([1e9, 2e9, 8e9, 3e9, 2e9], 2, [("body1", steel)])
    assert "8 GPa (step 3)" in late and "33.3 % of the counting steps" in late
    assert dg.above_hardness(np.array([[2e9, 0.0]]), [("body1", steel)]) == []


def test_asperity_plasticity_note_for_metals_without_a_hardness():
    """13 GPa on a gear flank's asperities (E* = 113 GPa: 0.115 E*, past the strain limit
    0.05) with no hardness given gets the note; with a hardness (judged instead), below the
    limit, or on an elastomer it does not."""
    from asperity.diagnostics import asperity_plasticity_note
    from asperity.materials import Material

    steel, e_star = Material(206e9, 0.3), 206e9 / (2 * (1 - 0.09))
    (note,) = asperity_plasticity_note(13e9, e_star, [("body1", steel), ("body2", steel)])
    assert "0.115 E*" in note and "body1.hardness" in note
    hard = Material(206e9, 0.3, "steel", 7e9)
    assert asperity_plasticity_note(13e9, e_star, [("body1", hard), ("body2", hard)]) == []
    assert asperity_plasticity_note(4e9, e_star, [("body1", steel), ("body2", steel)]) == []
    rubber = Material(5e6, 0.49)
    assert asperity_plasticity_note(1e6, 5e6, [("body1", rubber), ("body2", steel)]) == []


def test_a_generated_roughness_longer_than_its_grid_is_reported():
    """A periodic patch holds wavelengths up to its size: ``rolloff_wavelength = 100`` (meant
    in um, read in m) on a 0.5 mm patch ran without a word. The roll-off at the patch size
    itself, and a Gaussian correlation length of a quarter of it, are silent; one of more than
    half of it is a hill or two and is reported."""
    x = y = _cells(64, 0.5e-3)
    (line,) = dg.roughness_extent("roughness", x, y, rolloff_wavelength=100.0)
    _every_line_names_a_limit([line])
    assert line.startswith("roughness: rolloff_wavelength = 100 m is longer than the grid "
                           "(500 µm x 500 µm;")
    assert dg.roughness_extent("roughness", x, y, rolloff_wavelength=0.5e-3) == []
    assert dg.roughness_extent("roughness", x, y, correlation_length=0.125e-3) == []
    (line,) = dg.roughness_extent("roughness", x, y, correlation_length=0.3e-3)
    assert line.startswith("roughness: correlation_length = 300 µm is more than 1/2 of the grid")


# ------------------------------------------------------------------------- EHL friction
def test_friction_undefined_where_the_viscosity_overflows():
    """alpha = 999 1/GPa (the largest a case takes), eta0 = 10 mPa s: Roelands' index
    Z = alpha / (chi ln(eta0/kappa)) = 38.7, and at 183 MPa ln(eta/eta0) = ln(eta0/kappa)
    ((1 + chi p)^Z - 1) = 6.6e11: the law's viscosity is inf, without numpy's overflow
    warning, and the friction line names alpha; a finite friction is silent."""
    import warnings

    from asperity.ehl.lubricant import ROELANDS_CHI, ROELANDS_KAPPA, roelands_viscosity

    eta0, alpha, p = 0.01, 999e-9, 183e6
    z = alpha / (ROELANDS_CHI * math.log(eta0 / ROELANDS_KAPPA))
    assert z == pytest.approx(38.7, abs=0.05)
    assert math.log(eta0 / ROELANDS_KAPPA) * ((1 + ROELANDS_CHI * p) ** z - 1) > 709.8
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        eta = float(roelands_viscosity(p, eta0, alpha))
    assert eta == math.inf
    lines = dg.friction_undefined(math.nan, eta, p)
    assert len(lines) == 1 and lines[0].startswith("lubricant.alpha:") and "183 MPa" in lines[0]
    assert dg.friction_undefined(0.05, 1e3, p) == []
