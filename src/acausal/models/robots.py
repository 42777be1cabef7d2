"""Robot arms as 3-D multibody models: from Denavit–Hartenberg tables (``dh_chain``) and from
URDF files (``from_urdf``), built of MultiBody components (World, FixedRotation,
FixedTranslation, Revolute, Prismatic, Body), so the result is an ordinary Model: compile it,
simulate it, connect motors to its joints' axis flanges, export it as an FMU.

Both give every joint ``useAxisFlange=True`` by default: ``<joint>.axis`` and
``<joint>.support`` take 1-D motors, gears and sensors (Rotational for revolute joints,
Translational for prismatic ones); unconnected, the joints are free.
"""
from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from ..components.multibody import (Body, FixedRotation, FixedTranslation, FreeMotion,
                                    Planar, Prismatic, Revolute, RotationTypes, World)
from ..components.rotational import IdealGear
from ..core import Model
from ..errors import ParameterError, StructureError

__all__ = ["dh_chain", "from_urdf", "JointLimits"]

_SEQ = RotationTypes.PlanarRotationSequence


# ---- Denavit–Hartenberg ---------------------------------------------------------------------
def dh_chain(table: Sequence[Mapping], convention: str = "standard", name: str = "robot",
             useAxisFlange: bool = True, **world) -> Model:
    """A serial arm from its Denavit–Hartenberg table.

    ``table``: one row per joint i = 1..n, a mapping with ``theta`` [rad], ``d`` [m], ``a``
    [m], ``alpha`` [rad], ``joint`` "R" (revolute, default) or "P" (prismatic), and
    optionally ``body``: the link's mass properties as Body parameters (m [kg], r_CM [m],
    I_11..I_32 [kg.m²], resolved in link frame i; no body: a massless link). The joint
    variable's column holds its offset: q_i = 0 is theta_i (revolute) or d_i (prismatic).

    ``convention``:
    - "standard" (Denavit–Hartenberg's, distal frames):
      ⁱ⁻¹Tᵢ = Rot_z(θᵢ)·Trans_z(dᵢ)·Trans_x(aᵢ)·Rot_x(αᵢ), joint i about/along z_{i−1};
    - "modified" (Craig's, proximal frames; row i holds α_{i−1}, a_{i−1}, θᵢ, dᵢ):
      ⁱ⁻¹Tᵢ = Rot_x(α_{i−1})·Trans_x(a_{i−1})·Rot_z(θᵢ)·Trans_z(dᵢ), joint i about/along zᵢ.

    Frame 0 is the World's frame (``world``: World parameters, e.g. ``n=(0, 0, -1)`` for
    gravity along −z). Components: ``joint{i}`` (Revolute/Prismatic about/along z, with the
    axis flanges if ``useAxisFlange``), ``dh{i}`` (the table's constant part as a
    FixedRotation), ``body{i}`` (at link frame i); ``model.frames`` lists the frames 1..n
    (``frames[-1]`` the flange where a tool attaches), ``model.joints`` the joints.
    Coordinates: ``joint{i}.phi`` [rad] / ``joint{i}.s`` [m].
    """
    if convention not in ("standard", "modified"):
        raise ParameterError(f"dh_chain: convention must be 'standard' or 'modified', got "
                             f"{convention!r}")
    model = Model(name)
    model.world = World(**world)
    model.frames, model.joints = [], []
    prev = model.world.frame_b
    for i, row in enumerate(table, start=1):
        missing = [k for k in ("theta", "d", "a", "alpha") if k not in row]
        kind = row.get("joint", "R")
        if missing or kind not in ("R", "P"):
            raise ParameterError(f"dh_chain: row {i} " + (
                f"lacks {', '.join(missing)}" if missing else
                f"has joint {kind!r}; give 'R' (revolute) or 'P' (prismatic)"))
        theta, d, a, alpha = (float(row[k]) for k in ("theta", "d", "a", "alpha"))
        joint = (Revolute if kind == "R" else Prismatic)(n=(0.0, 0.0, 1.0),
                                                         useAxisFlange=useAxisFlange)
        if convention == "standard":
            # Rot_z(θ) Trans_z(d) Trans_x(a) Rot_x(α) with the joint's variable first
            fixed = FixedRotation(r=(a * math.cos(theta), a * math.sin(theta), d),
                                  rotationType=_SEQ, sequence=(3, 1, 3),
                                  angles=(math.degrees(theta), math.degrees(alpha), 0.0))
            first, second = joint, fixed
        else:
            # Rot_x(α) Trans_x(a) Rot_z(θ) Trans_z(d), then the joint's variable about z
            fixed = FixedRotation(r=(a, -d * math.sin(alpha), d * math.cos(alpha)),
                                  rotationType=_SEQ, sequence=(1, 3, 1),
                                  angles=(math.degrees(alpha), math.degrees(theta), 0.0))
            first, second = fixed, joint
        setattr(model, f"joint{i}", joint)
        setattr(model, f"dh{i}", fixed)
        model.connect(prev, first.frame_a)
        model.connect(first.frame_b, second.frame_a)
        prev = second.frame_b
        if row.get("body"):
            body = Body(**row["body"])
            setattr(model, f"body{i}", body)
            model.connect(prev, body.frame_a)
        model.frames.append(prev)
        model.joints.append(joint)
    if not model.joints:
        raise ParameterError("dh_chain: the table has no rows")
    return model


# ---- URDF -----------------------------------------------------------------------------------
class JointLimits(dict):
    """A URDF joint's <limit>: lower, upper [rad or m], effort [N.m or N], velocity [rad/s
    or m/s], and its <dynamics>: damping [N.m.s/rad or N.s/m], friction [N.m or N] (those
    the file gives), with the joint's ``type`` and ``axis``. Recorded, not applied:
    connect dampers or friction elements to the joint's flanges for them."""


def from_urdf(path, name: str | None = None, useAxisFlange: bool = True,
              gravity: Sequence[float] = (0.0, 0.0, -9.81), mimic: bool = True,
              floating_base: bool = False) -> Model:
    """The Model of a robot described by the URDF file ``path``.

    Every link with mass becomes a ``Body`` (URDF <inertial>: mass, origin and inertia,
    rotated into the link frame) named after the link; every joint a ``FixedRotation`` (or
    ``FixedTranslation``) named ``<joint>_origin`` for its <origin> (xyz [m], rpy [rad]:
    R = Rot_z(yaw)·Rot_y(pitch)·Rot_x(roll), the child frame in the parent's), then, for
    ``revolute`` and ``continuous`` joints a ``Revolute``, for ``prismatic`` ones a
    ``Prismatic`` about/along its <axis>, with the axis flanges (``useAxisFlange``) for motors
    (a ``continuous`` joint turns without end: lower and upper are not recorded even where
    the file gives them, as the URDF specification ignores them there);
    ``fixed`` joints are the origin only; a ``floating`` joint is a ``FreeMotion`` (states
    r_rel_a, v_rel_a in the parent link's frame, the quaternion Q and w_rel_b in the child's),
    a ``planar`` one a ``Planar`` moving in the plane orthogonal to its <axis> (s_x along the
    parent's x axis projected into it, or y where x is the axis; s_y; phi). Names are the
    URDF's, with characters other than letters, digits and '_' replaced by '_'. The root
    link is fixed to the World, whose gravity is ``gravity`` [m/s²] (world frame = root
    link frame); with ``floating_base`` it moves freely, on a FreeMotion ``root_joint`` from
    the World (Pinocchio's JointModelFreeFlyer root; its velocity v_rel_a is resolved in the
    world, Pinocchio's in the root link).

    ``model.limits`` maps each moving joint's name to its ``JointLimits`` (lower, upper,
    effort, velocity as the file gives them; type and axis); ``model.joints`` lists the
    joint components in the file's order. A joint that mimics another (<mimic joint
    multiplier offset>) follows it through their axis flanges when ``mimic`` (connected
    flanges for multiplier 1, an IdealGear ``<joint>_mimic`` of ratio 1/multiplier between
    revolute ones; offsets other than 0 are refused), or is a joint of its own when not
    (as Pinocchio's ``buildModelFromUrdf`` reads it by default). Meshes, collisions and
    transmissions are read past.
    """
    path = Path(path)
    try:
        robot = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as err:
        raise ParameterError(f"from_urdf: cannot read '{path}': {err}") from None
    if robot.tag != "robot":
        raise ParameterError(f"from_urdf: '{path}' is no URDF (its root is <{robot.tag}>, "
                             f"not <robot>)")
    links = {ln.get("name"): ln for ln in robot.findall("link")}
    joints = robot.findall("joint")
    children = {j.find("child").get("link") for j in joints}
    roots = [ln for ln in links if ln not in children]
    if len(roots) != 1:
        raise StructureError(f"from_urdf: '{path}' has {len(roots)} root links "
                             f"({', '.join(roots) or 'none'}); a robot is one tree of links")
    g = np.asarray(gravity, dtype=float)
    gnorm = float(np.linalg.norm(g))
    model = Model(name or robot.get("name") or path.stem)
    model.world = World(g=gnorm, n=tuple(g / gnorm) if gnorm else (0.0, 0.0, -1.0))
    model.limits, model.joints, model.joint_of = {}, [], {}
    taken = {"world"}

    def unique(raw: str) -> str:
        base = re.sub(r"\W", "_", raw)
        base = base if base and not base[0].isdigit() else "_" + base
        out, k = base, 1
        while out in taken or hasattr(Model, out):
            k += 1
            out = f"{base}_{k}"
        taken.add(out)
        return out

    root_frame = model.world.frame_b
    if floating_base:
        model.root_joint = FreeMotion()
        taken.add("root_joint")
        model.connect(root_frame, model.root_joint.frame_a)
        root_frame = model.root_joint.frame_b
        model.joints.append(model.root_joint)
    frame_of = {roots[0]: root_frame}
    _add_body(model, links[roots[0]], root_frame, unique)
    pending = list(joints)
    while pending:                       # parents first, whatever the file's order
        ready = [j for j in pending if j.find("parent").get("link") in frame_of]
        if not ready:
            raise StructureError(f"from_urdf: joints {', '.join(j.get('name') for j in pending)}"
                                 f" hang from links that are not connected to the root")
        for j in ready:
            pending.remove(j)
            frame_of[j.find("child").get("link")] = _add_joint(model, j, frame_of, unique,
                                                               useAxisFlange, links)
    for j in joints:
        if mimic and j.find("mimic") is not None:
            _add_mimic(model, j, unique, useAxisFlange)
    return model


def _add_mimic(model, j, unique, useAxisFlange: bool) -> None:
    """The follower joint ``j`` tied to its leader through their axis flanges."""
    m, jname = j.find("mimic"), j.get("name")
    leader = m.get("joint")
    multiplier, offset = float(m.get("multiplier", "1")), float(m.get("offset", "0"))
    where = f"from_urdf: joint '{jname}' mimics '{leader}'"
    if leader not in model.limits or jname not in model.limits:
        raise StructureError(f"{where}, which is no moving joint of the file")
    if not useAxisFlange or offset != 0.0 or multiplier == 0.0 or (
            multiplier != 1.0 and model.limits[jname]["type"] == "prismatic") \
            or (model.limits[jname]["type"] == "prismatic") != (
            model.limits[leader]["type"] == "prismatic"):
        raise StructureError(f"{where} with multiplier {multiplier:g} and offset {offset:g}: "
                             f"supported are multiplier 1 and offset 0 (any multiplier "
                             f"between revolute joints) with useAxisFlange=True; or read it "
                             f"as a joint of its own, from_urdf(..., mimic=False)")
    a, b = (model.joint_of[n].axis for n in (leader, jname))
    if multiplier == 1.0:
        model.connect(a, b)
        return
    gear = IdealGear(ratio=1.0 / multiplier)         # phi_leader = phi_follower/multiplier
    setattr(model, unique(f"{jname}_mimic"), gear)
    model.connect(a, gear.flange_a)
    model.connect(gear.flange_b, b)


def _floats(element, attribute: str, default: str) -> np.ndarray:
    text = element.get(attribute, default) if element is not None else default
    return np.array([float(v) for v in text.split()])


def _rpy(rpy) -> np.ndarray:
    """URDF's rotation of the child in the parent: Rot_z(yaw)·Rot_y(pitch)·Rot_x(roll)."""
    (sr, sp, sy), (cr, cp, cy) = np.sin(rpy), np.cos(rpy)
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def _placement(model, owner: str, origin, parent_frame, unique):
    """The FixedRotation/FixedTranslation of an <origin>: its frame_b."""
    xyz, rpy = _floats(origin, "xyz", "0 0 0"), _floats(origin, "rpy", "0 0 0")
    if not rpy.any():
        part = FixedTranslation(r=tuple(xyz))
    else:                    # MSL's T = Rᵀ = Rot_x(roll)ᵀ·Rot_y(pitch)ᵀ·Rot_z(yaw)ᵀ
        part = FixedRotation(r=tuple(xyz), rotationType=_SEQ, sequence=(3, 2, 1),
                             angles=tuple(np.degrees(rpy[::-1])))
    setattr(model, unique(owner), part)
    model.connect(parent_frame, part.frame_a)
    return part.frame_b


def _add_body(model, link, frame, unique) -> None:
    """A Body for the link's <inertial> (none when it has no mass)."""
    inertial = link.find("inertial")
    mass = inertial.find("mass") if inertial is not None else None
    m = float(mass.get("value", "0")) if mass is not None else 0.0
    if m <= 0:
        return
    origin = inertial.find("origin")
    R = _rpy(_floats(origin, "rpy", "0 0 0"))
    el = inertial.find("inertia")
    c = {k: float(el.get(k, "0")) if el is not None else 0.0
         for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")}
    I = R @ np.array([[c["ixx"], c["ixy"], c["ixz"]], [c["ixy"], c["iyy"], c["iyz"]],
                      [c["ixz"], c["iyz"], c["izz"]]]) @ R.T
    body = Body(m=m, r_CM=tuple(_floats(origin, "xyz", "0 0 0")), I_11=I[0, 0],
                I_22=I[1, 1], I_33=I[2, 2], I_21=I[1, 0], I_31=I[2, 0], I_32=I[2, 1])
    setattr(model, unique(link.get("name")), body)
    model.connect(frame, body.frame_a)


def _planar(axis) -> Planar:
    """MSL's Planar in the plane orthogonal to ``axis``: x along the parent's x axis
    projected into the plane (its y axis where x is the axis)."""
    n = axis / np.linalg.norm(axis)
    n_x = (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0)
    return Planar(n=tuple(float(a) for a in n), n_x=n_x)


def _add_joint(model, j, frame_of, unique, useAxisFlange: bool, links):
    """Origin, joint and the child link's body; the child link's frame."""
    jname, kind = j.get("name"), j.get("type")
    if kind not in ("revolute", "continuous", "prismatic", "fixed", "floating", "planar"):
        raise StructureError(f"from_urdf: joint '{jname}' is of type '{kind}'; revolute, "
                             f"continuous, prismatic, fixed, floating and planar joints are "
                             f"supported")
    frame = _placement(model, f"{jname}_origin", j.find("origin"),
                       frame_of[j.find("parent").get("link")], unique)
    if kind in ("floating", "planar"):
        joint = FreeMotion() if kind == "floating" else _planar(_floats(j.find("axis"), "xyz",
                                                                        "1 0 0"))
        setattr(model, unique(jname), joint)
        model.connect(frame, joint.frame_a)
        frame = joint.frame_b
        model.joints.append(joint)
        model.joint_of[jname] = joint
    elif kind != "fixed":
        axis = _floats(j.find("axis"), "xyz", "1 0 0")
        cls = Prismatic if kind == "prismatic" else Revolute
        joint = cls(n=tuple(float(a) for a in axis), useAxisFlange=useAxisFlange)
        setattr(model, unique(jname), joint)
        model.connect(frame, joint.frame_a)
        frame = joint.frame_b
        given = {k: float(el.get(k)) for tag, keys in (("limit", ("lower", "upper", "effort",
                                                                    "velocity")),
                                                      ("dynamics", ("damping", "friction")))
                 for el in [j.find(tag)] if el is not None for k in keys
                 if el.get(k) is not None
                 and not (kind == "continuous" and k in ("lower", "upper"))}
        model.limits[jname] = JointLimits(given, type=kind,
                                          axis=tuple(float(a) for a in axis))
        model.joints.append(joint)
        model.joint_of[jname] = joint
    _add_body(model, links[j.find("child").get("link")], frame, unique)
    return frame
