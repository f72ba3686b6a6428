"""Godunov finite volumes: Godunov flux, Riemann problems, conservation, exact step-CDF integrals."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from particle_methods.convergence import fit_order, order_table
from particle_methods.finite_volume import (
    BURGERS,
    CONCAVE,
    ScalarFlux,
    burgers_flux,
    cell_averages_of_step_cdf,
    concave_flux,
    godunov,
    godunov_flux,
    l1_distance_to_step_cdf,
)
from particle_methods.finite_volume.scalar import cfl_time_step

FLUXES = [(BURGERS, (-2.0, 2.0)), (CONCAVE, (-1.0, 2.0))]


def brute_force_godunov(f, a, b, samples=20001):
    """min of f over [a, b] if a <= b, else max over [b, a], on a fine grid with both ends."""
    u = np.linspace(min(a, b), max(a, b), samples)
    return f(u).min() if a <= b else f(u).max()


@pytest.mark.parametrize(("flux", "bounds"), FLUXES)
def test_godunov_flux_is_the_min_or_max_of_f_between_the_states(flux, bounds, rng):
    left, right = rng.uniform(*bounds, size=(2, 200))
    computed = godunov_flux(flux, left, right)
    expected = [brute_force_godunov(flux.f, a, b) for a, b in zip(left, right)]
    # Sampling misses the extremum by at most half a grid step: an error (h/2)^2/2 for |f''| = 1.
    np.testing.assert_allclose(computed, expected, rtol=0, atol=1e-8)
    assert computed.shape == left.shape


@pytest.mark.parametrize(("flux", "bounds"), FLUXES)
def test_godunov_flux_is_consistent(flux, bounds, rng):
    u = rng.uniform(*bounds, size=100)
    np.testing.assert_array_equal(godunov_flux(flux, u, u), flux.f(u))
    assert isinstance(godunov_flux(flux, 0.3, 0.3), float)


def test_named_fluxes_and_their_speeds():
    assert BURGERS.f is burgers_flux and CONCAVE.f is concave_flux
    assert (BURGERS.shape, BURGERS.extremum, CONCAVE.shape, CONCAVE.extremum) == ("convex", 0.0, "concave", 0.5)
    np.testing.assert_allclose(BURGERS.derivative([-1.0, 2.0]), [-1.0, 2.0])
    np.testing.assert_allclose(CONCAVE.derivative([0.0, 1.0]), [0.5, -0.5])
    assert BURGERS.max_speed(-2.0, 1.0) == 2.0
    assert BURGERS.max_speed(0.0, 0.0) == 0.0
    assert CONCAVE.max_speed(0.0, 1.0) == 0.5
    assert CONCAVE.max_speed(0.4, 0.6) == pytest.approx(0.1)


# Exact entropy solutions of the Riemann problems u(0, x) = uL for x < 0, uR for x > 0, at time T.
T = 0.5
RIEMANN = {
    "burgers shock": (BURGERS, 1.0, 0.0, lambda x: np.where(x < 0.5 * T, 1.0, 0.0)),
    "burgers rarefaction": (BURGERS, 0.0, 1.0, lambda x: np.clip(x / T, 0.0, 1.0)),
    # f(0) = f(1): Rankine-Hugoniot speed 0; f'(0) = 1/2 > 0 > -1/2 = f'(1), so the Lax condition holds.
    "concave stationary shock": (CONCAVE, 0.0, 1.0, lambda x: np.where(x < 0.0, 0.0, 1.0)),
    # Speed (f(0.6) - f(0.2)) / 0.4 = (0.12 - 0.08) / 0.4 = 0.1, between f'(0.6) = -0.1 and f'(0.2) = 0.3.
    "concave shock": (CONCAVE, 0.2, 0.6, lambda x: np.where(x < 0.1 * T, 0.2, 0.6)),
    # f'(u) = 1/2 - u = x/t in the fan, which spans f'(0.8) = -0.3 <= x/t <= f'(0.2) = 0.3.
    "concave rarefaction": (CONCAVE, 0.8, 0.2, lambda x: np.clip(0.5 - x / T, 0.2, 0.8)),
}
SHOCKS = ["burgers shock", "concave stationary shock", "concave shock"]
RAREFACTIONS = ["burgers rarefaction", "concave rarefaction"]
# Odd numbers of cells on [-1, 1]: the initial jump at x = 0 sits in the middle of a cell.
CELLS = np.array([201, 401, 801, 1601])


def riemann_error(case: str, cells: int, subsamples: int = 32) -> float:
    """L1 error on [-1, 1] at time T of Godunov started from the exact cell averages of the jump."""
    flux, left, right, exact = RIEMANN[case]
    edges = np.linspace(-1.0, 1.0, cells + 1)
    u0 = left + (right - left) * cell_averages_of_step_cdf([0.0], edges)
    u = godunov(flux, u0, edges, T)
    dx = edges[1] - edges[0]
    x = edges[:-1, None] + dx * (np.arange(subsamples) + 0.5) / subsamples
    return float(dx * np.mean(np.abs(u[:, None] - exact(x)), axis=1).sum())


@pytest.mark.parametrize("case", SHOCKS)
def test_shocks_converge_at_order_one(case):
    errors = np.array([riemann_error(case, n) for n in CELLS])
    order = fit_order(2.0 / CELLS, errors)
    assert 0.8 <= order <= 1.2, order_table(2.0 / CELLS, errors, "dx")


@pytest.mark.parametrize("case", RAREFACTIONS)
def test_rarefactions_converge_at_order_one_half_or_better(case):
    errors = np.array([riemann_error(case, n) for n in CELLS])
    assert np.all(np.diff(errors) < 0), order_table(2.0 / CELLS, errors, "dx")
    assert fit_order(2.0 / CELLS, errors) >= 0.5, order_table(2.0 / CELLS, errors, "dx")


def test_stationary_shock_keeps_its_middle_cell():
    """Both faces of the cell holding u* = 1/2 carry min(f(0), f(1/2)) = min(f(1/2), f(1)) = 0."""
    edges = np.linspace(-1.0, 1.0, 102)
    u0 = cell_averages_of_step_cdf([0.0], edges)
    assert u0[50] == 0.5
    np.testing.assert_array_equal(godunov(CONCAVE, u0, edges, 3.0), u0)


def test_one_step_is_the_conservative_update_with_ghost_states(rng):
    u0 = rng.uniform(-1.0, 2.0, size=50)
    u0[0], u0[-1] = 0.2, -0.3
    edges = np.linspace(0.0, 1.0, 51)
    # Ghost states that change both boundary fluxes: F(1.5, 0.2) = f(1.5) and F(-0.3, 1) = f(0).
    left, right = 1.5, 1.0
    dx = 0.02
    dt = 0.9 * dx / 2.0  # CFL step for Burgers on the range [-1, 2]
    t = 0.5 * dt  # a single, shortened step
    faces = godunov_flux(BURGERS, np.concatenate([[left], u0]), np.concatenate([u0, [right]]))
    u = godunov(BURGERS, u0, edges, t, left=left, right=right)
    np.testing.assert_allclose(u, u0 - t / dx * np.diff(faces), rtol=0, atol=1e-14)
    assert np.sum(u) * dx == pytest.approx(np.sum(u0) * dx - t * (faces[-1] - faces[0]), abs=1e-12)


@pytest.mark.parametrize(("flux", "outer"), [(BURGERS, 0.0), (CONCAVE, 1.0)])
def test_mass_is_conserved_when_the_boundary_fluxes_cancel(flux, outer, rng):
    """Data equal to the same constant near both ends: the two boundary fluxes are f(outer)."""
    edges = np.linspace(-2.0, 2.0, 401)
    centres = 0.5 * (edges[1:] + edges[:-1])
    u0 = np.where(np.abs(centres) < 0.5, rng.uniform(-1.0, 1.0, size=400), outer)
    u = godunov(flux, u0, edges, 0.5)
    assert u[0] == outer and u[-1] == outer
    assert np.sum(u) * 0.01 == pytest.approx(np.sum(u0) * 0.01, abs=1e-12)
    assert not np.allclose(u, u0)
    assert u.min() >= u0.min() and u.max() <= u0.max()  # maximum principle


def test_trivial_runs_return_the_data():
    edges = np.linspace(1e6, 1e6 + 1.0, 1001)  # uniform up to the rounding of large edges
    u0 = np.linspace(0.0, 1.0, 1000)
    np.testing.assert_array_equal(godunov(BURGERS, u0, edges, 0.0), u0)
    np.testing.assert_array_equal(godunov(BURGERS, np.zeros(1000), edges, 1.0), 0.0)
    np.testing.assert_array_equal(godunov(CONCAVE, np.full(1000, 0.5), edges, 1.0), 0.5)


def test_step_cdf_by_hand():
    np.testing.assert_array_equal(cell_averages_of_step_cdf([0.0], [-1.0, 0.0, 1.0]), [0.0, 1.0])
    assert l1_distance_to_step_cdf([0.0, 1.0], [-1.0, 0.0, 1.0], [0.0]) == 0.0
    np.testing.assert_array_equal(cell_averages_of_step_cdf([0.25, 0.75], [0.0, 1.0]), [0.5])
    assert l1_distance_to_step_cdf([0.5], [0.0, 1.0], [0.5]) == 0.5
    # Points outside the grid count through H: one on the left, one on the right.
    np.testing.assert_array_equal(cell_averages_of_step_cdf([-5.0, 5.0], [0.0, 1.0, 3.0]), [0.5, 0.5])
    assert l1_distance_to_step_cdf([0.0, 1.0], [0.0, 1.0, 3.0], [-5.0, 5.0]) == pytest.approx(0.5 + 2 * 0.5)


def random_grid_and_points(rng, cells=12, n=9):
    edges = np.sort(rng.uniform(-1.0, 1.0, size=cells + 1))
    points = np.sort(rng.uniform(-1.2, 1.2, size=n))  # some outside the grid
    return edges, points


def step_cdf(points, x):
    return np.searchsorted(points, x, side="right") / points.size


def test_cell_averages_match_fine_sampling(rng):
    samples = 20000
    for _ in range(5):
        edges, points = random_grid_and_points(rng)
        s = (np.arange(samples) + 0.5) / samples
        x = edges[:-1, None] + np.diff(edges)[:, None] * s
        sampled = step_cdf(points, x).mean(axis=1)
        # The midpoint rule misplaces each point by at most half a sample: 1/(n samples) per cell.
        np.testing.assert_allclose(cell_averages_of_step_cdf(points, edges), sampled, rtol=0, atol=1.0 / samples)


def test_l1_distance_matches_fine_sampling(rng):
    samples = 400_000
    for _ in range(5):
        edges, points = random_grid_and_points(rng)
        values = rng.uniform(-0.5, 1.5, size=edges.size - 1)
        h = (edges[-1] - edges[0]) / samples
        x = edges[0] + h * (np.arange(samples) + 0.5)
        v = values[np.clip(np.searchsorted(edges, x, side="right") - 1, 0, values.size - 1)]
        sampled = h * np.abs(v - step_cdf(points, x)).sum()
        # Each jump (edges and points, of size at most 2) costs at most 2h to the midpoint rule.
        tolerance = 2 * h * (edges.size + points.size)
        assert l1_distance_to_step_cdf(values, edges, points) == pytest.approx(sampled, abs=tolerance)


@settings(max_examples=60, deadline=None)
@given(
    x0=st.floats(-10, 10),
    dx=st.floats(1e-3, 10),
    cells=st.integers(1, 30),
    data=st.data(),
)
def test_l1_distance_properties(x0, dx, cells, data):
    edges = x0 + dx * np.arange(cells + 1)
    indices = sorted(data.draw(st.lists(st.integers(0, cells), min_size=1, max_size=20)))
    points = edges[indices]  # every point on a cell edge: H is constant on each cell
    averages = cell_averages_of_step_cdf(points, edges)
    assert l1_distance_to_step_cdf(averages, edges, points) == 0.0
    values = np.array(data.draw(st.lists(st.floats(-2, 2), min_size=cells, max_size=cells)))
    distance = l1_distance_to_step_cdf(values, edges, points)
    assert distance >= 0.0
    # H is constant on cells, so the distance is sum |values - averages| dx.
    assert distance == pytest.approx(dx * np.abs(values - averages).sum(), rel=1e-9, abs=1e-12)


EDGES = np.linspace(0.0, 1.0, 11)
U0 = np.linspace(0.0, 1.0, 10)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"u0": U0[:-1]}, "u0 has 9 cells but x_edges has 11 edges"),
        ({"u0": np.r_[U0[:-1], np.nan]}, "u0 contains NaN"),
        ({"x_edges": np.r_[EDGES[:-1], np.inf]}, "x_edges contains NaN or infinite"),
        ({"x_edges": EDGES[::-1]}, "x_edges must be sorted"),
        ({"x_edges": np.r_[EDGES[:-1], 1.5]}, "x_edges must be uniformly spaced"),
        ({"x_edges": [0.0]}, "x_edges must contain at least 2 edges"),
        ({"t": -1.0}, "t must be non-negative"),
        ({"t": np.nan}, "t must be finite"),
        ({"t": 1e9}, "t=1000000000.0 on x_edges with 10 cells"),
        ({"cfl": 0.0}, "cfl must be positive"),
        ({"cfl": 1.5}, r"cfl must lie in \(0, 1\]"),
        ({"left": np.nan}, "left must be finite"),
        ({"right": "1"}, "right must be a real number"),
        ({"flux": ScalarFlux(np.sin, np.cos, 0.0, "concave")}, "flux must be BURGERS or CONCAVE"),
    ],
)
def test_godunov_rejects_bad_input(kwargs, message):
    arguments = {"flux": BURGERS, "u0": U0, "x_edges": EDGES, "t": 0.1} | kwargs
    with pytest.raises(ValueError, match=message):
        godunov(**arguments)


def test_bad_fluxes_and_overflow_are_refused():
    with pytest.raises(TypeError, match="flux must be a ScalarFlux"):
        godunov("burgers", U0, EDGES, 0.1)
    with pytest.raises(TypeError, match="flux must be a ScalarFlux"):
        godunov_flux(burgers_flux, 0.0, 1.0)
    with pytest.raises(ValueError, match="shape must be one of"):
        ScalarFlux(burgers_flux, np.asarray, 0.0, "linear")
    with pytest.raises(ValueError, match="extremum must be finite"):
        ScalarFlux(burgers_flux, np.asarray, np.inf, "convex")
    with pytest.raises(TypeError, match="derivative must be callable"):
        ScalarFlux(burgers_flux, None, 0.0, "convex")
    with pytest.raises(ValueError, match="lo must not exceed hi"):
        BURGERS.max_speed(1.0, 0.0)
    with pytest.raises(ValueError, match="left contains NaN"):
        godunov_flux(BURGERS, [0.0, np.nan], [1.0, 1.0])
    with pytest.raises(ValueError, match="left and right must broadcast"):
        godunov_flux(BURGERS, [0.0, 1.0], [1.0, 1.0, 1.0])
    with pytest.raises(ValueError, match="the flux overflowed"):
        godunov(BURGERS, np.full(10, 1e200), EDGES, 1e-300)


def test_step_cdf_functions_reject_bad_input():
    with pytest.raises(ValueError, match="points must be sorted"):
        cell_averages_of_step_cdf([1.0, 0.0], EDGES)
    with pytest.raises(ValueError, match="points must contain at least one"):
        cell_averages_of_step_cdf([], EDGES)
    with pytest.raises(ValueError, match="x_edges must be strictly increasing"):
        cell_averages_of_step_cdf([0.5], [0.0, 1.0, 1.0])
    with pytest.raises(ValueError, match="values has 9 cells but x_edges has 11 edges"):
        l1_distance_to_step_cdf(U0[:-1], EDGES, [0.5])
    with pytest.raises(ValueError, match="values contains NaN"):
        l1_distance_to_step_cdf(np.r_[U0[:-1], np.nan], EDGES, [0.5])
    with pytest.raises(ValueError, match="points contains NaN"):
        l1_distance_to_step_cdf(U0, EDGES, [0.5, np.nan])


def test_the_package_resolves_its_names_lazily():
    """Every name of ``__all__`` resolves; importing the scalar scheme loads neither the p-system's schemes
    nor scipy.optimize (the Riemann solutions), in a fresh interpreter."""
    import subprocess
    import sys

    import particle_methods.finite_volume as fv

    assert all(getattr(fv, name) is not None for name in fv.__all__)
    with pytest.raises(AttributeError, match="no attribute"):
        fv.no_such_scheme  # noqa: B018
    code = ("import sys; import particle_methods.finite_volume.scalar; "
            "print('particle_methods.finite_volume.psystem' in sys.modules or 'scipy.optimize' in sys.modules)")
    loaded = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert loaded.strip() == "False"


def test_cfl_time_step_is_the_step_godunov_takes():
    """Three of its steps land on 3 dt in three steps; a flux that moves no state in the range has no step."""
    edges = np.linspace(-1.0, 1.0, 33)
    u0 = np.clip(np.linspace(-0.2, 1.2, 32), 0.0, 1.0)
    dt = cfl_time_step(CONCAVE, 0.0, 1.0, edges[1] - edges[0], 0.9)
    assert godunov(CONCAVE, u0, edges, 3 * dt, cfl=0.9, left=0.0, right=1.0, return_steps=True)[1] == 3
    with pytest.raises(ValueError, match="no time step"):
        cfl_time_step(CONCAVE, 0.5, 0.5, 0.1)
    with pytest.raises(ValueError, match="dx"):
        cfl_time_step(CONCAVE, 0.0, 1.0, -0.1)


def test_extreme_states_are_refused_by_the_parameter_they_come_from():
    """Issue 46 (census): overflows and ranges name the argument that caused them."""
    from particle_methods.finite_volume.grids import check_cell_steps, check_cells_match, l1_between_cell_functions
    from particle_methods.finite_volume.riemann import Wave

    with pytest.raises(ValueError, match="^left: the Burgers flux"):
        godunov_flux(BURGERS, [1e300, 0.0], [0.0, 0.0])
    with pytest.raises(ValueError, match="^right: the Burgers flux"):
        godunov_flux(BURGERS, [0.0, 0.0], [0.0, -1.7e308])
    with pytest.raises(ValueError, match="values_a - values_b"):
        l1_between_cell_functions(np.full(10, -1.7e308), EDGES, np.full(10, 1.7e308), EDGES)
    with pytest.raises(ValueError, match="low must not exceed high"):
        cfl_time_step(BURGERS, 1e300, 1.0, 0.1)
    with pytest.raises(ValueError, match=r"dx = 0.1 is too large for the speed .* in \[low, high\]"):
        cfl_time_step(BURGERS, 0.0, 5e-324, 0.1)  # cfl dx / 5e-324 overflows: was inf
    with pytest.raises(ValueError, match="lower the speeds of u0 and the ghost states left, right"):
        godunov(BURGERS, U0, EDGES, 0.1, left=1e300)
    with pytest.raises(TypeError, match="left must be a real number"):
        godunov(BURGERS, U0, EDGES, 0.1, left="1")
    with pytest.raises(ValueError, match="f\\(extremum\\) is not finite"):
        ScalarFlux(lambda u: np.full(np.shape(u), np.nan), np.asarray, 0.0, "convex")
    with pytest.raises(TypeError, match="derivative\\(extremum\\) failed"):
        ScalarFlux(burgers_flux, lambda u: None, 0.0, "convex")
    with pytest.raises(TypeError, match="cells must be an integer"):
        check_cell_steps(0.1, 0.01, None, 1000)
    with pytest.raises(ValueError, match="dt must be finite"):
        check_cell_steps(0.1, np.nan, 10, 1000)
    with pytest.raises(ValueError, match="more than the limit of 3e\\+00 cell updates"):
        check_cell_steps(0.1, 0.01, 10, 3)
    with pytest.raises(TypeError, match="u0 must be an array"):
        check_cells_match("u0", None, EDGES)
    with pytest.raises(ValueError, match="u0 must be an array of cell values"):
        check_cells_match("u0", 3.0, EDGES)
    with pytest.raises(ValueError, match="family must be 1 or 2"):
        Wave(None, 0.0, 0.0)
    with pytest.raises(ValueError, match="left_edge must be finite"):
        Wave(1, np.nan, 0.0)
    with pytest.raises(TypeError, match="right_edge must be a real number"):
        Wave(2, 0.0, "1")


def test_godunov_takes_one_step_when_the_speeds_underflow():
    """Speeds of 5e-324: cfl dx / speed overflows, yet one step of length t keeps the CFL condition."""
    u0 = np.full(10, 5e-324)
    np.testing.assert_array_equal(godunov(BURGERS, u0, EDGES, 0.1), u0)
