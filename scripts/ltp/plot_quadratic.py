"""Figures 2 and 3 from the cached W = x^2 runs."""


from particle_methods.convergence import fit_order
from particle_methods.plotting import hide_minor_log_labels, label_panel, new_figure, save_figure
from particle_methods.workflow import load_results, logged


def figure2(d, output):
    fig, axes = new_figure(1, 3, width=14, height=4.2)
    ax = axes[0]
    ax.plot(d["grid"], d["exact"], "k-", lw=2, label="exact (6.4)")
    for h, density in zip(d["plot_h"], d["plot_density"]):
        ax.plot(d["grid"], density, "--", label=f"LTP, h = {h:g}")
    ax.set(xlabel="x", ylabel="density", xlim=(-0.6, 0.4))
    ax.legend()
    label_panel(ax, f"(a) exact vs LTP at t = {float(d['t']):g}")

    ax = axes[1]
    k = int(d["order_points"])
    for column, name, marker in ((0, "L1", "o"), (1, "Linf", "s")):
        errors = d["ltp_errors"][:, column]
        order = fit_order(d["h_values"][-k:], errors[-k:])
        ax.loglog(d["h_values"], errors, marker + "-", label=f"LTP {name} error (order {order:.2f})")
    ax.set(xlabel="h", ylabel="error at t = 0.5")
    hide_minor_log_labels(ax)
    ax.legend()
    label_panel(ax, "(b) LTP errors against h")

    ax = axes[2]
    ax.plot(d["grid"], d["exact"], "k-", lw=2, label="exact (6.4)")
    for eps, density in zip(d["sp_eps"], d["sp_densities"]):
        ax.plot(d["grid"], density, lw=0.9, label=f"SP, eps = {eps:g}")
    ax.set(xlabel="x", ylabel="density", xlim=(-0.6, 0.4))
    ax.legend()
    label_panel(ax, "(c) SP with h = 0.01 and fixed eps")
    fig.suptitle("W = x^2, data (6.1), dt = 1e-4, B3 shape")
    save_figure(fig, output.fig2_pdf, output.fig2_png)


def figure3(d, output):
    fig, axes = new_figure(1, 2, width=11, height=4.2)
    ax = axes[0]
    for column, name, colour in ((0, "L1", "C0"), (1, "Linf", "C3")):
        ax.loglog(d["eps_values"], d["scan_sp"][:, column], "o-", ms=3, color=colour, label=f"SP {name}")
        ax.axhline(d["scan_ltp"][column], color=colour, ls="--", label=f"LTP {name}")
    ax.set(xlabel="SP particle width eps", ylabel="error at t = 0.5")
    ax.legend()
    label_panel(ax, "(a) h = 0.01, dt = 0.01")
    ax = axes[1]
    for column, name, colour in ((0, "L1", "C0"), (1, "Linf", "C3")):
        ax.loglog(d["h_values"], d["sp_errors"][:, column], "o-", color=colour, label=f"SP (eps = h) {name}")
        ax.loglog(d["h_values"], d["ltp_errors"][:, column], "s--", color=colour, label=f"LTP {name}")
    ax.set(xlabel="h", ylabel="error at t = 0.5")
    hide_minor_log_labels(ax)
    ax.legend()
    label_panel(ax, "(b) dt = 1e-4, eps = h")
    fig.suptitle("SP against LTP errors, W = x^2, data (6.1)")
    save_figure(fig, output.fig3_pdf, output.fig3_png)


with logged(snakemake.log[0]):  # noqa: F821
    data = load_results(snakemake.input.data)  # noqa: F821
    figure2(data, snakemake.output)  # noqa: F821
    figure3(data, snakemake.output)  # noqa: F821
