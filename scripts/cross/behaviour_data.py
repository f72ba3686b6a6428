"""What the methods do at the blow-up: the particle method at its first collision and the ODE solver
past it, the LTP method as the density blows up."""

import numpy as np
from scipy.integrate import DOP853

from particle_methods.blob.solver import CollisionError
from particle_methods.cross import methods
from particle_methods.cross.exact import AggregationSolution
from particle_methods.ltp.solver import StabilityError
from particle_replication.workflow import logged, progress, save_results


def first_collision(x, v):
    """Earliest meeting time of neighbours moving at constant velocities v (before any collision)."""
    closing = v[:-1] > v[1:]
    return float(np.min(np.diff(x)[closing] / (v[:-1] - v[1:])[closing]))


def stall(data, h, window, evaluations):
    """Integrate the particle method's ODE past its first collision without stopping there (DOP853
    at the blob package's tolerances), step by accepted step, until the end of the window or until
    ``evaluations`` right-hand sides are spent (the last step may spend up to one step's stages more):
    (collision time, right-hand sides until the first accepted step that reaches the collision, right-hand
    sides after it, time the accepted steps reached). The time reached is that of the accepted steps: the
    stages of a rejected step look ahead up to the end of the window, where the solver never got."""
    x, _, masses = methods.grid_particles(data, h)
    collision = first_collision(x, methods.weighted_velocities(masses))
    calls = 0

    def rhs(t, y):
        nonlocal calls
        calls += 1
        return methods.particle_velocities(y, masses)

    solver = DOP853(rhs, 0.0, x, collision + window, rtol=1e-12, atol=1e-14)
    before = None
    while solver.status == "running" and calls < evaluations:
        solver.step()
        if before is None and solver.t >= collision:
            before = calls
    if before is None:  # never reached the collision within the budget
        before = calls
    return collision, before, calls - before, solver.t


def densest_particle(data, h, dt, t):
    """(position, width / h) of the LTP particle where rho_h is largest at time t (a multiple of dt)."""
    particles = methods.ltp_method(data, h, dt, t)
    densest = int(np.argmax(particles.density(particles.centres)))
    return particles.centres[densest], particles.widths[densest] / h


def run(p, output):
    data_names, ltp = p["data"], p["ltp"]
    t_after = max(p["times"])
    predicted, measured = np.empty(len(data_names)), np.empty(len(data_names))
    stall_start, stall_before, stall_after, stall_reached = (np.empty(len(data_names)) for _ in range(4))
    # Not refused by t_final: an infinite refusal time (the claim then fails; NaN would not compare).
    b = p["behaviour"]
    refusal = np.full((len(data_names), len(b["ltp_inverse_h"])), np.inf)
    # The densest LTP particle at each refusal (NaN where LTP was not refused).
    peak_position, peak_width, peak_edge = (np.full(refusal.shape, np.nan) for _ in range(3))
    for i, data in enumerate(data_names):
        h = 1.0 / b["collision_inverse_h"]
        x, _, masses = methods.grid_particles(data, h)
        predicted[i] = first_collision(x, methods.weighted_velocities(masses))
        try:
            methods.particle_method(data, h, t_after)
            measured[i] = np.inf
        except CollisionError as error:
            measured[i] = error.time
        stall_start[i], stall_before[i], stall_after[i], stall_reached[i] = stall(
            data, h, b["stall_window"], b["stall_evaluations"])
        progress(f"{data}: first collision predicted {predicted[i]:.12g}, solver event {measured[i]:.12g}; "
                 f"without the event DOP853 spends {stall_before[i]:.0f} right-hand sides before it and "
                 f"{stall_after[i]:.0f} after it, reaching {stall_reached[i]:.12g}")

        for j, k in enumerate(b["ltp_inverse_h"]):
            h = 1.0 / k
            try:
                methods.ltp_method(data, h, ltp["dt_over_h"] * h, b["ltp_t_final"])
            except StabilityError as error:
                refusal[i, j] = error.time
            if not np.isfinite(refusal[i, j]):
                continue
            peak_position[i, j], peak_width[i, j] = densest_particle(data, h, ltp["dt_over_h"] * h, refusal[i, j])
            peak_edge[i, j] = AggregationSolution(data, refusal[i, j]).left_end
            progress(f"{data}, 1/h = {k}: at t = {refusal[i, j]:g} the densest LTP particle sits at "
                     f"{peak_position[i, j]:.6g} (support's ends +-{abs(peak_edge[i, j]):.6g}), width "
                     f"{peak_width[i, j]:.4g} h (exact flow: {1.0 - refusal[i, j]:.4g} h at the peak of rho0)")
        progress(f"{data}: LTP refused at t = {refusal[i]} (dt = {[ltp['dt_over_h'] / k for k in b['ltp_inverse_h']]})")

    save_results(output[0], data=np.array(data_names),
                 collision_predicted=predicted, collision_measured=measured, stall_collision=stall_start,
                 stall_before=stall_before, stall_after=stall_after, stall_reached=stall_reached,
                 ltp_peak_position=peak_position, ltp_peak_width=peak_width, ltp_peak_edge=peak_edge,
                 ltp_inverse_h=np.array(b["ltp_inverse_h"]), ltp_dt=ltp["dt_over_h"] / np.array(b["ltp_inverse_h"]),
                 ltp_refusal=refusal,
                 stall_window=b["stall_window"])


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output)  # noqa: F821
