"""The native runtime's dense least squares (fmu/c/linalg.c), compiled alone and called through
ctypes: the minimum-norm least-squares solution A⁺ b of ac_min_norm_lstsq (a complete
orthogonal decomposition from Householder QR) equals numpy's SVD-based lstsq (LAPACK gelsd)
for tall, wide, square and rank-deficient A, consistent or not — the projection of loop
assembly relies on it for redundant loop rows and singular configurations."""
from __future__ import annotations

import ctypes
import subprocess
from pathlib import Path

import numpy as np
import pytest

import acausal.fmu
from acausal.fmu.export import find_compiler

D = ctypes.POINTER(ctypes.c_double)
RUNTIME = Path(acausal.fmu.__file__).parent / "c"


@pytest.fixture(scope="module")
def linalg(tmp_path_factory):
    """linalg.c of the runtime as a shared library."""
    lib = tmp_path_factory.mktemp("linalg") / "linalg.so"
    subprocess.run([find_compiler(), "-O2", "-shared", "-fPIC", "-std=c99",
                    str(RUNTIME / "linalg.c"), "-o", str(lib), "-lm"], check=True)
    return ctypes.CDLL(str(lib))


def min_norm_lstsq(lib, A, b, rcond=1e-12):
    m, n = A.shape
    at = np.asfortranarray(A.T.copy())                    # n × m, column-major
    x = np.zeros(n)
    k = min(m, n)
    work = np.zeros(m * k + 2 * k + m + 1)
    perm = (ctypes.c_int * max(m, 1))()
    lib.ac_min_norm_lstsq(at.ctypes.data_as(D), n, m, np.ascontiguousarray(b).ctypes.data_as(D),
                          x.ctypes.data_as(D), ctypes.c_double(rcond), work.ctypes.data_as(D),
                          perm)
    return x


def random_matrix(rng, m, n, rank):
    return rng.standard_normal((m, rank)) @ rng.standard_normal((rank, n))


@pytest.mark.parametrize("m, n, rank", [(3, 6, 3), (6, 3, 3), (4, 4, 4), (4, 6, 2), (6, 4, 2),
                                        (5, 5, 3), (1, 4, 1), (4, 1, 1), (3, 3, 0)])
def test_min_norm_lstsq_equals_numpy(linalg, m, n, rank):
    rng = np.random.default_rng(100 * m + 10 * n + rank)
    A = random_matrix(rng, m, n, rank)
    for b in (rng.standard_normal(m), A @ rng.standard_normal(n)):   # inconsistent, consistent
        ref = np.linalg.lstsq(A, b, rcond=1e-12)[0]
        x = min_norm_lstsq(linalg, A, b)
        assert np.max(np.abs(x - ref)) < 1e-12 * (1 + np.max(np.abs(ref))), (x, ref)


def test_ill_conditioned_rows_keep_their_accuracy(linalg):
    """Condition 1e6, against A⁺ b from the exact SVD: normal equations (A Aᵀ, condition 1e12)
    lose 8 digits here (relative error 3e-8); the orthogonal factorizations keep it at 2e-12,
    as numpy's SVD does."""
    rng = np.random.default_rng(7)
    U = np.linalg.qr(rng.standard_normal((3, 3)))[0]
    V = np.linalg.qr(rng.standard_normal((5, 3)))[0]
    A = U @ np.diag([1.0, 1e-3, 1e-6]) @ V.T
    b = rng.standard_normal(3)
    ref = V @ ((U.T @ b) / np.array([1.0, 1e-3, 1e-6]))      # A⁺ b from the exact SVD
    x = min_norm_lstsq(linalg, A, b)
    assert np.max(np.abs(x - ref)) < 1e-10 * np.max(np.abs(ref))
