"""Jourdain and Reygner: sticky particle dynamics (SPD) and multitype SPD, Figures 1-7 and the study
beyond the paper. Every rule of this paper is generated from its registry
(particle_replication.registry.sticky, rules/registry.smk)."""

STICKY_FIGURES = registry.figure_outputs("sticky")
