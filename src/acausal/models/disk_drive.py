"""Hard-disk read/write head, a worked case of machine-dynamics courses: an actuator arm on a pivot with a
laterally flexible tip carrying the head.

The arm (inertia I about its fixed pivot) is turned by the voice-coil torque T(t) against a
rotational damper c_T; the head (mass m) sits at radius L on a flexible tip that deflects by
δ sideways (perpendicular to the arm, positive towards increasing θ) against a spring k. The
disk is horizontal: gravity is normal to the plane of motion (World g = 0). Coordinates
θ = ``pivot.phi``, δ = ``flexure.s``; input ``T`` [N.m]. The arm Body's centre of mass is on
the pivot axis, so its mass (``arm.m``) does not enter the equations. The flexure's
deflection (a few µm) and its rate (a few cm/s) carry their magnitudes as nominals
(``flexure.s`` 1e-6 m, ``flexure.v`` 1e-2 m/s): the integrators' absolute tolerance scales
with them; the pivot damper's phi_rel is the arm's angle, with MSL's phi_nominal 1e-4 rad.

Components (PlanarMechanics and MSL names):

    World(g=0)  base: Fixed.frame ── pivot: Revolute(useFlange) ── arm: Body (I about the pivot)
                    pivot.axis ← pivotDamper (to pivot.support), voiceCoil: Torque ← Input T
                    pivot.frame_b ── tip: FixedTranslation r = (L, 0)
                                     ── flexure: Prismatic(r = (0, 1), useFlange) ── head: Body (m)
                                        flexure.axis ← flexureSpring (to flexure.support)
"""
from __future__ import annotations

from ..components import rotational as rot
from ..components import translational as tr
from ..components.planar import Body, Fixed, FixedTranslation, Prismatic, Revolute, World
from ..core import Input, Model

ARM_INERTIA = 2.0e-6        # kg.m²
ARM_MASS = 0.01             # kg (on the pivot axis: no effect on the motion)
HEAD_MASS = 1.0e-4          # kg
RADIUS = 0.04               # m
FLEXURE_STIFFNESS = 1.6e4   # N/m (a lateral mode near 2 kHz)
PIVOT_DAMPING = 1.0e-6      # N.m.s/rad
FLEXURE_NOMINAL = (1.0e-6, 1.0e-2)  # m, m/s: magnitudes of the deflection and its rate


class DiskDriveHead(Model):
    """Actuator arm on a pivot with a laterally flexible tip carrying the head; input ``T``
    [N.m] is the voice-coil torque on the arm.

    I: arm inertia about the pivot [kg.m²]; m: head mass [kg]; L: radius of the head [m];
    k: flexure stiffness [N/m]; c_T: pivot damping [N.m.s/rad].
    """

    def __init__(self, name="disk", I=ARM_INERTIA, m=HEAD_MASS, L=RADIUS, k=FLEXURE_STIFFNESS,
                 c_T=PIVOT_DAMPING):
        super().__init__(name)
        self.world = World(g=0.0)
        self.base = Fixed()
        self.pivot = Revolute(useFlange=True)
        self.arm = Body(m=ARM_MASS, I=I)
        self.tip = FixedTranslation(r=(L, 0.0))
        self.flexure = Prismatic(r=(0.0, 1.0), useFlange=True,
                                 nominal={"s": FLEXURE_NOMINAL[0], "v": FLEXURE_NOMINAL[1]})
        self.head = Body(m=m, I=0.0)
        self.pivotDamper = rot.Damper(d=c_T)
        self.flexureSpring = tr.Spring(c=k)
        self.T = Input(unit="N.m", description="voice-coil torque on the arm")
        self.voiceCoil = rot.Torque(useSupport=True)
        for a, b in [(self.base.frame, self.pivot.frame_a),
                     (self.pivot.frame_b, self.arm.frame_a),
                     (self.pivot.frame_b, self.tip.frame_a),
                     (self.tip.frame_b, self.flexure.frame_a),
                     (self.flexure.frame_b, self.head.frame_a),
                     (self.pivot.support, self.pivotDamper.flange_a),
                     (self.pivotDamper.flange_b, self.pivot.axis),
                     (self.T.y, self.voiceCoil.tau),
                     (self.voiceCoil.flange, self.pivot.axis),
                     (self.voiceCoil.support, self.pivot.support),
                     (self.flexure.support, self.flexureSpring.flange_a),
                     (self.flexureSpring.flange_b, self.flexure.axis)]:
            self.connect(a, b)
