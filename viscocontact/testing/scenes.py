"""Small scenes for tests and examples, as TOML text (``Scene.from_toml(WAVY)``).

``WAVY`` is the adhesionless wavy contact that the package's own tests use throughout: the
sinusoid Λ̃ = 0.1 on a standard linear solid β = 10 at ζ = 1, p̃∞ = 0.1, with the Newton solver
named (a BEM solve of it takes a fraction of a second; the planned method solves it on a grid).
"""

WAVY = """
[profile]
kind = "sinusoid"
amplitude = 0.1
[rheology]
kind = "standard-linear-solid"
beta = 10.0
[solver]
kind = "newton"
[load]
mean_pressure = 0.1
[sliding]
zeta = 1.0
"""
