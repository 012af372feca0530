"""Robust defaults of the steady EHL solver across lubricated contacts (issue 17).

Every case is solved with ``solve_steady(problem)`` alone: the domain, the mesh and the
grid sequencing come from the problem (``default_domain``, ``default_nodes``: inlet from
Hamrock & Dowson's fully flooded distance, mesh from the estimated film), no solver setting is
tuned. Each row prints the sweeps (finest grid / all grids) and the central and minimum films
against the film formulas (run with ``-s`` to see the table; docs/ehl-robustness.md holds it
with the sources and the accuracy each formula claims).

Tolerances (central film):

- Newtonian, Barus, incompressible (the formulas' own model): 6 % against Nijenbanning et al.
  (point, ``ry >= rx``) and Moes (line), whose fits follow their numerical solutions within a
  few per cent; the default mesh adds about 2 %.
- Against Hamrock-Dowson (point, k >= 1): 25 %; it is a
  regression of older, coarser solutions that differ from converged solutions by up to
  about 20 % at high load. Chittenden et al. (k < 1, entrainment along the major axis): 5 %
  about the converged film's ratio to this transcription of the formula, 1.425 at k = 0.5
  and 1.78 at k = 0.25, measured by an independent reference solution that the solver
  matches within 0.3 % (tests/test_ehl_ellipse_reference.py; the default mesh lies 2 % and
  3 % under the converged film; docs/ehl-robustness.md).
- Roelands viscosity, Dowson-Higginson density and Eyring shear: 30 % below to 5 % above
  Hamrock-Dowson; compressibility and the Roelands law (lower viscosity at high pressure than
  Barus with the same alpha) thin the film by 10-20 %, the Eyring linearisation leaves the
  central film unchanged (it acts on the Poiseuille flow where the film is set, in the inlet,
  only weakly). The same band against Moes for the line contacts of the roller (Roelands +
  Dowson-Higginson at L = 18.4, measured 0.78-0.82 of Moes: the Dowson-Higginson density
  alone takes 18 % off Moes' film at M = 20, where the Roelands oil incompressible gives 0.98
  and the Barus one 1.03).
"""

import numpy as np
import pytest

from asperity.contact.hertz import radius_ratio
from asperity.ehl import LineContact, Lubricant, PointContact, solve_steady
from asperity.ehl.formulas import (
    chittenden_point,
    dowson_higginson_line,
    hamrock_dowson_point,
    moes_line,
    nijenbanning_point,
)
from asperity.materials import Material

STEEL = Material(210e9, 0.3)
GLASS = Material(75e9, 0.22)
BODY = Material(2e11, 0.3)
E_PRIME = 2e11 / (1 - 0.3**2)
GEAR = Material(227e9 * (1 - 0.3**2), 0.3)
BEARING_STEEL = Material(208e9, 0.3)


def _barus():
    return Lubricant(0.04, 2e-8, viscosity_model="barus", compressible=False)


def _point(M, L, k=1.0, lubricant=None):
    """Point contact with Moes groups M, L and k = b/a; Newtonian Barus incompressible unless
    ``lubricant`` is given (with ``alpha = 2e-8 /Pa``, ``eta0 = 0.04 Pa s``)."""
    alpha, eta0, rx = 2e-8, 0.04, 0.01
    two_u = (L / (alpha * E_PRIME)) ** 4
    u = 0.5 * two_u * E_PRIME * rx / eta0
    load = M * two_u**0.75 * E_PRIME * rx**2
    ry = rx / radius_ratio(1.0 / k)
    return PointContact(rx, ry, load, u, u, BODY, BODY, lubricant or _barus())


def _bearing():
    """A user's deep-groove ball bearing, inner-race contact (docs/ehl-robustness.md): steel
    (208 GPa), Rx = 3.2 mm, Ry = 40 mm (k = 5.2), 800 N (2.9 GPa), 8 m/s rolling, 0.02 Pa s,
    alpha = 18 1/GPa, Roelands + Dowson-Higginson: M = 3573, L = 18.8."""
    return PointContact(3.2e-3, 40e-3, 800.0, 8.0, 8.0, BEARING_STEEL, BEARING_STEEL,
                        Lubricant(0.02, 1.8e-8))


def _bearing_6205(lubricant):
    """A 6205 deep-groove ball bearing's inner-race contact at its most loaded ball, as its
    user writes it (docs/ehl-robustness.md): steel (208 GPa), ball 7.94 mm on a 31.5 mm
    raceway in a 0.52 D groove (Rx = 3.17 mm, Ry = 102 mm, k = 9.3), 1000 N (2.58 GPa),
    2.1 m/s rolling, 0.012 Pa s, alpha = 18 1/GPa: M = 18080, L = 11.9, beyond the other
    rows in M and k."""
    return PointContact(3.17e-3, 102e-3, 1000.0, 2.1, 2.1, BEARING_STEEL, BEARING_STEEL,
                        lubricant)


def _line(M, L):
    """Newtonian Barus incompressible line contact with Moes groups M, L."""
    alpha, eta0, r = 2e-8, 0.04, 0.01
    two_u = (L / (alpha * E_PRIME)) ** 4
    u = 0.5 * two_u * E_PRIME * r / eta0
    return LineContact(r, M * two_u**0.5 * E_PRIME * r, u, u, BODY, BODY, _barus())


def _line_oil(M, L):
    """The line contact of :func:`_line` with the default Roelands + Dowson-Higginson oil of
    the same ``eta0`` and ``alpha``."""
    b = _line(M, L)
    return LineContact(b.radius, b.load_per_length, b.u1, b.u2, b.body1, b.body2,
                       Lubricant(0.04, 2e-8))


def _ball(load, disc, tau0=None, xi=0.0):
    """12.5 mm radius steel ball on a flat disc, 0.25 Pa s Roelands + Dowson-Higginson oil at
    0.1 m/s: the slow, viscous ball-on-disc rig of the issue."""
    lub = Lubricant(0.25, 2e-8, eyring_stress=tau0)
    u = 0.1
    return PointContact(0.0125, 0.0125, load, u * (1 + xi / 2), u * (1 - xi / 2), STEEL, disc,
                        lub)


def _roller(M=None, tau0=None, xi=0.0):
    """The user's cylindrical roller on its inner race (docs/ehl-robustness.md): steel on
    steel, R = 6.2 mm, 6 m/s, 0.03 Pa s, alpha = 20 1/GPa, Roelands + Dowson-Higginson
    (M = 19.8, L = 18.4 at 450 kN/m); ``M`` sets the load at the same L."""
    lub = Lubricant(0.03, 2e-8, eyring_stress=tau0)
    u1, u2 = 6.0 * (1 + xi / 2), 6.0 * (1 - xi / 2)
    prob = LineContact(6.2e-3, 450e3, u1, u2, STEEL, STEEL, lub)
    if M is None:
        return prob
    return LineContact(6.2e-3, 450e3 * M / prob.M, u1, u2, STEEL, STEEL, lub)


def _roller_low_sliding(tau0=None, xi=0.05):
    """A user's roller on its inner race (docs/ehl-robustness.md, "Not in the table",
    session 36): steel on steel, R = 4 mm, 500 kN/m, 5 m/s, 0.02 Pa s, alpha = 18 1/GPa,
    Roelands + Dowson-Higginson (M = 36.8, L = 15.9), Eyring ``tau0`` at slide/roll ``xi``."""
    lub = Lubricant(0.02, 1.8e-8, eyring_stress=tau0)
    return LineContact(4e-3, 500e3, 5.0 * (1 + xi / 2), 5.0 * (1 - xi / 2), STEEL, STEEL, lub)


def _gear():
    """The seed's gear case (Holmes et al. 2005, Table 1): Roelands, DH, Eyring 10 MPa."""
    u, xi = 25.0, 0.25
    return PointContact(0.0191, 0.151, 962.0, u * (1 + xi / 2), u * (1 - xi / 2), GEAR, GEAR,
                        Lubricant(0.005, 11.1e-9, eyring_stress=10e6))


# name, problem factory, formula model ("exact": Newtonian Barus incompressible)
CASES = [
    ("circle M=10 L=10", lambda: _point(10, 10), "exact"),
    ("circle M=100 L=10", lambda: _point(100, 10), "exact"),
    ("circle M=1000 L=10", lambda: _point(1000, 10), "exact"),
    ("circle M=50 L=2", lambda: _point(50, 2), "exact"),
    ("circle M=10 L=3", lambda: _point(10, 3), "exact"),
    ("circle M=50 L=20", lambda: _point(50, 20), "exact"),
    ("ellipse k=2 M=100 L=10", lambda: _point(100, 10, 2.0), "exact"),
    ("ellipse k=4 M=100 L=10", lambda: _point(100, 10, 4.0), "exact"),
    ("ellipse k=8 M=100 L=10", lambda: _point(100, 10, 8.0), "exact"),
    ("ellipse k=0.5 M=100 L=10", lambda: _point(100, 10, 0.5), "exact"),
    ("ellipse k=0.25 M=100 L=10", lambda: _point(100, 10, 0.25), "exact"),
    ("ellipse k=5 M=1000 L=19", lambda: _point(1000, 19, 5.0), "exact"),
    ("circle M=1000 L=19 Roelands+DH", lambda: _point(1000, 19, 1.0, Lubricant(0.04, 2e-8)),
     "roelands"),
    ("ball bearing k=5.2 Roelands+DH", _bearing, "roelands"),
    ("6205 bearing k=9.3 M=18080", lambda: _bearing_6205(
        Lubricant(0.012, 1.8e-8, viscosity_model="barus", compressible=False)), "exact"),
    ("6205 bearing k=9.3 M=18080 Roelands+DH", lambda: _bearing_6205(
        Lubricant(0.012, 1.8e-8)), "roelands"),
    ("line M=10 L=10", lambda: _line(10, 10), "exact"),
    ("line M=100 L=10", lambda: _line(100, 10), "exact"),
    ("line M=1000 L=10", lambda: _line(1000, 10), "exact"),
    ("line M=50 L=20", lambda: _line(50, 20), "exact"),
    ("line M=100 L=3", lambda: _line(100, 3), "exact"),
    ("line M=20 L=2", lambda: _line(20, 2), "exact"),
    ("line M=1000 L=2", lambda: _line(1000, 2), "exact"),
    ("line M=100 L=3 Roelands+DH", lambda: _line_oil(100, 3), "roelands"),
    ("roller 450 kN/m Roelands+DH", _roller, "roelands"),
    ("roller M=10 Roelands+DH", lambda: _roller(10), "roelands"),
    ("roller M=50 Roelands+DH", lambda: _roller(50), "roelands"),
    ("roller Eyring 10 MPa xi=0.25", lambda: _roller(tau0=10e6, xi=0.25), "roelands"),
    # session 36: a user's roller at low sliding, converged by the refresh fallback
    # (solver.LINE_RETRY_REFRESH; before: 972 nm, load error -10 %, not converged)
    ("roller 500 kN/m Eyring 10 MPa xi=0.05", lambda: _roller_low_sliding(10e6), "roelands"),
    ("ball steel 15 N Roelands", lambda: _ball(15.0, STEEL), "roelands"),
    ("ball steel 15 N Eyring 5 MPa xi=0.5", lambda: _ball(15.0, STEEL, 5e6, 0.5), "roelands"),
    ("ball glass 30 N Eyring 5 MPa xi=0.5", lambda: _ball(30.0, GLASS, 5e6, 0.5), "roelands"),
    ("gear 25 m/s Eyring 10 MPa xi=0.25", _gear, "roelands"),
]


#: Cases whose converged film lies further from Nijenbanning's fit than its usual few per
#: cent: the circle at M = 10, L = 3 (near-rigid, near-isoviscous corner) gives 0.907 of it
#: on the default mesh, 0.908 with dX halved, 0.908 on an inlet at 8 a and 0.916 on a wider
#: domain (docs/ehl-robustness.md): converged, so the difference is the fit's, not tuned away.
FIT_TOLERANCE = {"circle M=10 L=3": 0.11}

#: The converged central film over Chittenden et al.'s (as transcribed) of the k < 1 rows,
#: from the independent reference of tests/test_ehl_ellipse_reference.py (0.09377 and
#: 0.0515 in Hertzian units, to about 0.2 %): the formula, not the solver, lies 30 % and 44 %
#: under it.
CHITTENDEN_RATIO = {"ellipse k=0.5 M=100 L=10": 1.425, "ellipse k=0.25 M=100 L=10": 1.78}


def _formulas(prob):
    """(name, central, minimum) rows of the formulas that apply to the problem, m."""
    lub = prob.lubricant
    args = (prob.mean_speed, lub.viscosity, lub.pressure_viscosity, prob.reduced_modulus)
    if isinstance(prob, LineContact):
        moes = moes_line(prob.load_per_length, prob.radius, *args)
        dh = dowson_higginson_line(prob.load_per_length, prob.radius, *args)
        return [("Moes", moes.central, None), ("Dowson-Higginson", None, dh.minimum)]
    rows = []
    if prob.ry >= prob.rx:
        rows.append(("Nijenbanning", nijenbanning_point(prob.load, prob.rx, prob.ry,
                                                        *args).central, None))
        hd = hamrock_dowson_point(prob.load, prob.rx, prob.ry, *args)
        rows.append(("Hamrock-Dowson", hd.central, hd.minimum))
    else:
        ch = chittenden_point(prob.load, prob.rx, prob.ry, *args)
        rows.append(("Chittenden", ch.central, ch.minimum))
    return rows


@pytest.mark.parametrize("name, factory, model", CASES, ids=[c[0] for c in CASES])
def test_default_settings_converge_and_match_the_film_formulas(name, factory, model):
    """Default settings converge; the central film agrees with the formulas (module doc)."""
    prob = factory()
    res = solve_steady(prob)
    rows = _formulas(prob)
    ratios = "  ".join(
        f"{f}: hc {res.central_film / hc:.3f}" if hc else f"{f}: hmin {res.minimum_film / hm:.3f}"
        for f, hc, hm in rows)
    hd_min = [res.minimum_film / hm for f, hc, hm in rows if hc and hm]
    nx, ny = res.levels[-1]
    print(f"\n| {name} | M {prob.M:.0f} | L {prob.L:.1f} | k "
          f"{'line' if ny == 1 else f'{prob.b / prob.a:.2f}'} | {nx}x{ny}, {len(res.levels)} "
          f"levels | sweeps {res.sweeps}/{res.total_sweeps} | hc {res.central_film * 1e9:.1f} nm"
          f" | hmin {res.minimum_film * 1e9:.1f} nm | {ratios}"
          + (f"  hmin/HD {hd_min[0]:.3f}" if hd_min else "") + " |")
    assert res.converged and abs(res.load_error) < 1e-4
    assert res.inlet_pressure < 0.01
    for formula, hc, _ in rows:
        if hc is None:
            continue
        ratio = res.central_film / hc
        if model == "exact" and formula in ("Nijenbanning", "Moes"):
            assert ratio == pytest.approx(1.0, abs=FIT_TOLERANCE.get(name, 0.06)), formula
        elif formula == "Chittenden":
            # k < 1: the converged film is 1.425 (k = 0.5) and 1.78 (k = 0.25) times this
            # transcription of the formula by an independent reference that the solver
            # matches within 0.3 % (tests/test_ehl_ellipse_reference.py); the default mesh
            # lies 2 % and 3 % under the converged film
            assert ratio == pytest.approx(CHITTENDEN_RATIO[name], rel=0.05), formula
        elif model == "exact":
            assert ratio == pytest.approx(1.0, abs=0.25), formula
        else:
            assert 0.7 < ratio < 1.05, formula
    assert 0 < res.minimum_film < res.central_film


def test_high_viscosity_ball_on_nearly_square_cells_converges():
    """The issue's failure: the slow viscous ball with an Eyring oil at xi = 0.5 on the former
    default mesh (129 x 65 on -2.5a..1.5a, cells nearly square) diverged (residual 0.5 after
    5000 sweeps, docs/ehl-robustness.md). With the density's Newton term in the row solve it
    converged there on one grid, slowly (1290 sweeps; 360 since session 42, with the grid
    sequence a given mesh now takes and its load tangent), to the film of the default mesh
    (dY >= 3 dX, measured 520 sweeps), which stays the default."""
    prob = _ball(15.0, STEEL, 5e6, 0.5)
    domain = ((-2.5 * prob.a, 1.5 * prob.a), (-2 * prob.b, 2 * prob.b))
    one_grid = solve_steady(prob, nx=129, ny=65, max_iter=5000, domain=domain, levels=1)
    sequenced = solve_steady(prob, nx=129, ny=65, max_iter=5000, domain=domain)
    new = solve_steady(prob)
    assert one_grid.converged and sequenced.converged and new.converged
    assert one_grid.sweeps > 2 * new.sweeps and new.sweeps < 1000
    assert len(sequenced.levels) == 3 and sequenced.sweeps < 1000
    assert sequenced.central_film == pytest.approx(one_grid.central_film, rel=2e-4)
    assert one_grid.central_film == pytest.approx(new.central_film, rel=0.03)
    # dY >= 3 dX, at b/10 on the default domain (+-2.4 b since the sides follow the inlet)
    assert (new.y[1] - new.y[0]) >= 3 * (new.x[1] - new.x[0])
    assert new.y[1] - new.y[0] == pytest.approx(prob.b / 10)


def test_default_domain_and_mesh_follow_the_regime():
    """The seed's domain for the gear case; a longer inlet for a thick film (low M), finer
    cells for a thin one (high M)."""
    gear = _gear()
    (x0, x1), (y0, y1) = gear.default_domain()
    assert x0 == pytest.approx(-2.5 * gear.a) and x1 == pytest.approx(1.5 * gear.a)
    assert y1 == pytest.approx(2 * gear.b)
    thick, thin = _point(10, 10), _point(1000, 10)
    assert thick.default_domain()[0][0] < -5 * thick.a
    assert thin.cells_per_a() >= 4 * thick.cells_per_a()
    nx, ny = thin.default_nodes()
    assert (nx - 1) % 8 == 0 and ny == 41
    assert np.isclose(thin.default_domain()[0][0], -2.5 * thin.a)
    # a long ellipse keeps dY <= 16 a/n (b/10 would be 33 dX, which diverged at L = 19); the
    # x-spacing itself is a little finer, the domain being a whole number of cells
    long = _point(1000, 19, 5.0)
    nx, ny = long.default_nodes()
    (x0, x1), (y0, y1) = long.default_domain()
    assert (y1 - y0) / (ny - 1) <= 16.0 * long.a / long.cells_per_a() * (1 + 1e-9)
    assert ny > 41


@pytest.mark.parametrize("half_width", np.linspace(1.5, 5.0, 15))
def test_default_mesh_passes_its_own_mesh_check_on_a_users_domain(half_width):
    """The default mesh on a domain of the user's width (a steel ball on glass, M = 25,
    L = 6.9, y = +-2.6 b): the cells across were rounded down to a multiple of 8 under the
    dY >= 3 dX bound, giving b/dy = 9.2, and the mesh check (diagnostics.ehl_mesh, limit
    10 per semi-axis) warned about the mesh asperity had chosen. It stays quiet now, and the
    cells keep dY >= 3 dX."""
    from asperity import diagnostics
    from asperity.ehl.problem import MIN_CELL_ASPECT

    prob = _point(25, 6.9)
    domain = ((-3.7 * prob.a, 3.0 * prob.a), (-half_width * prob.b, half_width * prob.b))
    nx, ny = prob.default_nodes(domain)
    x, y = prob.grid(nx, ny, domain)
    assert diagnostics.ehl_mesh(x, y, prob.a, prob.b) == []
    assert y[1] - y[0] >= MIN_CELL_ASPECT * (x[1] - x[0]) * (1 - 1e-9)


def test_case_file_without_grid_uses_the_regime_defaults():
    """The slow ball example has no [grid] table: it runs on the regime's mesh and converges;
    the same case on the former default grid table (129 x 65) is what failed."""
    from asperity.cases import load_case
    from asperity.examples import example_text
    from asperity.runners import run_case

    case = load_case(example_text("ball-on-disc-slow"))
    prob = case.problem()
    assert case.regime_mesh
    assert case.solve_options(prob) == {"nx": None, "ny": None, "domain": None,
                                         "levels": None}
    out = run_case(case)
    assert out.converged
    assert out.summary["central_film_thickness_m"] == pytest.approx(192.5e-9, rel=0.02)
    hd = out.summary["hamrock_dowson_central_film_m"]
    assert 0.7 < out.summary["central_film_thickness_m"] / hd < 1.05


@pytest.mark.slow
@pytest.mark.parametrize("name", ["circle M=1000 L=10", "line M=100 L=10",
                                  "ball steel 15 N Eyring 5 MPa xi=0.5"])
def test_default_mesh_error_is_near_two_percent(name):
    """Halving the default dX (same domain and dY) changes the central film by < 2.5 %: the
    default mesh's discretisation error is near its 2 % target."""
    factory = dict((c[0], c[1]) for c in CASES)[name]
    prob = factory()
    coarse = solve_steady(prob)
    nx, ny = coarse.levels[-1]
    domain = ((coarse.x[0], coarse.x[-1]), (coarse.y[0], coarse.y[-1]))
    fine = solve_steady(prob, nx=2 * (nx - 1) + 1, ny=ny, domain=domain,
                        levels=len(coarse.levels), max_iter=40000)
    print(f"\n{name}: hc {coarse.central_film * 1e9:.1f} -> {fine.central_film * 1e9:.1f} nm")
    assert coarse.converged and fine.converged
    assert fine.central_film == pytest.approx(coarse.central_film, rel=0.025)


def test_default_sides_follow_a_long_inlet():
    """A thick film (circle, M 10, L 10, inlet 5.8 a) gets sides at +-3.6 b (3.41 b rounded up
    to whole blocks of 8 cells of b/10): there the central and minimum films are within 1 % of
    those with the sides at +-4.4 b on the same mesh. On the earlier +-2 b they were 2.8 % and
    4.5 % below (docs/ehl-robustness.md, "Side boundaries"). The gear case, whose inlet is the
    seed's 2.5 a, keeps +-2 b."""
    thick = _point(10, 10)
    (x0, x1), (y0, y1) = thick.default_domain()
    assert y1 == pytest.approx(3.6 * thick.b) and y0 == -y1
    nx, ny = thick.default_nodes()
    assert ny == 73  # 72 cells of b/10
    res = solve_steady(thick)
    dy = (y1 - y0) / (ny - 1)
    extra = round((4.4 * thick.b - y1) / dy / 4) * 4  # whole cells of the coarsest grid
    wide = solve_steady(thick, nx=nx, ny=ny + 2 * extra, levels=len(res.levels),
                        domain=((x0, x1), (y0 - extra * dy, y1 + extra * dy)))
    assert res.converged and wide.converged
    assert abs(res.central_film / wide.central_film - 1) < 0.01
    assert abs(res.minimum_film / wide.minimum_film - 1) < 0.01
    gear = _gear()
    assert gear.default_domain()[1][1] == pytest.approx(2 * gear.b)


@pytest.mark.slow  # 45 s; the fallback itself runs in the fast suite through the runner
# (tests/test_ehl_analysis.py::test_run_rescued_by_y_line_sweeps_says_so)
def test_square_cells_fall_back_to_y_line_sweeps():
    """A user's mesh with cells not long across y: the a/b = 4 ellipse of the seed's
    aspect-ratio study (M = 1024, L = 6.9) on 129 x 129 nodes over -2.5a..1.5a, -2b..2b
    (dY = dX/4). The x-line relaxation alone takes 3660 sweeps there (one grid; at residual
    0.9 after 5000 on 257 x 257); with 3000 allowed, the fallback with a y-line sweep after
    every x-line sweep converges (measured 955 sweeps) to the film of the default mesh
    (513 x 81, dY >= 3 dX, 217.8 nm) within the error of its coarse x-spacing (a/32: measured
    206.4 nm, -5.2 %; on 257 x 257 219.0 nm, docs/ehl-robustness.md, "Square cells")."""
    from asperity.cases import load_case

    case = load_case({
        "analysis": "ehl-steady", "title": "a/b = 4 on a square node count",
        "reduced_modulus": "227 GPa",
        "contact": {"type": "point", "rx": "19.1 mm", "ry": "2.3003 mm", "load": "128.51 N"},
        "speeds": {"u": "25 m/s", "xi": 0.25},
        "lubricant": {"eta0": "0.005 Pa s", "alpha": "11.1 1/GPa"},
        "grid": {"nx": 129, "ny": 129, "x_min": -2.5, "x_max": 1.5, "y_min": -2.0,
                 "y_max": 2.0}})
    prob = case.problem()
    options = case.solve_options(prob)
    res = solve_steady(prob, **{**options, "levels": 1}, max_iter=3000)
    default = solve_steady(prob)
    assert res.converged and res.y_lines and not default.y_lines
    assert res.y[1] - res.y[0] < res.x[1] - res.x[0]
    assert res.central_film == pytest.approx(default.central_film, rel=0.07)


def test_coarse_grids_of_a_point_contact_stop_at_their_sweep_cap(monkeypatch):
    """The 6205 bearing's coarsest grid (65 x 39 at M = 18,080, a/16 cells) does not converge:
    uncapped it takes all of its 5000 sweeps before the next grid converges from its state.
    Capped at ``COARSE_SWEEPS`` the sequence gives the same converged film on the finest grid
    (here 257 x 153, three levels) to the solver's tolerance, with at most ``COARSE_SWEEPS``
    sweeps on each coarser grid (docs/ehl.md, grid sequencing)."""
    from asperity.ehl import solver

    prob = _bearing_6205(Lubricant(0.012, 1.8e-8, viscosity_model="barus", compressible=False))
    domain = prob.default_domain()
    cap = solver.COARSE_SWEEPS
    capped = solve_steady(prob, nx=257, ny=153, domain=domain, levels=3)
    monkeypatch.setattr(solver, "COARSE_SWEEPS", 10**6)
    uncapped = solve_steady(prob, nx=257, ny=153, domain=domain, levels=3)
    assert capped.converged and uncapped.converged
    assert uncapped.total_sweeps - uncapped.sweeps > 5000  # the coarsest grid never converged
    assert capped.total_sweeps - capped.sweeps <= 2 * cap
    assert capped.central_film == pytest.approx(uncapped.central_film, rel=1e-4)
    assert capped.minimum_film == pytest.approx(uncapped.minimum_film, rel=1e-3)
