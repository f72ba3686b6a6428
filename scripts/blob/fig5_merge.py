"""Figure 5: the runs of its cases (scripts/blob/fig5_data.py, one per case and h) in one file, case by case
with h from coarse to fine."""

import numpy as np

from particle_methods.workflow import load_results, logged, save_results

KEYS = ("trajectory", "density", "particles", "evaluations")


def run(p, runs, output):
    inverse_h = list(p["inverse_h"])
    results = {"h_values": 1.0 / np.asarray(inverse_h, dtype=float), "fit_points": p["fit_points"], "q": p["q"],
               "labels": []}
    for index in range(len(p["cases"])):
        loaded = [load_results(runs[index * len(inverse_h) + j]) for j in range(len(inverse_h))]
        results["labels"].append(str(loaded[0]["label"]))
        for key in KEYS:
            results[f"case{index}_{key}"] = np.array([run[key] for run in loaded])
    results["labels"] = np.array(results["labels"])
    save_results(output, **results)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.params.cfg, snakemake.input.runs, snakemake.output[0])  # noqa: F821
