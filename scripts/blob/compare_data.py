"""Figures 7 and 8: particle against blob trajectories in 2D for repulsive-attractive kernels.

The blob method runs twice: with our radial tables (8001 nodes on radius 5) and, as a check,
with the paper's coarse ones (``paper_tables``: radius and number of nodes). The kernels of
``without_origin`` (Figure 7) run again, particle and blob, without the grid particle at the origin,
up to the time given for each (``*_no_origin``, with the same time step of the records).
"""

import numpy as np

from particle_methods.blob.solver import integrate_particles, setup_2d
from particle_replication.workflow import logged, progress, save_results

RUNS = {"particle": {"method": "particle"}, "blob": {"method": "blob"}}


def without_origin(points, rho0, masses):
    """The grid without its particle at the origin (the one that sits at an unstable balance)."""
    keep = np.any(points != 0.0, axis=1)
    if keep.all():
        raise ValueError("the grid has no particle at the origin")
    return points[keep], rho0[keep], masses[keep]


def run(p, output):
    paper = p["paper_tables"]
    runs = {**RUNS, "blob_paper_tables": {"method": "blob", "table_radius": paper["radius"],
                                          "table_points": paper["points"]}}
    results = {"labels": []}
    no_origin = p.get("without_origin", {})
    for index, case in enumerate(p["cases"]):
        times = np.linspace(0.0, case["t_max"], p["times"])
        variants = [("", times, runs, False)]
        if case["kernel"] in no_origin:
            step = times[1] - times[0]
            longer = step * np.arange(round(no_origin[case["kernel"]] / step) + 1)
            variants.append(("_no_origin", longer, RUNS, True))
        for suffix, record, chosen, drop in variants:
            for name, options in chosen.items():
                progress(f"{case['kernel']} from {case['data']}: {name}{suffix}, h = {p['h']:.4g}, "
                         f"delta = {p['delta']}, t = {record[-1]:g}")
                # Only positions are compared: the densities, whose Laplacian sums stiffen the particle
                # method once particles cluster (Delta K ~ -1/r for the Morse kernels), are not carried.
                points, rho0, masses, kernel, _ = setup_2d(case["data"], case["kernel"], p["h"], delta=p["delta"],
                                                           **options)
                if drop:
                    points, rho0, masses = without_origin(points, rho0, masses)
                sim = integrate_particles(points, rho0, masses, kernel, record, with_density=False, rtol=p["rtol"],
                                          atol=p["atol"])
                # Pair distances must stay inside the radial tables (radius 2.5 for Figure 7's paper tables).
                if np.abs(sim.positions).max() > 0.48 * options.get("table_radius", 5.0):
                    raise ValueError(f"particles left the tabulated range in {case['kernel']} ({name}{suffix})")
                results[f"case{index}_{name}{suffix}"] = sim.positions
            results[f"case{index}_times{suffix}"] = record
        results["labels"].append(f"{case['kernel']}|{case['data']}")
    results["labels"] = np.array(results["labels"])
    save_results(output, h=p["h"], delta=p["delta"], paper_tables=np.array([paper["radius"], paper["points"]]),
                 **results)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
