"""The replication layer of the three papers: everything the pipeline needs beyond the numerics.

The numerics live in :mod:`particle_methods` (methods, kernels, exact solutions, norms, finite
volumes), which imports nothing from here and loads none of the pipeline's software. Here:

- :mod:`.claims` (claim records, the claims table, ``verify``), :mod:`.rates` (fitted rates over every
  window), :mod:`.steady` (steadiness and end-state criteria of the verdicts);
- :mod:`.verdicts` (the measure of every claim, one module per paper and study);
- :mod:`.configuration`, :mod:`.workflow`, :mod:`.paths` (the pipeline's configuration checks, logging,
  atomic results, rule inputs, output roots), :mod:`.plotting` (figure style), :mod:`.report` (the
  report's LaTeX snippets), :mod:`.environment` (the versions of a run), :mod:`.tour` (the notebooks).
"""
