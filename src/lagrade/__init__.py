"""lagrade: grades answers to Lagrangian and Hamiltonian dynamics problems."""

__version__ = "0.1.0"
