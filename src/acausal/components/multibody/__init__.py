"""3-D multibody mechanics, after Modelica.Mechanics.MultiBody.

Modules follow MSL's packages: ``interfaces`` (the Frame connector), ``world`` (World),
``parts`` (Fixed, FixedTranslation, FixedRotation, Body, BodyShape, BodyBox, BodyCylinder,
PointMass, Rotor1D, Mounting1D), ``joints`` (Revolute, Prismatic), ``joints_multi``
(Spherical, FreeMotion, Universal, Cylindrical, Planar), ``loop_joints`` and
``assemblies``, ``rolling`` (MSL's Parts.RollingWheel and Parts.RollingWheelSet as
RollingWheel, RollingWheelSet; their joints as RollingWheelJoint, RollingWheelSetJoint,
RollingConstraintVerticalWheel: no-slip constraints on velocities), ``forces``, ``sensors``
and ``visualizers`` (``resolving``: MSL's resolveInFrame). Names, parameters, defaults,
units and sign conventions are MSL's, so an MSL MultiBody model translates line by line::

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
generalized coordinates are the joint coordinates of the spanning tree. A body with no
joint path to the world is a free body (13 states: r_0, v_0, a quaternion Q, w_a; MSL's
angles_start, w_0_start ... start values), as are the relative motions of FreeMotion and
Spherical: quaternions, never singular (``acausal.compiler.charts``). ``compiled.lagrange``
gives M(q), the Coriolis/centrifugal terms and gravity as for planar models (in the
angular velocities of free frames: quasi-velocities).

Closed loops: where a joint's frames are both fixed by other paths, it closes the loop
with 6 constraint rows (position, MSL's Frames.Orientation.equalityConstraint); rows
redundant at the assembled configuration are found from the rank (``compiled.mobility``).
``loop_joints`` (RevolutePlanarLoopConstraint, SphericalSpherical, UniversalSpherical)
close loops with fewer rows, ``assemblies`` (JointSSP, JointSSR, JointUSR, JointUSP,
JointRRR, JointRRP) in closed form; JointUPS places the two parts of a line force with
mass (a hydraulic cylinder) between two frames placed by other paths.

The bodies register their mass properties with the compiler (``e.rigid_body``), so the
accelerations of trees come from the O(N) articulated-body recursion in spatial vectors
(``acausal.compiler.recursive``), checked against the Lagrangian's M(q) at compile time.
Robot arms from Denavit–Hartenberg tables and URDF files: ``acausal.multibody``. The
animation (``acausal.analysis.animation``) draws the parts from their shapes.

Loops may run through free bodies and Spherical or FreeMotion joints (their quaternion
states held on the loop constraints as the joint coordinates are).
"""
from .interfaces import Frame, Frame_a, Frame_b
from .assemblies import JointRRP, JointRRR, JointSSP, JointSSR, JointUPS, JointUSP, JointUSR
from .joints import Prismatic, Revolute
from .joints_multi import Cylindrical, FreeMotion, Planar, Spherical, Universal
from .loop_joints import RevolutePlanarLoopConstraint, SphericalSpherical, UniversalSpherical
from .parts import (Body, BodyBox, BodyCylinder, BodyShape, Fixed, FixedRotation,
                    FixedTranslation, PointMass, RotationTypes)
from .rolling import (RollingConstraintVerticalWheel, RollingWheel, RollingWheelJoint,
                      RollingWheelSet, RollingWheelSetJoint)
from .world import GravityTypes, World
from . import forces, sensors, visualizers
from .parts import Mounting1D, Rotor1D

__all__ = ["Frame", "Frame_a", "Frame_b", "World", "GravityTypes", "Fixed",
           "FixedTranslation", "FixedRotation", "RotationTypes", "Body", "BodyShape",
           "BodyBox", "BodyCylinder", "PointMass", "Revolute", "Prismatic", "Spherical",
           "FreeMotion", "Universal", "Cylindrical", "Planar", "RollingWheel",
           "RollingWheelSet", "RollingWheelJoint", "RollingWheelSetJoint",
           "RollingConstraintVerticalWheel", "forces", "sensors", "visualizers", "Rotor1D",
           "Mounting1D", "RevolutePlanarLoopConstraint", "SphericalSpherical",
           "UniversalSpherical", "JointSSP", "JointSSR", "JointUSR", "JointUSP", "JointRRR",
           "JointRRP", "JointUPS"]
