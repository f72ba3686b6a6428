"""The figure style: formulas of plain-text titles and labels in mathtext, sizes scaled to the printed width."""

import matplotlib.pyplot as plt
import pytest

from particle_replication.plotting import (
    MIN_PRINTED_SIZE,
    PRINTED_FONTS,
    PRINTED_WIDTH,
    SCRIPT_SCALE,
    apply_style,
    label_h_axis,
    legible,
    mathtext,
    new_figure,
    save_figure,
    suptitle,
    unicode_power,
    wrapped,
)


@pytest.mark.parametrize(("text", "expected"), [
    ("density rho_h", r"density $\rho _{h}$"),
    ("from (delta_-1 + delta_1)/2", r"from ($\delta _{-1} + \delta _{1})/2$"),
    ("K = |x|^3/3", r"$K = |x|^{3}/3$"),
    ("(b) dt = 0.0001, eps = h", r"(b) $\Delta t  = 0.0001$, $\varepsilon  = h$"),
    ("a title without formulas", "a title without formulas"),
    ("$already$ in mathtext", "$already$ in mathtext"),
    ("W = |x|^1.5/1.5:\ncollapse at t = 2", "$W = |x|^{1.5}/1.5$:\ncollapse at $t = 2$"),
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


@pytest.mark.parametrize(("label", "expected"), [
    (r"$\mathdefault{10^{-3}}$", "10⁻³"),
    (r"$\mathdefault{2\times10^{-12}}$", "2×10⁻¹²"),
    (r"$\mathdefault{10^{0}}$", "10⁰"),
    ("$\\mathdefault{10^{\N{MINUS SIGN}4}}$", "10⁻⁴"),
    (r"$\mathdefault{0.5}$", r"$\mathdefault{0.5}$"),   # not a power: left to mathtext
    ("", ""),
])
def test_log_tick_labels_are_written_with_unicode_superscripts(label, expected):
    assert unicode_power(label) == expected


def test_saved_log_axes_label_their_ticks_without_mathtext(tmp_path):
    fig, ax = new_figure(1, 1)
    ax.loglog([1e-3, 1e2], [1e-5, 3e-5])
    save_figure(fig, tmp_path / "f.pdf")
    labels = [text.get_text() for text in ax.xaxis.get_majorticklabels() + ax.yaxis.get_minorticklabels()]
    assert "10⁻³" in labels and "2×10⁻⁵" in labels
    assert not any("$" in label for label in labels)


def test_titles_break_between_words_outside_formulas_within_the_width():
    text = "one two $a = b + c$ three four"
    assert wrapped(text, 9) == "one two\n$a = b + c$\nthree\nfour"   # the formula counts 9 visible characters
    assert wrapped(text, 100) == text
    assert wrapped("averyveryverylongword x", 5) == "averyveryverylongword\nx"


def test_a_long_title_is_wrapped_to_the_figure(tmp_path):
    fig, _ = new_figure(1, 1, width=PRINTED_WIDTH)
    title = suptitle(fig, "K = |x|/2: " + "a long title of many words " * 8)
    assert len(title.get_text().split("\n")) >= 3
    assert title.get_window_extent(fig.canvas.get_renderer()).width <= fig.bbox.width


def test_text_below_the_printed_floor_is_raised_on_saving(tmp_path):
    fig, ax = new_figure(1, 1, width=2 * PRINTED_WIDTH, height=3.0)
    ax.set_title("a title in points")
    ax.title.set_fontsize(9)   # 4.5 pt as printed: a size that bypasses the module's scale
    ax.text(0.5, 0.5, "$h^{q}$", fontsize="x-small")
    ax.plot([0, 1], [0, 1], label="plain")
    ax.legend(fontsize=1)
    save_figure(fig, tmp_path / "f.pdf")
    assert ax.title.get_fontsize() == pytest.approx(2 * MIN_PRINTED_SIZE)
    assert ax.texts[0].get_fontsize() == pytest.approx(2 * MIN_PRINTED_SIZE / SCRIPT_SCALE)
    assert ax.get_legend().get_texts()[0].get_fontsize() == pytest.approx(2 * MIN_PRINTED_SIZE)


def test_a_figure_within_its_bounding_box_is_laid_out_once(monkeypatch):
    """Its width is the printed scale's, so the texts below their floors are raised before the one layout."""
    fig, ax = new_figure(1, 1, width=PRINTED_WIDTH, height=3.0)
    ax.set_title("a title in points", fontsize=4)
    draws = []
    layout = fig.draw_without_rendering
    monkeypatch.setattr(fig, "draw_without_rendering", lambda: draws.append(layout()))
    assert legible(fig) == ["a title in points"]
    assert len(draws) == 1 and ax.title.get_fontsize() == pytest.approx(MIN_PRINTED_SIZE)
    plt.close(fig)


def test_saving_draws_the_laid_out_figure_once_per_format(monkeypatch, tmp_path):
    """save_figure keeps the layout legible's draw solved: the PDF and the PNG are each drawn once, not once more
    before printing (as savefig does for a figure with a layout engine, even matplotlib's "none" placeholder)."""
    from matplotlib.figure import Figure

    fig, ax = new_figure(1, 2, width=PRINTED_WIDTH, height=3.0)
    ax[0].plot([0, 1], [1, 0])
    ax[0].set_title("a panel")
    renderers = []
    draw = Figure.draw
    monkeypatch.setattr(Figure, "draw", lambda self, renderer: (renderers.append(type(renderer).__name__),
                                                                draw(self, renderer))[1])
    save_figure(fig, tmp_path / "f.pdf")
    # legible's one layout (a figure at the printed width), then the PDF's and the PNG's prints: five draws before
    assert renderers == ["RendererAgg", "MixedModeRenderer", "RendererAgg"]
    assert fig.get_layout_engine() is None


def test_text_above_the_floor_keeps_its_size():
    fig, ax = new_figure(1, 1, width=PRINTED_WIDTH, height=3.0)
    ax.set_xlabel("plain", fontsize=12)
    assert "plain" not in legible(fig)
    assert ax.xaxis.label.get_fontsize() == 12
    plt.close(fig)


@pytest.mark.parametrize("width", [0, -1.0, "6.5", None])
def test_the_style_refuses_a_width_that_is_not_a_positive_number(width):
    with pytest.raises(ValueError, match="width"):
        apply_style(width)


def h_labels(h, **options):
    fig, ax = plt.subplots()
    ax.loglog(h, h)
    label_h_axis(ax, h, **options)
    fig.canvas.draw()
    texts = [tick.get_text() for tick in ax.get_xticklabels()]
    plt.close(fig)
    return texts


def test_every_tick_is_labelled_unless_more_than_most():
    h = [1 / n for n in (5, 10, 20, 40, 80)]
    assert h_labels(h) == h_labels(h, most=5) == ["1/5", "1/10", "1/20", "1/40", "1/80"]


def test_seven_sizes_keep_every_other_label_counted_from_the_finest():
    """Figure 5's overlay (7 grids on a narrow panel): the finest h keeps its label, every tick stays."""
    h = [1 / n for n in (5, 10, 20, 40, 80, 160, 320)]
    assert h_labels(h, most=5) == ["1/5", "", "1/20", "", "1/80", "", "1/320"]


def test_a_bad_most_is_refused_naming_it():
    with pytest.raises(ValueError, match="most"):
        h_labels([0.1, 0.05], most=0)
