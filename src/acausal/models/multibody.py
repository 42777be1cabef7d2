"""MSL MultiBody examples rebuilt line by line (component names, parameters, connections):
``Modelica.Mechanics.MultiBody.Examples.Elementary.Pendulum`` and ``DoublePendulum``, and
``chain`` (random-free helper for 3-D chains and trees of revolute and prismatic joints,
which the tests compare with Pinocchio).

Both examples start at rest with every joint at 0 (MSL: phi(fixed=true), w(fixed=true) at
their start values 0): the links lie along the world's x axis and fall under gravity
(-9.80665 m/s² along y). Coordinates: ``rev.phi`` / ``revolute1.phi``, ``revolute2.phi``.
"""
from __future__ import annotations

from collections.abc import Sequence

from ..components.multibody import (Body, BodyBox, FixedRotation, Prismatic, Revolute,
                                    World)
from ..components.rotational import Damper
from ..core import Model


class MultiBodyPendulum(Model):
    """MultiBody.Examples.Elementary.Pendulum: a Body (m = 1 kg, r_CM = {0.5, 0, 0} m) on a
    Revolute about z (useAxisFlange) with a rotational Damper (d = 0.1 N.m.s/rad) between
    its support and axis."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "Pendulum")
        self.world = World()
        self.rev = Revolute(n=(0, 0, 1), useAxisFlange=True)
        self.damper = Damper(d=0.1)
        self.body = Body(m=1.0, r_CM=(0.5, 0, 0))
        self.connect(self.world.frame_b, self.rev.frame_a)
        self.connect(self.damper.flange_b, self.rev.axis)
        self.connect(self.rev.support, self.damper.flange_a)
        self.connect(self.body.frame_a, self.rev.frame_b)


class MultiBodyDoublePendulum(Model):
    """MultiBody.Examples.Elementary.DoublePendulum: two BodyBoxes (r = {0.5, 0, 0} m,
    width 0.06 m, steel) on two Revolutes about z; a rotational Damper (d = 0.1) on the
    first joint."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "DoublePendulum")
        self.world = World()
        self.revolute1 = Revolute(useAxisFlange=True)
        self.damper = Damper(d=0.1)
        self.boxBody1 = BodyBox(r=(0.5, 0, 0), width=0.06)
        self.revolute2 = Revolute()
        self.boxBody2 = BodyBox(r=(0.5, 0, 0), width=0.06)
        self.connect(self.damper.flange_b, self.revolute1.axis)
        self.connect(self.revolute1.support, self.damper.flange_a)
        self.connect(self.revolute1.frame_b, self.boxBody1.frame_a)
        self.connect(self.revolute2.frame_b, self.boxBody2.frame_a)
        self.connect(self.boxBody1.frame_b, self.revolute2.frame_a)
        self.connect(self.world.frame_b, self.revolute1.frame_a)


def chain(links: Sequence[dict], name: str = "chain", useAxisFlange: bool = False,
          **world) -> Model:
    """A tree of joints and bodies: link i (``joint{i}``, ``body{i}``) hangs from link
    ``parent`` (-1: the world) through a FixedRotation ``mount{i}`` (r [m], n, angle [deg])
    and a Revolute or Prismatic (``kind`` "R" / "P", axis ``axis``, with the drive flanges
    if ``useAxisFlange``), its Body (m [kg], r_CM [m], I_11..I_32 [kg.m²]) at the joint's
    frame_b. ``world``: World parameters."""
    model = Model(name)
    model.world = World(**world)
    ends = []
    for i, link in enumerate(links):
        mount = FixedRotation(r=link["r"], n=link["n"], angle=link["angle"])
        joint = (Revolute if link["kind"] == "R" else Prismatic)(n=link["axis"],
                                                                useAxisFlange=useAxisFlange)
        body = Body(**link["body"])
        setattr(model, f"mount{i}", mount)
        setattr(model, f"joint{i}", joint)
        setattr(model, f"body{i}", body)
        parent = model.world.frame_b if link["parent"] < 0 else ends[link["parent"]]
        model.connect(parent, mount.frame_a)
        model.connect(mount.frame_b, joint.frame_a)
        model.connect(joint.frame_b, body.frame_a)
        ends.append(joint.frame_b)
    return model
