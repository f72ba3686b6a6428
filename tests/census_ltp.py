"""The census's calls (:mod:`census`) for ``particle_methods.ltp``: one good call of each public callable, by
keyword (:data:`ENTRIES`, built with :class:`census.Entry`), and the callables exempt from it with the reason
(:data:`EXEMPT`). Merged into :mod:`census_entries`. Tiny sizes and short times, so that the census stays cheap."""

from __future__ import annotations

PM = "particle_methods."

ENTRIES: dict = {}

EXEMPT: dict = {}
