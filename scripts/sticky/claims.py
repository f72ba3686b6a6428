"""Every checked claim of the sticky-particle paper, from the cached results and the config's rules.

The measures live in :mod:`particle_replication.verdicts.sticky`, where the tests feed them wrong
outcomes; this script only loads the results and writes the claims and their rate tables.
"""

from particle_methods.systems import PSystem
from particle_replication import claims as c
from particle_replication.rates import Recorder
from particle_replication.verdicts import sticky as v
from particle_replication.workflow import load_results, logged, progress


def run(inputs, cfg, output):
    rates = Recorder(progress)
    burgers, concave = load_results(inputs.burgers), load_results(inputs.concave)
    r33, l21, tspd, cost = cfg["remark33"], cfg["lemma21"], cfg["tspd_convergence"], cfg["cost"]
    rules = cfg["claims"]  # the tolerances no figure's section holds
    rows = [
        *v.burgers_claims(burgers, rates, cfg["fig2"]["order_window"], rules["order_tolerance"]),
        *v.concave_claims(concave, rates, cfg["fig3"]["decay_window"], cfg["fig3"]["decay_band"]),
        *v.theorem31_claims(burgers, concave),
        *v.remark33_claims(load_results(inputs.remark33), rates, r33["window"], r33["order_min"],
                           r33["convex"]["tolerance"]),
        *v.lemma21_claims(load_results(inputs.lemma21), rates, l21["rate_window"], l21["weibull_band"],
                          l21["heavy_tail"]["growth_ratio"], rules["quadrature_margin"],
                          rules["positive_density_tolerance"], rules["pareto_tolerance"]),
        *v.tspd_claims(load_results(inputs.tspd), rates, tspd["window"], tspd["delta_order_min"],
                       tspd["growth_max"], tspd["reference_share"], tspd["constant_ratio"]),
        *v.psystem_claims(load_results(inputs.rarefaction), load_results(inputs.shocks),
                          cfg["psystem"]["shocks"]["shock_fraction"],
                          PSystem(nu=cfg["psystem"]["nu"], kappa=cfg["psystem"]["kappa"])),
        *v.cost_claims(load_results(inputs.cost), rates, cost["window"], cost["band"]),
        *v.beyond_claims(load_results(inputs.beyond), rates, cfg["beyond"]),
    ]
    c.write_claims(output.claims, rows, log=progress)
    rates.write(output.rates)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.input, snakemake.params.cfg, snakemake.output)  # noqa: F821
