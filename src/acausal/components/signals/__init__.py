"""Causal signal blocks, after Modelica.Blocks (MSL 4.0): sources, math, continuous blocks.

Names, parameters, defaults and equations are those of the MSL blocks, so a block diagram
written against MSL translates line by line: ``Step(height=2, startTime=1)``,
``connect(step.y, feedback.u1)``, ``PID(k=..., Ti=..., Td=..., Nd=...)``.

Signals are dimensionless in general (``Real``); time parameters are in seconds [s],
frequencies in [Hz], angles in [rad]. Numeric parameters are acausal Parameters (symbolic,
changeable at simulation time without recompiling); structural data (a table, the number of
inputs of ``Sum``) and initial values of block states are constructor arguments.

Initialization: the continuous blocks (Integrator, LimIntegrator, Derivative, FirstOrder,
SecondOrder, PI, PID, LimPID, TransferFunction, StateSpace, CriticalDamping,
LowpassButterworth; Filter's option is MSL's ``init``) take MSL's ``initType`` (``Init``: NoInit,
SteadyState, InitialState, InitialOutput) with MSL's default for each block; SteadyState and
InitialOutput are initial equations (der(states) = 0; y = y_start). With NoInit and
InitialState a block's states start at their start values (``y_start``, ``x_start``, ...),
where nothing else fixes them (what MSL tools do with NoInit). Other initial values are given
at simulation time by the dotted name of a state or of any output, e.g. ``x0={"PI.y": 0.5}``.

Sources are expressions of time built with CasADi functions (``if_else``, ``floor``,
``interpolant``), so they are exact, differentiable where the MSL signal is, and usable
inside optimal control problems. Discontinuous sources (Step, Pulse, SawTooth, table jumps)
declare time events: the integrator restarts there. After MSL 4.1 also ContinuousClock,
Exponentials, Sinc, LogFrequencySweep, Sine/CosineVariableFrequencyAndAmplitude (the phase a
state) and KinematicPTP; RealExpression is not needed in Python (a source is any expression
of time: write a Component whose physics outputs it). Limiter, VariableLimiter and DeadZone generate
state events at their kinks (MSL's default strict=false), so the simulator locates where the
input reaches a limit; compiled with ``smooth=True`` their corners are rounded over a named
width ``u_smooth`` (see Limiter); so does LimPID's output limiter (``y_smooth``). Blocks
with Boolean signals (relations, Switch, Hysteresis, logical blocks) are in
``acausal.components.logical``, sampled-data blocks (Sampler, ZeroOrderHold, the discrete
TransferFunction and StateSpace, ...) in ``acausal.components.discrete``.

Math blocks (Modelica.Blocks.Math, MSL 4.1): Abs and Sign (MSL's ``generateEvent``: state
events where u crosses 0, a smooth form as Limiter's), the functions of one input (Sqrt,
Sin, ..., Log10, Power, Exponentiation; where MSL requires u in a domain, Sqrt, Asin, Acos,
Log, Log10, the requirement is an assertion: simulate() stops with a SimulationError
naming the block), Atan2, Max, Min, MinMax, MultiSum, MultiProduct, MatrixGain, the
sampled Mean, RootMeanSquare, Harmonic and TotalHarmonicDistortion over periods 1/f, and
InverseBlockConstraints (inverse models; with ``compile(model, index_reduction=True)``
where the inverted block has no direct feedthrough). Nonlinear: SlewRateLimiter and
PadeDelay (a delay approximated by a rational transfer function). FixedDelay and
VariableDelay (y = u(time − delayTime)) are not available: a true delay makes a delay
differential equation, which the compiled form (an ODE/DAE in the present states) and
its integrators do not express; PadeDelay approximates one.

A loop of blocks must contain a state (Integrator, FirstOrder, PI, ...) or pass through a
mechanical part; a purely algebraic loop is reported by the compiler as an error.

The blocks live in modules after MSL's packages, all importable from here:
``interfaces`` (SO, SISO, SI2SO, SignalSource, ``Init`` and what the blocks share),
``sources``, ``math_blocks`` (Math), ``routing`` (Routing: RealPassThrough, Replicator,
ExtractSignal, Multiplex, DeMultiplex, Multiplex2..6, DeMultiplex2..6: outputs that are
inputs, vector connectors sized at construction), ``nonlinear``, ``continuous``;
``filter_design`` computes the analog filters' coefficients.
"""
from .interfaces import (SO, SISO, SI2SO, SignalSource, Init)
from .sources import (Constant, Step, Ramp, Sine, Cosine, ExpSine, Pulse, Trapezoid, TimeTable,
                      CombiTimeTable, Smoothness, Extrapolation, TimeEvents, KinematicPTP2,
                      ContinuousClock, Exponentials, SawTooth, Sinc,
                      SineVariableFrequencyAndAmplitude, CosineVariableFrequencyAndAmplitude,
                      LogFrequencySweep, KinematicPTP)
from .math_blocks import (Gain, Add, Add3, Feedback, Product, Division, Sum, Abs, Sign,
                          Sqrt, Sin, Cos, Tan, Asin, Acos, Atan, Sinh, Cosh, Tanh, Exp,
                          Power, Exponentiation, Log, Log10, Atan2, Max, Min, MinMax, MultiSum,
                          MultiProduct, MatrixGain, Mean, RootMeanSquare,
                          InverseBlockConstraints, Harmonic, TotalHarmonicDistortion)
from .routing import (RealPassThrough, Replicator, ExtractSignal, Multiplex, DeMultiplex,
                      Multiplex2, Multiplex3, Multiplex4, Multiplex5, Multiplex6, DeMultiplex2,
                      DeMultiplex3, DeMultiplex4, DeMultiplex5, DeMultiplex6)
from .nonlinear import (Limiter, VariableLimiter, DeadZone, LimiterHomotopy,
                        VariableLimiterHomotopy, SlewRateLimiter, PadeDelay, pade_polynomials,
                        balance_abc)
from .continuous import (Integrator, Derivative, FirstOrder, SecondOrder, PI, PID, LimPID,
                         SimpleController, TransferFunction, StateSpace, LimIntegrator, Der,
                         LowpassButterworth, CriticalDamping, Filter)
from .filter_design import (AnalogFilter, FilterType)

__all__ = [
    "SO", "SISO", "SI2SO", "SignalSource", "Constant", "Step", "Ramp", "Sine", "Cosine", "ExpSine",
    "Pulse", "Trapezoid", "TimeTable", "CombiTimeTable", "Smoothness", "Extrapolation",
    "TimeEvents", "KinematicPTP2", "ContinuousClock", "Exponentials", "SawTooth", "Sinc",
    "SineVariableFrequencyAndAmplitude", "CosineVariableFrequencyAndAmplitude",
    "LogFrequencySweep", "KinematicPTP", "Gain", "Add", "Add3", "Feedback", "Product", "Division",
    "Sum", "Integrator", "Derivative", "FirstOrder", "SecondOrder", "PI", "PID", "LimPID",
    "SimpleController", "Init", "TransferFunction", "StateSpace", "LimIntegrator", "Der",
    "LowpassButterworth", "CriticalDamping", "Filter", "AnalogFilter", "FilterType", "Limiter",
    "VariableLimiter", "DeadZone", "LimiterHomotopy", "VariableLimiterHomotopy", "RealPassThrough",
    "Abs", "Sign", "Sqrt", "Sin", "Cos", "Tan", "Asin", "Acos", "Atan", "Sinh", "Cosh", "Tanh",
    "Exp", "Power", "Exponentiation", "Log", "Log10", "Atan2", "Max", "Min", "MinMax", "MultiSum",
    "MultiProduct", "MatrixGain", "Mean", "RootMeanSquare", "InverseBlockConstraints",
    "Harmonic", "TotalHarmonicDistortion", "SlewRateLimiter", "PadeDelay", "pade_polynomials",
    "balance_abc", "Replicator", "ExtractSignal", "Multiplex", "DeMultiplex",
    "Multiplex2", "Multiplex3", "Multiplex4", "Multiplex5", "Multiplex6", "DeMultiplex2",
    "DeMultiplex3", "DeMultiplex4", "DeMultiplex5", "DeMultiplex6",
]
