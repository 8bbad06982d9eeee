#!/usr/bin/env python3
"""section_energy.py -- the axial modulus of a bar's cross-section in the discrete LPS model
(omega = 1/r, uniform volumes h^3, the families truncated at the lateral surfaces), for the
homogeneous uniaxial strain u = eps z e_z (u_x = u_y = 0; the exact solution of a bar held
laterally, away from its ends). Pure Python 3; lattice units (h = 1).

Usage: python3 section_energy.py [--nu NU] [--m M] [--n N] [--round [--cube-centred]]

The section is the (N+1) x (N+1) nodes of a square of N cubes (--round: the vertices of the cubes
whose centres are within N/2 of the centre; a node on the centre, or with --cube-centred a cube's
centre there, the dog-bone's lattice: N = 30, 40, 50 for its gauge at h = 1, 0.75, 0.6 mm). Each node k carries the LPS energy density
W_k = A theta_k^2 / 6 + B / (2 m_k) sum_j omega (xi.eta)^2 / |xi|^2 (theory.md §15.1) with
theta_k = (3 / m_k) sum_j omega xi.eta over its members j (|xi| <= M; z unbounded). Prints
  M_n = sum_k 2 W_k / eps^2 / (number of nodes) / (lambda + 2 mu)
(the section's modulus per node area h^2, over the continuum's), the same with the whole family
(C11 of the lattice), and the profile of 2 W_k / eps^2 / (lambda + 2 mu) and theta_k / eps along
the section's mid-line from the surface inwards.
"""
import math
import sys


def main(argv):
    nu, m, n, round_bar, centred = 0.4, 3.015, 12, False, False
    i = 0
    while i < len(argv):
        if argv[i] == "--nu":
            nu = float(argv[i + 1]); i += 2
        elif argv[i] == "--m":
            m = float(argv[i + 1]); i += 2
        elif argv[i] == "--n":
            n = int(argv[i + 1]); i += 2
        elif argv[i] == "--round":
            round_bar = True; i += 1
        elif argv[i] == "--cube-centred":
            centred = True; i += 1
        else:
            sys.exit(__doc__)
    E = 1.0
    kappa = E / (3 * (1 - 2 * nu)); mu = E / (2 * (1 + nu)); lam = kappa - 2 * mu / 3
    A, B, M = 3 * kappa - 5 * mu, 15 * mu, lam + 2 * mu
    r_ = int(math.floor(m))
    bonds = [(a, b, c) for a in range(-r_, r_ + 1) for b in range(-r_, r_ + 1) for c in range(-r_, r_ + 1)
             if 0 < a * a + b * b + c * c <= m * m]
    if round_bar:
        nodes = set()
        c0 = n / 2 + (0.5 if centred else 0.0)  # the centre in lattice coordinates
        for j in range(n + 1):
            for i in range(n + 1):
                if math.hypot(i + 0.5 - c0, j + 0.5 - c0) <= n / 2:
                    nodes.update([(i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)])
    else:
        nodes = {(i, j) for i in range(n + 1) for j in range(n + 1)}

    def density(k):
        mk = s1 = s2 = 0.0
        for a, b, c in bonds:
            if (k[0] + a, k[1] + b) not in nodes:
                continue
            r2 = a * a + b * b + c * c
            r = math.sqrt(r2)
            w = 1.0 / r
            mk += w * r2
            s1 += w * c * c            # xi.eta / eps
            s2 += w * c ** 4 / r2      # (xi.eta)^2 / |xi|^2 / eps^2
        theta = 3.0 / mk * s1
        return 2 * (A * theta * theta / 6 + B / (2 * mk) * s2), theta

    # the whole family: every offset present
    mk = sum(math.sqrt(a * a + b * b + c * c) for a, b, c in bonds)
    s1 = sum(c * c / math.sqrt(a * a + b * b + c * c) for a, b, c in bonds)
    s2 = sum(c ** 4 / (a * a + b * b + c * c) ** 1.5 for a, b, c in bonds)
    C11 = 2 * (A * (3 * s1 / mk) ** 2 / 6 + B / (2 * mk) * s2)
    total = 0.0
    profile = {}
    for k in nodes:
        d, theta = density(k)
        total += d
        if k[1] == n // 2 and k[0] <= n // 2:
            profile[k[0]] = (d, theta)
    print("nu = %g, m = %g, %s N = %d: %d nodes; C11 of the lattice / (lambda + 2 mu) = %.4f; "
          "section M_n = %.4f" % (nu, m, "round" if round_bar else "square", n, len(nodes), C11 / M,
                                  total / len(nodes) / M))
    print("mid-line from the surface: i, 2W/eps^2/(lambda+2mu), theta/eps")
    keys = sorted(profile)
    for i in keys[: min(len(keys), r_ + 3)]:
        print("  %2d  %.4f  %.4f" % (i - keys[0], profile[i][0] / M, profile[i][1]))


if __name__ == "__main__":
    main(sys.argv[1:])
