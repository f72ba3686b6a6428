"""The figure style: formulas of plain-text titles and labels in mathtext, sizes scaled to the printed width."""

import matplotlib.pyplot as plt
import pytest

from particle_replication.plotting import PRINTED_FONTS, PRINTED_WIDTH, mathtext, new_figure, save_figure


@pytest.mark.parametrize(("text", "expected"), [
    ("density rho_h", r"density $\rho _{h}$"),
    ("from (delta_-1 + delta_1)/2", r"from ($\delta _{-1} + \delta _{1})/2$"),
    ("K = |x|^3/3", r"$K = |x|^{3}/3$"),
    ("(b) dt = 0.0001, eps = h", r"(b) $\Delta t  = 0.0001$, $\varepsilon  = h$"),
    ("a title without formulas", "a title without formulas"),
    ("$already$ in mathtext", "$already$ in mathtext"),
])
def test_mathtext_puts_the_formulas_of_plain_text_in_mathtext(text, expected):
    assert mathtext(text) == expected


def test_mathtext_leaves_text_it_cannot_parse_as_plain_text():
    assert mathtext("a^b^c = 1") == "a^b^c = 1"   # a double superscript: mathtext would refuse it


def test_fonts_are_scaled_to_the_printed_width_and_labels_converted_on_saving(tmp_path):
    fig, ax = new_figure(1, 1, width=2 * PRINTED_WIDTH, height=3.0)
    assert plt.rcParams["xtick.labelsize"] == pytest.approx(2 * PRINTED_FONTS["xtick.labelsize"])
    ax.plot([0, 1], [0, 1], label="rho_h")
    ax.set(xlabel="h_min", ylabel="a density")
    ax.legend()
    save_figure(fig, tmp_path / "f.pdf")
    assert ax.xaxis.get_label().get_text() == "$h_{min}$"
    assert ax.get_legend().get_texts()[0].get_text() == r"$\rho _{h}$"
    assert (tmp_path / "f.png").exists()
