"""Seeded random geometry shared by the scene generators (generate_icollide.py, stress/generate_stress.py).

Standard library only; every function takes the caller's random.Random so output stays reproducible.
"""
import math


def unit_vector(rng):
    """A uniformly distributed unit vector (rejection sampling in the unit ball)."""
    while True:
        v = [rng.uniform(-1.0, 1.0) for _ in range(3)]
        n = math.sqrt(sum(c * c for c in v))
        if 1e-3 < n <= 1.0:
            return [c / n for c in v]


def random_quaternion(rng):
    """Shoemake's uniform random rotation, written [x, y, z, w]."""
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a, b = math.sqrt(1.0 - u1), math.sqrt(u1)
    return [a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2),
            b * math.sin(2 * math.pi * u3), b * math.cos(2 * math.pi * u3)]
