"""Exact multitype sticky particle dynamics by event-driven simulation (sections 1.2.2, 5.2).

The MSPD moves clusters at constant velocities between events. Particles of one type that meet
stick (the TSPD of that type, section 1.2.2); particles of different types that meet cross, and
the TSPD restarts with the velocities (1.8) of the new ranks. Section 5.2 argues that the number
of such events is of order n^2 and leaves the exact algorithm aside; it is built here.

Data structure: one list of clusters of all types ordered along the line, a tie at one place
being ordered by decreasing type (the post-collisional order of (USH), as in
:func:`~particle_methods.sticky.mspd.ranks_kernel`). Trajectories are straight between events, so the
next meeting is between neighbours of this list: each cluster holds the time at which it meets
the next one, in an indexed binary heap. At an event:

- two clusters of one type merge; mass and momentum are conserved, so the merged cluster moves
  at the mean of its members' velocities;
- a cluster a of type alpha meets the cluster b of a higher type beta ahead of it (by (USH) lower
  types are faster, and no other pair of types can meet): a passes b, the members of a count
  |b| more particles of type beta behind them and those of b count |a| fewer of type alpha, and
  the members of a and b only get new velocities (1.8). A cluster whose members' new velocities
  separate them splits as the SPD started from one point decides: into the blocks of the
  non-decreasing (pool-adjacent-violators) regression of its members' velocities, each block
  moving at its mean. Every other particle keeps its rank, hence its velocity, and by the flow
  property of the SPD its motion.

Velocities (1.8) are read from a table built once from the primitive P_gamma of lambda^gamma in
its own variable at every level grid point (k_1/n, ..., k_d/n): lambda~^gamma_k = n (P_gamma(..,
k/n, ..) - P_gamma(.., (k-1)/n, ..)), as in :mod:`.mspd`. The grid holds (n+1)^d points and d of
them per point is at most :data:`MAX_TABLE`; on it (USH) is checked for every velocity.
By (USH) every pair of particles of different types crosses at most once, so there are at most
d(d-1)n^2/2 crossings. A crossing of clusters a and b makes |a| |b| pairs cross and costs O(|a| + |b|)
<= O(|a| |b| + 1) member updates and blocks, and a merge undoes one block: every count of
:class:`EventCounts` is O(d^2 n^2). A call is refused when the crossing bound d(d-1)n^2/2 + d n
exceeds :data:`MAX_EVENTS`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..jit import njit
from ..systems import checked_primitive
from ..validation import finite_array, finite_result, instance
from .mspd import checked_configuration, ranks_kernel
from .spd import check_reach

#: Largest velocity table d (n+1)^d one call builds (400 MB): n <= 4999 for d = 2.
MAX_TABLE = 5 * 10**7

#: Largest crossing bound d(d-1) n^2 / 2 + d n one call accepts (with the other events, about a minute).
MAX_EVENTS = 2 * 10**8

_NONE = -1


class EventCounts(NamedTuple):
    """Events processed by :func:`mspd_exact` up to its last requested time."""

    merges: int
    """meetings of two clusters of one type, which stick"""
    crossings: int
    """meetings of clusters of different types, which pass each other"""
    splits: int
    """clusters created by the splitting of a cluster after a crossing"""
    member_updates: int
    """velocities (1.8) recomputed at crossings: the work of the crossings"""


@njit
def _speed(table, strides, gamma, k, counts):
    """lambda~^gamma_k (1.8) of particle gamma:k (0-based k) with ``counts[g]`` particles of type g behind it."""
    flat = strides[gamma, gamma] * k
    for g in range(counts.size):
        if g != gamma:
            flat += strides[gamma, g] * counts[g]
    return table[gamma, flat]


@njit
def _position(cluster, t, xref, tref, vel):
    return xref[cluster] + vel[cluster] * (t - tref[cluster])


@njit
def _heap_swap(heap, where, i, j):
    a, b = heap[i], heap[j]
    heap[i], heap[j] = b, a
    where[b], where[a] = i, j


@njit
def _heap_update(heap, where, size, key, cluster):
    """Restore the heap after ``key[cluster]`` changed; inserts ``cluster`` if absent. Returns the size."""
    i = where[cluster]
    if i < 0:
        i = size
        heap[i] = cluster
        where[cluster] = i
        size += 1
    while i > 0 and key[heap[(i - 1) // 2]] > key[heap[i]]:
        _heap_swap(heap, where, i, (i - 1) // 2)
        i = (i - 1) // 2
    while True:
        smallest, left = i, 2 * i + 1
        if left < size and key[heap[left]] < key[heap[smallest]]:
            smallest = left
        if left + 1 < size and key[heap[left + 1]] < key[heap[smallest]]:
            smallest = left + 1
        if smallest == i:
            return size
        _heap_swap(heap, where, i, smallest)
        i = smallest


@njit
def _heap_remove(heap, where, size, key, cluster):
    """Remove ``cluster`` from the heap if present. Returns the size."""
    i = where[cluster]
    if i < 0:
        return size
    size -= 1
    last = heap[size]
    where[cluster] = -1
    if i < size:
        heap[i] = last
        where[last] = i
        size = _heap_update(heap, where, size, key, last)
    return size


@njit
def _meeting_time(a, now, kind, nxt, xref, tref, vel):
    """Time at which cluster a meets the next cluster of the list (inf if never)."""
    b = nxt[a]
    if b < 0 or not (kind[a] <= kind[b] and vel[a] > vel[b]):
        return np.inf  # a higher type ahead of a lower one, or no approach: they never meet
    gap = max(_position(b, now, xref, tref, vel) - _position(a, now, xref, tref, vel), 0.0)
    return now + gap / (vel[a] - vel[b])


@njit
def _schedule(a, now, heap, where, size, key, kind, nxt, xref, tref, vel):
    """Set the meeting time of cluster a with the next one and file it in the heap. Returns the size."""
    key[a] = _meeting_time(a, now, kind, nxt, xref, tref, vel)
    if key[a] < np.inf:
        return _heap_update(heap, where, size, key, a)
    return _heap_remove(heap, where, size, key, a)


@njit
def _append(last, cluster, prv, nxt):
    """Chain ``cluster`` after ``last`` in the list; True if it starts the list (last = -1)."""
    prv[cluster], nxt[cluster] = last, _NONE
    if last >= 0:
        nxt[last] = cluster
    return last < 0


@njit
def _blocks(values, lo, hi, starts, sums):
    """Pool-adjacent-violators on values[lo:hi]: the blocks of its non-decreasing regression.

    Block j holds members starts[j] to starts[j+1] - 1 (the last one ends at hi) and their sum
    sums[j]; adjacent blocks are pooled while the left one is at least as fast, so the block
    means increase strictly. This is the SPD of particles started from one place (the hull of
    section 5.1.1 with equal positions). Returns the number of blocks.
    """
    top = -1
    for k in range(lo, hi):
        total, start = values[k], k
        while top >= 0 and sums[top] * (k + 1 - start) >= total * (start - starts[top]):
            total += sums[top]
            start = starts[top]
            top -= 1
        top += 1
        starts[top], sums[top] = start, total
    return top + 1


@njit
def _new_blocks(reuse, gamma, lo, hi, place, now, count_row, lam, starts, sums, free, nfree, kind, low, high, xref,
                tref, vel, counts, prv, nxt):
    """Clusters for the blocks of the members lo..hi-1 of type gamma at ``place``, chained in order.

    The first block takes the id ``reuse`` (the cluster that held these members, or -1), the
    others ids from the stack ``free`` (its size in nfree[0]). Returns the first and last block;
    the caller links them into the list.
    """
    blocks = _blocks(lam[gamma], lo, hi, starts, sums)
    first = last = _NONE
    for j in range(blocks):
        end = starts[j + 1] if j + 1 < blocks else hi
        if j == 0 and reuse >= 0:
            cluster = reuse
        else:
            nfree[0] -= 1
            cluster = free[nfree[0]]
        kind[cluster], low[cluster], high[cluster] = gamma, starts[j], end
        xref[cluster], tref[cluster], vel[cluster] = place, now, sums[j] / (end - starts[j])
        counts[cluster, :] = count_row
        if _append(last, cluster, prv, nxt):
            first = cluster
        last = cluster
    return first, last


@njit
def _simulate(x0, ranks, table, strides, times, out, stats):
    """Event loop of the MSPD from x0 (shape (d, n)), writing the configuration at each of ``times``
    (non-decreasing) to ``out``; ``ranks`` is :func:`~particle_methods.sticky.mspd.ranks_kernel` of x0.
    ``stats`` receives the :class:`EventCounts`."""
    d, n = x0.shape
    capacity = d * n
    kind = np.empty(capacity, dtype=np.int64)
    low = np.empty(capacity, dtype=np.int64)
    high = np.empty(capacity, dtype=np.int64)
    xref, tref, vel, key = np.empty(capacity), np.empty(capacity), np.empty(capacity), np.empty(capacity)
    counts = np.empty((capacity, d), dtype=np.int64)
    prv = np.empty(capacity, dtype=np.int64)
    nxt = np.empty(capacity, dtype=np.int64)
    heap = np.empty(capacity, dtype=np.int64)
    where = np.full(capacity, -1, dtype=np.int64)
    free = np.arange(capacity - 1, -1, -1)
    nfree = np.array([capacity])
    starts, sums = np.empty(n, dtype=np.int64), np.empty(n)
    lam = np.empty((d, n))
    row, row_b = np.empty(d, dtype=np.int64), np.empty(d, dtype=np.int64)
    # Initial clusters: the blocks of each group of particles of one type at one place.
    by_type = np.empty((d, n), dtype=np.int64)  # clusters of each type, in order
    found = np.zeros(d, dtype=np.int64)
    for gamma in range(d):
        lo = 0
        while lo < n:
            hi = lo + 1
            while hi < n and x0[gamma, hi] == x0[gamma, lo]:
                hi += 1
            row[:] = ranks[gamma, lo]
            for k in range(lo, hi):
                lam[gamma, k] = _speed(table, strides, gamma, k, row)
            first, last = _new_blocks(_NONE, gamma, lo, hi, x0[gamma, lo], 0.0, row, lam, starts, sums, free, nfree,
                                      kind, low, high, xref, tref, vel, counts, prv, nxt)
            cluster = first
            while cluster >= 0:
                by_type[gamma, found[gamma]] = cluster
                found[gamma] += 1
                cluster = nxt[cluster]
            lo = hi
    # One list along the line, a tie at one place ordered by decreasing type (as in ranks_kernel).
    head, last = _NONE, _NONE
    current = np.zeros(d, dtype=np.int64)
    for _ in range(found.sum()):
        chosen = -1
        for g in range(d):
            if current[g] < found[g] and (chosen < 0 or xref[by_type[g, current[g]]] <= xref[by_type[chosen,
                                                                                                     current[chosen]]]):
                chosen = g
        cluster = by_type[chosen, current[chosen]]
        current[chosen] += 1
        if _append(last, cluster, prv, nxt):
            head = cluster
        last = cluster
    size, now = 0, 0.0
    cluster = head
    while cluster >= 0:
        size = _schedule(cluster, now, heap, where, size, key, kind, nxt, xref, tref, vel)
        cluster = nxt[cluster]
    behind = np.empty(d)
    index = 0
    while index < times.size:
        event_time = key[heap[0]] if size > 0 else np.inf
        while index < times.size and times[index] <= event_time:
            # Between events every cluster moves straight; a rounding guard keeps each type sorted.
            behind[:] = -np.inf
            cluster = head
            while cluster >= 0:
                gamma = kind[cluster]
                place = max(_position(cluster, times[index], xref, tref, vel), behind[gamma])
                behind[gamma] = place
                out[index, gamma, low[cluster]:high[cluster]] = place
                cluster = nxt[cluster]
            index += 1
        if index == times.size:
            break
        now = event_time
        a = heap[0]
        b = nxt[a]
        before, after = prv[a], nxt[b]
        if kind[a] == kind[b]:  # same type: stick, conserving mass and momentum
            ma, mb = high[a] - low[a], high[b] - low[b]
            place = (ma * _position(a, now, xref, tref, vel) + mb * _position(b, now, xref, tref, vel)) / (ma + mb)
            vel[a] = (ma * vel[a] + mb * vel[b]) / (ma + mb)
            xref[a], tref[a], high[a] = place, now, high[b]
            nxt[a] = after
            if after >= 0:
                prv[after] = a
            size = _heap_remove(heap, where, size, key, b)
            free[nfree[0]] = b
            nfree[0] += 1
            stats[0] += 1
            size = _schedule(a, now, heap, where, size, key, kind, nxt, xref, tref, vel)
        else:  # a (lower type) passes b: new ranks, new velocities (1.8) for their members only
            alpha, beta = kind[a], kind[b]
            place = 0.5 * (_position(a, now, xref, tref, vel) + _position(b, now, xref, tref, vel))
            row[:] = counts[a]
            row[beta] += high[b] - low[b]
            for k in range(low[a], high[a]):
                lam[alpha, k] = _speed(table, strides, alpha, k, row)
            row_b[:] = counts[b]
            row_b[alpha] -= high[a] - low[a]
            for k in range(low[b], high[b]):
                lam[beta, k] = _speed(table, strides, beta, k, row_b)
            stats[3] += high[a] - low[a] + high[b] - low[b]
            lo_a, hi_a, lo_b, hi_b = low[a], high[a], low[b], high[b]
            # The members of b and of a keep the ids b and a for their first blocks, filed anew below.
            first_b, last_b = _new_blocks(b, beta, lo_b, hi_b, place, now, row_b, lam, starts, sums, free, nfree, kind,
                                          low, high, xref, tref, vel, counts, prv, nxt)
            first_a, last_a = _new_blocks(a, alpha, lo_a, hi_a, place, now, row, lam, starts, sums, free, nfree, kind,
                                          low, high, xref, tref, vel, counts, prv, nxt)
            nxt[last_b], prv[first_a] = first_a, last_b
            prv[first_b], nxt[last_a] = before, after
            if before >= 0:
                nxt[before] = first_b
            else:
                head = first_b
            if after >= 0:
                prv[after] = last_a
            stats[1] += 1
            cluster = first_b
            while cluster != after:
                stats[2] += 1
                size = _schedule(cluster, now, heap, where, size, key, kind, nxt, xref, tref, vel)
                cluster = nxt[cluster]
            stats[2] -= 2  # the two clusters that passed each other are not new
        if before >= 0:
            size = _schedule(before, now, heap, where, size, key, kind, nxt, xref, tref, vel)


def _velocity_table(system, n: int, d: int) -> tuple[np.ndarray, np.ndarray, float]:
    """Velocities (1.8) at every rank, their strides and largest magnitude, after checking (USH).

    Row gamma holds lambda~^gamma_k for every k (axis gamma, n values) and every count of particles
    of each other type behind it (n + 1 values each), flattened in C order: the velocity of
    particle gamma:k with counts c is at sum_g strides[gamma, g] * (k if g == gamma else c_g).
    """
    if d * (n + 1) ** d > MAX_TABLE:
        raise ValueError(f"d = {d} types of n = {n} particles need a velocity table of d (n+1)^d = "
                         f"{d * (n + 1) ** d:.3g} values, more than MAX_TABLE = {MAX_TABLE:.0e}")
    shape = (n + 1,) * d
    levels = np.indices(shape).reshape(d, -1).T / n
    table = np.empty((d, n * (n + 1) ** (d - 1)))
    strides = np.empty((d, d), dtype=np.int64)
    lowest, highest = np.empty(d), np.empty(d)
    for gamma in range(d):
        speeds = n * np.diff(checked_primitive(system, gamma, levels).reshape(shape), axis=gamma)
        finite_result("the velocities (1.8)", speeds, "system.speed_primitive returned values whose differences "
                      "overflow or are not finite")
        table[gamma] = speeds.ravel()
        strides[gamma] = np.array(speeds.strides) // speeds.itemsize
        lowest[gamma], highest[gamma] = speeds.min(), speeds.max()
    for gamma in range(d - 1):
        if not lowest[gamma] > highest[gamma + 1:].max():
            raise ValueError(f"system violates (USH): a velocity (1.8) of type {gamma} ({lowest[gamma]:.6g}) is not "
                             f"above every velocity of the higher types (up to {highest[gamma + 1:].max():.6g})")
    return table, strides, float(max(np.abs(lowest).max(), np.abs(highest).max()))


def mspd_exact(x0, system, times, return_events: bool = False):
    """Exact MSPD (section 1.2.2) from the configuration ``x0`` at each of ``times``.

    Parameters
    ----------
    x0 : array (d, n), row gamma the sorted positions of the particles of type gamma (mass 1/n).
    system : a diagonal system (integer ``d``, method ``speed_primitive(gamma, levels)``, as in
        :mod:`.mspd`) satisfying (USH) with types ordered fastest first.
    times : non-decreasing, non-negative times.
    return_events : also return the :class:`EventCounts` up to the last time.

    Returns
    -------
    Array (len(times), d, n) of configurations, and the event counts if asked.
    """
    x0 = checked_configuration("x0", x0, system)
    times = finite_array("times", times)
    if times.size == 0:
        raise ValueError("times must contain at least one time")
    if times[0] < 0 or np.any(np.diff(times) < 0):
        raise ValueError("times must be non-negative and non-decreasing")
    d, n = x0.shape
    bound = d * (d - 1) // 2 * n * n + d * n
    if bound > MAX_EVENTS:
        raise ValueError(f"d = {d} types of n = {n} particles may need up to {bound:.3g} events, more than "
                         f"MAX_EVENTS = {MAX_EVENTS:.0e}")
    instance("return_events", return_events, (bool, np.bool_))
    table, strides, speed = _velocity_table(system, n, d)
    check_reach(x0, speed, float(times[-1]), "times", "velocities")
    out = np.empty((times.size, d, n))
    stats = np.zeros(4, dtype=np.int64)
    _simulate(x0, ranks_kernel(x0), table, strides, times, out, stats)
    if return_events:
        return out, EventCounts(*(int(s) for s in stats))
    return out
