"""Voltage and current sources (after Modelica.Electrical.Analog.Sources): constant, signal
driven and the timed waveforms of MSL's Interfaces.VoltageSource and CurrentSource (see the
package's docstring)."""
from __future__ import annotations

from types import MethodType

import casadi as ca

from ...core import (Component, ConditionalPort, NegativePin, Parameter, PositivePin,
                     RealInput)
from ...core.component import BoundParameters, bound_twin, who
from ...errors import ParameterError
from .. import signals as sig
from ..signals.sources import (_check_table, _table_events, _table_values,
                               _VariableFrequencyWave)
from .interfaces import OnePort


class _VoltageSource(OnePort):
    """A voltage source: v = p.v − n.v given by ``_voltage``; its current i [A] (from p
    through the source to n) is an unknown of the circuit."""

    def _voltage(self, e):
        raise NotImplementedError

    def physics(self, e):
        v, i = self._voltage(e), self._current(e)
        e.residual(self._v(e) - v)
        self._record(e, v, i)


class ConstantVoltage(_VoltageSource):
    """Constant voltage source: v = V [V]."""
    V = Parameter(1.0, "V", "value of constant voltage")

    def _voltage(self, e):
        return self.V


class SignalVoltage(_VoltageSource):
    """Voltage source driven by the input ``v`` [V] (= p.v − n.v)."""
    v = RealInput("voltage between pin p and n (= p.v - n.v) as input signal [V]")

    def _voltage(self, e):
        return e.input(self.v)

    def _record(self, e, v=None, i=None):           # v is the input, recorded as a signal
        super()._record(e, None, i)


class _BlockSignal:
    """The Modelica.Blocks.Sources block ``block`` that MSL's VoltageSource and
    CurrentSource redeclare as ``signalSource``, seen from the electrical ``source`` that
    holds it: the block's own methods (signal, before, events) on the source's values; a
    block parameter reads the source's parameter of the same name, or the one ``renamed``
    maps it to (the amplitude V or I), or, where the source has neither, the block's
    default (Pulse's nperiod in PulseVoltage), as MSL's modifiers bind them."""

    def __init__(self, source: Component, block: type, renamed: dict):
        self._source, self._block, self._renamed = source, block, renamed

    def __getattr__(self, name):
        if name in self._renamed:
            return getattr(self._source, self._renamed[name])
        if name in type(self._source).parameters() or isinstance(
                getattr(type(self._source), name, None), property):   # a parameter or binding
            return getattr(self._source, name)
        options = self._block.all_options()
        if name in options:
            return options[name]
        declared = self._block.parameters().get(name)
        if declared is not None:
            return declared.default
        attribute = getattr(self._block, name)
        return MethodType(attribute, self) if callable(attribute) else attribute


class _SignalSourced(OnePort):
    """MSL Interfaces.VoltageSource / CurrentSource: the source's value [V or A] is
    offset + (``before()`` before startTime, else ``signal(time)``) of its shape's
    Blocks.Sources block (``_block``, whose parameter ``_role`` is the source's amplitude
    ``_amplitude``), with the block's time events (startTime and the corners of the
    periodic waves)."""
    _block: type
    _role = "amplitude"
    _amplitude: str

    def _source_value(self, e):
        block = _BlockSignal(self, self._block, {self._role: self._amplitude})
        for time, period in block.events():
            e.time_event(time, period)
        return self.offset + ca.if_else(e.time < self.startTime, block.before(),
                                        block.signal(e.time))


class _TimedVoltage(_SignalSourced, _VoltageSource):
    """MSL Interfaces.VoltageSource: v = offset + (0 if time < startTime else signal) [V]."""
    _amplitude = "V"
    offset = Parameter(0.0, "V", "voltage offset")
    startTime = Parameter(0.0, "s", "time offset")

    def _voltage(self, e):
        return self._source_value(e)


# the shapes of the sources: the Blocks.Sources block and the parameters a voltage source
# and a current source of that shape share (their amplitude, V or I, is their own)
class _StepShape:
    _block, _role = sig.Step, "height"


class _RampShape:
    _block, _role = sig.Ramp, "height"
    duration = Parameter(2.0, "s", "duration of ramp", positive=True)


class _SineShape:
    _block = sig.Sine
    phase = Parameter(0.0, "rad", "phase of sine wave")
    f = Parameter(1.0, "Hz", "frequency of sine wave")


class _CosineShape:
    _block = sig.Cosine
    phase = Parameter(0.0, "rad", "phase of cosine wave")
    f = Parameter(1.0, "Hz", "frequency of cosine wave")


class _ExpSineShape:
    _block = sig.ExpSine
    f = Parameter(2.0, "Hz", "frequency of sine wave")
    phase = Parameter(0.0, "rad", "phase of sine wave")
    damping = Parameter(1.0, "1/s", "damping coefficient of sine wave")


class _PulseShape:
    _block = sig.Pulse
    width = Parameter(50.0, "%", "width of pulse in % of period", positive=True)
    period = Parameter(1.0, "s", "time for one period", positive=True)


class _TrapezoidShape:
    _block = sig.Trapezoid
    rising = Parameter(0.0, "s", "rising duration of trapezoid", nonnegative=True)
    width = Parameter(0.5, "s", "width duration of trapezoid", nonnegative=True)
    falling = Parameter(0.0, "s", "falling duration of trapezoid", nonnegative=True)
    period = Parameter(1.0, "s", "time for one period", positive=True)
    nperiod = Parameter(-1, "", "number of periods (< 0 means infinite number of periods)")


class _SawToothShape:
    _block = sig.SawTooth
    period = Parameter(1.0, "s", "time for one period", positive=True)


class _ExponentialsShape(BoundParameters):
    """The Exponentials block's rise and fall; fallTimeConst [s] follows riseTimeConst (MSL's
    binding, also at simulation time) unless given at construction, which makes it a
    parameter of its own (the class's twin registered by ``_own_fallTimeConst``)."""
    _block, _role = sig.Exponentials, "outMax"
    riseTime = Parameter(0.5, "s", "rise time", nonnegative=True)
    riseTimeConst = Parameter(0.1, "s", "rise time constant", positive=True)

    @property
    def fallTimeConst(self):
        """Fall time constant [s]: riseTimeConst (MSL's binding)."""
        return self.riseTimeConst


def _own_fallTimeConst(cls):
    """``cls`` with its twin whose fallTimeConst [s] is a parameter of its own (built by
    ``cls(fallTimeConst=...)``)."""
    return bound_twin(cls, "fallTimeConst",
                      Parameter(0.1, "s", "fall time constant", positive=True))


class _TableShape:
    """MSL's TableVoltage / TableCurrent: the Blocks.Sources.TimeTable redeclared with the
    source's ``table`` (constructor argument, rows [time [s], value], times non-decreasing
    from 0, a time given twice a jump; MSL's default [0, 0; 1, 1; 2, 4]), interpolated
    linearly by the TimeTable's own functions at time − startTime (its shiftTime bound to
    startTime, timeScale 1 s), extrapolated through the last two rows; a time event at
    startTime and at every jump. The table is fixed when the model is compiled."""

    def __init__(self, name: str | None = None, *, table=((0.0, 0.0), (1.0, 1.0), (2.0, 4.0)),
                 **params):
        super().__init__(name, **params)
        tab = _check_table(table, who(self), first_at_zero=False)
        if tab.shape[1] != 2:
            raise ParameterError(f"{who(self)}: table must have rows [time, value] (shape "
                                 f"(n, 2)), got shape {tab.shape}")
        if tab.shape[0] > 1 and tab[0, 0] != 0:
            raise ParameterError(f"{who(self)}: the first point in time has to be 0, but is "
                                 f"table[1,1] = {tab[0, 0]}; shift the table with startTime")
        self.__dict__["times"] = tab[:, 0]
        self.__dict__["table"] = tuple(float(v) for v in tab[:, 1])

    def _source_value(self, e):
        smoothness, extrapolation, time_events = sig.TimeTable._modes()
        e.time_event(self.startTime, None)
        for tk, period in _table_events(self.times, smoothness, extrapolation, time_events):
            e.time_event(self.startTime + tk, period)
        value = _table_values(e.time - self.startTime, self.times, self.table, smoothness,
                              extrapolation)[0]
        return self.offset + ca.if_else(e.time < self.startTime, 0.0, value)


class StepVoltage(_StepShape, _TimedVoltage):
    """Step voltage source: v = offset + (0 if time < startTime else V) [V]."""
    V = Parameter(1.0, "V", "height of step")


class RampVoltage(_RampShape, _TimedVoltage):
    """Ramp voltage source (MSL Sources.RampVoltage): v rises linearly from offset to
    offset + V [V] between startTime and startTime + duration [s] (duration > 0)."""
    V = Parameter(1.0, "V", "height of ramp")


class SineVoltage(_SineShape, _TimedVoltage):
    """Sine voltage source: v = offset + V·sin(2π·f·(time − startTime) + phase) after
    startTime, offset before [V]."""
    V = Parameter(1.0, "V", "amplitude of sine wave")


class CosineVoltage(_CosineShape, _TimedVoltage):
    """Cosine voltage source (MSL Sources.CosineVoltage): v = offset + V·cos(2π·f·(time −
    startTime) + phase) after startTime, offset before [V]."""
    V = Parameter(1.0, "V", "amplitude of cosine wave")


class ExpSineVoltage(_ExpSineShape, _TimedVoltage):
    """Exponentially damped sine voltage source (MSL Sources.ExpSineVoltage): v = offset +
    V·exp(−damping·τ)·sin(2π·f·τ + phase), τ = time − startTime ≥ 0, offset before [V]."""
    V = Parameter(1.0, "V", "amplitude of sine wave")


class PulseVoltage(_PulseShape, _TimedVoltage):
    """Pulse voltage source (MSL Sources.PulseVoltage): v = offset + V [V] during the first
    ``width`` percent of every period [s] from startTime, offset otherwise; the edges are
    time events."""
    V = Parameter(1.0, "V", "amplitude of pulse")


class TrapezoidVoltage(_TrapezoidShape, _TimedVoltage):
    """Trapezoidal voltage source (MSL Sources.TrapezoidVoltage): from startTime, every
    period [s] v rises from offset to offset + V [V] in ``rising``, holds ``width``, falls in
    ``falling`` [s], then stays at offset; nperiod periods (< 0: infinitely many); the
    corners are time events."""
    V = Parameter(1.0, "V", "amplitude of trapezoid")


class SawToothVoltage(_SawToothShape, _TimedVoltage):
    """Saw tooth voltage source (MSL Sources.SawToothVoltage): from startTime, v rises
    linearly from offset to offset + V [V] within every period [s] and jumps back at its end
    (a time event there); offset before startTime."""
    V = Parameter(1.0, "V", "amplitude of saw tooth")


@_own_fallTimeConst
class ExponentialsVoltage(_ExponentialsShape, _TimedVoltage):
    """Rising and falling exponential voltage source (MSL Sources.ExponentialsVoltage): for
    τ = time − startTime ≥ 0, v = offset + vMax·(1 − exp(−τ/riseTimeConst)) while τ <
    riseTime [s], then the value reached decays as exp(−(τ − riseTime)/fallTimeConst) [V];
    offset before startTime. fallTimeConst [s] is riseTimeConst unless given (MSL's
    binding). Time events at startTime and at the end of the rise (MSL declares vMax a plain
    Real; it is the voltage's upper bound)."""
    _amplitude = "vMax"
    vMax = Parameter(1.0, "V", "upper bound for rising edge")


class TableVoltage(_TableShape, _TimedVoltage):
    """Voltage source by linear interpolation in a table (MSL Sources.TableVoltage): v =
    offset + the table's voltage [V] at time − startTime, offset before startTime (see
    ``_TableShape``: ``table`` rows [time [s], voltage [V]])."""


class _CurrentSource(OnePort):
    """A current source: i [A] from p through the source to n given by ``_current_value``;
    its voltage v = p.v − n.v [V] is what the circuit sets."""

    def _current_value(self, e):
        raise NotImplementedError

    def physics(self, e):
        self._record(e, self._v(e), self._current(e, self._current_value(e)))


class ConstantCurrent(_CurrentSource):
    """Constant current source: i = I [A] from p through the source to n."""
    I = Parameter(1.0, "A", "value of constant current")         # noqa: E741 (MSL's name)

    def _current_value(self, e):
        return self.I


class _TimedCurrent(_SignalSourced, _CurrentSource):
    """MSL Interfaces.CurrentSource: i = offset + (0 if time < startTime else signal) [A]
    from p through the source to n."""
    _amplitude = "I"
    offset = Parameter(0.0, "A", "current offset")
    startTime = Parameter(0.0, "s", "time offset")

    def _current_value(self, e):
        return self._source_value(e)


class StepCurrent(_StepShape, _TimedCurrent):
    """Step current source (MSL Sources.StepCurrent): i = offset + (0 if time < startTime
    else I) [A]."""
    I = Parameter(1.0, "A", "height of step")                   # noqa: E741 (MSL's name)


class RampCurrent(_RampShape, _TimedCurrent):
    """Ramp current source (MSL Sources.RampCurrent): i rises linearly from offset to
    offset + I [A] between startTime and startTime + duration [s] (duration > 0)."""
    I = Parameter(1.0, "A", "height of ramp")                   # noqa: E741 (MSL's name)


class SineCurrent(_SineShape, _TimedCurrent):
    """Sine current source (MSL Sources.SineCurrent): i = offset + I·sin(2π·f·(time −
    startTime) + phase) after startTime, offset before [A]."""
    I = Parameter(1.0, "A", "amplitude of sine wave")           # noqa: E741 (MSL's name)


class CosineCurrent(_CosineShape, _TimedCurrent):
    """Cosine current source (MSL Sources.CosineCurrent): i = offset + I·cos(2π·f·(time −
    startTime) + phase) after startTime, offset before [A]."""
    I = Parameter(1.0, "A", "amplitude of cosine wave")         # noqa: E741 (MSL's name)


class ExpSineCurrent(_ExpSineShape, _TimedCurrent):
    """Exponentially damped sine current source (MSL Sources.ExpSineCurrent): i = offset +
    I·exp(−damping·τ)·sin(2π·f·τ + phase), τ = time − startTime ≥ 0, offset before [A]
    (MSL declares I a plain Real; it is the current's amplitude)."""
    I = Parameter(1.0, "A", "amplitude of sine wave")           # noqa: E741 (MSL's name)


class PulseCurrent(_PulseShape, _TimedCurrent):
    """Pulse current source (MSL Sources.PulseCurrent): i = offset + I [A] during the first
    ``width`` percent of every period [s] from startTime, offset otherwise; the edges are
    time events."""
    I = Parameter(1.0, "A", "amplitude of pulse")               # noqa: E741 (MSL's name)


class TrapezoidCurrent(_TrapezoidShape, _TimedCurrent):
    """Trapezoidal current source (MSL Sources.TrapezoidCurrent): the TrapezoidVoltage's
    wave for the current i [A], amplitude I; nperiod periods (< 0: infinitely many)."""
    I = Parameter(1.0, "A", "amplitude of trapezoid")           # noqa: E741 (MSL's name)


class SawToothCurrent(_SawToothShape, _TimedCurrent):
    """Saw tooth current source (MSL Sources.SawToothCurrent): the SawToothVoltage's wave
    for the current i [A], amplitude I."""
    I = Parameter(1.0, "A", "amplitude of saw tooth")           # noqa: E741 (MSL's name)


@_own_fallTimeConst
class ExponentialsCurrent(_ExponentialsShape, _TimedCurrent):
    """Rising and falling exponential current source (MSL Sources.ExponentialsCurrent): the
    ExponentialsVoltage's wave for the current i [A], upper bound iMax (a plain Real in
    MSL)."""
    _amplitude = "iMax"
    iMax = Parameter(1.0, "A", "upper bound for rising edge")


class TableCurrent(_TableShape, _TimedCurrent):
    """Current source by linear interpolation in a table (MSL Sources.TableCurrent): i =
    offset + the table's current [A] at time − startTime, offset before startTime (see
    ``_TableShape``: ``table`` rows [time [s], current [A]])."""


class SignalCurrent(OnePort):
    """Current source driven by the input ``i`` [A] (from p through the source to n)."""
    i = RealInput("current flowing from pin p to pin n as input signal [A]")

    def physics(self, e):
        self._current(e, e.input(self.i))
        self._record(e, v=self._v(e))


class _VariableFrequencyShape(_VariableFrequencyWave):
    """MSL's Sources.*VariableFrequencyAndAmplitude: the source's value offset +
    amplitude·wave(phi), der(phi) = 2π·f, by the logic of Blocks.Sources'
    SineVariableFrequencyAndAmplitude (``signals.sources._VariableFrequencyWave``): the
    phase phi [rad] a state (start ``phi_start``, 0), f [Hz] the input ``f`` or
    constantFrequency (``useConstantFrequency``), the amplitude the input V or I or
    constantAmplitude (``useConstantAmplitude``)."""
    constantFrequency = Parameter(1.0, "Hz", "constant frequency")
    f = ConditionalPort(RealInput("frequency [Hz]"), "useConstantFrequency", False)


class _VariableVoltage(_VariableFrequencyShape, _VoltageSource):
    constantAmplitude = Parameter(1.0, "V", "constant amplitude")
    offset = Parameter(0.0, "V", "offset of the sine wave")
    V = ConditionalPort(RealInput("amplitude [V]"), "useConstantAmplitude", False)
    _amplitude = "V"

    def _voltage(self, e):
        return self._wave_value(e)


class _VariableCurrent(_VariableFrequencyShape, _CurrentSource):
    constantAmplitude = Parameter(1.0, "A", "constant amplitude")
    offset = Parameter(0.0, "A", "offset of the sine wave")
    I = ConditionalPort(RealInput("amplitude [A]"), "useConstantAmplitude",   # noqa: E741
                        False)
    _amplitude = "I"

    def _current_value(self, e):
        return self._wave_value(e)


class SineVoltageVariableFrequencyAndAmplitude(_VariableVoltage):
    """Sine voltage source with variable frequency and amplitude (MSL
    Sources.SineVoltageVariableFrequencyAndAmplitude): v = offset + V·sin(phi) [V],
    der(phi) = 2π·f; the amplitude V [V] and the frequency f [Hz] inputs, or the constants
    of the options useConstantAmplitude / useConstantFrequency (``_VariableFrequencyShape``).
    A frequency that changes changes the wave's rate without a jump."""
    wave = staticmethod(ca.sin)


class CosineVoltageVariableFrequencyAndAmplitude(_VariableVoltage):
    """Cosine voltage source with variable frequency and amplitude (MSL
    Sources.CosineVoltageVariableFrequencyAndAmplitude): v = offset + V·cos(phi) [V],
    der(phi) = 2π·f, as SineVoltageVariableFrequencyAndAmplitude."""
    wave = staticmethod(ca.cos)


class SineCurrentVariableFrequencyAndAmplitude(_VariableCurrent):
    """Sine current source with variable frequency and amplitude (MSL
    Sources.SineCurrentVariableFrequencyAndAmplitude): i = offset + I·sin(phi) [A] from p
    through the source to n, der(phi) = 2π·f; the amplitude I [A] and the frequency f [Hz]
    inputs, or the constants of the options useConstantAmplitude / useConstantFrequency."""
    wave = staticmethod(ca.sin)


class CosineCurrentVariableFrequencyAndAmplitude(_VariableCurrent):
    """Cosine current source with variable frequency and amplitude (MSL
    Sources.CosineCurrentVariableFrequencyAndAmplitude): i = offset + I·cos(phi) [A],
    der(phi) = 2π·f, as SineCurrentVariableFrequencyAndAmplitude."""
    wave = staticmethod(ca.cos)


class SupplyVoltage(Component):
    """Supply voltage, positive and negative (MSL Sources.SupplyVoltage): pin_p.v − ground.v
    = Vps and pin_n.v − ground.v = Vns [V] (MSL's two ConstantVoltages, positiveSupply
    from ground to pin_p and negativeSupply from pin_n to ground, written as these two
    equations); the currents into pin_p and pin_n are what the circuit draws, ground
    returns their sum (pin_p.i + pin_n.i + ground.i = 0). Records the supplies' currents
    i_p = −pin_p.i and i_n = pin_n.i [A] (positiveSupply.i and negativeSupply.i in MSL:
    from their p through them to their n)."""
    Vps = Parameter(15.0, "V", "positive supply")
    Vns = Parameter(-15.0, "V", "negative supply")
    pin_p = PositivePin("positive supply pin")
    pin_n = NegativePin("negative supply pin")
    ground = NegativePin("ground pin")

    def physics(self, e):
        ip, i_n = e.flow_of(self.pin_p), e.flow_of(self.pin_n)
        e.flow(self.ground, -(ip + i_n))
        v0 = e.potential(self.ground)
        e.residual(e.potential(self.pin_p) - v0 - self.Vps)
        e.residual(e.potential(self.pin_n) - v0 - self.Vns)
        e.variable("i_p", -ip, "A", "current of the positive supply (positiveSupply.i)")
        e.variable("i_n", i_n, "A", "current of the negative supply (negativeSupply.i)")
