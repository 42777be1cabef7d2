"""The rotational compliant elements (Spring, Damper, SpringDamper) go through the compiler's
batched physics path, and give there what a hand-written model gives.

Reference: the chain's linear ODE M φ'' = −K φ − D φ' written here with numpy and solved
exactly with scipy's matrix exponential.
"""
import numpy as np
import pytest
from scipy.linalg import expm

import acausal
from acausal.compiler import batch
from acausal.components import rotational as rot

N = 8                                   # bodies; MIN_BATCH instances of each compliant class
J = np.linspace(0.4, 1.1, N)            # [kg.m2]
C = np.linspace(60.0, 25.0, N)          # series springs [N.m/rad]
D = np.linspace(0.05, 0.3, N)           # series dampers [N.m.s/rad]
C0 = np.linspace(5.0, 12.0, N)          # spring-dampers to the ground [N.m/rad]
D0 = np.linspace(0.2, 0.02, N)          # [N.m.s/rad]
PHI0 = 0.1 * np.sin(np.arange(1, N + 1))
T = np.linspace(0.0, 1.5, 61)


def chain() -> acausal.Model:
    """ground -(Spring ∥ Damper)- j0 -(Spring ∥ Damper)- j1 ... j7; each j_i also held to
    the ground by a SpringDamper."""
    m = acausal.Model("chain")
    m.ground = rot.Fixed()
    left = m.ground.flange
    for i in range(N):
        parts = dict(s=rot.Spring(c=C[i]), d=rot.Damper(d=D[i]),
                     sd=rot.SpringDamper(c=C0[i], d=D0[i]), j=rot.Inertia(J=J[i]))
        for k, part in parts.items():
            setattr(m, f"{k}{i}", part)
        j = parts["j"]
        for element in (parts["s"], parts["d"]):
            m.connect(left, element.flange_a)
            m.connect(element.flange_b, j.flange_a)
        m.connect(m.ground.flange, parts["sd"].flange_a)
        m.connect(parts["sd"].flange_b, j.flange_b)
        left = j.flange_b
    return m


def hand_model():
    """φ, ω, φ'' of the bodies on T, from x' = A x, x = [φ; ω]: x(t) = expm(A t) x(0)."""
    K, Dm = np.diag(C0), np.diag(D0)
    for i in range(N):           # series element i joins body i-1 (ground for i = 0) and i
        for mat, k in ((K, C[i]), (Dm, D[i])):
            mat[i, i] += k
            if i:
                mat[i - 1, i - 1] += k
                mat[i, i - 1] -= k
                mat[i - 1, i] -= k
    Minv = np.diag(1.0 / J)
    A = np.block([[np.zeros((N, N)), np.eye(N)], [-Minv @ K, -Minv @ Dm]])
    x0 = np.concatenate([PHI0, np.zeros(N)])
    X = np.stack([expm(A * t) @ x0 for t in T], axis=1)
    return X[:N], X[N:], (A @ X)[N:]


def compiled_with_batch_log(monkeypatch):
    """Compile the chain, recording which classes went through the batched path."""
    used = {}
    original = batch._batched

    def spy(ws, members, points):
        ok = original(ws, members, points)
        used[type(members[0]).__name__] = (len(members), ok)
        return ok

    monkeypatch.setattr(batch, "_batched", spy)
    return acausal.compile(chain()), used


def simulate(compiled):
    return compiled.simulate(T[-1], t=T, x0={f"j{i}.phi": PHI0[i] for i in range(N)},
                             rtol=1e-12, atol=1e-14)


def test_rotational_compliant_elements_are_batched():
    for cls in (rot.Spring, rot.Damper, rot.SpringDamper, rot.Inertia):
        assert vars(cls).get("batch_physics") is True, cls.__name__


def test_batched_rotational_chain_vs_hand_model(monkeypatch):
    compiled, used = compiled_with_batch_log(monkeypatch)
    for name in ("Spring", "Damper", "SpringDamper", "Inertia"):
        assert used.get(name) == (N, True), f"{name} not batched: {used}"
    res = simulate(compiled)
    phi, w, acc = hand_model()
    scale = np.max(np.abs(PHI0))
    for i in range(N):
        ground = np.zeros_like(T)
        prev = (phi[i - 1], w[i - 1], acc[i - 1]) if i else (ground, ground, ground)
        phi_rel, w_rel, a_rel = phi[i] - prev[0], w[i] - prev[1], acc[i] - prev[2]
        expected = {f"j{i}.phi": phi[i], f"j{i}.w": w[i],
                    f"s{i}.phi_rel": phi_rel, f"s{i}.tau": C[i] * phi_rel,
                    f"d{i}.w_rel": w_rel, f"d{i}.a_rel": a_rel, f"d{i}.tau": D[i] * w_rel,
                    f"d{i}.lossPower": D[i] * w_rel ** 2,
                    f"sd{i}.tau": C0[i] * phi[i] + D0[i] * w[i],
                    f"sd{i}.lossPower": D0[i] * w[i] ** 2}
        for name, ref in expected.items():
            err = np.max(np.abs(res[name] - ref)) / max(1.0, np.max(np.abs(ref)))
            assert err <= 1e-9 * max(1.0, scale), f"{name}: error {err:.2e}"


def test_batched_and_plain_paths_give_the_same_model(monkeypatch):
    batched, _ = compiled_with_batch_log(monkeypatch)
    monkeypatch.setattr(batch, "MIN_BATCH", 10 ** 9)
    plain, used = compiled_with_batch_log(monkeypatch)
    assert not used, f"plain path expected, batched: {used}"
    a, b = simulate(batched), simulate(plain)
    for name in ("j0.phi", "j7.w", "s3.tau", "d5.a_rel", "sd7.lossPower"):
        assert np.max(np.abs(a[name] - b[name])) <= 1e-12 * max(1.0, np.max(np.abs(b[name]))), \
            name


@pytest.mark.parametrize("cls, law", [
    (rot.Spring, lambda phi_rel, w_rel, c, d: c * phi_rel),
    (rot.Damper, lambda phi_rel, w_rel, c, d: d * w_rel),
    (rot.SpringDamper, lambda phi_rel, w_rel, c, d: c * phi_rel + d * w_rel)])
def test_compliant_laws_have_one_signature(cls, law):
    """torque(phi_rel, w_rel) and loss_power(phi_rel, w_rel, tau), as translational's
    force(s_rel, v_rel) and loss_power(s_rel, v_rel, f)."""
    params = {k: v for k, v in (("c", 3.0), ("d", 0.5)) if k in cls.parameters()}
    element = cls(**params)
    tau = element.torque(0.2, -1.5)
    assert tau == pytest.approx(law(0.2, -1.5, params.get("c", 0.0), params.get("d", 0.0)))
    loss = element.loss_power(0.2, -1.5, tau)
    assert loss is None if cls is rot.Spring else loss == pytest.approx(0.5 * 1.5 ** 2)
