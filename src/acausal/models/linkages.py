"""Planar linkages with closed kinematic loops: the four-bar (crank-rocker), its parallelogram
and double-parallelogram variants, the four-bar with a driven crank, the slider-crank, and
PlanarMechanics' two examples whose loops run through massless links, KinematicLoop and
PistonEngine.

Every link of the first ones is a bar (two FixedTranslations) with a Body at its middle, a
slender rod (I = m L²/12): ``add_link``. The compiler takes the tree joints' angles as
coordinates and keeps the joint that closes a loop as constraint rows Φ(q) = 0.

KinematicLoop and PistonEngine are PlanarMechanics' examples line by line (component names,
parameters, connections); their links are massless FixedTranslations, so which joint the
compiler cuts decides whether the tree's coordinates carry mass. ``order`` permutes the
order in which their components are declared (tests check that the results do not depend
on it).
"""
from __future__ import annotations

from collections.abc import Sequence

from ..components import rotational as rot
from ..components import signals as sig
from ..components import translational as tr
from ..components.planar import Body, Fixed, FixedTranslation, Prismatic, Revolute, World
from ..core import Input, Model
from ..errors import StructureError

FOUR_BAR_LENGTHS = (1.0, 0.3, 1.0, 0.8)      # m: ground L0, crank L1, coupler L2, rocker L3
FOUR_BAR_MASSES = (0.5, 1.0, 0.8)            # kg: crank, coupler, rocker
SLIDER_CRANK_LENGTHS = (0.2, 0.6, 0.05)      # m: crank R, rod L, offset H of the slider's track
SLIDER_CRANK_MASSES = (0.4, 0.6, 1.0)        # kg: crank, rod, slider
SLIDER_INERTIA = 0.01                        # kg.m² (the slider does not turn)


def add_link(model: Model, name: str, L: float, m: float, frame):
    """A bar of length L [m] along ``frame``'s x axis with a Body of mass m [kg] (a slender
    rod, I = m L²/12) at its middle (``name``), halves ``name_a`` and ``name_b``, added to
    ``model``; returns the frame at its far end."""
    half_a, half_b = FixedTranslation(r=(L / 2, 0.0)), FixedTranslation(r=(L / 2, 0.0))
    body = Body(m=m, I=m * L ** 2 / 12)
    setattr(model, f"{name}_a", half_a)
    setattr(model, name, body)
    setattr(model, f"{name}_b", half_b)
    model.connect(frame, half_a.frame_a)
    model.connect(half_a.frame_b, body.frame_a)
    model.connect(body.frame_a, half_b.frame_a)
    return half_b.frame_b


class FourBar(Model):
    """Four-bar linkage under gravity, undamped: 1 degree of freedom (Gruebler 3·3 − 4·2).

    Ground pivots A = (0, 0) and D = (L0, 0); the crank A–B (rev1), the coupler B–C (rev2) and
    the rocker D–C (rev3) are links (``add_link``); rev4 joins the coupler's end to the
    rocker's end at C and closes the loop. Coordinates rev1.phi, rev2.phi, rev3.phi.

        World   A: Fixed ── rev1 ── crank ── rev2 ── coupler ──┐
                                                             rev4   (closes the loop at C)
                D: Fixed ── rev3 ── rocker ────────────────────┘

    lengths: (ground L0, crank L1, coupler L2, rocker L3) [m]; masses: (crank, coupler,
    rocker) [kg]; crank_flange: rev1 with its 1-D flange, to be driven or loaded;
    fifth_link: a link as long as the crank, with the rocker's mass, from E = (L0/2, 0)
    (rev5) to the coupler's middle (rev6) — with parallelogram lengths, a redundant second
    loop.
    """

    def __init__(self, name="four_bar", lengths=FOUR_BAR_LENGTHS, masses=FOUR_BAR_MASSES,
                 crank_flange: bool = False, fifth_link: bool = False):
        super().__init__(name)
        (l0, l1, l2, l3), (m1, m2, m3) = lengths, masses
        self.world = World()
        self.A, self.D = Fixed(), Fixed(r=(l0, 0.0))
        self.rev1 = Revolute(useFlange=crank_flange)
        self.rev2, self.rev3, self.rev4 = Revolute(), Revolute(), Revolute()
        self.connect(self.A.frame, self.rev1.frame_a)
        B = add_link(self, "crank", l1, m1, self.rev1.frame_b)
        self.connect(B, self.rev2.frame_a)
        C = add_link(self, "coupler", l2, m2, self.rev2.frame_b)
        self.connect(self.D.frame, self.rev3.frame_a)
        C_rocker = add_link(self, "rocker", l3, m3, self.rev3.frame_b)
        self.connect(C, self.rev4.frame_a)               # the loop closes here
        self.connect(C_rocker, self.rev4.frame_b)
        if fifth_link:
            self.E = Fixed(r=(l0 / 2, 0.0))
            self.rev5, self.rev6 = Revolute(), Revolute()
            self.connect(self.E.frame, self.rev5.frame_a)
            self.connect(add_link(self, "link5", l1, m3, self.rev5.frame_b), self.rev6.frame_a)
            self.connect(self.coupler.frame_a, self.rev6.frame_b)


class Parallelogram(FourBar):
    """The four-bar with the rocker as long as the crank and the coupler as long as the
    ground: the coupler translates. ground, crank: lengths [m]; masses: (crank, coupler,
    rocker) [kg]; crank_flange, fifth_link as for FourBar (with the fifth link: a double
    parallelogram, Gruebler 0 yet 1 degree of freedom, one loop row redundant)."""

    def __init__(self, name="parallelogram", ground=FOUR_BAR_LENGTHS[0],
                 crank=FOUR_BAR_LENGTHS[1], masses=FOUR_BAR_MASSES, crank_flange: bool = False,
                 fifth_link: bool = False):
        super().__init__(name, (ground, crank, ground, crank), masses, crank_flange, fifth_link)


class DrivenFourBar(FourBar):
    """The FourBar with rev1 driven through its flange by ``drive``: "position" (an exact
    Position source ``drive``, phi_ref = 1 + 2t + 0.3 sin(πt) [rad] from the signals
    ``ramp`` + ``wobble``) or "torque" (a Torque source ``drive`` fed by the model Input
    ``T`` [N.m])."""

    def __init__(self, drive: str = "position", name: str = "driven_four_bar"):
        super().__init__(name, crank_flange=True)
        if drive == "position":
            self.drive = rot.Position(exact=True)
            self.ramp = sig.Ramp(height=2.0 * 100, duration=100.0, offset=1.0)
            self.wobble = sig.Sine(amplitude=0.3, f=0.5)
            self.ref = sig.Add()
            self.connect(self.ramp.y, self.ref.u1)
            self.connect(self.wobble.y, self.ref.u2)
            self.connect(self.ref.y, self.drive.phi_ref)
        else:
            self.T, self.drive = Input(unit="N.m", description="crank torque"), rot.Torque()
            self.connect(self.T.y, self.drive.tau)
        self.connect(self.drive.flange, self.rev1.axis)


class SliderCrank(Model):
    """Slider-crank under gravity, undamped: a closed loop with a prismatic joint, 1 degree
    of freedom (Gruebler 3·3 − 4·2).

    The crank O–A turns about O = (0, 0) (rev1), the connecting rod A–B hangs on the crank
    (rev2) and its end B is pinned (rev3) to a slider that runs on a horizontal Prismatic
    along x, a distance H below O. Crank and rod are links (``add_link``). The compiler
    reaches the slider through the crank and rod first: coordinates rev1.phi, rev2.phi,
    rev3.phi; the prismatic joint closes the loop (its rows: the slider's distance from the
    track and its angle).

        World   O: Fixed ── rev1 ── crank ── rev2 ── rod ── rev3 ──┐
                track: Fixed(0, −H) ── prismatic ───────── slider: Body

    lengths: (crank R, rod L, track offset H) [m]; masses: (crank, rod, slider) [kg];
    driven: a Torque source ``motor`` on the crank's flange from the model Input ``tau``
    [N.m].
    """

    def __init__(self, name="slider_crank", driven: bool = False,
                 lengths=SLIDER_CRANK_LENGTHS, masses=SLIDER_CRANK_MASSES):
        super().__init__(name)
        (R, L, H), (m_crank, m_rod, m_slider) = lengths, masses
        self.world = World()
        self.O, self.track = Fixed(), Fixed(r=(0.0, -H))
        self.rev1, self.rev2, self.rev3 = Revolute(useFlange=driven), Revolute(), Revolute()
        if driven:
            self.tau = Input(unit="N.m", description="torque driving the crank")
            self.motor = rot.Torque()
            self.connect(self.tau.y, self.motor.tau)
            self.connect(self.motor.flange, self.rev1.axis)
        self.prismatic = Prismatic(r=(1.0, 0.0))
        self.slider = Body(m=m_slider, I=SLIDER_INERTIA)
        self.connect(self.O.frame, self.rev1.frame_a)
        A = add_link(self, "crank", R, m_crank, self.rev1.frame_b)
        self.connect(A, self.rev2.frame_a)
        B = add_link(self, "rod", L, m_rod, self.rev2.frame_b)
        self.connect(B, self.rev3.frame_a)
        self.connect(self.track.frame, self.prismatic.frame_a)
        self.connect(self.prismatic.frame_b, self.slider.frame_a)
        self.connect(self.rev3.frame_b, self.slider.frame_a)


# ---- PlanarMechanics.Examples: loops through massless links --------------------------------
def _declare(model: Model, parts: dict, order) -> None:
    """Add ``parts`` (name -> component, in PlanarMechanics' declaration order) to ``model``
    in ``order``: None (PlanarMechanics' order), "reversed", or every name in some order."""
    names = list(parts)
    if order is None:
        chosen = names
    elif isinstance(order, str):
        if order != "reversed":
            raise StructureError(f"{type(model).__name__}: order is None, 'reversed' or a "
                                 f"permutation of {names}, got {order!r}")
        chosen = names[::-1]
    else:
        chosen = list(order)
        if sorted(chosen) != sorted(names):
            raise StructureError(f"{type(model).__name__}: order must name each of {names} "
                                 f"once, got {chosen}")
    for name in chosen:
        setattr(model, name, parts[name])


class KinematicLoop(Model):
    """PlanarMechanics.Examples.KinematicLoop: a triangle of two massless links of 0.5 m and a
    prismatic base, held by a 1-D spring-damper on the prismatic joint, with a pendulum (a
    Body, m = 1 kg, I = 0.1 kg.m², on a massless rod of 0.6 m) hanging from the apex.

        fixed ── revolute1 ── fixedTranslation1 (0, −0.5) ── revolute2 ──┐  (apex)
          └──── prismatic1 (s) ── revolute3 ── fixedTranslation2 (0, −0.5) ┘
        apex ── revolute4 ── fixedTranslation3 (0, −0.6) ── body
        fixed1D ── springDamper1D (c = 20 N/m, d = 4 N.s/m, s_rel0 = 0.4 m) ── prismatic1.axis

    2 degrees of freedom (Gruebler 3·5 − 2·6 − 1·1, the 1-D flange and spring count nothing):
    the loop's and the pendulum's. PlanarMechanics' initial values: prismatic1.s = 0.4 m,
    prismatic1.v = 0, revolute4.phi = −0.698 rad, revolute4.w = 0 (fixed); revolute1.phi
    starts at asin(0.4) (the apex below the base). The loop has no mass of its own: only the
    pendulum's motion, through the apex, gives it inertia. Its reference results are
    revolute1.phi, revolute1.w, revolute4.phi, revolute4.w over 6 s.

    order: the declaration order of the components (see ``_declare``): None,
    "reversed" or a permutation of ``KinematicLoop.COMPONENTS``."""

    COMPONENTS = ("revolute1", "revolute3", "revolute2", "revolute4", "prismatic1",
                  "springDamper1D", "body", "fixedTranslation1", "fixedTranslation2",
                  "fixedTranslation3", "fixed", "fixed1D", "planarWorld")
    X0 = {"prismatic1.s": 0.4, "prismatic1.v": 0.0, "revolute4.phi": -0.69813170079773,
          "revolute4.w": 0.0}
    STOP_TIME = 6.0

    def __init__(self, name: str = "kinematic_loop", order: Sequence[str] | str | None = None):
        super().__init__(name)
        parts = dict(
            revolute1=Revolute(), revolute3=Revolute(), revolute2=Revolute(),
            revolute4=Revolute(), prismatic1=Prismatic(r=(1.0, 0.0), useFlange=True),
            springDamper1D=tr.SpringDamper(c=20.0, d=4.0, s_rel0=0.4),
            body=Body(m=1.0, I=0.1),
            fixedTranslation1=FixedTranslation(r=(0.0, -0.5)),
            fixedTranslation2=FixedTranslation(r=(0.0, -0.5)),
            fixedTranslation3=FixedTranslation(r=(0.0, -0.6)),
            fixed=Fixed(), fixed1D=tr.Fixed(), planarWorld=World())
        _declare(self, parts, order)
        c = self.connect
        c(self.fixedTranslation1.frame_a, self.revolute1.frame_b)
        c(self.fixedTranslation2.frame_a, self.revolute3.frame_b)
        c(self.revolute2.frame_a, self.fixedTranslation1.frame_b)
        c(self.revolute2.frame_b, self.fixedTranslation2.frame_b)
        c(self.fixedTranslation3.frame_a, self.revolute4.frame_b)
        c(self.revolute1.frame_a, self.fixed.frame)
        c(self.fixed1D.flange, self.springDamper1D.flange_a)
        c(self.revolute4.frame_a, self.fixedTranslation1.frame_b)
        c(self.body.frame_a, self.fixedTranslation3.frame_b)
        c(self.prismatic1.frame_a, self.fixed.frame)
        c(self.springDamper1D.flange_b, self.prismatic1.axis)
        c(self.prismatic1.frame_b, self.revolute3.frame_a)


class PistonEngine(Model):
    """PlanarMechanics.Examples.PistonEngine: a slider-crank whose connecting rod has no body.

        fixed ── revoluteDrive ── fixedTranslationDisc (0.3, 0) ── revoluteDisc ── pistonRod
        (bodyDrive, m = 1 kg, I = 0.1 kg.m², on the crank's axis)      (0.8, 0), massless
        fixed1 ── prismatic (along x) ── bodyPiston (m = 3 kg, I = 0.1) ── revolutePiston ┘

    1 degree of freedom. PlanarMechanics' initial values: revoluteDrive.phi = 0,
    revoluteDrive.w = −2.5 rad/s (fixed); the piston then sits 1.1 m right of the crank's axis
    (prismatic.s = −1.1 m, the rod along +x: revoluteDisc.phi = 0, the start value). Gravity
    (−y) does no work: the piston runs along x and the crank's body sits on its axis. Its
    reference results are revoluteDrive.phi and revoluteDrive.w over 10 s.

    order: the declaration order of the components (see ``_declare``): None,
    "reversed" or a permutation of ``PistonEngine.COMPONENTS``."""

    COMPONENTS = ("bodyDrive", "revoluteDrive", "fixedTranslationDisc", "fixed", "prismatic",
                  "fixed1", "revoluteDisc", "pistonRod", "bodyPiston", "revolutePiston",
                  "planarWorld")
    X0 = {"revoluteDrive.phi": 0.0, "revoluteDrive.w": -2.5}
    STOP_TIME = 10.0

    def __init__(self, name: str = "piston_engine", order: Sequence[str] | str | None = None):
        super().__init__(name)
        parts = dict(
            bodyDrive=Body(m=1.0, I=0.1), revoluteDrive=Revolute(),
            fixedTranslationDisc=FixedTranslation(r=(0.3, 0.0)), fixed=Fixed(),
            prismatic=Prismatic(r=(1.0, 0.0)), fixed1=Fixed(), revoluteDisc=Revolute(),
            pistonRod=FixedTranslation(r=(0.8, 0.0)), bodyPiston=Body(m=3.0, I=0.1),
            revolutePiston=Revolute(), planarWorld=World())
        _declare(self, parts, order)
        c = self.connect
        c(self.fixed.frame, self.revoluteDrive.frame_a)
        c(self.revoluteDrive.frame_b, self.fixedTranslationDisc.frame_a)
        c(self.fixed1.frame, self.prismatic.frame_b)
        c(self.fixedTranslationDisc.frame_b, self.revoluteDisc.frame_a)
        c(self.bodyDrive.frame_a, self.revoluteDrive.frame_b)
        c(self.revoluteDisc.frame_b, self.pistonRod.frame_a)
        c(self.revolutePiston.frame_b, self.pistonRod.frame_b)
        c(self.prismatic.frame_a, self.revolutePiston.frame_a)
        c(self.prismatic.frame_a, self.bodyPiston.frame_a)
