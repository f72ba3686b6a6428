"""Campos Pinto, Carrillo, Charles, Choi: linearly transformed particles, Figures 1-8 and our long-time
and non-affine studies. Every rule of this paper is generated from its registry
(particle_replication.registry.ltp, rules/registry.smk)."""

LTP_FIGURES = registry.figure_outputs("ltp")
