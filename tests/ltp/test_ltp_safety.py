"""Safe API of particle_methods.ltp (issue "safe API"): the reviewer's failures and property-based fuzzing.

Every public entry point gets bad values (None, strings, complex, object arrays, NaN, inf, huge
integers, wrong shapes) and extreme ones through :func:`fuzzing.safe_call`: it must return finite
results or raise ValueError/TypeError with a message, within the watchdog's time.
"""

import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from particle_methods.ltp import (
    B3,
    HAT,
    InitialDensity,
    Particles,
    Potential,
    Shape,
    density_named,
    exact_density,
    exact_support,
    grid_particles,
    hat_biorthogonal_kernel,
    kernels,
    measures,
    potential,
    shape_named,
    simulate,
)
from particle_methods.ltp.checks import MAX_PARTICLES
from particle_methods.ltp.solver import MAX_PAIRS, MAX_RECORDED, MAX_STEPS
from particle_methods.validation import ParameterTypeError

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from fuzzing import FUZZ, Later, bad_array, bad_scalar, built, extreme, safe_call, watchdog

RHO1, RHO2, RHO3 = (density_named(name) for name in ("rho1", "rho2", "rho3"))
QUADRATIC = potential("quadratic")
POTENTIALS = [QUADRATIC, potential("power", a=1.5), potential("attractive_repulsive", a=3, b=1.1),
              Potential("repulsive x^2/2", (-1.0,), (2.0,)), potential("newtonian")]
RUN = {"initial": "rho2", "potential": potential("power", a=1.5), "h": 0.25, "dt": 0.05, "t_final": 0.1}
SIM = Later(lambda: simulate(**RUN, record_every=1))  # built on first use (fuzzing.Later)

short_arrays = st.lists(extreme | st.floats(-2, 2), min_size=1, max_size=3).map(np.array)
any_value = bad_scalar | bad_array | extreme


def assert_finite_run(sim):
    for values in (sim.centres, sim.widths, sim.velocities, sim.times):
        assert np.all(np.isfinite(values))
    assert np.all(sim.widths > 0)


# The reviewer's failures.


def test_mismatched_particle_arrays_are_refused_before_the_kernels():
    centres, weights, widths = np.linspace(-1, 1, 2000), np.full(3, 0.3), np.full(2000, 0.01)
    with pytest.raises(ValueError, match="mismatched array lengths: centres has 2000, weights has 3"):
        Particles(centres, weights, widths, B3)
    x = np.linspace(-1, 1, 5)
    with pytest.raises(ValueError, match="weights has 3"):
        kernels.density_at(x, centres, weights, widths, B3.breaks, B3.coefficients)
    with pytest.raises(ValueError, match="weights has 3"):
        kernels.cumulative_mass_at(x, centres, weights, widths, B3.breaks, B3.coefficients)
    with pytest.raises(ValueError, match="weights has 3"):
        kernels.convolutions(x, centres, weights, widths, *QUADRATIC.as_arrays(), B3.breaks, B3.coefficients)


def test_exact_density_refuses_a_time_beyond_the_double_range():
    with pytest.raises(ValueError, match="t = 1000 is too large"):
        exact_density(RHO1, QUADRATIC, 1e3, [0.0])
    assert np.all(np.isfinite(exact_density(RHO1, QUADRATIC, 300.0, np.linspace(-1, 1, 11))))


def test_exact_density_refuses_none():
    with pytest.raises(ParameterTypeError, match="x must be an array of real numbers"):
        exact_density(RHO1, QUADRATIC, 0.5, None)


def test_a_step_beyond_the_stability_bound_is_refused():
    """W = x^2 (c = 2, unit mass): explicit Euler keeps the particles in order for dt < 1/2."""
    with pytest.raises(ValueError, match=r"dt = 10 exceeds the stability bound .* = 0\.5 .* at step 0"):
        simulate("rho1", QUADRATIC, 0.2, 10.0, 50.0)
    with pytest.raises(ValueError, match=r"dt = 0\.6 exceeds the stability bound"):
        simulate("rho1", QUADRATIC, 0.2, 0.6, 1.2)
    assert_finite_run(simulate("rho1", QUADRATIC, 0.2, 0.45, 0.9))


def test_the_bound_accepts_figure_5_up_to_just_before_the_collapse():
    """config.yaml's Figure 5 run (a = 1.5, dt = 0.01 to t = 2, there with h = 0.01): dt max W'' * rho_h reaches
    0.7 at its last update, 1.17 at t = 2 for every h; one step more is refused as the collapse."""
    w = potential("power", a=1.5)
    assert_finite_run(simulate("rho2", w, 0.05, 0.01, 2.0))
    with pytest.raises(ValueError, match=r"at step 200 \(t = 2\): the particles collapse"):
        simulate("rho2", w, 0.05, 0.01, 2.01)


@pytest.mark.parametrize("dt, t_final", [(1e-300, 1.0), (0.1, 1e9), (5e-324, 1e308)])
def test_too_many_steps_are_refused_at_once(dt, t_final):
    with watchdog(5.0), pytest.raises(ValueError, match=f"beyond the limit MAX_STEPS = {MAX_STEPS}"):
        simulate("rho1", QUADRATIC, 0.2, dt, t_final)


def test_power_exponent_must_be_a_number():
    with pytest.raises(ParameterTypeError, match="a must be a real number, got '2'"):
        potential("power", "2")
    with pytest.raises(ValueError, match="takes no exponent a"):
        potential("quadratic", a=3.0)


@pytest.mark.parametrize("h", [1e-300, 5e-324, 1e-5])
def test_too_many_particles_are_refused(h):
    with pytest.raises(ValueError, match=f"h = .* particles .* beyond the limit MAX_PARTICLES = {MAX_PARTICLES}"):
        simulate("rho1", QUADRATIC, h, 0.1, 1.0)


def test_pair_and_record_limits():
    with pytest.raises(ValueError, match="beyond the limit MAX_PAIRS"):
        simulate("rho1", potential("power", a=1.5), 0.001, 1e-4, 10.0)
    with pytest.raises(ValueError, match="beyond the limit MAX_RECORDED"):
        simulate("rho1", QUADRATIC, 0.0005, 1e-3, 100.0, record_every=1)
    assert MAX_PAIRS > 250 * 803**2 and MAX_RECORDED > 601 * 201  # the repository's largest runs


def test_wrong_types_are_named():
    sim = built(SIM)
    with pytest.raises(ParameterTypeError, match="initial must be of type InitialDensity, got None"):
        simulate(None, QUADRATIC, 0.1, 0.1, 0.2)
    with pytest.raises(ParameterTypeError, match="initial must be of type InitialDensity"):
        exact_density(None, QUADRATIC, 0.1, [0.0])
    with pytest.raises(ParameterTypeError, match="h must be a real number"):
        simulate("rho1", QUADRATIC, 0.1 + 1j, 0.1, 0.2)
    with pytest.raises(ParameterTypeError, match="x must hold real numbers, got dtype complex"):
        sim.at(-1).density(np.array([0.1 + 1j]))
    with pytest.raises(ParameterTypeError, match="index must be an integer"):
        sim.at(1.0)
    with pytest.raises(ValueError, match="index must lie in"):
        sim.at(sim.steps.size)


def test_second_derivative_is_not_returned_infinite():
    with pytest.raises(ValueError, match="x must not contain 0"):
        potential("power", a=1.5).second_derivative([0.0, 1.0])


def test_a_custom_shape_must_have_unit_mass_and_mean_zero():
    with pytest.raises(ValueError, match="unit mass and mean 0"):
        Shape("wide", np.array([-1.0, 1.0]), np.array([[1.0, 0.0, 0.0, 0.0]]))
    assert Shape("box", np.array([-0.5, 0.5]), np.array([[1.0, 0.0, 0.0, 0.0]]))(0.2) == 1.0


# Property-based fuzzing: one bad value at a time in an otherwise valid call, and valid but extreme calls.


def one_bad(function, valid: dict, name: str, value):
    """``function(**valid)`` with the argument ``name`` replaced by ``value``: finite or refused."""
    return safe_call(function, **{**valid, name: value})


@FUZZ
@given(any_value)
def test_fuzz_names(value):
    for function in (density_named, shape_named, potential):
        assert safe_call(function, value) is None


@FUZZ
@given(st.sampled_from(["quadratic", "half_quadratic", "newtonian", "power", "attractive_repulsive"]),
       st.sampled_from(["a", "b"]), st.none() | any_value)
def test_fuzz_potential_parameters(kind, name, value):
    one_bad(potential, {"kind": kind, "a": 3.0, "b": 1.5}, name, value)
    one_bad(Potential, {"name": "fuzzed", "coefficients": (1.0, -1.0), "exponents": (3.0, 1.5)},
            "coefficients" if name == "a" else "exponents", value)


@FUZZ
@given(extreme | st.floats(1.0, 5.0), extreme | st.floats(1.0, 5.0), bad_array | short_arrays)
def test_fuzz_potential_values(a, b, x):
    for w in (safe_call(potential, "power", a), safe_call(potential, "attractive_repulsive", a, b)):
        if w is not None:
            for method in (w, w.derivative, w.second_derivative):
                safe_call(method, x)


@FUZZ
@given(any_value | short_arrays, bad_array | short_arrays)
def test_fuzz_shapes(breaks, x):
    assert safe_call(Shape, "fuzzed", breaks, B3.coefficients) is None
    for function in (HAT, B3, hat_biorthogonal_kernel):
        safe_call(function, x)


@FUZZ
@given(bad_scalar | extreme | st.floats(-2.0, 2.0), bad_scalar | extreme | st.floats(-2.0, 2.0),
       extreme | st.floats(0.01, 1.0))
def test_fuzz_initial_density(lower, upper, h):
    density = safe_call(InitialDensity, "fuzzed", RHO2.pdf, RHO2.cdf, lower, upper)
    if density is not None:
        safe_call(lambda: density.mean)
        safe_call(grid_particles, density, h, HAT)


@FUZZ
@given(st.sampled_from(["density", "h", "shape", "weights", "offset"]), any_value | short_arrays)
def test_fuzz_grid_particles_bad(name, value):
    one_bad(grid_particles, {"density": RHO1, "h": 0.1, "shape": HAT, "weights": "biorthogonal", "offset": 0.5}, name,
            value)


@FUZZ
@given(st.sampled_from([RHO1, RHO2, RHO3]), extreme | st.floats(0.01, 2.0), st.sampled_from(["cell", "biorthogonal"]))
def test_fuzz_grid_particles_extreme(density, h, weights):
    safe_call(grid_particles, density, h, HAT, weights)


@FUZZ
@given(st.sampled_from(["initial", "potential", "t", "x"]), any_value | short_arrays)
def test_fuzz_exact_bad(name, value):
    valid = {"initial": RHO1, "potential": QUADRATIC, "t": 0.5}
    one_bad(exact_density, {**valid, "x": [0.0, 0.3]}, name, value)
    if name != "x":
        one_bad(exact_support, valid, name, value)


@FUZZ
@given(st.sampled_from([RHO1, RHO2, RHO3]), st.sampled_from([QUADRATIC, potential("half_quadratic"), POTENTIALS[-1]]),
       extreme | st.floats(0.0, 1e3), short_arrays)
def test_fuzz_exact_extreme(initial, w, t, x):
    safe_call(exact_density, initial, w, t, x)
    safe_call(exact_support, initial, w, t)


triples = st.lists(extreme | st.floats(-2, 2), min_size=3, max_size=3).map(np.array)


@FUZZ
@given(triples, triples, triples.map(np.abs) | bad_array, bad_array | short_arrays, st.sampled_from(POTENTIALS))
def test_fuzz_particles(centres, weights, widths, x, w):
    particles = safe_call(Particles, centres, weights, widths, B3)
    if particles is not None:
        safe_call(particles.density, x)
        safe_call(particles.cumulative_mass, x)
        safe_call(particles.convolutions, w, x)
        safe_call(particles.convolutions, w)
        safe_call(lambda: particles.mass)
        safe_call(lambda: particles.centre_of_mass)


@FUZZ
@given(st.sampled_from(["centres", "weights", "widths", "shape"]), any_value | short_arrays)
def test_fuzz_particles_bad(name, value):
    final = built(SIM).at(-1)
    valid = {"centres": final.centres, "weights": final.weights, "widths": final.widths, "shape": B3}
    assert one_bad(Particles, valid, name, value) is None


@FUZZ
@given(st.integers(0, 7), st.integers(0, 5), any_value | short_arrays)
def test_fuzz_kernels(convolution_argument, density_argument, value):
    particles = built(SIM).at(-1)
    arrays = [particles.centres, particles.weights, particles.widths]
    shape = [B3.breaks, B3.coefficients]
    convolution_arguments = [particles.centres, *arrays, *RUN["potential"].as_arrays(), *shape]
    convolution_arguments[convolution_argument] = value
    safe_call(kernels.convolutions, *convolution_arguments)
    density_arguments = [particles.centres, *arrays, *shape]
    density_arguments[density_argument] = value
    safe_call(kernels.density_at, *density_arguments)
    safe_call(kernels.cumulative_mass_at, *density_arguments)


@FUZZ
@given(st.sampled_from(["method", "shape", "potential", "h", "dt", "steps", "times", "weights", "centres", "widths",
                        "velocities"]), any_value | short_arrays, any_value | st.integers(-10, 10),
       bad_array | short_arrays)
def test_fuzz_simulation(field, value, index, x):
    sim = built(SIM)
    safe_call(replace, sim, **{field: value})
    safe_call(sim.at, index)
    safe_call(sim.densities, x)
    safe_call(sim.peak_densities)


@FUZZ
@given(st.sampled_from(["initial", "potential", "h", "dt", "t_final", "shape", "weights", "method", "eps",
                        "record_every", "log", "offset"]), any_value | short_arrays)
def test_fuzz_simulate_bad(name, value):
    sim = one_bad(simulate, RUN, name, value)
    if sim is not None:
        assert_finite_run(sim)


@FUZZ
@given(st.sampled_from(["rho1", "rho2", "rho3"]), st.sampled_from(POTENTIALS), extreme | st.floats(0.05, 2.0),
       extreme | st.sampled_from([0.01, 0.1, 0.4, 1.0, 10.0]), st.integers(0, 4),
       st.sampled_from([{}, {"method": "sp", "eps": 0.1}, {"method": "sp", "eps": 1e-300}, {"shape": "hat"}]))
def test_fuzz_simulate_extreme(initial, w, h, dt, steps, options):
    sim = safe_call(simulate, initial, w, h, dt, steps * dt, **options)
    if sim is not None:
        assert_finite_run(sim)


@FUZZ
@given(bad_array | short_arrays, bad_scalar | extreme)
def test_fuzz_measures_bad(values, number):
    """The measures of section 6.2 refuse bad input (their own tests cover valid runs)."""
    times = np.linspace(0.0, 1.0, 11)
    safe_call(measures.shrink_rate_inverse, times, values)
    safe_call(measures.collapse_times, times, np.exp(-times), values)
    safe_call(measures.side_concentration, np.array([-1.0, 1.0]), np.ones(2), values, number, 0.1)
    safe_call(measures.peak_count, values, number)
    safe_call(measures.excess_variation, values, values)
    safe_call(measures.shrink_rate_ratios, times, np.exp(-times), number, number, number)
    safe_call(measures.concentration_series, values, 0.5, number)


def test_a_decreasing_user_cdf_is_refused_before_the_run():
    # Its cell weights (2.14), the CDF's increments, are negative: the run had a total mass of -2.3 before.
    from particle_methods.ltp import potential, simulate
    from particle_methods.ltp.initial import InitialDensity

    with pytest.raises(ValueError, match="cdf must give finite non-decreasing values"):  # at its construction
        InitialDensity("decreasing", lambda x: np.ones_like(x), lambda x: -x, -1.0, 1.0)
    dipping = InitialDensity("dipping", lambda x: np.ones_like(x),  # increases from lower to upper, dips between
                             lambda x: 0.5 * (x + 1.0) - 0.4 * np.sin(np.pi * x), -1.0, 1.0)
    with pytest.raises(ValueError, match="CDF of dipping decreases"):
        simulate(dipping, potential("quadratic"), 0.1, 0.01, 0.1)
