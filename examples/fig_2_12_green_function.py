"""Reproduce the thesis's Fig. 2.12: the periodic steady-sliding Green function against x̃.

Plots ``π·G̃_V(x̃)`` (the normalisation of eq. 2.48, ``G_V π E0 / (2(1-ν²))``) for a standard linear
solid with E∞/E0 = 10 and several ζ = q0·V·τ. Small ζ gives the relaxed kernel log|2 sin(x/2)|, large
ζ the glassy one divided by 10, intermediate ζ the asymmetric viscoelastic kernels.

Usage: ``python examples/fig_2_12_green_function.py [--out fig_2_12.png]``
"""
from __future__ import annotations

import argparse

import numpy as np


def main(argv=None) -> str:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="fig_2_12.png", help="PNG file to write")
    parser.add_argument("--beta", type=float, default=10.0, help="E∞/E0")
    args = parser.parse_args(argv)

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from viscocontact.kernels import HalfPlane
    from viscocontact.rheology.sls import StandardLinearSolid

    rheology = StandardLinearSolid(beta=args.beta)
    x = np.linspace(-np.pi, np.pi, 2001)
    x = x[np.abs(x) > 1e-3]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for zeta, style in [(1e-3, "-"), (0.1, "-"), (0.3, "-"), (1.0, "-"), (3.0, "-"), (1e3, "--")]:
        g = np.pi * HalfPlane().prepare(rheology, zeta).values(x)
        ax.plot(x, g, style, lw=1.2, label=f"ζ = {zeta:g}")
    ax.set_xlabel("x̃ = q0 x")
    ax.set_ylabel("G̃_V (x̃) = G_V π E0 / (2(1-ν²))")
    ax.set_title(f"Periodic viscoelastic Green function, E∞/E0 = {args.beta:g}")
    ax.set_ylim(-4, 1.0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=130)
    print(args.out)
    return args.out


if __name__ == "__main__":
    main()
