"""Readable equations: a component's reference in help(), a compiled model's summary, and the
two-link arm's Lagrange equations as sympy prints them (and LaTeX).

    python examples/readable_equations.py
"""
import acausal as ac
from acausal.components.planar import Body
from acausal.models.pendulums import PendulumChain

if __name__ == "__main__":
    print(Body.__doc__[Body.__doc__.index("Parameters"):])   # what help(Body) lists
    arm = ac.compile(PendulumChain(2, name="arm"))
    print(arm)                                         # coordinates, states, parameters
    # the arm's geometry across the bars fixed, everything else a named symbol
    across = {k: v for k, v in arm.param_defaults.items()
              if k in ("fixed.phi", "bar1.r[1]", "bar2.r[1]", "world.n[1]", "world.n[2]")}
    eq = arm.lagrange.with_values(across).to_sympy()
    print("M(q) =", eq.M)
    print("gravity =", eq.gravity)
    print("coriolis =", eq.coriolis)
    print(eq.latex().splitlines()[1][:200], "…")
