"""W1 distances to the exact solution: the exact step-function integral of norms.l1_to_step_function, and the
wrappers of cross.distances for point masses, finite-volume cells and smooth particle reconstructions, each
against a scipy quadrature of |F - F_h| or a distance known in closed form."""

import math

import numpy as np
import pytest
from scipy import integrate, optimize

from particle_methods.cross import distances, methods
from particle_methods.cross.exact import AggregationSolution
from particle_methods.norms import l1_to_step_function, tail_integrals, w1_to_measure
from particle_methods.sticky import ConcaveLaplaceSolution

CASES = [("smooth20", 0.5), ("smooth20", 1.1), ("indicator", 0.6), ("indicator", 1.5), ("smooth10", 1.3),
         ("laplace", 1.0), ("laplace", 3.0)]


def kinks(solution):
    """Where F is not smooth: the support ends and 0 (the Dirac mass)."""
    return {0.0, solution.left_end, -solution.left_end} - {-math.inf, math.inf}


def quad_l1(solution, step, low, high, extra=()):
    """int_low^high |F - step| by quad, split at the kinks of F and at ``extra``."""
    cuts = sorted({low, high, *[k for k in (*kinks(solution), *extra) if low < k < high]})
    return sum(integrate.quad(lambda x: abs(float(solution.cdf(x)) - step(x)), a, b, epsabs=1e-13, epsrel=1e-12,
                              limit=200)[0] for a, b in zip(cuts[:-1], cuts[1:]))


def quad_step_distance(solution, breaks, values):
    """int_R |F - S| for the step function S of l1_to_step_function, by quad piece by piece and the two tails."""
    mass = solution.mass
    reach = 40.0 if math.isinf(solution.profile.radius) else 1.0
    total = quad_l1(solution, lambda x: 0.0, min(-reach, breaks[0]), breaks[0])
    total += quad_l1(solution, lambda x: mass, breaks[-1], max(reach, breaks[-1]))
    for a, b, s in zip(breaks[:-1], breaks[1:], values[:-1]):
        if b > a:
            crossing = float(solution.quantile(s)) if 0.0 < s < mass else a
            total += quad_l1(solution, lambda x, s=s: s, a, b, extra=(crossing,))
    return total


def random_step_function(rng, mass, size):
    """Breaks in [-1.5, 1.5] with repeats (and 0, where the Dirac mass sits); values in [0, M] with exact 0s
    and Ms, not monotone, the first 0 and the last M."""
    breaks = np.sort(np.concatenate([rng.uniform(-1.5, 1.5, size), [0.0]]))
    breaks = np.sort(np.concatenate([breaks, rng.choice(breaks, 3)]))  # repeated breaks
    values = rng.uniform(0.0, mass, breaks.size)
    values[rng.choice(breaks.size, 3)] = rng.choice([0.0, mass], 3)
    values[0], values[-1] = 0.0, mass
    return breaks, values


@pytest.mark.parametrize(("data", "t"), CASES)
def test_l1_to_step_function_equals_quad_on_random_step_functions(data, t, rng):
    solution = AggregationSolution(data, t)
    for size in (1, 6):
        breaks, values = random_step_function(rng, solution.mass, size)
        exact = l1_to_step_function(solution, breaks, values)
        assert exact == pytest.approx(quad_step_distance(solution, breaks, values), abs=1e-10)


@pytest.mark.parametrize(("data", "t"), [*CASES, ("smooth20", 0.0), ("indicator", 0.0), ("laplace", 0.0)])
def test_l1_to_step_function_against_one_dirac_mass_is_the_first_absolute_moment(data, t):
    """S = M from 0 on (M delta_0): the distance is int |x| d rho = -2 G(M/2) (symmetric data), and at t = 0
    int |x| rho0 by quad."""
    solution = AggregationSolution(data, t)
    moment = -2.0 * float(solution.quantile_integral(0.5 * solution.mass))
    assert l1_to_step_function(solution, [0.0], [solution.mass]) == pytest.approx(moment, rel=1e-13, abs=1e-16)
    # breaks to the left where S = 0 change nothing
    assert l1_to_step_function(solution, [-3.0, -1.0, 0.0], [0.0, 0.0, solution.mass]) == pytest.approx(
        moment, rel=1e-13, abs=1e-16)
    if t == 0.0:
        reach = 40.0 if math.isinf(solution.profile.radius) else 1.0
        by_quad = 2.0 * integrate.quad(lambda x: x * float(solution.profile.density(x)), 0.0, reach,
                                       epsabs=1e-14)[0]
        assert moment == pytest.approx(by_quad, abs=1e-12)


@pytest.mark.parametrize("t", [0.5, 2.5, 4.0])
def test_l1_to_step_function_equals_w1_to_measure_for_unit_mass(t, rng):
    points = np.sort(rng.laplace(size=200))
    points[50:53] = points[50]  # repeated positions
    levels = np.arange(1, points.size + 1) / points.size
    for measure in (ConcaveLaplaceSolution(t), AggregationSolution("laplace", t)):
        assert l1_to_step_function(measure, points, levels) == pytest.approx(w1_to_measure(measure, points),
                                                                             rel=1e-12, abs=1e-15)


def test_l1_to_step_function_refuses_a_last_value_other_than_the_mass():
    solution = AggregationSolution("indicator", 0.5)
    l1_to_step_function(solution, [0.0, 1.0], [1.0, 2.0 * (1 + 1e-10)])  # within 1e-9 relative
    for last in (1.9, 2.1, 0.0):
        with pytest.raises(ValueError, match="values"):
            l1_to_step_function(solution, [0.0, 1.0], [1.0, last])
    with pytest.raises(ValueError, match="breaks"):
        l1_to_step_function(solution, [1.0, 0.0], [1.0, 2.0])
    with pytest.raises(ValueError, match="values"):
        l1_to_step_function(solution, [0.0, 1.0], [2.0])


@pytest.mark.parametrize(("data", "t"), CASES)
def test_w1_atoms_does_not_depend_on_the_order_of_the_atoms(data, t, rng):
    solution = AggregationSolution(data, t)
    positions = np.round(rng.uniform(-1.0, 1.0, 40), 1)  # many coinciding atoms
    masses = rng.uniform(0.0, 1.0, positions.size)
    masses[[3, 7]] = 0.0
    masses *= solution.mass / masses.sum()
    reference = distances.w1_atoms(solution, positions, masses)
    order = np.argsort(positions, kind="stable")
    breaks, levels = positions[order], np.cumsum(masses[order])
    assert reference == pytest.approx(l1_to_step_function(solution, breaks, levels), abs=1e-15)
    assert reference == pytest.approx(quad_step_distance(solution, breaks, levels), abs=1e-10)
    for _ in range(3):
        shuffle = rng.permutation(positions.size)
        assert distances.w1_atoms(solution, positions[shuffle], masses[shuffle]) == pytest.approx(reference,
                                                                                                  abs=1e-15)


def test_w1_atoms_of_the_dirac_masses_of_the_collapsed_indicator_is_zero():
    solution = AggregationSolution("indicator", 1.5)
    assert distances.w1_atoms(solution, [0.0], [2.0]) == 0.0
    assert distances.w1_atoms(solution, [0.0, 0.0], [0.5, 1.5]) == 0.0
    assert distances.w1_atoms(solution, [0.25], [2.0]) == pytest.approx(0.5, abs=1e-15)  # M times the shift


def test_w1_atoms_refusals():
    solution = AggregationSolution("smooth20", 0.5)
    with pytest.raises(ValueError, match="masses"):
        distances.w1_atoms(solution, [0.0, 1.0], [solution.mass])
    with pytest.raises(ValueError, match="masses"):
        distances.w1_atoms(solution, [0.0, 1.0], [-0.1, solution.mass + 0.1])
    with pytest.raises(ValueError, match="masses must add up"):
        distances.w1_atoms(solution, [0.0, 1.0], [0.1, 0.1])
    with pytest.raises(ValueError, match="positions"):  # x F(x) would overflow
        distances.w1_atoms(AggregationSolution("indicator", 0.5), [1.7e308], [2.0])
    with pytest.raises(TypeError, match="solution"):
        distances.w1_atoms("smooth20", [0.0], [solution.mass])


@pytest.mark.parametrize(("data", "t"), CASES)
def test_w1_cells_equals_quad_of_the_cell_values(data, t, rng):
    solution = AggregationSolution(data, t)
    edges = np.linspace(-1.0, 1.0, 9)
    values = np.sort(rng.uniform(0.0, solution.mass, edges.size - 1))
    values[3] = solution.mass * 0.5

    def step(x):
        if x < edges[0]:
            return 0.0
        if x >= edges[-1]:
            return solution.mass
        return values[min(np.searchsorted(edges, x, side="right") - 1, values.size - 1)]

    reach = 40.0 if math.isinf(solution.profile.radius) else 1.0
    crossings = [float(solution.quantile(v)) for v in values if 0.0 < v < solution.mass]
    expected = quad_l1(solution, step, -reach, reach, extra=(*edges, *crossings))
    assert distances.w1_cells(solution, edges, values) == pytest.approx(expected, abs=1e-10)


def test_w1_cells_of_the_godunov_scheme_equals_quad():
    solution = AggregationSolution("smooth20", 0.5)
    edges, values = methods.godunov_mass("smooth20", 16, 0.5)
    crossings = [float(solution.quantile(v)) for v in values if 0.0 < v < solution.mass]

    def step(x):  # cell i of width 1/8 holds values[i]; 0 left of the grid, M right of it
        return 0.0 if x < -1.0 else solution.mass if x >= 1.0 else values[min(int((x + 1.0) * 8), 15)]

    expected = quad_l1(solution, step, -1.0, 1.0, extra=(*edges, *crossings))
    assert distances.w1_cells(solution, edges, values) == pytest.approx(expected, abs=1e-10)


def test_w1_cells_refusals():
    solution = AggregationSolution("smooth20", 0.5)
    with pytest.raises(ValueError, match="edges"):
        distances.w1_cells(solution, [0.0, -1.0], [0.1])
    with pytest.raises(ValueError, match="one value per cell"):
        distances.w1_cells(solution, [0.0, 1.0], [0.1, 0.2])


@pytest.mark.parametrize("data", ["smooth20", "indicator", "smooth10"])
@pytest.mark.parametrize("shift", [1e-3, 0.1, 0.7])
def test_w1_smooth_of_the_shifted_exact_solution_is_shift_times_mass(data, shift):
    """Before the blow-up F is continuous; F(x - s) is the solution moved by s, at W1 exactly s M."""
    solution = AggregationSolution(data, 0.5)
    ends = [solution.left_end + shift, shift, -solution.left_end + shift]

    def moved(x):
        return solution.cdf(np.asarray(x) - shift)

    assert distances.w1_smooth(solution, moved, ends, 0.05) == pytest.approx(shift * solution.mass, rel=1e-12)


def test_w1_smooth_of_the_exact_solution_itself_is_zero():
    solution = AggregationSolution("smooth20", 0.5)
    breaks = [solution.left_end, 0.0, -solution.left_end]
    assert distances.w1_smooth(solution, solution.cdf, breaks, 0.05) < 1e-16


def smooth_pieces_quad(solution, cumulative, knots):
    """int |F - F_h| by quad on the pieces between ``knots`` and the sign changes of F - F_h (located by brentq
    on a dense sampling), where the integrand is smooth."""

    def difference(x):
        return float(solution.cdf(x)) - float(cumulative(np.array([x]))[0])

    cuts = [knots[0]]
    for a, b in zip(knots[:-1], knots[1:]):
        samples = np.linspace(a, b, 17)
        values = solution.cdf(samples) - cumulative(samples)
        for i in np.flatnonzero(values[:-1] * values[1:] < 0):
            cuts.append(optimize.brentq(difference, samples[i], samples[i + 1], xtol=1e-15, rtol=1e-15))
        cuts.append(b)
    # (pieces between knots that differ by rounding, |F - F_h| times 1e-12 at most, are left out)
    return sum(abs(integrate.quad(difference, a, b, epsabs=1e-14, epsrel=1e-12, limit=50)[0])
               for a, b in zip(cuts[:-1], cuts[1:]) if b - a > 1e-12)


@pytest.mark.parametrize(("method", "eps", "t"), [("ltp", None, 0.5), ("sp", 0.1, 1.1)])
def test_w1_smooth_of_ltp_particles_equals_a_dense_quad(method, eps, t):
    h = 0.1
    particles = methods.ltp_method("smooth20", h, h / 2, t, method=method, eps=eps)
    solution = AggregationSolution("smooth20", t)
    # every knot of F_h: the centres plus widths times the knots -2, -1, 0, 1, 2 of the B3 shape
    knots = np.unique(particles.centres[:, None] + particles.widths[:, None] * particles.shape.breaks[None, :])
    measured = distances.w1_smooth(solution, particles.cumulative_mass, knots, particles.widths.min())
    reference = np.union1d(knots, sorted(k for k in kinks(solution) if knots[0] < k < knots[-1]))
    expected = smooth_pieces_quad(solution, particles.cumulative_mass, reference)
    expected += sum(tail_integrals(solution, knots[0], knots[-1]))
    assert measured == pytest.approx(expected, rel=1e-11)
    assert 0.0 < measured < 0.05
    assert distances.w1_particles(solution, particles) == measured  # the scripts' helper: the same knots
    # With the support ends only as breaks (as scripts/cross/study_data.py passes them) the Gauss rule crosses
    # the interior knots, where F_h is only C^3: still within 1e-7 relative.
    ends = np.union1d(particles.centres - 2.0 * particles.widths, particles.centres + 2.0 * particles.widths)
    coarse = distances.w1_smooth(solution, particles.cumulative_mass, ends, particles.widths.min())
    assert coarse == pytest.approx(expected, rel=1e-7)


def test_w1_smooth_refusals():
    solution = AggregationSolution("smooth20", 0.5)
    with pytest.raises(TypeError, match="cumulative"):
        distances.w1_smooth(solution, None, [0.0, 1.0], 0.1)
    with pytest.raises(ValueError, match="breaks"):
        distances.w1_smooth(solution, solution.cdf, [0.0], 0.1)
    with pytest.raises(ValueError, match="largest"):
        distances.w1_smooth(solution, solution.cdf, [0.0, 1.0], 0.0)
    with pytest.raises(ValueError, match="pieces"):
        distances.w1_smooth(solution, solution.cdf, [0.0, 1.0], 1e-9)


def test_issue_46_w1_smooth_names_cumulative_and_breaks():
    solution = AggregationSolution("smooth20", 0.5)
    with pytest.raises(ValueError, match="cumulative returned NaN"):
        distances.w1_smooth(solution, lambda x: np.full(x.shape, np.nan), [-1.5, 0.0, 1.5], 0.5)
    with pytest.raises(ValueError, match="the breaks' span"):
        distances.w1_smooth(solution, solution.cdf, [-1.5e300, 0.0, 1.5e300], 0.5)
