"""Event-driven sticky collisions: an independent reference for the hull algorithm.

Clusters are followed in time from one collision to the next; colliding clusters
merge with conservation of mass and momentum (section 1.1.2): the merged cluster sits
at the mass-weighted mean of the two positions and moves at the mass-weighted mean of
the two velocities. With the velocities of section 1.1.3 (equal masses) or of
:func:`~particle_methods.sticky.spd.velocities_from_levels` (masses c_k - c_{k-1}), a
cluster holding the levels (c_{a-1}, c_b] moves at the Rankine-Hugoniot speed of the
jump of u from c_{a-1} to c_b, so for a concave flux (every upward jump is then an
admissible shock) this is also front tracking of the entropy solution with the
discretised data (Remark 3.3).

O(n) work per collision and up to n - 1 collisions: O(n^2), meant for checks, hence at most
:data:`MAX_PARTICLES` particles.
"""

from __future__ import annotations

import numpy as np

from ..validation import nonnegative
from .spd import check_reach, checked_masses, checked_state

#: Most particles :func:`sticky_collisions` accepts: its O(n^2) work then takes about a second.
MAX_PARTICLES = 10**4


def sticky_collisions(x, v, t: float, masses=None) -> np.ndarray:
    """Positions at time ``t`` by explicit simulation of every collision.

    ``masses`` as in :func:`~particle_methods.sticky.spd.spd_positions`: positive, one per
    particle, None for equal masses.
    """
    x, v = checked_state(x, v)
    if x.size > MAX_PARTICLES:
        raise ValueError(f"sticky_collisions takes at most MAX_PARTICLES = {MAX_PARTICLES} particles (O(n^2) work), "
                         f"got {x.size}: use spd_positions")
    t = nonnegative("t", t)
    masses = None if masses is None else checked_masses(masses, x)
    check_reach(x, np.abs(v).max(), t, masses=masses)
    position = x.copy()
    velocity = v.copy()
    mass = np.ones(x.size) if masses is None else masses
    count = np.ones(x.size, dtype=np.int64)
    elapsed = 0.0
    while True:
        approach = velocity[:-1] - velocity[1:]
        gap = position[1:] - position[:-1]
        closing = approach > 0
        if not np.any(closing):
            break
        waits = np.full(gap.shape, np.inf)
        waits[closing] = gap[closing] / approach[closing]
        first = int(np.argmin(waits))
        if elapsed + waits[first] > t:
            break
        position += waits[first] * velocity
        elapsed += waits[first]
        total = mass[first] + mass[first + 1]
        velocity[first] = (mass[first] * velocity[first] + mass[first + 1] * velocity[first + 1]) / total
        position[first] = (mass[first] * position[first] + mass[first + 1] * position[first + 1]) / total
        mass[first] = total
        count[first] += count[first + 1]
        position, velocity, mass, count = (np.delete(values, first + 1) for values in (position, velocity, mass, count))
    return np.repeat(position + (t - elapsed) * velocity, count)
