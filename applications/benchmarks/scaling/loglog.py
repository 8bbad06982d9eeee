"""Least-squares exponents of the scaling benchmarks (run.sh, growth.sh): b of t = a N^b, fitted
to log t against log N over the sizes from 5 x 10^4 DoFs on (below, fixed costs still show)."""
import math

SMALLEST_DOFS = 5e4


def large(rows, dim):
    """The rows of dimension @p dim (the CSV's "dim" column) from SMALLEST_DOFS DoFs on."""
    return [r for r in rows if r["dim"] == dim and float(r["dofs"]) >= SMALLEST_DOFS]


def exponent(rows, quantity):
    """The slope of log(quantity) against log(dofs) over @p rows (values floored at 1e-9)."""
    x = [math.log(float(r["dofs"])) for r in rows]
    y = [math.log(max(float(r[quantity]), 1e-9)) for r in rows]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (c - my) for a, c in zip(x, y)) / sum((a - mx) ** 2 for a in x)
