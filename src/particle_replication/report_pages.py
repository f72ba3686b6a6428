"""Pages of the browsable report (``snakemake --report``): a Markdown result of the run (the claims
table ``results/claims.md``, the software versions ``results/versions.md``) as a standalone HTML page
whose tables the report shows as tables.

``python -m particle_replication.report_pages results/claims.md results/report/claims.html --title "..."``
"""

from __future__ import annotations

import argparse
import html
from pathlib import Path

from nbconvert.filters.markdown_mistune import markdown2html_mistune

# Readable at a laptop's width: wrapped text cells, numbers kept on one line, a header that stays in view.
STYLE = """
body { font-family: system-ui, sans-serif; font-size: 14px; line-height: 1.4; margin: 1.5em; color: #222; }
h1 { font-size: 1.5em; } h2 { font-size: 1.25em; margin-top: 1.5em; }
table { border-collapse: collapse; margin: 1em 0; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.5em; vertical-align: top; text-align: left; }
th { background: #eee; position: sticky; top: 0; }
tbody tr:nth-child(even) { background: #f7f7f7; }
td code { white-space: nowrap; }
td.fail { background: #fbe3e3; font-weight: bold; }
td.pass { color: #1a6b2a; }
"""
# The verdicts a cell may hold alone, marked so that a failure stands out in a long table.
VERDICTS = ("pass", "fail")


def markdown_page(text: str, title: str) -> str:
    """A standalone HTML page (UTF-8, inline style, no external resource) of the Markdown ``text``,
    its tables rendered as HTML tables, cells holding a verdict alone marked by it."""
    if not isinstance(text, str):
        raise TypeError(f"text must be a str, got {type(text).__name__}")
    if not isinstance(title, str) or not title.strip():
        raise ValueError(f"title must be a non-empty str, got {title!r}")
    body = markdown2html_mistune(text)
    for verdict in VERDICTS:
        for cell in (verdict, f"<strong>{verdict}</strong>"):
            body = body.replace(f"<td>{cell}</td>", f'<td class="{verdict}">{cell}</td>')
    return (
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        f"<title>{html.escape(title)}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n{body}\n</body>\n</html>\n"
    )


def write_page(source, output, title: str) -> None:
    """Write :func:`markdown_page` of the Markdown file ``source`` to ``output``."""
    source, output = Path(source), Path(output)
    if not source.is_file():
        raise ValueError(f"source must be an existing Markdown file, got {source}")
    if output.suffix != ".html":
        raise ValueError(f"output must end in .html, got {output}")
    output.parent.mkdir(parents=True, exist_ok=True)
    output.write_text(markdown_page(source.read_text(encoding="utf-8"), title), encoding="utf-8")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("source", help="a Markdown file")
    parser.add_argument("output", help="the HTML page to write")
    parser.add_argument("--title", required=True, help="the page's title")
    args = parser.parse_args(argv)
    write_page(args.source, args.output, args.title)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
