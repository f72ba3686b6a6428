"""Every checked claim of the blob paper, measured from the cached results (measures in
particle_replication.verdicts.blob; thresholds, tolerances and windows from the config's blob.claims
and the figures' sections)."""

from particle_replication import claims as c
from particle_replication.rates import Recorder
from particle_replication.verdicts import blob as v
from particle_replication.workflow import load_results, logged, progress


def run(inputs, output, p):
    recorder = Recorder(progress)  # every fitted rate of the run
    rules = p["claims"]  # every tolerance, threshold and cut-off of the claims
    rows = [*v.newtonian_claims(load_results(inputs.fig1), load_results(inputs.fig2), load_results(inputs.fig3),
                                rules, recorder),
            *v.fig4_claims(load_results(inputs.fig4), rules, recorder),
            *v.fig4log_claims(load_results(inputs.fig4log), load_results(inputs.fig4), rules, recorder),
            *v.repulsive_claims(load_results(inputs.repulsive), p["fig4"], rules, recorder),
            *v.fig5_claims(load_results(inputs.fig5), rules, recorder),
            *v.fig6_claims(load_results(inputs.fig6), rules),
            *v.fig7_claims(load_results(inputs.fig7), p["fig7"], rules),
            *v.fig8_claims(load_results(inputs.fig8), p["fig8"], rules)]
    c.write_claims(output.claims, rows, log=progress)
    recorder.write(output.rates)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.input, snakemake.output, snakemake.params.cfg)  # noqa: F821
