"""MSL's analog filters (Modelica.Blocks.Continuous.Filter): the step responses and Bode
magnitudes of the four analog filter types, low pass of order 3 at f_cut = 2 Hz (normalized:
-3 dB at f_cut), and their -3 dB frequencies measured on the compiled model's linearization.

Run:  MPLBACKEND=Agg python examples/filters.py   (writes filters.png)
"""
import math

import matplotlib.pyplot as plt
import numpy as np
from scipy.optimize import brentq

import acausal
from acausal import Model
from acausal.analysis import linearize
from acausal.components.signals import AnalogFilter, Filter, Step

F_CUT = 2.0

# step responses: a step from 0.1 to 1.1 at 0.1 s, the filters in steady state at the start
m = Model("filters")
m.step = Step(startTime=0.1, offset=0.1)
for kind in AnalogFilter:
    setattr(m, kind.value, Filter(analogFilter=kind, order=3, f_cut=F_CUT))
    m.connect(m.step.y, getattr(m, kind.value).u)
t = np.linspace(0.0, 1.5, 601)
res = acausal.compile(m).simulate(t[-1], t=t)


def magnitude(kind: AnalogFilter):
    """|H(j·2π·f)| of the filter, from the linearization of the compiled block."""
    lm = Model("bode")
    lm.u, lm.f, lm.y = acausal.Input(), Filter(analogFilter=kind, order=3, f_cut=F_CUT,
                                               init="NoInit"), acausal.Output()
    lm.connect(lm.u.y, lm.f.u)
    lm.connect(lm.f.y, lm.y.u)
    lin = linearize(acausal.compile(lm), {})
    eye = np.eye(lin.A.shape[0])
    return lambda f: abs((lin.C @ np.linalg.solve(2j * math.pi * f * eye - lin.A, lin.B)
                          + lin.D)[0, 0])


fig, (ax_step, ax_bode) = plt.subplots(1, 2, figsize=(11, 4))
f = np.logspace(-1, 1.5, 300)
print("analog filter      -3 dB frequency [Hz]  (f_cut = 2 Hz)")
for kind in AnalogFilter:
    H = magnitude(kind)
    f3 = brentq(lambda x: 20 * math.log10(H(x)) + 3.0, 0.1, 20.0)
    print(f"{kind.value:18s} {f3:.6f}")
    ax_step.plot(res.t, res[f"{kind.value}.y"], label=kind.value)
    ax_bode.semilogx(f, [20 * math.log10(H(x)) for x in f], label=kind.value)
ax_step.plot(res.t, res["step.y"], "k:", label="input")
ax_step.set(xlabel="time [s]", ylabel="y", title="step responses (order 3, f_cut = 2 Hz)")
ax_bode.axhline(-3.0, color="k", lw=0.5)
ax_bode.axvline(F_CUT, color="k", lw=0.5)
ax_bode.set(xlabel="frequency [Hz]", ylabel="|H| [dB]", ylim=(-60, 5), title="magnitude")
ax_step.legend()
ax_bode.legend()
fig.tight_layout()
fig.savefig("filters.png", dpi=100)
