"""Orders of convergence: least-squares slopes and tables of pairwise orders."""

from __future__ import annotations

import numpy as np

from .validation import ParameterTypeError, finite_array, finite_result


def _log_pairs(steps, errors):
    steps = finite_array("steps", steps)
    errors = finite_array("errors", errors)
    if steps.shape != errors.shape or steps.size < 2:
        raise ValueError("steps and errors must have the same length, at least 2")
    if np.any(steps <= 0) or np.any(errors <= 0):
        raise ValueError("steps and errors must be positive to take logarithms")
    return np.log(steps), np.log(errors)


def fit_order(steps, errors) -> float:
    """Least-squares slope of log(error) against log(step) over the points given.

    Pass only the asymptotic range: with steps = h the slope is the order p of
    error ~ C h^p; with steps = n (a number of particles) it is -p.
    """
    log_steps, log_errors = _log_pairs(steps, errors)
    if np.ptp(log_steps) == 0:
        raise ValueError("steps must not all be equal: a slope needs two different steps")
    return finite_result("the fitted order", float(np.polyfit(log_steps, log_errors, 1)[0]),
                         "steps too close together")


def pairwise_orders(steps, errors) -> np.ndarray:
    """Slopes between consecutive points: log(e_{i+1}/e_i) / log(s_{i+1}/s_i)."""
    log_steps, log_errors = _log_pairs(steps, errors)
    if np.any(np.diff(log_steps) == 0):
        raise ValueError("consecutive steps must differ")
    return np.diff(log_errors) / np.diff(log_steps)


def order_table(steps, errors, step_name: str = "h") -> str:
    """Plain-text table step | error | pairwise order, for logs and failing tests."""
    if not isinstance(step_name, str):
        raise ParameterTypeError(f"step_name must be a string, got {step_name!r}")
    orders = pairwise_orders(steps, errors)
    lines = [f"{step_name:>12} | {'error':>12} | order"]
    for i, (step, error) in enumerate(zip(np.asarray(steps, float), np.asarray(errors, float))):
        order = f"{orders[i - 1]:.3f}" if i > 0 else ""
        lines.append(f"{step:12.5g} | {error:12.5e} | {order}")
    return "\n".join(lines)
