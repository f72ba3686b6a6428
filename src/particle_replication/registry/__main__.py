"""Print the README's figure map: ``python -m particle_replication.registry``."""

from . import figure_map

print(figure_map())
