"""Every checked claim of the LTP paper, measured from the cached results.

The measures live in particle_replication.verdicts.ltp; their thresholds and windows come from the
config (the figures' sections and ltp.claims), fixed before measuring."""

from particle_replication import claims as c
from particle_replication.rates import Recorder
from particle_replication.verdicts import ltp as v
from particle_replication.workflow import load_results, logged, progress


def run(inputs, output, p):
    rates = Recorder(progress)
    d5, d6, d7 = load_results(inputs.fig5), load_results(inputs.fig6), load_results(inputs.fig7)
    rules = p["claims"]  # the tolerances, thresholds and bands no figure's section holds
    rows = [
        *v.quadratic_claims(load_results(inputs.quadratic), rates, p["quadratic"], rules),
        *v.nonaffine_claims(load_results(inputs.nonaffine), rates, p["nonaffine"], rules),
        *v.fig4_claims(load_results(inputs.fig4), rules),
        *v.fig5_claims(d5, p["fig5"], rules),
        *v.fig6_claims(d6, p["concentration"], rules),
        *v.fig7_claims(d7, p["concentration"]),
        *v.fig8_claims(load_results(inputs.fig8), p["fig8"], rules),
        *v.conservation_claims([
            (d5, [f"case{i}_" for i in range(len(d5["labels"]))]),
            (d6, [f"case{i}_" for i in range(len(d6["labels"]))]),
            (d7, [""]),
        ]),
    ]
    c.write_claims(output.claims, rows, log=progress)
    rates.write(output.rates)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.input, snakemake.output, snakemake.params.cfg)  # noqa: F821
