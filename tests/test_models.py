"""The shared models of acausal.models build and compile to the coordinates, states and inputs
their docstrings state (structure only: their physics is checked where they are used)."""
import pytest

import acausal
from acausal import models
from acausal.models import rotational_fmus, translational_fmus
from acausal.errors import ParameterError

CRANE = ["rail.s", "hinge.phi"]
LOOP = ["rev1.phi", "rev2.phi", "rev3.phi"]

# builder, coordinates, extra states (after the velocities), inputs
CASES = {
    "crane": (models.GantryCrane, CRANE, [], ["F"]),
    "disk_drive": (models.DiskDriveHead, ["pivot.phi", "flexure.s"], [], ["T"]),
    "pendulum_on_cart": (models.PendulumOnCart, CRANE, [], []),
    "pendulum_on_cart_input": (lambda: models.PendulumOnCart(drive="input"), CRANE, [], ["u"]),
    "cartpole": (models.CartPole, CRANE, [], ["F"]),
    "friction_cartpole": (models.FrictionCartPole, CRANE, [], ["F"]),
    "four_bar": (models.FourBar, LOOP, [], []),
    "parallelogram": (models.Parallelogram, LOOP, [], []),
    "double_parallelogram": (lambda: models.Parallelogram(fifth_link=True),
                             LOOP + ["rev5.phi"], [], []),
    "four_bar_position_driven": (models.DrivenFourBar, ["rev2.phi", "rev3.phi"], [], []),
    "four_bar_torque_driven": (lambda: models.DrivenFourBar("torque"), LOOP, [], ["T"]),
    "slider_crank": (models.SliderCrank, LOOP, [], []),
    "slider_crank_driven": (lambda: models.SliderCrank(driven=True), LOOP, [], ["tau"]),
    "pendulum_chain": (lambda: models.PendulumChain(4),
                       ["rev1.phi", "rev2.phi", "rev3.phi", "rev4.phi"], [], []),
    "drivetrain": (models.Drivetrain, ["motor.phi", "drum.phi"], ["motor.i"], []),
    "oscillator": (models.Oscillator, ["mass.s"], [], []),
    "duffing": (models.duffing_model, ["mass.s"], [], []),
    "motor": (models.motor_model, ["rotor.phi"], ["motor.i"], ["V"]),
    "coupled_clutches": (models.CoupledClutches, [f"J{k}.phi" for k in (1, 2, 3, 4)], [], []),
    "one_way_clutch": (models.OneWayClutchDrive, ["inertiaIn.phi", "inertiaOut.phi"], [], []),
    "one_way_clutch_disengaged": (models.OneWayClutchDisengaged,
                                  ["inertiaIn.phi", "inertiaOut.phi"], [], []),
    "thermostat": (models.Thermostat, [], ["plant.y"], []),
    "thermostat_hysteresis": (lambda: models.Thermostat(kind="Hysteresis"), [], ["plant.y"],
                              []),
    "sampled_p_controller": (models.SampledPController, ["mass.s"], [], []),
    "resistor_example": (models.ResistorExample, [], [], []),
    "heating_rectifier": (models.HeatingRectifier, [], ["Capacitor1.v", "HeatCapacitor1.T"],
                          []),
    "direct_inertia": (rotational_fmus.DirectInertia, ["inertia.phi"], [], ["tauDrive", "tau"]),
    "inverse_inertia": (rotational_fmus.InverseInertia, [], [], ["phi", "w", "a"]),
    "rotational_spring_block": (rotational_fmus.Spring, [], [], ["phi1", "phi2"]),
    "rotational_spring_damper_block": (rotational_fmus.SpringDamper, [], [],
                                       ["phi1", "w1", "phi2", "w2"]),
    "direct_mass": (translational_fmus.DirectMass, ["mass.s"], [], ["fDrive", "f"]),
    "inverse_mass": (translational_fmus.InverseMass, [], [], ["s", "v", "a"]),
    "translational_spring_block": (translational_fmus.Spring, [], [], ["s1", "s2"]),
    "translational_spring_damper_block": (translational_fmus.SpringDamper, [], [],
                                          ["s1", "v1", "s2", "v2"]),
    "rotational_generation_of_fmus": (
        models.RotationalGenerationOfFMUs,
        ["directInertia.inertia.phi", "inertia2a.phi", "inertia2b.phi", "inertia3a.phi",
         "inertia3b.phi"], [], []),
    "translational_generation_of_fmus": (
        models.TranslationalGenerationOfFMUs,
        ["directMass.mass.s", "mass2a.s", "mass2b.s", "mass3a.s", "mass3b.s"], [], []),
}


@pytest.mark.parametrize("name", CASES)
def test_model_compiles_to_its_stated_coordinates(name):
    build, coordinates, extra_states, inputs = CASES[name]
    model = build()
    assert isinstance(model, acausal.Model)
    compiled = acausal.compile(model)
    assert compiled.coordinates == coordinates
    velocities = compiled.lagrange.qd_names
    assert len(velocities) == len(coordinates)
    assert compiled.x_names == coordinates + velocities + extra_states
    assert compiled.lagrange.u_names == inputs


def test_closed_loops_keep_their_closing_joint_as_constraints():
    """The four-bar's rev4 and the slider-crank's prismatic joint close the loops: Φ rows."""
    for model, joint in ((models.FourBar(), "rev4"), (models.SliderCrank(), "prismatic")):
        rows = acausal.compile(model).loop_rows
        assert rows and all(row.startswith(f"{joint}.") for row in rows), rows


def test_pendulum_on_cart_refuses_an_unknown_drive():
    with pytest.raises(ParameterError, match=r"drive must be 'position' or 'input', got 'force'"):
        models.PendulumOnCart(drive="force")


def test_thermostat_refuses_an_unknown_kind():
    with pytest.raises(ParameterError, match=r"kind must be 'OnOffController' or "
                                             r"'Hysteresis', got 'PID'"):
        models.Thermostat(kind="PID")
