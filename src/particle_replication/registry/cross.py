"""Our cross-method study: the 1D aggregation equation with K = |x|/2 by every method."""

from .records import Figure, Paper, Plot, listing


def _study(name, label, caption):
    return Plot(
        "plot_study.py",
        (Figure(name, label, caption, ours=True),),
        data={"data": "results/cross/study.npz"},
        params=lambda s: {"cfg": s},
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
    ),
    notebook=("results/cross/study.npz", "results/cross/behaviour.npz"),
)
