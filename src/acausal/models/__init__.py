"""The models that examples, tests and benchmarks share, kept inside the library as the
Modelica Standard Library keeps its Examples.

Each builder returns an uncompiled ``acausal.Model`` (compile it with ``acausal.compile``);
its docstring gives the parameters with their units and the coordinates it compiles to. The
package depends only on ``acausal.core`` and ``acausal.components`` (and ``acausal.errors``):
no compiler or simulation imports.

    crane               GantryCrane: cart on a damped rail, load on a rope (input F)
    disk_drive          DiskDriveHead: actuator arm with a flexible tip (input T)
    pendulum_on_cart    PendulumOnCart: pendulum on a spring-mounted, base-excited cart
    cartpole            CartPole: cart with a pole on a hinge (input F); FrictionCartPole:
                        with Coulomb friction on the rail
    linkages            FourBar, Parallelogram, DrivenFourBar, SliderCrank, add_link;
                        KinematicLoop, PistonEngine (PlanarMechanics' examples)
    pendulums           PendulumChain: N-link planar pendulum
    drivetrains         Drivetrain: DC motor, gear, elastic shaft, fan drum
    dc_motors           DCMotorCircuit: the DC motor composed of Resistor, Inductor,
                        RotationalEMF and Inertia (equal to rotational.DCMotor)
    elastic_bearing     ElasticBearing: MSL's gearbox on an elastic bearing (nominals)
    oscillators         Oscillator: mass on a spring and a damper
    quarter_car         QuarterCar: body and wheel on springs over a road height (input road)
    bouncing_ball       BouncingBall, Floor: a state event with a reinit (impacts)
    friction            RotationalFriction: MSL's drive train with a clutch and a brake
    clutches            CoupledClutches: MSL's drive train with 3 coupled clutches;
                        OneWayClutchDrive, OneWayClutchDisengaged: MSL's one-way clutch
    event_blocks        Thermostat: a bang-bang loop (OnOffController or Hysteresis);
                        SampledPController: Sampler and ZeroOrderHold on a mass
    translational_friction  TranslationalBrake, TranslationalFriction, PreLoad: MSL's
                        Translational Examples Brake, Friction (MassWithStopAndFriction) and
                        PreLoad (ElastoGap)
    gears               LossyGearDemo1..3, Backlash: MSL's gear-loss and backlash examples
    circuits            CauerLowPassAnalog: MSL's Cauer low-pass filter (capacitor loops:
                        compiled with index_reduction=True); ChuaCircuit: MSL's Chua circuit;
                        ResistorExample, HeatingRectifier: MSL's Resistor (a resistor heating
                        through a thermal conductor) and HeatingRectifier (a heating diode)
    eddy_current_brakes RotationalEddyCurrentBrake, TranslationalEddyCurrentBrake: MSL's
                        EddyCurrentBrake examples (a brake heating a heat capacitor)
    heat_losses         TranslationalHeatLosses, RotationalHeatLosses: MSL's HeatLosses
                        examples (every dissipating element's heatPort to one convection)
    rotational_fmus,    MSL's GenerationOfFMUs examples (RotationalGenerationOfFMUs,
    translational_fmus  TranslationalGenerationOfFMUs) and the blocks of their Utilities
                        to export as FMUs: DirectInertia, InverseInertia, Spring,
                        SpringDamper; DirectMass, InverseMass, Spring, SpringDamper
    custom_components   CubicSpring, Flywheel, SimpleDCMotor; duffing_model, motor_model
    robot_axis          OneAxis: MSL's RobotR3.OneAxis (path planning, P-PI controller,
                        op-amp current-controlled Motor, GearType1 with bearing friction),
                        with AxisType1/2, GearType1/2, Controller, PathPlanning1
    multibody           MultiBodyPendulum, MultiBodyDoublePendulum: MSL MultiBody's
                        Elementary Pendulum and DoublePendulum; chain: 3-D joint trees
    multibody_loops     MultiBodyFourbar1, MultiBodyFourbar2, MultiBodyFourbarAnalytic,
                        MultiBodyEngine1a (on MultiBodyEngine1Base): MSL MultiBody's Loops
                        examples; EngineJointRRP, ParallelFourbar
    blocks_examples     InverseModel, ShowLogicalSources, TotalHarmonicDistortion: MSL's
                        Blocks examples (InverseModel compiled with index_reduction=True)
    robots              dh_chain: a serial arm from its Denavit–Hartenberg table (standard or
                        modified); from_urdf: a fixed-base robot from its URDF file (also
                        ``acausal.multibody``)
"""
from .blocks_examples import InverseModel, ShowLogicalSources, TotalHarmonicDistortion
from .bouncing_ball import BouncingBall, Floor
from .cartpole import CartPole, FrictionCartPole
from .circuits import CauerLowPassAnalog, ChuaCircuit, HeatingRectifier, ResistorExample
from .clutches import CoupledClutches, OneWayClutchDisengaged, OneWayClutchDrive
from .crane import GantryCrane
from .custom_components import CubicSpring, Flywheel, SimpleDCMotor, duffing_model, motor_model
from .disk_drive import DiskDriveHead
from .dc_motors import DCMotorCircuit
from .drivetrains import Drivetrain
from .eddy_current_brakes import RotationalEddyCurrentBrake, TranslationalEddyCurrentBrake
from .elastic_bearing import ElasticBearing
from .event_blocks import SampledPController, Thermostat
from .friction import RotationalFriction
from .gears import Backlash, LossyGearDemo1, LossyGearDemo2, LossyGearDemo3
from .heat_losses import RotationalHeatLosses, TranslationalHeatLosses
from .linkages import (DrivenFourBar, FourBar, KinematicLoop, Parallelogram, PistonEngine,
                       SliderCrank, add_link)
from .multibody import MultiBodyDoublePendulum, MultiBodyPendulum, chain
from .multibody_loops import (EngineJointRRP, MultiBodyEngine1a, MultiBodyEngine1Base,
                              MultiBodyFourbar1, MultiBodyFourbar2, MultiBodyFourbarAnalytic,
                              ParallelFourbar)
from .robots import dh_chain, from_urdf
from .rotational_fmus import GenerationOfFMUs as RotationalGenerationOfFMUs
from .translational_fmus import GenerationOfFMUs as TranslationalGenerationOfFMUs
from .oscillators import Oscillator
from .pendulum_on_cart import PendulumOnCart
from .pendulums import PendulumChain
from .quarter_car import QuarterCar
from .robot_axis import OneAxis
from .translational_friction import PreLoad, TranslationalBrake, TranslationalFriction

__all__ = ["BouncingBall", "Floor", "CartPole", "FrictionCartPole", "GantryCrane", "CubicSpring",
           "Flywheel", "SimpleDCMotor", "duffing_model", "motor_model", "DiskDriveHead",
           "Drivetrain", "DrivenFourBar", "ElasticBearing", "FourBar", "KinematicLoop",
           "Parallelogram", "PistonEngine", "SliderCrank", "add_link", "Oscillator",
           "PendulumOnCart", "PendulumChain", "QuarterCar", "RotationalFriction", "CoupledClutches",
           "OneWayClutchDrive", "OneWayClutchDisengaged", "PreLoad", "TranslationalBrake",
           "TranslationalFriction", "Backlash", "LossyGearDemo1", "LossyGearDemo2",
           "LossyGearDemo3", "SampledPController", "Thermostat", "CauerLowPassAnalog",
           "ChuaCircuit", "RotationalEddyCurrentBrake", "TranslationalEddyCurrentBrake",
           "TranslationalHeatLosses", "RotationalHeatLosses", "ResistorExample",
           "HeatingRectifier", "DCMotorCircuit", "OneAxis", "MultiBodyPendulum",
           "MultiBodyDoublePendulum", "chain", "MultiBodyFourbar1", "MultiBodyFourbar2",
           "MultiBodyFourbarAnalytic", "MultiBodyEngine1Base", "MultiBodyEngine1a",
           "EngineJointRRP", "ParallelFourbar", "dh_chain", "from_urdf", "InverseModel",
           "ShowLogicalSources", "TotalHarmonicDistortion", "RotationalGenerationOfFMUs",
           "TranslationalGenerationOfFMUs"]
