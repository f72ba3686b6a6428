"""Craig and Bertozzi, the blob method: Figures 1-8 (1D and 2D), the reading of Figure 4's row
label and the study of the repulsive density error."""

from .records import Figure, Paper, Plot, listing


def _newtonian(name, label, caption, title):
    return Plot(
        "plot_newtonian.py",
        (Figure(name, label, caption, lambda s: title),),
        data={"data": f"results/blob/{name}.npz"},
        params=lambda s: {"error_t": s[name]["error_t"]},
    )


def _compare(name, label, kernels, title):
    return Plot(
        "plot_compare.py",
        (
            Figure(
                name,
                label,
                lambda s: f"2D particle (top) and blob (bottom, delta = {s[name]['delta']}) end states for {kernels}.",
                lambda s: title,
            ),
        ),
        data={"data": f"results/blob/{name}.npz"},
    )


PAPER = Paper(
    id="blob",
    plots=(
        _newtonian(
            "fig1",
            "blob m = 4, Newtonian, smooth data (A-D)",
            lambda s: (
                f"Blob method, m = {s['fig1']['order']}, delta = h^{s['fig1']['q']}, K = |x|/2, data "
                f"(4.3): trajectories, densities at t = {listing(s['fig1']['density_times'])}, zoom near "
                f"t = 1, and L1_h errors against h at t = {s['fig1']['error_t']}."
            ),
            "Blob method (m = 4, delta = h^0.9), K = |x|/2, data (4.3)",
        ),
        _newtonian(
            "fig2",
            "particle method, same data",
            lambda s: (
                "Particle method (grad K(0) = 0), same data: trajectories (straight lines), zoom, and "
                "trajectory errors against h."
            ),
            "Particle method (grad K(0) = 0), K = |x|/2, data (4.3)",
        ),
        _newtonian(
            "fig3",
            "blob m = 4, discontinuous data",
            lambda s: (
                "Blob method for the discontinuous data (4.4): trajectories, rounded densities, zoom and "
                "slower convergence."
            ),
            "Blob method (m = 4, delta = h^0.9), K = |x|/2, discontinuous data (4.4)",
        ),
        Plot(
            "plot_fig4.py",
            (
                Figure(
                    "fig4",
                    "errors, two kernels x (particle, m = 4, m = 6)",
                    lambda s: (
                        f"L1_h errors at t = {s['fig4']['t']} for data (4.5): K = -|x|/2 and |x|^3/3; particle method, "
                        f"m = 4 and m = 6."
                    ),
                ),
            ),
            data={"data": "results/blob/fig4.npz"},
            params=lambda s: {"t": s["fig4"]["t"]},
        ),
        Plot(
            "plot_repulsive.py",
            (
                Figure(
                    "repulsive",
                    "the repulsive density error of Figure 4 split into quadrature and regularisation parts",
                    lambda s: (
                        f"K = -|x|/2, data (4.5), t = {s['fig4']['t']}, q = {s['fig4']['q']}: density error "
                        f"of the blob method (m = 4, 6) split into its quadrature and regularisation parts, with "
                        f"the model of the quadrature part fitted on the paper's h and the runs extended to h = "
                        f"1/{s['fig4']['repulsive']['extra_inverse_h'][-1]}."
                    ),
                    ours=True,
                ),
            ),
            data={"data": "results/blob/repulsive.npz"},
        ),
        Plot(
            "plot_fig4.py",
            (
                Figure(
                    "fig4log",
                    "Figure 4's row label read as written, K = -log|x|/(2 pi)",
                    lambda s: (
                        f"Figure 4's first row read as its label writes it, K = -log|x|/(2 pi) (its caption and text "
                        f"say (-Delta)^(-1)): L1_h errors at t = {s['fig4']['t']} against an m = 6 reference on a grid "
                        f"{s['fig4']['log_reading']['reference_factor']} times finer."
                    ),
                    ours=True,
                ),
            ),
            data={"data": "results/blob/fig4log.npz"},
            params=lambda s: {"t": s["fig4"]["t"]},
        ),
        Plot(
            "plot_fig5.py",
            (
                Figure(
                    "fig5",
                    "2D errors, Newtonian kernel (blob, particle, disk)",
                    lambda s: (
                        f"2D, K = log|x|/(2 pi): L1_h errors at t = {s['fig5']['t']} for the blob method with regular "
                        f"data, the particle method, and the blob method with the indicator of the disk."
                    ),
                ),
            ),
            data={"data": "results/blob/fig5.npz"},
            params=lambda s: {"t": s["fig5"]["t"]},
        ),
        Plot(
            "plot_fig6.py",
            (
                Figure(
                    "fig6",
                    "2D trajectories, densities, star patch, three kernels",
                    lambda s: (
                        f"2D blob method for log|x|/(2 pi), |x|^2/2, |x|^3/3: {s['fig6']['top']['trajectories']} "
                        f"trajectories and the density at t = {s['fig6']['top']['t_density']} (bump data), star patch "
                        f"density at t = {s['fig6']['bottom']['t']} from the side and from above."
                    ),
                ),
            ),
            data={"data": "results/blob/fig6.npz"},
            params=lambda s: {"cfg": s["fig6"]},
        ),
        _compare(
            "fig7",
            "particle vs blob, power-law kernels (and on the paper's coarse radial tables)",
            "|x|^4/4 - log|x|/(2 pi), |x|^4/4 - |x|^1.5/1.5 and |x|^7/7 - |x|^1.5/1.5",
            "Repulsive-attractive power kernels, data (4.7): particle (top) and blob (bottom) methods",
        ),
        _compare(
            "fig8",
            "particle vs blob, Morse kernels, run until steady (and on the paper's coarse radial tables)",
            "the Morse kernels e^-|x| - 2e^-|x|/2 and 2e^-|x| - 2e^-|x|/2, data (4.7) and the star patch",
            "Morse kernels, data (4.7) and star patch (4.6): particle (top) and blob (bottom) methods",
        ),
    ),
    notebook=("results/blob/fig4.npz", "results/blob/fig5.npz", "results/blob/fig7.npz"),
)
