"""Figure 5: the runs of its cases (scripts/blob/fig5_data.py, one file per case and group of grids) in one
file, case by case, h from coarse to fine."""

import numpy as np

from particle_replication.workflow import load_results, logged, save_results

KEYS = ("trajectory", "density", "particles", "evaluations")


def run(p, runs, output):
    cases = len(p["cases"])
    groups = len(runs) // cases
    results = {"h_values": 1.0 / np.asarray(p["inverse_h"], dtype=float), "fit_points": p["fit_points"], "q": p["q"],
               "labels": []}
    for index in range(cases):
        loaded = [load_results(path) for path in runs[index * groups:(index + 1) * groups]]
        inverse_h = np.concatenate([part["inverse_h"] for part in loaded])
        if not np.array_equal(inverse_h, np.asarray(p["inverse_h"])):
            raise ValueError(f"the runs of case {index} cover 1/h = {inverse_h}, not the config's {p['inverse_h']}")
        results["labels"].append(str(loaded[0]["label"]))
        for key in KEYS:
            results[f"case{index}_{key}"] = np.concatenate([part[key] for part in loaded])
    results["labels"] = np.array(results["labels"])
    save_results(output, **results)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.params.cfg, snakemake.input.runs, snakemake.output[0])  # noqa: F821
