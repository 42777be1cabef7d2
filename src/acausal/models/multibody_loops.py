"""MSL MultiBody's kinematic loops rebuilt line by line (component names, parameters,
connections): ``Modelica.Mechanics.MultiBody.Examples.Loops.Fourbar1``, ``Fourbar2``,
``Fourbar_analytic`` and ``Engine1a``; and ``ParallelFourbar``, a 3-D four-bar of revolutes
with parallel axes (over-constrained: Gruebler 3·6 − 4·5 = −2, 1 degree of freedom).

The four-bars start as MSL's: j1.phi = 0 and j1.w = 300 deg/s fixed (x0), the prismatic
joint's s = −0.2 m a guess (Fourbar1) or fixed (Fourbar2); simulate them with
``x0=FOURBAR_START`` (and ``guess={"j2.s": -0.2}``). Engine1a starts with the inertia at
phi = 0, w = 10 rad/s, the cylinder's s = 0.15 m a guess (``ENGINE_START``).
"""
from __future__ import annotations

import math

from ..components.multibody import (BodyBox, BodyCylinder, BodyShape, FixedTranslation,
                                    JointRRP, JointSSP, Prismatic, Revolute,
                                    RevolutePlanarLoopConstraint, UniversalSpherical, World)
from ..components.rotational import Inertia
from ..core import Model

__all__ = ["MultiBodyFourbar1", "MultiBodyFourbar2", "MultiBodyFourbarAnalytic",
           "MultiBodyEngine1Base", "MultiBodyEngine1a", "EngineJointRRP", "ParallelFourbar",
           "FOURBAR_START", "ENGINE_START"]

#: MSL's fixed start values of the four-bars: j1.phi = 0 [rad], j1.w = 300 deg/s [rad/s]
FOURBAR_START = {"j1.phi": 0.0, "j1.w": 5.235987755982989}
#: MSL's fixed start values of Engine1a [rad, rad/s]
ENGINE_START = {"inertia.phi": 0.0, "inertia.w": 10.0}


class MultiBodyFourbar1(Model):
    """Loops.Fourbar1: one loop of 6 revolute joints and a prismatic joint (j2, along x)
    with four BodyCylinders (diameter 0.05 m); Dymola solves 5 nonlinear equations, here
    the loop closes at rev1 with 6 constraint rows (7 coordinates, 1 degree of
    freedom)."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "Fourbar1")
        self.world = World()
        self.j1 = Revolute(n=(1, 0, 0), stateSelect="always")
        self.j2 = Prismatic(n=(1, 0, 0))
        self.b1 = BodyCylinder(r=(0, 0.5, 0.1), diameter=0.05)
        self.b2 = BodyCylinder(r=(0, 0.2, 0), diameter=0.05)
        self.b3 = BodyCylinder(r=(-1, 0.3, 0.1), diameter=0.05)
        self.rev = Revolute(n=(0, 1, 0))
        self.rev1 = Revolute()
        self.j3 = Revolute(n=(1, 0, 0))
        self.j4 = Revolute(n=(0, 1, 0))
        self.j5 = Revolute(n=(0, 0, 1))
        self.b0 = FixedTranslation(animation=False, r=(1.2, 0, 0))
        c = self.connect
        c(self.j2.frame_b, self.b2.frame_a)
        c(self.j1.frame_b, self.b1.frame_a)
        c(self.rev.frame_a, self.b2.frame_b)
        c(self.rev.frame_b, self.rev1.frame_a)
        c(self.rev1.frame_b, self.b3.frame_a)
        c(self.world.frame_b, self.j1.frame_a)
        c(self.b1.frame_b, self.j3.frame_a)
        c(self.j3.frame_b, self.j4.frame_a)
        c(self.j4.frame_b, self.j5.frame_a)
        c(self.j5.frame_b, self.b3.frame_b)
        c(self.b0.frame_a, self.world.frame_b)
        c(self.b0.frame_b, self.j2.frame_a)


class MultiBodyFourbar2(Model):
    """Loops.Fourbar2: Fourbar1 with the rod b3 and its five revolutes replaced by a
    massless UniversalSpherical (n1_a = {0, 1, 0}, computeRodLength = true, rRod_ia =
    {−1, 0.3, 0.1} m): one constraint row; the rod length is computed at initialization
    from j1.phi = 0 and j2.s = −0.2 m, both fixed (x0). MSL's FixedFrame on frame_ia (a
    visualizer) is left out."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "Fourbar2")
        self.world = World()
        self.j1 = Revolute(n=(1, 0, 0), stateSelect="always", useAxisFlange=False)
        self.j2 = Prismatic(n=(1, 0, 0))
        self.b1 = BodyCylinder(r=(0, 0.5, 0.1), diameter=0.05)
        self.b2 = BodyCylinder(r=(0, 0.2, 0), diameter=0.05)
        self.universalSpherical = UniversalSpherical(n1_a=(0, 1, 0), computeRodLength=True,
                                                     rRod_ia=(-1, 0.3, 0.1))
        self.b3 = FixedTranslation(r=(1.2, 0, 0), animation=False)
        c = self.connect
        c(self.j2.frame_b, self.b2.frame_a)
        c(self.j1.frame_b, self.b1.frame_a)
        c(self.j1.frame_a, self.world.frame_b)
        c(self.b1.frame_b, self.universalSpherical.frame_b)
        c(self.universalSpherical.frame_a, self.b2.frame_b)
        c(self.b3.frame_a, self.world.frame_b)
        c(self.b3.frame_b, self.j2.frame_a)


class MultiBodyFourbarAnalytic(Model):
    """Loops.Fourbar_analytic: Fourbar1 with the rod b3, its revolutes and the prismatic
    joint replaced by a JointSSP (rod1Length = |{−1, 0.3, 0.1}| m, n_b = {1, 0, 0},
    s_offset = −0.2 m, rRod2_ib = {0, 0.2, 0} m) carrying b2 (animation off) at frame_ib:
    the loop closes in closed form, 1 coordinate (j1.phi), no constraint row. MSL's
    outputs j2_s = jointSSP.prismatic.distance, j2_v its rate."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "Fourbar_analytic")
        self.world = World(animateGravity=False)
        self.j1 = Revolute(n=(1, 0, 0), stateSelect="always", useAxisFlange=False)
        self.b1 = BodyCylinder(r=(0, 0.5, 0.1), diameter=0.05)
        self.b3 = FixedTranslation(r=(1.2, 0, 0), animation=False)
        self.jointSSP = JointSSP(rod1Length=math.sqrt(1 + 0.09 + 0.01), n_b=(1, 0, 0),
                                 s_offset=-0.2, rRod2_ib=(0, 0.2, 0), checkTotalPower=True)
        self.b2 = BodyCylinder(r=(0, 0.2, 0), diameter=0.05, animation=False)
        c = self.connect
        c(self.j1.frame_b, self.b1.frame_a)
        c(self.j1.frame_a, self.world.frame_b)
        c(self.b3.frame_a, self.world.frame_b)
        c(self.b1.frame_b, self.jointSSP.frame_a)
        c(self.b3.frame_b, self.jointSSP.frame_b)
        c(self.b2.frame_a, self.jointSSP.frame_ib)


class MultiBodyEngine1Base(Model):
    """Loops.Utilities.Engine1Base: the one-cylinder engine without its loop: the crank
    (BodyCylinders and BodyBoxes) on the bearing (Revolute about x with its axis flange)
    driving the output Inertia (J = 1 kg.m²), the piston (BodyCylinder) and connectingRod
    (BodyBox), the crank pin ``mid`` and the cylinder's position ``cylPosition``
    (FixedTranslations). Subclasses close the loop."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "Engine1Base")
        self.world = World()
        self.piston = BodyCylinder(diameter=0.1, r=(0, -0.1, 0))
        self.connectingRod = BodyBox(widthDirection=(1, 0, 0), width=0.02, height=0.06,
                                     r=(0, -0.2, 0))
        self.bearing = Revolute(useAxisFlange=True, n=(1, 0, 0))
        self.inertia = Inertia(J=1.0, stateSelect="always")
        self.crank1 = BodyCylinder(diameter=0.05, r=(0.1, 0, 0))
        self.crank2 = BodyBox(height=0.05, widthDirection=(1, 0, 0), width=0.02,
                              r=(0, 0.1, 0))
        self.crank3 = BodyCylinder(r=(0.1, 0, 0), diameter=0.03)
        self.crank4 = BodyBox(height=0.05, widthDirection=(1, 0, 0), width=0.02,
                              r=(0, -0.1, 0))
        self.mid = FixedTranslation(r=(0.05, 0, 0))
        self.cylPosition = FixedTranslation(animation=False, r=(0.15, 0.45, 0))
        c = self.connect
        c(self.world.frame_b, self.bearing.frame_a)
        c(self.crank2.frame_a, self.crank1.frame_b)
        c(self.bearing.frame_b, self.crank1.frame_a)
        c(self.world.frame_b, self.cylPosition.frame_a)
        c(self.crank3.frame_b, self.crank4.frame_a)
        c(self.inertia.flange_b, self.bearing.axis)
        c(self.crank2.frame_b, self.crank3.frame_a)
        c(self.crank2.frame_b, self.mid.frame_a)


class MultiBodyEngine1a(MultiBodyEngine1Base):
    """Loops.Engine1a: Engine1Base closed by a planar slider-crank loop: Revolute b1,
    RevolutePlanarLoopConstraint b2 (2 rows), Prismatic cylinder along {0, −1, 0}. With
    ``planarLoopConstraint=False``, b2 is a plain Revolute: the planar loop MSL's
    documentation warns about (over-constrained: 6 rows, 3 redundant, which the compiler
    finds from the rank)."""

    def __init__(self, name: str | None = None, planarLoopConstraint: bool = True):
        super().__init__(name or "Engine1a")
        self.b1 = Revolute(n=(1, 0, 0))
        self.b2 = (RevolutePlanarLoopConstraint if planarLoopConstraint else Revolute)(
            n=(1, 0, 0))
        self.cylinder = Prismatic(n=(0, -1, 0))
        c = self.connect
        c(self.cylPosition.frame_b, self.cylinder.frame_a)
        c(self.b2.frame_a, self.mid.frame_b)
        c(self.b2.frame_b, self.connectingRod.frame_b)
        c(self.connectingRod.frame_a, self.b1.frame_b)
        c(self.b1.frame_a, self.piston.frame_b)
        c(self.cylinder.frame_b, self.piston.frame_a)


class EngineJointRRP(MultiBodyEngine1Base):
    """Engine1Base closed in closed form by a JointRRP (MSL's Engine1b_analytic without its
    gas force): frame_a at the crank pin ``mid``, frame_b at ``cylPosition``, the prismatic
    axis n_b = {0, −1, 0}, the rod from the crank pin to the piston pin rRod1_ia = {0, 0.2,
    0} m carrying connectingRod (its frame_b at frame_ia), the piston pin at rRod2_ib =
    {0, −0.1, 0} m from frame_ib, which carries the piston; the negative branch (the rod
    above the crank pin: s = 0.05 m at the start). The same mechanism as Engine1a, 1
    coordinate (the bearing's angle), no constraint row."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "EngineJointRRP")
        self.jointRRP = JointRRP(n_a=(1, 0, 0), n_b=(0, -1, 0), rRod1_ia=(0, 0.2, 0),
                                 rRod2_ib=(0, -0.1, 0), positiveBranch=False)
        c = self.connect
        c(self.jointRRP.frame_a, self.mid.frame_b)
        c(self.jointRRP.frame_b, self.cylPosition.frame_b)
        c(self.jointRRP.frame_ia, self.connectingRod.frame_b)
        c(self.jointRRP.frame_ib, self.piston.frame_a)


class ParallelFourbar(Model):
    """A four-bar linkage of 3-D parts whose four Revolutes all turn about z (planar motion
    of a spatial model): crank j1 at the world origin (BodyShape r = {0, 0.5, 0} m, m = 1
    kg, I_33 = 0.03 kg.m²), coupler (r = {1.2, 0.2, 0} m, 2 kg, 0.25 kg.m²), rocker (r =
    {0, −0.7, 0} m, 1.5 kg, 0.07 kg.m²; centres of mass in the middle) hinged by j4 to the
    ground at {1.2, 0, 0} m (FixedTranslation ``ground``); closed with every angle 0.
    Gruebler's count is 3·6 − 4·5 = −2, yet it moves with 1 degree of freedom: 3 of the 6
    rows that close the loop are redundant (out of the plane). A crank-rocker (Grashof:
    0.5 + 1.217 ≤ 0.7 + 1.2); gravity along −y, no damping."""

    LINKS = {"crank": ((0, 0.5, 0), 1.0, 0.03), "coupler": ((1.2, 0.2, 0), 2.0, 0.25),
             "rocker": ((0, -0.7, 0), 1.5, 0.07)}

    def __init__(self, name: str | None = None):
        super().__init__(name or "ParallelFourbar")
        self.world = World()
        self.ground = FixedTranslation(r=(1.2, 0, 0))
        self.j1, self.j2, self.j3, self.j4 = Revolute(), Revolute(), Revolute(), Revolute()
        for link, (r, m, I) in self.LINKS.items():
            setattr(self, link, BodyShape(r=r, r_CM=tuple(x / 2 for x in r), m=m, I_11=I,
                                          I_22=I, I_33=I))
        c = self.connect
        c(self.world.frame_b, self.j1.frame_a)
        c(self.j1.frame_b, self.crank.frame_a)
        c(self.crank.frame_b, self.j2.frame_a)
        c(self.j2.frame_b, self.coupler.frame_a)
        c(self.coupler.frame_b, self.j3.frame_a)
        c(self.j3.frame_b, self.rocker.frame_a)
        c(self.world.frame_b, self.ground.frame_a)
        c(self.ground.frame_b, self.j4.frame_a)
        c(self.j4.frame_b, self.rocker.frame_b)
