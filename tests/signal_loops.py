"""A model with an algebraic loop of blocks around a state, shared by the compiler's and the
FMU's tests: a mass driven by y = k·(r − v − g·y)."""
import acausal
from acausal.components import signals as sg
from acausal.components.translational import Force, Mass, SpeedSensor


def speed_loop(m_=2.0, k=5.0, g=0.5, r=1.5):
    """A mass driven by y = k·(r − v − g·y), the loop through Feedbacks and a Gain: y =
    k·(r − v)/(1 + k·g), so v(t) = r·(1 − exp(−k·t/(m·(1 + k·g))))."""
    m = acausal.Model("speed")
    m.ref, m.err, m.fb, m.k, m.g = sg.Constant(k=r), sg.Feedback(), sg.Feedback(), \
        sg.Gain(k=k), sg.Gain(k=g)
    m.mass, m.force, m.speed = Mass(m=m_), Force(), SpeedSensor()
    m.connect(m.ref.y, m.err.u1)
    m.connect(m.speed.v, m.err.u2)
    m.connect(m.err.y, m.fb.u1)
    m.connect(m.fb.y, m.k.u)
    m.connect(m.k.y, m.g.u)
    m.connect(m.g.y, m.fb.u2)
    m.connect(m.k.y, m.force.f)
    m.connect(m.force.flange, m.mass.flange_a)
    m.connect(m.speed.flange, m.mass.flange_b)
    return m
