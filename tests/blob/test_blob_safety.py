"""Safe API of particle_methods.blob: every public entry point refuses bad input with a message, never
returns NaN or inf, and refuses work beyond its stated limits (issue: safe API).

A property-based suite calls each entry point with one argument replaced by a bad or extreme value
(:mod:`fuzzing`); explicit regression tests cover the failures a reviewer reported.
"""

import math
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from particle_methods import blob
from particle_methods.blob import (
    BlobRun,
    Data1D,
    Data2D,
    Kernel,
    Mollifier,
    blowup_time,
    checks,
    data_1d,
    data_2d,
    grid_1d,
    grid_2d,
    integrate_particles,
    kernel_1d,
    kernel_2d,
    mass_defect,
    mollifier,
    newtonian_exact,
    newtonian_exact_2d,
    run_1d,
    run_2d,
    solver,
    uniform_ring_radius,
)
from particle_methods.blob.aliasing import quadrature_prediction, saddle_ratio
from particle_methods.blob.kernels import POWER

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from fuzzing import FUZZ, Later, bad_array, bad_scalar, built, extreme, safe_call

from particle_replication.paths import read_yaml

ROOT = Path(__file__).resolve().parents[2]
PSI1, PSI2 = mollifier(4, 1), mollifier(4, 2)
CUBIC = kernel_1d("cubic", PSI1, 0.3)
LINE = np.linspace(-1.0, 1.0, 5)[:, None]
SMALL_RUN = Later(lambda: run_1d("smooth20", "cubic", 0.5, [0.0, 0.05]))  # built on first use (fuzzing.Later)

# Valid calls of every public entry point (tiny particle counts, short times); the fuzzing replaces
# one argument at a time. Classes are fuzzed through their constructors, then their methods.
CALLS = {
    "data_1d": (data_1d, {"name": "smooth20"}),
    "data_2d": (data_2d, {"name": "regular"}),
    "grid_1d": (grid_1d, {"h": 0.25}),
    "grid_2d": (grid_2d, {"h": 0.25, "data": "regular"}),
    "Data1D": (lambda **a: Data1D(**a).mass_from_origin(0.5), {"name": "test", "power": 3}),
    "Data1D.moment_from_left": (data_1d("smooth20").moment_from_left, {"x": np.array([-1.0, 0.3, 2.0])}),
    "Data1D.__call__": (data_1d("smooth10").__call__, {"x": np.array([-0.5, 0.0, 2.0])}),
    "Data2D": (lambda **a: Data2D(**a)(np.zeros((1, 2))), {"name": "disk", "radius": 1.0}),
    "Data2D.mass_from_origin": (data_2d("regular").mass_from_origin, {"r": np.array([0.0, 0.5])}),
    "mollifier": (mollifier, {"order": 4, "dimension": 1}),
    "Mollifier": (lambda **a: Mollifier(**a)(0.5, 0.3), {"order": 4, "dimension": 1, "weights": (4 / 3, -1 / 3),
                                                          "widths": (1.0, 2.0)}),
    "Mollifier.__call__": (PSI2.__call__, {"r": np.array([0.0, 0.3]), "delta": 0.2}),
    "kernel_1d": (kernel_1d, {"name": "cubic", "mollifier": PSI1, "delta": 0.3}),
    "kernel_2d": (kernel_2d, {"name": "quartic_power", "mollifier": PSI2, "delta": 0.5, "table_radius": 2.0,
                              "table_points": 41}),
    "Kernel": (lambda **a: Kernel(**a).profile(np.array([0.0, 0.5])),
               {"name": "test", "dimension": 1, "kinds": (POWER,), "coefficients": (1.0,), "parameters": (3.0,)}),
    "Kernel.profile": (CUBIC.profile, {"r": np.array([0.0, 0.1, 2.0])}),
    "uniform_ring_radius": (uniform_ring_radius, {"a": 4.0, "b": 1.5}),
    "quadrature_prediction": (quadrature_prediction, {"data": "smooth10", "h": 0.25, "q": 0.9, "t": 0.5, "order": 4}),
    "saddle_ratio": (saddle_ratio, {"data": "smooth10", "h": 0.25, "q": 0.9, "order": 4}),
    "blowup_time": (blowup_time, {"data": "smooth20", "kernel": "newtonian_attractive"}),
    "newtonian_exact": (newtonian_exact, {"data": "smooth20", "kernel": "newtonian_attractive",
                                          "alpha": np.array([0.1, 0.5]), "t": 0.5}),
    "newtonian_exact_2d": (newtonian_exact_2d, {"data": "regular", "points": np.array([[0.1, 0.2], [0.5, 0.0]]),
                                                "t": 0.3}),
    "integrate_particles": (integrate_particles, {"points": LINE, "densities0": np.ones(5), "masses": np.full(5, 0.1),
                                                  "kernel": CUBIC, "times": np.array([0.0, 0.05]), "rtol": 1e-8,
                                                  "atol": 1e-10}),
    "mass_defect": (mass_defect, {"points": LINE[1:4], "rho0": np.ones(3), "masses": np.full(3, 0.5),
                                  "kernel": CUBIC, "t": 0.05, "offset": 1e-5, "rtol": 1e-8, "atol": 1e-10}),
    "run_1d": (run_1d, {"data": "smooth20", "kernel": "cubic", "h": 0.5, "times": np.array([0.0, 0.05]),
                        "method": "blob", "order": 4, "q": 0.9, "rtol": 1e-8, "atol": 1e-10}),
    "run_1d particle": (run_1d, {"data": "smooth20", "kernel": "newtonian_attractive", "h": 0.5,
                                 "times": np.array([0.0, 0.05]), "method": "particle"}),
    "run_2d": (run_2d, {"data": "regular", "kernel": "newtonian", "h": 0.5, "times": np.array([0.0, 0.05]),
                        "method": "blob", "q": 0.9, "delta": 0.5, "rtol": 1e-8, "atol": 1e-10}),
    "run_2d tabulated": (run_2d, {"data": "regular", "kernel": "cubic", "h": 0.5, "times": np.array([0.0, 0.05]),
                                  "table_radius": 2.0, "table_points": 41}),
    "BlobRun": (lambda **a: BlobRun(**a).energies(), {"kernel": SMALL_RUN.kernel, "h": 0.5, "times": SMALL_RUN.times,
                                                      "positions": SMALL_RUN.positions,
                                                      "densities": SMALL_RUN.densities, "masses": SMALL_RUN.masses,
                                                      "evaluations": 3}),
}


def with_entry(array, index, value):
    changed = array.copy()
    changed.flat[index] = value
    return changed


def replacements(value):
    """Bad values of any kind, and for a float or a float array, extreme values of the same shape."""
    options = [bad_scalar, bad_array]
    if isinstance(value, float):
        options.append(extreme)
    if isinstance(value, np.ndarray):
        options.append(extreme.map(lambda v: np.full_like(value, v)))
        options.append(st.tuples(st.integers(0, value.size - 1), extreme).map(lambda p: with_entry(value, *p)))
    return st.one_of(options)


def assert_finite_run(result):
    if isinstance(result, BlobRun):
        assert np.isfinite(result.positions).all()
        assert result.densities is None or np.isfinite(result.densities).all()


def test_every_public_entry_point_is_fuzzed():
    fuzzed = {name.split(".")[0].split(" ")[0] for name in CALLS}
    errors = {name for name in blob.__all__ if name.endswith("Error")}  # exceptions raised, not called
    assert set(blob.__all__) - errors <= fuzzed


@pytest.mark.parametrize("name", sorted(CALLS))
@FUZZ
@given(data=st.data())
def test_bad_or_extreme_arguments_are_refused_or_give_finite_results(name, data):
    function, valid = CALLS[name][0], built(CALLS[name][1])
    parameter = data.draw(st.sampled_from(sorted(valid)), label="parameter")
    value = data.draw(replacements(valid[parameter]), label="value")
    assert_finite_run(safe_call(function, **{**valid, parameter: value}))


def test_valid_calls_succeed():
    for name, (function, valid) in CALLS.items():
        assert safe_call(function, **built(valid)) is not None, name


# Regression tests: the reviewer's failures.


@pytest.mark.parametrize("masses", [[0.01], np.ones(51)])
def test_masses_of_the_wrong_length_are_refused(masses):
    with pytest.raises(ValueError, match="masses has"):
        integrate_particles(np.linspace(-1, 1, 50)[:, None], np.ones(50), masses, kernel_1d("cubic"), [0, 0.1])


def test_points_must_match_the_kernel_dimension_and_densities_their_count():
    with pytest.raises(ValueError, match=r"points must have shape \(N, 2\)"):
        integrate_particles(LINE, np.ones(5), np.ones(5), kernel_2d("cubic"), [0, 0.1])
    with pytest.raises(ValueError, match="densities0 has 4"):
        integrate_particles(LINE, np.ones(4), np.ones(5), CUBIC, [0, 0.1])
    with pytest.raises(ValueError, match="points contains NaN"):
        integrate_particles(with_entry(LINE, 2, np.nan), np.ones(5), np.ones(5), CUBIC, [0, 0.1])


def test_ring_radius_overflow_is_refused():
    with pytest.raises(ValueError, match="Gamma overflows"):
        uniform_ring_radius(1e308, 1.0)


def test_times_must_be_non_empty_and_strictly_increasing():
    for times in ([0.0, 0.0], [], [0.2, 0.1], [-0.1, 0.1], [0.0, np.inf]):
        with pytest.raises(ValueError, match="times"):
            run_1d("smooth20", "cubic", 0.25, times)


def test_a_single_time_zero_returns_the_initial_state():
    run = run_1d("smooth20", "cubic", 0.25, [0])
    np.testing.assert_array_equal(run.positions[0], grid_1d(0.25))
    np.testing.assert_array_equal(run.densities[0], data_1d("smooth20")(grid_1d(0.25)[:, 0]))
    assert run.evaluations == 0


def test_mass_defect_accepts_lists():
    points, rho0, masses = [[-0.25], [0.0], [0.25]], [0.5, 1.0, 0.5], [0.1, 0.2, 0.1]
    as_lists = mass_defect(points, rho0, masses, CUBIC, 0.1)
    assert as_lists == mass_defect(np.array(points), np.array(rho0), np.array(masses), CUBIC, 0.1)


def test_blowup_time_names_the_kernel_and_the_valid_ones():
    with pytest.raises(ValueError, match="'cubic'.*newtonian_attractive.*newtonian_repulsive"):
        blowup_time(data_1d("smooth20"), "cubic")
    assert blowup_time("smooth20", "newtonian_repulsive") == math.inf   # no blow-up, on purpose


@pytest.mark.parametrize(("make", "limit"), [
    (lambda: run_1d("smooth20", "cubic", 1e-300, [0, 1]), "MAX_PARTICLES"),
    (lambda: run_2d("regular", "newtonian", 1e-300, [0, 1]), "MAX_FMM_PARTICLES"),
    (lambda: mass_defect(np.zeros((6000, 2)), np.ones(6000), np.ones(6000), kernel_2d("quadratic"), 0.1),
     "MAX_PARTICLES"),
    (lambda: mass_defect(np.zeros((90000, 2)), np.ones(90000), np.ones(90000), kernel_2d("newtonian"), 0.1),
     "MAX_FMM_PARTICLES"),
])
def test_particle_counts_beyond_the_limit_are_refused(make, limit):
    """MAX_PARTICLES in general, MAX_FMM_PARTICLES for the 2D Newtonian kernel (its sums are O(N)): each refusal
    names its own limit."""
    with pytest.raises(ValueError, match=rf"(?<![A-Z_]){limit}"):
        make()


def test_the_limits_cover_the_repository_runs():
    """Figure 5 extended (config/fig5-extended.yaml: its finest grid within MAX_FMM_PARTICLES, its kernel the
    Newtonian one) and the longest runs (Figure 8, t = 400)."""
    config = read_yaml(ROOT / "config" / "config.yaml")["blob"]
    extended = read_yaml(ROOT / "config" / "fig5-extended.yaml")["blob"]["fig5"]
    finest = max(extended["inverse_h"] + config["fig5"]["inverse_h"])
    for case in config["fig5"]["cases"]:
        assert len(grid_2d(1.0 / finest, case["data"])) <= checks.MAX_FMM_PARTICLES
        assert kernel_2d(config["fig5"]["kernel"]).max_particles == checks.MAX_FMM_PARTICLES
    fig4 = config["fig4"]
    assert 2 * max(fig4["inverse_h"]) * fig4["reference_factor"] + 1 <= checks.MAX_PARTICLES
    t_max = [case["t_max"] for fig in ("fig7", "fig8") for case in config[fig]["cases"]]
    assert max(t_max) <= checks.MAX_TIME
    fig7 = config["fig7"]
    assert fig7["delta"] >= checks.MIN_DELTA_OVER_H * fig7["h"]


def first_collision_time(h):
    """K = |x|/2 with grad K(0) := 0: X_i moves at (M_right - M_left)/2 until a collision, so neighbours close
    their gap h at the rate (m_i + m_{i+1})/2 and meet at 2 / (rho0_i + rho0_{i+1})."""
    rho0 = data_1d("smooth20")(grid_1d(h)[:, 0])
    return (2.0 / (rho0[:-1] + rho0[1:])).min()


def test_the_particle_method_stops_at_the_first_collision():
    with pytest.raises(ValueError, match="collide at t = ([0-9.]+)") as error:
        run_1d("smooth20", "newtonian_attractive", 0.25, [0, 5.0], method="particle")
    reported = float(str(error.value).split("t = ")[1].split(":")[0])
    assert reported == pytest.approx(first_collision_time(0.25), rel=1e-5)
    assert run_1d("smooth20", "newtonian_attractive", 0.25, [0, 1.5], method="particle").evaluations > 0
    assert run_1d("smooth20", "newtonian_repulsive", 0.25, [0, 5.0], method="particle").evaluations > 0


def test_long_time_spans_and_stalled_solves_are_refused(monkeypatch):
    with pytest.raises(ValueError, match="MAX_TIME"):
        run_1d("smooth20", "newtonian_repulsive", 0.25, [0, 1e6])
    monkeypatch.setattr(solver, "MAX_EVALUATIONS", 20)
    with pytest.raises(ValueError, match="MAX_EVALUATIONS = 20"):
        run_1d("smooth20", "newtonian_repulsive", 0.25, [0, 1.0])


def test_tiny_delta_is_refused():
    with pytest.raises(ValueError, match="MIN_DELTA_OVER_H"):
        run_2d("regular", "newtonian", 0.5, [0, 0.1], delta=1e-300)
    with pytest.raises(ValueError, match="radial table's step"):
        kernel_2d("quartic_power", PSI2, 1e-4)
    with pytest.raises(ValueError, match="MAX_TABLE_WORK"):
        kernel_2d("quartic_power", PSI2, 1e-3)


@pytest.mark.parametrize("make, name", [
    (lambda: run_1d(None, "cubic", 0.25, [0, 1]), "data"),
    (lambda: run_2d(None, "newtonian", 0.25, [0, 1]), "data"),
    (lambda: run_1d("smooth20", "cubic", 0.25, [0, 1], q=None), "q"),
    (lambda: run_1d("smooth20", "cubic", 0.25, np.array([0, 1 + 1j])), "times"),
    (lambda: integrate_particles(LINE + 1j, np.ones(5), np.ones(5), CUBIC, [0, 0.1]), "points"),
    (lambda: integrate_particles(LINE, np.ones(5), np.ones(5), "cubic", [0, 0.1]), "kernel"),
    (lambda: newtonian_exact(None, "newtonian_attractive", [0.1], 0.1), "data"),
])
def test_wrong_types_raise_a_type_error_naming_the_parameter(make, name):
    with warnings.catch_warnings():
        warnings.simplefilter("error")   # no ComplexWarning: the imaginary part is refused, not dropped
        with pytest.raises(TypeError, match=f"^{name} "):
            make()


def test_kernels_are_checked_before_the_compiled_sums_read_them():
    with pytest.raises(ValueError, match="kinds"):
        Kernel("k", 1, (99,), (1.0,), (1.0,))
    with pytest.raises(ValueError, match="dimension"):
        Kernel("k", 2, (0,), (1.0,), (0.1,))           # a 1D Gaussian term in 2D
    with pytest.raises(ValueError, match="index one of the 0 tables"):
        Kernel("k", 2, (5,), (1.0,), (0.0,))           # a TABLE term without a table
    with pytest.raises(ValueError, match="mismatched"):
        Kernel("k", 1, (POWER, POWER), (1.0,), (3.0, 1.0))
    tabulated = kernel_2d("quartic_power", PSI2, 0.5, table_radius=2.0, table_points=41)
    k, g, _ = tabulated.profile(np.array([0.0, 1.0]))
    assert k is None and np.isfinite(g).all()          # no NaN for the unknown potential
    with pytest.raises(ValueError, match="overflows"):
        Kernel("k", 1, (POWER,), (1.0,), (0.5,)).profile(np.array([5e-324]))   # r^-1.5


def test_an_absolute_tolerance_below_the_range_is_refused_naming_atol():
    # It ran into MAX_EVALUATIONS before, naming no parameter.
    from particle_methods.blob import run_1d

    with pytest.raises(ValueError, match="atol must lie in"):
        run_1d("smooth20", "newtonian_attractive", 0.1, [0.0, 0.1], atol=1e-300)


def test_issue_46_near_field_pairs_are_counted_and_refused_before_the_sums():
    """newtonian_sums on points within one width of each other took every pair in its near field (O(N^2): 10^6
    random points of the unit square with width 1 ran for hours); the cell list's pairs are counted first (here all
    N (N - 1)/2 = 5e9 of 10^5 points, in one cell) and refused beyond MAX_NEAR_PAIRS."""
    from particle_methods.blob import newtonian_fmm

    points = np.random.default_rng(46).random((10**5, 2))
    with pytest.raises(ValueError, match=r"positions put 5e\+09 pairs in the near field .* MAX_NEAR_PAIRS"):
        newtonian_fmm.newtonian_sums(points, np.ones(10**5), [1.0, -0.5], [1.0, 0.5])
    # The count is the loop's: on a grid with a narrow width each point's partners are its few neighbours.
    grid = np.stack(np.meshgrid(np.arange(30.0), np.arange(30.0)), axis=-1).reshape(-1, 2)
    keys, columns = newtonian_fmm._cell_keys(grid[:, 0].copy(), grid[:, 1].copy(),
                                             newtonian_fmm.GAUSS_CUTOFF * 0.1 / newtonian_fmm.CELL_SPLIT)
    # cells 0.217 wide: one point per cell; the partners j > i within the stencil lie in the same row (none) and
    # the next rows, up to CELL_SPLIT * 0.217 = 0.65 away: none on a grid of spacing 1.
    assert newtonian_fmm._near_pair_count(np.sort(keys), columns) == 0


def test_issue_46_mass_defect_refuses_points_of_no_dimension():
    with pytest.raises(ValueError, match=r"points must have shape \(N, d\) with d = 1 or 2, got \(2, 0\)"):
        mass_defect(np.zeros((2, 0)), [1.0, 1.0], [0.5, 0.5], kernel_1d("newtonian_attractive"), 0.1)  # IndexError


def test_issue_46_pair_sums_check_the_kernel_arrays_and_their_sums():
    """pair_sums took the arrays of Kernel.arrays unchecked: NaN kinds or parameters, strings and ragged lists
    gave NaN sums, numba typing errors or messages naming nothing; huge masses or widths of 5e-324 NaN sums."""
    from particle_methods.blob.pair_sums import pair_sums

    line = np.array([[-0.5], [0.0], [0.5]])
    masses = np.array([0.25, 0.5, 0.25])
    arrays = dict(zip(("kinds", "coefficients", "parameters", "tables", "steps"), CUBIC.arrays()))
    for name, bad in [("kinds", np.array([1.0, np.nan])), ("kinds", "abc"), ("kinds", np.array([99, 99])),
                      ("coefficients", [[1.0], [2.0, 3.0]]), ("parameters", np.array([0.3, np.nan])),
                      ("parameters", np.array([0.3, -1.0])), ("tables", None), ("steps", np.array([np.inf])),
                      ("positions", "abc"), ("masses", np.broadcast_to(1.0, (10**9,)))]:
        with pytest.raises(ValueError, match=name):
            pair_sums(**{"positions": line, "masses": masses, **arrays, name: bad})
    with pytest.raises(ValueError, match="not finite: .*parameters"):
        pair_sums(line, masses, **{**arrays, "parameters": np.array([5e-324, 5e-324])})
    with pytest.raises(ValueError, match="not finite: .*masses"):
        pair_sums(line, np.full(3, -1.7e308), **arrays)


def test_issue_46_newtonian_sums_refuse_an_overflow_and_take_huge_widths():
    """Huge widths raised an OverflowError (the square of the closest-pair bound), huge coefficients returned inf."""
    from particle_methods.blob import newtonian_fmm

    plane = np.array([[0.0, 0.0], [0.5, 0.0], [0.0, 0.5]])
    masses = np.array([0.25, 0.5, 0.25])
    # Points far closer than the widths: None, the documented answer that sends the caller to the direct sums.
    assert newtonian_fmm.newtonian_sums(plane, masses, [2.0, -1.0], [1e300, 1e300]) is None
    with pytest.raises(ValueError, match="coefficients"):
        newtonian_fmm.newtonian_sums(plane, masses, [-1.7e308, -1.7e308], [0.5, 0.7])


def test_issue_46_radial_quadrature_checks_its_inputs_and_result():
    """mollified_laplacian took any laplacian, mollifier, delta and r (AttributeError for a mollifier of None, NaN
    for delta = 5e-324, a hang for 10^9 radii); tabulate on a radius of 5e-324 failed in scipy."""
    from particle_methods.blob.radial import mollified_laplacian, tabulate

    def quartic(r):
        return 4.0 * np.asarray(r) ** 2

    r = np.array([0.0, 0.5, 1.0])
    for name, arguments in [("mollifier", (quartic, None, 0.5, r)), ("laplacian", (None, PSI2, 0.5, r)),
                            ("delta", (quartic, PSI2, 5e-324, r)), ("r", (quartic, PSI2, 0.5, [1.0, np.inf])),
                            ("r", (quartic, PSI2, 0.5, np.broadcast_to(0.0, (10**7,)))),
                            ("laplacian", (lambda x: np.full(np.shape(x), np.nan), PSI2, 0.5, r))]:
        with pytest.raises(ValueError, match=name):
            mollified_laplacian(*arguments)
    with pytest.raises(ValueError, match="radius"):
        tabulate(quartic, PSI2, 0.5, 5e-324, 21)
    with pytest.raises(ValueError, match="radius"):
        tabulate(quartic, PSI2, 0.5, 1e300, 21)


def test_issue_46_limits_of_mollifier_order_run_evaluations_and_tracer_offset():
    with pytest.raises(ValueError, match="order = 10.* twice the number of Gaussians"):
        Mollifier(10**400, 1, (4 / 3, -1 / 3), (1.0, 2.0))
    run = built(SMALL_RUN)
    with pytest.raises(ValueError, match="evaluations must be at most"):
        BlobRun(run.kernel, 0.5, run.times, run.positions, run.densities, run.masses, 10**400)
    with pytest.raises(ValueError, match="offset = 1e\\+300 must be at most MAX_OFFSET"):
        mass_defect(LINE, np.ones(5), np.full(5, 0.2), CUBIC, 0.05, offset=1e300)


def test_issue_46_refusals_name_the_parameter():
    """Refusals that named another parameter or none (the census, tests/census_blob.py)."""
    with pytest.raises(ValueError, match="dimension d = 3"):
        mollifier(4, 3)
    with pytest.raises(ValueError, match="parameters: .* must be positive"):
        Kernel("k", 1, (POWER,), (1.0,), (-3.0,))
    with pytest.raises(ValueError, match="per label of alpha"):
        newtonian_exact("smooth20", "newtonian_attractive", [], 0.5, rho0=[0.5, 1.0, 0.5])
    with pytest.raises(ValueError, match="points"):
        newtonian_exact_2d("regular", np.full((2, 2), 1.7e308), 0.5)
    with pytest.raises(ValueError, match="max rho0"):
        newtonian_exact_2d("regular", np.zeros((1, 2)), 0.5, rho0=[1e300])
    with pytest.raises(ValueError, match="weights"):
        PSI1.sums_1d(np.zeros(3), np.zeros(3), np.full(3, -1.7e308), 0.3)
    run = built(SMALL_RUN)
    with pytest.raises(ValueError, match="masses"):
        BlobRun(run.kernel, 0.5, run.times, run.positions, None, [], 0)
    with pytest.raises(ValueError, match="points, masses"):
        integrate_particles(np.full((3, 1), 1e300), np.ones(3), np.ones(3), CUBIC, [0.0, 0.1])
    with pytest.raises(ValueError, match="points, masses"):
        integrate_particles(LINE[:3], np.ones(3), np.full(3, 1e300), CUBIC, [0.0, 0.1])
