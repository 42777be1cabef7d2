"""Optimal control over compiled models, in CasADi (direct collocation, direct multiple
shooting, IPOPT), written with the model's names::

    ocp = acausal.ocp.OCP(compiled, N=40, T=2.0, method="collocation", degree=3)
    ocp.minimize(ocp.integral(lambda v: v["F"] ** 2))
    ocp.bounds("F", -20, 20)
    ocp.initial({"rail.s": 0, "hinge.phi": 0, "rail.v": 0, "hinge.w": 0})
    ocp.final({"rail.s": 1, "hinge.phi": np.pi, "rail.v": 0, "hinge.w": 0})
    sol = ocp.solve()
    sol["hinge.phi"], sol.control("F"), sol.cost, sol.plot(path=".")

Models with state events or modes (friction, impacts) are transcribed in their smooth form
(``OCP(..., smooth=True)``, the default: the Model compiled again with ``compile(model,
smooth=True)``), noted by a ``SmoothFormWarning``; ``ocp.regularized`` names the components
and their regularization parameters.

Modules: problem (OCP, FreeTime), transcription (Collocation, MultipleShooting), solution
(Solution), model (the names of a compiled model by kind), nlp (the NLP container), errors.
"""
from ..errors import OCPError, SmoothFormWarning, SolveError
from .problem import OCP, FreeTime
from .solution import Solution

__all__ = ["OCP", "FreeTime", "Solution", "OCPError", "SolveError", "SmoothFormWarning"]
