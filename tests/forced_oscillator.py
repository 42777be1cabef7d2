"""The forced oscillator of the simulation tests, m s'' + d s' + c s = F: wall | spring (c)
|| damper (d) | mass (m) pushed by the model input F [N], and its linear system written by
hand (the exact references: ``lti``)."""
import numpy as np

import acausal
from acausal.components.translational import Damper, Fixed, Force, Mass, Spring


def forced_oscillator(m: float = 0.5, c: float = 8.0, d: float | None = None,
                      F_start: float = 0.0) -> acausal.Model:
    """wall | spring (c [N/m], unstretched at s = 0) || damper (d [N·s/m]; None: none) |
    mass (m [kg]) <- force of the input F [N] (its start value F_start)."""
    model = acausal.Model("forced")
    model.wall, model.spring, model.mass = Fixed(), Spring(c=c), Mass(m=m)
    model.force, model.F = Force(), acausal.Input(start=F_start, unit="N")
    model.connect(model.wall.flange, model.spring.flange_a)
    model.connect(model.spring.flange_b, model.mass.flange_a)
    if d is not None:
        model.damper = Damper(d=d)
        model.connect(model.wall.flange, model.damper.flange_a)
        model.connect(model.damper.flange_b, model.mass.flange_a)
    model.connect(model.force.flange, model.mass.flange_b)
    model.connect(model.F.y, model.force.f)
    return model


def oscillator_system(m: float, c: float = 0.0, d: float = 0.0):
    """(A, B) of m s'' + d s' + c s = F as x' = A x + B F, x = [s, v]."""
    return np.array([[0.0, 1.0], [-c / m, -d / m]]), np.array([0.0, 1.0 / m])
