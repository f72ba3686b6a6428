"""Figure 8: end states of the SP and LTP methods for |x|^4/4 - |x|^2.5/2.5 from (6.2)."""

import numpy as np

from particle_methods.ltp import density_named, potential, simulate
from particle_methods.workflow import logged, progress, save_results


def run(p, output):
    initial = density_named(p["initial"])
    w = potential("attractive_repulsive", a=p["a"], b=p["b"])
    dt = p["t"] / p["steps"]
    grid = np.linspace(-1.1, 1.1, 8801)
    results = {"grid": grid, "label": np.array(w.name)}
    for method, eps in (("ltp", None), ("sp", p["sp_eps"])):
        progress(f"{method}: {p['steps']} steps up to t = {p['t']}")
        final = simulate(initial, w, p["h"], dt, p["t"], method=method, eps=eps).at(-1)
        results.update({f"{method}_density": final.density(grid), f"{method}_centres": final.centres,
                        f"{method}_widths": final.widths, f"{method}_mass": final.mass})
    save_results(output, **results)


with logged(snakemake.log[0]):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
