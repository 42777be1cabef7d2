"""Analog electrical components after Modelica.Electrical.Analog (Basic, Ideal, Sources,
Sensors, Semiconductors).

Pins carry the potential v [V] and the current i [A] flowing into the pin (MSL's sign); a
connection set has one potential and its currents sum to zero (Kirchhoff), as compiled by
``acausal.compiler.networks``. A two-pin element (MSL's ``OnePort``) has v = p.v − n.v and
the current i = p.i flowing from p through the element to n (n.i = −i). Start values of
the states are constructor keywords (``Capacitor(C=1e-3, v_start=5)``, MSL's
``v(start=5)``), like ``x0`` at simulation.

The timed sources (StepVoltage ... TrapezoidCurrent) are MSL's Interfaces.VoltageSource and
CurrentSource: offset + the waveform of the Modelica.Blocks.Sources block MSL redeclares,
evaluated by that block's own code in ``signals``, with its time events.

A circuit needs a ``Ground``; a loop of capacitors and voltage sources, or a node fed only
by inductors and current sources, is a higher-index network, refused when compiled with
an error naming its parts.

The ideal switching elements (IdealDiode, IdealThyristor, IdealGTOThyristor, the opening,
closing, two-way and intermediate switches) are MSL's parametric characteristics: an
auxiliary unknown s places each path on one of two straight segments, chosen by a Boolean
(a mode switched at state events for the semiconductors and the Controlled* switches, the
control input for the others); the modes have no smooth form.

The operational amplifiers: Ideal.IdealOpAmp, IdealOpAmp3Pin and IdealOpAmpLimited
(nullors), Basic.OpAmp (a smooth limited characteristic) and Ideal.OpAmpLimited /
IdealizedOpAmpLimited (a finite gain limited to the supply, whose power they draw from
their supply pins). The semiconductors: Diode, Diode2, ZDiode, the Thyristor, the
SimpleTriac (two of them) and Ideal.IdealTriac (two ideal thyristors and a snubber), the
bipolar transistors NPN and PNP
(Ebers–Moll with their junction capacitances: see NPN about the loops those close) and the
MOSFETs NMOS and PMOS.

The components live in modules after MSL's packages, all importable from here:
``interfaces`` (OnePort, TwoPort, the conditional heat port), ``basic``, ``sources``,
``sensors``, ``ideal`` and ``semiconductors``.
"""
from .interfaces import OnePort, TwoPort
from .basic import (Ground, Resistor, HeatingResistor, Conductor, VariableResistor,
                    VariableConductor, Potentiometer, Capacitor, Inductor, VariableCapacitor,
                    VariableInductor, SaturatingInductor, Transformer, M_Transformer, VCV, VCC,
                    CCV, CCC, Gyrator, RotationalEMF, EMF, TranslationalEMF, NonlinearResistor,
                    OpAmp)
from .sources import (ConstantVoltage, SignalVoltage, StepVoltage, RampVoltage, SineVoltage,
                      CosineVoltage, ExpSineVoltage, PulseVoltage, TrapezoidVoltage,
                      SawToothVoltage, ExponentialsVoltage, TableVoltage, ConstantCurrent,
                      SignalCurrent, StepCurrent, RampCurrent, SineCurrent, CosineCurrent,
                      ExpSineCurrent, PulseCurrent, TrapezoidCurrent, SawToothCurrent,
                      ExponentialsCurrent, TableCurrent, SineVoltageVariableFrequencyAndAmplitude,
                      CosineVoltageVariableFrequencyAndAmplitude,
                      SineCurrentVariableFrequencyAndAmplitude,
                      CosineCurrentVariableFrequencyAndAmplitude, SupplyVoltage)
from .sensors import PotentialSensor, VoltageSensor, CurrentSensor, PowerSensor, MultiSensor
from .ideal import (IdealDiode, IdealThyristor, IdealGTOThyristor, IdealOpeningSwitch,
                    IdealClosingSwitch, ControlledIdealOpeningSwitch,
                    ControlledIdealClosingSwitch, IdealTwoWaySwitch, IdealCommutingSwitch,
                    ControlledIdealTwoWaySwitch, ControlledIdealCommutingSwitch,
                    IdealIntermediateSwitch, ControlledIdealIntermediateSwitch, Short, Idle,
                    IdealTransformer, IdealOpAmp, IdealOpAmpLimited, S_NOISE, IdealOpAmp3Pin,
                    OpAmpLimited, IdealizedOpAmpLimited, InitOpAmp, IdealTriac)
from .semiconductors import (Diode, ZDiode, K_BOLTZMANN, Q_ELECTRON, exlin, Thyristor,
                             SimpleTriac, NPN, PNP, NMOS, PMOS, Diode2, exlin2,
                             powlin)

__all__ = ["Ground", "OnePort", "TwoPort", "Resistor", "HeatingResistor", "Conductor",
           "VariableResistor", "VariableConductor", "Potentiometer", "Capacitor", "Inductor",
           "VariableCapacitor", "VariableInductor", "Transformer", "M_Transformer", "VCV",
           "VCC", "CCV", "CCC",
           "RotationalEMF", "EMF", "TranslationalEMF",
           "ConstantVoltage", "SignalVoltage", "StepVoltage", "RampVoltage", "SineVoltage",
           "CosineVoltage", "ExpSineVoltage", "PulseVoltage", "TrapezoidVoltage",
           "SawToothVoltage", "ExponentialsVoltage", "TableVoltage",
           "ConstantCurrent", "SignalCurrent", "StepCurrent", "RampCurrent", "SineCurrent",
           "CosineCurrent", "ExpSineCurrent", "PulseCurrent", "TrapezoidCurrent",
           "SawToothCurrent", "ExponentialsCurrent", "TableCurrent",
           "SineVoltageVariableFrequencyAndAmplitude",
           "CosineVoltageVariableFrequencyAndAmplitude",
           "SineCurrentVariableFrequencyAndAmplitude",
           "CosineCurrentVariableFrequencyAndAmplitude", "SupplyVoltage",
           "PotentialSensor", "VoltageSensor", "CurrentSensor", "PowerSensor", "MultiSensor",
           "IdealDiode", "IdealThyristor", "IdealGTOThyristor", "IdealOpeningSwitch",
           "IdealClosingSwitch", "ControlledIdealOpeningSwitch", "ControlledIdealClosingSwitch",
           "IdealTwoWaySwitch", "IdealCommutingSwitch", "ControlledIdealTwoWaySwitch",
           "ControlledIdealCommutingSwitch", "IdealIntermediateSwitch",
           "ControlledIdealIntermediateSwitch", "Short", "Idle",
           "IdealTransformer", "Gyrator", "NonlinearResistor", "IdealOpAmp",
           "IdealOpAmpLimited", "Diode", "ZDiode", "SaturatingInductor",
           "OpAmp", "IdealOpAmp3Pin", "OpAmpLimited", "IdealizedOpAmpLimited", "InitOpAmp",
           "Diode2", "Thyristor", "SimpleTriac", "IdealTriac", "NPN", "PNP", "NMOS", "PMOS",
           "exlin2", "powlin",
           "S_NOISE", "K_BOLTZMANN", "Q_ELECTRON", "exlin"]
