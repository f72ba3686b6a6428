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
        "results/cross/aggregates.npz",
        "aggregates_data.py",
        (
            "times",
            "fixed_times",
            "exact_positions",
            "exact_masses",
            "merger",
            "blowups",
            "methods",
            "size",
            "error",
            "centre",
            "method_merger",
            "spd_difference",
            "path_times",
            "path_positions",
            "path_masses",
            "spd_clusters",
        ),
        Job(
            "two_bumps: the SPDs, the particle and blob methods, Godunov, LTP and SP against the exact aggregates on a "
            "time grid",
            lambda s: {"cfg": s["aggregates"]},
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

PAPER = Paper(
    id="cross",
    plots=(
        _study(
            "error_size",
            "W1 against particles or cells, every method, (4.3) and (4.4), before and after the blow-up",
            lambda s: (
                f"K = |x|/2 from (4.3) and (4.4): W1 distance to the exact solution against the number of "
                f"particles or cells, at t = {listing(s['times'])} (blow-up at t = 1). Dotted: W1 = "
                f"{s['target_error']:g}."
            ),
        ),
        _study(
            "error_time",
            "W1 against wall time, the same runs",
            lambda s: (
                f"K = |x|/2 from (4.3) and (4.4): W1 distance to the exact solution against wall time after "
                f"JIT warm-up (the same runs, timed on 2 cores with no other rule running), at t = "
                f"{listing(s['times'])}."
            ),
        ),
        Plot(
            "plot_aggregates.py",
            (
                Figure(
                    "aggregates",
                    "two_bumps: the aggregates' paths against the exact ones, W1 uniformly in time",
                    lambda s: (
                        "K = |x|/2 from the asymmetric two_bumps: (a) the exact aggregates (lines, width growing with "
                        "their mass) and the equal-mass SPD's heavy clusters (dots), blow-ups at t = 1/2 and 1 and the "
                        "merger at 1.985; (b) W1 to the exact solution against t at each method's largest size (LTP "
                        "and the particle method up to the first blow-up); (c) its largest value over t against the "
                        "size."
                    ),
                    ours=True,
                ),
            ),
            data={"data": "results/cross/aggregates.npz"},
            params=lambda s: {"cfg": s["aggregates"]},
        ),
    ),
    results=RESULTS,
    notebook=("results/cross/study.npz", "results/cross/behaviour.npz"),
)
