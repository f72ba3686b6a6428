"""Jourdain and Reygner, sticky particle dynamics: Figures 1-7 and the study beyond the paper."""

from ..work_limits import solver_limit
from .records import Figure, Job, Paper, Plot, Result, listing


def _psystem(section, case):
    return section["psystem"][case]


def _rarefaction_title(s):
    return f"p-system, w0+ >= w0- (x0 = {_psystem(s, 'rarefaction')['x0']:g})"


def _shocks_title(s):
    return f"p-system with shocks, w0+ = 1{{x >= 0}} (x0 = {_psystem(s, 'shocks')['x0']:g})"


def _psystem_plot(name, label, case, kind, caption, title):
    return Plot(
        "plot_psystem.py",
        (Figure(name, label, caption, title),),
        data={"data": f"results/sticky/psystem_{case}.npz"},
        params=lambda s: {"kind": kind},
    )


def _beyond_plot(name, label, caption):
    return Plot(
        "plot_beyond.py",
        (Figure(name, label, caption, ours=True),),
        data={"data": "results/sticky/beyond.npz"},
        params=lambda s: {"cfg": s["beyond"]},
    )


PSYSTEM_KEYS = (
    "times",
    "trajectories",
    "field_path",
    "field_x",
    "w_minus",
    "w_plus",
    "u",
    "v",
    "trajectories_end",
    "field_end",
    "max_time",
)

SCALAR_KEYS = (
    "trajectory_times",
    "trajectories",
    "field_times",
    "field_x",
    "field",
    "profile_times",
    "profile_particle_cdf",
    "profile_exact_cdf",
    "error_p",
    "error_n",
    "error_times",
    "errors",
    "rate_n",
    "rate_errors",
    "initial_errors",
    "heaviside_errors",
    "clusters",
    "flux_lipschitz",
)

LIMIT_KEYS = (
    "t",
    "cases",
    "limit_n",
    "reference_cells",
    "upwind_reference_cells",
    "*_limit_to_hll",
    "*_limit_to_upwind",
    "*_mspd_gap",
    "*_hll_gap",
    "*_upwind_gap",
    "*_hll_to_upwind",
    "*_hll_w",
    "*_upwind_w",
    "*_mspd",
)


#: The settings of the `beyond` section each data job reads (the others, bands and tolerances, are the claims'
#: alone: a change of a band reruns no study).
LIMIT_SETTINGS = ("t", "domain", "cfl", "limit_n", "reference_cells", "upwind_reference_cells")
COST_SETTINGS = ("t", "domain", "cfl", "repeats", "tspd_n", "exact_n", "upwind_cells", "scalar")


#: The p-system's two cases of section 5.2.2 (config ``sticky.psystem``), each with jobs of its own.
PSYSTEM_CASES = ("rarefaction", "shocks")
#: The two runs of each reference of the beyond studies, one job each: the reference and the run at half its
#: resolution, whose distance to it is its own error. The exact MSPD (scripts/sticky/beyond_reference.py, the cost
#: study's) and the upwind scheme for (1.7) (beyond_upwind.py, the limits study's and the cost study's other
#: candidate), each with what its parts hold.
REFERENCE_PARTS = {"reference": {"full": "reference_n particles per type", "half": "half as many"},
                   "upwind": {"full": "upwind_reference_cells cells", "half": "half as many"}}
#: Each part's resolution: the reference's (reference_n, upwind_reference_cells) over its divisor.
PART_DIVISORS = {"full": 1, "half": 2}


def reference_path(study: str, case: str, part: str) -> str:
    """The result of one part of a reference (``study``: "reference", the exact MSPD, or "upwind") for one p-system
    case."""
    return f"results/sticky/beyond_{study}_{case}.npz" if part == "full" else \
        f"results/sticky/beyond_{study}_{case}_{part}.npz"


def _beyond(s, keys):
    return {key: s["beyond"][key] for key in keys}


def _upwind_cells(s, part: str) -> int:
    """The cells of one part of the upwind reference."""
    return s["beyond"]["upwind_reference_cells"] // PART_DIVISORS[part]


def _upwind_threads(s, part: str) -> int | str:
    """Every core for a part of the upwind reference whose grid splits the p-system's primitive among threads, one
    otherwise: the upwind scheme evaluates 3 (cells + 1) values of it a step
    (:func:`particle_methods.finite_volume.psystem.upwind_diagonal`), split only from
    :data:`particle_methods.systems.PARALLEL_MIN_PRIMITIVES` on (read from its source: the workflow starts without
    numba). The quick run's grids stay below: their jobs held two cores and ran on one."""
    threshold = solver_limit("particle_methods.systems.PARALLEL_MIN_PRIMITIVES")
    return "all" if 3 * (_upwind_cells(s, part) + 1) >= threshold else 1


def _system(s):
    return {key: s["psystem"][key] for key in ("nu", "kappa")}


def _cases(s):
    return {case: s["psystem"][case] for case in PSYSTEM_CASES}


def _scalar_result(name):
    return Result(
        f"results/sticky/{name}.npz",
        "scalar_data.py",
        SCALAR_KEYS,
        Job("SPD trajectories, u(t, x), profiles and exact L1 errors (Figures 2, 3)", lambda s: {"cfg": s[name]}),
    )


def _psystem_result(case):
    return Result(
        f"results/sticky/psystem_{case}.npz",
        "psystem_data.py",
        PSYSTEM_KEYS,
        Job(
            "iterated TSPD for the p-system: trajectories and space-time fields (Figures 4-7)",
            lambda s: {"case": case, "system": _system(s), "cfg": s["psystem"][case]},
        ),
    )


RESULTS = (
    _scalar_result("fig2"),
    _scalar_result("fig3"),
    _psystem_result("rarefaction"),
    _psystem_result("shocks"),
    Result(
        "results/sticky/lemma21.npz",
        "lemma21_data.py",
        (
            "n_values",
            "odd_n",
            "pareto_alpha",
            "weibull_alpha",
            "*_odd",
            "*_sqrt_variance",
            "*_support",
            "uniform",
            "two_atoms",
            "laplace",
            "exponential_*",
            "pareto_*",
            "weibull_*",
            "heavy_upper",
            "heavy_errors",
        ),
        Job("Lemma 2.1 and the tail examples: W1 error of the discretisation (2.1)", lambda s: {"cfg": s["lemma21"]}),
    ),
    Result(
        "results/sticky/remark33.npz",
        "remark33_data.py",
        (
            "admissibility_n",
            "admissibility_times",
            "admissibility_rankine_hugoniot",
            "admissibility_entropy",
            "admissibility_clusters",
            "convex_admissibility",
            "hopf_gaps",
            "convex_hopf_gaps",
            "refined_cells",
            "refined_distances",
            "refined_n",
            "refined_t",
            "dirac_n",
            "dirac_times",
            "dirac_errors",
            "godunov_n",
            "godunov_times",
            "cells_per_unit",
            "distances",
            "total_errors",
            "initial_errors",
            "convex_distances",
            "convex_n",
            "convex_t",
        ),
        Job(
            "Remark 3.3: the exact t/(4n) error from one Dirac mass; the SPD against Hopf's formula for the "
            "entropy solution (the exact test) and against Rankine-Hugoniot speeds and Oleinik's condition (a "
            "check); SPD against Godunov",
            lambda s: {"cfg": s["remark33"]},
        ),
    ),
    Result(
        "results/sticky/tspd_convergence.npz",
        "tspd_convergence_data.py",
        (
            "cases",
            "times",
            "deltas",
            "delta_n",
            "reference_delta",
            "delta_errors",
            "delta_reference_gap",
            "n_values",
            "n_delta",
            "reference_n",
            "n_errors",
            "bounds",
            "n_reference_gap",
        ),
        Job(
            "Theorem 4.4: iterated TSPD errors, a Delta sweep at fixed n and an n sweep at small Delta",
            lambda s: {"system": _system(s), "cases": _cases(s), "cfg": s["tspd_convergence"]},
        ),
    ),
    Result(
        "results/sticky/cost.npz",
        "cost_data.py",
        (
            "hull_n",
            "hull_operations",
            "hull_free_operations",
            "hull_times",
            "hull_free_times",
            "rank_n",
            "rank_operations",
            "rank_times",
            "tspd_n",
            "tspd_operations",
            "tspd_times",
            "tspd_steps",
            "steps_values",
            "steps_operations",
            "steps_times",
            "steps_n",
            "cpu",
            "cpu_share",
            "load",
            "cores",
            "threads",
        ),
        Job(
            "sections 5.1.1 and 5.2.1: operations the compiled kernels count against n and the number of steps, "
            "and their times (timed: alone on the cores)",
            lambda s: {"cfg": s["cost"]},
            threads="all",
        ),
    ),
    Result(
        "results/sticky/beyond_limits.npz",
        "beyond_limits.py",
        LIMIT_KEYS,
        Job(
            "beyond the paper: the exact MSPD against conservative and upwind finite volumes (untimed)",
            lambda s: {"system": _system(s), "cases": _cases(s), "cfg": _beyond(s, LIMIT_SETTINGS)},
            inputs={f"{case}_{part}": reference_path("upwind", case, part) for case in PSYSTEM_CASES
                    for part in REFERENCE_PARTS["upwind"]},
        ),
    ),
    *(Result(
        reference_path("upwind", case, part),
        "beyond_upwind.py",
        ("case", "part", "upwind_reference_cells", "cells", "upwind_w"),
        Job(
            f"beyond the paper: the upwind reference of the limits study, {case} case, {about} (untimed)",
            lambda s, case=case, part=part: {"system": _system(s), "x0": s["psystem"][case]["x0"], "case": case,
                                             "part": part, "size": _upwind_cells(s, part),
                                             "cfg": _beyond(s, ("t", "domain", "cfl", "upwind_reference_cells"))},
            # the primitive's evaluation, most of its time, split among the threads (bit for bit the same)
            threads=lambda s, part=part: _upwind_threads(s, part),
        ),
    ) for case in PSYSTEM_CASES for part, about in REFERENCE_PARTS["upwind"].items()),
    *(Result(
        reference_path("reference", case, part),
        "beyond_reference.py",
        ("case", "part", "n", "mspd"),
        Job(
            f"beyond the paper: the cost study's exact MSPD reference, {case} case, {about} (untimed)",
            lambda s, case=case, part=part: {"system": _system(s), "x0": s["psystem"][case]["x0"], "case": case,
                                             "part": part, "size": s["beyond"]["reference_n"] // PART_DIVISORS[part],
                                             "cfg": _beyond(s, ("t", "reference_n"))},
        ),
    ) for case in PSYSTEM_CASES for part, about in REFERENCE_PARTS["reference"].items()),
    Result(
        "results/sticky/beyond.npz",
        "beyond_data.py",
        (
            *LIMIT_KEYS,
            "tspd_n",
            "exact_n",
            "upwind_cells",
            "scalar_cases",
            "*_tspd",
            "*_exact",
            "*_upwind",
            "*_spd",
            "*_godunov",
            "*_spd_n",
            "*_cells",
            "*_reference",
            "*_reference_error",
            "*_timing",
            "cpu",
            "cpu_share",
            "load",
            "cores",
            "threads",
        ),
        Job(
            "beyond the paper: the cost study (timed runs, alone on the cores), merged with the limits",
            lambda s: {"system": _system(s), "cases": _cases(s), "cfg": _beyond(s, COST_SETTINGS)},
            inputs={"limits": "results/sticky/beyond_limits.npz",
                    **{f"{case}_{part}": reference_path("reference", case, part) for case in PSYSTEM_CASES
                       for part in REFERENCE_PARTS["reference"]}},
            threads="all",
        ),
    ),
    Result(
        "results/sticky/theory.npz",
        "theory_data.py",
        (
            "cases",
            "d",
            "speed_bound",
            "hyperbolicity",
            "lipschitz",
            "crossings_bound",
            "scalar_*",
            "doubling",
            "burgers_prop32",
            "cubic_prop32",
            "step_*",
            "collisions",
            "mspd_distances",
            "largest_count",
            "count_histogram",
            "smallest_shrink",
            "largest_collision_gap",
            "extent",
            "random_*",
            "reference_n",
            "reference_gap",
            "tspd_errors",
        ),
        Job(
            "sections 3 and 4 beyond the figures: Proposition 3.2 and (3.3), Lemma 4.2, Remark 4.3, (4.5), (4.1) "
            "against the exact MSPD, the constants of (4.6), Corollary 4.6 on random data, section 5.2 in t",
            lambda s: {"system": _system(s), "cases": _cases(s), "cfg": s["theory"]},
        ),
    ),
)

PAPER = Paper(
    id="sticky",
    name="Sticky",
    plots=(
        Plot(
            "plot_fig1.py",
            (
                Figure(
                    "fig1",
                    "one iteration of the hull algorithm",
                    lambda s: (
                        "One iteration of the Brenier-Grenier hull algorithm (section 5.1.1): the list L before the "
                        "iteration, the removal of a concave corner, and L after it."
                    ),
                ),
            ),
            params=lambda s: {"cfg": s["fig1"]},
        ),
        *(
            Plot(
                "plot_scalar.py",
                (Figure(name, label, caption, title),),
                data={"data": f"results/sticky/{name}.npz"},
                params=lambda s, name=name: {"case": s[name]["case"]},
            )
            for name, label, caption, title in (
                (
                    "fig2",
                    "Burgers, two atoms (a-d)",
                    lambda s: (
                        f"Burgers equation from (delta_-1 + delta_1)/2: (a) trajectories of "
                        f"{s['fig2']['trajectory_particles']} particles, (b) u(t, x), (c) profiles at t = "
                        f"{listing(s['fig2']['profile_times'])} with the exact fans dashed, (d) log L1 error against "
                        f"p for n = 2^p, t = {listing(s['fig2']['error_times'])}: slope -log 2."
                    ),
                    lambda s: r"Burgers equation (5.1) from $(\delta_{-1} + \delta_1)/2$",
                ),
                (
                    "fig3",
                    "concave flux, Laplace data (a-d)",
                    lambda s: (
                        f"Concave flux u(1-u)/2 from the Laplace law: (a) {s['fig3']['trajectory_particles']} "
                        f"trajectories, (b) u(t, x), (c) profiles at t = {listing(s['fig3']['profile_times'])} with "
                        f"the exact solution, (d) log L1 error against p, t = {listing(s['fig3']['error_times'])}: "
                        f"plateau, then log(n)/n decay."
                    ),
                    lambda s: "concave flux $u(1-u)/2$ (5.3) from the Laplace law (5.4)",
                ),
            )
        ),
        _psystem_plot(
            "fig4",
            "MSPD trajectories, w0+ >= w0-",
            "rarefaction",
            "trajectories",
            lambda s: (
                f"p-system, w0+ >= w0- (x0 = {_psystem(s, 'rarefaction')['x0']}): MSPD trajectories by the "
                f"iterated TSPD (Delta = {_psystem(s, 'rarefaction')['delta']}), "
                f"{_psystem(s, 'rarefaction')['trajectory_particles']} particles per type; no same-type "
                f"collision."
            ),
            _rarefaction_title,
        ),
        _psystem_plot(
            "fig5",
            "w-, w+, u, v, same case",
            "rarefaction",
            "fields",
            lambda s: (
                f"p-system, w0+ >= w0-: w-, w+, specific volume u and velocity v in the space-time plane "
                f"(n = {_psystem(s, 'rarefaction')['field_particles']} per type, Delta = "
                f"{_psystem(s, 'rarefaction')['delta']})."
            ),
            _rarefaction_title,
        ),
        _psystem_plot(
            "fig6",
            "MSPD trajectories with shocks",
            "shocks",
            "trajectories",
            lambda s: (
                f"p-system with shocks (x0 = {_psystem(s, 'shocks')['x0']}, w0+ = 1{{x >= 0}}): trajectories, "
                f"{_psystem(s, 'shocks')['trajectory_particles']} per type (Delta = "
                f"{_psystem(s, 'shocks')['delta']}); the + cluster forms, then breaks up after crossing."
            ),
            _shocks_title,
        ),
        _psystem_plot(
            "fig7",
            "w-, w+, u, v, same case",
            "shocks",
            "fields",
            lambda s: (
                f"p-system with shocks: w-, w+, u and v in the space-time plane (n = "
                f"{_psystem(s, 'shocks')['field_particles']} per type, Delta = {_psystem(s, 'shocks')['delta']})."
            ),
            _shocks_title,
        ),
        _beyond_plot(
            "beyond_limits",
            "exact MSPD against conservative HLL and upwind for the diagonal system (1.7) of the sticky paper",
            lambda s: (
                f"Beyond the paper, p-system at t = {s['beyond']['t']}: (a, b) w- and w+ of the exact MSPD "
                f"(n = {s['beyond']['limit_n'][-1]} per type), the conservative HLL scheme "
                f"({s['beyond']['reference_cells']} cells) and the upwind scheme for (1.7) "
                f"({s['beyond']['upwind_reference_cells']} cells), rarefaction and shock cases; (c) W1 "
                f"distance of the exact MSPD to both schemes against n, with each reference's distance to its "
                f"half-resolution run."
            ),
        ),
        _beyond_plot(
            "beyond_cost",
            "error against operations and wall time: SPD/Godunov, TSPD/exact MSPD/upwind",
            lambda s: (
                "Beyond the paper, the cost argument of section 5.2: error against operation count (top) and "
                "wall time (bottom); SPD and Godunov on the scalar cases of Figures 2 and 3, iterated TSPD "
                "(L = n), exact MSPD and upwind scheme for (1.7) on the two p-system cases. Dotted: error "
                "proportional to work^-1 (steep) and work^-1/2."
            ),
        ),
    ),
    results=RESULTS,
    notebook=("results/sticky/fig2.npz", "results/sticky/fig3.npz"),
)
