"""MSL's GenerationOfFMUs done as its documentation asks: the blocks of
Rotational.Examples.Utilities and Translational.Examples.Utilities (acausal.models.
rotational_fmus, translational_fmus) exported as native FMUs, connected again signal to
signal outside acausal (FMI calls through fmpy, the states integrated by scipy), must move as
the bodies connected by flanges (``msl_examples.generation_of_fmus_motion``: a closed form
and a hand-written model); and an independent importer (fmusim) runs each block with
constant inputs to its closed form.
"""
from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("fmpy")
from fmpy.validation import validate_fmu                         # noqa: E402
from scipy.integrate import solve_ivp                            # noqa: E402

import acausal                                                   # noqa: E402
from acausal.models import rotational_fmus, translational_fmus  # noqa: E402
from fmi_calls import derivatives, get_real, init, instance, set_real  # noqa: E402
from importers import fmusim                                     # noqa: E402
from msl_examples import generation_of_fmus_motion               # noqa: E402

J1, J2, C, D = 1.1, 2.2, 1e4, 100.0       # MSL's example: bodies, spring, damper

# domain: its blocks (direct, inverse, spring-damper, spring) with the example's
# parameters, and its connector names: direct (drive, load, position, speed, acceleration),
# force law (position 1, speed 1, out 1, position 2, speed 2, out 2)
DOMAINS = {
    "rotational": ((lambda: rotational_fmus.DirectInertia(J=J1),
                    lambda: rotational_fmus.InverseInertia(J=J2),
                    lambda: rotational_fmus.SpringDamper(c=C, d=D),
                    lambda: rotational_fmus.Spring(c=C)),
                   ("tauDrive", "tau", "phi", "w", "a"),
                   ("phi1", "w1", "tau1", "phi2", "w2", "tau2")),
    "translational": ((lambda: translational_fmus.DirectMass(m=J1),
                       lambda: translational_fmus.InverseMass(m=J2),
                       lambda: translational_fmus.SpringDamper(c=C, d=D),
                       lambda: translational_fmus.Spring(c=C)),
                      ("fDrive", "f", "s", "v", "a"),
                      ("s1", "v1", "f1", "s2", "v2", "f2")),
}
BLOCKS = ("direct", "inverse", "spring_damper", "spring")
VERSIONS = {"rotational": ("2.0", "3.0"), "translational": ("2.0",)}
EXPORTED = [(domain, v) for domain in DOMAINS for v in VERSIONS[domain]]


@pytest.fixture(scope="module")
def fmus(fmu_dir):
    """{(domain, block, FMI version): path}, exported once."""
    out = {}
    for domain, (makers, _, _) in DOMAINS.items():
        for block, make in zip(BLOCKS, makers):
            compiled = acausal.compile(make())
            for v in VERSIONS[domain]:
                out[domain, block, v] = compiled.export_fmu(
                    fmu_dir / f"{domain}_{block}_{v[0]}.fmu", fmi_version=v)
    return out


def drive(t):
    """The example's sine1: 10·sin(2π·2·t)."""
    return 10.0 * np.sin(4 * np.pi * t)


class Block:
    """A block's FMU for model exchange in continuous-time mode: outputs (and the state
    derivatives) for given time, states and inputs."""

    def __init__(self, path):
        self.fmu, self.vr, self.md = instance(path)
        init(self.fmu, self.md)
        self.fmu.enterContinuousTimeMode()

    def __call__(self, t, x, inputs: dict, outputs: tuple):
        """(outputs, state derivatives) at t, states x, inputs by name."""
        set_real(self.fmu, self.md, [self.vr[n] for n in inputs], list(inputs.values()))
        dx = derivatives(self.fmu, self.md, x, t) if len(x) else np.zeros(0)
        return get_real(self.fmu, self.md, [self.vr[n] for n in outputs]), dx

    def close(self):
        self.fmu.terminate()
        self.fmu.freeInstance()


def integrate(rhs, n: int, t: np.ndarray) -> np.ndarray:
    return solve_ivp(rhs, (0.0, t[-1]), np.zeros(n), t_eval=t, rtol=1e-10, atol=1e-12).y


@pytest.mark.parametrize("domain, version", EXPORTED)
def test_blocks_validate(fmus, domain, version):
    for block in BLOCKS:
        assert validate_fmu(str(fmus[domain, block, version])) == [], block


@pytest.mark.parametrize("domain", list(DOMAINS))
def test_direct_fmu_carrying_inverse_fmu_is_one_body(fmus, domain):
    """The upper part: the direct block's FMU (states: its body's position and speed)
    outputs position, speed and acceleration to the inverse block's FMU, whose output, the
    force or torque its body needs, loads the direct one: an algebraic loop (the direct
    acceleration depends on the load, the load on the acceleration), linear, solved at every
    evaluation from two trials. Together they are one body of 1.1 + 2.2 under the drive:
    the closed form to 1e-8."""
    _, (drive_in, load, pos, speed, acc), _ = DOMAINS[domain]
    direct, inverse = (Block(fmus[domain, b, "2.0"]) for b in ("direct", "inverse"))

    def load_needed(t, x, trial):
        (p, v, a), _ = direct(t, x, {drive_in: drive(t), load: trial}, (pos, speed, acc))
        return inverse(t, [], {pos: p, speed: v, acc: a}, (load,))[0][0]

    def rhs(t, x):
        g0, g1 = load_needed(t, x, 0.0), load_needed(t, x, 1.0)
        closed = g0 / (1.0 - (g1 - g0))             # l = g0 + (g1 − g0)·l
        return direct(t, x, {drive_in: drive(t), load: closed}, ())[1]

    t = np.linspace(0.0, 1.0, 101)
    x = integrate(rhs, 2, t)
    position, velocity = generation_of_fmus_motion(t)["direct"]
    assert np.max(np.abs(x[0] - position)) < 1e-8
    assert np.max(np.abs(x[1] - velocity)) < 1e-8
    direct.close()
    inverse.close()


@pytest.mark.parametrize("block, part", [("spring_damper", "2"), ("spring", "3")])
@pytest.mark.parametrize("domain", list(DOMAINS))
def test_force_law_fmu_between_two_bodies(fmus, domain, block, part):
    """The middle and lower parts: the spring-damper's (spring's) FMU gets the two bodies'
    positions and speeds (positions) and returns the forces or torques that load them
    (body 1 driven, 1.1; body 2, 2.2): the hand-written model of the bodies joined by
    flanges to 1e-8."""
    _, _, (p1, v1, out1, p2, v2, out2) = DOMAINS[domain]
    law = Block(fmus[domain, block, "2.0"])
    speeds = block == "spring_damper"

    def rhs(t, x):
        inputs = {p1: x[0], p2: x[1]} | ({v1: x[2], v2: x[3]} if speeds else {})
        (f1, f2), _ = law(t, [], inputs, (out1, out2))
        return [x[2], x[3], (drive(t) - f1) / J1, -f2 / J2]

    t = np.linspace(0.0, 1.0, 101)
    x = integrate(rhs, 4, t)
    motion = generation_of_fmus_motion(t)
    for k, body in enumerate((f"{part}a", f"{part}b")):
        assert np.max(np.abs(x[k] - motion[body][0])) < 1e-8, body
        assert np.max(np.abs(x[k + 2] - motion[body][1])) < 1e-7, body
    law.close()


@pytest.mark.parametrize("kind", ["me", "cs"])
@pytest.mark.parametrize("domain, version", EXPORTED)
def test_blocks_in_fmusim(fmus, domain, version, kind, tmp_path):
    """fmusim runs each block with constant inputs (start values): the direct body
    accelerates uniformly by (drive − load)/1.1; the inverse body needs 2.2·a; the force
    laws return ∓(c·(p2 − p1) + d·(v2 − v1)), d = 0 for the spring."""
    _, (drive_in, load, pos, speed, acc), (p1, v1, out1, p2, v2, out2) = DOMAINS[domain]
    T, dt = 1.0, 0.1
    t = np.linspace(0.0, T, 11)
    res = fmusim(fmus[domain, "direct", version], kind, T, dt, {drive_in: 2.0, load: 0.5},
                 [pos, speed, acc], tmp_path)
    a = 1.5 / J1
    assert np.allclose(res["time"], t, rtol=0, atol=1e-12)
    assert np.allclose(res[pos], a * t ** 2 / 2, rtol=0, atol=1e-9)
    assert np.allclose(res[speed], a * t, rtol=0, atol=1e-9)
    assert np.allclose(res[acc], a, rtol=0, atol=1e-12)
    res = fmusim(fmus[domain, "inverse", version], kind, T, dt, {pos: 0.3, speed: -1.0, acc: 4.0},
                 [load], tmp_path)
    assert np.allclose(res[load], J2 * 4.0, rtol=1e-14)
    at = {p1: 0.1, v1: 2.0, p2: 0.25, v2: -1.0}
    for block, d in (("spring_damper", D), ("spring", 0.0)):
        start = at if d else {p1: at[p1], p2: at[p2]}
        res = fmusim(fmus[domain, block, version], kind, T, dt, start, [out1, out2], tmp_path)
        f = C * (at[p2] - at[p1]) + d * (at[v2] - at[v1])
        assert np.allclose(res[out1], -f, rtol=1e-14) and np.allclose(res[out2], f, rtol=1e-14)
