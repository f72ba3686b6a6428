"""The README's figure map: ``python -m particle_replication.registry`` prints it, ``--write`` puts it into README.md
between its markers."""

import argparse
import re

from ..paths import REPOSITORY
from . import figure_map

MARKERS = re.compile(r"(<!-- figure map:.*?-->\n)(.*?)(\n<!-- end of the figure map -->)", flags=re.DOTALL)

parser = argparse.ArgumentParser(prog="python -m particle_replication.registry", description=__doc__)
parser.add_argument("--write", action="store_true", help="rewrite the figure map of README.md in place")
args = parser.parse_args()
if args.write:
    readme = REPOSITORY / "README.md"
    text = readme.read_text()
    if not MARKERS.search(text):
        raise SystemExit(f"{readme} has lost the markers of its figure map")
    readme.write_text(MARKERS.sub(lambda match: match.group(1) + figure_map() + match.group(3), text, count=1))
else:
    print(figure_map())
