#!/usr/bin/env python3
"""The homogeneous (long-wave) cubic moduli C11, C12, C44 of the discrete LPS lattice (omega = 1/r,
uniform volumes, a whole family) and the cube-axis Young's modulus E_100 and Poisson ratio."""
import math, sys
E = 60e9
for nu in [float(a) for a in sys.argv[1:]] or [0.4]:
    kappa = E/(3*(1-2*nu)); mu = E/(2*(1+nu)); lam = kappa - 2*mu/3
    A = 3*kappa - 5*mu; B = 15*mu
    for m in (2.01, 3.015, 4.02, 5.025, 6.03, 10.05, 20.1):
        n = int(math.floor(m)); mm = szz = q4 = q22 = 0.0
        for i in range(-n, n+1):
            for j in range(-n, n+1):
                for k in range(-n, n+1):
                    r2 = i*i+j*j+k*k
                    if r2 == 0 or r2 > m*m: continue
                    r = math.sqrt(r2); w = 1/r
                    mm += w*r2; szz += w*k*k; q4 += w*k**4/r2; q22 += w*i*i*k*k/r2
        s = 3*szz/mm
        C11 = A/3*s*s + B/mm*q4; C12 = A/3*s*s + B/mm*q22; C44 = B/mm*q22
        E100 = (C11-C12)*(C11+2*C12)/(C11+C12); nu100 = C12/(C11+C12)
        print("nu=%.2f m=%6.3f C11/(l+2mu)=%.4f C12/lam=%.4f C44/mu=%.4f  E100/E=%.4f nu100=%.4f"
              % (nu, m, C11/(lam+2*mu), C12/lam, C44/mu, E100/E, nu100))
