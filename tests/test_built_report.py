"""The built report and supplement, read from the PDFs as a reader sees them: the report has at most
MAX_REPORT_PAGES pages, and no text of any figure prints below MIN_PRINTED_SIZE points (sub- and superscripts
included).

PyMuPDF's ``page.get_text("dict")`` gives every text span with its size in the page's coordinates, which
include the scale at which LaTeX prints the embedded figure: a 9 pt title of a figure printed at half its
drawn size reads 4.5 pt. A span belongs to a figure when its font is used by a Form XObject of the page (an
included PDF figure), not by the page's own text, and to the figure whose caption ("Figure Blob 7:") is the
nearest below it. The test skips, saying why, when a PDF has not been built (run `snakemake paper/ms.pdf
paper/supplement.pdf`) or PyMuPDF is not installed."""

import re
from pathlib import Path

import pytest

from particle_replication.plotting import MIN_PRINTED_SIZE

ROOT = Path(__file__).resolve().parents[1]
DOCUMENTS = [ROOT / "paper" / "ms.pdf", ROOT / "paper" / "supplement.pdf"]
#: The report a referee reads; the rest goes to the supplement.
MAX_REPORT_PAGES = 25
_CAPTION = re.compile(r"^Figure\s+(.+?):")


def _built(document: Path) -> Path:
    if not document.exists():
        name = document.relative_to(ROOT)
        pytest.skip(f"{name} is not built: run `snakemake --cores 1 {name}`")
    return document


def test_the_report_has_at_most_its_pages():
    pymupdf = pytest.importorskip("pymupdf", reason="PyMuPDF (pip install pymupdf) reads the built PDF")
    with pymupdf.open(_built(DOCUMENTS[0])) as document:
        assert document.page_count <= MAX_REPORT_PAGES, (
            f"paper/ms.pdf has {document.page_count} pages: move detail to paper/supplement.tex")


def figure_text_sizes(path) -> dict[str, tuple[float, str, int]]:
    """{figure label: (smallest text size as printed in points, that text, page)} of the PDF at ``path``."""
    pymupdf = pytest.importorskip("pymupdf", reason="PyMuPDF (pip install pymupdf) reads the built PDF")
    smallest = {}
    with pymupdf.open(path) as document:
        for page in document:
            # Fonts referenced from a Form XObject (an included figure), named as the spans name them.
            figure_fonts = {font[3].split("+", 1)[-1] for font in page.get_fonts(full=True) if font[-1] != 0}
            captions, spans = [], []
            for block in page.get_text("dict")["blocks"]:
                for line in block.get("lines", []):
                    first = line["spans"][0]
                    match = _CAPTION.match("".join(span["text"] for span in line["spans"]).strip())
                    if match and first["font"] not in figure_fonts and "Bold" in first["font"]:
                        captions.append((line["bbox"][1], match.group(1)))
                    spans += [span for span in line["spans"] if span["font"] in figure_fonts and span["text"].strip()]
            captions.sort()
            for span in spans:
                below = [label for top, label in captions if top >= span["bbox"][3] - 1]
                label = below[0] if below else f"a figure without caption on page {page.number + 1}"
                if label not in smallest or span["size"] < smallest[label][0]:
                    smallest[label] = (span["size"], span["text"].strip(), page.number + 1)
    return smallest


@pytest.mark.parametrize("document", DOCUMENTS, ids=lambda path: path.name)
def test_no_figure_text_prints_below_the_smallest_legible_size(document):
    sizes = figure_text_sizes(_built(document))
    assert sizes, f"no figure text found in {document.name}: the figures' fonts were not recognised"
    small = {label: size for label, size in sizes.items() if size[0] < MIN_PRINTED_SIZE - 0.01}
    report = "\n".join(f"  Figure {label}: {size:.2f} pt ({text!r}, page {page})"
                       for label, (size, text, page) in sorted(small.items(), key=lambda item: item[1][0]))
    assert not small, f"{len(small)} figures of {document.name} print text below {MIN_PRINTED_SIZE} pt:\n{report}"
