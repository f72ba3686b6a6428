"""Figure 5: the results of its cases (scripts/blob/fig5_data.py) in one file, case by case."""

import numpy as np

from particle_methods.workflow import load_results, logged, save_results


def run(p, cases, output):
    results = {"h_values": 1.0 / np.asarray(p["inverse_h"], dtype=float), "fit_points": p["fit_points"], "q": p["q"],
               "labels": []}
    for index, path in enumerate(cases):
        case = load_results(path)
        results["labels"].append(str(case["label"]))
        for key in ("trajectory", "density", "particles", "evaluations"):
            results[f"case{index}_{key}"] = case[key]
    results["labels"] = np.array(results["labels"])
    save_results(output, **results)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.params.cfg, snakemake.input.cases, snakemake.output[0])  # noqa: F821
