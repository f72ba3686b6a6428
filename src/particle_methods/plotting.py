"""Figure style shared by every paper: fonts, panel labels, PDF + PNG output."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

STYLE = {
    "font.size": 10,
    "axes.titlesize": 10,
    "axes.labelsize": 10,
    "legend.fontsize": 8,
    "xtick.labelsize": 9,
    "ytick.labelsize": 9,
    "lines.linewidth": 1.2,
    "figure.dpi": 100,
    "savefig.dpi": 200,
    "savefig.bbox": "tight",
    "image.cmap": "viridis",
}


def new_figure(rows: int = 1, columns: int = 1, width: float = 10.0, height: float = 4.0, **kwargs):
    """Figure and axes with the repository style applied."""
    plt.rcParams.update(STYLE)
    return plt.subplots(rows, columns, figsize=(width, height), constrained_layout=True, **kwargs)


def label_panel(ax, label: str) -> None:
    """Write a panel label such as "(a)" in the upper-left corner, outside the axes."""
    ax.set_title(label, loc="left", fontweight="bold")


def save_figure(fig, pdf_path, png_path=None) -> None:
    """Save ``fig`` as PDF and PNG (the PNG next to the PDF unless given) and close it."""
    pdf_path = Path(pdf_path)
    png_path = Path(png_path) if png_path is not None else pdf_path.with_suffix(".png")
    pdf_path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(pdf_path)
    fig.savefig(png_path)
    plt.close(fig)


def hide_minor_log_labels(ax) -> None:
    """Keep minor ticks on log axes but drop their labels, which crowd short decades."""
    from matplotlib.ticker import NullFormatter

    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.yaxis.set_minor_formatter(NullFormatter())
