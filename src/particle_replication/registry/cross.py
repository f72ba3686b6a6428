"""Our cross-method study: the 1D aggregation equation with K = |x|/2 by every method."""

from .records import Figure, Job, Paper, Plot, Result, listing


def _study(name, label, caption):
    return Plot(
        "plot_study.py",
        (Figure(name, label, caption, ours=True),),
        data={"data": "results/cross/study.npz"},
        params=lambda s: {"cfg": s},
    )


STUDY_KEYS = (
    "data",
    "times",
    "methods",
    "data_index",
    "time_index",
    "method_index",
    "size",
    "count",
    "error",
    "dirac_width",
    "spd_difference",
    "case_data",
    "case_times",
    "case_mass",
    "case_dirac",
)

RESULTS = (
    Result(
        "results/cross/study_errors.npz",
        "study_data.py",
        STUDY_KEYS,
        Job(
            "every method at every size on both data and times, each run once: W1 errors and diagnostics",
            lambda s: {"cfg": s, "part": "errors"},
        ),
    ),
    Result(
        "results/cross/study.npz",
        "study_data.py",
        (*STUDY_KEYS, "seconds", "cpu", "cpu_share", "load", "cores", "threads"),
        Job(
            "the same runs timed after JIT warm-up (alone on the cores), merged with the errors",
            lambda s: {"cfg": s, "part": "times"},
            inputs={"errors": "results/cross/study_errors.npz"},
            threads="all",
        ),
    ),
    Result(
        "results/cross/behaviour.npz",
        "behaviour_data.py",
        (
            "data",
            "collision_predicted",
            "collision_measured",
            "stall_collision",
            "stall_before",
            "stall_after",
            "stall_reached",
            "ltp_peak_position",
            "ltp_peak_width",
            "ltp_peak_edge",
            "ltp_inverse_h",
            "ltp_dt",
            "ltp_refusal",
            "stall_window",
        ),
        Job("the particle method at its first collision, LTP at the blow-up", lambda s: {"cfg": s}),
    ),
)

#: The bump data whose aggregates move and merge (config cross.aggregates.cases): one result and one figure each.
AGGREGATE_CASES = {
    "two_bumps": "two symmetric bumps, each collapsed before they merge",
    "skewed": "a skewed bump whose aggregate forms off its centre of mass and merges before it has collapsed",
}
AGGREGATE_KEYS = ("data", "times", "fixed_times", "window_times", "exact_positions", "exact_masses", "exact_lowers",
                  "exact_identity", "exact_offsets", "merger", "blowups", "methods", "size", "count", "error", "centre",
                  "spread", "method_merger", "merger_gap", "spd_merger_n", "spd_merger", "spd_levels", "spd_difference",
                  "mass", "support", "path_times", "path_positions", "path_masses", "spd_clusters")


def aggregate_settings(aggregates, case: str) -> dict:
    """The settings of one case of the aggregates study: the common ones with the case's own on top."""
    common = {key: value for key, value in aggregates.items() if key != "cases"}
    return {**common, **aggregates["cases"][case]}


#: Part ``godunov_ltp`` of a case (scripts/cross/aggregates_data.py): the exact merger, the time grid, the rows of
#: Godunov, LTP and SP.
AGGREGATE_LTP_KEYS = ("merger", "window_times", "times", "methods", "size", "count", "error", "centre", "spread")

RESULTS += tuple(
    result
    for case in AGGREGATE_CASES
    for result in (
        Result(
            f"results/cross/aggregates_{case}_godunov_ltp.npz",
            "aggregates_data.py",
            AGGREGATE_LTP_KEYS,
            Job(f"{case}: the exact merger and time grid, Godunov, LTP and SP against the exact aggregates on it",
                lambda s, case=case: {"cfg": aggregate_settings(s["aggregates"], case), "part": "godunov_ltp"}),
        ),
        Result(
            f"results/cross/aggregates_{case}.npz",
            "aggregates_data.py",
            AGGREGATE_KEYS,
            Job(f"{case}: the SPDs, the particle and blob methods against the exact aggregates on a time grid, with "
                "Godunov, LTP and SP", lambda s, case=case: {"cfg": aggregate_settings(s["aggregates"], case),
                                                              "part": "rest"},
                inputs={"ltp": f"results/cross/aggregates_{case}_godunov_ltp.npz"}),
        ),
    )
)


def _aggregates_figure(case: str, about: str) -> Plot:
    def caption(s):
        q = aggregate_settings(s["aggregates"], case)
        return (f"K = |x|/2 from {q['data']} ({about}): (a) the exact aggregates (lines from their blow-ups, width "
                f"growing with their mass) and the heavy clusters of the SPD with n = {q['spd_n'][0]} (dots); (b) each "
                "method's mean distance of the exact aggregates' levels from them, against t, at its largest size; "
                "(c) W1 to the exact solution against t at each method's largest size (LTP and the particle method "
                "up to the first blow-up); (d) its largest value over t > 0 against the particles or cells.")

    return Plot(
        "plot_aggregates.py",
        (Figure(f"aggregates_{case}", f"{case}: the aggregates' paths, levels and W1 against the exact ones", caption,
                ours=True),),
        data={"data": f"results/cross/aggregates_{case}.npz"},
        params=lambda s: {"cfg": aggregate_settings(s["aggregates"], case)},
    )


PAPER = Paper(
    id="cross",
    name="Cross",
    plots=(
        _study(
            "error_size",
            "W1 against particles or cells, every method, the blob paper's data (4.3) and (4.4), before and after "
            "the blow-up",
            lambda s: (
                f"K = |x|/2 from the blob paper's data (4.3) and (4.4): W1 distance to the exact solution against "
                f"the number of particles or cells, at t = {listing(s['times'])} (blow-up at t = 1). Dotted: W1 = "
                f"{s['target_error']:g}."
            ),
        ),
        _study(
            "error_time",
            "W1 against wall time, the same runs",
            lambda s: (
                f"K = |x|/2 from the blob paper's data (4.3) and (4.4): W1 distance to the exact solution against "
                f"wall time after JIT warm-up (the same runs, timed holding every core, with no other rule running), "
                f"at t = {listing(s['times'])}."
            ),
        ),
        *(_aggregates_figure(case, about) for case, about in AGGREGATE_CASES.items()),
    ),
    results=RESULTS,
    notebook=("results/cross/study.npz", "results/cross/behaviour.npz"),
)
