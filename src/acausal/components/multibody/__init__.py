"""3-D multibody mechanics, after Modelica.Mechanics.MultiBody.

Modules follow MSL's packages: ``interfaces`` (the Frame connector), ``world`` (World),
``parts`` (Fixed, FixedTranslation, FixedRotation, Body, BodyShape, BodyBox, BodyCylinder,
PointMass), ``joints`` (Revolute, Prismatic). Names, parameters, defaults, units and sign
conventions are MSL's, so an MSL MultiBody model translates line by line::

    m.world, m.rev = World(), Revolute(n=(0, 0, 1), useAxisFlange=True)
    m.body = Body(m=1.0, r_CM=(0.5, 0, 0))
    m.connect(m.world.frame_b, m.rev.frame_a); m.connect(m.rev.frame_b, m.body.frame_a)

The connector (core's ``MultiBodyFrame``) carries MSL's potentials r_0[3] [m] and R (R.T,
from the world to the frame) and flows f[3] [N], t[3] [N.m] resolved in the frame. The
compiler gives a 3-D frame a position (r_0 and R.T) and a velocity (v, w), its twist
resolved in the frame, the velocity conjugate to (f, t): so Lagrange's generalized forces
of a frame's force and torque, and the recovery of cut forces from reactions, are the same
code as for planar frames (``acausal.compiler.relations``). Orientations are 3×3
transformation matrices in the kinematics (``acausal.frames``, after MSL's Frames); the
generalized coordinates are the joint coordinates of the spanning tree, so there are no
orientation states and no singularity: a body must be connected to the World through
joints. ``compiled.lagrange`` gives M(q), the Coriolis/centrifugal terms and gravity as for
planar models.

The bodies register their mass properties with the compiler (``e.rigid_body``), so the
accelerations of trees come from the O(N) articulated-body recursion in spatial vectors
(``acausal.compiler.recursive``), checked against the Lagrangian's M(q) at compile time.
Robot arms from Denavit–Hartenberg tables and URDF files: ``acausal.multibody``.

Not here yet: free and spherical joints (orientation states), loops of 3-D frames,
forces, sensors, visualizers, animation.
"""
from .interfaces import Frame, Frame_a, Frame_b
from .joints import Prismatic, Revolute
from .parts import (Body, BodyBox, BodyCylinder, BodyShape, Fixed, FixedRotation,
                    FixedTranslation, PointMass, RotationTypes)
from .world import GravityTypes, World

__all__ = ["Frame", "Frame_a", "Frame_b", "World", "GravityTypes", "Fixed",
           "FixedTranslation", "FixedRotation", "RotationTypes", "Body", "BodyShape",
           "BodyBox", "BodyCylinder", "PointMass", "Revolute", "Prismatic"]
