"""acausal.ocp's user-facing checks: unknown names (with a suggestion), bad bounds and bad
options raise the package's errors naming the variable at fault; free final time. (The
failed solve and the bounds on recorded variables are checked on the cart-pole, in
test_cartpole.py; a DAE with a non-DAE integrator in test_index1_model.py.)
"""
import math

import casadi as ca
import numpy as np
import pytest

import acausal
from acausal.errors import AcausalError, ParameterError
from acausal.models.oscillators import Oscillator
from acausal.ocp import OCP, FreeTime, OCPError


@pytest.fixture(scope="module")
def osc():
    return acausal.compile(Oscillator())


def test_unknown_names_suggest_the_right_one(osc):
    ocp = OCP(osc, N=5, T=1.0)
    with pytest.raises(OCPError, match=r"no variable 'mass.ss'.*did you mean 'mass.s'"):
        ocp["mass.ss"]
    with pytest.raises(OCPError, match=r"'spring.cc'.*did you mean 'spring.c'"):
        ocp.bounds("spring.cc", 0, 1)
    with pytest.raises(OCPError, match="did you mean 'mass.v'"):
        ocp.initial({"mass.vv": 0.0})
    with pytest.raises(OCPError, match="did you mean 'mass.s'"):
        ocp.integral(lambda v: v["mass.sx"] ** 2)
    with pytest.raises(ParameterError, match=r"no parameter 'spring.k'.*did you mean"):
        OCP(osc, N=5, free=["spring.k"])
    with pytest.raises(ParameterError, match="'damper.dd'"):
        OCP(osc, N=5, params={"damper.dd": 1.0})
    assert issubclass(OCPError, AcausalError)


def test_an_integrand_that_makes_nan_of_symbols_is_refused(osc):
    """math.cos accepts a CasADi symbol and gives NaN (no error): the cost would be NaN."""
    ocp = OCP(osc, N=5, T=1.0)
    with pytest.raises(OCPError, match="turns the model's CasADi symbols into NaN"):
        ocp.integral(lambda v: math.cos(v["mass.s"]) ** 2)
    cost = ocp.view.expression(lambda v: np.cos(v["mass.s"]) ** 2)       # numpy: symbolic
    assert float(ca.Function("f", [osc.x], [cost])(np.zeros(osc.x.numel()))) == 1.0


def test_bad_bounds_guesses_and_options(osc):
    ocp = OCP(osc, N=5, T=1.0)
    with pytest.raises(OCPError, match=r"bounds of 'mass.s': lower 1 > upper -1"):
        ocp.bounds("mass.s", 1.0, -1.0)
    with pytest.raises(OCPError, match=r"'spring.c' is a fixed parameter.*free="):
        ocp.bounds("spring.c", 0.0, 1.0)
    with pytest.raises(OCPError, match="lower bound of 'mass.s' is NaN"):
        ocp.bounds("mass.s", float("nan"), 1.0)
    with pytest.raises(OCPError, match="guess of 'mass.s'.*6 values"):
        ocp.guess({"mass.s": [1.0, 2.0]})
    with pytest.raises(OCPError, match="'spring.c' is not a decision variable"):
        ocp.guess({"spring.c": 1.0})
    with pytest.raises(OCPError, match="'spring.c' is a parameter"):
        ocp.final({"spring.c": 1.0})
    with pytest.raises(OCPError, match="Python cannot chain"):
        ocp.subject_to(ocp["mass.s"] + 1.0)
    with pytest.raises(OCPError, match="cost must be a scalar"):
        ocp.minimize(ocp["mass.s"])
    ocp.bounds("mass.s", -0.1, 0.1)
    ocp.initial({"mass.s": 0.5})
    with pytest.raises(OCPError, match=r"initial value 0.5 of 'mass.s' is outside its bounds"):
        ocp.solve()
    with pytest.raises(OCPError, match="method 'euler'"):
        OCP(osc, N=5, method="euler")
    with pytest.raises(OCPError, match="scheme 'gauss'"):
        OCP(osc, N=5, scheme="gauss")
    with pytest.raises(OCPError, match="N must be a positive integer"):
        OCP(osc, N=0)
    with pytest.raises(OCPError, match="horizon T must be a positive"):
        OCP(osc, N=5, T=-1.0)
    bad_time = OCP(osc, N=5, T=FreeTime(guess=5.0, lower=0.1, upper=1.0))
    bad_time.minimize(bad_time.T)
    with pytest.raises(OCPError, match="free final time"):
        bad_time.solve()


def test_free_final_time_with_a_cost_on_time_and_effort(osc):
    """The mass on a spring c = 1 N/m and a damper d = 0.1 N.s/m (params), released from
    rest at 1 m, first passes s = 0 (minimize a free T with s(T) = 0) at the closed form
    t = (π/2 + atan(ζ/√(1−ζ²))) / ω_d, ω_d = ω√(1−ζ²), ω = 1 rad/s, ζ = d / (2√(c m))."""
    ocp = OCP(osc, N=40, T=FreeTime(guess=1.0, lower=0.1, upper=2.5),
              params={"spring.c": 1.0, "damper.d": 0.1})
    ocp.minimize(ocp.T)
    ocp.initial({"mass.s": 1.0, "mass.v": 0.0})
    ocp.final({"mass.s": 0.0})
    sol = ocp.solve({"tol": 1e-12})
    w, zeta = 1.0, 0.1 / 2.0
    wd = w * np.sqrt(1 - zeta ** 2)
    assert sol.T == pytest.approx((np.pi / 2 + np.arctan(zeta / np.sqrt(1 - zeta ** 2))) / wd,
                                  rel=1e-8)
    assert isinstance(ocp.T, ca.MX)


def test_a_model_with_events_is_refused_in_exact_form():
    """The transcriptions know no events: with smooth=False a model with some is an error
    naming the components, not a problem that ignores them."""
    from acausal.models import BouncingBall
    with pytest.raises(OCPError, match="events or modes.*floor.*smooth=True"):
        OCP(acausal.compile(BouncingBall()), N=10, T=1.0, smooth=False)


def test_a_model_with_events_is_transcribed_in_smooth_form_and_says_so():
    """By default the Model is compiled again in smooth form: a SmoothFormWarning names the
    regularized component and the parameters only its smooth form uses (the floor's
    restitution e is used by both forms, so it is not one of them); the OCP and its
    solution report it. The smooth ball dropped from 1 m hits the floor at √(2h/g)."""
    from acausal.errors import SmoothFormWarning
    from acausal.models import BouncingBall
    exact = acausal.compile(BouncingBall())
    with pytest.warns(SmoothFormWarning, match=r"floor \(floor.c = 1e\+07 N/m2, "
                                               r"floor.v_smooth = 0.001 m/s\)"):
        ocp = OCP(exact, N=20, T=0.4, params={"floor.v_smooth": 0.001})
    assert ocp.smooth and ocp.model.smooth and not ocp.model.has_events
    assert ocp.regularized == {"floor": {"floor.c": 1e7, "floor.v_smooth": 0.001}}
    assert "smooth form of floor" in repr(ocp)
    ocp.initial({"ball.s": 1.0, "ball.v": 0.0})
    ocp.minimize(ocp["ball.s"][-1] ** 2)
    sol = ocp.solve()
    assert sol.smooth and sol.regularized == ocp.regularized
    assert "smooth form of floor" in repr(sol)
    np.testing.assert_allclose(sol["ball.s"], 1.0 - 9.81 / 2 * sol.t ** 2, atol=1e-9)
    # a model compiled smooth already is kept, and what it regularizes still named
    with pytest.warns(SmoothFormWarning):
        again = OCP(acausal.compile(BouncingBall(), smooth=True), N=5, T=0.1)
    assert again.regularized == {"floor": {"floor.c": 1e7, "floor.v_smooth": 0.001}}
