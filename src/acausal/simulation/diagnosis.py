"""Why an integration failed, in the model's terms, and what helps.

The integrators report codes (``IDA_CONV_FAIL``, ``CV_TOO_MUCH_WORK``) and a time. For a
closed loop the configuration reached there is examined: where the loop constraints'
Jacobian Φ_q loses rank (links lining up: a dead point, a parallelogram passing its
collinear position), the constraints no longer determine the motion, and the rows that became
dependent and the coordinates are named. Otherwise the advice follows the code and the
tolerances: a Newton iteration that cannot converge at very tight tolerances needs looser
ones, not tighter. Equations of motion that are not finite at the start are explained too:
a singular mass matrix by the coordinates it leaves without inertia (``not_finite``).
"""
from __future__ import annotations

import io
import os
import re
import sys
import tempfile
from contextlib import contextmanager

import casadi as ca
import numpy as np

from ..numerics import independent_rows, short_error

TIGHT_RTOL, TIGHT_ATOL = 1e-10, 1e-12


def failure_message(model, error: Exception, a: float, b: float, rtol: float, atol: float,
                    state_near=None, p=None, u_at=None, start=None) -> str:
    """The message of a failed integration of ``model`` over [a, b]: what the solver said
    (``error``, with what it wrote on standard error: ``solver_account``), and why in the
    model's terms. ``state_near(t)`` gives (x, z) shortly before t (or None) for a closed
    loop's configuration; ``p``, ``u_at(t)`` the parameters and inputs; ``start`` the
    (x, z) the integration started from at a."""
    text = str(error)
    unknown = re.search(r"Unknown option: (\S+)", text)
    if unknown:
        return (f"simulation of '{model.name}': the integrator has no option "
                f"'{unknown.group(1)}'; options= takes the options of CasADi's integrator "
                f"plugin (e.g. 'max_num_steps', 'max_order', 'step0'), see casadi.integrator")
    said = short_error(error).rstrip(". ")
    head = f"simulation of '{model.name}' failed between t = {a:g} and {b:g} s: {said}"
    if start is not None and model.z.numel() and not model.has_loops and p is not None:
        undetermined = _undetermined(model, a, *start, u_at(a), p)
        if undetermined:
            return f"{head}. {undetermined}"
    t_fail = _failure_time(text)
    if model.has_loops and t_fail is not None and state_near is not None:
        near = state_near(t_fail)
        if near is not None:
            singular = _singular_configuration(model, t_fail, *near, u_at(t_fail), p)
            if singular:
                return f"{head}. {singular}"
    why = blow_up(text)
    if why:
        return f"{head}. {why}"
    if "TOO_MUCH_WORK" in text:
        return (f"{head}. The solver took too many steps: the model may be stiff (give "
                f"solver='cvodes' for BDF) or the tolerances tighter than needed; "
                f"options={{'max_num_steps': n}} raises the limit")
    if ("CONV_FAIL" in text or "ERR_FAIL" in text) and (rtol < TIGHT_RTOL or atol < TIGHT_ATOL):
        return (f"{head}. rtol = {rtol:g}, atol = {atol:g} are tighter than the solver's "
                f"Newton iteration can meet on this model (round-off in the equations' own "
                f"solve): loosen them, e.g. rtol = {TIGHT_RTOL:g}, atol = {TIGHT_ATOL:g}")
    return (f"{head}. Check the parameters and the initial values (a value that makes the "
            f"equations blow up), or try another solver")


def blow_up(text: str) -> str:
    """What a failed integration's ``text`` (its error and what the solver wrote) says when
    the equations became infinite or NaN: where, and the likely causes; else ""."""
    if not re.search(r"(?:Inf|NaN) detected", text):
        return ""
    t_fail = _failure_time(text)
    near = f" near t = {t_fail:g} s" if t_fail is not None else ""
    return (f"The equations became infinite or NaN{near}: the states grow without bound "
            f"there (a finite-time blow-up), or an expression divides by zero; check the "
            f"parameters, the initial values and the inputs")


def _failure_time(text: str) -> float | None:
    """The time where the solver says it stopped ("At t = …", "Internal t = …"), or None."""
    found = re.search(r"(?:At|Internal) t = ([-+0-9.eE]+)", text)
    return float(found.group(1)) if found else None


def _undetermined(model, t, x, z, u, p) -> str | None:
    """The description of algebraic variables that the algebraic equations leave free at
    (t, x, z) (their Jacobian in z singular there), or None. For DAEs of index 1: a closed
    loop's multipliers enter no equation of their own by design."""
    J = np.array(model.function("alg_z", [ca.jacobian(model.alg, model.z)])(t, x, z, u, p),
                 dtype=float)
    if not np.all(np.isfinite(J)):
        return None
    s, V = np.linalg.svd(J)[1:]
    tol = 1e-10 * max(1.0, s.max(initial=0.0))
    if s.size == J.shape[1] and s.min() > tol:
        return None
    null = V[-1] if s.size == J.shape[1] else V[s.size]
    free = [model.z_names[k] for k in np.flatnonzero(np.abs(null) > 0.1 * np.abs(null).max())]
    return (f"The algebraic equations do not determine {', '.join(free)} at t = {t:g} s "
            f"(their Jacobian is singular there): those are parts without mass or inertia "
            f"whose common motion nothing holds (say, a spring-damper or a chain of dampers "
            f"connected to nothing fixed), or a part of a network that floats; connect them "
            f"to a fixed point (Fixed, Ground) or give them mass or inertia")


def _singular_configuration(model, t, x, z, u, p) -> str | None:
    """The description of a singular loop configuration at (t, x, z), or None."""
    J = np.array(model.phi_q_function(t, x, z, u, p), dtype=float)
    on = [i for i in range(J.shape[0]) if p[model.loop_switches[i]] > 0.5]
    keep = independent_rows(J[on])
    lost = [model.loop_rows[on[k]] for k in range(len(on)) if not keep[k]]
    if not lost:
        return None
    coords = ", ".join(f"{n} = {x[i]:.6g}" for n, i in
                       zip(model.lagrange.q_names, model.position_states))
    return (f"Near t = {t:g} s the closed loop reaches a singular configuration ({coords}): the "
            f"loop constraints' Jacobian loses rank there (rows {', '.join(lost)} become "
            f"dependent on the others), so the links line up (a dead point, such as a "
            f"parallelogram passing its collinear position) and the constraints no longer "
            f"determine the motion. Start the mechanism on another assembly branch (guess), "
            f"keep it away from that configuration (less energy, a stop), or, when a loop is "
            f"redundant only there, build the mechanism without that redundant link")


@contextmanager
def _stderr_to(fd: int, stream):
    """Standard error sent to ``fd`` for the block: the process's file descriptor 2, where
    SUNDIALS writes, and Python's sys.stderr (``stream``), where CasADi's warnings go."""
    sys.stderr.flush()
    saved, saved_stream = os.dup(2), sys.stderr
    try:
        os.dup2(fd, 2)
        sys.stderr = stream
        yield
    finally:
        sys.stderr = saved_stream
        os.dup2(saved, 2)
        os.close(saved)


@contextmanager
def quiet_stderr():
    """Standard error discarded: around a solve whose failure is handled (a retry, a
    fallback), not reported."""
    null = os.open(os.devnull, os.O_WRONLY)
    try:
        with _stderr_to(null, io.StringIO()):
            yield
    finally:
        os.close(null)


@contextmanager
def solver_account(lines: int = 8):
    """What an integration in the block writes on standard error (SUNDIALS, CasADi's
    warnings) kept from the terminal: a RuntimeError raised in the block carries it after
    its own message (where the solver stopped and why, for ``failure_message``); after a
    block that succeeds, its first ``lines`` lines and a count of the rest are passed on."""
    stream = io.StringIO()
    with tempfile.TemporaryFile() as f:
        try:
            with _stderr_to(f.fileno(), stream):
                yield
        except RuntimeError as e:
            f.seek(0)
            said = f.read().decode(errors="replace") + stream.getvalue()
            raise RuntimeError(f"{e}\n{said}") from None
        f.seek(0)
        rows = (f.read().decode(errors="replace") + stream.getvalue()).splitlines()
    if rows:
        more = f"\n... ({len(rows) - lines} more lines)" if len(rows) > lines else ""
        sys.stderr.write("\n".join(rows[:lines]) + more + "\n")


def not_finite(model, x0, fx0, p, u0, t0) -> str:
    """Why the state derivatives are not finite at the start: a singular mass matrix (named
    by its coordinates), or non-finite values."""
    bad = [f"d({n})/dt = {v}" for n, v in zip(model.x_names, fx0) if not np.isfinite(v)][:4]
    head = f"the equations of motion of '{model.name}' are not finite at t = {t0:g} s " \
           f"({', '.join(bad)})"
    L = model.lagrange
    if L.q.numel() and not model.z.numel():
        M = np.array(model.function("M", [L.M])(t0, x0, np.zeros(0), u0, p), dtype=float)
        if np.all(np.isfinite(M)):
            w, V = np.linalg.eigh(M)
            tol = 1e-12 * max(1.0, np.abs(w).max(initial=0.0))
            null = [L.q_names[k] for k in np.flatnonzero(np.abs(V[:, np.argmin(np.abs(w))])
                                                         > 0.1)] if w.min() <= tol else []
            if null:
                return (f"{head}: the mass matrix is singular there, along the coordinates "
                        f"{', '.join(null)}: a part without mass or inertia moves them; give it "
                        f"mass / inertia, or connect it to something that has some")
    return (f"{head}; check the parameters, inputs and initial values for values that make "
            f"the equations infinite (a division by zero, a zero length)")
