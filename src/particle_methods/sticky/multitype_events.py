"""Exact multitype sticky particle dynamics by event-driven simulation (sections 1.2.2, 5.2).

The MSPD moves clusters at constant velocities between events. Particles of one type that meet
stick (the TSPD of that type, section 1.2.2); particles of different types that meet cross, and
the TSPD restarts with the velocities (1.8) of the new ranks. Section 5.2 argues that the number
of such events is of order n^2 and leaves the exact algorithm aside; it is built here.

Data structure: one list of clusters of all types ordered along the line, a tie at one place
being ordered by decreasing type (the post-collisional order of (USH), as in
:func:`~particle_methods.sticky.mspd.ranks_kernel`). Trajectories are straight between events, so the
next meeting is between neighbours of this list: the time at which each cluster meets the next one
is filed in an indexed binary heap, which holds the times beside the cluster ids. At an event:

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

Velocities (1.8) are differences of the primitive P_gamma of lambda^gamma in its own variable:
lambda~^gamma_k = n (P_gamma(.., k/n, ..) - P_gamma(.., (k-1)/n, ..)), the other levels being the
counts of the other types behind the particle over n, as in :mod:`.mspd`. They are computed when
an event needs them, at the ranks of that event only: at the start for every particle, then at a
crossing for the members of its two clusters, m + 1 values of the primitive for a cluster of m
members. No velocity is kept for ranks that no particle occupies (a table over every rank held
d (n+1)^d of them), so a run holds O(d^2 n) words: d n clusters with their d counts each, as many
as the ranks of :func:`~particle_methods.sticky.mspd.ranks_kernel`; for d = 2, 86 bytes per
particle (the ids and counts in 32 bits: :data:`MAX_EVENTS` keeps d n far below 2^31). For a
:class:`~particle_methods.systems.PSystem` the primitive is evaluated inside the compiled event loop
(:func:`~particle_methods.systems.speed_primitive_formula`, with libm's sinh and atan where NumPy has its own:
the results agree to rounding). Its variable is the spread
w^+ - w^- = (i - j)/n of two counts, as the loop rounds it, fl(i/n) - fl(j/n): a few doubles for
each of the 2 n + 1 differences i - j. A table of 2 n + 1 rows keeps the values computed for the
last :data:`PRIMITIVE_WAYS` doubles of each difference (64 more bytes per particle), so the loop
evaluates each double about once (at n = 3200, 8.9e4 and 2.3e4 evaluations in the rarefaction and shock
cases for 1.8e7 and 1.9e7 without it), and a kept value is the one it would compute anew: the table
changes no bit. Any other system's
``speed_primitive`` is a Python method: the loop leaves the compiled kernel at each crossing for
it and resumes there (:data:`MAX_PYTHON_EVENTS`). (USH) is checked on every velocity the run
computes: each must be above every velocity of the higher types computed so far and below those of
the lower types, else the call stops with a ValueError. That is what the algorithm relies on: a
cluster of a higher type behind one of a lower type never catches up with it.

By (USH) every pair of particles of different types crosses at most once, so there are at most
d(d-1)n^2/2 crossings (section 5.2). A crossing of clusters a and b makes |a| |b| pairs cross and
costs O(|a| + |b|) <= O(|a| |b| + 1) member updates and blocks, and a merge undoes one block: every
count of :class:`EventCounts` is O(d^2 n^2). A call is refused when the crossing bound
d(d-1)n^2/2 + d n exceeds :data:`MAX_EVENTS`.

At one time and for two types, :func:`mspd_exact_at` computes the same configuration over the grid of
crossings where particles of one type never meet (the section below :func:`mspd_exact`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..jit import NO_RUNTIME, njit
from ..systems import PSystem, checked_primitive, speed_primitive_formula
from ..validation import finite_array, finite_number, finite_result, instance, integer_at_least
from .mspd import checked_configuration, ranks_kernel
from .spd import MAX_POSITIONS, check_reach

#: Largest crossing bound d(d-1) n^2 / 2 + d n one call accepts: n = 26,456 per type for d = 2, above the
#: cost study's reference (25,600 per type). On an AMD EPYC (AVX2, 2 cores, shared: load average 2.0) the
#: p-system cases with n = 6400 per type took 4.8 s (rarefaction, 1.8e7 crossings, 0.26 us each) and 2.8 s
#: (shocks, 1.3e7 crossings, 0.22 us) up to t = 2 (benchmarks/bench_mspd_exact.py). A crossing costs more
#: at larger n, as the heap and the clusters leave the caches (before the heap and table of issue 47: 0.40 us
#: at n = 6400, 0.65 us in the pipeline's jobs at n = 25,600 and 12,800; with 64-bit ids and a table of 8
#: values a difference, 0.54 to 0.58 us for the shock case at 25,600 alone, 0.35 to 0.47 us with the 32-bit
#: ids and 4 values kept), so the n^2 count of crossings gives a lower bound: over 75 s for the rarefaction
#: case's event loop at n = 25,600, over 3 minutes for a run reaching the bound. Memory is no limit: 150 bytes
#: per particle.
MAX_EVENTS = 7 * 10**8

#: Largest crossing bound d(d-1) n^2 / 2 for a system whose ``speed_primitive`` is Python (any but a
#: :class:`~particle_methods.systems.PSystem`): each crossing then costs two calls of it from Python,
#: about 55 us, so 10**6 crossings take about a minute (n = 1000 per type for d = 2).
MAX_PYTHON_EVENTS = 10**6

_NONE = -1


class _Counts(NamedTuple):

    merges: int
    """meetings of two clusters of one type, which stick"""
    crossings: int
    """meetings of clusters of different types, which pass each other"""
    splits: int
    """clusters created by the splitting of a cluster after a crossing"""
    member_updates: int
    """velocities (1.8) recomputed at crossings: the work of the crossings"""


class EventCounts(_Counts):
    """Events processed by :func:`mspd_exact` up to its last requested time: counts, non-negative integers."""

    __slots__ = ()

    def __new__(cls, merges, crossings, splits, member_updates):
        counts = (merges, crossings, splits, member_updates)
        return super().__new__(cls, *(integer_at_least(name, value, 0) for name, value in zip(cls._fields, counts)))


_primitive_formula = njit(speed_primitive_formula)


#: Values of the primitive the compiled loops keep per difference of counts (:func:`_primitive_of_spread`): a row
#: of 4 (spread, value) pairs is one 64-byte cache line, the table 128 n bytes. With 8 (128 bytes a row) the loops
#: evaluated the primitive least (at n = 3200, 1.1e4 times in the rarefaction case and 2.2e4 in the shock case;
#: 8.9e4 and 2.3e4 with 4, 2.7e6 and 9.6e5 with 2), but at n = 25,600 its 6.5 MB table left the caches. Measured
#: there on an AMD EPYC (AVX2, 2 cores; benchmarks/README.md): the shock case's event loop took 113 to 120 s with
#: 8 values, 74 to 97 s with 4 and 72 to 86 s with 2; the rarefaction case's grid 15.7 to 17.1 s, 13.5 to 16.8 s
#: and 19.2 to 19.9 s.
PRIMITIVE_WAYS = 4


def _primitive_table(n: int) -> np.ndarray:
    """The table of :func:`_primitive_of_spread` for n particles per type: 2 n + 1 rows (the differences of counts
    -n..n) of :data:`PRIMITIVE_WAYS` (spread, value) pairs, empty (NaN equals no spread)."""
    return np.full((2 * n + 1, 2 * PRIMITIVE_WAYS), np.nan)


@njit(inline="always")
def _primitive_of_spread(spread, difference, table, a, coefficient):
    """coefficient * atan(sinh(a spread)) for spread = (i - j)/n as the loop rounds it, fl(i/n) - fl(j/n): the
    value kept in row ``difference`` = i - j + n of ``table`` (pairs spread, value, most recent first) for the
    same double, else computed and kept. Rounding makes a few doubles of one difference (up to 16 at n = 6400);
    a kept value is the one evaluated anew. A spread is never -0.0 (x - x is +0.0), so == compares the bits."""
    for way in range(PRIMITIVE_WAYS):
        if table[difference, 2 * way] == spread:
            return table[difference, 2 * way + 1]
    value = _primitive_formula(spread, a, coefficient)
    for slot in range(2 * PRIMITIVE_WAYS - 1, 1, -1):
        table[difference, slot] = table[difference, slot - 2]
    table[difference, 0], table[difference, 1] = spread, value
    return value


@njit(inline="always")
def _primitive(i, j, n, table, a, coefficient):
    """The p-system's primitive P (5.7) at the w^+ level i/n and the w^- level j/n, of the spread w^+ - w^- as
    the loops round it, fl(i/n) - fl(j/n), through ``table`` (:func:`_primitive_of_spread`, row i - j + n)."""
    return _primitive_of_spread(i / n - j / n, i - j + n, table, a, coefficient)


@njit(inline="always")
def _psystem_speeds(a, coefficient, gamma, lo, hi, row, lam, table):
    """Velocities (1.8) lam[gamma, lo:hi] of the p-system's particles gamma:lo .. gamma:hi-1 with ``row[g]``
    particles of type g behind them, from the m + 1 = hi - lo + 1 values of the primitive of (5.7) in its own
    variable, P = coefficient * atan(sinh(a (w^+ - w^-))), at the own levels lo/n .. hi/n: particle k moves
    at n (P((k+1)/n) - P(k/n)), the other level being (its count)/n. Type 0 is w^-, type 1 is w^+
    (:func:`_primitive`)."""
    n = lam.shape[1]
    count = row[1 - gamma]
    below = 0.0
    for k in range(lo, hi + 1):
        if gamma == 0:
            above = _primitive(count, k, n, table, a, coefficient)
        else:
            above = _primitive(k, count, n, table, a, coefficient)
        if k > lo:
            lam[gamma, k - 1] = n * (above - below)
        below = above


@njit(inline="always")
def _record_speeds(lam, gamma, lo, hi, extremes, report):
    """Fold the velocities lam[gamma, lo:hi] into the extremes (row 0 lowest, row 1 highest per type) and
    check (USH) when one moved: every velocity of a type above every velocity of each higher type. Returns
    False (the offending lower type, its lowest and the higher types' highest velocity in ``report``) if not."""
    lowest, highest = extremes[0, gamma], extremes[1, gamma]
    for k in range(lo, hi):
        speed = lam[gamma, k]
        if not speed == speed:  # NaN: no order at all
            report[0], report[1], report[2] = gamma, speed, speed
            return False
        lowest = min(lowest, speed)
        highest = max(highest, speed)
    if lowest == extremes[0, gamma] and highest == extremes[1, gamma]:
        return True  # nothing new: the check made when these extremes were reached holds
    extremes[0, gamma], extremes[1, gamma] = lowest, highest
    d = extremes.shape[1]
    for lower in range(d - 1):
        fastest_above = -np.inf
        for higher in range(lower + 1, d):
            fastest_above = max(fastest_above, extremes[1, higher])
        if not extremes[0, lower] > fastest_above:
            report[0], report[1], report[2] = lower, extremes[0, lower], fastest_above
            return False
    return True


@njit(inline="always")
def _position(cluster, t, xref, tref, vel):
    return xref[cluster] + vel[cluster] * (t - tref[cluster])


@njit(inline="always")
def _heap_place(heap, hkey, where, size, i, cluster, value):
    """File ``cluster`` with meeting time ``value`` in the heap from the free slot i (its old slot, or the end
    of the heap): the entries it passes move into the hole, up while their parent's time is larger, else
    down while the smaller child's time is smaller (the left child on a tie). The times sit in the heap
    beside the ids (``hkey``, +inf beyond the last entry), so a comparison reads no cluster, and the right
    child is read without a test of the size."""
    moved = False
    while i > 0:
        parent = (i - 1) >> 1
        if not hkey[parent] > value:
            break
        entry = heap[parent]
        heap[i], hkey[i], where[entry] = entry, hkey[parent], i
        i, moved = parent, True
    while not moved:
        child = 2 * i + 1
        if child >= size:
            break
        child += hkey[child + 1] < hkey[child]
        if not hkey[child] < value:
            break
        entry = heap[child]
        heap[i], hkey[i], where[entry] = entry, hkey[child], i
        i = child
    heap[i], hkey[i], where[cluster] = cluster, value, i


@njit(inline="always")
def _heap_update(heap, hkey, where, size, cluster, value):
    """File ``cluster`` with the meeting time ``value``, in the heap or not yet. Returns the size."""
    i = where[cluster]
    if i < 0:
        i = size
        size += 1
    _heap_place(heap, hkey, where, size, i, cluster, value)
    return size


@njit(inline="always")
def _heap_remove(heap, hkey, where, size, cluster):
    """Remove ``cluster`` from the heap if present: the last entry fills its slot. Returns the size."""
    i = where[cluster]
    if i < 0:
        return size
    size -= 1
    where[cluster] = -1
    last, value = heap[size], hkey[size]
    hkey[size] = np.inf
    if i < size:
        _heap_place(heap, hkey, where, size, i, last, value)
    return size


@njit(inline="always")
def _meeting_time(a, now, kind, nxt, xref, tref, vel):
    """Time at which cluster a meets the next cluster of the list (inf if never)."""
    b = nxt[a]
    if b < 0 or not (kind[a] <= kind[b] and vel[a] > vel[b]):
        return np.inf  # a higher type ahead of a lower one, or no approach: they never meet
    gap = max(_position(b, now, xref, tref, vel) - _position(a, now, xref, tref, vel), 0.0)
    return now + gap / (vel[a] - vel[b])


@njit(inline="always")
def _schedule(a, now, heap, hkey, where, size, kind, nxt, xref, tref, vel):
    """File cluster a in the heap with the time it meets the next one (out of it if never). Returns the size."""
    time = _meeting_time(a, now, kind, nxt, xref, tref, vel)
    if time < np.inf:
        return _heap_update(heap, hkey, where, size, a, time)
    return _heap_remove(heap, hkey, where, size, a)


@njit(inline="always")
def _append(last, cluster, prv, nxt):
    """Chain ``cluster`` after ``last`` in the list; True if it starts the list (last = -1)."""
    prv[cluster], nxt[cluster] = last, _NONE
    if last >= 0:
        nxt[last] = cluster
    return last < 0


@njit(inline="always")
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


@njit(inline="always")
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
        for g in range(count_row.size):
            counts[cluster, g] = count_row[g]
        if _append(last, cluster, prv, nxt):
            first = cluster
        last = cluster
    return first, last


#: Values returned by :func:`_start` and :func:`_advance`.
_DONE, _NEEDS_SPEEDS, _VIOLATES_USH = 0, 1, 2
#: Slots of their ``state``: the heap's size, the head of the list, the next time to write, the stage, the
#: number of free cluster ids.
_SIZE, _HEAD, _INDEX, _STAGE, _FREE = 0, 1, 2, 3, 4
#: Stages of :func:`_advance`: running, running with the speeds of the pending crossing supplied.
_RUNNING, _SUPPLIED = 0, 1


@njit
def _start(x0, ranks, lam, clusters, motion, counts, starts, sums, rows, state, extremes, report):
    """Clusters of the configuration x0 (shape (d, n)) with the velocities (1.8) ``lam`` at its ``ranks``
    (:func:`~particle_methods.sticky.mspd.ranks_kernel`): the blocks of each group of particles of one type at
    one place, in one list along the line, each filed in the heap with its meeting time (arrays of
    :func:`_advance`). Returns ``_DONE``, or ``_VIOLATES_USH`` (:func:`_record_speeds`) on the velocities."""
    d, n = x0.shape
    kind, low, high, prv, nxt, heap, where, free = clusters
    xref, tref, vel, hkey = motion
    row = rows[0]
    for gamma in range(d):
        if not _record_speeds(lam, gamma, 0, n, extremes, report):
            return _VIOLATES_USH
    nfree = state[_FREE:_FREE + 1]
    # Initial clusters: the blocks of each group of particles of one type at one place.
    by_type = np.empty((d, n), dtype=np.int64)  # clusters of each type, in order
    found = np.zeros(d, dtype=np.int64)
    for gamma in range(d):
        lo = 0
        while lo < n:
            hi = lo + 1
            while hi < n and x0[gamma, hi] == x0[gamma, lo]:
                hi += 1
            for g in range(d):  # element by element: a slice copy compiles numba's shape-mismatch error (1.5 s)
                row[g] = ranks[gamma, lo, g]
            first, last = _new_blocks(_NONE, gamma, lo, hi, x0[gamma, lo], 0.0, row, lam, starts, sums, free,
                                      nfree, kind, low, high, xref, tref, vel, counts, prv, nxt)
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
    size = 0
    cluster = head
    while cluster >= 0:
        size = _schedule(cluster, 0.0, heap, hkey, where, size, kind, nxt, xref, tref, vel)
        cluster = nxt[cluster]
    state[_SIZE], state[_HEAD], state[_INDEX] = size, head, 0
    return _DONE


@njit(**NO_RUNTIME)
def _advance(x0, lam, times, out, stats, clusters, motion, counts, starts, sums, rows, behind, state, request,
             extremes, report, constants, compiled, table):
    """Event loop of the MSPD from x0 (shape (d, n)) with the initial velocities (1.8) ``lam``, writing the
    configuration at each of ``times`` (non-decreasing) to ``out``; ``stats`` receives the :class:`EventCounts`.

    With ``compiled`` (a p-system, constants (a, -A/a)) a crossing's velocities are computed here by
    :func:`_psystem_speeds`, with the primitive's ``table``. Otherwise the loop returns ``_NEEDS_SPEEDS`` at
    each crossing, with its two clusters in ``request`` (type, first and end member, for a then b) and their
    counts behind in ``rows``; the caller writes their velocities into ``lam``, sets the stage to
    ``_SUPPLIED`` and calls again: the loop resumes at the same event (nothing has moved) from ``state``.
    Returns ``_DONE``, or ``_VIOLATES_USH`` (see :func:`_record_speeds`) before using a velocity that breaks
    (USH). The arrays of ``clusters`` (kind, first member, end member, previous, next, heap, heap slot, free
    ids), ``motion`` (reference place and time, velocity; then the heap's meeting times, one per slot of the
    heap and +inf beyond its last entry) and ``counts`` have one row per cluster, at most d n of them.
    Compiled without numba's runtime (:data:`~particle_methods.jit.NO_RUNTIME`): it creates no array, and its
    helpers are inlined. With the runtime, the atomic reference counts of the arrays passed to its helpers
    took half of its time (perf): it ran 2.4 times slower with the helpers
    inlined, about 5 times without (n = 3200 per type)."""
    d, n = x0.shape
    kind, low, high, prv, nxt, heap, where, free = clusters
    xref, tref, vel, hkey = motion
    row, row_b = rows[0], rows[1]
    nfree = state[_FREE:_FREE + 1]
    size, head, index = state[_SIZE], state[_HEAD], state[_INDEX]
    supplied = state[_STAGE] == _SUPPLIED
    state[_STAGE] = _RUNNING
    while index < times.size:
        event_time = hkey[0] if size > 0 else np.inf
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
            size = _heap_remove(heap, hkey, where, size, b)
            free[nfree[0]] = b
            nfree[0] += 1
            stats[0] += 1
            size = _schedule(a, now, heap, hkey, where, size, kind, nxt, xref, tref, vel)
        else:  # a (lower type) passes b: new ranks, new velocities (1.8) for their members only
            alpha, beta = kind[a], kind[b]
            lo_a, hi_a, lo_b, hi_b = low[a], high[a], low[b], high[b]
            if supplied:  # the caller computed them for this very event (rows and lam are set)
                supplied = False
            else:
                for g in range(d):  # element by element: a copy of a row would need an allocation
                    row[g], row_b[g] = counts[a, g], counts[b, g]
                row[beta] += hi_b - lo_b
                row_b[alpha] -= hi_a - lo_a
                if compiled:
                    _psystem_speeds(constants[0], constants[1], alpha, lo_a, hi_a, row, lam, table)
                    _psystem_speeds(constants[0], constants[1], beta, lo_b, hi_b, row_b, lam, table)
                else:
                    request[0], request[1], request[2] = alpha, lo_a, hi_a
                    request[3], request[4], request[5] = beta, lo_b, hi_b
                    state[_SIZE], state[_HEAD], state[_INDEX] = size, head, index
                    return _NEEDS_SPEEDS
            if not (_record_speeds(lam, alpha, lo_a, hi_a, extremes, report)
                    and _record_speeds(lam, beta, lo_b, hi_b, extremes, report)):
                return _VIOLATES_USH
            place = 0.5 * (_position(a, now, xref, tref, vel) + _position(b, now, xref, tref, vel))
            stats[3] += hi_a - lo_a + hi_b - lo_b
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
                size = _schedule(cluster, now, heap, hkey, where, size, kind, nxt, xref, tref, vel)
                cluster = nxt[cluster]
            stats[2] -= 2  # the two clusters that passed each other are not new
        if before >= 0:
            size = _schedule(before, now, heap, hkey, where, size, kind, nxt, xref, tref, vel)
    state[_SIZE], state[_HEAD], state[_INDEX] = size, head, index
    return _DONE


class _Run(NamedTuple):
    """Arrays of one run of :func:`_start` and :func:`_advance`: O(d^2 n) words in all (:meth:`nbytes`),
    nothing per rank that no particle occupies."""

    lam: np.ndarray
    clusters: tuple
    motion: tuple
    counts: np.ndarray
    starts: np.ndarray
    sums: np.ndarray
    rows: np.ndarray
    behind: np.ndarray
    state: np.ndarray
    request: np.ndarray
    extremes: np.ndarray
    report: np.ndarray
    table: np.ndarray

    @classmethod
    def allocate(cls, lam: np.ndarray, compiled: bool) -> _Run:
        """The arrays for the velocities ``lam`` (d, n); with ``compiled`` (a p-system) the table of the primitive's
        values (:func:`_primitive_of_spread`), 2 n + 1 rows of 2 :data:`PRIMITIVE_WAYS` doubles. Ids, members and
        counts are 32-bit (below d n <= :data:`MAX_EVENTS`): with 64-bit ones and a table of 8 values a difference,
        the shock case at n = 25,600 per type ran 1.2 to 1.5 times as long as now, its arrays out of the caches."""
        d, n = lam.shape
        capacity = d * n  # at most one cluster per particle
        ints = [np.empty(capacity, dtype=np.int32) for _ in range(6)]  # kind, low, high, prv, nxt, heap
        where = np.full(capacity, -1, dtype=np.int32)
        free = np.arange(capacity - 1, -1, -1, dtype=np.int32)
        state = np.zeros(5, dtype=np.int64)
        state[_STAGE], state[_FREE] = _RUNNING, capacity
        extremes = np.empty((2, d))
        extremes[0], extremes[1] = np.inf, -np.inf
        motion = (*(np.empty(capacity) for _ in range(3)), np.full(capacity + 1, np.inf))  # xref, tref, vel, hkey
        return cls(lam, (*ints, where, free), motion,
                   np.empty((capacity, d), dtype=np.int32), np.empty(n, dtype=np.int32), np.empty(n),
                   np.empty((2, d), dtype=np.int64), np.empty(d), state, np.empty(6, dtype=np.int64), extremes,
                   np.empty(3),
                   _primitive_table(n) if compiled else np.empty((0, 2 * PRIMITIVE_WAYS)))

    def nbytes(self) -> int:
        """Bytes held by the run's arrays (the velocities included)."""
        arrays = [self.lam, *self.clusters, *self.motion, self.counts, self.starts, self.sums, self.rows, self.behind,
                  self.state, self.request, self.extremes, self.report, self.table]
        return sum(array.nbytes for array in arrays)


def _python_speeds(system, gamma: int, lo: int, hi: int, row: np.ndarray, n: int) -> np.ndarray:
    """Velocities (1.8) of particles gamma:lo .. gamma:hi-1 with ``row[g]`` particles of type g behind them,
    from ``system.speed_primitive`` at the hi - lo + 1 levels (own count)/n, (counts of the others)/n."""
    levels = np.empty((hi - lo + 1, row.size))
    levels[:] = row / n
    levels[:, gamma] = np.arange(lo, hi + 1) / n
    speeds = n * np.diff(checked_primitive(system, gamma, levels))
    return finite_result("the velocities (1.8)", speeds, "system.speed_primitive returned values whose differences "
                         "overflow or are not finite")


def _initial_speeds(system, ranks: np.ndarray) -> np.ndarray:
    """Velocities (1.8) at the ``ranks`` of x0 (:func:`~particle_methods.sticky.mspd.ranks_kernel`): for each
    type, the primitive at every particle's levels, own count k + 1 and k, two calls of ``speed_primitive``."""
    d, n = ranks.shape[:2]
    lam = np.empty((d, n))
    for gamma in range(d):
        upper = ranks[gamma]
        lower = upper.copy()
        lower[:, gamma] -= 1
        lam[gamma] = n * (checked_primitive(system, gamma, upper / n) - checked_primitive(system, gamma, lower / n))
    return finite_result("the velocities (1.8)", lam, "system.speed_primitive returned values whose differences "
                         "overflow or are not finite")


def _compiled_system(system) -> bool:
    """True for a :class:`PSystem` whose primitive is the class's own (d = 2): the event loop evaluates it
    compiled, by :func:`_psystem_speeds`."""
    return (isinstance(system, PSystem) and type(system).speed_primitive is PSystem.speed_primitive
            and system.d == 2)


def mspd_exact(x0, system, times, return_events: bool = False):
    """Exact MSPD (section 1.2.2) from the configuration ``x0`` at each of ``times``.

    Velocities (1.8) come from the primitive at the ranks each event needs (module docstring): memory
    O(d^2 n), no table over the (n+1)^d rank points.

    Parameters
    ----------
    x0 : array (d, n), row gamma the sorted positions of the particles of type gamma (mass 1/n).
    system : a diagonal system (integer ``d``, method ``speed_primitive(gamma, levels)``, as in
        :mod:`.mspd`) satisfying (USH) with types ordered fastest first. A
        :class:`~particle_methods.systems.PSystem` runs compiled up to :data:`MAX_EVENTS`; any other
        system calls its ``speed_primitive`` from Python at each crossing, up to :data:`MAX_PYTHON_EVENTS`.
    times : non-decreasing, non-negative times.
    return_events : also return the :class:`EventCounts` up to the last time.

    Returns
    -------
    Array (len(times), d, n) of configurations, and the event counts if asked.

    Raises ValueError if a velocity the run computes breaks (USH) (checked on every one, against those of
    the other types computed before) or could carry a particle beyond the double range by the last time.
    """
    # Contiguous copies: the compiled kernels would be compiled again for any other layout (12 s).
    x0 = np.ascontiguousarray(checked_configuration("x0", x0, system))
    times = np.ascontiguousarray(finite_array("times", times))
    if times.size == 0:
        raise ValueError("times must contain at least one time")
    if times[0] < 0 or np.any(np.diff(times) < 0):
        raise ValueError("times must be non-negative and non-decreasing")
    d, n = x0.shape
    if times.size * x0.size > MAX_POSITIONS:
        raise ValueError(f"{times.size} times of {x0.size} particles give {times.size * x0.size:.3g} positions, more "
                         f"than MAX_POSITIONS = {MAX_POSITIONS:.0e} in one call: split the times")
    compiled = _compiled_system(system)
    crossings = d * (d - 1) // 2 * n * n
    if crossings + d * n > MAX_EVENTS:
        raise ValueError(f"d = {d} types of n = {n} particles may need up to {crossings + d * n:.3g} events, more "
                         f"than MAX_EVENTS = {MAX_EVENTS:.2g}")
    if not compiled and crossings > MAX_PYTHON_EVENTS:
        raise ValueError(f"d = {d} types of n = {n} particles may need up to {crossings:.3g} crossings, more than "
                         f"MAX_PYTHON_EVENTS = {MAX_PYTHON_EVENTS:.0e} for a system whose speed_primitive is Python "
                         "(called at each crossing; a PSystem runs compiled up to MAX_EVENTS)")
    instance("return_events", return_events, (bool, np.bool_))
    last = float(times[-1])
    ranks = ranks_kernel(x0)[0]
    lam = _initial_speeds(system, ranks)
    # Every velocity (1.8) of the p-system is an average of lambda^gamma, at most A = speed_scale in
    # magnitude; the rounding of n (P((k+1)/n) - P(k/n)) adds about 8 n eps |P| with |P| <= A
    # (|atan(sinh(y))| <= |y|), below A for any n accepted: 2 A bounds every velocity the run computes.
    check_reach(x0, 2.0 * system.speed_scale if compiled else float(np.abs(lam).max()), last, "times", "velocities",
                position_name="x0")
    run = _Run.allocate(lam, compiled)
    status = _start(x0, ranks, run.lam, run.clusters, run.motion, run.counts, run.starts, run.sums, run.rows, run.state,
                    run.extremes, run.report)
    del ranks
    constants = np.array([system.a, system.primitive_coefficient]) if compiled else np.zeros(2)
    out = np.empty((times.size, d, n))
    stats = np.zeros(4, dtype=np.int64)
    while status != _VIOLATES_USH:
        status = _advance(x0, run.lam, times, out, stats, run.clusters, run.motion, run.counts, run.starts, run.sums,
                          run.rows, run.behind, run.state, run.request, run.extremes, run.report, constants, compiled,
                          run.table)
        if status != _NEEDS_SPEEDS:
            break
        for (gamma, lo, hi), row in zip(run.request.reshape(2, 3), run.rows):
            run.lam[gamma, lo:hi] = _python_speeds(system, int(gamma), int(lo), int(hi), row, n)
            check_reach(x0, float(np.abs(run.lam[gamma, lo:hi]).max()), last, "times", "velocities",
                        position_name="x0")
        run.state[_STAGE] = _SUPPLIED
    if status == _VIOLATES_USH:
        lower, lowest, highest = run.report
        raise ValueError(f"system violates (USH): a velocity (1.8) of type {int(lower)} ({lowest:.6g}) is not above "
                         f"every velocity of the higher types (up to {highest:.6g})")
    if return_events:
        return out, EventCounts(*(int(s) for s in stats))
    return out


# --------------------------------------------------------------------------------------------------------------
# The exact MSPD of two types at one time over the grid of its crossings (sections 1.2.2, 5.2).
#
# Where no two particles of one type ever meet (the p-system's rarefaction case of section 5.2.2, for one), every
# cluster of :func:`mspd_exact` is one particle, and a particle's velocity (1.8) changes only when it crosses a
# particle of the other type. Number the particles of type 0 (the faster, by (USH)) k = 0..n-1 and those of type 1
# i = 0..n-1 along the line. Type-0 particle k passes the type-1 particles ahead of it in the order i = c_k,
# c_k + 1, ..., and type-1 particle i is passed by the type-0 particles behind it in the order k = e_i - 1,
# e_i - 2, ... (c_k, e_i: the counts of the other type behind them at the start). So the crossing E(k, i) needs
# only two earlier ones: E(k, i - 1), after which particle k moves straight at its velocity with i particles of
# type 1 behind it, and E(k + 1, i), after which particle i moves straight at its velocity with k + 1 particles of
# type 0 behind it. Its time and place follow from theirs. The crossings that happen before t are computed row by
# row over this grid, at O(1) work each and with O(n) memory, with no event queue: at n = 25,600 per type the
# rarefaction case (about 3e8 crossings) takes about 20 s instead of 220 to 312 s (benchmarks/bench_mspd_grid.py).
#
# Every crossing is computed with the floating-point operations of the event loop (its meeting time from the later
# of the two particles' last events, its place the mean of their positions, the velocities (1.8) by the same
# compiled primitive), so the two agree to rounding. They need not agree bit for bit, as the event loop may file a
# meeting from a later event of a neighbour; they did at every n measured on the rarefaction case, 1 to 25,600 per
# type, and on every random draw the grid took (tests/sticky/test_mspd_grid.py, benchmarks/README.md).
#
# Whether particles of one type meet is decided on the run itself. The pass by rows walks each type-0 particle's
# trajectory beside that of the type-0 particle ahead of it and checks their gap at every breakpoint of either
# trajectory, where the gap, piecewise linear in time, takes its smallest values; a second pass, column by column,
# does the same for type 1 and must give the same configuration. Where a gap closes, where particles of one type
# start at one place, where a velocity breaks (USH), or for any other system than a two-type
# :class:`~particle_methods.systems.PSystem`, :func:`mspd_exact_at` runs :func:`mspd_exact` instead.


@njit(inline="always")
def _meeting(ta, xa, va, tb, xb, vb):
    """Time at which a type-0 particle, at xa at time ta with velocity va, meets the type-1 particle ahead of it,
    at xb at time tb with velocity vb < va: from the later of the two times, as the event loop's meeting time."""
    start = max(ta, tb)
    gap = max((xb + vb * (start - tb)) - (xa + va * (start - ta)), 0.0)
    return start + gap / (va - vb)


@njit
def _rows(x0, start_speeds, behind, t, constants, table, lam, out, extremes):
    """Pass over the grid row by row: type-0 particles from the right (k = n-1 .. 0), each through the type-1
    particles it passes before t. Writes the positions at t to ``out`` and the lowest type-0 and highest type-1
    velocity computed to ``extremes``; returns the crossings made, or -1 if two type-0 particles meet (their
    gap is checked at every breakpoint of either trajectory) or a meeting pair's velocities break (USH)."""
    n = x0.shape[1]
    lam[:] = start_speeds
    # Type-1 particles: time, place and count of type-0 particles behind them, at their last crossing.
    t1, x1, count1 = np.zeros(n), x0[1].copy(), behind[1].copy()
    # The trajectory of the type-0 particle ahead (k + 1), as breakpoints in time order, and the current row's.
    trail = np.empty((2, 3, n))
    ends = np.zeros(2, dtype=np.int64)
    crossings = 0
    for k in range(n - 1, -1, -1):
        mine, ahead = trail[k % 2], trail[(k + 1) % 2]
        ta, xa, va, i = 0.0, x0[0, k], lam[0, k], behind[0, k]
        extremes[0] = min(extremes[0], va)
        filled, walked, st, sx, sv, front = 0, 0, 0.0, 0.0, 0.0, 0.0
        if k + 1 < n:
            sx, sv = x0[0, k + 1], start_speeds[0, k + 1]
        while True:
            t_new, vb = np.inf, 0.0
            if i < n and count1[i] == k + 1:  # i is the next of type 1 ahead of k, and k the next behind i
                vb = lam[1, i]
                if not va > vb:
                    return -1
                t_new = _meeting(ta, xa, va, t1[i], x1[i], vb)
            stop = min(t_new, t)
            if k + 1 < n:
                while walked < ends[(k + 1) % 2] and ahead[0, walked] < stop:
                    if not xa + va * (ahead[0, walked] - ta) < ahead[1, walked]:
                        return -1
                    st, sx, sv = ahead[0, walked], ahead[1, walked], ahead[2, walked]
                    walked += 1
                front = sx + sv * (stop - st)
            if not t_new < t:  # a crossing at t itself comes after the configuration at t, as in the event loop
                out[0, k] = xa + va * (t - ta)
                if k + 1 < n and not out[0, k] <= front:
                    return -1
                break
            place = 0.5 * ((xa + va * (t_new - ta)) + (x1[i] + vb * (t_new - t1[i])))
            if k + 1 < n and not place < front:
                return -1
            # the velocities (1.8) after the crossing: k with i + 1 of type 1 behind it, i with k of type 0
            here = _primitive(i + 1, k, n, table, constants[0], constants[1])
            va = n * (_primitive(i + 1, k + 1, n, table, constants[0], constants[1]) - here)
            lam[1, i] = n * (here - _primitive(i, k, n, table, constants[0], constants[1]))
            ta, xa, lam[0, k] = t_new, place, va
            extremes[0], extremes[1] = min(extremes[0], va), max(extremes[1], lam[1, i])
            mine[0, filled], mine[1, filled], mine[2, filled] = ta, xa, va
            filled += 1
            t1[i], x1[i], count1[i] = t_new, place, k
            crossings += 1
            i += 1
        ends[k % 2] = filled
    for i in range(n):
        extremes[1] = max(extremes[1], start_speeds[1, i])
        out[1, i] = x1[i] + lam[1, i] * (t - t1[i])
    return crossings


@njit
def _columns(x0, start_speeds, behind, t, constants, table, lam, out):
    """The same crossings column by column: type-1 particles from the left (i = 0 .. n-1), each passed by the
    type-0 particles behind it before t, with the gap of each type-1 particle to the one behind it checked at
    every breakpoint of either trajectory. Each crossing is computed from the same two earlier ones, by the same
    operations, as in :func:`_rows`. Returns the crossings made, or -1 if two type-1 particles meet."""
    n = x0.shape[1]
    lam[:] = start_speeds
    t0, x0_, count0 = np.zeros(n), x0[0].copy(), behind[0].copy()
    trail = np.empty((2, 3, n))
    ends = np.zeros(2, dtype=np.int64)
    crossings = 0
    for i in range(n):
        mine, back = trail[i % 2], trail[(i + 1) % 2]
        tb, xb, vb, k = 0.0, x0[1, i], lam[1, i], behind[1, i] - 1
        filled, walked, st, sx, sv, rear, va = 0, 0, 0.0, 0.0, 0.0, 0.0, 0.0
        if i > 0:
            sx, sv = x0[1, i - 1], start_speeds[1, i - 1]
        while True:
            t_new = np.inf
            if k >= 0 and count0[k] == i:  # k is the next of type 0 behind i, and i the next ahead of k
                va = lam[0, k]
                if not va > vb:
                    return -1
                t_new = _meeting(t0[k], x0_[k], va, tb, xb, vb)
            stop = min(t_new, t)
            if i > 0:
                while walked < ends[(i + 1) % 2] and back[0, walked] < stop:
                    if not back[1, walked] < xb + vb * (back[0, walked] - tb):
                        return -1
                    st, sx, sv = back[0, walked], back[1, walked], back[2, walked]
                    walked += 1
                rear = sx + sv * (stop - st)
            if not t_new < t:
                out[1, i] = xb + vb * (t - tb)
                if i > 0 and not rear <= out[1, i]:
                    return -1
                break
            place = 0.5 * ((x0_[k] + va * (t_new - t0[k])) + (xb + vb * (t_new - tb)))
            if i > 0 and not rear < place:
                return -1
            here = _primitive(i + 1, k, n, table, constants[0], constants[1])
            lam[0, k] = n * (_primitive(i + 1, k + 1, n, table, constants[0], constants[1]) - here)
            vb = n * (here - _primitive(i, k, n, table, constants[0], constants[1]))
            t0[k], x0_[k], count0[k] = t_new, place, i + 1
            tb, xb, lam[1, i] = t_new, place, vb
            mine[0, filled], mine[1, filled], mine[2, filled] = tb, xb, vb
            filled += 1
            crossings += 1
            k -= 1
        ends[i % 2] = filled
    for k in range(n):
        out[0, k] = x0_[k] + lam[0, k] * (t - t0[k])
    return crossings


def mspd_exact_at(x0, system, t, return_method: bool = False):
    """Exact MSPD (section 1.2.2) from the configuration ``x0`` at the one time ``t``: the configuration
    :func:`mspd_exact` gives at [t], to rounding.

    For a :class:`~particle_methods.systems.PSystem` (d = 2) whose particles of one type never meet up to t,
    it is computed over the grid of crossings (module docstring); otherwise, or if that is found not to hold on
    the run, by the event loop of :func:`mspd_exact`, which also
    raises its errors (a velocity breaking (USH), a particle carried beyond the double range).

    Parameters
    ----------
    x0 : array (d, n), row gamma the sorted positions of the particles of type gamma (mass 1/n).
    system : a diagonal system, as for :func:`mspd_exact`.
    t : non-negative time.
    return_method : also return "grid" or "events", the algorithm that computed it.

    Returns
    -------
    Array (d, n): the configuration at t (and the method, if asked).
    """
    x0 = np.ascontiguousarray(checked_configuration("x0", x0, system))
    t = finite_number("t", t)
    if t < 0:
        raise ValueError(f"t must be non-negative, got {t!r}")
    instance("return_method", return_method, (bool, np.bool_))
    result, method = _by_grid(x0, system, t), "grid"
    if result is None:
        result, method = mspd_exact(x0, system, [t])[0], "events"
    return (result, method) if return_method else result


def _by_grid(x0: np.ndarray, system, t: float):
    """The configuration at t over the grid of crossings, or None where that does not apply (module docstring)."""
    if not _compiled_system(system) or np.any(np.diff(x0, axis=1) <= 0):
        return None  # another system, or particles of one type at one place: clusters from the start
    d, n = x0.shape
    ranks = ranks_kernel(x0)[0]
    behind = np.ascontiguousarray(ranks[[0, 1], :, [1, 0]])  # counts of the other type behind each particle
    start_speeds = _initial_speeds(system, ranks)
    # As in mspd_exact: every velocity (1.8) of the p-system is at most 2 A in magnitude.
    check_reach(x0, 2.0 * system.speed_scale, t, "t", "velocities", position_name="x0")
    constants = np.array([system.a, system.primitive_coefficient])
    table = _primitive_table(n)
    lam, out, extremes = np.empty((d, n)), np.empty((d, n)), np.array([np.inf, -np.inf])
    if _rows(x0, start_speeds, behind, t, constants, table, lam, out, extremes) < 0 or not extremes[0] > extremes[1]:
        return None
    again = np.empty((d, n))
    if _columns(x0, start_speeds, behind, t, constants, table, lam, again) < 0 or not np.array_equal(out, again):
        return None
    return np.maximum.accumulate(out, axis=1)  # the event loop's guard keeping each type sorted
