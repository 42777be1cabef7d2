"""The pythonfmu co-simulation slave of an acausal FMU (a template shipped inside every FMU).

``export_pythonfmu`` copies this file into the FMU's ``resources`` folder (as a module whose
name carries a hash of this file, so that FMUs of different acausal versions loaded into one
process do not share a module) next to ``acausal_model/``: ``model.json`` (variables, value
references, units, parameter checks, solver settings) and the model's serialized CasADi
Functions (``*.casadi``); and next to it the module ``<this module>_kernels``, a copy of
``acausal/numerics.py`` (the numerics acausal runs in-process: initial-value
projection, time events, solver messages). The slave needs only Python, numpy and casadi — not
acausal, and not pythonfmu either (the FMU carries pythonfmu's Python files).

One step ``do_step(t, h)`` integrates from t to t + h with the inputs held at their current
values (zero-order hold), splitting the step at the model's time events. The integrator is
built once at export — the DAE in scaled time τ ∈ [0, 1], t = t0 + h·τ, so that one CasADi
integrator serves every step size — and kept for the FMU's life; each call restarts it from
the state reached (the state travels between steps, exactly as in acausal.simulate at its time
events). Closed loops (index-2 stabilized DAE) integrate the deviation δ = x − x0 − τ·h·ẋ0, whose
derivative at τ = 0 is zero, so IDAS starts every step from consistent values without its own
(ill-conditioned for index 2) initial-value computation.

Errors never raise into the FMI wrapper (pythonfmu turns a Python exception into fmi2Fatal and
drops the instance): a failed solve makes ``do_step`` return False (fmi2Discard) with the reason
logged at status error; an invalid parameter value is logged at status error when set and the
slave refuses to step (fmi2Discard) until a valid value is set.
"""
from __future__ import annotations

import importlib
import json
from pathlib import Path

import casadi as ca
import numpy as np
from pythonfmu.enums import Fmi2Causality, Fmi2Initial, Fmi2Status, Fmi2Variability
from pythonfmu.fmi2slave import Fmi2Slave
from pythonfmu.variables import Real

DATA = "acausal_model"          # folder in resources with model.json and the *.casadi files
# acausal.numerics, shipped next to this module under this module's name (unique per
# acausal version) + "_kernels"
kernels = importlib.import_module(f"{__name__}_kernels")
_CAUSALITY = {c.name: c for c in Fmi2Causality}
_VARIABILITY = {v.name: v for v in Fmi2Variability}
_INITIAL = {i.name: i for i in Fmi2Initial}


class AcausalSlave(Fmi2Slave):
    """An acausal CompiledModel as an FMI 2.0 co-simulation slave."""

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        folder = Path(self.resources) / DATA
        meta = json.loads((folder / "model.json").read_text(encoding="utf-8"))
        self.meta = meta
        self.modelName = meta["identifier"]
        self.description = meta["description"]
        self.version = meta["acausal_version"]
        self.fn = {name: ca.Function.load(str(folder / f"{name}.casadi"))
                   for name in meta["functions"]}
        if ca.__version__ != meta["casadi_version"]:
            self.log(f"this FMU was exported with casadi {meta['casadi_version']}; casadi "
                     f"{ca.__version__} is installed (the serialized functions may not load or "
                     f"behave the same: install casadi=={meta['casadi_version']})",
                     Fmi2Status.warning)
        self.nx, self.nz = len(meta["x_names"]), len(meta["z_names"])
        scale = np.array(meta["nominal"], dtype=float)   # the integrator's [x; z] / scale
        self.x_scale, self.z_scale = scale[:self.nx], scale[self.nx:]
        self.vars_meta = meta["variables"]
        kinds = {}
        for v in self.vars_meta:
            kinds.setdefault(v["kind"], []).append(v)
        self.p = np.array(meta["param_defaults"], dtype=float)
        self.u = np.array([v["start"] for v in kinds.get("input", [])], dtype=float)
        self.x_declared = np.array([v["start"] for v in kinds.get("state", [])], dtype=float)
        self.x_given = {}               # state index -> value set before initialization
        self.bad = {}                   # parameter index -> message of an invalid value
        self.error = None               # why the slave cannot step (failed init / solve)
        self.t = 0.0
        self.initialized = False
        self.x, self.z = self._start()
        self._cache = None
        self.by_vr = {}
        for v in self.vars_meta:
            self._register(v)

    # ---- variables ------------------------------------------------------------------------
    def _register(self, v):
        var = Real(v["name"], start=v["start"] if v["initial"] == "exact" or v["kind"] == "input"
                   else None,
                   causality=_CAUSALITY[v["causality"]],
                   variability=_VARIABILITY[v["variability"]],
                   initial=_INITIAL[v["initial"]] if v["initial"] else None,
                   description=v["description"] or None,
                   getter=lambda: 0.0, setter=lambda value: None)
        var.value_reference = v["value_reference"]
        self.vars[v["value_reference"]] = var
        self.by_vr[v["value_reference"]] = v

    def to_xml(self, model_options=dict()):
        """pythonfmu's description plus units, derivative and nominal attributes and the
        complete model structure (outputs, derivatives, initial unknowns), so that it
        validates."""
        from xml.etree.ElementTree import Element, SubElement
        root = super().to_xml(model_options)
        elements = list(root.findall("ModelVariables/ScalarVariable"))
        index = {}
        for pos, (sv, v) in enumerate(zip(elements, self.vars_meta), start=1):
            index[v["value_reference"]] = pos
            real = sv.find("Real")
            if v["unit"]:
                real.set("unit", v["unit"])
            if v["derivative_of"] is not None:
                real.set("derivative", str(index[v["derivative_of"]]))
            if v["start"] is not None and real.get("start") is not None:
                real.set("start", repr(float(v["start"])))
            if v["kind"] == "state" and self.x_scale[v["index"]] != 1.0:
                real.set("nominal", repr(float(self.x_scale[v["index"]])))
        root.set("variableNamingConvention", self.meta["naming_convention"])
        if self.meta["units"]:
            defs = Element("UnitDefinitions")
            for u in self.meta["units"]:
                unit = SubElement(defs, "Unit", name=u["name"])
                if u["base"] is not None:
                    SubElement(unit, "BaseUnit", u["base"])
            root.insert(list(root).index(root.find("CoSimulation")) + 1, defs)
        root.remove(root.find("ModelStructure"))
        structure = SubElement(root, "ModelStructure")
        outputs = [index[v["value_reference"]] for v in self.vars_meta if v["kind"] == "output"]
        derivatives = [index[v["value_reference"]] for v in self.vars_meta
                       if v["kind"] == "derivative"]
        switches = [index[v["value_reference"]] for v in self.vars_meta if v["kind"] == "switch"]
        for tag, rows in (("Outputs", outputs), ("Derivatives", derivatives),
                          ("InitialUnknowns", sorted(outputs + derivatives + switches))):
            if rows:
                node = SubElement(structure, tag)
                for i in rows:
                    SubElement(node, "Unknown", index=str(i))
        return root

    def get_real(self, vrs):
        try:
            return [self._value(self.by_vr[vr]) for vr in vrs]
        except Exception as e:                       # never raise into the FMI wrapper
            self.log(f"getReal failed: {e}", Fmi2Status.error)
            return [float("nan")] * len(vrs)

    def set_real(self, vrs, values):
        for vr, value in zip(vrs, values):
            try:
                self._set(self.by_vr[vr], float(value))
            except Exception as e:
                self.log(f"setReal of value reference {vr} failed: {e}", Fmi2Status.error)

    def _set(self, v, value):
        kind, i = v["kind"], v["index"]
        if kind == "parameter":
            self.p[i] = value
            problem = self._check_parameter(i, value)
            if problem:
                self.bad[i] = problem
                self.log(problem, Fmi2Status.error)
            else:
                self.bad.pop(i, None)
        elif kind == "input":
            self.u[i] = value
        elif kind == "state" and not self.initialized:
            self.x_given[i] = value
            self.x[i] = value
        else:
            when = " after initialization" if kind == "state" else ""
            self.log(f"'{v['name']}' ({v['causality']} {kind}) cannot be set{when}; the value "
                     f"{value} is ignored", Fmi2Status.error)
            return
        self._cache = None

    def _check_parameter(self, i, value):
        """acausal's rule for the parameter's value (``numerics.parameter_problem``, the one
        Parameter.check_scalar applies), as a message or None."""
        check = self.meta["parameter_checks"][i]
        return kernels.parameter_problem(self.meta["param_names"][i], value, **check)

    def _value(self, v):
        kind, i = v["kind"], v["index"]
        if kind in ("parameter", "switch"):
            return float(self.p[i])
        if kind == "input":
            return float(self.u[i])
        if kind == "state":
            return float(self.x[i])
        c = self._derived()
        if kind == "derivative":
            return float(c["xdot"][i])
        if kind == "output":
            return float(c["y"][i])
        where, j = self.meta["recorded_layout"][i]
        return float(self.x[j] if where == "x" else c["r"][j])

    def _derived(self):
        """Outputs, state derivatives and recorded variables at the current point (cached)."""
        if self._cache is None:
            args = (self.t, self.x, self.z, self.u, self.p)
            xdot = self.fn["f"](*args)[0]
            y = self.fn["outputs"](*args)
            r = self.fn["recorded"](*args)
            self._cache = {k: np.asarray(ca.DM(val).full(), dtype=float).ravel()
                           for k, val in (("xdot", xdot), ("y", y), ("r", r))}
        return self._cache

    # ---- initialization -------------------------------------------------------------------
    def _start(self):
        w = np.asarray(self.fn["start"](self.p).full(), dtype=float).ravel()
        x, z = w[:self.nx].copy(), w[self.nx:].copy()
        for i, value in self.x_given.items():
            x[i] = value
        return x, z

    def setup_experiment(self, start_time, stop_time=None, tolerance=None):
        self.t = float(start_time)
        self._cache = None

    def exit_initialization_mode(self):
        """States: set values that differ from the declared start are held exactly; the
        others start at the model's start values for the current parameters. Closed loops and
        algebraic equations are then made consistent (as acausal's initial_state does)."""
        try:
            self._initialize()
        except Exception as e:
            self.error = f"initialization failed: {e}"
            self.log(self.error, Fmi2Status.error)
        self.initialized = True
        self._cache = None
        if self.error is None:
            self._check_assertions()

    def _check_assertions(self) -> bool:
        """The components' assertions at the present point: False, with the error logged
        (the component, its message, the time), where one fails."""
        if "assertions" not in self.fn:
            return True
        held = self.fn["assertions"](self.t, self.x, self.z, self.u, self.p)
        failure = kernels.first_failed_assertion(held.full(), [self.t],
                                                 self.meta["assertion_texts"])
        if failure is None:
            return True
        self.error = failure[1]
        self.log(self.error, Fmi2Status.error)
        return False

    def _initialize(self):
        hard = {i: v for i, v in self.x_given.items() if v != self.x_declared[i]}
        self.x_given = hard
        self.x, self.z = self._start()
        if "init" not in self.fn:
            return
        self.x, self.z = self._consistent(hard)
        if "phi_q" in self.fn:          # enforce the loop rows independent here, as simulate()
            J = self.fn["phi_q"](self.t, self.x, self.z, self.u, self.p)
            self.p[self.meta["loop_switches"]] = kernels.independent_rows(J.full())

    def _consistent(self, hard):
        """Gauss-Newton projection of the start values onto the loop constraints Φ = 0,
        Φ̇ = 0, the algebraic equations and the held states (acausal's initial_state)."""
        rows = sorted(hard)
        start = np.concatenate([self.x, self.z])      # the held states in place already
        E = np.zeros((len(rows), start.size))
        E[np.arange(len(rows)), rows] = 1.0
        targets = [hard[i] for i in rows]

        def equations(w):
            h, J = self.fn["init"](self.t, w, self.u, self.p)
            h = np.asarray(h.full(), dtype=float).ravel()
            return np.concatenate([E @ w - targets, h]), np.vstack([E, np.asarray(J.full())])

        names = self.meta["x_names"]
        labels = [names[i] for i in rows] + self.meta["init_labels"]
        w = kernels.project(equations, start, start, self.nx, labels, targets, given="start",
                            positions=self.meta["positions"])
        note = kernels.moved_note(names, start, w)
        if note:
            self.log(note, Fmi2Status.ok)
        return w[:self.nx], w[self.nx:]

    # ---- stepping -------------------------------------------------------------------------
    def do_step(self, current_time, step_size):
        if self.error is not None or self.bad:
            self.log(self.error or "; ".join(self.bad.values()), Fmi2Status.error)
            return False
        t0, t1 = float(current_time), float(current_time) + float(step_size)
        if step_size <= 0:
            return True
        try:
            x, z, a = self.x, self.z, t0
            for b, end in self._segments(t0, t1):
                x, z = self._advance(x, z, a, end)
                a = b
        except Exception as e:
            self.error = (f"the solver failed in the step from t = {t0:g} to {t1:g} s: "
                          f"{kernels.short_error(e)}; check the parameters and inputs")
            self.log(self.error, Fmi2Status.error)
            return False
        self.x, self.z, self.t = x, z, t1
        self._cache = None
        return self._check_assertions()

    def _segments(self, t0, t1):
        """(restart time, end) of the pieces of [t0, t1] between time events: each piece ends
        just before its event, as in acausal.simulate; an event at t1 ends the step just
        before it too."""
        tol = 1e-12 * max(1.0, abs(t1))
        out = [(e, kernels.just_before(e)) for e in
               kernels.event_times(*self.fn["events"](self.p), t0, t1 + tol)]
        if not out or abs(out[-1][0] - t1) > tol:
            out.append((t1, t1))
        return out

    def _advance(self, x, z, a, b):
        """The states and algebraic variables at b from (x, z) at a; the integrator works on
        them divided by their nominals (x_scale, z_scale)."""
        h = b - a
        if h <= 0:
            return x, z
        P = [self.p, self.u, [a, h]]
        if self.meta["deviation_form"]:
            f0 = np.asarray(self.fn["f"](a, x, z, self.u, self.p)[0].full(), dtype=float).ravel()
            P += [x, f0]
            sol = self.fn["integrator"](x0=np.zeros(self.nx), z0=z / self.z_scale,
                                        p=np.concatenate(P))
            d = np.asarray(sol["xf"].full(), dtype=float).ravel() * self.x_scale
            zf = np.asarray(sol["zf"].full(), dtype=float).ravel() * self.z_scale
            return x + h * f0 + d, zf
        kw = {"x0": x / self.x_scale, "p": np.concatenate(P)}
        if self.nz:
            kw["z0"] = z / self.z_scale
        sol = self.fn["integrator"](**kw)
        xf = np.asarray(sol["xf"].full(), dtype=float).ravel() * self.x_scale
        zf = np.asarray(sol["zf"].full(), dtype=float).ravel() * self.z_scale if self.nz else z
        return xf, zf

    # ---- FMU state, termination -----------------------------------------------------------
    def _get_fmu_state(self):
        return {"t": self.t, "x": self.x.tolist(), "z": self.z.tolist(), "p": self.p.tolist(),
                "u": self.u.tolist(), "initialized": self.initialized, "error": self.error,
                "bad": {str(k): v for k, v in self.bad.items()},
                "x_given": {str(k): v for k, v in self.x_given.items()}}

    def _set_fmu_state(self, state):
        self.t = float(state["t"])
        self.x, self.z = np.array(state["x"], dtype=float), np.array(state["z"], dtype=float)
        self.p, self.u = np.array(state["p"], dtype=float), np.array(state["u"], dtype=float)
        self.initialized, self.error = bool(state["initialized"]), state["error"]
        self.bad = {int(k): v for k, v in state["bad"].items()}
        self.x_given = {int(k): v for k, v in state["x_given"].items()}
        self._cache = None

    def terminate(self):
        """Release the CasADi objects (integrator memory, functions) so that the importer can
        unload the FMU and exit cleanly."""
        self.fn = {}
        self._cache = None

