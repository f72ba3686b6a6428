"""Figure style shared by every paper: fonts, panel labels, PDF + PNG output."""

from __future__ import annotations

import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.ticker import Formatter, LogFormatterSciNotation

#: Width (inches) at which the report prints every figure, its text width: sizes below are as printed.
PRINTED_WIDTH = 6.5
#: The smallest text of a figure as printed (points), sub- and superscripts included.
MIN_PRINTED_SIZE = 7.0
#: Font sizes as printed (points). Mathtext draws sub- and superscripts at SCRIPT_SCALE of their text, so text
#: that holds a formula needs MIN_PRINTED_SIZE / SCRIPT_SCALE (10 pt): :func:`save_figure` raises any text below
#: its floor to it, relative sizes ("small") and sizes a script sets in points included.
PRINTED_FONTS = {"font.size": 9.0, "axes.titlesize": 10.0, "axes.labelsize": 10.0, "legend.fontsize": 8.5,
                 "xtick.labelsize": 8.0, "ytick.labelsize": 8.0}
#: The size of mathtext's sub- and superscripts relative to their text (matplotlib's, as TeX's).
SCRIPT_SCALE = 0.7
#: Line and tick sizes as printed (points).
PRINTED_LINES = {"lines.linewidth": 1.0, "lines.markersize": 4.0, "axes.linewidth": 0.6,
                 "xtick.major.width": 0.6, "ytick.major.width": 0.6, "xtick.major.size": 3.0, "ytick.major.size": 3.0,
                 "xtick.minor.width": 0.4, "ytick.minor.width": 0.4, "xtick.minor.size": 1.8, "ytick.minor.size": 1.8}
STYLE = {
    "figure.dpi": 100,
    "savefig.dpi": 200,
    "savefig.bbox": "tight",
    "image.cmap": "viridis",
}


def new_figure(rows: int = 1, columns: int = 1, width: float = 10.0, height: float = 4.0, **kwargs):
    """Figure and axes with the repository style applied. A figure ``width`` inches wide is printed
    PRINTED_WIDTH wide, so its fonts and lines are drawn width / PRINTED_WIDTH times their printed sizes;
    scripts give other sizes relative to these ("small"), never in points; :func:`save_figure` raises any
    text below the printed floor (:func:`legible`)."""
    apply_style(width)
    return plt.subplots(rows, columns, figsize=(width, height), constrained_layout=True, **kwargs)


def apply_style(width: float) -> float:
    """Set the repository style for a figure ``width`` inches wide, printed PRINTED_WIDTH wide; returns the
    scale width / PRINTED_WIDTH from printed sizes to drawn ones (for figures built without :func:`new_figure`)."""
    if not isinstance(width, (int, float)) or not width > 0:
        raise ValueError(f"width must be a positive number of inches, got {width!r}")
    scale = width / PRINTED_WIDTH
    plt.rcParams.update(STYLE | {key: size * scale for key, size in (PRINTED_FONTS | PRINTED_LINES).items()})
    return scale


def _has_script(text: str) -> bool:
    """Whether ``text`` holds a mathtext formula with a sub- or superscript."""
    return any(("^" in piece or "_" in piece) for piece in text.split("$")[1::2])


def legible(fig) -> list[str]:
    """Raise every text of ``fig`` below its floor as printed to that floor: MIN_PRINTED_SIZE, or MIN_PRINTED_SIZE /
    SCRIPT_SCALE for text with a sub- or superscript, so that a size set in points, relative ("x-small") or from an
    rc parameter cannot print smaller. The figure prints PRINTED_WIDTH wide as saved, that is with its tight
    bounding box, which a legend or a label outside the axes makes wider than the figure: the floors follow that
    width, measured by drawing the figure, again after raising texts (which can widen it), at most three times.
    The figure's own width is a lower bound of that width, so the texts that exist before drawing are first raised
    to the floors it gives: a figure whose bounding box is no wider than itself is then drawn once, not twice (4 of
    the quick run's 49 layouts were such second draws; the other 12 raise texts that widen the bounding box, or
    tick labels, which exist once drawn). The figure is left drawn at its final sizes: its layout is solved for
    them. Returns the texts raised."""
    raised = _raise_below_floor(fig, fig.get_figwidth() / PRINTED_WIDTH)
    fig.draw_without_rendering()
    for _ in range(3):
        now = _raise_below_floor(fig, max(fig.get_figwidth(), fig.get_tightbbox().width) / PRINTED_WIDTH)
        if not now:
            break
        raised += now
        fig.draw_without_rendering()  # the layout with the raised sizes
    return raised


def _raise_below_floor(fig, scale: float) -> list[str]:
    """Raise the visible texts of ``fig`` below their floors for a figure printed at 1 / ``scale`` of its size
    (:func:`legible`); returns them."""
    from matplotlib.text import Text

    raised = []
    for text in fig.findobj(Text):
        content = text.get_text()
        if not text.get_visible() or not content.strip():
            continue
        floor = MIN_PRINTED_SIZE * scale / (SCRIPT_SCALE if _has_script(content) else 1.0)
        if text.get_fontsize() < floor - 1e-9:
            text.set_fontsize(floor)
            raised.append(content)
    return raised


#: Width of an average character of a title, in ems of its font (0.47 to 0.50 measured on the titles of
#: the figures in DejaVu Sans, formulas included): lines are filled to this estimate.
TITLE_CHARACTER_WIDTH = 0.56


def suptitle(fig, text: str):
    """The figure's title, its formulas in mathtext (:func:`mathtext`), wrapped to the figure's width (a title
    wider than the figure would widen the saved image and print every panel smaller). Lines are broken
    between words outside formulas, by an estimate of their width (:data:`TITLE_CHARACTER_WIDTH`):
    matplotlib's own wrapping measures every prefix of the title, a mathtext parse each, which took about
    a sixth of a plot job's time. Returns the title's Text."""
    title = fig.suptitle(mathtext(text))
    columns = fig.get_figwidth() * 72 / (title.get_fontsize() * TITLE_CHARACTER_WIDTH)
    title.set_text(wrapped(title.get_text(), int(columns)))
    return title


def wrapped(text: str, columns: int) -> str:
    """``text`` broken into lines of at most ``columns`` visible characters (a formula's markup not
    counted) at spaces outside $...$; a word longer than a line keeps a line of its own."""
    lines, line, words, inside = [], "", [], False
    for word in text.split(" "):
        words.append(word)
        inside ^= (word.count("$") - word.count(r"\$")) % 2 == 1
        if inside:
            continue
        piece, words = " ".join(words), []
        candidate = f"{line} {piece}" if line else piece
        if line and _visible_length(candidate) > columns:
            lines.append(line)
            candidate = piece
        line = candidate
    if words:
        line = f"{line} {' '.join(words)}" if line else " ".join(words)
    return "\n".join([*lines, line])


def _visible_length(text: str) -> int:
    """Characters of ``text`` as drawn, roughly: a mathtext command counts one, '$' and braces none."""
    return len(re.sub(r"\\[A-Za-z]+", "x", text).replace("$", "").replace("{", "").replace("}", ""))


def label_panel(ax, label: str) -> None:
    """Write a panel label such as "(a)" in the upper-left corner, outside the axes."""
    ax.set_title(mathtext(label), loc="left", fontweight="bold")


def save_figure(fig, pdf_path, png_path=None) -> None:
    """Save ``fig`` as PDF and PNG (the PNG next to the PDF unless given) and close it."""
    pdf_path = Path(pdf_path)
    png_path = Path(png_path) if png_path is not None else pdf_path.with_suffix(".png")
    pdf_path.parent.mkdir(parents=True, exist_ok=True)
    _formulas_in_mathtext(fig)
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            for formatter, set_formatter in ((axis.get_major_formatter(), axis.set_major_formatter),
                                             (axis.get_minor_formatter(), axis.set_minor_formatter)):
                if type(formatter) is LogFormatterSciNotation:
                    set_formatter(UnicodePowers(formatter))
    legible(fig)
    # legible's last draw solved the layout at the final sizes: both saves keep it and crop to the bounding box it
    # gives (with savefig.pad_inches, as savefig's "tight" pads it), so neither draws the figure once more to solve
    # the layout and measure the box. No layout engine at all, not matplotlib's "none" (a placeholder engine, for
    # which savefig still draws the figure once before it prints it): two more of a plot job's draws.
    box = fig.get_tightbbox().padded(plt.rcParams["savefig.pad_inches"])
    with plt.rc_context({"figure.autolayout": False, "figure.constrained_layout.use": False}):
        fig.set_layout_engine(None)
    fig.savefig(pdf_path, bbox_inches=box)
    fig.savefig(png_path, bbox_inches=box)
    plt.close(fig)


_SUPERSCRIPTS = str.maketrans("0123456789-\N{MINUS SIGN}", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁻")
_POWER = re.compile(r"\$\\mathdefault\{(?:(?P<mantissa>\d+(?:\.\d+)?)\\times\s*)?"
                    r"(?P<base>\d+)\^\{(?P<exponent>[-\N{MINUS SIGN}]?\d+)\}\}\$")


class UnicodePowers(Formatter):
    """A log axis's labels (``LogFormatterSciNotation``: "$\\mathdefault{2\\times10^{-3}}$") written with
    Unicode superscripts ("2×10⁻³"): the same text without mathtext, whose parsing of every label took
    about a quarter of a plot job's time. A label of another form is kept as the wrapped formatter
    writes it."""

    def __init__(self, formatter: LogFormatterSciNotation):
        self.formatter = formatter

    def set_axis(self, axis) -> None:
        super().set_axis(axis)
        self.formatter.set_axis(axis)

    def set_locs(self, locs) -> None:
        self.formatter.set_locs(locs)

    def __call__(self, x, pos=None) -> str:
        return unicode_power(self.formatter(x, pos))


def unicode_power(label: str) -> str:
    """"$\\mathdefault{m\\times b^{k}}$" -> "m×bᵏ" in superscript digits; any other label unchanged."""
    match = _POWER.fullmatch(label)
    if match is None:
        return label
    mantissa = f"{match['mantissa']}×" if match["mantissa"] else ""
    return f"{mantissa}{match['base']}{match['exponent'].translate(_SUPERSCRIPTS)}"


def _formulas_in_mathtext(fig) -> None:
    """Axis labels, axes titles and legend entries written in plain text (``"density rho_h"``) with their
    formulas in mathtext; text that already holds a '$' is left as it is."""
    for ax in fig.axes:
        texts = [ax.xaxis.label, ax.yaxis.label, ax.title]
        legend = ax.get_legend()
        if legend is not None:
            texts += legend.get_texts()
        for text in texts:
            text.set_text(mathtext(text.get_text()))


def hide_minor_log_labels(ax) -> None:
    """Keep minor ticks on log axes but drop their labels, which crowd short decades."""
    from matplotlib.ticker import NullFormatter

    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.yaxis.set_minor_formatter(NullFormatter())


# Words that plain-text titles (rule params, data files) use for mathematical symbols.
_MATH_WORDS = {"delta": r"\delta", "Delta": r"\Delta", "pi": r"\pi", "grad": r"\nabla", "nabla": r"\nabla",
               "log": r"\log", "exp": r"\exp", "rho": r"\rho", "psi": r"\psi", "epsilon": r"\varepsilon",
               "alpha": r"\alpha", "eps": r"\varepsilon", "dt": r"\Delta t"}
_OPERATORS = {"=", "+", "-", "<", ">", "<=", ">=", "*", "/", "~"}


def _is_math_token(token: str) -> tuple[bool, bool]:
    """(may sit in a formula, marks a formula) for one whitespace-separated token."""
    import re

    if token in _OPERATORS:
        return True, True
    if re.fullmatch(r"[-+]?\d+(\.\d+)?(/\d+(\.\d+)?)?", token):
        return True, False
    if re.fullmatch(r"[A-Za-z](\([^()]*\))?", token):
        return True, False
    if token in _MATH_WORDS:
        return True, True
    if any(mark in token for mark in "|^_") or re.search(r"(?<![A-Za-z])(" + "|".join(_MATH_WORDS) + r")(?![A-Za-z])",
                                                          token):
        return True, True
    return False, False


def _to_tex(formula: str) -> str:
    """Plain-text formula -> mathtext body: Greek and operator words, braces after '^' and '_'."""
    import re

    formula = re.sub(r"(?<![A-Za-z\\])(" + "|".join(_MATH_WORDS) + r")(?![A-Za-z])",
                     lambda match: _MATH_WORDS[match.group(1)] + " ", formula)
    formula = re.sub(r"_(?!\{)(-?[A-Za-z0-9]+)", r"_{\1}", formula)   # h_min, delta_-1: the whole subscript
    formula = formula.replace(">=", r"\geq ").replace("<=", r"\leq ")
    return re.sub(r"\^(?!\{)(-?(?:\d+(?:\.\d+)?|[A-Za-z]|\|[^|]*\|))", r"^{\1}", formula).replace(" )", ")")


def mathtext(text: str) -> str:
    """Plain-text title such as ``"m = 4, delta = h^0.9, K = log|x|/(2 pi)"`` in matplotlib mathtext:
    each formula (a run of tokens with an operator, '|', '^' or a Greek word) goes between '$'.

    Text that already holds a '$' is returned unchanged; text of several lines is converted line by line;
    text mathtext cannot parse comes back as plain text (with '$' escaped), so a title never breaks a figure.
    """
    if "$" in text:
        return text
    if "\n" in text:  # line by line: a formula never spans lines
        return "\n".join(map(mathtext, text.split("\n")))
    pieces, run, strong, depth = [], [], False, 0

    def close():
        nonlocal run, strong, depth
        if run:
            body = " ".join(run)
            pieces.append(f"${_to_tex(body)}$" if strong else body)
        run, strong, depth = [], False, 0

    for word in text.split(" "):
        lead, core, tail = "", word, ""
        while core and core[-1] in ",;:":
            core, tail = core[:-1], core[-1] + tail
        if core.startswith("(") and core.count("(") > core.count(")"):
            lead, core = "(", core[1:]
        while core.endswith(")") and depth + core.count("(") - core.count(")") < 0:
            core, tail = core[:-1], ")" + tail
        math, marks = _is_math_token(core) if core else (False, False)
        if lead or not math:
            close()
        if math:
            if lead:
                pieces.append(lead + "\u200b")
            run.append(core)
            strong = strong or marks
            depth += core.count("(") - core.count(")")
            if tail:
                close()
                pieces.append("\u200b" + tail)
        else:
            pieces.append(lead + core + tail)
    close()
    result = " ".join(pieces).replace("\u200b ", "").replace(" \u200b", "").replace("\u200b", "")
    try:
        from matplotlib.mathtext import MathTextParser

        MathTextParser("agg").parse(result)
    except ValueError:
        return text.replace("$", r"\$")
    return result


def label_h_axis(ax, h_values, axis: str = "x", most: int | None = None) -> None:
    """Ticks of a log axis at the grid sizes ``h_values``, labelled 1/N when 1/h is an integer
    (decimal otherwise), without minor ticks. With ``most``, at most that many ticks are labelled: every k-th,
    counted from the last h given (the others keep an unlabelled tick), so that a narrow panel's labels do not
    run into each other."""
    import numpy as np
    from matplotlib.ticker import FixedFormatter, FixedLocator, NullLocator

    from particle_methods.validation import integer_at_least

    h_values = np.asarray(h_values, dtype=float)
    inverse = 1.0 / h_values
    if np.allclose(inverse, np.round(inverse), rtol=1e-6, atol=0):
        labels = [f"1/{int(round(n))}" for n in inverse]
    else:
        labels = [f"{h:.3g}" for h in h_values]
    if most is not None:
        step = -(-len(labels) // integer_at_least("most", most, 1))
        labels = [label if (len(labels) - 1 - index) % step == 0 else "" for index, label in enumerate(labels)]
    target = ax.xaxis if axis == "x" else ax.yaxis
    target.set_major_locator(FixedLocator(h_values))
    target.set_major_formatter(FixedFormatter(labels))
    target.set_minor_locator(NullLocator())
